"""The hand-written rule on the ``candidates_path`` observation (``python -m agents.path_rule``)."""
from __future__ import annotations

import gymnasium as gym

import billiards_env  # noqa: F401
from agents.path_rule import interval_action


def _env():
    return gym.make("BilliardsOneBall-v0", action_type="candidates_aim", observation_type="candidates_path",
                    candidate_slots=7, candidate_speed_factor=3.0)


def test_the_interval_rule_pots_where_the_observation_says_it_can():
    """The hand-written rule on the observation (agents/path_rule.py) pots the ball without a scratch on most tables:
    the thresholds are the engine's (a wrong sign or unit would send it into the jaws or after the object ball)."""
    env = _env()
    ok = 0
    for seed in range(40):
        obs, _ = env.reset(seed=seed)
        ok += bool(env.step(interval_action(obs, 7))[4]["is_success"])
    assert ok >= 36
