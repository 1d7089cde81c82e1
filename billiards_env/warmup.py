"""Compile (or load from numba's cache) every kernel once: ``python -m billiards_env.warmup [--workers N]``.

The set-up script runs this, so a user's first shot or first ``env.step`` loads compiled code. The work is split
into tasks (:data:`TASKS`) run in phases (:data:`PHASES`): the tasks of a phase compile disjoint kernels, in
parallel worker processes (one per core by default), and a later phase's tasks load what earlier phases compiled
from the cache instead of compiling it again.
"""
from __future__ import annotations

import argparse
import multiprocessing
import os
import sys
import time
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor

from .kernel_cache import clear_stale_cache
from .registration import ENV_IDS

def _physics(*kernels: str) -> Callable[[], None]:
    """A task: the physics kernels ``kernels`` (:data:`billiards_env.physics.warmup.KERNELS`)."""
    def task() -> None:
        from .physics.warmup import warm_up as warm_up_physics
        warm_up_physics(kernels)
    return task


def _players() -> None:
    """The players' kernels (:func:`billiards_env.players.warmup.warm_up`) and the placement of a ball in hand."""
    import numpy as np

    from .physics.layout import nearest_free_point
    from .players.warmup import warm_up as warm_up_players

    warm_up_players()
    nearest_free_point(0.3, 0.3, np.array([[0.3, 0.3], [1.0, 0.5]]), np.ones(2, np.bool_), np.full(2, 0.028575), 0,
                       (0.1, 0.6, 0.1, 1.1), holes=np.array([[0.0, 0.0, 0.06]]))


def _envs(*env_ids: str) -> Callable[[], None]:
    """A task: one reset and one step of each of ``env_ids``."""
    def task() -> None:
        import gymnasium as gym

        import billiards_env  # noqa: F401  (registers the ids)

        for env_id in env_ids:
            env = gym.make(env_id)
            env.reset(seed=0)
            env.step(env.action_space.sample())
            env.close()
    return task


def _candidates() -> None:
    """A game with the ``candidates`` action and observation types."""
    import gymnasium as gym
    import numpy as np

    import billiards_env  # noqa: F401

    env = gym.make("Billiards9Ball-v0", action_type="candidates", observation_type="candidates", opponent=None,
                   opening="ball_in_hand")
    env.reset(seed=0)
    env.step(np.zeros(env.action_space.shape, np.float32))
    env.close()


def _vector_pots() -> None:
    """The native vector env's pot-scene kernels: serial, on two threads (the same kernel on slices of the tables),
    with shot noise, and the spin model."""
    import gymnasium as gym

    import billiards_env  # noqa: F401

    for kwargs in ({"threads": 1}, {"threads": 2, "angle_noise": 0.01},
                   {"threads": 1, "physics": {"friction": "spin"}, "spin_action": True}):
        env = gym.make_vec("BilliardsThreeBalls-v0", 2, **kwargs)
        env.reset(seed=0)
        env.step(env.action_space.sample())
        env.close()


def _vector_games() -> None:
    """The native vector env's game kernels (9-ball and 8-ball in compiled code: one kernel for every thread
    count)."""
    import gymnasium as gym

    import billiards_env  # noqa: F401

    env = gym.make_vec("Billiards9Ball-v0", 2)
    env.reset(seed=0)
    env.step(env.action_space.sample())
    env.close()


#: Every task by name: what it compiles (or loads).
TASKS: dict[str, Callable[[], None]] = {
    "exact": _physics("exact"),
    "exact_spin": _physics("exact_spin"),
    "step": _physics("step"),
    "step_spin": _physics("step_spin"),
    "players": _players,
    "vector_pots": _vector_pots,
    "vector_games": _vector_games,
    "candidates": _candidates,
    **{f"env:{env_id}": _envs(env_id) for env_id in ENV_IDS},
}
#: The order of the tasks: each phase's tasks run in parallel after the previous phase, longest first. The physics
#: kernels come first (everything calls them), then the players (the games' opponents call them), then the envs.
#: The pot-task envs come after ``vector_pots``: their step is the native vector env's kernel on one table
#: (``envs/_pot_fast.py``), which two tasks of one phase would each compile in their own process.
_EARLY_ENVS = ("env:BilliardsThreeCushion-v0", "env:BilliardsSnooker-v0")
PHASES: tuple[tuple[str, ...], ...] = (
    ("exact", "exact_spin", "step", "step_spin"),
    ("players", "vector_pots", *_EARLY_ENVS),
    ("vector_games", "candidates", *(f"env:{i}" for i in ENV_IDS if f"env:{i}" not in _EARLY_ENVS)),
)


def _run_task(name: str) -> tuple[str, float]:
    """Run task ``name`` in this process; returns its name and seconds."""
    start = time.perf_counter()
    TASKS[name]()
    return name, time.perf_counter() - start


def default_workers() -> int:
    """One worker process per core this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not on Linux
        return max(1, os.cpu_count() or 1)


def warm_up(workers: int | None = None, report: Callable[[str, float], None] | None = None) -> float:
    """Every task of :data:`PHASES`, phase after phase, in ``workers`` processes (default: one per core; 1 runs them
    in this process); ``report(task, seconds)`` hears each task end. Returns the seconds it all took."""
    workers = default_workers() if workers is None else workers
    if workers < 1:
        raise ValueError(f"workers: must be >= 1, got {workers}")
    start = time.perf_counter()
    clear_stale_cache()
    for phase in PHASES:
        if workers == 1:
            done = [_run_task(name) for name in phase]
        else:
            ctx = multiprocessing.get_context("spawn")  # fresh interpreters: no numba state copied by a fork
            with ProcessPoolExecutor(max_workers=min(workers, len(phase)), mp_context=ctx) as pool:
                done = list(pool.map(_run_task, phase))
        for name, seconds in done:
            if report is not None:
                report(name, seconds)
    return time.perf_counter() - start


def main(argv: Sequence[str] | None = None) -> int:
    """The command line: ``python -m billiards_env.warmup [--workers N] [--verbose]``."""
    ap = argparse.ArgumentParser(prog="python -m billiards_env.warmup",
                                 description="Compile (or load from numba's cache) every billiards_env kernel once.")
    ap.add_argument("--workers", type=int, default=None,
                    help=f"worker processes (default: one per core, here {default_workers()}; 1: this process only)")
    ap.add_argument("--verbose", action="store_true", help="print each task's seconds as it ends")
    args = ap.parse_args(argv)
    if args.workers is not None and args.workers < 1:
        ap.error(f"--workers: must be >= 1, got {args.workers}")
    report = (lambda name, s: print(f"  {name}: {s:.1f} s", flush=True)) if args.verbose else None
    print(f"billiards_env kernels ready ({warm_up(args.workers, report):.1f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
