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


def check_env_id(env_id: str) -> str:
    """``env_id`` if Gymnasium knows it (ours, or another registered id), else a :class:`ValueError` in one line with
    a did-you-mean and our ids: what every command-line tool prints instead of Gymnasium's ``NameNotFound``."""
    import difflib

    known: list[str] = list(ENV_IDS)
    try:
        from gymnasium.envs.registration import registry
    except ImportError:  # pragma: no cover - physics-only use without gymnasium
        pass
    else:
        if env_id in registry:
            return env_id
        known += [k for k in registry if k not in ENVS]
    if env_id in ENVS:
        return env_id
    close = difflib.get_close_matches(str(env_id), known, n=1)
    hint = f"did you mean {close[0]!r}? " if close else ""
    raise ValueError(f"unknown env id {env_id!r}; {hint}the billiards ids: {', '.join(ENV_IDS)}")


def env_id_arg(text: str) -> str:
    """An argparse ``type`` for an ``--env`` option: :func:`check_env_id`, so a typo is argparse's one-line error
    (exit 2) with the did-you-mean."""
    import argparse

    try:
        return check_env_id(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


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


__all__ = ["ENVS", "SCENES", "ENV_IDS", "check_env_id", "env_id_arg", "register_envs", "vector_entry_point"]
