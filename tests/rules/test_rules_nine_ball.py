"""9-ball rules, each on a scripted table: the break, the 9, push-outs, three fouls."""
from __future__ import annotations

import pytest
from rules_helpers import (FOOT_SPOT, HEAD_SPOT, TABLE, combo, diamond_rack, miss_all, pot,
                           rail_miss, scratch_pot, shoot, straight_scratch)

from billiards_env.rules import (ANYWHERE, KITCHEN, GameState, NineBall, NineBallOptions, RulesError, ShotInfo,
                                 nine_ball_targets)
from billiards_env.rules import state as S

PUSH = ShotInfo(push_out=True)


def mid(on=(1, 2, 9), **kw) -> GameState:
    """A 9-ball game after the break, player 0 to shoot from where the cue ball lies."""
    kw.setdefault("ball_in_hand", False)
    return GameState("nine_ball", on, break_shot=False, **kw)


def break_state(on=tuple(range(1, 10))) -> GameState:
    return NineBall().initial_state(0, on)


def test_initial_state_is_a_break_from_the_kitchen():
    st = NineBall().initial_state()
    assert st.break_shot and st.ball_in_hand == KITCHEN and st.shooter == 0
    assert st.on_table == tuple(range(1, 10)) and not st.push_out_available
    assert nine_ball_targets(st) == (1,)


def test_target_is_the_lowest_ball():
    assert nine_ball_targets(mid((3, 5, 9))) == (3,)
    assert NineBall().legal_targets(mid((9,))) == (9,)


# --- the break ---------------------------------------------------------------------------------------------------

def test_break_driving_four_balls_to_the_rail_is_legal_and_opens_the_push_out():
    """A full-speed break on a pocketless table: nothing drops, many balls reach a cushion."""
    rack = diamond_rack(FOOT_SPOT)
    s = shoot({"cue": HEAD_SPOT, **rack}, 0.0, 8.0, table=TABLE.without_pockets())
    assert s.first_contact == 1 and not s.pocketed and s.object_balls_to_rail >= 4
    rules = NineBall()
    c, nxt = rules.play(break_state(), s)
    assert c.legal and c.turn_over and c.ball_in_hand is False and not c.game_over
    assert nxt.shooter == 1 and not nxt.break_shot and nxt.push_out_available


def test_soft_break_is_a_foul_with_ball_in_hand_anywhere():
    rack = diamond_rack(FOOT_SPOT)
    cue = (FOOT_SPOT[0] - 0.35, FOOT_SPOT[1])
    s = shoot({"cue": cue, **rack}, 0.0, 0.5)
    assert s.first_contact == 1 and not s.pocketed and s.object_balls_to_rail < 4
    c, nxt = NineBall().play(break_state(), s)
    assert c.foul and c.reason == S.ILLEGAL_BREAK and c.ball_in_hand == ANYWHERE and c.next_shooter == 1
    assert nxt.ball_in_hand == ANYWHERE and nxt.push_out_available  # the incoming player may still push out


def test_break_rail_count_is_an_option():
    rack = diamond_rack(FOOT_SPOT)
    cue = (FOOT_SPOT[0] - 0.35, FOOT_SPOT[1])
    s = shoot({"cue": cue, **rack}, 0.0, 0.5)
    assert s.object_balls_to_rail == 0
    assert NineBall(NineBallOptions(break_rail_balls=0)).call(break_state(), s).legal


def test_break_that_pockets_a_ball_is_legal_and_the_breaker_continues():
    """The 1 drives the 2 into pocket 5; the other balls wait at the far end."""
    s = combo("1", "2", others=(3, 4, 5, 6, 7, 8, 9))
    assert s.first_contact == 1 and s.pocketed == (2,) and s.object_balls_to_rail < 4
    c, nxt = NineBall().play(break_state(), s)
    assert c.legal and not c.turn_over and nxt.shooter == 0 and 2 not in nxt.on_table
    assert nxt.push_out_available


