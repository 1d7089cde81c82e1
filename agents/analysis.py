"""Where a one-ball agent loses its points: every table of an evaluation played, and its misses classified.

    python -m agents.analysis runs/main/one_ball_sac-20261201-120000 --episodes 1000 --out runs/analysis
    python -m agents.analysis runs/<run> --baselines geometric search     # also which tables they pot

Episode ``k`` is ``reset(seed=seed + k)`` of the run's env (``env.json`` / ``config.yaml``), as in
:mod:`agents.evaluate`, so the same tables as the main job's evaluation. For each table the agent's shot is read
back into geometry: the direction the object ball leaves in (the line of centres at the cue ball's first touch,
:func:`object_direction`), the pocket whose entry window it points into (:func:`billiards_env.physics.aim.pocket_window`,
the directions along which the object ball enters the capture circle before touching a cushion), and whether it
leaves fast enough to reach it (the engine's motion law). A failed table gets one class (:data:`CLASSES`):

- ``scratch, object potted`` / ``scratch, object not potted``: the cue ball went in;
- ``no direct hit``: the cue ball's line misses the object ball (it hits it off a cushion, or not at all);
- ``aim``: the object ball left outside every pocket's window (the error: angle to the nearest window edge);
- ``too soft``: inside a window, but too slow to reach the pocket;
- ``other``: inside a window and fast enough, yet not potted (a jaw graze between window samples...).

The table's difficulty comes from the geometric player's easiest shot (:func:`billiards_env.players.ghost_ball_shots`):
its cut angle, the object ball's distance to its pocket, the cue-angle tolerance; plus the object ball's clearance
to the nearest cushion and the cue -> object distance. The report gives the pocket rate binned by each, the
failure classes, and (``--baselines``) how many of the agent's failures a baseline pots. Files in ``--out``:
``analysis.md``, ``analysis.json`` (summary + one row per table).
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from billiards_env.physics.aim import (aim_angle, cut_angle, direction_vector, object_ball_speed, pocket_window,
                                       ray_circle_entry, wrap_angle)
from billiards_env.physics.motion import speed_after_distance, stop_distance
from billiards_env.players import BASELINES, ghost_ball_shots

from .evaluate import baseline_player, model_player, run_player

#: Failure classes, in the order they are tested.
CLASSES = ("scratch, object potted", "scratch, object not potted", "no direct hit", "aim", "too soft", "other")

#: Bins of the report: (name, row key, edges, unit).
BINS: tuple[tuple[str, str, tuple[float, ...], str], ...] = (
    ("cut angle of the easiest shot", "cut_deg", (0, 15, 30, 45, 60, 75, 91), "deg"),
    ("object ball -> pocket distance", "d_obj", (0, 0.3, 0.6, 1.0, 1.5, 3.0), "m"),
    ("cue -> object ball distance", "d_cue", (0, 0.3, 0.6, 1.0, 1.5, 3.0), "m"),
    ("object ball clearance to the nearest cushion", "rail_gap", (0, 0.1, 0.2, 0.3, 1.0), "m"),
    ("cue-angle tolerance of the easiest shot", "tolerance_mrad", (0, 0.5, 1, 2, 4, 1000), "mrad"),
    ("offset of the aimed pocket's window from its centre line", "window_offset_deg", (0, 0.5, 1, 2, 5, 180),
     "deg"),
)


def object_direction(cue: np.ndarray, obj: np.ndarray, angle: float, reach: float) -> tuple[float, float] | None:
    """``(direction the object ball leaves in, distance the cue ball travels to the contact)`` for a cue ball
    struck at ``angle`` from ``cue`` (the line of centres at first contact); None if it misses the object ball."""
    ux, uy = math.cos(angle), math.sin(angle)
    d = ray_circle_entry(float(cue[0]), float(cue[1]), ux, uy, float(obj[0]), float(obj[1]), reach)
    if not math.isfinite(d):
        return None
    contact = (cue[0] + ux * d, cue[1] + uy * d)
    return aim_angle(contact, obj), float(d)


def table_geometry(env: Any) -> dict[str, Any]:
    """The table before the shot: distances, the object ball's cushion clearance, every pocket's window and the
    geometric player's easiest shot (cut, distance, tolerance, pocket)."""
    u = env.unwrapped
    b, table, physics = u.balls, u.table, u.physics
    cue, obj = b.pos[0].copy(), b.pos[1].copy()
    r = float(b.radius[1])
    windows = [pocket_window(obj, r, table, p) for p in range(table.n_pockets)]
    shots = ghost_ball_shots(b, table, physics, 0, [1], (u.config.speed_min, u.config.speed_max))
    best = shots[0] if shots else None
    rail_gap = min(obj[0], table.length - obj[0], obj[1], table.width - obj[1]) - r
    return {
        "cue": cue, "obj": obj, "windows": windows,
        "d_cue": float(np.hypot(*(obj - cue))), "rail_gap": float(rail_gap),
        "best_pocket": best.pocket if best else -1,
        "cut_deg": math.degrees(best.cut) if best else 90.0,
        "d_obj": best.d_obj if best else 3.0 - 1e-9,
        "tolerance_mrad": 1000.0 * best.tolerance if best else 0.0,
        "best_speed": best.speed if best else float("nan"),
        "best_clear": bool(best.clear and best.reachable and not best.scratch_risk) if best else False,
    }


