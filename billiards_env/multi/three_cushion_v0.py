"""``three_cushion_v0``: three-cushion for two players, a PettingZoo AEC env on ``BilliardsThreeCushion-v0``'s game.

::

    from billiards_env.multi import three_cushion_v0

    env = three_cushion_v0.env()
    env.reset(seed=0)
    for agent in env.agent_iter():
        obs, reward, terminated, truncated, info = env.last()
        action = None if terminated or truncated else env.action_space(agent).sample()
        env.step(action)

The manual (agents, spaces, rewards, infos, episode end): :class:`billiards_env.multi.aec.BilliardsGameAEC`; the
game: :class:`billiards_env.envs.three_cushion.ThreeCushionEnv` and docs/rules.md.
"""
from __future__ import annotations

from billiards_env.envs.three_cushion import ThreeCushionEnv

from .aec import game_module

raw_env, env, parallel_env = game_module(ThreeCushionEnv, "three_cushion_v0", __name__, doc="""\
three-cushion for two players (see :class:`~billiards_env.multi.aec.BilliardsGameAEC` for the manual, and
:class:`billiards_env.envs.three_cushion.ThreeCushionEnv` for the spaces).""")

__all__ = ["env", "parallel_env", "raw_env"]
