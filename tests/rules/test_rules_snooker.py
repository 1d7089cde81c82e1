"""Snooker rules, each on a scripted snooker table (:mod:`snooker_helpers`) or, where a shot cannot be scripted
reliably, on a hand-made summary."""
from __future__ import annotations

import math

import numpy as np
import pytest
from snooker_helpers import (R, SIM, SPOTS, TABLE, angle_to, hit_and_stay, in_off, layout, miss_all, pot,
                             pot_two)

from billiards_env.physics.batch import run_shots
from billiards_env.games.snooker_layout import SNOOKER_COLOURS, snooker_balls
from billiards_env.rules import RulesError
from billiards_env.rules import snooker as S
from billiards_env.rules.snooker import (Snooker, SnookerOptions, SnookerShotInfo, SnookerState, SnookerSummary,
                                         ball_on_mask, judge, judge_batch, snooker_values, snookered,
                                         summarize_snooker)

RULES = Snooker()
ALL = SNOOKER_COLOURS


def st(**kw) -> SnookerState:
    """A frame under way, player 0 at the table, the cue ball where it lies."""
    kw.setdefault("ball_in_hand", False)
    return SnookerState(**kw)


def clearance(on: str, **kw) -> SnookerState:
    """The reds gone, ``on`` and the colours above it on the table."""
    return st(reds=0, on=on, colours=ALL[ALL.index(on):], **kw)


# --- the start and the reds --------------------------------------------------------------------------------------

def test_initial_state_is_a_break_off_from_the_d_on_a_red():
    s = RULES.initial_state(1)
    assert s.shooter == 1 and s.on == "red" and s.reds == 15 and s.colours == ALL and s.ball_in_hand == "d"
    assert s.score == (0, 0) and s.points_left == 147 and RULES.legal_targets(s) == ("red",)
    assert RULES.initial_state(0, reds=6).reds == 6


@pytest.mark.parametrize("pocket", [2, 1])
def test_potted_red_scores_one_and_the_striker_is_on_a_colour(pocket):
    s = pot("red1", pocket=pocket)
    assert s.first == "red" and s.reds_potted == 1 and not s.cue_pocketed
    c, nxt = RULES.play(st(score=(10, 3), break_points=4), s)
    assert c.points == 1 and not c.foul and c.foul_points == 0 and c.score == (11, 3) and c.reason == S.POT
    assert not c.turn_over and c.on == "colour" and c.break_points == 5 and c.respot == ()
    assert nxt.reds == 14 and nxt.on == "colour" and nxt.break_points == 5 and nxt.shooter == 0
    assert RULES.legal_targets(nxt) == ALL


def test_every_red_potted_counts():
    s = SnookerSummary("red", reds_potted=2)  # (two reds in one shot: not scripted)
    c, nxt = RULES.play(st(), s)
    assert c.points == 2 and nxt.reds == 13 and nxt.on == "colour"


def test_red_hit_but_not_potted_passes_the_turn_and_ends_the_break():
    s = hit_and_stay("red1")
    assert s.first == "red" and not s.reds_potted
    c, nxt = RULES.play(st(break_points=9, best_break=(4, 20)), s)
    assert not c.foul and c.points == 0 and c.turn_over and c.reason == S.NO_POT and c.break_points == 9
    assert nxt.shooter == 1 and nxt.on == "red" and nxt.break_points == 0 and nxt.best_break == (9, 20)
    assert not nxt.after_foul


# --- colours while reds remain ----------------------------------------------------------------------------------

def test_colour_after_a_red_scores_its_value_and_is_respotted():
    s = pot("black")
    assert s.first == "black" and s.colours_potted == ("black",)
    c, nxt = RULES.play(st(on="colour", reds=14, break_points=1), s)
    assert c.points == 7 and c.nominated == "black" and c.respot == ("black",) and c.on == "red"
    assert not c.turn_over and c.break_points == 8
    assert nxt.colours == ALL and nxt.on == "red" and nxt.reds == 14


def test_the_first_colour_hit_counts_as_nominated_and_a_declared_one_must_be_hit():
    s = pot("pink", pocket=5)
    assert RULES.call(st(on="colour"), s).points == 6
    assert RULES.call(st(on="colour"), s, SnookerShotInfo(nominated="pink")).points == 6
    c = RULES.call(st(on="colour"), s, SnookerShotInfo(nominated="blue"))
    assert c.foul and c.fouls == (S.BALL_NOT_ON_FIRST, S.BALL_NOT_ON_POTTED) and c.foul_points == 6
    assert c.points == 0 and c.respot == ("pink",) and c.turn_over and c.on == "red"


