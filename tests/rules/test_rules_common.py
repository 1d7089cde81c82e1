"""Rules both games share, each on a scripted table: the shooter's ball first, a rail or a pot after contact, no
scratch; a foul hands the opponent the cue ball anywhere; a legal pot keeps the turn, a legal miss ends it."""
from __future__ import annotations

import math

import pytest
from rules_helpers import (R, angle_to, miss_all, parked, pot, rail_miss, scratch_pot, shoot, soft_touch,
                           straight_scratch)

from billiards_env.rules import ANYWHERE, EightBall, GameState, NineBall, legal_targets, ruleset_for
from billiards_env.rules import state as S


def nine_mid() -> tuple[NineBall, GameState, str]:
    """9-ball after the break, balls 1, 2, 9 up: the 1 is the target, the 2 a wrong ball."""
    return NineBall(), GameState("nine_ball", (1, 2, 9), ball_in_hand=False, break_shot=False), "2"


def eight_mid() -> tuple[EightBall, GameState, str]:
    """8-ball, player 0 on solids, balls 1, 2, 8, 9, 10 up: the 1 is his, the 9 a wrong ball."""
    st = GameState("eight_ball", (1, 2, 8, 9, 10), ball_in_hand=False, break_shot=False,
                   groups=("solids", "stripes"))
    return EightBall(), st, "9"


GAMES = pytest.mark.parametrize("setup", [nine_mid, eight_mid], ids=["nine_ball", "eight_ball"])


def others(state: GameState, *skip: str) -> list[int]:
    return [n for n in state.on_table if str(n) not in skip]


def assert_foul(call, state, reason):
    assert call.foul and not call.legal
    assert call.reason == reason and reason in call.fouls
    assert call.turn_over and call.next_shooter == state.opponent
    assert call.ball_in_hand == ANYWHERE
    assert not call.game_over


@GAMES
def test_target_pocketed_keeps_the_turn(setup):
    rules, state, _ = setup()
    s = pot("1", others(state, "1"))
    assert s.first_contact == 1 and s.pocketed == (1,) and not s.cue_pocketed
    c, nxt = rules.play(state, s)
    assert c.legal and not c.foul and c.reason == S.LEGAL
    assert not c.turn_over and c.next_shooter == state.shooter and c.ball_in_hand is False
    assert 1 not in nxt.on_table and nxt.shooter == state.shooter and c.respot == ()


@GAMES
def test_legal_miss_with_a_rail_passes_the_turn_without_ball_in_hand(setup):
    rules, state, _ = setup()
    s = rail_miss("1", others(state, "1"))
    assert s.first_contact == 1 and s.rail_balls and not s.pocketed
    c, nxt = rules.play(state, s)
    assert c.legal and c.turn_over and c.ball_in_hand is False
    assert nxt.shooter == state.opponent and nxt.ball_in_hand is False and nxt.on_table == state.on_table


@GAMES
def test_scratch_is_a_foul_and_the_pocketed_target_stays_down(setup):
    rules, state, _ = setup()
    s = scratch_pot("1", others(state, "1"))
    assert s.cue_pocketed and s.pocketed == (1,) and s.first_contact == 1
    c, nxt = rules.play(state, s)
    assert_foul(c, state, S.SCRATCH)
    assert c.cue_pocketed and c.respot == () and 1 not in nxt.on_table
    assert nxt.ball_in_hand == ANYWHERE and nxt.shooter == state.opponent


@GAMES
def test_scratch_without_contact_is_a_foul(setup):
    rules, state, _ = setup()
    s = straight_scratch(state.on_table)
    assert s.cue_pocketed and s.first_contact is None
    c = rules.call(state, s)
    assert_foul(c, state, S.SCRATCH)
    assert c.fouls == (S.SCRATCH, S.NO_CONTACT)


@GAMES
def test_hitting_no_ball_is_a_foul(setup):
    rules, state, _ = setup()
    s = miss_all(state.on_table)
    assert s.first_contact is None and not s.cue_pocketed
    assert_foul(rules.call(state, s), state, S.NO_CONTACT)


@GAMES
def test_wrong_ball_first_is_a_foul(setup):
    rules, state, wrong = setup()
    assert int(wrong) not in legal_targets(state)
    s = rail_miss(wrong, others(state, wrong))
    assert s.first_contact == int(wrong) and s.rail_balls
    assert_foul(rules.call(state, s), state, S.WRONG_BALL_FIRST)


@GAMES
def test_wrong_ball_first_pocketed_is_a_foul_and_stays_down(setup):
    rules, state, wrong = setup()
    s = pot(wrong, others(state, wrong))
    assert s.first_contact == int(wrong) and s.pocketed == (int(wrong),)
    c, nxt = rules.play(state, s)
    assert_foul(c, state, S.WRONG_BALL_FIRST)
    assert c.respot == () and int(wrong) not in nxt.on_table


@GAMES
def test_no_rail_after_contact_is_a_foul(setup):
    rules, state, _ = setup()
    s = soft_touch("1", others(state, "1"))
    assert s.first_contact == 1 and not s.rail_balls and not s.pocketed
    assert_foul(rules.call(state, s), state, S.NO_RAIL)


@GAMES
def test_a_cushion_before_the_contact_does_not_count_as_the_rail(setup):
    """The cue ball banks off the bottom cushion into the 1, which then rolls a little: no rail after contact."""
    rules, state, _ = setup()
    cue, one = (0.9, 0.3), (1.3, 0.3)
    mirror = (one[0], -one[1])  # aim at the 1's image in the bottom cushion
    s = shoot({"cue": cue, "1": one, **parked(others(state, "1"))}, angle_to(cue, mirror), 0.5)
    assert s.first_contact == 1 and not s.pocketed and not s.rail_balls
    assert_foul(rules.call(state, s), state, S.NO_RAIL)


@GAMES
def test_ruleset_for_builds_the_games_ruleset(setup):
    rules, state, _ = setup()
    assert type(ruleset_for(state.game)) is type(rules)


@GAMES
def test_frozen_ball_driven_into_its_cushion_counts_as_the_rail(setup):
    """Simplification (docs/rules.md): the 1 rests against the bottom cushion and is driven into it; the engine
    reports the cushion contact, so the shot is legal (the WPA would want the ball to leave and come back)."""
    rules, state, _ = setup()
    s = shoot({"cue": (1.0, 0.4), "1": (1.0, R), **parked(others(state, "1"))}, -math.pi / 2, 0.5)
    assert s.first_contact == 1 and 1 in s.rail_balls and not s.pocketed
    assert rules.call(state, s).legal
