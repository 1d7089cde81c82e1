"""Compile (or load from numba's cache) every kernel once: ``python -m billiards_env.warmup``.

The set-up script runs this, so a user's first shot or first ``env.step`` loads compiled code.
"""
from __future__ import annotations

import time

from .physics.warmup import warm_up as warm_up_physics


def warm_up() -> float:
    """Physics kernels, then one reset and step of each registered env; returns the seconds it took."""
    start = time.perf_counter()
    warm_up_physics()
    import gymnasium as gym

    import billiards_env  # noqa: F401  (registers the ids)

    for env_id in ("BilliardsOneBall-v0", "BilliardsThreeBalls-v0", "BilliardsRack-v0"):
        env = gym.make(env_id)
        env.reset(seed=0)
        env.step(env.action_space.sample())
        env.close()
    return time.perf_counter() - start


if __name__ == "__main__":
    print(f"billiards_env kernels ready ({warm_up():.1f} s)")
