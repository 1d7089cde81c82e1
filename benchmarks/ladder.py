"""The model ladder: how often each physics model, from the lecture's drag to the ``pooltool`` preset, plays a shot
to the same outcome as the preset, and what it costs. ``python -m benchmarks --only ladder`` writes
``docs/bench/ladder.md`` and ``ladder.json`` (``--quick``: fewer shots); ``python -m benchmarks.ladder --pockets``
measures the pocket rung alone (``--write``: into the committed report, the other rungs kept).

Models (rungs), each a :class:`~billiards_env.physics.Physics`:

- ``drag``: the lecture's friction factor (0.999 per 1/60 s, min speed 5 mm/s), no spin;
- ``rolling``: constant rolling resistance (mu_roll 0.01), no spin (the envs' default today);
- ``spin``: sliding, rolling and spinning balls (Leckie & Greenspan), frictionless ball-ball collisions, the impulse
  cushion at the ball's equator;
- ``spin + throw``: and Alciatore's speed-dependent ball-ball friction (``ball_ball: alciatore``);
- ``spin + throw + cushion``: and Stronge's compliant cushion with the nose at 0.036576 m (the preset without
  squirt);
- ``pooltool``: the preset (and squirt on the strike): the reference.

Scenes (shots), each struck at the centre of the cue ball and with english: ``one ball`` (the one-ball env's
table: cue and object ball at random places, the cue aimed by the ghost ball to pot it in the pocket of the smallest
cut, random speed and tip offset), ``9-ball break`` (the
diamond at the foot spot, the cue ball on the head string, struck at the 1 at 7-9 m/s), ``9-ball run-out`` (2 to 9
balls at random places, the lowest one potted as in ``one ball``), ``off cushions`` (two object balls, the cue ball
struck at random and meeting at least three cushions under the preset). Every rung plays the same shot: the same
cue angle and speed, and for the spin rungs the same tip offsets (``drag`` and ``rolling`` have no spin: their cue
ball leaves rolling).

Outcome agreement with the preset: the same balls pocketed and every ball left on the table within 5 mm of where
the preset leaves it. Speed: CPU time per shot of ``Simulator.run_in_place(balls)`` (the exact solver's kernel on
the ball arrays, as the envs call it), the median of interleaved rounds.
"""
from __future__ import annotations

import json
import math
import statistics
import time
from pathlib import Path
from typing import Any

import numpy as np

from billiards_env.physics import Balls, Physics, Simulator, Table
from billiards_env.physics.aim import cut_angle, ghost_point, path_clear, pocket_window
from billiards_env.physics.layout import diamond_positions, foot_spot

from .common import (DRAG_FACTOR, DRAG_FRAME_DT, DRAG_MIN_SPEED, load_now, log, machine_info, machine_markdown,
                     publish, rerender, write_json)

R = 0.028575
#: Final positions within this of the preset's count as the same outcome (m).
SAME_POSITION = 0.005
#: A shot's tip offsets are drawn in the disc of this radius (fractions of R).
TIP = 0.35


def rungs() -> dict[str, Physics]:
    return {
        "drag": Physics("drag", drag_k=Physics.drag_k_from_factor(DRAG_FACTOR, DRAG_FRAME_DT),
                        min_speed=DRAG_MIN_SPEED),
        "rolling": Physics(),
        "spin": Physics(friction="spin"),
        "spin + throw": Physics(friction="spin", ball_ball="alciatore"),
        "spin + throw + cushion": Physics.from_preset("pooltool", squirt=0.0),
        "pooltool": Physics.from_preset("pooltool"),
    }


REFERENCE = "pooltool"


def describe(physics: Physics) -> str:
    """The fields of ``physics`` that differ from the defaults (``Physics()``)."""
    plain = Physics()
    diff = {f: getattr(physics, f) for f in physics.__dataclass_fields__ if getattr(physics, f) != getattr(plain, f)}
    return ", ".join(f"{k}={v!r}" for k, v in diff.items()) or "the defaults"


