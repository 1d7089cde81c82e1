"""8-ball rules, each on a scripted table: the break, the open table and groups, the 8."""
from __future__ import annotations

import pytest
from rules_helpers import (FOOT_SPOT, HEAD_SPOT, PARK, TABLE, L, R, angle_to, behind, combo, pot, pot_into,
                           rail_miss, scratch_pot, shoot, straight_scratch, triangle_rack)

from billiards_env.rules import (ANYWHERE, KITCHEN, EightBall, EightBallOptions, GameState, RulesError, ShotInfo,
                                 eight_ball_targets, group_of)
from billiards_env.rules import state as S

FULL = tuple(range(1, 16))
SOLIDS_STRIPES = ("solids", "stripes")


def game(on=(1, 2, 8, 9, 10), groups=SOLIDS_STRIPES, shooter=0, **kw) -> GameState:
    """An 8-ball game after the break (default: player 0 on solids, player 1 on stripes)."""
    kw.setdefault("ball_in_hand", False)
    return GameState("eight_ball", on, groups=groups, shooter=shooter, break_shot=False, **kw)


def break_state(on=FULL) -> GameState:
    return EightBall().initial_state(0, on)


def others(on, *skip) -> list[int]:
    return [n for n in on if str(n) not in skip]


def test_groups_and_targets():
    assert [group_of(n) for n in (1, 7, 8, 9, 15)] == ["solids", "solids", None, "stripes", "stripes"]
    assert eight_ball_targets(break_state()) == FULL
    assert eight_ball_targets(game(groups=None)) == (1, 2, 9, 10)  # open table: anything but the 8
    assert eight_ball_targets(game()) == (1, 2)
    assert eight_ball_targets(game(shooter=1)) == (9, 10)
    assert eight_ball_targets(game(on=(8, 9, 10))) == (8,)  # solids cleared: on the 8
    rules = EightBall()
    assert rules.needs_called_pocket(game(on=(8, 9, 10))) and not rules.needs_called_pocket(game())
    assert not EightBall(EightBallOptions(call_eight=False)).needs_called_pocket(game(on=(8, 9, 10)))


# --- the break ---------------------------------------------------------------------------------------------------

def test_break_pots_leave_the_table_open_and_the_breaker_continues():
    """A solid dropped on the break: legal, the breaker shoots again, no group yet."""
    s = combo("1", "3", others=others(FULL, "1", "3")[:12])
    assert s.pocketed == (3,)
    on = (1, 3) + tuple(n for n in others(FULL, "1", "3")[:12])
    c, nxt = EightBall().play(break_state(on), s)
    assert c.legal and not c.turn_over and c.groups is None and nxt.groups is None and nxt.shooter == 0
    assert eight_ball_targets(nxt) == tuple(n for n in nxt.on_table if n != 8)


def test_break_driving_four_balls_to_the_rail_is_legal():
    s = shoot({"cue": HEAD_SPOT, **triangle_rack(FOOT_SPOT)}, 0.0, 8.0, table=TABLE.without_pockets())
    assert not s.pocketed and s.object_balls_to_rail >= 4
    c, nxt = EightBall().play(break_state(), s)
    assert c.legal and c.turn_over and nxt.shooter == 1 and nxt.ball_in_hand is False and nxt.groups is None
    assert not nxt.push_out_available


def test_soft_break_is_a_foul():
    """WPA lets the incoming player re-rack; simplified to a foul with ball in hand (anywhere by default)."""
    rack = triangle_rack(FOOT_SPOT)
    s = shoot({"cue": (FOOT_SPOT[0] - 0.35, FOOT_SPOT[1]), **rack}, 0.0, 0.5)
    assert s.first_contact is not None and not s.pocketed and s.object_balls_to_rail < 4
    c, nxt = EightBall().play(break_state(), s)
    assert c.foul and c.reason == S.ILLEGAL_BREAK and nxt.shooter == 1 and nxt.ball_in_hand == ANYWHERE
    opts = EightBallOptions(illegal_break_ball_in_hand="kitchen")
    assert EightBall(opts).call(break_state(), s).ball_in_hand == KITCHEN


def test_break_scratch_gives_ball_in_hand_behind_the_head_string():
    s = straight_scratch(others(FULL)[:14])
    on = tuple(others(FULL)[:14])
    c, nxt = EightBall().play(break_state(on), s)
    assert c.foul and c.reason == S.SCRATCH and c.ball_in_hand == KITCHEN and nxt.ball_in_hand == KITCHEN
    assert nxt.shooter == 1
    opts = EightBallOptions(break_scratch_ball_in_hand="anywhere")
    assert EightBall(opts).call(break_state(on), s).ball_in_hand == ANYWHERE


