"""Cross-check of the spin model against an independent implementation: pooltool 0.6.0 with the same sub-models.

    python -m benchmarks.spin_crosscheck            # needs the pooltool venv (bash benchmarks/pooltool_setup.sh)

Both engines start from the same ball states (position, velocity, angular velocity) on a pocketless 2.54 x 1.27 m
table and run to rest; the script prints, per scene, both event sequences and the largest difference of the final
positions. Sub-models that match billiards_env's spin model: pooltool's frictionless elastic ball-ball collision
(billiards_env with ``ball_restitution = 1``, ``ball_friction = 0``), its ``impulse_frictional_inelastic`` cushion
with the cushion nose at the balls' equator (``cushion_height = R``: otherwise the contact normal tilts), equal
friction constants (``mu_slide 0.2``, ``mu_roll 0.01``, ``mu_spin 0.0127``, ``e_c 0.85``, cushion friction 0.2).

pooltool's table has its length along ``y``: a point ``(x, y)`` of billiards_env is ``(y, x)`` there, a vector
likewise, and an angular velocity (a pseudovector under this reflection) ``w -> -(wy, wx, wz)``. Not part of the
test suite (it needs the second venv); its output is evidence that the two implementations agree.
"""
from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np

from billiards_env.physics import Balls, Physics, Simulator, Table
from billiards_env.physics.codes import EVENT_KINDS, MOTION_STATES
from billiards_env.physics.spin_motion import classify

REPO = Path(__file__).resolve().parents[1]
POOLTOOL_SCRIPT = Path(__file__).with_name("spin_crosscheck_pooltool.py")
R = 0.028575
M = 0.17
L, W = 2.54, 1.27


def scenes() -> list[tuple[str, Balls]]:
    """The cross-check shots: single-ball spin shots, spin shots into a ball, off a rail, and random ones."""
    one = Balls.from_positions([[0.6, 0.5]])
    two = Balls.from_positions([[0.6, 0.5], [1.5, 0.62]])
    out = [
        ("stun", one.strike("cue", 0.1, 2.0)),
        ("follow", one.strike("cue", 0.3, 2.5, top=0.4)),
        ("draw into a ball", two.strike("cue", math.atan2(0.12, 0.9), 2.5, top=-0.4)),
        ("follow into a ball", two.strike("cue", math.atan2(0.12, 0.9), 2.0, top=0.3)),
        ("english off a rail", one.strike("cue", 1.2, 2.0, side=0.4)),
        ("draw + english off a rail", one.strike("cue", -0.9, 3.0, side=-0.3, top=-0.3)),
        ("cut with follow", two.strike("cue", math.atan2(0.12, 0.9) + 0.35, 2.5, top=0.35, side=0.2)),
    ]
    rng = np.random.default_rng(3)
    for k in range(5):
        pos = [[rng.uniform(0.2, L - 0.2), rng.uniform(0.2, W - 0.2)] for _ in range(3)]
        while min(math.dist(p, q) for i, p in enumerate(pos) for q in pos[i + 1:]) < 3 * R:
            pos = [[rng.uniform(0.2, L - 0.2), rng.uniform(0.2, W - 0.2)] for _ in range(3)]
        d = np.subtract(pos[1], pos[0])
        angle = math.atan2(d[1], d[0]) + rng.uniform(-0.2, 0.2)
        a, b = rng.uniform(-0.35, 0.35, size=2)
        out.append((f"random {k}", Balls.from_positions(pos).strike("cue", angle, rng.uniform(1.0, 4.0), side=a,
                                                                        top=b)))
    return out


def to_pooltool(balls: Balls) -> list[dict]:
    rows = []
    for i, bid in enumerate(balls.ids):
        (x, y), (vx, vy), (wx, wy, wz) = balls.pos[i], balls.vel[i], balls.ang[i]
        rows.append({"id": bid, "x": y, "y": x, "vx": vy, "vy": vx, "wx": -wy, "wy": -wx, "wz": -wz,
                     "state": int(classify(vx, vy, wx, wy, wz, R))})
    return rows


