"""Speed against error: the ``step`` solver at a series of ``dt`` (both contact treatments) against ``exact``.

For every friction law and shot category (one-ball, three-ball, 15-ball break) the ``exact`` solver runs each
shot once as the reference; then ``step`` runs the same shots at each ``dt`` and each shot's final state is
compared with the reference: position error over the balls on the table in both, whether the set of pocketed
balls differs, the collisions the step solver tunnelled through. A chaos floor is calibrated by re-running
``exact`` with the aim nudged by tiny angles: below it no solver can be judged on final positions.

Timing: ``Simulator.run(balls, validate=False)`` (validation is the same Python cost for every solver), after a
warm-up call; a shot slower than 50 ms is timed once, faster ones 3 to 20 times (until the calls total 2 ms),
taking the median; per cell the median over its shots. Small ``dt`` is expensive (cost ~ 1/dt): each cell has
a cap on its shot count and a time budget, predicting each shot's cost from the steps it will take (the
reference's duration / dt) and the cost per step measured at the previous, larger dt; the shots a cell used are
the first ones of the fixed list.
"""
from __future__ import annotations

import json
import math
import statistics
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from billiards_env.physics import ShotResult, Simulator, Table

from .common import (Shot, break_shots, fmt_num, fmt_rate, fmt_time, load_now, log, machine_info, machine_markdown,
                     one_ball_shots, physics_description, physics_laws, straight_shot, three_ball_shots, time_call,
                     write_json)

CATEGORIES = ("one_ball", "three_ball", "break")
CATEGORY_NAMES = {"one_ball": "one-ball (cue + 1)", "three_ball": "three-ball (cue + 2)", "break": "15-ball break"}
CONTACTS = ("lecture", "rewind")
DEFAULT_DTS = (1 / 30, 1 / 60, 1 / 120, 1 / 240, 1e-3, 1e-4, 1e-5)
NUDGES = (1e-9, 1e-6, 1e-4)
#: A step cell whose mean position error is below this (mm) is "accurate" for the exact-is-faster target.
ACCURATE_MM = 1.0


@dataclass
class AccuracyConfig:
    """The size of the accuracy suite. ``caps`` maps a dt to the most shots per category run at that dt
    (dts not listed run every shot); ``cell_budget_s`` is the time budget of one (law, category, contact, dt)
    cell."""

    n_shots: dict[str, int]
    dts: tuple[float, ...] = DEFAULT_DTS
    caps: dict[float, dict[str, int]] = field(default_factory=dict)
    cell_budget_s: float = 15.0
    #: The first shot of a cell runs if predicted to take at most this long (so most cells get one shot).
    first_shot_max_s: float = 30.0
    laws: tuple[str, ...] = ("rolling", "drag")
    contacts: tuple[str, ...] = CONTACTS
    nudges: tuple[float, ...] = NUDGES
    seed: int = 1

    def cap(self, dt: float, category: str) -> int:
        for d, caps in self.caps.items():
            if math.isclose(d, dt, rel_tol=1e-9):
                return min(caps.get(category, self.n_shots[category]), self.n_shots[category])
        return self.n_shots[category]


FULL = AccuracyConfig(
    n_shots={"one_ball": 40, "three_ball": 20, "break": 5},
    caps={1e-4: {"one_ball": 20, "three_ball": 10, "break": 3}, 1e-5: {"one_ball": 5, "three_ball": 3, "break": 1}},
    cell_budget_s=15.0,
    first_shot_max_s=90.0,
)
QUICK = AccuracyConfig(
    n_shots={"one_ball": 10, "three_ball": 5, "break": 2},
    dts=(1 / 30, 1 / 60, 1 / 240, 1e-3, 1e-4),
    caps={1e-4: {"one_ball": 2, "three_ball": 1, "break": 1}},
    cell_budget_s=0.6,
    first_shot_max_s=1.2,
)


def dt_label(dt: float) -> str:
    inv = 1.0 / dt
    if abs(inv - round(inv)) < 1e-6 and round(inv) in (30, 60, 120, 240, 480):
        return f"1/{round(inv)}"
    return f"{dt:.0e}".replace("e-0", "e-")


def make_shots(cfg: AccuracyConfig, table: Table) -> dict[str, list[Shot]]:
    return {
        "one_ball": one_ball_shots(cfg.n_shots["one_ball"], seed=cfg.seed, table=table),
        "three_ball": three_ball_shots(cfg.n_shots["three_ball"], seed=cfg.seed + 1, table=table),
        "break": break_shots(cfg.n_shots["break"], table=table),
    }


