"""Straight pool (14.1 continuous) rules, each on a scripted table (rules_helpers plays the shot with the exact
solver) or, where the stroke cannot be set up by hand reliably (two balls dropping at once), on its summary:
the call, the points, the spotted balls, the three fouls, the break requirement, the re-rack, the target."""
from __future__ import annotations

import pytest
from rules_helpers import (FOOT_SPOT, HEAD_SPOT, TABLE, combo, miss_all, pot, pot_into, rail_miss, scratch_pot,
                           shoot, soft_touch, triangle_rack)

from billiards_env.rules import KITCHEN, RulesError, ShotSummary
from billiards_env.rules.state import NO_CONTACT, NO_RAIL, SCRATCH
from billiards_env.rules.straight_pool import (BREAK_VIOLATION, CALLED_POCKETED, CENTER_SPOT, HEAD_SPOT as HEAD,
                                               NOT_CALLED, RACKED, STAYS, TARGET_REACHED, THIRD_FOUL, CalledShot,
                                               StraightPool, StraightPoolOptions, StraightPoolState, rerack_placement)

RULES = StraightPool()


def mid(on=(3, 7, 12), **kw) -> StraightPoolState:
    """A game after the break, player 0 to shoot from where the cue ball lies."""
    kw.setdefault("ball_in_hand", False)
    kw.setdefault("break_shot", False)
    return StraightPoolState(on, **kw)


def test_initial_state_is_a_break_from_the_kitchen_with_the_full_rack():
    st = RULES.initial_state(first_shooter=1)
    assert st.break_shot and st.ball_in_hand == KITCHEN and st.shooter == 1 and st.on_table == tuple(range(1, 16))
    assert st.score == (0, 0) and st.target == 150
    assert StraightPool(StraightPoolOptions(target=100)).initial_state().target == 100
    assert RULES.legal_targets(mid((4, 9))) == (4, 9)  # any ball may be hit first


def test_the_called_ball_in_the_called_pocket_scores_and_the_shooter_continues():
    s = pot("3", others=("7", "12"))
    assert s.pocketed == (3,) and s.pockets == (2,)
    c, nxt = RULES.play(mid(), s, CalledShot(3, 2))
    assert c.legal and c.reason == CALLED_POCKETED and c.points == 1 and not c.turn_over and c.respot == ()
    assert nxt.shooter == 0 and nxt.score == (1, 0) and nxt.on_table == (7, 12)


def test_a_ball_in_another_pocket_than_called_is_spotted_and_ends_the_inning():
    s = pot_into("3", 5, others=("7", "12"))
    assert s.pocketed == (3,) and s.pockets == (5,)
    c, nxt = RULES.play(mid(), s, CalledShot(3, 0))
    assert c.legal and not c.foul and c.reason == NOT_CALLED and c.points == 0 and c.turn_over
    assert c.respot == (3,) and nxt.on_table == (3, 7, 12) and nxt.shooter == 1 and nxt.ball_in_hand is False


def test_another_ball_than_the_one_called_is_spotted_too():
    s = combo("7", "3", others=("12",), pocket=5)
    assert s.pocketed == (3,) and s.first_contact == 7
    c, nxt = RULES.play(mid(), s, CalledShot(7, 5))  # the 7 was called, the 3 dropped
    assert c.reason == NOT_CALLED and c.respot == (3,) and c.turn_over and nxt.score == (0, 0)
    c, _ = RULES.play(mid(), s, CalledShot(3, 5))  # a combination: the called 3, hit through the 7, counts
    assert c.reason == CALLED_POCKETED and c.points == 1


def test_an_uncalled_shot_scores_nothing():
    c, _ = RULES.play(mid(), pot("3", others=("7", "12")))
    assert c.reason == NOT_CALLED and c.points == 0 and c.respot == (3,)


def test_every_ball_of_a_called_stroke_counts():
    s = ShotSummary(first_contact=3, rail_balls=(), pocketed=(3, 12), pockets=(2, 4))
    c, nxt = RULES.play(mid((3, 7, 9, 12)), s, CalledShot(3, 2))
    assert c.reason == CALLED_POCKETED and c.points == 2 and c.rerack == 0
    assert nxt.score == (2, 0) and nxt.on_table == (7, 9)


