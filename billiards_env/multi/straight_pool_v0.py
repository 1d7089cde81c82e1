"""``straight_pool_v0``: straight pool (14.1 continuous) for two players, a PettingZoo AEC env on
``BilliardsStraightPool-v0``'s game.

::

    from billiards_env.multi import straight_pool_v0

    env = straight_pool_v0.env(rules={"target": 50})  # any config key of the single-agent env
    env.reset(seed=0)
    for agent in env.agent_iter():
        obs, reward, terminated, truncated, info = env.last()
        action = None if terminated or truncated else env.action_space(agent).sample()
        env.step(action)

The manual (agents, spaces, rewards, infos, episode end): :class:`billiards_env.multi.aec.BilliardsGameAEC`; the
game (rack, rules, action layout): :class:`billiards_env.envs.straight_pool.StraightPoolEnv` and docs/games.md.
"""
from __future__ import annotations

from billiards_env.envs.straight_pool import StraightPoolEnv

from .aec import game_module

raw_env, env, parallel_env = game_module(StraightPoolEnv, "straight_pool_v0", __name__, doc="""\
Straight pool for two players (see :class:`~billiards_env.multi.aec.BilliardsGameAEC` for the manual).

Action ``Box(-1, 1, (6,))`` by default: aim, power, place_x, place_y, ball, pocket (the called ball and pocket;
+ side, top with ``spin_action``). Observation ``Box(0, 1, (56,))``: 16 positions, 16 pocketed flags, 8 game
features. A game ends when a player reaches the target (``rules={"target": ...}``, 150 by default).
""")

__all__ = ["env", "parallel_env", "raw_env"]
