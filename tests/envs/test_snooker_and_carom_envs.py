"""Snooker and three-cushion as envs: scripted tables played through ``env.step``, checking the call the env reports
(the rules themselves are tested on scripted tables in tests/rules; here the wiring: layouts, the shot outcome read
into the rules' summary, re-spots, the D, the rows following the turn in three-cushion, the players)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from env_helpers import gym

from billiards_env.multi import three_cushion_v0
from billiards_env.games.carom_layout import carom_start_positions
from billiards_env.games.snooker_layout import SNOOKER_IDS, d_geometry, snooker_spots
from billiards_env.table_state import HalfDiscArea

L, W = 3.569, 1.778


def _snooker(**kw):
    env = gym.make("BilliardsSnooker-v0", **{"opponent": None, **kw})
    env.reset(seed=0)
    return env, env.unwrapped


def _table(u, red_at=None):
    """The spots' layout with one red on the table (at ``red_at``) and the others potted."""
    pos = u.balls.pos.copy()
    pocketed = np.zeros(len(SNOOKER_IDS), bool)
    for k, bid in enumerate(SNOOKER_IDS):
        if bid.startswith("red"):
            pocketed[k] = bid != "red1"
    if red_at is not None:
        pos[SNOOKER_IDS.index("red1")] = red_at
    return pos, pocketed


def test_snooker_starts_from_the_spots_with_the_cue_ball_in_the_d():
    env, u = _snooker()
    spots = snooker_spots(u.table)
    for colour, xy in spots.items():
        assert np.allclose(u.balls.pos[SNOOKER_IDS.index(colour)], xy)
    area = u.table_state.view.place_area
    assert isinstance(area, HalfDiscArea) and area.contains(*u.balls.pos[0])
    assert env.observation_space.shape == (3 * 22 + 10,)
    assert u.table_state.view.targets == tuple(range(1, 16))  # the reds


def test_a_potted_red_scores_one_and_the_colour_is_on():
    env, u = _snooker()
    pos, pocketed = _table(u, red_at=(L - 0.3, W - 0.3))
    pos[0] = (L - 0.8, W - 0.8)
    env.reset(options={"positions": pos, "pocketed": pocketed})
    obs, reward, term, trunc, info = env.step(u.action_from_shot(math.pi / 4, 2.0))
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert w["pocketed"] == ("red1",) and info["points"] == 1 and not info["foul"]
    assert w["on"] == "colour" and w["score"] == (1, 0) and not info["turn_over"] and not term
    assert u.table_state.view.targets == tuple(SNOOKER_IDS.index(c) for c in ("yellow", "green", "brown", "blue", "pink",
                                                                          "black"))


def test_hitting_a_colour_first_on_a_red_gives_its_value_away():
    env, u = _snooker()
    pos, pocketed = _table(u, red_at=(0.3, 0.3))
    pos[0] = (2.2, 0.889)  # between the blue and the pink: the pink straight ahead
    env.reset(options={"positions": pos, "pocketed": pocketed})
    *_, term, trunc, info = env.step(u.action_from_shot(0.0, 1.0))
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert w["first_contact"] == "pink" and info["foul"] and info["foul_points"] == 6
    assert w["score"] == (0, 6) and info["turn_over"] and term  # alone: the practice ends at a foul


def test_an_in_off_puts_the_cue_ball_in_hand_in_the_d():
    env, u = _snooker(opponent="geometric", opponent_infos=True)  # the opponent's shots one by one too
    pos, pocketed = _table(u, red_at=(0.3, 1.4))
    pos[0] = (3.3, 0.25)  # straight into the bottom-right corner pocket
    env.reset(options={"positions": pos, "pocketed": pocketed})
    *_, info = env.step(u.action_from_shot(math.atan2(-0.25, L - 3.3), 2.0))
    assert info["scratch"] and info["foul"] and info["foul_points"] == 4 and info["turn_over"]
    turns = info["opponent_turns"]
    assert turns and turns[0]["shooter"] == 1  # the opponent played, from the D
    assert info["opponent_shots"] == len(turns) and info["opponent_fouls"] == sum(t["foul"] for t in turns)
    assert u.balls.on_table[0]