def test_a_scratch_costs_a_point_spots_the_ball_and_gives_ball_in_hand_in_the_kitchen():
    s = scratch_pot("3", others=("7", "12"))
    assert s.cue_pocketed and s.pocketed == (3,)
    c, nxt = RULES.play(mid(score=(5, 2)), s, CalledShot(3, 2))
    assert c.foul and c.reason == SCRATCH and c.points == -1 and c.respot == (3,) and c.ball_in_hand == KITCHEN
    assert nxt.score == (4, 2) and nxt.shooter == 1 and nxt.fouls_in_a_row == (1, 0) and 3 in nxt.on_table


def test_no_contact_is_a_foul_and_the_opponent_plays_the_cue_ball_where_it_lies():
    c, nxt = RULES.play(mid(), miss_all(others=("3", "7", "12")), CalledShot(3, 2))
    assert c.foul and c.reason == NO_CONTACT and c.points == -1 and c.ball_in_hand is False
    assert nxt.shooter == 1 and nxt.score == (-1, 0)  # scores may go below zero


def test_no_rail_after_contact_is_a_foul_and_a_cushion_is_not():
    c, _ = RULES.play(mid(), soft_touch("3", others=("7", "12")))
    assert c.foul and c.reason == NO_RAIL
    c, _ = RULES.play(mid(), rail_miss("3", others=("7", "12")))
    assert not c.foul and c.reason == NOT_CALLED and c.points == 0


def test_a_legal_shot_clears_the_shooters_fouls():
    _, nxt = RULES.play(mid(fouls_in_a_row=(2, 1)), rail_miss("3", others=("7", "12")))
    assert nxt.fouls_in_a_row == (0, 1)


def test_the_third_foul_in_a_row_costs_sixteen_and_the_offender_rebreaks_a_full_rack():
    s = miss_all(others=("3", "7", "12"))
    c, nxt = RULES.play(mid(fouls_in_a_row=(2, 0), score=(10, 4)), s)
    assert c.foul and c.reason == THIRD_FOUL and c.points == -16 and c.rerack == 15 and c.break_next
    assert not c.turn_over and c.next_shooter == 0 and c.ball_in_hand == KITCHEN
    assert nxt.score == (-6, 4) and nxt.fouls_in_a_row == (0, 0) and nxt.break_shot
    assert nxt.on_table == tuple(range(1, 16)) and nxt.racks == 1
    # fouls separated by the opponent's turns still count; the opponent's own do not
    c, _ = RULES.play(mid(fouls_in_a_row=(1, 2)), s)
    assert c.reason == NO_CONTACT and c.points == -1
    assert StraightPool(StraightPoolOptions(three_foul_penalty=10)).call(mid(fouls_in_a_row=(2, 0)), s).points == -11


def test_a_break_that_drives_two_balls_and_the_cue_ball_to_a_cushion_is_legal():
    rack = triangle_rack(FOOT_SPOT)
    s = shoot({"cue": HEAD_SPOT, **rack}, 0.0, 8.0, table=TABLE.without_pockets())
    assert s.object_balls_to_rail >= 2 and 0 in s.rail_balls and not s.pocketed
    c, nxt = RULES.play(RULES.initial_state(), s)
    assert not c.foul and c.reason == NOT_CALLED and c.turn_over and nxt.score == (0, 0) and not nxt.break_shot


def test_a_soft_break_is_a_breaking_violation_of_two_points_not_a_foul():
    rack = triangle_rack(FOOT_SPOT)
    cue = (FOOT_SPOT[0] - 0.35, FOOT_SPOT[1])
    s = shoot({"cue": cue, **rack}, 0.0, 0.5)
    assert s.object_balls_to_rail < 2 and not s.cue_pocketed
    c, nxt = RULES.play(RULES.initial_state(), s)
    assert c.reason == BREAK_VIOLATION and not c.foul and c.points == -2 and c.turn_over and c.ball_in_hand is False
    assert nxt.score == (-2, 0) and nxt.fouls_in_a_row == (0, 0) and not nxt.break_shot and nxt.shooter == 1
    assert StraightPool(StraightPoolOptions(break_violation_points=3)).call(RULES.initial_state(), s).points == -3


