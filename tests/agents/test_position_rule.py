"""The hand-written rule on the ``candidates_position`` observation (``python -m agents.position_rule``)."""
from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401
from agents.position_rule import RULE_KWARGS, PositionRulePlayer, position_action
from billiards_env.envs.candidates import SLOT_FEATURES
from billiards_env.envs.position import POINT_VALUES, POSITION_FEATURES, POWERS, TOPS


def _obs(n_slots=4, n_balls=10):
    return np.zeros(3 * n_balls + (SLOT_FEATURES + POSITION_FEATURES) * n_slots + 11, np.float32)


def _grid(o, n_slots=4, n_balls=10):
    base = 3 * n_balls
    slots = o[base:base + SLOT_FEATURES * n_slots].reshape(n_slots, SLOT_FEATURES)
    grid = o[base + SLOT_FEATURES * n_slots:base + (SLOT_FEATURES + POSITION_FEATURES) * n_slots].reshape(
        n_slots, len(POWERS) * len(TOPS), POINT_VALUES)
    return slots, grid


def test_it_plays_the_grid_point_that_pots_without_scratch_and_leaves_the_easiest_next_shot():
    o = _obs()
    slots, grid = _grid(o)
    slots[:3, 0] = 1.0
    slots[:3, 7] = 1.0
    grid[:3, :, 0] = 1.0  # every point pots
    grid[:3, :, 2] = 0.5  # a rest point
    grid[0, :, 4] = 0.2
    grid[1, 7, 4] = 0.9  # slot 1, power 0.83 (index 2), top 0 (index 1): the best next shot...
    grid[1, 8, 4] = 1.0  # ...unless the best scratches
    grid[1, 8, 1] = 1.0
    grid[2, 1, 4] = 1.0  # the softest power is left out
    a = position_action(o)
    assert a[0] == pytest.approx(1.5 / 4) and a[1] == pytest.approx(POWERS[2]) and a[3] == pytest.approx(TOPS[1])
    assert a[2] == 0.0 and np.all(a[4:] == 0.0)
    # with the softest power allowed, slot 2's point wins
    a = position_action(o, min_power=0)
    assert a[0] == pytest.approx(2.5 / 4) and a[1] == pytest.approx(POWERS[0])
    # nothing that pots: action 0 (the geometric player's shot)
    grid[:, :, 0] = 0.0
    assert np.all(position_action(o) == 0.0)


def test_it_plays_a_game_env_in_its_types():
    env = gym.make("Billiards9Ball-v0", **{**RULE_KWARGS, "opponent": "geometric"})
    obs, _ = env.reset(seed=0)
    rule = PositionRulePlayer()
    for _ in range(6):
        a = rule.act(env, obs)
        assert env.action_space.contains(a)
        obs, _, term, trunc, _ = env.step(a)
        if term or trunc:
            break
    other = gym.make("Billiards9Ball-v0", action_type="candidates", observation_type="candidates")
    other_obs, _ = other.reset(seed=0)
    with pytest.raises(ValueError, match="candidates_position"):
        rule.act(other, other_obs)


def test_the_command_line_plays_the_geometric_player_and_reports_every_game(capsys):
    import re

    from agents.position_rule import main

    assert main(["--games", "2", "--noise", "0"]) == 0
    line = capsys.readouterr().out.strip().splitlines()[-1]
    m = re.match(r"position rule vs geometric, noise 0: (\d+)-(\d+) = ([\d.]+)% \[(\d+), (\d+)\]", line)
    assert m, line
    wins, losses, pct = int(m[1]), int(m[2]), float(m[3])
    assert wins + losses == 2 and pct == 100 * wins / 2
    assert int(m[4]) <= pct <= int(m[5])