def test_red_first_when_on_a_colour_is_a_seven_point_foul():
    s = pot("red1")
    c, nxt = RULES.play(st(on="colour", reds=15), s)
    assert c.foul and c.foul_points == 7 and c.points == 0 and c.score == (0, 7) and c.turn_over
    assert nxt.reds == 14 and nxt.on == "red" and nxt.shooter == 1  # the red stays down


def test_colour_first_when_on_a_red_is_a_foul_worth_the_colour():
    s = hit_and_stay("blue")
    c, nxt = RULES.play(st(), s)
    assert c.foul and c.fouls == (S.BALL_NOT_ON_FIRST,) and c.foul_points == 5 and c.score == (0, 5)
    assert nxt.shooter == 1 and nxt.after_foul and nxt.ball_in_hand is False
    assert RULES.call(st(), hit_and_stay("green")).foul_points == 4  # at least 4


def test_potting_a_colour_with_the_red_is_a_foul():
    s = pot_two("red1", "pink")  # the red hits the pink into the pocket
    assert s.first == "red" and s.colours_potted == ("pink",) and not s.reds_potted
    c, nxt = RULES.play(st(), s)
    assert c.foul and c.fouls == (S.BALL_NOT_ON_POTTED,) and c.foul_points == 6 and c.respot == ("pink",)
    assert nxt.colours == ALL


def test_potting_a_red_with_the_colour_is_a_foul():
    s = pot_two("blue", "red1")
    assert s.first == "blue" and s.reds_potted == 1
    c, nxt = RULES.play(st(on="colour", reds=15), s)
    assert c.foul and c.fouls == (S.BALL_NOT_ON_POTTED,) and c.foul_points == 5 and nxt.reds == 14


def test_in_off_is_a_foul_and_the_opponent_plays_from_the_d():
    s = in_off("red1")
    assert s.cue_pocketed and s.reds_potted == 1
    c, nxt = RULES.play(st(score=(20, 0), break_points=20), s)
    assert c.foul and c.fouls == (S.IN_OFF,) and c.foul_points == 4 and c.points == 0 and c.score == (20, 4)
    assert c.ball_in_hand == "d" and c.turn_over and c.break_points == 20
    assert nxt.ball_in_hand == "d" and nxt.reds == 14 and nxt.shooter == 1 and nxt.best_break == (20, 0)
    assert RULES.call(st(on="colour"), in_off("black")).foul_points == 7  # in-off off the black


def test_no_ball_hit_is_a_foul_worth_the_ball_on():
    s = miss_all()
    assert s.first is None
    assert RULES.call(st(), s).foul_points == 4 and RULES.call(st(), s).fouls == (S.NO_BALL_HIT,)
    assert RULES.call(st(on="colour"), s).foul_points == 7  # a foul before nominating a colour
    assert RULES.call(st(on="colour"), s, SnookerShotInfo(nominated="pink")).foul_points == 6
    assert RULES.call(clearance("blue"), s).foul_points == 5


# --- the colours in order ----------------------------------------------------------------------------------------

def test_last_red_then_any_colour_then_the_colours_in_order():
    s = pot("red1")
    c, nxt = RULES.play(st(reds=1), s)
    assert c.on == "colour" and nxt.reds == 0 and nxt.on == "colour" and nxt.colours == ALL
    c2, nxt2 = RULES.play(nxt, pot("pink", pocket=5, reds=0))
    assert c2.points == 6 and c2.respot == ("pink",) and c2.on == "yellow" and nxt2.colours == ALL
    c3 = RULES.call(nxt, miss_all(reds=0))  # failing on the colour after the last red: the opponent is on yellow
    assert c3.foul and c3.on == "yellow" and c3.foul_points == 7
    c4 = RULES.call(nxt, hit_and_stay("pink", reds=0))
    assert not c4.foul and c4.on == "yellow" and c4.turn_over


def test_colour_on_in_order_stays_down():
    s = pot("yellow", reds=0)
    c, nxt = RULES.play(clearance("yellow", break_points=30), s)
    assert c.points == 2 and c.respot == () and c.on == "green" and not c.turn_over and c.break_points == 32
    assert nxt.colours == ALL[1:] and nxt.on == "green"


def test_colour_out_of_order_is_a_foul_and_respotted():
    s = pot_two("yellow", "green", reds=0)
    assert s.first == "yellow" and s.colours_potted == ("green",)
    c, nxt = RULES.play(clearance("yellow"), s)
    assert c.foul and c.foul_points == 4 and c.respot == ("green",) and nxt.colours == ALL and nxt.on == "yellow"
    c = RULES.call(clearance("yellow"), hit_and_stay("pink", reds=0))
    assert c.foul and c.foul_points == 6