class Shot:
    """Balls at rest and the cue ball's strike (angle, speed, tip offsets)."""

    def __init__(self, pos: np.ndarray, angle: float, speed: float, side: float, top: float) -> None:
        self.pos, self.angle, self.speed, self.side, self.top = pos, angle, speed, side, top

    def centre_ball(self) -> "Shot":
        """The same shot struck at the centre of the cue ball (no tip offsets: what an env without spin actions
        plays)."""
        return Shot(self.pos, self.angle, self.speed, 0.0, 0.0)

    def balls(self, physics: Physics) -> Balls:
        spin = physics.has_spin
        return Balls.from_positions(self.pos).strike(0, self.angle, self.speed, side=self.side if spin else 0.0,
                                                     top=self.top if spin else 0.0, physics=physics)


def _tip(rng: np.random.Generator) -> tuple[float, float]:
    rad, th = TIP * math.sqrt(rng.uniform()), rng.uniform(-math.pi, math.pi)
    return rad * math.cos(th), rad * math.sin(th)


def _clear_of_pockets(pos: np.ndarray, table: Table) -> bool:
    d = np.linalg.norm(pos[:, None, :] - table.pocket_xy[None], axis=-1)
    return bool(np.all(d > table.pocket_radius[None] + 2 * R))


def _random_layout(rng: np.random.Generator, table: Table, n: int) -> np.ndarray:
    while True:
        pos = np.column_stack([rng.uniform(R + 0.03, table.length - R - 0.03, n),
                               rng.uniform(R + 0.03, table.width - R - 0.03, n)])
        d = np.linalg.norm(pos[:, None] - pos[None], axis=-1) + np.eye(n)
        if (d > 2 * R + 0.01).all() and _clear_of_pockets(pos, table):
            return pos


def _pot_aim(pos: np.ndarray, target: int, table: Table) -> float | None:
    """The ghost-ball aim that pots ball ``target`` in the pocket of the smallest cut with a clear path, or None."""
    cue = pos[0]
    others = np.delete(pos, [0, target], axis=0)
    best = None
    for p in range(table.n_pockets):
        win = pocket_window(pos[target], R, table, p)
        if win is None:
            continue
        gx, gy = ghost_point(pos[target, 0], pos[target, 1], win[0], 2 * R)
        aim = np.array([gx - cue[0], gy - cue[1]])
        dist = float(np.hypot(*aim))
        if dist < 1e-9:
            continue
        cut = cut_angle(aim / dist, (math.cos(win[0]), math.sin(win[0])))
        if cut > math.radians(70):
            continue
        clearance = np.full(len(others), 2 * R)
        if len(others) and not path_clear(cue, (gx, gy), others, clearance):
            continue
        if best is None or cut < best[0]:
            best = (cut, math.atan2(aim[1], aim[0]))
    return None if best is None else best[1]


def one_ball_shots(n: int, rng: np.random.Generator, table: Table) -> list[Shot]:
    return _pot_shots(n, rng, table, lambda: 2)


def runout_shots(n: int, rng: np.random.Generator, table: Table) -> list[Shot]:
    return _pot_shots(n, rng, table, lambda: int(rng.integers(3, 11)))


def _pot_shots(n: int, rng: np.random.Generator, table: Table, count) -> list[Shot]:
    shots = []
    while len(shots) < n:
        pos = _random_layout(rng, table, count())
        aim = _pot_aim(pos, 1, table)
        if aim is None:
            continue
        shots.append(Shot(pos, aim, float(rng.uniform(1.0, 3.5)), *_tip(rng)))
    return shots


def break_shots(n: int, rng: np.random.Generator, table: Table) -> list[Shot]:
    rack = diamond_positions(foot_spot(table), R)
    shots = []
    for _ in range(n):
        cue = np.array([0.25 * table.length, rng.uniform(0.35, 0.65) * table.width])
        pos = np.vstack([cue[None], rack])
        d = pos[1] - cue
        angle = math.atan2(d[1], d[0]) + rng.uniform(-1.0, 1.0) * 0.2 * R / float(np.hypot(*d))
        side, top = _tip(rng)
        shots.append(Shot(pos, angle, float(rng.uniform(7.0, 9.0)), 0.5 * side, 0.5 * top))
    return shots


