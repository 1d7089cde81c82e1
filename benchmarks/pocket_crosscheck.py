"""Cross-check of the jaw pockets against pooltool 0.6.0's default physics on its own pocket table.

    python -m benchmarks.pocket_crosscheck          # needs the pooltool venv (bash benchmarks/pooltool_setup.sh)
    python -m benchmarks.pocket_crosscheck --table wpa

Both engines play the same scenes on the same table: pooltool's 7-ft default table (``pt.Table.default()``: its
``PocketTableSpecs``) by default, or the WPA 9-ft preset given to pooltool field by field, and pooltool's default
physics (billiards_env's ``pooltool`` physics preset; pooltool's ``default_resolver()``). The scenes are clean pots
into corner and side pockets, a pot off a jaw tip, jaw rattles, a steep side-pocket rejection, a ball grazing a
side mouth, a rail run into a corner, a soft roll that dies in the jaws, a hanger, a bank, a scratch, a combination
and random shots. Per scene it prints the balls each engine pockets and in which pocket, and the largest distance
between the final positions of the balls left on the table; then how many scenes agree.

The frames differ as in :mod:`benchmarks.pooltool_crosscheck` (pooltool's length runs along its ``y``); pooltool's
pockets ``lb, lc, lt, rb, rc, rt`` are this engine's 0-5 (bottom-left, bottom-middle, bottom-right, top-left,
top-middle, top-right). Not part of the test suite (it needs the second venv).
"""
from __future__ import annotations

import argparse
import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from billiards_env.physics import Balls, Physics, Simulator
from billiards_env.physics.pocket_specs import POOLTOOL_7FT, WPA_9FT, PocketSpecs
from billiards_env.physics.table import jaw_table

from .pooltool_crosscheck import REPO, M, R, from_pooltool_vec, run_pooltool

#: pooltool's pocket ids in this engine's pocket order.
POOLTOOL_POCKETS = ("lb", "lc", "lt", "rb", "rc", "rt")
TABLES = {"pooltool": POOLTOOL_7FT, "wpa": WPA_9FT}


def _aim(src: tuple[float, float], dst: tuple[float, float]) -> float:
    return math.atan2(dst[1] - src[1], dst[0] - src[0])


def _ghost(obj: np.ndarray, target: np.ndarray) -> np.ndarray:
    """Where the cue ball's centre must be at contact to send ``obj`` towards ``target`` (no throw)."""
    d = target - obj
    return obj - 2 * R * d / np.linalg.norm(d)