def test_ball_on_potted_on_a_foul_is_respotted():
    s = in_off("yellow", reds=0)
    c, nxt = RULES.play(clearance("yellow"), s)
    assert c.foul and c.respot == ("yellow",) and nxt.colours == ALL and nxt.on == "yellow"


# --- the end of the frame -------------------------------------------------------------------------------------------

def test_last_black_ends_the_frame_to_the_higher_score():
    s = pot("black", reds=0, colours=("black",))
    c, nxt = RULES.play(clearance("black", score=(40, 45)), s)
    assert c.frame_over and c.winner == 0 and c.score == (47, 45) and c.reason == S.FRAME_OVER
    assert nxt.frame_over and nxt.winner == 0
    with pytest.raises(RulesError, match="frame is over"):
        RULES.call(nxt, s)


def test_foul_on_the_last_black_ends_the_frame():
    c = RULES.call(clearance("black", score=(50, 45)), miss_all(reds=0, colours=("black",)))
    assert c.foul and c.foul_points == 7 and c.frame_over and c.winner == 1 and c.score == (50, 52)


def test_a_tie_goes_to_the_respotted_black():
    c, nxt = RULES.play(clearance("black", score=(40, 47)), pot("black", reds=0, colours=("black",)))
    assert not c.frame_over and c.respotted_black and c.respot == ("black",) and c.reason == S.RESPOTTED_BLACK
    assert c.next_shooter == 1 and c.ball_in_hand == "d" and c.score == (47, 47)
    assert nxt.respotted_black and nxt.on == "black" and nxt.ball_in_hand == "d" and nxt.shooter == 1
    c2, nxt2 = RULES.play(nxt, hit_and_stay("black", reds=0, colours=("black",)))
    assert not c2.frame_over and nxt2.shooter == 0  # no score, no foul: play on
    c3 = RULES.call(nxt2, miss_all(reds=0, colours=("black",)))
    assert c3.frame_over and c3.winner == 1 and c3.score == (47, 54)  # the first foul ends it
    c4 = RULES.call(nxt2, pot("black", reds=0, colours=("black",)))
    assert c4.frame_over and c4.winner == 0  # the first score ends it


def test_a_tie_after_a_foul_on_the_last_black():
    c = RULES.call(clearance("black", score=(47, 40)), miss_all(reds=0, colours=("black",)))
    assert c.respotted_black and c.score == (47, 47) and c.respot == ("black",) and c.next_shooter == 1


# --- free ball ------------------------------------------------------------------------------------------------------

def test_free_ball_is_offered_only_after_a_foul_to_a_snookered_striker():
    after = st(after_foul=True)
    assert RULES.free_ball_available(after, snookered=True)
    assert not RULES.free_ball_available(after, snookered=False)
    assert not RULES.free_ball_available(st(), snookered=True)
    assert not RULES.free_ball_available(st(after_foul=True, ball_in_hand="d"), snookered=True)
    assert not Snooker(SnookerOptions(free_ball=False)).free_ball_available(after, snookered=True)
    assert not RULES.free_ball_available(clearance("black", after_foul=True), snookered=True)  # nothing to name


def test_free_ball_when_on_a_red_counts_as_a_red_and_is_respotted():
    s = pot("blue")
    c, nxt = RULES.play(st(after_foul=True), s, SnookerShotInfo(free_ball="blue", snookered=True))
    assert not c.foul and c.points == 1 and c.free_ball == "blue" and c.respot == ("blue",) and c.on == "colour"
    assert nxt.colours == ALL and nxt.reds == 15
    auto = RULES.call(st(after_foul=True), s, SnookerShotInfo(snookered=True))  # the first ball hit is named
    assert auto.points == 1 and auto.free_ball == "blue"
    no_auto = Snooker(SnookerOptions(auto_free_ball=False)).call(st(after_foul=True), s,
                                                                 SnookerShotInfo(snookered=True))
    assert no_auto.foul and no_auto.foul_points == 5
    assert RULES.call(st(after_foul=True), s, SnookerShotInfo(snookered=False)).foul  # no free ball: a foul


def test_free_ball_and_red_both_potted_count_each():
    s = SnookerSummary("blue", reds_potted=1, colours_potted=("blue",))
    c = RULES.call(st(after_foul=True), s, SnookerShotInfo(free_ball="blue", snookered=True))
    assert not c.foul and c.points == 2 and c.respot == ("blue",)