def test_an_in_off_leaves_the_next_striker_in_hand_in_the_d():
    env, u = _snooker()
    pos, pocketed = _table(u, red_at=(0.3, 1.4))
    pos[0] = (3.3, 0.25)
    env.reset(options={"positions": pos, "pocketed": pocketed})
    *_, info = env.step(u.action_from_shot(math.atan2(-0.25, L - 3.3), 2.0))
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert info["scratch"] and w["ball_in_hand"] == "d"
    cx, cy, r = d_geometry(u.table)
    assert u.balls.on_table[0] and HalfDiscArea(cx - r, cx, cy - r, cy + r).contains(*u.balls.pos[0], tol=1e-6)


def test_ball_in_hand_places_the_cue_ball_in_the_d():
    env, u = _snooker()
    pos, pocketed = _table(u, red_at=(2.8, 1.2))
    env.reset(options={"positions": pos, "pocketed": pocketed, "ball_in_hand": "d"})
    area = u.table_state.view.place_area
    for place in ((-1.0, -1.0), (1.0, 1.0), (0.0, 0.0), (1.0, -0.3)):
        shot = u.shot_from_action(np.array([0.0, 0.0, *place], np.float32))
        assert area.contains(*shot.place, tol=1e-6)
    with pytest.raises(ValueError, match="outside the ball-in-hand area the half-disc"):
        u.action_from_shot(0.0, 1.0, place=(1.5, 0.9))
    a = u.action_from_shot(0.0, 1.0, place=(0.6, 0.8))
    assert np.allclose(u.shot_from_action(a).place, (0.6, 0.8), atol=1e-6)


def _carom(**kw):
    env = gym.make("BilliardsThreeCushion-v0", **kw)
    env.reset(seed=0)
    return env, env.unwrapped


def test_three_cushion_opening_must_meet_the_red_first():
    env, u = _carom(opponent=None)
    start = carom_start_positions(u.table, breaker=0)
    assert u.ball_ids == ("white", "yellow", "red") and np.allclose(u.balls.pos[0], start["white"])
    yellow = u.balls.pos[1]
    angle = math.atan2(yellow[1] - u.balls.pos[0][1], yellow[0] - u.balls.pos[0][0])
    *_, term, trunc, info = env.step(u.action_from_shot(angle, 1.0))
    # Rows as the shot saw them: row 1 the other cue ball (yellow for white's opening; the turn passed, and with it
    # the rows: now yellow is row 0).
    w = env.unwrapped.info_words(info, ids=("white", "yellow", "red"))
    assert info["first_contact"] == 1 and u.ball_ids[0] == "yellow"
    assert w["first_contact"] == "yellow" and info["foul"] and w["call"] == "break not on the red"
    assert not info["point"] and info["turn_over"] and term


def test_a_point_from_the_search_player_counts_and_the_inning_goes_on():
    env, u = _carom(opponent=None)
    from billiards_env.players import three_cushion as carom_players

    player = carom_players.CaromSearchPlayer(seed=0)
    action = player.act(env, None)
    assert player.last.point
    *_, term, trunc, info = env.step(action)
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert info["point"] and info["cushions"] >= 3 and w["score"] == (1, 0) and info["run"] == 1
    assert not info["turn_over"] and not term and u.ball_ids[0] == "white"


def test_the_rows_follow_the_turn():
    env = three_cushion_v0.env()
    env.reset(seed=1)
    game = env.unwrapped.game_env
    assert env.agent_selection == "player_0" and game.ball_ids[0] == "white"
    # player_0 misses everything: the yellow player's ball is row 0 on its turn, and its observation lists it first
    env.step(game.action_from_shot(math.pi / 2, 0.6, side=0.0, top=0.0))
    assert env.agent_selection == "player_1" and game.ball_ids == ("yellow", "white", "red")
    assert np.allclose(env.observe("player_1")[:2] * [game.table.length, game.table.width],
                       game.balls.pos[0], atol=1e-6)
    assert game.task.session.game_state.shooter == 1


def test_snooker_and_carom_players_choose_legal_shots():
    for env_id in ("BilliardsSnooker-v0", "BilliardsThreeCushion-v0"):
        for name in ("geometric", "search"):
            env = gym.make(env_id, opponent=None)
            obs, _ = env.reset(seed=2)
            env.unwrapped.set_opponent(name)  # a name makes that player of this game
            player = env.unwrapped.task.opponent
            action = player.act(env, obs)
            assert env.action_space.contains(action)
            env.step(action)