def test_eight_on_the_break_is_respotted_and_the_breaker_continues():
    s = combo("1", "8", others=(2, 3, 9, 10))
    assert s.pocketed == (8,) and not s.cue_pocketed
    on = (1, 2, 3, 8, 9, 10)
    c, nxt = EightBall().play(break_state(on), s)
    assert c.legal and not c.game_over and c.respot == (8,) and not c.turn_over
    assert 8 in nxt.on_table and nxt.shooter == 0


def test_eight_on_the_break_wins_by_option():
    s = combo("1", "8", others=(2, 3, 9, 10))
    c = EightBall(EightBallOptions(eight_on_break="win")).call(break_state((1, 2, 3, 8, 9, 10)), s)
    assert c.game_over and c.winner == 0 and c.reason == S.EIGHT_ON_BREAK


def test_eight_and_a_scratch_on_the_break():
    """The 8 drops and the cue ball follows: a foul, the 8 respotted, the opponent in hand behind the head
    string (under either option)."""
    s = scratch_pot("8", others=(1, 2, 9, 10))
    assert s.pocketed == (8,) and s.cue_pocketed
    for opts in (EightBallOptions(), EightBallOptions(eight_on_break="win")):
        c, nxt = EightBall(opts).play(break_state((1, 2, 8, 9, 10)), s)
        assert c.foul and not c.game_over and c.respot == (8,) and c.ball_in_hand == KITCHEN
        assert 8 in nxt.on_table and nxt.shooter == 1


# --- open table and groups ----------------------------------------------------------------------------------------

@pytest.mark.parametrize("ball, shooter, expect", [("2", 0, SOLIDS_STRIPES), ("10", 0, ("stripes", "solids")),
                                                   ("2", 1, ("stripes", "solids"))])
def test_first_legal_pot_on_an_open_table_decides_the_groups(ball, shooter, expect):
    on = (1, 2, 8, 9, 10)
    s = pot(ball, others(on, ball))
    c, nxt = EightBall().play(game(on, groups=None, shooter=shooter), s)
    assert c.legal and not c.turn_over and c.groups == expect and nxt.groups == expect
    assert eight_ball_targets(nxt) == tuple(n for n in nxt.on_table if group_of(n) == group_of(int(ball)))


def test_open_table_any_group_may_be_hit_first():
    """On an open table a stripe may be used to pocket a solid: the solid decides."""
    on = (1, 2, 8, 9, 10)
    s = combo("9", "2", others=(1, 8, 10))
    assert s.first_contact == 9 and s.pocketed == (2,)
    c = EightBall().call(game(on, groups=None), s)
    assert c.legal and c.groups == SOLIDS_STRIPES and not c.turn_over


def test_open_table_miss_keeps_it_open():
    c = EightBall().call(game(groups=None), rail_miss("9", (1, 2, 8, 10)))
    assert c.legal and c.turn_over and c.groups is None


def test_open_table_eight_first_is_a_foul():
    on = (1, 2, 8, 9, 10)
    s = rail_miss("8", others(on, "8"))
    assert s.first_contact == 8
    c = EightBall().call(game(on, groups=None), s)
    assert c.foul and c.reason == S.WRONG_BALL_FIRST and c.groups is None and c.ball_in_hand == ANYWHERE


def test_open_table_foul_pot_assigns_no_group():
    on = (1, 2, 8, 9, 10)
    s = scratch_pot("2", others(on, "2"))
    c, nxt = EightBall().play(game(on, groups=None), s)
    assert c.foul and nxt.groups is None and 2 not in nxt.on_table


# --- groups -------------------------------------------------------------------------------------------------------

def test_opponent_ball_first_is_a_foul():
    s = pot("9", (1, 2, 8, 10))
    c, nxt = EightBall().play(game(), s)
    assert c.foul and c.reason == S.WRONG_BALL_FIRST and 9 not in nxt.on_table and nxt.shooter == 1


def test_pocketing_only_an_opponent_ball_ends_the_turn_without_a_foul():
    """Player 0 (solids) plays the 1 into the 9, which drops: legal, but his turn is over and the 9 stays down."""
    s = combo("1", "9", others=(2, 8, 10))
    assert s.first_contact == 1 and s.pocketed == (9,)
    c, nxt = EightBall().play(game(), s)
    assert c.legal and c.turn_over and nxt.shooter == 1 and 9 not in nxt.on_table and c.groups == SOLIDS_STRIPES