def cushion_shots(n: int, rng: np.random.Generator, table: Table, reference: Physics) -> list[Shot]:
    sim = Simulator(table, reference)
    shots = []
    while len(shots) < n:
        pos = _random_layout(rng, table, 3)
        shot = Shot(pos, float(rng.uniform(-math.pi, math.pi)), float(rng.uniform(2.5, 5.0)), *_tip(rng))
        ev = sim.run(shot.balls(reference)).events
        if int(np.sum((ev.kind == 1) & (ev.ball == 0))) >= 3:
            shots.append(shot)
    return shots


def _sizes(quick: bool) -> dict[str, int]:
    return {"shots": 40 if quick else 300, "breaks": 20 if quick else 100, "rounds": 3 if quick else 7}


def _outcome(res) -> tuple[frozenset, np.ndarray, np.ndarray]:
    on = res.balls.on_table
    return frozenset(np.flatnonzero(~on).tolist()), res.balls.pos.copy(), on.copy()


def _same(a, b) -> tuple[bool, float]:
    """Same pocketed balls, and the largest distance between the final positions of the balls on the table."""
    if a[0] != b[0]:
        return False, math.inf
    on = a[2] & b[2]
    d = float(np.max(np.linalg.norm(a[1][on] - b[1][on], axis=1))) if on.any() else 0.0
    return d <= SAME_POSITION, d


def run(quick: bool = False, table: Table | None = None, sizes: dict[str, int] | None = None) -> dict[str, Any]:
    table = table or Table()
    sizes = sizes or _sizes(quick)
    models = rungs()
    ref = models[REFERENCE]
    rng = np.random.default_rng(2026)
    english = {
        "one ball": one_ball_shots(sizes["shots"], rng, table),
        "9-ball break": break_shots(sizes["breaks"], rng, table),
        "9-ball run-out": runout_shots(sizes["shots"], rng, table),
        "off cushions": cushion_shots(sizes["shots"], rng, table, ref),
    }
    families = {}
    for tip in ("centre ball", "english"):
        for fam, shots in english.items():
            families[(tip, fam)] = [s.centre_ball() for s in shots] if tip == "centre ball" else shots
    sims = {name: Simulator(table, ph) for name, ph in models.items()}
    rows = []
    for (tip, fam), shots in families.items():
        log(f"[ladder] {fam}, {tip}: {len(shots)} shots")
        struck = {name: [s.balls(ph) for s in shots] for name, ph in models.items()}
        outcomes = {name: [_outcome(sims[name].run(b, validate=False)) for b in struck[name]] for name in models}
        times: dict[str, list[float]] = {name: [] for name in models}
        for r in range(sizes["rounds"]):
            order = list(models) if r % 2 == 0 else list(models)[::-1]
            for name in order:
                sim = sims[name]
                fresh = [b.copy() for b in struck[name]]
                t = time.process_time()
                for b in fresh:
                    sim.run_in_place(b)
                times[name].append((time.process_time() - t) / len(shots))
        for name in models:
            same = [_same(o, p) for o, p in zip(outcomes[name], outcomes[REFERENCE])]
            dists = [d for ok, d in same if math.isfinite(d)]
            rows.append({"family": fam, "tip": tip, "model": name, "shots": len(shots),
                         "same_outcome": sum(ok for ok, _ in same) / len(shots),
                         "same_pocketed": sum(math.isfinite(d) for _, d in same) / len(shots),
                         "median_pos_diff_mm": 1e3 * statistics.median(dists) if dists else None,
                         "time_per_shot_s": statistics.median(times[name])})
    return {"sizes": sizes, "models": {k: describe(v) for k, v in models.items()}, "rows": rows,
            "reference": REFERENCE, "same_position_m": SAME_POSITION}


