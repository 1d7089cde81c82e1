"""The spin model's benchmark: time per spin shot (``exact``) against pooltool 0.6.0 with its default models, and
the ``step`` solver's speed against error on spin shots. ``python -m benchmarks --only spin --write``
writes ``docs/bench/spin.md`` and ``spin.json``.

- **Speed**: stun, draw and follow shots into a ball, english off a rail, a 15-ball break with follow and side;
  ours: ``Simulator(table, Physics(friction="spin")).run`` (with and without validating the balls) and the
  ``pooltool`` preset's (pooltool's default physics, with squirt); pooltool:
  ``pooltool.simulate`` on the same shots struck with the same tip offsets (its own cue model and default
  physics: frictional ball-ball, compliant cushions, pockets), in interleaved rounds of the same run, in its own
  venv (``benchmarks/pooltool_setup.sh``) through :mod:`.pooltool_runner`. Target: the preset at least 100x
  pooltool's speed on every shot.
- **Speed against error**: the ``step`` solver (both contact treatments, several ``dt``) against ``exact`` on
  random two-ball spin shots (random cut, speed 0.5-3 m/s, tip offset anywhere on the disc) and the fixed spin
  shots: mean error of the final positions, share of shots whose outcome (pocketed balls) differs, time per shot.
"""
from __future__ import annotations

import math
import statistics
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from billiards_env.physics import Balls, Physics, Simulator, Table
from billiards_env.physics.layout import rack_balls

from .common import fmt_time, load_now, log, machine_info, machine_markdown, one_ball_shots, rerender, write_json

TARGET_SPEEDUP = 100.0
DTS = (1e-3, 1e-4, 1e-5)
CONTACTS = ("lecture", "rewind")


@dataclass(frozen=True)
class SpinShot:
    """Balls at rest, then ball ``ball`` struck at ``angle`` (rad) and ``speed`` (m/s) with tip offsets ``side`` and
    ``top`` (fractions of R)."""

    name: str
    balls: Balls
    ball: int
    angle: float
    speed: float
    side: float
    top: float

    def struck(self) -> Balls:
        return self.balls.strike(self.ball, self.angle, self.speed, side=self.side, top=self.top)

    def spec(self) -> dict[str, Any]:
        """JSON form for the pooltool subprocess (:mod:`.pooltool_bench`)."""
        return {"ids": list(self.balls.ids), "pos": self.balls.pos.tolist(), "ball": self.ball, "angle": self.angle,
                "speed": self.speed, "side": self.side, "top": self.top}


def fixed_shots(table: Table) -> list[SpinShot]:
    """The named spin shots of the speed table."""
    two = Balls.from_positions([[0.7, 0.635], [1.6, 0.635]])
    one = Balls.from_positions([[0.8, 0.4]])
    brk = rack_balls(table)
    d = brk.pos[1] - brk.pos[0]
    return [
        SpinShot("stun into a ball", two, 0, 0.0, 2.5, 0.0, 0.0),
        SpinShot("draw into a ball", two, 0, 0.0, 2.5, 0.0, -0.4),
        SpinShot("follow into a ball", two, 0, 0.0, 2.5, 0.0, 0.4),
        SpinShot("english off a rail", one, 0, math.radians(50), 2.0, 0.4, 0.1),
        SpinShot("break with spin", brk, 0, math.atan2(d[1], d[0]), 8.0, 0.1, 0.2),
    ]


def random_spin_shots(n: int, seed: int, table: Table) -> list[SpinShot]:
    """Two-ball shots of the accuracy suite (random places, a random cut, 0.5-3 m/s) with a random tip offset."""
    rng = np.random.default_rng(seed)
    out = []
    for s in one_ball_shots(n, seed=seed, table=table):
        r = 0.5 * math.sqrt(rng.uniform(0.0, 1.0))
        phi = rng.uniform(-math.pi, math.pi)
        out.append(SpinShot(f"random {s.index}", s.balls, s.ball, s.angle, s.speed, r * math.cos(phi),
                            r * math.sin(phi)))
    return out


def _sizes(quick: bool) -> dict[str, int]:
    if quick:
        return {"reps": 5, "break_reps": 2, "rounds": 2, "pt_reps": 1, "n_random": 6, "dts": 2}
    return {"reps": 30, "break_reps": 5, "rounds": 3, "pt_reps": 3, "n_random": 30, "dts": 3}


