"""Scripted two-player games: tables set with reset options, known shots; the turn, ball in hand, each agent's
point of view, the winner and zero-sum rewards."""
from __future__ import annotations

import math
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from billiards_env.multi import eight_ball_v0, nine_ball_v0  # noqa: E402

L, W = 2.54, 1.27
PARKED = [(0.3 + 0.1 * k, 0.1) for k in range(15)]
TOP_RIGHT_BALL, TOP_RIGHT_CUE = (L - 0.25, W - 0.25), (L - 0.65, W - 0.65)  # on the diagonal of pocket 5 (L, W)
BOTTOM_LEFT_BALL, BOTTOM_LEFT_CUE = (0.25, 0.25), (0.65, 0.65)  # on the diagonal of pocket 0 (0, 0)
TOWARDS_TOP_RIGHT, TOWARDS_BOTTOM_LEFT = math.pi / 4, -3 * math.pi / 4
# Game features (the last 11 values of an observation): see GameTask.features.
BIH, LOWEST, SOLIDS, STRIPES, ON_EIGHT, OWN_FOULS, OPP_FOULS, MY_TURN = 0, 3, 4, 5, 6, 7, 8, 10


def table(n_balls, cue, placed):
    """Positions (rows cue, 1..n) and pocketed flags: the balls in ``placed`` where given, the others pocketed."""
    pos = np.array([cue] + PARKED[:n_balls], dtype=float)
    off = np.ones(n_balls + 1, dtype=bool)
    off[0] = False
    for number, xy in placed.items():
        pos[number] = xy
        off[number] = False
    return pos, off


def features(env, agent):
    return env.observe(agent)[-11:]


def finish(env):
    """Step both agents out after the game (None), checking PettingZoo's end protocol."""
    seen = []
    for agent in env.agent_iter():
        obs, reward, terminated, truncated, info = env.last()
        assert terminated and not truncated
        seen.append((agent, reward, info))
        env.step(None)
    assert env.agents == [] and sorted(a for a, _, _ in seen) == ["player_0", "player_1"]
    return {a: (r, i) for a, r, i in seen}


def test_nine_ball_turns_ball_in_hand_and_the_winner():
    env = nine_ball_v0.env()
    pos, off = table(9, TOP_RIGHT_CUE, {1: TOP_RIGHT_BALL, 9: BOTTOM_LEFT_BALL})
    env.reset(seed=0, options={"positions": pos, "pocketed": off})
    game = env.unwrapped.game_env
    assert env.agent_selection == "player_0"
    assert features(env, "player_0")[MY_TURN] == 1.0 and features(env, "player_1")[MY_TURN] == 0.0

    # player_0 pots the 1 straight in: legal, keeps the table.
    env.step(game.action_from_shot(TOWARDS_TOP_RIGHT, 1.2))
    info = env.infos["player_0"]
    w = game.info_words(info)  # the balls as ids, the codes as names
    assert w["pocketed"] == ("1",) and not info["foul"] and not info["turn_over"] and info["shot_by"] == 0
    assert env.agent_selection == "player_0" and env.rewards == {"player_0": 0.0, "player_1": 0.0}
    assert w["legal_targets"] == ("9",) and "opponent_shots" not in info

    # player_0 then strikes the cue ball up the table, away from the 9: no contact, a foul.
    env.step(game.action_from_shot(math.pi / 2, 0.6))
    for agent in ("player_0", "player_1"):
        info = env.infos[agent]
        w = game.info_words(info)
        assert w["foul_reason"] == "no contact" and info["shooter"] == 1 and w["ball_in_hand"] == "anywhere"
        assert info["player"] == ("player_0", "player_1").index(agent) and info["shot_by"] == 0
    assert env.agent_selection == "player_1"
    mine, theirs = features(env, "player_1"), features(env, "player_0")
    assert (mine[BIH], mine[MY_TURN], mine[OWN_FOULS], mine[OPP_FOULS]) == (1.0, 1.0, 0.0, 0.5)
    assert (theirs[BIH], theirs[MY_TURN], theirs[OWN_FOULS], theirs[OPP_FOULS]) == (0.0, 0.0, 0.5, 0.0)
    np.testing.assert_array_equal(env.observe("player_0")[:-11], env.observe("player_1")[:-11])  # one table

    # player_1 takes the cue ball in hand, places it on the 9's diagonal and pots the 9: player_1 wins.
    action = game.action_from_shot(TOWARDS_BOTTOM_LEFT, 1.2, place=BOTTOM_LEFT_CUE)
    assert game.shot_from_action(action).place == pytest.approx(BOTTOM_LEFT_CUE, abs=1e-6)  # float32
    env.step(action)
    assert env.terminations == {"player_0": True, "player_1": True} and not any(env.truncations.values())
    assert env.rewards == {"player_0": -1.0, "player_1": 1.0}
    assert env.unwrapped.winner == "player_1" and game.info_words(env.infos["player_1"])["call"] == "9 pocketed"
    final = finish(env)
    assert final["player_1"][0] == 1.0 and final["player_0"][0] == -1.0  # accumulated since each last acted
    assert final["player_1"][1]["is_success"] and not final["player_0"][1]["is_success"]
    assert final["player_0"][1]["winner"] == 1