def run_pockets(quick: bool = False, sizes: dict[str, int] | None = None) -> list[dict[str, Any]]:
    """The pocket rung: the same shots on the WPA 9-ft table with jaws (``table: {preset: wpa}``) and with capture
    circles calibrated on its mouths (``pockets: capture``), under the ``rolling`` model and the ``pooltool``
    preset. The shots are aimed through the jaw table's mouths (its pocket windows). Per scene: how often the
    capture circles give the jaws' outcome (same balls pocketed, every other ball within 5 mm; in brackets the same
    balls pocketed), and the CPU time per shot of each (median of interleaved rounds)."""
    from billiards_env.physics.table import TABLE_PRESETS
    from billiards_env.physics.scene import parse_table

    sizes = sizes or _sizes(quick)
    jaws = TABLE_PRESETS["wpa"]()
    capture = parse_table({"preset": "wpa", "pockets": "capture"})
    rng = np.random.default_rng(2027)
    scenes = {"one ball": one_ball_shots(sizes["shots"], rng, jaws),
              "9-ball break": break_shots(sizes["breaks"], rng, jaws),
              "9-ball run-out": runout_shots(sizes["shots"], rng, jaws)}
    rows = []
    for model in ("rolling", REFERENCE):
        ph = rungs()[model]
        sims = {"jaws": Simulator(jaws, ph), "capture": Simulator(capture, ph)}
        for fam, shots in scenes.items():
            log(f"[ladder] pockets: {fam}, {model}: {len(shots)} shots")
            struck = [s.balls(ph) for s in shots]
            outcomes = {k: [_outcome(sim.run(b, validate=False)) for b in struck] for k, sim in sims.items()}
            times: dict[str, list[float]] = {k: [] for k in sims}
            for r in range(sizes["rounds"]):
                for k in (("jaws", "capture") if r % 2 == 0 else ("capture", "jaws")):
                    fresh = [b.copy() for b in struck]
                    t = time.process_time()
                    for b in fresh:
                        sims[k].run_in_place(b)
                    times[k].append((time.process_time() - t) / len(shots))
            same = [_same(c, j) for c, j in zip(outcomes["capture"], outcomes["jaws"])]
            t_j, t_c = statistics.median(times["jaws"]), statistics.median(times["capture"])
            rows.append({"family": fam, "model": model, "shots": len(shots),
                         "same_outcome": sum(ok for ok, _ in same) / len(shots),
                         "same_pocketed": sum(math.isfinite(d) for _, d in same) / len(shots),
                         "jaws_pocketed": sum(len(o[0]) for o in outcomes["jaws"]) / len(shots),
                         "capture_pocketed": sum(len(o[0]) for o in outcomes["capture"]) / len(shots),
                         "jaws_s": t_j, "capture_s": t_c, "ratio": t_j / t_c})
    return rows


def render_pockets(rows: list[dict[str, Any]]) -> list[str]:
    lines = ["", "## The pocket rung: capture circles against jaws", "",
             "The same shots on the WPA 9-ft table with jaws (`table: {preset: wpa}`: rails that stop at the "
             "mouths, jaw faces, rounded tips, pocket circles behind the mouths) and with capture circles "
             "calibrated on its mouths (`pockets: capture`), aimed through the jaw table's mouths. Same outcome: "
             "the capture circles pocket the same balls as the jaws and leave every other ball within 5 mm; in "
             "brackets the same balls pocketed. Time: CPU time per shot (`Simulator.run_in_place`, median of "
             "interleaved rounds).", "",
             "| scene | model | shots | same outcome | balls pocketed a shot, jaws / capture | µs a shot, jaws "
             "/ capture | jaws / capture |", "|---|---|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['family']} | `{r['model']}` | {r['shots']} | {100 * r['same_outcome']:.0f}% "
                     f"({100 * r['same_pocketed']:.0f}%) | {r['jaws_pocketed']:.2f} / {r['capture_pocketed']:.2f} | "
                     f"{r['jaws_s'] * 1e6:.1f} / {r['capture_s'] * 1e6:.1f} | {r['ratio']:.2f}x |")
    return lines