def scenes(s: PocketSpecs, seed: int = 0) -> list[tuple[str, list[list[float]], float, float, float, float]]:
    """``(name, ball centres, cue angle, ball speed, side, top)`` on the table ``s``; ball 0 is struck."""
    L, W = s.l, s.w
    c = R * 1.05
    corner = np.array([0.0, 0.0])
    out = []
    # Clean pots: along the corner's diagonal, square into the side pocket, a cut into the corner.
    out.append(("corner, straight in", [[0.45, 0.45]], _aim((0.45, 0.45), (0, 0)), 1.5, 0.0, 0.0))
    out.append(("side, square in", [[L / 2, 0.4]], -math.pi / 2, 1.2, 0.0, 0.0))
    obj = np.array([0.35, 0.25])
    g = _ghost(obj, corner + 0.01)
    cue = g + np.array([0.5, 0.25])
    out.append(("corner, cut 30 deg", [cue.tolist(), obj.tolist()], _aim(tuple(cue), tuple(g)), 2.0, 0.0, 0.0))
    # Off a jaw tip and in; off a tip and out; rattles between the jaws.
    out.append(("corner, off the near tip", [[0.6, 0.35]], _aim((0.6, 0.35), (0.035, 0.0)), 1.5, 0.0, 0.0))
    out.append(("corner, jaw rattle", [[0.8, 0.2]], _aim((0.8, 0.2), (0.0, 0.045)), 1.0, 0.0, 0.0))
    out.append(("side, off the tip", [[L / 2 - 0.25, 0.45]], _aim((L / 2 - 0.25, 0.45), (L / 2 - 0.05, 0.0)), 1.5,
                0.0, 0.0))
    out.append(("side, steep rejection", [[L / 2 - 0.6, 0.25]], _aim((L / 2 - 0.6, 0.25), (L / 2, 0.0)), 2.0,
                0.0, 0.0))
    # Along a rail: past a side mouth, into a corner.
    out.append(("rail run past the side mouth", [[0.4, c]], 0.0, 2.5, 0.0, 0.0))
    out.append(("rail run into the corner", [[L - 0.5, c]], 0.0, 1.2, 0.0, 0.0))
    # Soft: a roll that dies in the jaws; a hanger knocked in.
    out.append(("soft roll dies in the jaws", [[0.25, 0.25]], _aim((0.25, 0.25), (0, 0)) + 0.14, 0.45, 0.0, 0.0))
    hanger = np.array([0.045, 0.045])
    g = _ghost(hanger, corner)
    out.append(("hanger", [[0.5, 0.5], hanger.tolist()], _aim((0.5, 0.5), tuple(g)), 0.8, 0.0, 0.0))
    # A bank into the side, a scratch, a combination.
    out.append(("bank into the side", [[L / 2 - 0.3, W - 0.5]], _aim((L / 2 - 0.3, W - 0.5), (L / 2, W * 0.5 + 0.0)),
                2.5, 0.0, 0.0))
    obj = np.array([0.3, 0.3])
    g = _ghost(obj, corner)
    out.append(("scratch after the pot", [[0.7, 0.7], obj.tolist()], _aim((0.7, 0.7), tuple(g)), 2.5, 0.0, 0.5))
    b1 = np.array([0.5, 0.32])
    b2 = np.array([0.25, 0.16])
    g2 = _ghost(b2, corner)
    g1 = _ghost(b1, g2)
    cue = g1 + 0.4 * (g1 - b1) / np.linalg.norm(g1 - b1)
    out.append(("combination", [cue.tolist(), b1.tolist(), b2.tolist()], _aim(tuple(cue), tuple(g1)), 3.0, 0.0, 0.0))
    rng = np.random.default_rng(seed)
    for k in range(6):
        pos: list[list[float]] = []
        while len(pos) < 3:
            p = [float(rng.uniform(0.1, L - 0.1)), float(rng.uniform(0.1, W - 0.1))]
            if all(math.dist(p, q) > 2.5 * R for q in pos):
                pos.append(p)
        out.append((f"random {k}", pos, float(rng.uniform(-math.pi, math.pi)), float(rng.uniform(1.0, 4.0)),
                    0.0, 0.0))
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--pooltool-python", default=str(REPO / ".venv-pooltool" / "bin" / "python"))
    ap.add_argument("--table", choices=sorted(TABLES), default="pooltool")
    ap.add_argument("--reps", type=int, default=7, help="timed repeats of each shot in each engine (default 7)")
    args = ap.parse_args(argv)
    if not Path(args.pooltool_python).exists():
        print(f"pooltool is not installed at {args.pooltool_python}: run `bash benchmarks/pooltool_setup.sh`",
              file=sys.stderr)
        return 2
    specs = TABLES[args.table]
    physics = Physics.from_preset("pooltool")
    table = jaw_table(specs, 0.85)
    shots = scenes(specs)
    spec = {"length": specs.l, "width": specs.w, "R": R, "m": M, "e_c": table.cushion_restitution,
            "f_c": physics.cushion_friction, "cushion_height": physics.cushion_height, "cushion": "stronge",
            "pocket_specs": {**specs.to_dict(), "cushion_height": physics.cushion_height},
            "warm_repeats": args.reps}
    theirs = run_pooltool(args.pooltool_python, spec, shots)
    if theirs is None:
        return 1
    sim = Simulator(table, physics)
    print(f"billiards_env jaws vs pooltool {theirs['version']} default physics on the {args.table!r} table\n")
    print(f"{'scene':32s} {'ours: ball->pocket':>22s} {'pooltool':>22s} {'final |dpos| m':>15s}")
    same = 0
    worst = 0.0
    ours_s = 0.0
    for (name, pos, angle, speed, side, top), pt_scene in zip(shots, theirs["scenes"]):
        balls = Balls.from_positions(pos).strike("cue", angle, speed, side=side, top=top, physics=physics)
        res = sim.run(balls)
        reps = []
        for _ in range(args.reps):  # the kernel on the ball arrays, as the envs call it
            fresh = balls.copy()
            t = time.perf_counter()
            sim.run_in_place(fresh)
            reps.append(time.perf_counter() - t)
        ours_s += statistics.median(reps)
        ours = {k: int(p) for k, p in enumerate(res.pocket) if p >= 0}
        pt_pockets: dict[int, int] = {}
        for kind, _, ids in pt_scene["events"]:
            if "pocket" in kind:
                ball = 0 if ids[0] == "cue" else int(ids[0])
                pt_pockets[ball] = POOLTOOL_POCKETS.index(ids[1])
        agree = ours == pt_pockets
        on = [k for k in range(len(pos)) if k not in ours and k not in pt_pockets]
        dpos = max((float(np.linalg.norm(res.balls.pos[k] - from_pooltool_vec(pt_scene["balls"][k]["x"],
                                                                            pt_scene["balls"][k]["y"])))
                    for k in on), default=0.0)
        if agree:
            same += 1
            worst = max(worst, dpos)
        fmt = lambda d: " ".join(f"{b}->{p}" for b, p in sorted(d.items())) or "-"  # noqa: E731
        print(f"{name:32s} {fmt(ours):>22s} {fmt(pt_pockets):>22s} {dpos:15.2e}" + ("" if agree else "  DIFFERS"))
    print(f"\n{same} of {len(shots)} scenes end with the same balls in the same pockets; on those, the worst final "
          f"position of a ball left on the table differs by {worst * 1e3:.4f} mm")
    pt_s = sum(sc["seconds"] for sc in theirs["scenes"])
    pt_first = sum(sc.get("first_seconds", sc["seconds"]) for sc in theirs["scenes"])
    print(f"time for all {len(shots)} shots: pooltool {pt_s:.3f} s (pt.simulate warm, median of {args.reps}; its first "
          f"runs, compiling, {pt_first:.1f} s), billiards_env {ours_s * 1e3:.2f} ms (Simulator.run_in_place, median "
          f"of {args.reps}): {pt_s / ours_s:.0f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