def test_free_ball_in_the_clearance_scores_the_ball_on():
    s = pot("pink", pocket=5, reds=0)
    c, nxt = RULES.play(clearance("yellow", after_foul=True), s, SnookerShotInfo(free_ball="pink", snookered=True))
    assert c.points == 2 and c.respot == ("pink",) and c.on == "yellow" and not c.turn_over
    both = SnookerSummary("pink", colours_potted=("pink", "yellow"))
    c = RULES.call(clearance("yellow", after_foul=True), both, SnookerShotInfo(free_ball="pink", snookered=True))
    assert c.points == 2 and c.respot == ("pink",) and c.on == "green"  # the ball on stays down


def test_free_ball_must_be_hit_first():
    c = RULES.call(st(after_foul=True), hit_and_stay("red1"), SnookerShotInfo(free_ball="pink", snookered=True))
    assert c.foul and c.fouls == (S.BALL_NOT_ON_FIRST,) and c.foul_points == 4


# --- the miss rule -------------------------------------------------------------------------------------------------

def test_miss_puts_the_balls_back_and_the_offender_plays_again():
    rules = Snooker(SnookerOptions(miss_rule=True))
    s = hit_and_stay("blue")
    c, nxt = rules.play(st(score=(5, 5), break_points=3), s)
    assert c.foul and c.miss and c.replace and c.reason == S.MISS and c.next_shooter == 0 and not c.turn_over
    assert c.score == (5, 10) and nxt.shooter == 0 and nxt.on == "red" and nxt.misses == (1, 0)
    assert nxt.break_points == 0
    snookered_call = rules.call(st(), s, SnookerShotInfo(snookered=True))
    assert snookered_call.foul and not snookered_call.miss and snookered_call.turn_over  # a foul, not a miss
    assert not rules.call(st(), in_off("red1")).miss  # hit the ball on first: no miss
    c3 = rules.call(st(misses=(2, 0)), s)
    assert c3.frame_over and c3.winner == 1 and c3.reason == S.THREE_MISSES
    assert not RULES.call(st(), s).miss  # the option is off by default


def test_a_legal_shot_resets_the_misses():
    rules = Snooker(SnookerOptions(miss_rule=True))
    assert rules.play(st(misses=(2, 1)), hit_and_stay("red1"))[1].misses == (0, 1)


# --- the referee's look: snookered ----------------------------------------------------------------------------------

def test_snookered_behind_a_colour():
    b = layout({"cue": (2.0, 0.4), "blue": (2.0, 0.6), "red1": (2.0, 0.9)}, reds=1)
    vals = snooker_values(b.ids)
    assert snookered(b.pos, b.on_table, b.radius, vals, "red")
    assert not snookered(b.pos, b.on_table, b.radius, vals, "colour")  # the blue itself is on
    b.pos[b.index("blue")] = (2.0 + 1.5 * R, 0.6)  # one edge of the red comes free, the other does not
    assert snookered(b.pos, b.on_table, b.radius, vals, "red")
    b.pos[b.index("blue")] = (2.0 + 5 * R, 0.6)
    assert not snookered(b.pos, b.on_table, b.radius, vals, "red")


def test_other_balls_on_do_not_snooker():
    b = layout({"cue": (2.0, 0.4), "red2": (2.0, 0.6), "red1": (2.0, 0.9)}, reds=2)
    assert not snookered(b.pos, b.on_table, b.radius, snooker_values(b.ids), "red")
    assert ball_on_mask(snooker_values(b.ids), "red").sum() == 2
    assert ball_on_mask(snooker_values(b.ids), "colour").sum() == 6


def test_a_scripted_foul_leaves_the_opponent_snookered_and_a_free_ball():
    """The striker, on a red, plays the pink by mistake; the cue ball stops behind the blue, the only red hidden."""
    balls = {"cue": (2.0, 0.25), "pink": (2.0, 0.1), "blue": (2.0, 0.7), "red1": (2.0, 1.3)}
    b = layout(balls, reds=1).strike("cue", -math.pi / 2, 0.3)
    res = SIM.run(b)
    ev = np.stack([res.events.kind, res.events.ball, res.events.other], axis=1)
    vals = snooker_values(b.ids)
    c, nxt = RULES.play(st(reds=1), summarize_snooker(ev, res.pocket, vals))
    assert c.foul and c.foul_points == 6 and nxt.after_foul and nxt.shooter == 1
    snk = snookered(res.balls.pos, res.balls.on_table, res.balls.radius, vals, nxt.on)
    assert snk and RULES.free_ball_available(nxt, snk)


# --- batch judging ---------------------------------------------------------------------------------------------------

