"""Compile (or load from numba's cache) every kernel once: ``python -m billiards_env.warmup``.

The set-up script runs this, so a user's first shot or first ``env.step`` loads compiled code.
"""
from __future__ import annotations

import hashlib
import time
from pathlib import Path

from .physics.warmup import warm_up as warm_up_physics
from .players.warmup import warm_up as warm_up_players
from .registration import ENV_IDS

_PACKAGE = Path(__file__).resolve().parent
_STAMP = _PACKAGE / "__pycache__" / "kernels.sha256"


def kernel_sources() -> list[Path]:
    """Every module of the package with compiled code (``njit``), and all of ``physics/``."""
    out = set((_PACKAGE / "physics").glob("*.py"))
    for path in _PACKAGE.rglob("*.py"):
        if "njit" in path.read_text():
            out.add(path)
    return sorted(out)


def clear_stale_cache() -> bool:
    """Delete numba's cached machine code if a kernel source (:func:`kernel_sources`) changed since it was compiled.

    numba keys each cached function on its own file only, so a kernel that calls into another module would
    otherwise keep stale code after that module changes. Returns True if the cache was cleared.
    """
    digest = hashlib.sha256()
    for path in kernel_sources():
        digest.update(path.relative_to(_PACKAGE).as_posix().encode())
        digest.update(path.read_bytes())
    want = digest.hexdigest()
    if _STAMP.exists() and _STAMP.read_text() == want:
        return False
    for pattern in ("*.nbi", "*.nbc"):
        for f in _PACKAGE.rglob(pattern):
            f.unlink(missing_ok=True)
    _STAMP.parent.mkdir(exist_ok=True)
    _STAMP.write_text(want)
    return True


def warm_up() -> float:
    """Physics kernels, the players' kernels (:func:`billiards_env.players.warmup.warm_up`), the placement of a ball
    in hand, then one reset and step of each registered env (and of a game with the ``candidates`` types) and of the
    native vector env's paths (the pot scenes' and the games'); returns the seconds it took."""
    start = time.perf_counter()
    clear_stale_cache()
    warm_up_physics()
    warm_up_players()
    import gymnasium as gym
    import numpy as np

    from .physics.layout import nearest_free_point

    nearest_free_point(0.3, 0.3, np.array([[0.3, 0.3], [1.0, 0.5]]), np.ones(2, np.bool_), np.full(2, 0.028575), 0,
                       (0.1, 0.6, 0.1, 1.1), holes=np.array([[0.0, 0.0, 0.06]]))

    import billiards_env  # noqa: F401  (registers the ids)

    for env_id in ENV_IDS:
        env = gym.make(env_id)
        env.reset(seed=0)
        env.step(env.action_space.sample())
        env.close()
    env = gym.make("Billiards9Ball-v0", action_type="candidates", observation_type="candidates", opponent=None,
                   opening="ball_in_hand")
    env.reset(seed=0)
    env.step(np.zeros(env.action_space.shape, np.float32))
    env.close()
    # The native vector env's kernels: serial (one call per step), parallel, with shot noise, and the spin model.
    for kwargs in ({"threads": 1}, {"threads": 2, "angle_noise": 0.01},
                   {"threads": 1, "physics": {"friction": "spin"}, "spin_action": True}):
        env = gym.make_vec("BilliardsThreeBalls-v0", 2, **kwargs)
        env.reset(seed=0)
        env.step(env.action_space.sample())
        env.close()
    # The games' tables (9-ball and 8-ball in compiled code: one kernel for every thread count).
    env = gym.make_vec("Billiards9Ball-v0", 2)
    env.reset(seed=0)
    env.step(env.action_space.sample())
    env.close()
    return time.perf_counter() - start


if __name__ == "__main__":
    print(f"billiards_env kernels ready ({warm_up():.1f} s)")
