"""Cross-check of the ``pooltool`` preset against pooltool 0.6.0's default physics, on pocketless scenes with
throw, spin and cushion hits.

    python -m benchmarks.pooltool_crosscheck        # needs the pooltool venv (bash benchmarks/pooltool_setup.sh)
    python -m benchmarks.pooltool_crosscheck --cushion mathavan   # both engines with Mathavan 2010 cushions

Every scene is balls at rest and one cue strike: billiards_env strikes with ``Balls.strike(..., physics=preset)``
and runs ``Simulator(pocketless table, Physics.from_preset("pooltool"))``; pooltool strikes with its own cue model
(``InstantaneousPoint`` with squirt, the cue speed chosen so that the ball leaves at the same speed) and runs
``pooltool.simulate`` with ``default_resolver()`` (frictional inelastic ball-ball collisions with Alciatore's
friction, Stronge's compliant cushions with ``omega_ratio`` 1.8) on a pocketless table of the same size whose
cushion nose is at 0.036576 m. Same ball parameters (R 0.028575 m, m 0.17 kg, e_c 0.85, f_c 0.2, the rest
pooltool's defaults, which the preset copies). Scenes: cut shots at several cut angles and speeds with stun,
follow and draw (throw), stun with side into a ball, running and reverse english off a rail, banks and kicks off
several rails, and random three-ball shots with spin. The script prints per scene both engines' collision and
cushion counts, the largest difference of the struck ball's velocity after the strike, and the largest difference
of the final positions; then the worst and median of those.

pooltool's table has its length along ``y``: a point ``(x, y)`` of billiards_env is ``(y, x)`` there, a vector
likewise, an angular velocity (a pseudovector under this reflection) ``w -> -(wy, wx, wz)``, a cue direction
``a`` (rad) is ``90 - degrees(a)`` degrees, and right english (billiards_env ``side > 0``) is pooltool's left
(``a = +side``). Not part of the test suite (it needs the second venv).
"""
from __future__ import annotations

import argparse
import json
import math
import statistics
import subprocess
import sys
from pathlib import Path

import numpy as np

from billiards_env.physics import Balls, Physics, Simulator, Table
from billiards_env.physics.codes import EVENT_KINDS

REPO = Path(__file__).resolve().parents[1]
POOLTOOL_SCRIPT = Path(__file__).with_name("pooltool_crosscheck_pooltool.py")
R = 0.028575
M = 0.17
L, W = 2.54, 1.27
CUE_MASS = 0.567  #: pooltool's default cue mass (kg): sets the cue speed that gives the ball our speed


def _cut(name: str, cut_deg: float, speed: float, top: float = 0.0, side: float = 0.0) -> tuple:
    """The cue ball 0.8 m from the object ball, aimed to cut it by ``cut_deg`` (ghost-ball aim, no throw)."""
    obj = np.array([1.5, 0.62])
    phi = math.radians(cut_deg)
    ghost = obj - 2 * R * np.array([math.cos(phi), math.sin(phi)])
    cue = ghost - 0.8 * np.array([1.0, 0.0]) * 1.0
    angle = math.atan2(ghost[1] - cue[1], ghost[0] - cue[0])
    return name, [cue.tolist(), obj.tolist()], angle, speed, side, top


def scenes() -> list[tuple[str, list[list[float]], float, float, float, float]]:
    """``(name, ball centres, cue angle, ball speed, side, top)``: ball 0 is struck."""
    out = [
        _cut("cut 15 deg stun 1 m/s", 15, 1.0),
        _cut("cut 30 deg stun 1 m/s", 30, 1.0),
        _cut("cut 45 deg stun 0.8 m/s", 45, 0.8),
        _cut("cut 30 deg stun 3 m/s", 30, 3.0),
        _cut("cut 60 deg stun 2 m/s", 60, 2.0),
        _cut("cut 30 deg follow 1.5 m/s", 30, 1.5, top=0.4),
        _cut("cut 30 deg draw 2 m/s", 30, 2.0, top=-0.4),
        _cut("cut 20 deg outside english", 20, 1.5, side=-0.3),
        _cut("cut 20 deg inside english", 20, 1.5, side=0.3),
        _cut("straight stun with side", 0, 2.0, side=0.35),
        ("running english off a rail", [[0.6, 0.4]], math.radians(60), 2.0, 0.35, 0.0),
        ("reverse english off a rail", [[0.6, 0.4]], math.radians(60), 2.0, -0.35, 0.0),
        ("follow into a rail", [[0.6, 0.6]], math.radians(80), 2.5, 0.0, 0.4),
        ("draw into a rail", [[0.6, 0.6]], math.radians(-75), 2.5, 0.0, -0.4),
        ("bank, object ball two rails", [[0.9, 0.4], [1.3, 0.5]], math.atan2(0.1, 0.4) + 0.04, 3.5, 0.0, 0.1),
        ("three-rail kick with english", [[0.5, 0.3]], math.radians(35), 4.0, 0.3, 0.2),
        ("soft follow along a rail", [[0.4, 0.05]], math.radians(5), 1.5, 0.1, 0.3),
    ]
    rng = np.random.default_rng(11)
    for k in range(8):
        pos = [[rng.uniform(0.2, L - 0.2), rng.uniform(0.2, W - 0.2)] for _ in range(3)]
        while min(math.dist(p, q) for i, p in enumerate(pos) for q in pos[i + 1:]) < 3 * R:
            pos = [[rng.uniform(0.2, L - 0.2), rng.uniform(0.2, W - 0.2)] for _ in range(3)]
        d = np.subtract(pos[1], pos[0])
        angle = math.atan2(d[1], d[0]) + rng.uniform(-0.25, 0.25)
        rad, th = 0.45 * math.sqrt(rng.uniform()), rng.uniform(-math.pi, math.pi)
        out.append((f"random {k}", pos, angle, rng.uniform(1.0, 4.0), rad * math.cos(th), rad * math.sin(th)))
    return out