def test_batch_judge_equals_the_call_on_every_candidate():
    """Candidate shots from the opening layout, judged in one compiled call, agree with the full call."""
    balls = snooker_balls(TABLE)
    vals = snooker_values(balls.ids)
    rng = np.random.default_rng(3)
    n = 40
    res = run_shots(SIM, balls, rng.uniform(-math.pi, math.pi, n), rng.uniform(0.5, 7.0, n), events=True)
    state = RULES.initial_state(0)
    out = judge_batch(res.first_contact, res.pocket, vals, 0, state.on_value, 0, 0, state.reds, state.colour_mask)
    fouls, penalty, points, nom, respot, next_on = out[:6]
    seen = set()
    for k in range(n):
        log = res.events.row(k)
        s = summarize_snooker(np.stack([log.kind, log.ball, log.other], axis=1), res.pocket[k], vals)
        c = RULES.call(state, s)
        assert (c.foul, c.foul_points, c.points) == (bool(fouls[k]), penalty[k], points[k])
        assert c.on == S._ON_NAME[next_on[k]]
        seen.add((c.foul, c.points > 0))
    assert (True, False) in seen and (False, False) in seen


def test_judge_penalty_is_the_highest_concerned():
    # on a red, the black hit first and the pink potted: 7
    assert judge(1, 0, 0, 15, 0b11111100, 7, 0, 1 << 6, False)[1] == 7
    # on yellow, the cue ball in-off after hitting the yellow: 4
    assert judge(2, 0, 0, 0, 0b11111100, 2, 0, 0, True)[1] == 4
    # legal black after a red: 7 points, no penalty
    assert judge(0, 0, 0, 14, 0b11111100, 7, 0, 1 << 7, False)[1:3] == (0, 7)


# --- bad input -------------------------------------------------------------------------------------------------------

def test_bad_input_is_refused_clearly():
    with pytest.raises(RulesError, match="nothing to nominate"):
        RULES.call(st(), pot("red1"), SnookerShotInfo(nominated="pink"))
    with pytest.raises(RulesError, match="no free ball now"):
        RULES.call(st(), pot("red1"), SnookerShotInfo(free_ball="pink", snookered=True))
    with pytest.raises(RulesError, match="not the ball on"):
        RULES.call(clearance("yellow", after_foul=True), pot("yellow", reds=0),
                   SnookerShotInfo(free_ball="yellow", snookered=True))
    with pytest.raises(RulesError, match="only 0 reds"):
        RULES.call(clearance("yellow"), SnookerSummary("yellow", reds_potted=1))
    with pytest.raises(RulesError, match="not on the table"):
        RULES.call(clearance("pink"), SnookerSummary("yellow"))
    with pytest.raises(RulesError, match="not a colour"):
        SnookerShotInfo(nominated="purple")
    with pytest.raises(RulesError, match="on: 'red' but no red"):
        SnookerState(reds=0, on="red")
    with pytest.raises(RulesError, match="lowest colour"):
        SnookerState(reds=0, on="pink", colours=("blue", "pink", "black"))
    with pytest.raises(RulesError, match="while reds remain"):
        SnookerState(on="pink")
    with pytest.raises(RulesError, match="every colour"):
        SnookerState(colours=("black",))
    with pytest.raises(RulesError, match="ball_in_hand"):
        SnookerState(ball_in_hand="kitchen")
    with pytest.raises(RulesError, match="snooker needs the ids"):
        snooker_values(["cue", "1"])
    with pytest.raises(RulesError, match="exactly one ball with id 'cue'"):
        snooker_values(["red1", "black"])
    with pytest.raises(RulesError, match="miss_limit"):
        SnookerOptions(miss_limit=0)
    with pytest.raises(RulesError, match="state.shooter"):
        RULES.next_state(st(shooter=1), RULES.call(st(), pot("red1")))
    assert SPOTS["black"][0] > SPOTS["pink"][0] and angle_to((0, 0), (1, 0)) == 0.0


def test_summary_lists_colours_in_the_order_they_dropped():
    """A hand-made log: the pink drops before the blue although its row comes later."""
    ids = ("cue", "red1", "blue", "pink")
    vals = snooker_values(ids)
    ev = np.array([[0, 0, 3], [2, 3, 2], [2, 2, 5], [3, 0, -1]])  # cue hits pink; pink drops; blue drops; cue stops
    s = summarize_snooker(ev, np.array([-1, -1, 5, 2]), vals)
    assert s.first == "pink" and s.colours_potted == ("pink", "blue") and s.reds_potted == 0 and not s.cue_pocketed