def pocketed_set(res: ShotResult) -> frozenset[int]:
    return frozenset(int(i) for i in np.flatnonzero(res.pocket >= 0))


def compare(a: ShotResult, b: ShotResult) -> tuple[np.ndarray, bool]:
    """Final position differences (m) of the balls on the table in both, and whether the pocketed sets differ."""
    both = a.balls.on_table & b.balls.on_table
    err = np.linalg.norm(a.balls.pos[both] - b.balls.pos[both], axis=1)
    return err, pocketed_set(a) != pocketed_set(b)


def _summary(errs: list[np.ndarray]) -> tuple[float | None, float | None, int]:
    e = np.concatenate(errs) if errs else np.zeros(0)
    if len(e) == 0:
        return None, None, 0
    return float(e.mean() * 1e3), float(e.max() * 1e3), int(len(e))


def run_accuracy(cfg: AccuracyConfig, table: Table | None = None, progress: bool = True) -> dict[str, Any]:
    """Run the suite; returns the JSON-ready document (``cells``, ``exact``, ``chaos``, ``config``)."""
    table = table or Table()
    t_start = time.perf_counter()
    laws = physics_laws()
    shots = make_shots(cfg, table)
    warm = straight_shot(table).struck()
    exact_rows: list[dict[str, Any]] = []
    chaos_rows: list[dict[str, Any]] = []
    cells: list[dict[str, Any]] = []
    for law in cfg.laws:
        phys = laws[law]
        ex = Simulator(table, phys, solver="exact")
        ex.run(warm, validate=False)
        for cat in CATEGORIES:
            cat_shots = shots[cat]
            if not cat_shots:
                continue
            ref: list[ShotResult] = []
            ref_time: list[float] = []
            self_err = 0.0
            for shot in cat_shots:
                b = shot.struck()
                el, res = time_call(lambda: ex.run(b, validate=False))
                again = ex.run(b, validate=False)
                e, diff = compare(res, again)
                self_err = max(self_err, float(e.max(initial=0.0)) * 1e3 + (1e9 if diff else 0.0))
                ref.append(res)
                ref_time.append(el)
            n = len(cat_shots)
            exact_rows.append({
                "law": law, "category": cat, "solver": "exact", "n_shots": n,
                "median_time_s": statistics.median(ref_time), "mean_time_s": statistics.fmean(ref_time),
                "shots_per_s": n / sum(ref_time), "per_shot_time_s": ref_time,
                "self_error_max_mm": self_err,
                "median_events": statistics.median([r.n_events for r in ref]),
                "median_sim_time_s": statistics.median([r.time for r in ref]),
                "max_sim_time_s": max(r.time for r in ref),
                "mean_pocketed": statistics.fmean([len(pocketed_set(r)) for r in ref]),
                "statuses": sorted({r.status for r in ref}),
            })
            for nudge in cfg.nudges:
                errs, n_diff = [], 0
                for shot, r0 in zip(cat_shots, ref):
                    e, diff = compare(ex.run(shot.struck(nudge), validate=False), r0)
                    errs.append(e)
                    n_diff += diff
                mean_mm, max_mm, n_balls = _summary(errs)
                chaos_rows.append({"law": law, "category": cat, "nudge_rad": nudge, "n_shots": n,
                                   "outcome_change_rate": n_diff / n, "n_outcome_changed": n_diff,
                                   "pos_div_mean_mm": mean_mm, "pos_div_max_mm": max_mm, "n_balls": n_balls})
            if progress:
                log(f"[accuracy] {law:7s} {cat:10s} exact: {n} shots, median {fmt_time(statistics.median(ref_time))}")

            for contact in cfg.contacts:
                ns_per_step: float | None = None
                for dt in sorted(cfg.dts, reverse=True):
                    sim = Simulator(table, phys, solver="step", dt=dt, contact=contact)
                    sim.run(warm, validate=False)  # compile / load the kernel before timing
                    cap = cfg.cap(dt, cat)
                    times, errs, used = [], [], 0
                    n_diff = tunnelled = shots_tunnelled = time_caps = steps = 0
                    skipped = None
                    spent = 0.0
                    for shot, r0 in zip(cat_shots[:cap], ref[:cap]):
                        if ns_per_step is not None:
                            predicted = ns_per_step * 1e-9 * max(r0.time, dt) / dt
                            limit = max(cfg.first_shot_max_s, cfg.cell_budget_s) if used == 0 else cfg.cell_budget_s
                            if spent + predicted > limit:
                                if used == 0:
                                    skipped = (f"predicted {predicted:.1f} s for one shot, over the limit of "
                                               f"{limit:g} s")
                                break
                        b = shot.struck()
                        el, res = time_call(lambda: sim.run(b, validate=False))
                        spent += el
                        used += 1
                        times.append(el)
                        steps += res.n_steps
                        e, diff = compare(res, r0)
                        errs.append(e)
                        n_diff += diff
                        tunnelled += res.n_tunnelled
                        shots_tunnelled += res.n_tunnelled > 0
                        time_caps += res.status != "rest"
                    if used:
                        ns_per_step = sum(times) / max(steps, 1) * 1e9
                    mean_mm, max_mm, n_balls = _summary(errs)
                    ex_t = ref_time[:used]
                    cell = {
                        "law": law, "category": cat, "solver": f"step-{contact}", "contact": contact, "dt": dt,
                        "dt_label": dt_label(dt), "n_shots": used, "n_available": n, "cap": cap,
                        "skipped": skipped,
                        "median_time_s": statistics.median(times) if times else None,
                        "mean_time_s": statistics.fmean(times) if times else None,
                        "shots_per_s": used / sum(times) if times else None,
                        "ns_per_step": ns_per_step if used else None,
                        "pos_err_mean_mm": mean_mm, "pos_err_max_mm": max_mm, "n_balls_compared": n_balls,
                        "outcome_diff_rate": n_diff / used if used else None, "n_outcome_diff": n_diff,
                        "n_tunnelled": tunnelled, "shots_with_tunnelling": shots_tunnelled,
                        "n_not_rest": time_caps,
                        "exact_median_time_s": statistics.median(ex_t) if ex_t else None,
                        "per_shot_time_s": times,
                    }
                    if times and ex_t:
                        cell["exact_speedup"] = cell["median_time_s"] / cell["exact_median_time_s"]
                    cells.append(cell)
                    if progress:
                        msg = (f"[accuracy] {law:7s} {cat:10s} {contact:7s} dt={dt_label(dt):5s} "
                               f"{used}/{n} shots, median {fmt_time(cell['median_time_s'])}, "
                               f"err {fmt_num(mean_mm)} mm, outcome diff {n_diff}/{used}, tunnelled {tunnelled}")
                        log(msg + (f" [{skipped}]" if skipped else ""))
    return {
        "config": {
            "n_shots": cfg.n_shots, "dts": list(cfg.dts), "dt_labels": [dt_label(d) for d in cfg.dts],
            "caps": {dt_label(k): v for k, v in cfg.caps.items()}, "cell_budget_s": cfg.cell_budget_s,
            "first_shot_max_s": cfg.first_shot_max_s,
            "laws": list(cfg.laws), "contacts": list(cfg.contacts), "nudges_rad": list(cfg.nudges),
            "seed": cfg.seed, "physics": {k: physics_description()[k] for k in cfg.laws},
            "table": {"length": table.length, "width": table.width,
                      "cushion_restitution": table.cushion_restitution},
        },
        "exact": exact_rows,
        "chaos": chaos_rows,
        "cells": cells,
        "wall_time_s": time.perf_counter() - t_start,
    }