def test_break_must_hit_the_one_first():
    rack = diamond_rack(FOOT_SPOT, numbers=(2, 1, 3, 4, 9, 5, 6, 7, 8))  # the 2 at the apex
    s = shoot({"cue": HEAD_SPOT, **rack}, 0.0, 8.0, table=TABLE.without_pockets())
    assert s.first_contact == 2 and s.object_balls_to_rail >= 4
    c = NineBall().call(break_state(), s)
    assert c.foul and c.fouls == (S.WRONG_BALL_FIRST,) and c.ball_in_hand == ANYWHERE


def test_break_scratch_is_a_foul_with_ball_in_hand_anywhere():
    s = straight_scratch(range(1, 10))
    assert s.cue_pocketed
    c = NineBall().call(break_state(), s)
    assert c.foul and c.reason == S.SCRATCH and c.ball_in_hand == ANYWHERE and c.next_shooter == 1


def test_nine_on_a_legal_break_wins():
    s = combo("1", "9", others=(2, 3, 4, 5, 6, 7, 8))
    assert s.first_contact == 1 and s.pocketed == (9,) and not s.cue_pocketed
    c = NineBall().call(break_state(), s)
    assert c.game_over and c.winner == 0 and c.legal and c.reason == S.NINE_POCKETED and c.respot == ()


def test_nine_on_a_fouled_break_is_respotted():
    """The cue ball hits the 9 first (the 1 waits at the far end): a foul, the 9 comes back."""
    s = pot("9", others=range(1, 9))
    assert s.first_contact == 9 and s.pocketed == (9,)
    c, nxt = NineBall().play(break_state(), s)
    assert c.foul and not c.game_over and c.respot == (9,) and 9 in nxt.on_table


# --- the 9 --------------------------------------------------------------------------------------------------------

def test_nine_on_a_legal_combination_wins():
    s = combo("1", "9", others=(2,))
    assert s.first_contact == 1 and s.pocketed == (9,)
    c = NineBall().call(mid(), s)
    assert c.game_over and c.winner == 0 and c.reason == S.NINE_POCKETED


def test_nine_on_a_scratch_is_respotted_and_the_opponent_has_ball_in_hand():
    s = scratch_pot("9")
    assert s.first_contact == 9 and s.pocketed == (9,) and s.cue_pocketed
    c, nxt = NineBall().play(mid((9,), shooter=1), s)
    assert c.foul and c.reason == S.SCRATCH and not c.game_over and c.respot == (9,)
    assert nxt.on_table == (9,) and nxt.shooter == 0 and nxt.ball_in_hand == ANYWHERE


def test_nine_hit_first_out_of_turn_is_respotted_and_other_balls_stay_down():
    """The 9 is hit before the 1 and drops: foul, the 9 back on the table; the 2, pocketed by a foul too, stays
    down."""
    s = pot("9", others=(1, 2))
    c, nxt = NineBall().play(mid(), s)
    assert c.foul and c.reason == S.WRONG_BALL_FIRST and c.respot == (9,) and nxt.on_table == (1, 2, 9)
    s = pot("2", others=(1, 9))
    c, nxt = NineBall().play(mid(), s)
    assert c.foul and c.respot == () and nxt.on_table == (1, 9)


# --- push-out -----------------------------------------------------------------------------------------------------

def after_break(shooter: int = 1) -> GameState:
    return mid((1, 2, 9), shooter=shooter, push_out_available=True)