def test_own_ball_pocketed_keeps_the_turn_for_stripes_too():
    s = pot("10", (1, 2, 8, 9))
    c = EightBall().call(game(shooter=1), s)
    assert c.legal and not c.turn_over and c.next_shooter == 1


# --- the 8 --------------------------------------------------------------------------------------------------------

ON_EIGHT = (8, 9, 10)  # player 0's solids are cleared


@pytest.mark.parametrize("pocket", range(6))
def test_eight_in_the_called_pocket_wins(pocket):
    s = pot_into("8", pocket, others=(9, 10))
    assert s.pocketed == (8,) and s.pockets == (pocket,) and not s.cue_pocketed
    c, nxt = EightBall().play(game(ON_EIGHT), s, ShotInfo(called_pocket=pocket))
    assert c.game_over and c.winner == 0 and c.legal and c.reason == S.EIGHT_POCKETED
    assert nxt.game_over and nxt.winner == 0


def test_eight_in_another_pocket_than_called_loses():
    s = pot_into("8", 5, others=(9, 10))
    c = EightBall().call(game(ON_EIGHT), s, ShotInfo(called_pocket=2))
    assert c.game_over and c.winner == 1 and c.reason == S.EIGHT_WRONG_POCKET


def test_eight_without_a_call_loses_when_calls_are_on_and_wins_when_off():
    s = pot_into("8", 5, others=(9, 10))
    c = EightBall().call(game(ON_EIGHT), s)
    assert c.game_over and c.winner == 1 and c.reason == S.EIGHT_NOT_CALLED
    c = EightBall(EightBallOptions(call_eight=False)).call(game(ON_EIGHT), s, ShotInfo(called_pocket=0))
    assert c.game_over and c.winner == 0 and c.reason == S.EIGHT_POCKETED


def test_eight_before_the_group_is_cleared_loses():
    """Player 0 still has the 2: he plays the 1 into the 8, which drops."""
    s = combo("1", "8", others=(2, 9, 10), pocket=2)
    assert s.first_contact == 1 and s.pocketed == (8,)
    c = EightBall().call(game((1, 2, 8, 9, 10)), s, ShotInfo(called_pocket=2))
    assert c.game_over and c.winner == 1 and c.reason == S.EIGHT_EARLY and not c.foul


def test_eight_with_the_last_group_ball_loses():
    """The 1 (player 0's last solid) drives the 8 into pocket 2 and follows it in: the 8 dropped on the stroke
    that cleared the group, before the group was cleared."""
    eight = (L - 0.07, 0.07)
    one = behind(eight, 2, 2 * R + 0.06)
    cue = behind(eight, 2, 2 * R + 0.06 + 0.3)
    s = shoot({"cue": cue, "1": one, "8": eight, "9": PARK[0], "10": PARK[1]}, angle_to(cue, one), 8.0)
    assert s.pocketed == (8, 1) and not s.cue_pocketed
    c = EightBall().call(game((1, 8, 9, 10)), s, ShotInfo(called_pocket=2))
    assert c.game_over and c.winner == 1 and c.reason == S.EIGHT_EARLY


def test_eight_on_an_open_table_loses():
    s = combo("1", "8", others=(2, 9, 10), pocket=2)
    c = EightBall().call(game((1, 2, 8, 9, 10), groups=None), s)
    assert c.game_over and c.winner == 1 and c.reason == S.EIGHT_EARLY


def test_eight_with_a_scratch_loses():
    s = scratch_pot("8", others=(9, 10))
    assert s.pocketed == (8,) and s.cue_pocketed
    c = EightBall().call(game(ON_EIGHT, shooter=0), s, ShotInfo(called_pocket=2))
    assert c.game_over and c.winner == 1 and c.reason == S.EIGHT_ON_FOUL and c.fouls == (S.SCRATCH,)


def test_scratch_on_the_eight_without_pocketing_it_is_a_plain_foul():
    s = scratch_pot("9", others=(8, 10))
    c = EightBall().call(game(ON_EIGHT, shooter=0), s, ShotInfo(called_pocket=2))
    assert c.foul and not c.game_over and c.ball_in_hand == ANYWHERE


def test_three_foul_rule_is_off_by_default_in_eight_ball():
    st = game(fouls_in_a_row=(2, 0))
    s = pot("9", (1, 2, 8, 10))
    assert not EightBall().call(st, s).game_over
    c = EightBall(EightBallOptions(three_foul_rule=True)).call(st, s)
    assert c.game_over and c.winner == 1 and c.reason == S.THREE_FOULS


def test_eight_ball_needs_the_eight():
    with pytest.raises(RulesError, match="8"):
        EightBall().initial_state(0, (1, 2, 3))