def run_speed(quick: bool, table: Table, pooltool_python: str | None, allow_setup: bool,
              sizes: dict[str, int] | None = None) -> dict[str, Any]:
    """Time per shot, ours and pooltool's, on the fixed spin shots."""
    from .pooltool_runner import PooltoolSession, PooltoolUnavailable

    n = sizes or _sizes(quick)
    shots = fixed_shots(table)
    sim = Simulator(table, Physics(friction="spin"))
    preset = Physics.from_preset("pooltool")
    sim_p = Simulator(table, preset)
    struck = [s.struck() for s in shots]
    struck_p = [s.balls.strike(s.ball, s.angle, s.speed, side=s.side, top=s.top, physics=preset) for s in shots]
    for b, bp in zip(struck, struck_p):
        sim.run(b)
        sim_p.run(bp)
    reps = [n["break_reps"] if "break" in s.name else n["reps"] for s in shots]
    ours: dict[str, list[float]] = {s.name: [] for s in shots}
    ours_nv: dict[str, list[float]] = {s.name: [] for s in shots}
    ours_p: dict[str, list[float]] = {s.name: [] for s in shots}
    pt_times: dict[str, list[float]] = {s.name: [] for s in shots}
    pt_events: dict[str, int] = {}
    out: dict[str, Any] = {"time": time.strftime("%Y-%m-%d %H:%M:%S")}
    session = None
    try:
        session = PooltoolSession([(s.name, [s]) for s in shots], table.length, table.width, python=pooltool_python,
                                  allow_setup=allow_setup)
        out["pooltool"] = dict(session.ready, available=True)
    except PooltoolUnavailable as exc:
        out["pooltool"] = {"available": False, "note": str(exc)}
        log(f"[spin] pooltool skipped: {exc}")
    try:
        for _ in range(n["rounds"]):
            for s, b, bp, r in zip(shots, struck, struck_p, reps):
                for run, store in ((lambda: sim.run(b), ours), (lambda: sim.run(b, validate=False), ours_nv),
                                   (lambda: sim_p.run(bp), ours_p)):
                    for _k in range(r):
                        t = time.perf_counter()
                        run()
                        store[s.name].append(time.perf_counter() - t)
                if session is not None:
                    ans = session.time(s.name, n["pt_reps"])
                    pt_times[s.name].extend(ans["times"][0])
                    pt_events[s.name] = ans["events"][0]
    except PooltoolUnavailable as exc:
        out["pooltool"] = {"available": False, "note": str(exc)}
        session = None
    finally:
        if session is not None:
            session.close()
    rows = []
    for s, b, bp in zip(shots, struck, struck_p):
        res = sim.run(b)
        res_p = sim_p.run(bp)
        row = {"shot": s.name, "side": s.side, "top": s.top, "speed": s.speed, "n_balls": len(s.balls),
               "ours_s": statistics.median(ours[s.name]), "ours_novalidate_s": statistics.median(ours_nv[s.name]),
               "ours_events": res.n_events, "ours_status": res.status,
               "preset_s": statistics.median(ours_p[s.name]), "preset_events": res_p.n_events}
        if pt_times[s.name]:
            pt = statistics.median(pt_times[s.name])
            row.update(pooltool_s=pt, pooltool_events=pt_events[s.name], speedup=pt / row["ours_s"],
                       preset_speedup=pt / row["preset_s"])
        rows.append(row)
        log(f"[spin] {s.name}: ours {fmt_time(row['ours_s'])} ({res.n_events} events), preset "
            f"{fmt_time(row['preset_s'])} ({res_p.n_events} events)"
            + (f", pooltool {fmt_time(row['pooltool_s'])}: {row['speedup']:.0f}x, preset {row['preset_speedup']:.0f}x"
               if "speedup" in row else ""))
    out["rows"] = rows
    return out


def run_accuracy(quick: bool, table: Table, sizes: dict[str, int] | None = None) -> dict[str, Any]:
    """The step solver against exact on spin shots: final-position error, outcome changes, time per shot."""
    n = sizes or _sizes(quick)
    physics = Physics(friction="spin")
    shots = [s for s in fixed_shots(table) if "break" not in s.name] + random_spin_shots(n["n_random"], 21, table)
    exact = Simulator(table, physics)
    ref = []
    t_exact = []
    for s in shots:
        b = s.struck()
        t = time.perf_counter()
        ref.append(exact.run(b))
        t_exact.append(time.perf_counter() - t)
    cells = []
    for contact in CONTACTS:
        for dt in DTS[: n["dts"]]:
            sim = Simulator(table, physics, solver="step", dt=dt, contact=contact)
            errs, diffs, times = [], 0, []
            for s, r0 in zip(shots, ref):
                t = time.perf_counter()
                r = sim.run(s.struck())
                times.append(time.perf_counter() - t)
                on = r0.balls.on_table & r.balls.on_table
                errs.append(float(np.mean(np.hypot(*(r.balls.pos[on] - r0.balls.pos[on]).T))) if on.any() else 0.0)
                diffs += int(not np.array_equal(r0.pocket >= 0, r.pocket >= 0))
            cells.append({"solver": f"step-{contact}", "dt": dt, "n_shots": len(shots),
                          "time_s": statistics.median(times), "pos_err_mean_mm": 1e3 * float(np.mean(errs)),
                          "pos_err_max_mm": 1e3 * float(np.max(errs)), "outcome_diff_rate": diffs / len(shots)})
            log(f"[spin] step-{contact} dt={dt:g}: {fmt_time(cells[-1]['time_s'])}/shot, mean error "
                f"{cells[-1]['pos_err_mean_mm']:.3g} mm, outcome differs {100 * cells[-1]['outcome_diff_rate']:.0f}%")
    return {"n_shots": len(shots), "exact_time_s": statistics.median(t_exact), "cells": cells}


