"""Measure ``env.step`` throughput of every registered id in one process (no rendering).

``python -m billiards_env.envs.benchmark [--seconds 3] [--ids ...] [--wrapped] [--compare]`` prints, per id:
steps/s including the auto-resets (random actions, ``reset`` whenever the episode ends, as a training loop
does) per wall-clock second and per CPU second of this process (steadier on a busy machine), step and reset
times separately, and the mean simulated events per shot. The unwrapped env is timed; ``--wrapped`` adds the
env made by ``gym.make`` (passive checker and order enforcing wrappers), ``--compare`` the same shots run
through ``Simulator.run(validate=False)`` instead of the in-place kernel call.
"""
from __future__ import annotations

import argparse
import time

import gymnasium as gym
import numpy as np

import billiards_env  # noqa: F401  (registers the ids)

from . import ENV_IDS


def measure(env_id: str, seconds: float = 3.0, seed: int = 0, wrapped: bool = False, fast: bool = True,
            **kwargs) -> dict:
    """Steps/s of ``env_id`` with random actions and auto-reset. ``wrapped``: time the ``gym.make`` env rather
    than the unwrapped one; ``fast=False``: run shots through ``Simulator.run(validate=False)`` instead of the
    in-place kernel call (to measure what the fast path saves)."""
    env = gym.make(env_id, **kwargs)
    env.unwrapped._fast = fast and env.unwrapped.config.solver == "exact"
    if not wrapped:
        env = env.unwrapped
    rng = np.random.default_rng(seed)
    actions = rng.uniform(-1, 1, size=(4096, 2)).astype(np.float32)
    env.reset(seed=seed)
    for k in range(20):  # warm-up (numba dispatch, first calls)
        _, _, term, trunc, _ = env.step(actions[k])
        if term or trunc:
            env.reset()
    steps = resets = events = 0
    t_step = t_reset = 0.0
    start = time.perf_counter()
    cpu0 = time.process_time()
    while time.perf_counter() - start < seconds:
        for _ in range(200):
            t0 = time.perf_counter()
            _, _, term, trunc, info = env.step(actions[steps % len(actions)])
            t1 = time.perf_counter()
            t_step += t1 - t0
            steps += 1
            events += info["n_events"]
            if term or trunc:
                env.reset()
                t_reset += time.perf_counter() - t1
                resets += 1
    total = time.perf_counter() - start
    cpu = time.process_time() - cpu0
    env.close()
    return {"id": env_id, "wrapped": wrapped, "path": "kernel" if fast else "Simulator.run", "steps": steps,
            "steps_per_s": steps / total, "steps_per_cpu_s": steps / cpu,
            "step_only_per_s": steps / t_step, "step_us": 1e6 * t_step / steps,
            "reset_us": 1e6 * t_reset / max(resets, 1), "events_per_shot": events / steps}


def main(argv: list[str] | None = None) -> None:
    p = argparse.ArgumentParser(prog="python -m billiards_env.envs.benchmark", description=__doc__.split("\n")[0])
    p.add_argument("--seconds", type=float, default=3.0, help="time per id (s)")
    p.add_argument("--ids", nargs="*", default=list(ENV_IDS), help="env ids to measure")
    p.add_argument("--wrapped", action="store_true", help="also time the gym.make wrappers")
    p.add_argument("--compare", action="store_true", help="also time shots through Simulator.run(validate=False)")
    args = p.parse_args(argv)
    print(f"{'id':<24} {'wrapped':<8} {'path':<14} {'steps/s (incl. reset)':>22} {'per CPU-s':>10} "
          f"{'step only/s':>12} {'step us':>8} {'reset us':>9} {'events/shot':>12}")
    for env_id in args.ids:
        for wrapped in ((False, True) if args.wrapped else (False,)):
            for fast in ((True, False) if args.compare else (True,)):
                m = measure(env_id, args.seconds, wrapped=wrapped, fast=fast)
                print(f"{m['id']:<24} {str(m['wrapped']):<8} {m['path']:<14} {m['steps_per_s']:>22,.0f} "
                      f"{m['steps_per_cpu_s']:>10,.0f} "
                      f"{m['step_only_per_s']:>12,.0f} {m['step_us']:>8.1f} {m['reset_us']:>9.1f} "
                      f"{m['events_per_shot']:>12.1f}")


if __name__ == "__main__":
    main()