def test_push_out_needs_no_contact_and_hands_the_choice_to_the_opponent():
    s = miss_all((1, 2, 9))
    assert s.first_contact is None
    rules = NineBall()
    c, nxt = rules.play(after_break(), s, PUSH)
    assert c.legal and not c.foul and c.reason == S.PUSH_OUT and c.push_out
    assert c.turn_over and c.ball_in_hand is False
    assert nxt.shooter == 0 and nxt.push_out_pending and not nxt.push_out_available
    back = rules.pass_back(nxt)
    assert back.shooter == 1 and not back.push_out_pending and back.ball_in_hand is False
    # Playing instead of passing: an ordinary shot, and the pending choice is gone.
    c2, nxt2 = rules.play(nxt, rail_miss("1", (2, 9)))
    assert c2.legal and not nxt2.push_out_pending and nxt2.shooter == 1


def test_push_out_pockets_stay_down_but_the_nine_is_respotted():
    s = pot("9", others=(1, 2))
    c, nxt = NineBall().play(after_break(), s, PUSH)
    assert c.legal and not c.game_over and c.respot == (9,) and c.turn_over and nxt.on_table == (1, 2, 9)
    s = pot("2", others=(1, 9))
    c, nxt = NineBall().play(after_break(), s, PUSH)
    assert c.legal and c.respot == () and nxt.on_table == (1, 9) and nxt.push_out_pending


def test_push_out_scratch_is_a_foul():
    s = straight_scratch((1, 2, 9))
    c, nxt = NineBall().play(after_break(), s, PUSH)
    assert c.foul and c.fouls == (S.SCRATCH,) and c.ball_in_hand == ANYWHERE and not nxt.push_out_pending


def test_push_out_only_right_after_the_break():
    rules = NineBall()
    with pytest.raises(RulesError, match="push_out"):
        rules.call(mid(), miss_all((1, 2, 9)), PUSH)
    st = after_break()
    _, nxt = rules.play(st, rail_miss("1", (2, 9)))  # an ordinary shot uses up the chance
    assert not nxt.push_out_available
    with pytest.raises(RulesError, match="pass_back"):
        rules.pass_back(nxt)


def test_push_out_option_off():
    rack = diamond_rack(FOOT_SPOT)
    s = shoot({"cue": HEAD_SPOT, **rack}, 0.0, 8.0, table=TABLE.without_pockets())
    rules = NineBall(NineBallOptions(push_out=False))
    _, nxt = rules.play(rules.initial_state(), s)
    assert not nxt.push_out_available


# --- three fouls --------------------------------------------------------------------------------------------------

def test_third_foul_in_a_row_loses():
    s = miss_all((1, 2, 9))
    st = mid(shooter=1, fouls_in_a_row=(0, 2))
    c = NineBall().call(st, s)
    assert c.game_over and c.winner == 0 and c.reason == S.THREE_FOULS and c.foul and c.fouls == (S.NO_CONTACT,)
    c = NineBall(NineBallOptions(three_foul_rule=False)).call(st, s)
    assert not c.game_over and c.foul


def test_three_fouls_over_a_played_sequence():
    """Player 0 fouls, player 1 plays safe, three times: player 0 loses on the third foul; a legal shot in between
    resets the count."""
    rules = NineBall()
    foul_shot = miss_all((1, 2, 9))
    safe = rail_miss("1", (2, 9))
    st = mid()
    for k in range(2):
        c, st = rules.play(st, foul_shot)
        assert c.foul and not c.game_over and st.fouls_in_a_row[0] == k + 1
        c, st = rules.play(st, safe)  # player 1, ball in hand (placement is the env's; the shot is scripted)
        assert c.legal and st.shooter == 0
    reset, _ = rules.play(st, safe)
    assert reset.legal and rules.next_state(st, reset).fouls_in_a_row[0] == 0
    c, st = rules.play(st, foul_shot)
    assert c.game_over and c.winner == 1 and st.game_over and st.winner == 1
    with pytest.raises(RulesError, match="game is over"):
        rules.call(st, safe)


def test_three_foul_counts_are_per_player():
    st = mid(fouls_in_a_row=(0, 2))  # player 1 had two fouls; player 0 fouls now
    c = NineBall().call(st, miss_all((1, 2, 9)))
    assert c.foul and not c.game_over

