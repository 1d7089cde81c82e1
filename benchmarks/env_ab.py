"""Before/after env rates: this tree's envs (and pocket windows) against another commit's, in interleaved rounds.

    python -m benchmarks.env_ab --base 22b30d2            # the commit before the env-layer redesign
    python -m benchmarks.env_ab --base main --seconds 1   # quicker
    python -m benchmarks.env_ab --cpu                     # this tree: prebuilt kernels against compiled here

With ``--cpu`` the two sides are this tree's kernels from the prebuilt archive (built for numba's generic CPU:
"before") and compiled here for this CPU (``BILLIARDS_PREBUILT=0``: "after"), each in an empty numba cache of its
own (the compiled side's warm-up compiles every kernel: 3-4 minutes).

The base commit is checked out (``git worktree add --detach``) into a temporary directory; each round runs one child
process per tree (alternating which goes first) that times, for every id both trees have, ``env.step`` with random
actions on the single env (seeded resets at episode ends), a seeded ``reset`` + ``step`` episode on the one-ball
env, and the native vector env (256 tables, one thread) of the pot scenes and of the games (against their default
geometric opponent; a step is an agent step, its opponent's turns included), and the pocket windows the players
aim through (``physics.aim.window_of`` from random balls into every pocket, on the WPA jaw table and on capture
circles of its size). The table gives, per measurement, each tree's best
rate over the rounds (the run least disturbed by other work on a shared machine) and their ratio (after / before).
Not part of the default benchmark run.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[1]
POT = ("BilliardsOneBall-v0", "BilliardsThreeBalls-v0", "BilliardsRack-v0")
GAMES = ("Billiards9Ball-v0", "Billiards8Ball-v0")


def _rate(fn: Any, seconds: float) -> float:
    """Calls of ``fn`` per second over ``seconds`` (after one warm-up call); ``fn`` returns how many it counts."""
    fn()
    n, t0 = 0, time.perf_counter()
    while n == 0 or time.perf_counter() - t0 < seconds:  # one call at least, however busy the machine
        n += fn()
    return n / (time.perf_counter() - t0)


def child(seconds: float) -> dict[str, float]:
    """The measurements of the tree this process imports (printed as JSON by ``--child``)."""
    import gymnasium as gym
    import numpy as np

    import billiards_env  # noqa: F401

    out: dict[str, float] = {}
    rng = np.random.default_rng(0)
    for env_id in POT + GAMES:
        env = gym.make(env_id)
        env.reset(seed=0)
        seed = [1]

        def step() -> int:
            *_, term, trunc, _ = env.step(rng.uniform(-1, 1, env.action_space.shape).astype(np.float32))
            if term or trunc:
                env.reset(seed=seed[0])
                seed[0] += 1
            return 1

        out[f"step {env_id}"] = _rate(step, seconds)
        env.close()
    env = gym.make("BilliardsOneBall-v0")
    acts = rng.uniform(-1, 1, (1024, 2)).astype(np.float32)
    k = [0]

    def episode() -> int:
        env.reset(seed=k[0])
        env.step(acts[k[0] % 1024])
        k[0] += 1
        return 1

    out["episode BilliardsOneBall-v0 (seeded reset + step)"] = _rate(episode, seconds)
    out.update(_window_rates(seconds))
    for env_id in POT + GAMES:
        vec = gym.make_vec(env_id, 256, vectorization_mode="vector_entry_point", threads=1)
        vec.reset(seed=0)
        acts_v = rng.uniform(-1, 1, (256,) + vec.single_action_space.shape).astype(np.float32)

        def vstep() -> int:
            vec.step(acts_v)
            return 256

        out[f"vector 256 {env_id} (1 thread)"] = _rate(vstep, seconds)
        vec.close()
    return out


def _window_rates(seconds: float) -> dict[str, float]:
    """Pocket windows per second (``physics.aim.window_of``, in one compiled loop) from 500 seeded random balls into
    the 6 pockets of the WPA jaw table, and into the same table's capture circles (no walls)."""
    import numpy as np
    from numba import njit

    from billiards_env.physics import aim
    from billiards_env.physics.scene import parse_table

    @njit
    def windows(balls, r, pxy, prs, length, width, segs, tips):  # (compiled: numba types the arguments)
        total = 0.0
        for i in range(balls.shape[0]):
            for p in range(prs.shape[0]):
                total += aim.window_of(balls[i, 0], balls[i, 1], r, pxy[p, 0], pxy[p, 1], prs[p], length, width,
                                       aim.WINDOW_SAMPLES, segs, tips)[1]
        return total

    table = parse_table({"preset": "wpa"})
    segs, tips = (np.ascontiguousarray(a, dtype=np.float64) for a in table.walls())
    pxy = np.ascontiguousarray(table.pocket_xy, dtype=np.float64)
    prs = np.ascontiguousarray(table.pocket_radius, dtype=np.float64)
    r = 0.028575
    balls = np.random.default_rng(0).uniform([r, r], [table.length - r, table.width - r], (500, 2))
    out = {}
    for name, walls in (("jaw table", (segs, tips)), ("capture circles", (np.zeros((0, 6)), np.zeros((0, 3))))):
        def run(walls: tuple = walls) -> int:
            windows(balls, r, pxy, prs, table.length, table.width, *walls)
            return balls.shape[0] * prs.shape[0]

        out[f"pocket windows ({name}, 500 balls x 6 pockets)"] = _rate(run, seconds)
    return out


