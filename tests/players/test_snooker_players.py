"""The snooker players (geometric and search) and the referee that plays their shots on a table."""
from __future__ import annotations

import math

import numpy as np
import pytest

from billiards_env.physics import Balls, Physics, Simulator
from billiards_env.games.snooker_layout import SNOOKER_COLOURS, in_d, snooker_balls, snooker_spots
from billiards_env.physics.table import SNOOKER_BALL_MASS, SNOOKER_BALL_RADIUS, snooker_table
from billiards_env.players.referee import snooker_turn
from billiards_env.players.snooker import (SnookerSearchSettings, SnookerShot, snooker_geometric_shot,
                                           snooker_search_shot, target_rows)
from billiards_env.rules.snooker import Snooker, SnookerOptions, SnookerState, snooker_values, snookered

TABLE = snooker_table()
SIM = Simulator(TABLE, Physics())
SPOTS = snooker_spots(TABLE)
RULES = Snooker()
L, W = TABLE.length, TABLE.width
R = SNOOKER_BALL_RADIUS


def table_with(pos: dict[str, tuple[float, float]], colours=SNOOKER_COLOURS) -> tuple[Balls, np.ndarray]:
    """``pos`` (the cue ball and any reds), and the ``colours`` on their spots unless placed."""
    p = dict(pos)
    for c in colours:
        p.setdefault(c, SPOTS[c])
    ids = list(p)
    b = Balls.from_positions([p[i] for i in ids], ids=ids, radius=R, mass=SNOOKER_BALL_MASS)
    return b, snooker_values(b.ids)


def mid(**kw) -> SnookerState:
    kw.setdefault("ball_in_hand", False)
    return SnookerState(**kw)


def play(balls, values, state, shot, **kw):
    return snooker_turn(SIM, balls, values, state, shot, RULES, **kw)


# A red straight in front of the bottom-right pocket; the cue ball 0.5 m behind it.
RED_POT = {"cue": (2.7, 0.45), "red1": (3.2, 0.16)}


@pytest.mark.parametrize("player", ["geometric", "search"])
def test_player_pots_an_easy_red(player):
    balls, values = table_with(RED_POT)
    state = mid(reds=1)
    fn = snooker_geometric_shot if player == "geometric" else snooker_search_shot
    shot = fn(balls, SIM, state, values)
    assert shot.target == balls.index("red1") and shot.nominated is None and shot.place is None
    turn = play(balls, values, state, shot)
    assert turn.call.points == 1 and not turn.call.foul and turn.state.on == "colour"


def test_geometric_player_prefers_the_black_and_nominates_it():
    """On a colour with the yellow and the black equally easy (mirror images), the black is worth more."""
    pos = {"cue": (L / 2, W / 2 - 0.3), "yellow": (L / 2 - 0.5, 0.3), "black": (L / 2 + 0.5, 0.3),
           "red1": (0.3, 1.5), "green": (0.3, 1.3), "brown": (0.5, 1.5), "blue": (0.5, 1.3), "pink": (0.7, 1.5)}
    balls, values = table_with(pos)
    shot = snooker_geometric_shot(balls, SIM, mid(on="colour"), values)
    assert shot.nominated == "black" and shot.target == balls.index("black")


def test_search_player_on_a_colour_scores_and_nominates():
    pos = {"cue": (2.7, 0.45), "black": (3.2, 0.16), "red1": (1.0, 1.5)}
    balls, values = table_with(pos)
    state = mid(on="colour")
    shot = snooker_search_shot(balls, SIM, state, values)
    turn = play(balls, values, state, shot)
    assert turn.call.points == 7 and turn.call.nominated == "black" and shot.nominated == "black"
    assert turn.call.respot == ("black",) and tuple(balls.pos[balls.index("black")]) == SPOTS["black"]


@pytest.mark.parametrize("player", ["geometric", "search"])
def test_ball_in_hand_is_placed_in_the_d(player):
    balls = snooker_balls(TABLE)
    values = snooker_values(balls.ids)
    state = RULES.initial_state(0)
    fn = snooker_geometric_shot if player == "geometric" else snooker_search_shot
    shot = fn(balls, SIM, state, values)
    assert shot.place is not None and in_d(*shot.place, TABLE)
    gaps = np.hypot(*(balls.pos[1:] - np.asarray(shot.place)).T)
    assert gaps.min() >= 2 * R  # a legal place, off the other balls
    turn = play(balls, values, state, shot)
    assert turn.state.shot_number == 1 and not np.array_equal(balls.pos[0], shot.place)