def to_pooltool_cue(angle: float, speed: float, side: float, top: float) -> dict:
    """pooltool's cue state for our strike: the cue speed that gives the ball ``speed`` (TP A-30's
    ``v = 2 V0 / (1 + m/M + 5/2 (a^2 + b^2))``), the direction and tip offsets in its mirrored frame."""
    v0 = speed * (1.0 + M / CUE_MASS + 2.5 * (side * side + top * top)) / 2.0
    return {"V0": v0, "phi": (90.0 - math.degrees(angle)) % 360.0, "a": side, "b": top}


def from_pooltool_vec(x: float, y: float) -> np.ndarray:
    return np.array([y, x])


def from_pooltool_ang(wx: float, wy: float, wz: float) -> np.ndarray:
    return -np.array([wy, wx, wz])


def run_pooltool(python: str, spec: dict, shots: list) -> dict | None:
    """pooltool's side of a cross-check: ``spec`` (:mod:`benchmarks.pooltool_crosscheck_pooltool`'s input, without
    its scenes) with ``shots`` (``(name, centres, angle, speed, side, top)``, ball 0 struck) mapped into pooltool's
    frame, run by pooltool's Python; its output, or None (its error printed) if it failed."""
    spec = {**spec, "scenes": []}
    for name, pos, angle, speed, side, top in shots:
        ids = ["cue"] + [str(k) for k in range(1, len(pos))]
        spec["scenes"].append({"name": name, "balls": [{"id": i, "x": y, "y": x} for i, (x, y) in zip(ids, pos)],
                               "cue": {"ball": "cue", **to_pooltool_cue(angle, speed, side, top)}})
    proc = subprocess.run([python, str(POOLTOOL_SCRIPT)], input=json.dumps(spec), text=True, capture_output=True,
                          timeout=3600)
    if proc.returncode != 0:
        print(proc.stderr[-3000:], file=sys.stderr)
        return None
    return json.loads(proc.stdout.strip().splitlines()[-1])


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--pooltool-python", default=str(REPO / ".venv-pooltool" / "bin" / "python"))
    ap.add_argument("--cushion", choices=("stronge", "mathavan"), default="stronge",
                    help="cushion model on both sides (default: the preset's, stronge)")
    args = ap.parse_args(argv)
    if not Path(args.pooltool_python).exists():
        print(f"pooltool is not installed at {args.pooltool_python}: run `bash benchmarks/pooltool_setup.sh`",
              file=sys.stderr)
        return 2
    physics = Physics.from_preset("pooltool", cushion=args.cushion)
    table = Table(length=L, width=W, cushion_restitution=0.85).without_pockets()
    shots = scenes()
    spec = {"length": L, "width": W, "R": R, "m": M, "e_c": table.cushion_restitution, "f_c": physics.cushion_friction,
            "cushion_height": physics.cushion_height, "cushion": args.cushion}
    theirs = run_pooltool(args.pooltool_python, spec, shots)
    if theirs is None:
        return 1
    sim = Simulator(table, physics)
    print(f"billiards_env preset 'pooltool' vs pooltool {theirs['version']} default physics, pocketless table"
          + (" (both with Mathavan 2010 cushions)" if args.cushion == "mathavan" else "") + "\n")
    print(f"{'scene':32s} {'ours: coll+cush':>15s} {'pooltool':>9s} {'strike |dv| m/s':>16s} {'final |dpos| m':>15s}")
    diffs = []
    for (name, pos, angle, speed, side, top), pt_scene in zip(shots, theirs["scenes"]):
        balls = Balls.from_positions(pos).strike("cue", angle, speed, side=side, top=top, physics=physics)
        s = pt_scene["struck"]
        dv = max(float(np.linalg.norm(balls.vel[0] - from_pooltool_vec(s["vx"], s["vy"]))),
                 float(np.linalg.norm(balls.ang[0] - from_pooltool_ang(s["wx"], s["wy"], s["wz"]))) * R)
        res = sim.run(balls)
        kinds = [EVENT_KINDS[k] for k in res.events.kind]
        ours = f"{kinds.count('collision')}+{kinds.count('cushion')}"
        pt_kinds = [e[0] for e in pt_scene["events"]]
        pt_ev = f"{sum('ball_ball' in k for k in pt_kinds)}+{sum('cushion' in k for k in pt_kinds)}"
        dpos = max(float(np.linalg.norm(res.balls.pos[i] - from_pooltool_vec(r["x"], r["y"])))
                   for i, r in enumerate(pt_scene["balls"]))
        diffs.append(dpos)
        print(f"{name:32s} {ours:>15s} {pt_ev:>9s} {dv:16.2e} {dpos:15.2e}")
    print(f"\n{len(diffs)} scenes; final positions: worst {max(diffs) * 1e3:.4f} mm, median "
          f"{statistics.median(diffs) * 1e3:.4f} mm (strike |dv|: the larger of the velocity's and R times the "
          "angular velocity's difference)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