def _environ(tree: Path, extra: dict[str, str]) -> dict[str, str]:
    """A child's environment: ``tree`` on the path, ``extra`` on top of this process's environment (without the
    numba CPU this process's import of the package may have set, when ``extra`` says where the cache is)."""
    drop = ("NUMBA_CPU_NAME", "NUMBA_CPU_FEATURES", "BILLIARDS_PREBUILT") if "NUMBA_CACHE_DIR" in extra else ()
    return {**{k: v for k, v in os.environ.items() if k not in drop}, "PYTHONPATH": str(tree),
            "SDL_VIDEODRIVER": "dummy", **extra}


def _run(tree: Path, seconds: float, extra: dict[str, str]) -> dict[str, float]:
    env = _environ(tree, extra)
    res = subprocess.run([sys.executable, "-c", f"import sys; sys.path.insert(0, {str(tree)!r}); "
                          f"from benchmarks.env_ab import child; import json; print(json.dumps(child({seconds})))"],
                         cwd=str(tree), env=env, capture_output=True, text=True, check=True)
    return json.loads(res.stdout.strip().splitlines()[-1])


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks.env_ab", description=__doc__.split("\n")[0])
    p.add_argument("--base", default="HEAD", help="the commit to compare with (default HEAD)")
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--seconds", type=float, default=2.0, help="timing per measurement and round")
    p.add_argument("--base-tree", type=Path, default=None,
                   help="an existing checkout of the base (e.g. a git worktree), used instead of a new worktree of "
                        "--base; warmed up as a new one is")
    p.add_argument("--cpu", action="store_true",
                   help="compare this tree's prebuilt kernels (generic CPU) with kernels compiled here for this CPU "
                        "instead of two commits")
    args = p.parse_args(argv)
    worktree = args.base_tree is None and not args.cpu
    with tempfile.TemporaryDirectory() as tmp:
        base = REPO if args.cpu else args.base_tree.resolve() if args.base_tree else Path(tmp) / "base"
        if worktree:
            subprocess.run(["git", "-C", str(REPO), "worktree", "add", "--detach", "-q", str(base), args.base],
                           check=True)
        label = ("prebuilt kernels (before) against compiled for this CPU (after)" if args.cpu
                 else args.base if worktree else str(base))
        sides: dict[str, tuple[Path, dict[str, str]]] = {"before": (base, {}), "after": (REPO, {})}
        if args.cpu:
            sides = {"before": (REPO, {"NUMBA_CACHE_DIR": f"{tmp}/prebuilt"}),
                     "after": (REPO, {"NUMBA_CACHE_DIR": f"{tmp}/compiled", "BILLIARDS_PREBUILT": "0"})}
        else:
            (base / "benchmarks" / "env_ab.py").write_text(Path(__file__).read_text())  # the same timing code
        try:
            for name, (tree, extra) in sides.items():
                if tree != REPO or extra:
                    print(f"[env_ab] warming up {name}: {tree} {extra} (its kernels compile once)", file=sys.stderr)
                    subprocess.run([sys.executable, "-m", "billiards_env.warmup"], cwd=str(tree), check=True,
                                   env=_environ(tree, extra), capture_output=True)
            best: dict[str, dict[str, float]] = {"before": {}, "after": {}}
            for r in range(args.rounds):
                order = ["before", "after"] if r % 2 == 0 else ["after", "before"]
                for name in order:
                    tree, extra = sides[name]
                    got = _run(tree, args.seconds, extra)
                    for key, rate in got.items():
                        best[name][key] = max(best[name].get(key, 0.0), rate)
                print(f"[env_ab] round {r + 1}/{args.rounds} done", file=sys.stderr)
        finally:
            if worktree:
                subprocess.run(["git", "-C", str(REPO), "worktree", "remove", "--force", str(base)], check=False)
    print(f"env rates, best of {args.rounds} interleaved rounds of {args.seconds:g} s (base {label}):\n")
    print("| measurement | before (/s) | after (/s) | after / before |")
    print("|---|---:|---:|---:|")
    for key in best["after"]:
        if key in best["before"]:
            b, a = best["before"][key], best["after"][key]
            print(f"| {key} | {b:,.0f} | {a:,.0f} | {a / b:.2f} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
