"""``eight_ball_v0``: 8-ball for two players, a PettingZoo AEC env on ``Billiards8Ball-v0``'s game.

::

    from billiards_env.multi import eight_ball_v0

    env = eight_ball_v0.env(rules={"call_eight": False})   # any config key
    env.reset(seed=0)
    for agent in env.agent_iter():
        obs, reward, terminated, truncated, info = env.last()
        action = None if terminated or truncated else env.action_space(agent).sample()
        env.step(action)

The manual (agents, spaces, rewards, infos, episode end): :class:`billiards_env.multi.aec.BilliardsGameAEC`; the
game (rack, groups, the called 8, action layout): :class:`billiards_env.envs.eight_ball.EightBallEnv` and
docs/rules.md.
"""
from __future__ import annotations

from billiards_env.envs.eight_ball import EightBallEnv

from .aec import game_module

raw_env, env, parallel_env = game_module(EightBallEnv, "eight_ball_v0", __name__, doc="""\
8-ball for two players (see :class:`~billiards_env.multi.aec.BilliardsGameAEC` for the manual).

Action ``Box(-1, 1, (5,))`` by default: aim, power, place_x, place_y, pocket (the pocket called for the 8; no
such dim with ``rules={"call_eight": False}``; + side, top with ``spin_action``). Observation ``Box(0, 1,
(59,))``: 16 positions, 16 pocketed flags, 11 game features (the own group is each agent's own). A game ends on
the 8: pocketed legally in the called pocket after clearing the group wins, early / on a foul / in another
pocket loses.
""")

__all__ = ["env", "parallel_env", "raw_env"]
