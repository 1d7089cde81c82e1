"""Three-cushion rules, each on a scripted table (shots built on the engine, :mod:`carom_helpers`) or, where a
shot cannot be scripted reliably, on a hand-made event log."""
from __future__ import annotations

import math

import numpy as np
import pytest
from carom_helpers import SIM, carom, place_on_path, run

from billiards_env.physics import Physics, Simulator
from billiards_env.physics.batch import run_shots
from billiards_env.physics.codes import EV_COLLISION, EV_CUSHION, EV_JAM, EV_ROLL, EV_STOP
from billiards_env.games.carom_layout import CAROM_IDS, carom_balls
from billiards_env.physics.table import carom_table
from billiards_env.rules import RulesError
from billiards_env.rules import three_cushion as T
from billiards_env.rules.three_cushion import (CaromSummary, ThreeCushion, ThreeCushionOptions, ThreeCushionState,
                                               carom_rows, scan_carom_batch, summarize_carom)

WHITE, YELLOW, RED = 0, 1, 2  # rows of CAROM_IDS
ANGLE, SPEED = 0.5, 3.0  # the cue ball's test path: around the table, a cushion every second or so
START = {"white": (0.5, 0.4)}


def events_of(res) -> np.ndarray:
    return np.stack([res.events.kind, res.events.ball, res.events.other], axis=1)


def summary_of(pos, cue="white", angle=ANGLE, speed=SPEED) -> CaromSummary:
    res = run(pos, cue, angle, speed)
    return summarize_carom(events_of(res), carom_rows(CAROM_IDS, CAROM_IDS.index(cue)))


def mid(**kw) -> ThreeCushionState:
    """A game after the opening shot, player 0 at the table."""
    kw.setdefault("break_shot", False)
    return ThreeCushionState(**kw)


def log(*rows) -> np.ndarray:
    return np.array(rows, dtype=np.int64).reshape(-1, 3)


def cushion(ball=WHITE, side=0):
    return (EV_CUSHION, ball, side)


def hit(a, b):
    return (EV_COLLISION, a, b)


# --- the point, on the engine ------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def three_then_both():
    """White: three cushions, then the red (a cut), then the yellow."""
    pos = place_on_path(START, "white", ANGLE, SPEED, "cushion", 3, "red")
    return place_on_path(pos, "white", ANGLE, SPEED, "collision", 1, "yellow", cut=-0.3)


def test_three_cushions_then_both_balls_is_a_point_and_the_inning_goes_on(three_then_both):
    s = summary_of(three_then_both)
    assert (s.first, s.second, s.cushions, s.cushions_before_first) == ("red", "opponent", 3, 3) and s.point
    c, nxt = ThreeCushion().play(mid(score=(4, 2)), s)
    assert c.point and c.cushions == 3 and c.score == (5, 2) and not c.turn_over and c.reason == T.POINT
    assert c.run == 1 and c.next_shooter == 0 and not c.foul
    assert nxt.shooter == 0 and nxt.run == 1 and nxt.score == (5, 2) and nxt.innings == (1, 0)


def test_two_cushions_before_the_second_ball_is_no_point_and_the_turn_passes():
    pos = place_on_path(START, "white", ANGLE, SPEED, "cushion", 2, "red")
    pos = place_on_path(pos, "white", ANGLE, SPEED, "collision", 1, "yellow", cut=-0.3)
    s = summary_of(pos)
    assert (s.first, s.second, s.cushions) == ("red", "opponent", 2) and not s.point
    c, nxt = ThreeCushion().play(mid(score=(4, 2), run=3), s)
    assert not c.point and c.cushions == 2 and c.turn_over and c.reason == T.NO_POINT and not c.foul
    assert c.score == (4, 2) and c.next_shooter == 1 and c.innings == (1, 1)
    assert nxt.shooter == 1 and nxt.run == 0 and nxt.cue_ball == "yellow"


@pytest.mark.parametrize("before_first", [0, 1])
def test_cushions_before_the_first_ball_count_towards_the_three(before_first):
    """The cue ball meets the yellow after ``before_first`` cushions, then the red after its third cushion in all."""
    pos = place_on_path(START, "white", ANGLE, SPEED, "cushion", before_first, "yellow", cut=0.9)
    pos = place_on_path(pos, "white", ANGLE, SPEED, "cushion", 3, "red", cut=0.2, frac=0.3)
    s = summary_of(pos)
    assert (s.first, s.second, s.cushions, s.cushions_before_first) == ("opponent", "red", 3, before_first)
    assert ThreeCushion().call(mid(), s).point