# --------------------------------------------------------------------------------------------------- reporting

def exact_faster_check(doc: dict[str, Any]) -> dict[str, Any]:
    """Target: ``exact`` faster than ``step`` at every dt whose mean error is below 1 mm (same shots)."""
    rows = []
    for c in doc["cells"]:
        if c["pos_err_mean_mm"] is None or c["n_shots"] == 0:
            continue
        if c["pos_err_mean_mm"] < ACCURATE_MM:
            rows.append({"law": c["law"], "category": c["category"], "solver": c["solver"],
                         "dt": c["dt_label"], "err_mm": c["pos_err_mean_mm"],
                         "exact_speedup": c.get("exact_speedup"),
                         "pass": bool(c.get("exact_speedup") and c["exact_speedup"] > 1.0)})
    return {"cells": rows, "pass": all(r["pass"] for r in rows) if rows else None,
            "min_speedup": min((r["exact_speedup"] for r in rows if r["exact_speedup"]), default=None)}


def _chaos_lookup(doc: dict[str, Any]) -> dict[tuple[str, str, float], dict[str, Any]]:
    return {(r["law"], r["category"], r["nudge_rad"]): r for r in doc["chaos"]}


def chaos_notes(doc: dict[str, Any]) -> list[str]:
    """Where chaos makes final positions meaningless as an error measure."""
    notes = []
    chaos = _chaos_lookup(doc)
    for law in doc["config"]["laws"]:
        for cat in CATEGORIES:
            smallest = chaos.get((law, cat, min(doc["config"]["nudges_rad"])))
            if smallest is None:
                continue
            if smallest["outcome_change_rate"] > 0 or (smallest["pos_div_mean_mm"] or 0) > ACCURATE_MM:
                notes.append(
                    f"**{law}, {CATEGORY_NAMES[cat]}**: turning the aim by {smallest['nudge_rad']:g} rad already "
                    f"moves the final positions by {fmt_num(smallest['pos_div_mean_mm'])} mm on average (max "
                    f"{fmt_num(smallest['pos_div_max_mm'])} mm) and changes the outcome in "
                    f"{smallest['outcome_change_rate']:.0%} of the shots: final positions here measure chaos, "
                    "not the solver; compare outcomes, and expect even those to differ at some rate.")
    return notes


