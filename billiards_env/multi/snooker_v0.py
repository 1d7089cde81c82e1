"""``snooker_v0``: Snooker for two players, a PettingZoo AEC env on ``BilliardsSnooker-v0``'s game.

::

    from billiards_env.multi import snooker_v0

    env = snooker_v0.env()
    env.reset(seed=0)
    for agent in env.agent_iter():
        obs, reward, terminated, truncated, info = env.last()
        action = None if terminated or truncated else env.action_space(agent).sample()
        env.step(action)

The manual (agents, spaces, rewards, infos, episode end): :class:`billiards_env.multi.aec.BilliardsGameAEC`; the
game: :class:`billiards_env.envs.snooker.SnookerEnv` and docs/rules.md.
"""
from __future__ import annotations

from typing import Any, ClassVar

from pettingzoo import AECEnv

from billiards_env.envs.snooker import SnookerEnv

from .aec import BilliardsGameAEC, wrap


class raw_env(BilliardsGameAEC):  # noqa: N801 - PettingZoo's name
    """Snooker for two players (see :class:`~billiards_env.multi.aec.BilliardsGameAEC` for the manual, and
    :class:`billiards_env.envs.snooker.SnookerEnv` for the spaces)."""

    metadata: ClassVar[dict[str, Any]] = {**BilliardsGameAEC.metadata, "name": "snooker_v0"}
    game_class = SnookerEnv


def env(render_mode: str | None = None, config: Any = None, **overrides: Any) -> AECEnv:
    """:class:`raw_env` in PettingZoo's ``OrderEnforcingWrapper`` (see :func:`billiards_env.multi.aec.wrap`)."""
    return wrap(raw_env(render_mode=render_mode, config=config, **overrides))


__all__ = ["env", "raw_env"]
