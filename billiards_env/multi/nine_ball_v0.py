"""``nine_ball_v0``: 9-ball for two players, a PettingZoo AEC env on ``Billiards9Ball-v0``'s game.

::

    from billiards_env.multi import nine_ball_v0

    env = nine_ball_v0.env()             # any config key: nine_ball_v0.env(friction="spin", spin_action=True)
    env.reset(seed=0)
    for agent in env.agent_iter():
        obs, reward, terminated, truncated, info = env.last()
        action = None if terminated or truncated else env.action_space(agent).sample()
        env.step(action)

The manual (agents, spaces, rewards, infos, episode end): :class:`billiards_env.multi.aec.BilliardsGameAEC`; the
game (rack, rules, action layout): :class:`billiards_env.envs.nine_ball.NineBallEnv` and docs/rules.md.
"""
from __future__ import annotations

from billiards_env.envs.nine_ball import NineBallEnv

from .aec import game_module

raw_env, env, parallel_env = game_module(NineBallEnv, "nine_ball_v0", __name__, doc="""\
9-ball for two players (see :class:`~billiards_env.multi.aec.BilliardsGameAEC` for the manual).

Action ``Box(-1, 1, (4,))`` by default: aim, power, place_x, place_y (+ side, top with ``spin_action``; + push
with ``rules={"push_out": True}``). Observation ``Box(0, 1, (41,))``: 10 positions, 10 pocketed flags, 11 game
features. A game ends on the 9 pocketed legally (its shooter wins) or a third foul in a row (its player loses).
""")

__all__ = ["env", "parallel_env", "raw_env"]