def render_markdown(doc: dict[str, Any], info: dict[str, Any], png_name: str | None) -> str:
    cfg = doc["config"]
    lines = ["# Speed against error: `step` vs `exact`", ""]
    lines.append(machine_markdown(info, doc.get("end_load")))
    lines.append("")
    lines.append("Produced by `python -m benchmarks --only accuracy` "
                 f"({'quick' if doc.get('quick') else 'full'} configuration, {doc['wall_time_s']:.0f} s). "
                 "Shots: seeded random one-ball shots (cue + 1 object ball, aimed at it with a random cut, "
                 "0.5-3 m/s), three-ball shots (cue + 2, 0.5-4 m/s), 15-ball breaks (touching rack, cue ball "
                 "on the head string at several places, aimed at the apex ball, 8 m/s). Physics: "
                 + "; ".join(f"{k}: {v}" for k, v in cfg["physics"].items()) + ".")
    lines.append("")
    lines.append("Columns: median wall time per shot (`Simulator.run(..., validate=False)`, warm; a shot under "
                 "50 ms is timed 3-20 times and its median kept), shots per "
                 "second (shots / total time), how many times slower than `exact` on the same shots, mean and "
                 "max final-position error (mm) against `exact` over the balls on the table in both, the rate of "
                 "shots whose set of pocketed balls differs from `exact`'s, and the collisions the step solver "
                 "tunnelled through (pairs that passed through each other within one step), summed over the "
                 "shots. At small dt only the first shots of each list are run (shown as `used/total`; "
                 f"caps {cfg['caps']}, a budget of {cfg['cell_budget_s']:g} s per cell; a cell's first shot runs "
                 f"if predicted to take at most {cfg.get('first_shot_max_s', 0):g} s).")
    lines.append("")
    if png_name:
        lines.append(f"![error vs time per shot]({png_name})")
        lines.append("")
    exact = {(r["law"], r["category"]): r for r in doc["exact"]}
    chaos = _chaos_lookup(doc)
    for law in cfg["laws"]:
        for cat in CATEGORIES:
            e = exact.get((law, cat))
            if e is None:
                continue
            lines.append(f"## {law}: {CATEGORY_NAMES[cat]} ({e['n_shots']} shots)")
            lines.append("")
            lines.append(f"Reference: median {e['median_events']:g} events, median simulated duration "
                         f"{e['median_sim_time_s']:.1f} s (max {e['max_sim_time_s']:.1f} s), "
                         f"{e['mean_pocketed']:.2f} balls pocketed per shot on average.")
            lines.append("")
            lines.append("| solver | dt | shots | time/shot | shots/s | x exact | mean err (mm) | max err (mm) "
                         "| outcome differs | tunnelled |")
            lines.append("|---|---|---|---|---|---|---|---|---|---|")
            lines.append(f"| exact | - | {e['n_shots']} | {fmt_time(e['median_time_s'])} | "
                         f"{fmt_rate(e['shots_per_s'])} | 1 | {fmt_num(e['self_error_max_mm'])} (re-run) | - | - | - |")
            for c in doc["cells"]:
                if c["law"] != law or c["category"] != cat:
                    continue
                if c["n_shots"] == 0:
                    lines.append(f"| {c['solver']} | {c['dt_label']} | 0/{c['n_available']} | skipped: "
                                 f"{c['skipped']} | | | | | | |")
                    continue
                od = f"{c['outcome_diff_rate']:.0%} ({c['n_outcome_diff']})"
                tun = f"{c['n_tunnelled']} in {c['shots_with_tunnelling']} shots" if c["n_tunnelled"] else "0"
                if c["n_not_rest"]:
                    tun += f"; {c['n_not_rest']} hit max_time"
                lines.append(
                    f"| {c['solver']} | {c['dt_label']} | {c['n_shots']}/{c['n_available']} | "
                    f"{fmt_time(c['median_time_s'])} | {fmt_rate(c['shots_per_s'])} | "
                    f"{fmt_num(c.get('exact_speedup'))} | {fmt_num(c['pos_err_mean_mm'])} | "
                    f"{fmt_num(c['pos_err_max_mm'])} | {od} | {tun} |")
            floor = [chaos.get((law, cat, nd)) for nd in cfg["nudges_rad"]]
            floor_txt = "; ".join(
                f"{r['nudge_rad']:g} rad: {fmt_num(r['pos_div_mean_mm'])} mm mean / {fmt_num(r['pos_div_max_mm'])} "
                f"mm max, outcome changed {r['outcome_change_rate']:.0%}" for r in floor if r)
            lines.append("")
            lines.append(f"Chaos floor (exact, aim nudged by): {floor_txt}.")
            lines.append("")
    lines.append("## Chaos floor")
    lines.append("")
    lines.append("`exact` re-run with the aim turned by a tiny angle: how far the final positions move (mean / max "
                 "over balls on the table in both runs) and how often the set of pocketed balls changes. An "
                 "error against `exact` of the size of the 1e-9 rad divergence is indistinguishable from "
                 "rounding-level differences in the aim: no solver can be judged below it on final positions.")
    lines.append("")
    lines.append("| law | shots | nudge (rad) | mean divergence (mm) | max divergence (mm) | outcome changed |")
    lines.append("|---|---|---|---|---|---|")
    for r in doc["chaos"]:
        lines.append(f"| {r['law']} | {CATEGORY_NAMES[r['category']]} ({r['n_shots']}) | {r['nudge_rad']:g} | "
                     f"{fmt_num(r['pos_div_mean_mm'])} | {fmt_num(r['pos_div_max_mm'])} | "
                     f"{r['outcome_change_rate']:.0%} ({r['n_outcome_changed']}) |")
    lines.append("")
    notes = chaos_notes(doc)
    if notes:
        lines.append("Where chaos dominates:")
        lines.append("")
        lines.extend(f"- {n}" for n in notes)
        lines.append("")
    chk = exact_faster_check(doc)
    lines.append("## Is `exact` faster than every accurate `step`?")
    lines.append("")
    if chk["pass"] is None:
        lines.append(f"No step cell reached a mean error below {ACCURATE_MM:g} mm.")
    else:
        lines.append(f"Step cells with mean error below {ACCURATE_MM:g} mm: {len(chk['cells'])}; `exact` is faster "
                     f"in {sum(r['pass'] for r in chk['cells'])} of them (smallest ratio: step "
                     f"{fmt_num(chk['min_speedup'])}x slower): **{'PASS' if chk['pass'] else 'FAIL'}**.")
        slow = [r for r in chk["cells"] if not r["pass"]]
        for r in slow:
            lines.append(f"- FAIL: {r['law']} {r['category']} {r['solver']} dt={r['dt']}: error "
                         f"{fmt_num(r['err_mm'])} mm, step/exact time {fmt_num(r['exact_speedup'])}")
    lines.append("")
    return "\n".join(lines)