def test_search_player_avoids_the_in_off():
    """A red on the lip of the pocket with the cue ball straight behind: a firm pot follows it in; the search pots
    it without the foul."""
    pos = {"cue": (3.2, 0.3), "red1": (3.569 - 0.075, 0.075)}
    balls, values = table_with(pos)
    state = mid(reds=1)
    shot = snooker_search_shot(balls, SIM, state, values)
    turn = play(balls, values, state, shot)
    assert not turn.call.foul and turn.call.points == 1


def test_search_player_plays_a_free_ball_when_snookered_after_a_foul():
    """The only red is hidden behind the blue: after the opponent's foul the striker takes a free ball."""
    pos = {"cue": (2.0, 0.25), "blue": (2.0, 0.7), "red1": (2.0, 1.3)}
    balls, values = table_with(pos)
    state = mid(reds=1, after_foul=True, shooter=1)
    snk = snookered(balls.pos, balls.on_table, balls.radius, values, "red")
    assert snk and RULES.free_ball_available(state, snk)
    assert balls.index("blue") in target_rows(balls, values, state, free_ball=True)
    shot = snooker_search_shot(balls, SIM, state, values, snookered=snk)
    turn = play(balls, values, state, shot, is_snookered=snk)
    assert not turn.call.foul


def test_referee_handles_in_off_respot_and_the_miss_rule():
    u = np.array([-L / 2, W / 2]) / math.hypot(L / 2, W / 2)  # from the bottom-right pocket towards the centre
    black = np.array([L, 0.0]) + 0.06 * u
    cue = black + 0.3 * u
    balls, values = table_with({"cue": tuple(cue), "black": tuple(black), "red1": (1.0, 1.5)})
    a = math.atan2(-u[1], -u[0])
    turn = play(balls, values, mid(on="colour"), SnookerShot(a, 6.0))  # black and cue ball both go in
    assert turn.call.foul and "in-off" in turn.call.fouls and turn.state.ball_in_hand == "d"
    assert turn.call.respot == ("black",) and balls.on_table[balls.index("black")]
    assert not balls.on_table[0] and not turn.snookered
    # the miss rule: the table is put back and the offender plays again
    rules = Snooker(SnookerOptions(miss_rule=True))
    balls, values = table_with({"cue": (2.4, 0.5), "red1": (1.0, 1.5)})
    before = balls.pos.copy()
    turn = snooker_turn(SIM, balls, values, mid(reds=1), SnookerShot(-math.pi / 2, 1.0), rules)
    assert turn.call.miss and turn.call.replace and np.array_equal(balls.pos, before)
    assert turn.state.shooter == 0 and turn.state.misses == (1, 0) and turn.state.score == (0, 4)


def test_search_players_finish_a_short_frame():
    """Three reds and the colours, the search player against itself from the break-off, to the end."""
    balls = snooker_balls(TABLE)
    for k in range(4, 16):  # only red1..red3 stay
        balls.on_table[balls.index(f"red{k}")] = False
    values = snooker_values(balls.ids)
    state = RULES.initial_state(0, reds=3)
    snk = False
    rng = np.random.default_rng(0)
    settings = SnookerSearchSettings(n_geometric=5, sweep_angles=24, top_k=3, robust_samples=3)
    for _ in range(120):
        shot = snooker_search_shot(balls, SIM, state, values, settings, snookered=snk, rng=rng)
        turn = play(balls, values, state, shot, is_snookered=snk)
        state, snk = turn.state, turn.snookered
        if state.frame_over:
            break
    assert state.frame_over and state.winner in (0, 1) and state.score[state.winner] > state.score[1 - state.winner]
    assert not balls.on_table[(values >= 1) & (values <= 6)].any()  # a frame ends on the last black


def test_search_is_deterministic_for_a_seed_and_leaves_the_balls_alone():
    balls, values = table_with(RED_POT)
    before = balls.pos.copy()
    shots = [snooker_search_shot(balls, SIM, mid(reds=1), values, angle_noise=0.002, speed_noise=0.03,
                                 rng=np.random.default_rng(5)) for _ in range(2)]
    assert shots[0] == shots[1] and np.array_equal(balls.pos, before)
