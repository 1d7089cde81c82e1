"""The registered environment ids: the one list every other module reads (Gymnasium registration, tests,
benchmarks, warm-up, players).

``ENVS`` maps each id to its entry point (``module:Class``): the scenes without rules, then every game of the game
registry (:data:`billiards_env.games.GAMES`, which lists each game once). ``register_envs()`` registers them with
Gymnasium (``import billiards_env`` calls it). This module and the game registry import nothing heavy, so reading the
list costs nothing.
"""
from __future__ import annotations

from .games.registry import GAMES

#: The scenes without rules: registered id -> entry point of its environment class.
SCENES: dict[str, str] = {
    "BilliardsOneBall-v0": "billiards_env.envs.one_ball:OneBallEnv",
    "BilliardsThreeBalls-v0": "billiards_env.envs.three_balls:ThreeBallsEnv",
    "BilliardsRack-v0": "billiards_env.envs.rack:RackEnv",
}
#: Registered id -> entry point of its environment class (the scenes, then the games).
ENVS: dict[str, str] = {**SCENES, **{g.env_id: g.env_class for g in GAMES.values()}}
#: Every registered id, in registration order.
ENV_IDS: tuple[str, ...] = tuple(ENVS)


def vector_entry_point(env_id: str) -> str:
    """``module:Class`` of the native vector env of ``env_id`` (``billiards_env/envs/vector.py`` defines one per
    id, named after the env class: ``OneBallEnv`` -> ``OneBallVectorEnv``)."""
    name = ENVS[env_id].rsplit(":", 1)[1]
    return f"billiards_env.envs.vector:{name.removesuffix('Env')}VectorEnv"


def register_envs() -> None:
    """Register every id with Gymnasium, with its native vector env as ``vector_entry_point`` (so
    ``gymnasium.make_vec(id, n)`` returns it); idempotent; a no-op without Gymnasium: physics-only use."""
    try:
        from gymnasium.envs.registration import register, registry
    except ImportError:  # pragma: no cover - physics-only use without gymnasium
        return
    for env_id, entry_point in ENVS.items():
        if env_id not in registry:
            register(id=env_id, entry_point=entry_point, vector_entry_point=vector_entry_point(env_id))


__all__ = ["ENVS", "SCENES", "ENV_IDS", "register_envs", "vector_entry_point"]
