"""A game's declarations as data: each Declaration maps an action value to its value and back, checks a value, and
the action types carry whatever a game declares (no branch per declaration)."""
from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401
from billiards_env.envs.actions import AbsoluteAim
from billiards_env.games.declarations import CALLED_BALL, CALLED_POCKET, PUSH_OUT, Declaration, calls_of
from billiards_env.shot_path import CueShot


@pytest.mark.parametrize("decl, values", [(CALLED_POCKET, range(6)), (CALLED_BALL, range(1, 16)),
                                          (PUSH_OUT, (False, True))])
def test_every_value_round_trips_through_its_action_value(decl, values):
    for v in values:
        a = decl.encode(v, 6, 16)
        assert -1.0 <= a <= 1.0 and decl.decode(a, 6, 16) == v
        assert decl.decode(np.float32(a), 6, 16) == v  # through the float32 action


def test_the_ends_of_the_action_range_are_the_first_and_last_values():
    assert CALLED_BALL.decode(-1.0, 6, 16) == 1 and CALLED_BALL.decode(1.0, 6, 16) == 15
    assert CALLED_POCKET.decode(1.0, 6, 16) == 5 and PUSH_OUT.decode(0.0, 6, 16) is False
    assert CALLED_POCKET.encode(None, 6, 16) == CALLED_POCKET.encode(0, 6, 16)  # nothing called: the first


def test_values_are_checked_with_the_valid_range():
    with pytest.raises(ValueError, match="pocket: must be a pocket index 0..5, got 6"):
        CALLED_POCKET.check(6, 6, 16)
    with pytest.raises(ValueError, match="ball: must be an object ball's row 1..9, got 0"):
        CALLED_BALL.check(0, 6, 10)
    with pytest.raises(ValueError, match="push: must be True or False"):
        PUSH_OUT.check(1, 6, 16)
    with pytest.raises(ValueError, match="kind 'colour'"):
        Declaration("nominated", "colour")


def test_a_shot_carries_the_declarations_of_its_game_only():
    shot = CueShot(0.1, 2.0, calls=calls_of((CALLED_BALL, CALLED_POCKET), {"pocket": 3}))
    assert shot.calls == (("ball", None), ("pocket", 3)) and shot.call("pocket") == 3 and shot.call("push") is None
    assert shot.with_calls(ball=4, push=True).calls == (("ball", 4), ("pocket", 3))
    assert CueShot(0.1, 2.0).with_calls(pocket=2).calls == ()


def test_an_action_type_adds_one_dim_per_declaration_in_order():
    env = gym.make("BilliardsStraightPool-v0", opponent=None)
    u = env.unwrapped
    at = AbsoluteAim(u.config, True, (PUSH_OUT, CALLED_BALL), u.table.n_pockets)
    assert at.layout() == "aim, power, place_x, place_y, push, ball" and at.space.shape == (6,)
    env.reset(seed=0)
    shot = at.shot(u.table_state, at.action(u.table_state, 0.2, 3.0, push=True, ball=9, pocket=4))  # pocket: not declared
    assert shot.calls == (("push", True), ("ball", 9))
    with pytest.raises(TypeError, match="Declaration objects"):
        AbsoluteAim(u.config, True, ("pocket",), 6)