def plot(doc: dict[str, Any], path: Path) -> None:
    """Log-log error vs time per shot per law and category, and outcome mismatch vs time."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    cfg = doc["config"]
    laws = cfg["laws"]
    exact = {(r["law"], r["category"]): r for r in doc["exact"]}
    chaos = _chaos_lookup(doc)
    fig, axes = plt.subplots(len(laws) + 1, 3, figsize=(15, 4.2 * (len(laws) + 1)), squeeze=False)
    colors = {"step-lecture": "tab:blue", "step-rewind": "tab:orange"}
    law_style = {"rolling": "-", "drag": "--"}
    law_marker = {"rolling": "o", "drag": "s"}
    for col, cat in enumerate(CATEGORIES):
        for row, law in enumerate(laws):
            ax = axes[row][col]
            e = exact.get((law, cat))
            for solver, color in colors.items():
                cs = [c for c in doc["cells"] if c["law"] == law and c["category"] == cat and c["solver"] == solver
                      and c["n_shots"] and c["pos_err_mean_mm"] is not None]
                if not cs:
                    continue
                x = [c["median_time_s"] * 1e3 for c in cs]
                y = [max(c["pos_err_mean_mm"], 1e-7) for c in cs]
                ymax = [max(c["pos_err_max_mm"], 1e-7) for c in cs]
                ax.plot(x, y, "o-", color=color, label=f"{solver} mean")
                ax.plot(x, ymax, "v:", color=color, alpha=0.5, label=f"{solver} max")
                for c, xi, yi in zip(cs, x, y):
                    ax.annotate(c["dt_label"], (xi, yi), textcoords="offset points", xytext=(4, 4), fontsize=7,
                                color=color)
            if e:
                ax.axvline(e["median_time_s"] * 1e3, color="k", lw=1.2, label="exact (error 0)")
            for nudge, ls in zip(cfg["nudges_rad"], (":", "-.", "--")):
                r = chaos.get((law, cat, nudge))
                if r and r["pos_div_mean_mm"]:
                    ax.axhline(max(r["pos_div_mean_mm"], 1e-7), color="gray", ls=ls, lw=1,
                               label=f"chaos floor {nudge:g} rad")
            ax.axhline(ACCURATE_MM, color="green", lw=0.8, alpha=0.5, label="1 mm")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_title(f"{law}: {CATEGORY_NAMES[cat]}", fontsize=10)
            ax.set_xlabel("median time per shot (ms)")
            ax.set_ylabel("final position error (mm)")
            ax.grid(True, which="both", alpha=0.25)
            if row == 0 and col == 0:
                ax.legend(fontsize=7, loc="lower left")
        ax = axes[len(laws)][col]
        for law in laws:
            for solver, color in colors.items():
                cs = [c for c in doc["cells"] if c["law"] == law and c["category"] == cat and c["solver"] == solver
                      and c["n_shots"]]
                if cs:
                    ax.plot([c["median_time_s"] * 1e3 for c in cs], [100 * c["outcome_diff_rate"] for c in cs],
                            marker=law_marker.get(law, "o"), ls=law_style.get(law, "-"), color=color,
                            label=f"{law} {solver}", alpha=0.85)
            r = chaos.get((law, cat, min(cfg["nudges_rad"])))
            if r:
                ax.axhline(100 * r["outcome_change_rate"], color="gray", ls=law_style.get(law, "-"), lw=1,
                           label=f"{law} chaos floor {r['nudge_rad']:g} rad")
        ax.set_xscale("log")
        ax.set_xlabel("median time per shot (ms)")
        ax.set_ylabel("shots with a different outcome (%)")
        ax.set_title(f"outcome vs exact: {CATEGORY_NAMES[cat]}", fontsize=10)
        ax.grid(True, which="both", alpha=0.25)
        if col == 0:
            ax.legend(fontsize=7)
    fig.suptitle("step solver vs exact: final-position error and outcome mismatch against time per shot "
                 "(labels: dt in s)", fontsize=11)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def render(out: Path) -> None:
    """Re-write ``speed_vs_error.md`` and the plot from ``speed_vs_error.json`` without measuring."""
    doc = json.loads((out / "speed_vs_error.json").read_text())
    doc["target_exact_faster"] = exact_faster_check(doc)
    write_json(out / "speed_vs_error.json", doc)
    png = out / "speed_vs_error.png"
    plot(doc, png)
    (out / "speed_vs_error.md").write_text(render_markdown(doc, doc["machine"], png.name))


def main(out: Path | None, quick: bool = False, cfg: AccuracyConfig | None = None) -> dict[str, Any]:
    """Measure; write ``speed_vs_error.md/.json/.png`` into ``out`` if given, else print the report."""
    cfg = cfg or (QUICK if quick else FULL)
    info = machine_info()
    doc = run_accuracy(cfg)
    doc["quick"] = quick
    doc["end_load"] = load_now()
    doc["machine"] = info
    doc["target_exact_faster"] = exact_faster_check(doc)
    if out is None:
        print(render_markdown(doc, info, None), flush=True)
        return doc
    out.mkdir(parents=True, exist_ok=True)
    write_json(out / "speed_vs_error.json", doc)
    png = out / "speed_vs_error.png"
    try:
        plot(doc, png)
        png_name = png.name
    except ImportError as exc:
        log(f"[accuracy] no plot: {exc}")
        png_name = None
    (out / "speed_vs_error.md").write_text(render_markdown(doc, info, png_name))
    log(f"[accuracy] wrote {out / 'speed_vs_error.md'} ({doc['wall_time_s']:.0f} s)")
    return doc