def test_hitting_the_opponents_ball_first_is_not_a_foul(three_then_both):
    """The same shot with the two object balls swapped: the opponent's ball first, then the red."""
    swapped = {**three_then_both, "red": three_then_both["yellow"], "yellow": three_then_both["red"]}
    s = summary_of(swapped)
    assert (s.first, s.second) == ("opponent", "red") and s.point
    c = ThreeCushion().call(mid(), s)
    assert c.point and not c.foul


def test_one_ball_only_is_no_point():
    pos = place_on_path(START, "white", ANGLE, SPEED, "cushion", 3, "red")
    s = summary_of(pos)
    assert s.first == "red" and s.second is None and s.cushions == s.cushions_total >= 3
    c = ThreeCushion().call(mid(), s)
    assert not c.point and c.turn_over and c.cushions == s.cushions_total


def test_missing_both_balls_is_no_point_and_a_foul_only_by_option():
    s = summary_of({"white": (0.5, 0.4)})
    assert s.first is None and s.cushions_before_first == -1 and s.cushions == s.cushions_total > 3
    c = ThreeCushion().call(mid(), s)
    assert not c.point and not c.foul and c.turn_over
    c = ThreeCushion(ThreeCushionOptions(miss_is_foul=True)).call(mid(), s)
    assert c.foul and c.fouls == (T.NO_CONTACT,) and c.reason == T.NO_CONTACT and c.turn_over


def test_player_one_shoots_the_yellow(three_then_both):
    """The same layout with the cue balls' roles swapped: player 1 plays the yellow."""
    pos = {"yellow": three_then_both["white"], "white": three_then_both["yellow"], "red": three_then_both["red"]}
    s = summary_of(pos, cue="yellow")
    assert (s.first, s.second, s.cushions) == ("red", "opponent", 3)
    c = ThreeCushion().call(mid(shooter=1, innings=(1, 1), score=(3, 3)), s)
    assert c.point and c.score == (3, 4) and c.next_shooter == 1


# --- the opening shot -------------------------------------------------------------------------------------------

def test_opening_shot_must_meet_the_red_first_directly():
    table = carom_table()
    balls = carom_balls(table)
    rows = carom_rows(balls.ids, 0)
    sim = Simulator(table, Physics())
    red, yellow, white = (balls.pos[balls.index(i)] for i in ("red", "yellow", "white"))
    direct = sim.run(balls.strike("white", math.atan2(*(red - white)[::-1]), 3.0))
    s = summarize_carom(events_of(direct), rows)
    assert s.first == "red" and s.cushions_before_first == 0
    rules = ThreeCushion()
    st = rules.initial_state(0)
    assert st.break_shot and st.innings == (1, 0) and st.cue_ball == "white"
    assert not rules.call(st, s).foul
    at_yellow = sim.run(balls.strike("white", math.atan2(*(yellow - white)[::-1]), 3.0))
    s = summarize_carom(events_of(at_yellow), rows)
    assert s.first == "opponent"
    c = rules.call(st, s)
    assert c.foul and c.fouls == (T.BREAK_NOT_ON_RED,) and c.turn_over and not c.point
    assert not ThreeCushion(ThreeCushionOptions(break_red_first=False)).call(st, s).foul


def test_opening_shot_scoring_after_a_cushion_first_is_a_foul_and_scores_nothing():
    s = CaromSummary("red", "opponent", cushions=3, cushions_total=3, cushions_before_first=1)
    c = ThreeCushion().call(ThreeCushion().initial_state(0), s)
    assert c.foul and not c.point and c.score == (0, 0) and c.turn_over
    assert ThreeCushion().call(mid(), s).point  # the same shot later in the game scores


# --- the event scan (hand-made logs) -------------------------------------------------------------------------