def pocket_kind(table: Any, pocket: int) -> str:
    """``corner`` or ``side`` (a pocket not at a corner of the table)."""
    x, y = table.pocket_xy[pocket]
    corner = min(x, table.length - x) < 1e-9 and min(y, table.width - y) < 1e-9
    return "corner" if corner else "side"


def classify(env: Any, geo: dict[str, Any], angle: float, speed: float, info: dict[str, Any]) -> dict[str, Any]:
    """The agent's shot read back into geometry, and its class (``success`` or one of :data:`CLASSES`)."""
    u = env.unwrapped
    b, table, physics = u.balls, u.table, u.physics
    rc, ro = float(b.radius[0]), float(b.radius[1])
    law = physics.path_args
    out: dict[str, Any] = {"speed": float(speed), "pocket": -1, "aim_error_deg": None, "reach_margin": None,
                           "window_offset_deg": 180.0}
    hit = object_direction(geo["cue"], geo["obj"], angle, rc + ro)
    if hit is not None:
        theta, d_contact = hit
        # The pocket whose window holds theta (or, outside all, the nearest window edge).
        best_p, best_err = -1, math.inf
        for p, w in enumerate(geo["windows"]):
            if w is None:
                continue
            err = abs(wrap_angle(theta - w[0])) - w[1]
            if err < best_err:
                best_p, best_err = p, err
        out["pocket"] = best_p
        out["aim_error_deg"] = math.degrees(max(best_err, 0.0)) if best_p >= 0 else None
        if best_p >= 0:  # how far the window's middle lies from the line to the pocket's centre
            centre = aim_angle(geo["obj"], table.pocket_xy[best_p])
            out["window_offset_deg"] = math.degrees(abs(wrap_angle(geo["windows"][best_p][0] - centre)))
        impact = speed_after_distance(speed, d_contact, *law)
        cut = cut_angle(direction_vector(angle), direction_vector(theta))
        v_obj = object_ball_speed(impact, math.cos(cut), physics.ball_restitution, float(b.mass[0]),
                                  float(b.mass[1]))
        out["obj_speed"] = float(v_obj)
        out["cut_deg_played"] = math.degrees(cut)
        if best_p >= 0:
            out["reach_margin"] = float(stop_distance(v_obj, *law, physics.min_speed) - geo["windows"][best_p][2])
            out["pocket_kind"] = pocket_kind(table, best_p)
    potted = bool(info["pocketed"][1])  # a mask over the rows: row 1 the object ball
    if info.get("is_success"):
        kind = "success"
    elif info.get("scratch"):
        kind = CLASSES[0] if potted else CLASSES[1]
    elif hit is None:
        kind = "no direct hit"
    elif out["aim_error_deg"] is None or out["aim_error_deg"] > 0.0:
        kind = "aim"
    elif out["reach_margin"] is not None and out["reach_margin"] < 0.0:
        kind = "too soft"
    else:
        kind = "other"
    out["class"] = kind
    return out