def from_pooltool(row: dict) -> tuple[np.ndarray, np.ndarray]:
    """Position and angular velocity back in billiards_env's frame."""
    return np.array([row["y"], row["x"]]), -np.array([row["wy"], row["wx"], row["wz"]])


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--pooltool-python", default=str(REPO / ".venv-pooltool" / "bin" / "python"))
    args = ap.parse_args(argv)
    if not Path(args.pooltool_python).exists():
        print(f"pooltool is not installed at {args.pooltool_python}: run `bash benchmarks/pooltool_setup.sh`",
              file=sys.stderr)
        return 2
    table = Table(length=L, width=W).without_pockets()
    physics = Physics(friction="spin", ball_restitution=1.0, ball_friction=0.0, cushion_friction=0.2)
    shots = scenes()
    spec = {"length": W, "width": L, "R": R, "m": M, "e_c": table.cushion_restitution,
            "f_c": physics.cushion_friction,
            "scenes": [{"name": name, "balls": to_pooltool(b)} for name, b in shots]}
    # pooltool's BilliardTableSpecs: l is the length (its y), w the width (its x).
    spec["length"], spec["width"] = L, W
    proc = subprocess.run([args.pooltool_python, str(POOLTOOL_SCRIPT)], input=json.dumps(spec), text=True,
                          capture_output=True, timeout=1800)
    if proc.returncode != 0:
        print(proc.stderr[-2000:], file=sys.stderr)
        return 1
    theirs = json.loads(proc.stdout.strip().splitlines()[-1])
    sim = Simulator(table, physics)
    worst = 0.0
    print(f"billiards_env spin model vs pooltool {theirs['version']} (frictionless elastic ball-ball, "
          "impulse_frictional_inelastic cushion at the equator, pocketless table)\n")
    print(f"{'scene':28s} {'events ours/pooltool':>22s} {'max |dt| (s)':>13s} {'max |dpos| (m)':>15s} "
          f"{'max |dw| (rad/s)':>17s}")
    for (name, balls), pt_scene in zip(shots, theirs["scenes"]):
        res = sim.run(balls)
        n_ours = {k: int(np.sum(res.events.kind == c)) for c, k in enumerate(EVENT_KINDS)}
        pt_kinds = [e[0] for e in pt_scene["events"]]
        coll = sum("ball_ball" in k for k in pt_kinds)
        cush = sum("cushion" in k for k in pt_kinds)
        dpos = max(float(np.linalg.norm(res.balls.pos[i] - from_pooltool(r)[0]))
                   for i, r in enumerate(pt_scene["balls"]))
        dw = max(float(np.linalg.norm(res.balls.ang[i] - from_pooltool(r)[1])) for i, r in enumerate(pt_scene["balls"]))
        worst = max(worst, dpos)
        ev = f"{n_ours['collision']}+{n_ours['cushion']} / {coll}+{cush}"
        # Times of the collisions and cushion hits, in order, where both engines have the same sequence.
        ours_t = [float(t) for t, k in zip(res.events.time, res.events.kind) if EVENT_KINDS[k] in ("collision",
                                                                                                   "cushion")]
        theirs_t = [e[1] for e in pt_scene["events"] if "ball_ball" in e[0] or "cushion" in e[0]]
        dt = max((abs(a - b) for a, b in zip(ours_t, theirs_t)), default=0.0) if len(ours_t) == len(theirs_t) \
            else float("nan")
        print(f"{name:28s} {ev:>22s} {dt:13.3e} {dpos:15.3e} {dw:17.3e}")
        states = [MOTION_STATES[r["state"]] for r in pt_scene["balls"]]
        assert all(s == "stationary" for s in states), states
    print(f"\nevents: ball-ball + cushion. Largest final-position difference: {worst:.3e} m")
    return 0


if __name__ == "__main__":
    sys.exit(main())