def _reference(ev: np.ndarray, cue: int, opp: int, red: int) -> tuple[int, int, int, int, int]:
    """A plain-Python reading of the rule, to cross-check the compiled scan."""
    met: list[int] = []
    cush = 0
    at_second, before_first = None, -1
    for kind, b, o in ev.tolist():
        if kind == EV_CUSHION and b == cue:
            cush += 1
        elif kind == EV_COLLISION and cue in (b, o):
            x = o if b == cue else b
            if x in (opp, red) and x not in met:
                met.append(x)
                if len(met) == 1:
                    before_first = cush
                else:
                    at_second = cush
    return (met[0] if met else -1, met[1] if len(met) > 1 else -1, cush if at_second is None else at_second, cush,
            before_first)


def test_a_kiss_between_the_object_balls_is_not_the_cue_ball_meeting_the_second():
    ev = log(hit(WHITE, RED), cushion(), cushion(), cushion(), hit(RED, YELLOW), cushion(), hit(YELLOW, WHITE))
    s = summarize_carom(ev, (WHITE, YELLOW, RED))
    assert (s.first, s.second, s.cushions, s.cushions_total) == ("red", "opponent", 4, 4) and s.point


def test_cushions_of_other_balls_and_other_event_kinds_do_not_count():
    ev = log(cushion(), cushion(RED), cushion(YELLOW), (EV_ROLL, WHITE, -1), hit(RED, WHITE), cushion(RED),
             (EV_JAM, WHITE, 2), cushion(), hit(WHITE, YELLOW), cushion(), (EV_STOP, WHITE, -1))
    s = summarize_carom(ev, (WHITE, YELLOW, RED))
    assert (s.first, s.second, s.cushions, s.cushions_total, s.cushions_before_first) == ("red", "opponent", 2, 3, 1)
    assert not s.point


def test_meeting_the_first_ball_again_does_not_make_it_the_second():
    ev = log(hit(WHITE, RED), cushion(), hit(RED, WHITE), cushion(), cushion(), hit(WHITE, YELLOW))
    s = summarize_carom(ev, (WHITE, YELLOW, RED))
    assert (s.first, s.second, s.cushions) == ("red", "opponent", 3) and s.point


def test_the_scan_agrees_with_a_plain_reading_on_random_shots():
    """Random shots under the spin model: the compiled scan, single and batched, equals the plain-Python reading."""
    rng = np.random.default_rng(7)
    table = carom_table()
    sim = Simulator(table, Physics(friction="spin"))
    balls = carom_balls(table)
    n = 120
    to_red = math.atan2(*(balls.pos[RED] - balls.pos[WHITE])[::-1])
    angles = np.where(np.arange(n) % 2, rng.uniform(-math.pi, math.pi, n), to_red + rng.uniform(-0.4, 0.4, n))
    res = run_shots(sim, balls, angles, rng.uniform(1.0, 6.0, n), ball="white",
                    side=rng.uniform(-0.35, 0.35, n), top=rng.uniform(-0.3, 0.3, n), events=True)
    ev = res.events
    first, second, cush, total, before, point = scan_carom_batch(ev.offsets, ev.kind, ev.ball, ev.other,
                                                                 WHITE, YELLOW, RED)
    kinds = set()
    for k in range(n):
        a, b = ev.offsets[k], ev.offsets[k + 1]
        rows = np.stack([ev.kind[a:b], ev.ball[a:b], ev.other[a:b]], axis=1)
        ref = _reference(rows, WHITE, YELLOW, RED)
        assert (first[k], second[k], cush[k], total[k], before[k]) == ref
        s = summarize_carom(rows, (WHITE, YELLOW, RED))
        assert s.point == point[k] == (ref[1] >= 0 and ref[2] >= 3)
        kinds.add(int(first[k] >= 0) + int(second[k] >= 0))
    assert kinds == {0, 1, 2}  # the sample has misses, one-ball shots and both-ball shots


# --- the game ----------------------------------------------------------------------------------------------------

POINT = CaromSummary("red", "opponent", 3, 3, 0)
MISS = CaromSummary("red", None, 2, 2, 0)


def test_the_first_to_the_target_wins():
    rules = ThreeCushion(ThreeCushionOptions(target_points=3))
    c, st = rules.play(mid(score=(2, 1)), POINT)
    assert c.game_over and c.winner == 0 and c.reason == T.TARGET_REACHED and c.score == (3, 1)
    assert st.game_over and st.winner == 0
    with pytest.raises(RulesError, match="game is over"):
        rules.call(st, POINT)


