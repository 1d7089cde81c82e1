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

from billiards_env.envs.snooker import SnookerEnv

from .aec import game_module

raw_env, env, parallel_env = game_module(SnookerEnv, "snooker_v0", __name__, doc="""\
Snooker for two players (see :class:`~billiards_env.multi.aec.BilliardsGameAEC` for the manual, and
:class:`billiards_env.envs.snooker.SnookerEnv` for the spaces).""")

__all__ = ["env", "parallel_env", "raw_env"]