def test_a_break_that_pockets_its_called_ball_is_legal_without_the_cushions():
    st = RULES.initial_state(on_table=(3, 7, 12))
    s = pot("3", others=("7", "12"))
    assert s.object_balls_to_rail < 2
    c, nxt = RULES.play(st, s, CalledShot(3, 2))
    assert c.reason == CALLED_POCKETED and c.points == 1 and not c.turn_over and not nxt.break_shot
    c, _ = RULES.play(st, s)  # the same stroke without the call: a breaking violation
    assert c.reason == BREAK_VIOLATION


def test_pocketing_the_fourteenth_ball_re_racks_fourteen_and_play_goes_on():
    s = pot("3", others=("7",))
    c, nxt = RULES.play(mid((3, 7), score=(40, 20)), s, CalledShot(3, 2))
    assert c.reason == CALLED_POCKETED and c.rerack == 14 and not c.turn_over
    assert nxt.on_table == tuple(range(1, 16)) and nxt.shooter == 0 and nxt.score == (41, 20) and nxt.racks == 1
    assert not nxt.break_shot  # a re-rack is no opening break


def test_pocketing_the_last_two_balls_re_racks_fifteen():
    s = ShotSummary(first_contact=3, rail_balls=(), pocketed=(3, 7), pockets=(2, 5))
    c, nxt = RULES.play(mid((3, 7)), s, CalledShot(3, 2))
    assert c.rerack == 15 and c.points == 2 and nxt.on_table == tuple(range(1, 16))


def test_reaching_the_target_wins():
    st = mid(score=(149, 120))
    c, nxt = RULES.play(st, pot("3", others=("7", "12")), CalledShot(3, 2))
    assert c.game_over and c.winner == 0 and c.reason == TARGET_REACHED and nxt.score == (150, 120)
    c, _ = RULES.play(mid(score=(148, 0)), pot("3", others=("7", "12")), CalledShot(3, 2))
    assert not c.game_over
    with pytest.raises(RulesError, match="game is over"):
        RULES.call(nxt, pot("7", others=("12",)))


@pytest.mark.parametrize("fifteenth, cue_in_rack, cue_in_kitchen, expected", [
    ("rack", True, False, (HEAD, True)),
    ("rack", False, False, (HEAD, False)),
    ("rack", False, True, (CENTER_SPOT, False)),
    (None, True, False, (RACKED, True)),
    (None, False, True, (RACKED, False)),
    ("head spot", True, False, (CENTER_SPOT, True)),
    ("head spot", False, False, (STAYS, False)),
    ("elsewhere", True, False, (STAYS, True)),
    ("elsewhere", False, True, (STAYS, False)),
])
def test_the_fifteenth_ball_and_the_cue_ball_after_a_re_rack(fifteenth, cue_in_rack, cue_in_kitchen, expected):
    assert rerack_placement(fifteenth, cue_in_rack, cue_in_kitchen) == expected


def test_bad_input_is_refused_with_the_fix():
    with pytest.raises(RulesError, match="target: must be a whole number >= 1"):
        StraightPoolOptions(target=0)
    with pytest.raises(RulesError, match="unknown option 'targt'; did you mean 'target'"):
        StraightPoolOptions(targt=100)
    with pytest.raises(RulesError, match="cue ball"):
        CalledShot(0, 2)
    with pytest.raises(RulesError, match="ball 9 is not on the table"):
        RULES.call(mid(), pot("3", others=("7", "12")), CalledShot(9, 2))
    with pytest.raises(RulesError, match="ball_in_hand"):
        StraightPoolState((1,), ball_in_hand="d")
    with pytest.raises(RulesError, match="fifteenth"):
        rerack_placement("table", False, False)