def test_innings_are_counted_and_the_run_resets():
    rules = ThreeCushion()
    st = rules.initial_state(1)
    assert st.shooter == 1 and st.innings == (0, 1)
    st = rules.next_state(st, rules.call(st, CaromSummary("red", None, 0, 0, 0)))
    assert st.shooter == 0 and st.innings == (1, 1) and not st.break_shot
    for _ in range(2):
        st = rules.next_state(st, rules.call(st, POINT))
    assert st.run == 2 and st.score == (2, 0) and st.shooter == 0
    st = rules.next_state(st, rules.call(st, MISS))
    assert st.shooter == 1 and st.run == 0 and st.innings == (1, 2)


def test_innings_limit_ends_the_game_after_the_second_players_inning():
    rules = ThreeCushion(ThreeCushionOptions(max_innings=2))
    st = mid(innings=(2, 1), score=(1, 1), shooter=0)
    c, st = rules.play(st, MISS)  # the breaker's 2nd inning ends: the other player still has his
    assert not c.game_over and st.shooter == 1 and st.innings == (2, 2)
    c, st = rules.play(st, POINT)
    assert not c.game_over
    c, st = rules.play(st, MISS)
    assert c.game_over and c.winner == 1 and c.reason == T.INNINGS_LIMIT
    c = rules.call(mid(innings=(2, 2), score=(1, 1), shooter=1), MISS)
    assert c.game_over and c.winner is None  # a draw


def test_equalizing_inning():
    rules = ThreeCushion(ThreeCushionOptions(target_points=3, equalizing_inning=True))
    c, st = rules.play(mid(score=(2, 1), innings=(3, 2)), POINT)  # the breaker reaches the target
    assert not c.game_over and c.turn_over and c.reason == T.EQUALIZING and st.shooter == 1 and st.last_inning
    assert st.innings == (3, 3)
    c2, st2 = rules.play(st, POINT)
    assert not c2.game_over and not c2.turn_over  # 2 of 3: the inning goes on
    c3 = rules.call(st2, POINT)
    assert c3.game_over and c3.winner is None and c3.score == (3, 3)  # equalized: a draw
    c4 = rules.call(st2, MISS)
    assert c4.game_over and c4.winner == 0  # fell short: the breaker wins
    c5 = rules.call(mid(shooter=1, score=(1, 2), innings=(3, 3)), POINT)
    assert c5.game_over and c5.winner == 1  # the second player reaching it ends the game at once


# --- bad input -----------------------------------------------------------------------------------------------------

def test_bad_input_is_refused_clearly():
    with pytest.raises(RulesError, match="target_points"):
        ThreeCushionOptions(target_points=0)
    with pytest.raises(RulesError, match="max_innings"):
        ThreeCushionOptions(max_innings=True)
    with pytest.raises(RulesError, match="miss_is_foul"):
        ThreeCushionOptions(miss_is_foul=1)
    with pytest.raises(RulesError, match="ThreeCushion options"):
        ThreeCushion({"target_points": 3})
    with pytest.raises(RulesError, match="score"):
        ThreeCushionState(score=(1, -1))
    with pytest.raises(RulesError, match="winner"):
        ThreeCushionState(winner=0)
    with pytest.raises(RulesError, match="second"):
        CaromSummary(None, "red")
    with pytest.raises(RulesError, match="cushions"):
        CaromSummary("red", None, 4, 2, 0)
    with pytest.raises(RulesError, match="'red', 'opponent' or None"):
        CaromSummary("blue")
    with pytest.raises(RulesError, match="three-cushion needs the ids"):
        carom_rows(("cue", "1", "2"), 0)
    with pytest.raises(RulesError, match=r"\(M, 3\)"):
        summarize_carom(np.zeros((2, 2)), (0, 1, 2))
    with pytest.raises(RulesError, match="three different balls"):
        summarize_carom(np.zeros((0, 3)), (0, 0, 2))
    st = mid()
    c = ThreeCushion().call(st, MISS)
    with pytest.raises(RulesError, match="state.shooter"):
        ThreeCushion().next_state(mid(shooter=1), c)
    assert SIM.table.n_pockets == 0 and carom({}).ids == CAROM_IDS