def test_eight_ball_each_agent_sees_its_own_group_and_an_uncalled_eight_loses():
    env = eight_ball_v0.env()
    # Solids cleared: player_0 (solids) is on the 8; player_1 (stripes) still has the 11.
    pos, off = table(15, TOP_RIGHT_CUE, {8: TOP_RIGHT_BALL, 11: (0.6, 0.3)})
    env.reset(seed=0, options={"positions": pos, "pocketed": off, "groups": ("solids", "stripes")})
    game = env.unwrapped.game_env
    p0, p1 = features(env, "player_0"), features(env, "player_1")
    assert (p0[SOLIDS], p0[STRIPES], p0[ON_EIGHT], p0[LOWEST]) == (1.0, 0.0, 1.0, pytest.approx(8 / 15))
    assert (p1[SOLIDS], p1[STRIPES], p1[ON_EIGHT], p1[LOWEST]) == (0.0, 1.0, 0.0, pytest.approx(11 / 15))

    # player_0 pots the 8 in the top-right pocket (5) but calls pocket 0: the shooter loses, player_1 wins.
    env.step(game.action_from_shot(TOWARDS_TOP_RIGHT, 1.2, pocket=0))
    assert game.info_words(env.infos["player_0"])["call"] == "8 in an uncalled pocket"
    assert env.rewards == {"player_0": -1.0, "player_1": 1.0}  # zero-sum, to the player who did not shoot too
    final = finish(env)
    assert final["player_1"][0] == 1.0 and final["player_1"][1]["is_success"]


def test_eight_ball_legal_eight_in_the_called_pocket_wins_and_shaping_is_per_shooter():
    env = eight_ball_v0.env(pot_reward=0.1, foul_penalty=0.5)
    pos, off = table(15, TOP_RIGHT_CUE, {8: TOP_RIGHT_BALL, 11: (0.6, 0.3)})
    env.reset(seed=0, options={"positions": pos, "pocketed": off, "groups": ("solids", "stripes")})
    env.step(env.unwrapped.game_env.action_from_shot(TOWARDS_TOP_RIGHT, 1.2, pocket=5))
    assert env.unwrapped.game_env.info_words(env.infos["player_0"])["call"] == "8 pocketed"
    assert env.unwrapped.winner == "player_0"
    # The shooter's shaping (+0.1 for its legal pot) on top of the win; the loser gets only the loss.
    assert env.rewards == {"player_0": pytest.approx(1.1), "player_1": -1.0}


def test_truncation_after_max_shots_of_both_players():
    env = nine_ball_v0.env(max_shots=3, rules={"three_foul_rule": False})
    pos, off = table(9, (0.5, 0.3), {1: (1.5, 0.9), 9: (2.0, 0.4)})
    env.reset(seed=0, options={"positions": pos, "pocketed": off})
    game = env.unwrapped.game_env
    shooters = []
    for agent in env.agent_iter():
        _, reward, terminated, truncated, info = env.last()
        if terminated or truncated:
            assert truncated and not terminated and reward == 0.0 and info["winner"] == -1
            env.step(None)
            continue
        shooters.append(agent)
        # A soft shot straight down into the bottom cushion touches no ball: a foul, the turn passes.
        env.step(game.action_from_shot(-math.pi / 2, 0.5))
    assert shooters == ["player_0", "player_1", "player_0"] and env.unwrapped.winner is None