def render_markdown(doc: dict[str, Any]) -> str:
    fams = list(dict.fromkeys(r["family"] for r in doc["rows"]))
    tips = list(dict.fromkeys(r["tip"] for r in doc["rows"]))
    models = list(dict.fromkeys(r["model"] for r in doc["rows"]))
    cell = {(r["tip"], r["family"], r["model"]): r for r in doc["rows"]}
    scenes = [(t, f) for t in tips for f in fams]
    head = "| scene | shots | " + " | ".join(f"`{m}`" for m in models) + " |"
    rule = "|---|---:|" + "---:|" * len(models)

    def table(fmt) -> list[str]:
        return [head, rule] + [f"| {f}, {t} | {cell[(t, f, models[0])]['shots']} | "
                               + " | ".join(fmt(cell[(t, f, m)]) for m in models) + " |" for t, f in scenes]

    lines = ["# The model ladder", "",
             "How often each model plays a shot to the same outcome as the `pooltool` preset, and what a shot costs. "
             "Command: `python -m benchmarks --only ladder`. Every scene's shots are played twice: struck at the "
             "centre "
             "of the cue ball (what the envs without spin actions play) and with english (tip offsets anywhere in "
             f"the disc of radius {TIP} R; `drag` and `rolling` have no spin and play those as centre-ball shots).",
             "", f"Same outcome as the preset: the same balls pocketed and every ball left on the table within "
             f"{doc['same_position_m'] * 1e3:.0f} mm of the preset's; in brackets, the same balls pocketed:", ""]
    lines += table(lambda c: f"{100 * c['same_outcome']:.0f}% ({100 * c['same_pocketed']:.0f}%)")
    lines += ["", "Median distance of the final positions from the preset's (mm; shots with the same balls "
              "pocketed):", ""]
    lines += table(lambda c: "-" if c["median_pos_diff_mm"] is None else f"{c['median_pos_diff_mm']:.3g}")
    lines += ["", "CPU time per shot (µs; `Simulator.run_in_place`, the exact solver's kernel as the envs call it; "
              "median of interleaved rounds):", ""]
    lines += table(lambda c: f"{c['time_per_shot_s'] * 1e6:.1f}")
    lines += ["", "Models (fields that differ from `Physics()`):", ""] + \
        [f"- `{m}`: {doc['models'][m]}" for m in models] + [""]
    if doc.get("pockets"):
        lines += render_pockets(doc["pockets"]) + [""]
        if "pockets_machine" in doc:  # the pocket rung measured on its own (run_pockets)
            lines += ["The pocket rung's run: " + machine_markdown(doc["pockets_machine"], doc.get("pockets_end_load")),
                      ""]
    if "machine" in doc:
        lines += [machine_markdown(doc["machine"], doc.get("end_load")), ""]
    return "\n".join(lines)


def render(out: Path) -> None:
    """Re-write ``ladder.md`` from ``ladder.json``, without measuring."""
    rerender(out, "ladder", render_markdown)


def main(out: Path | None, quick: bool = False) -> dict[str, Any]:
    """Measure, print the ladder, and write ``ladder.json`` and ``ladder.md`` into ``out`` if given."""
    doc = {"machine": machine_info(), **run(quick)}
    doc["pockets"] = run_pockets(quick)
    doc["end_load"] = load_now()
    publish(doc, render_markdown(doc), out, "ladder")
    return doc


def main_pockets(out: Path | None, quick: bool = False) -> list[dict[str, Any]]:
    """Measure the pocket rung alone and print it; with ``out``, put it into ``out/ladder.json`` (the other rungs as
    they were, the rung's own machine line) and re-write ``ladder.md``."""
    machine = machine_info()
    rows = run_pockets(quick)
    print("\n".join(render_pockets(rows)))
    if out is not None:
        doc = json.loads((out / "ladder.json").read_text())
        doc.update(pockets=rows, pockets_machine=machine, pockets_end_load=load_now())
        write_json(out / "ladder.json", doc)
        rerender(out, "ladder", render_markdown)
        log(f"[ladder] wrote the pocket rung into {out / 'ladder.md'}")
    return rows


if __name__ == "__main__":
    import argparse

    parser = argparse.ArgumentParser(prog="python -m benchmarks.ladder", description=__doc__.split("\n\n")[0])
    parser.add_argument("--pockets", action="store_true", required=True,
                        help="the pocket rung alone: capture circles against jaws, outcomes and CPU time per shot")
    parser.add_argument("--quick", action="store_true", help="fewer shots")
    parser.add_argument("--write", action="store_true", help="put it into docs/bench/ladder.json and ladder.md")
    args = parser.parse_args()
    main_pockets(Path(__file__).resolve().parents[1] / "docs" / "bench" if args.write else None, args.quick)