def render_markdown(doc: dict[str, Any]) -> str:
    L = ["# Spin model: speed, and the step solver's speed against error", "",
         "Produced by `python -m benchmarks --only spin` (see `benchmarks/spin.py`). Medians of repeated runs after "
         "a warm-up, on the machine below; ratios measured in the same run, interleaved.", "",
         machine_markdown(doc["machine"], doc.get("end_load")), ""]
    sp = doc["speed"]
    p = sp["pooltool"]
    L.append(f"## Time per shot against pooltool ({sp['time']})")
    L.append("")
    if p.get("available"):
        L.append(f"pooltool {p.get('version')} with its default physics (frictional ball-ball collisions with "
                 "Alciatore's friction, Stronge's compliant cushions, squirt, pockets) and its own cue strike given "
                 "the same ball speed and tip offsets; ours: the `exact` solver, `Simulator.run` (validating the "
                 "balls), of the spin model (also with `validate=False`) and of the `pooltool` preset, which plays "
                 "pooltool's default physics (its event counts differ from pooltool's only by the pocket geometry: "
                 "pooltool's pockets have jaws). Target: the preset at least 100x pooltool's speed.")
    else:
        L.append(f"pooltool not run: {p.get('note')}")
    L.append("")
    L.append("| shot | tip (side, top) | spin run() | spin validate=False | preset run() | pooltool | speed-up "
             "spin | speed-up preset | events spin / preset / pooltool |")
    L.append("|---|---|---|---|---|---|---|---|---|")
    for r in sp["rows"]:
        pt = fmt_time(r.get("pooltool_s")) if "pooltool_s" in r else "-"
        su = f"{r['speedup']:.0f}x" if "speedup" in r else "-"
        sp_ = (f"{r['preset_speedup']:.0f}x" + (" (>= 100x: pass)" if r["preset_speedup"] >= TARGET_SPEEDUP else
                                                " (>= 100x: **miss**)")) if "preset_speedup" in r else "-"
        ev = f"{r['ours_events']} / {r.get('preset_events', '-')} / {r.get('pooltool_events', '-')}"
        L.append(f"| {r['shot']} | ({r['side']:g}, {r['top']:g}) | {fmt_time(r['ours_s'])} | "
                 f"{fmt_time(r['ours_novalidate_s'])} | {fmt_time(r.get('preset_s'))} | {pt} | {su} | {sp_} | "
                 f"{ev} |")
    acc = doc["accuracy"]
    L += ["", f"## Speed against error of `step` on spin shots ({acc['n_shots']} shots)", "",
          "The four fixed two-ball shots above and random two-ball shots (random places, a random cut, 0.5-3 m/s, "
          "a tip offset anywhere on the disc); error: mean distance of the final positions of the balls left on "
          f"the table from `exact`'s. `exact`: {fmt_time(acc['exact_time_s'])} per shot.", "",
          "| solver | dt | time/shot | mean error | max error | outcome differs |", "|---|---|---|---|---|---|"]
    for c in acc["cells"]:
        L.append(f"| {c['solver']} | {c['dt']:g} s | {fmt_time(c['time_s'])} | {c['pos_err_mean_mm']:.3g} mm | "
                 f"{c['pos_err_max_mm']:.3g} mm | {100 * c['outcome_diff_rate']:.0f}% |")
    L.append("")
    return "\n".join(L)


def render(out: Path) -> None:
    """Re-write ``spin.md`` from ``spin.json``, without measuring."""
    rerender(out, "spin", render_markdown)


def main(out: Path | None, quick: bool = False, pooltool_python: str | None = None, allow_setup: bool = False) -> dict:
    """Run both parts; write ``spin.json`` and ``spin.md`` into ``out`` if given, else print the report."""
    table = Table()
    doc = {"machine": machine_info(), "quick": quick}
    doc["speed"] = run_speed(quick, table, pooltool_python, allow_setup)
    doc["accuracy"] = run_accuracy(quick, table)
    doc["end_load"] = load_now()
    if out is None:
        print(render_markdown(doc), flush=True)
        return doc
    out.mkdir(parents=True, exist_ok=True)
    write_json(out / "spin.json", doc)
    (out / "spin.md").write_text(render_markdown(doc))
    log(f"[spin] wrote {out / 'spin.md'}")
    return doc
