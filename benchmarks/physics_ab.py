"""Before/after timing of the physics engine in one process: this tree's ``billiards_env.physics`` against a copy of
another commit's (default ``HEAD``), on the same shots, in interleaved rounds.

    python -m benchmarks.physics_ab                 # against HEAD (uncommitted changes vs the last commit)
    python -m benchmarks.physics_ab --base main     # against another commit, branch or tag
    python -m benchmarks.physics_ab --quick

The base is extracted with ``git archive`` into a temporary directory and imported as a package of another name
(the physics package imports only relatively, and imports neither Gymnasium nor the envs). Both compile once
(numba caches them); then each round times every shot group with both, alternating which goes first; the table
gives each group's median CPU time per run over the rounds, and the ratio of the fastest runs (after / before: the
fastest is the one least disturbed by other work).
Only models both trees have are timed (rolling, drag and the spin model on their defaults, exact and step), so
this measures what a change costs the scenes that do not use it. Not part of the default benchmark run.
"""
from __future__ import annotations

import argparse
import importlib
import math
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any, Callable

import numpy as np

REPO = Path(__file__).resolve().parents[1]
BASE_NAME = "_physics_base"


def load_base(rev: str, where: Path) -> Any:
    """The physics package of commit ``rev``, imported as :data:`BASE_NAME`."""
    archive = subprocess.run(["git", "-C", str(REPO), "archive", rev, "billiards_env/physics"], check=True,
                             capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", str(where)], input=archive, check=True)
    (where / "billiards_env" / "physics").rename(where / BASE_NAME)
    sys.path.insert(0, str(where))
    return importlib.import_module(BASE_NAME)


def _positions(rng: np.random.Generator, n: int, r: float = 0.028575) -> np.ndarray:
    while True:
        pos = np.column_stack([rng.uniform(0.15, 2.39, n), rng.uniform(0.15, 1.12, n)])
        d = np.linalg.norm(pos[:, None] - pos[None], axis=-1) + np.eye(n)
        if (d > 2 * r + 0.001).all():
            return pos


def shot_groups(pkg: Any, quick: bool) -> dict[str, Callable[[], None]]:
    """Named groups of shots, each a function that runs all of its shots once with package ``pkg``."""
    from billiards_env.physics.layout import rack_balls  # geometry only (same in both trees)

    table = pkg.Table()
    n = 10 if quick else 40
    rng = np.random.default_rng(7)
    two = [_positions(rng, 2) for _ in range(n)]
    three = [_positions(rng, 3) for _ in range(n)]
    angles = rng.uniform(-math.pi, math.pi, n)
    speeds = rng.uniform(0.5, 4.0, n)
    tips = 0.45 * np.sqrt(rng.uniform(0, 1, (n, 1))) * np.column_stack([np.cos(angles * 3), np.sin(angles * 3)])
    rack = rack_balls(table, cue_xy=(0.25 * table.length, 0.5 * table.width))
    rack_pos = np.array(rack.pos)
    aim = math.atan2(rack_pos[1, 1] - rack_pos[0, 1], rack_pos[1, 0] - rack_pos[0, 0])
    laws = {
        "rolling": pkg.Physics(),
        "drag": pkg.Physics(friction="drag", drag_k=0.3, min_speed=0.01),
        "spin": pkg.Physics(friction="spin"),
    }

    def aimed(pos: np.ndarray, k: int) -> float:
        return math.atan2(pos[1, 1] - pos[0, 1], pos[1, 0] - pos[0, 0]) + 0.3 * math.sin(angles[k])

    groups: dict[str, Callable[[], None]] = {}
    for law, physics in laws.items():
        spin = law == "spin"
        for solver in ("exact", "step"):
            sim = pkg.Simulator(table, physics, solver=solver, dt=1e-3)
            struck2 = [pkg.Balls.from_positions(p).strike(0, aimed(p, k), speeds[k], *(tips[k] if spin else (0, 0)))
                       for k, p in enumerate(two)]
            struck3 = [pkg.Balls.from_positions(p).strike(0, aimed(p, k), speeds[k], *(tips[k] if spin else (0, 0)))
                       for k, p in enumerate(three)]
            brk = pkg.Balls.from_positions(rack_pos).strike(0, aim, 8.0, *((0.0, 0.2) if spin else (0, 0)))
            reps = 1 if solver == "step" else 5

            def run_all(sim=sim, shots=struck2) -> None:
                for b in shots:
                    sim.run(b, validate=False)

            def run_break(sim=sim, b=brk, reps=reps) -> None:
                for _ in range(reps):
                    sim.run(b, validate=False)

            groups[f"{law}/{solver}/two balls"] = run_all
            groups[f"{law}/{solver}/three balls"] = lambda sim=sim, shots=struck3: [sim.run(b, validate=False)
                                                                                    for b in shots]
            groups[f"{law}/{solver}/15-ball break"] = run_break
        if law != "drag":
            sim = pkg.Simulator(table, physics)
            base = pkg.Balls.from_positions(three[0])
            kw = {"side": tips[:, 0], "top": tips[:, 1]} if spin else {}
            groups[f"{law}/batch/run_shots"] = (
                lambda sim=sim, base=base, kw=kw: pkg.batch.run_shots(sim, base, angles, speeds, threads=1, **kw))
    return groups


def _timed(fn: Callable[[], Any], min_time: float) -> float:
    """CPU seconds of this process per call of ``fn``, called until ``min_time`` CPU seconds have passed (CPU time:
    less disturbed than wall time by other work on a shared machine)."""
    calls = 0
    start = time.process_time()
    while True:
        fn()
        calls += 1
        elapsed = time.process_time() - start
        if elapsed >= min_time:
            return elapsed / calls


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--base", default="HEAD", help="commit, branch or tag to compare against (default HEAD)")
    ap.add_argument("--rounds", type=int, default=15)
    ap.add_argument("--min-time", type=float, default=0.05, help="seconds of calls per group and side in a round")
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args(argv)
    import billiards_env.physics as new
    import billiards_env.physics.batch  # noqa: F401  (the batch module, as pkg.batch)

    with tempfile.TemporaryDirectory(prefix="physics_ab_") as tmp:
        old = load_base(args.base, Path(tmp))
        importlib.import_module(f"{BASE_NAME}.batch")
        g_new = shot_groups(new, args.quick)
        g_old = shot_groups(old, args.quick)
        for fn in list(g_new.values()) + list(g_old.values()):  # compile / load both
            fn()
        times: dict[str, dict[str, list[float]]] = {k: {"before": [], "after": []} for k in g_new}
        rounds = 3 if args.quick else args.rounds
        for r in range(rounds):
            for name in g_new:
                order = (("before", g_old[name]), ("after", g_new[name]))
                for which, fn in (order if r % 2 == 0 else order[::-1]):
                    times[name][which].append(_timed(fn, args.min_time))
    print(f"physics A/B: this tree vs {args.base} ({rounds} interleaved rounds; times per group run)")
    print(f"{'group':34s} {'before':>10s} {'after':>10s} {'after/before':>13s}  "
          "(CPU time per run: median; ratio of minima)")
    worst = 0.0
    for name, tt in times.items():
        ratio = min(tt["after"]) / min(tt["before"])
        worst = max(worst, ratio)
        print(f"{name:34s} {statistics.median(tt['before']) * 1e3:8.3f}ms {statistics.median(tt['after']) * 1e3:8.3f}ms"
              f" {ratio:13.3f}")
    print(f"worst ratio: {worst:.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