def play_agent(run: str | Path, episodes: int, seed: int) -> tuple[list[dict[str, Any]], Any]:
    """Every table played by the trained agent (deterministic), with its geometry and class."""
    spec = model_player(run)
    env = spec.make_env()
    rows: list[dict[str, Any]] = []
    try:
        for k in range(episodes):
            obs, _ = env.reset(seed=seed + k)
            geo = table_geometry(env)
            action = spec.act(env, obs)
            shot = env.unwrapped.shot_from_action(action)
            obs, reward, term, trunc, info = env.step(action)
            row = {key: v for key, v in geo.items() if key not in ("cue", "obj", "windows")}
            row.update(seed=seed + k, success=bool(info.get("is_success")), scratch=bool(info.get("scratch")),
                       action=[float(x) for x in np.asarray(action).reshape(-1)],
                       cue_xy=geo["cue"].tolist(), obj_xy=geo["obj"].tolist(),
                       best_pocket_kind=pocket_kind(env.unwrapped.table, geo["best_pocket"])
                       if geo["best_pocket"] >= 0 else "none")
            row.update(classify(env, geo, shot.angle, shot.speed, info))
            rows.append(row)
    finally:
        env.close()
    return rows, spec


def _rate(rows: Sequence[dict[str, Any]]) -> str:
    return f"{100.0 * sum(r['success'] for r in rows) / len(rows):.1f}%" if rows else "-"


def summarise(rows: list[dict[str, Any]], baseline_success: dict[str, list[bool]]) -> dict[str, Any]:
    """Counts per class, the pocket rate per bin of each difficulty measure, and the baselines on the failures."""
    n = len(rows)
    fails = [r for r in rows if not r["success"]]
    summary: dict[str, Any] = {
        "episodes": n, "successes": n - len(fails), "pocket_rate": (n - len(fails)) / n if n else 0.0,
        "classes": {c: sum(r["class"] == c for r in fails) for c in CLASSES},
        "bins": {}, "pocket_kind": {}, "baselines_on_failures": {},
    }
    for name, key, edges, unit in BINS:
        table = []
        for lo, hi in zip(edges[:-1], edges[1:]):
            sel = [r for r in rows if lo <= r[key] < hi]
            table.append({"range": f"{lo}-{hi} {unit}", "tables": len(sel), "pocket_rate": _rate(sel),
                          "failures": {c: sum(r["class"] == c for r in sel) for c in CLASSES}})
        summary["bins"][name] = table
    for kind in ("corner", "side"):
        sel = [r for r in rows if r.get("pocket_kind") == kind]
        summary["pocket_kind"][kind] = {"tables": len(sel), "pocket_rate": _rate(sel)}
    aims = [r["aim_error_deg"] for r in fails if r["class"] == "aim" and r["aim_error_deg"] is not None]
    summary["aim_error_deg_median"] = float(np.median(aims)) if aims else None
    soft = [r for r in fails if r["class"] in CLASSES[:2]]
    summary["scratch_speed_median"] = float(np.median([r["speed"] for r in soft])) if soft else None
    summary["scratch_geometric_speed_median"] = float(np.nanmedian([r["best_speed"] for r in soft])) if soft else None
    summary["chose_geometric_pocket"] = _rate([r for r in rows if r["pocket"] == r["best_pocket"]])
    summary["chose_other_pocket"] = _rate([r for r in rows if r["pocket"] != r["best_pocket"]])
    summary["tables_choosing_other_pocket"] = sum(r["pocket"] != r["best_pocket"] for r in rows)
    for name, succ in baseline_success.items():
        by_class = {c: sum(succ[i] for i, r in enumerate(rows) if r["class"] == c) for c in CLASSES}
        summary["baselines_on_failures"][name] = {"pocket_rate": sum(succ) / len(succ),
                                                  "pots_agent_failures": sum(by_class.values()), "by_class": by_class}
    return summary


