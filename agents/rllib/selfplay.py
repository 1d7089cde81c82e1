"""The two-player games on RLlib's multi-agent API: the PettingZoo AEC env of :mod:`billiards_env.multi` in
RLlib's :class:`~ray.rllib.env.wrappers.pettingzoo_env.PettingZooEnv`, for self-play.

One AEC step is one shot of the player to shoot; RLlib's wrapper returns the observation of the agent to act next
only (a turn-based game), and each agent's reward for the shots since it last acted (zero-sum win/loss by
default). ``self_play="shared"`` maps both seats to one policy (module ``shared``: it learns from both sides of
every game); ``"separate"`` gives each seat its own (modules ``player_0`` and ``player_1``). The observation is
the single-agent game env's from the shooter's point of view, so the shared policy also plays
``Billiards9Ball-v0`` / ``Billiards8Ball-v0`` against their built-in opponent (how ``agents.evaluate`` rates it).
"""
from __future__ import annotations

import importlib
from typing import Any

from billiards_env.games import GAMES as REGISTERED

from .config import SELF_PLAY_PREFIX, RLlibConfigError

#: Registered id of each game -> its two-player module in billiards_env.multi.
GAMES = {g.env_id: f"billiards_env.multi.{g.aec_module}" for g in REGISTERED.values()}
SHARED_MODULE = "shared"


def env_name(env_id: str) -> str:
    """The name the self-play env of ``env_id`` is registered under with Ray (``billiards_selfplay:<id>``)."""
    if env_id not in GAMES:
        raise RLlibConfigError(f"self_play: {env_id} is not a two-player game; self-play needs one of {sorted(GAMES)}")
    return SELF_PLAY_PREFIX + env_id


def make_env(env_id: str, env_config: Any) -> Any:
    """The two-player env of ``env_id`` with the config keys ``env_config`` in RLlib's PettingZoo wrapper."""
    from ray.rllib.env.wrappers.pettingzoo_env import PettingZooEnv

    module = importlib.import_module(GAMES[env_id])
    return PettingZooEnv(module.env(**dict(env_config or {})))


def register(env_id: str) -> str:
    """Register the self-play env of ``env_id`` with Ray (env runners on every node find it); its name."""
    from functools import partial

    from ray.tune.registry import register_env

    name = env_name(env_id)
    register_env(name, partial(make_env, env_id))
    return name


def map_shared(agent_id: str, episode: Any = None, **kwargs: Any) -> str:
    """Policy mapping: both seats play the one shared policy."""
    return SHARED_MODULE


def map_by_seat(agent_id: str, episode: Any = None, **kwargs: Any) -> str:
    """Policy mapping: each seat (``player_0``, ``player_1``) has its own policy."""
    return str(agent_id)


def policies(mode: str) -> tuple[set[str], Any]:
    """``(module ids, mapping function)`` for ``self_play`` mode ``shared`` or ``separate``."""
    if mode == "shared":
        return {SHARED_MODULE}, map_shared
    from billiards_env.multi import AGENTS

    return set(AGENTS), map_by_seat


__all__ = ["GAMES", "SHARED_MODULE", "env_name", "make_env", "register", "map_shared", "map_by_seat", "policies"]