def markdown(summary: dict[str, Any], run: str, seed: int) -> str:
    n = summary["episodes"]
    lines = [f"# Where the agent fails: {run}", "",
             f"{n} tables (seeds {seed}..{seed + n - 1}); pocket rate **{100 * summary['pocket_rate']:.1f}%** "
             f"({n - summary['successes']} failures).", "",
             "| failure class | tables |" + "".join(f" {b} pots |" for b in summary["baselines_on_failures"]),
             "|---|---|" + "---|" * len(summary["baselines_on_failures"])]
    for c in CLASSES:
        cells = "".join(f" {v['by_class'][c]} |" for v in summary["baselines_on_failures"].values())
        lines.append(f"| {c} | {summary['classes'][c]} |{cells}")
    lines += ["", f"Median aim error of the `aim` failures: {summary['aim_error_deg_median']} deg outside the window; "
              f"median speed of the scratches: {summary['scratch_speed_median']} m/s (the geometric player's speed on "
              f"those tables: {summary['scratch_geometric_speed_median']} m/s). Pocket rate when the agent aims at "
              f"the geometric player's pocket: {summary['chose_geometric_pocket']}, at another "
              f"({summary['tables_choosing_other_pocket']} tables): {summary['chose_other_pocket']}. "
              "By the pocket aimed at: " + ", ".join(f"{k} {v['pocket_rate']} ({v['tables']} tables)"
                                                      for k, v in summary["pocket_kind"].items()) + "."]
    for name, table in summary["bins"].items():
        lines += ["", f"| {name} | tables | pocket rate | " + " | ".join(CLASSES) + " |",
                  "|---|---|---|" + "---|" * len(CLASSES)]
        for t in table:
            lines.append(f"| {t['range']} | {t['tables']} | {t['pocket_rate']} | "
                         + " | ".join(str(t["failures"][c]) for c in CLASSES) + " |")
    return "\n".join(lines) + "\n"


def analyse(run: str | Path, episodes: int = 1000, seed: int = 100_000, out: str | Path | None = None,
            baselines: Sequence[str] = ()) -> dict[str, Any]:
    """Play, classify, summarise; write ``analysis.md`` / ``analysis.json`` into ``out`` (if given)."""
    t0 = time.perf_counter()
    rows, spec = play_agent(run, episodes, seed)
    base: dict[str, list[bool]] = {}
    for name in baselines:
        _, brows = run_player(baseline_player(name, spec.env_id, spec.env_kwargs), episodes, seed)
        base[name] = [r["success"] for r in brows]
    summary = summarise(rows, base)
    summary.update(run=str(run), seed=seed, env_id=spec.env_id, env_kwargs=spec.env_kwargs,
                   seconds=time.perf_counter() - t0)
    if out is not None:
        out = Path(out)
        out.mkdir(parents=True, exist_ok=True)
        (out / "analysis.md").write_text(markdown(summary, str(run), seed))
        (out / "analysis.json").write_text(json.dumps({"summary": summary, "tables": rows}, indent=1, default=str))
    return summary


def main(argv: Sequence[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m agents.analysis", description=__doc__.split("\n\n")[0])
    p.add_argument("run", help="run folder (its best_model.zip) or model .zip of a one-ball agent")
    p.add_argument("--episodes", type=int, default=1000)
    p.add_argument("--seed", type=int, default=100_000, help="table k is reset(seed=seed + k), as agents.main")
    p.add_argument("--baselines", nargs="*", default=[], choices=BASELINES)
    p.add_argument("--out", default=None, help="folder for analysis.md / analysis.json")
    args = p.parse_args(argv)
    summary = analyse(args.run, args.episodes, args.seed, args.out, args.baselines)
    print(markdown(summary, args.run, args.seed))
    return 0


if __name__ == "__main__":
    sys.exit(main())
