"""The option scorer with the cue ball in hand: the places it weighs, the labels of the teacher's place and shot,
and the shot it plays (agents/option_policies.py)."""
from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401
from agents.option_policies import (HAND_PLACES, N_GRID, N_SLOTS, RULE_KWARGS, Scorer, action_of, hand_label,
                                    hand_places, make_net, placed_observations)

pytest.importorskip("torch")
OPTIONS_PER_PLACE = (N_SLOTS - 1) * N_GRID


def _in_hand_env(seed: int):
    env = gym.make("Billiards9Ball-v0", **RULE_KWARGS, opponent="geometric", opening="ball_in_hand",
                   first_shooter="agent")
    obs, _ = env.reset(seed=seed)
    assert env.unwrapped.table_state.view.place_area is not None
    return env, obs


def test_cue_placed_plays_the_table_from_the_place():
    env, _ = _in_hand_env(3)
    u = env.unwrapped
    state, at = u.table_state, u.action_type
    view, cue = state.view, state.balls.pos[0].copy()
    assert at.slots(state).in_hand
    place = hand_places(state, at)[0]
    with state.cue_placed(place):
        assert state.view.place_area is None and state.view.targets == view.targets
        assert tuple(state.balls.pos[0]) == place and state.balls.on_table[0]
        slots = at.slots(state)
        assert not slots.in_hand and slots.count > 0
    assert state.view is view and np.array_equal(state.balls.pos[0], cue) and at.slots(state).in_hand
    env.close()


def test_placed_observations_see_the_cue_ball_at_each_place():
    env, obs = _in_hand_env(4)
    u = env.unwrapped
    places = hand_places(u.table_state, u.action_type)
    assert 1 <= len(places) <= HAND_PLACES
    for a in places:  # the search player's places: at least a ball apart
        for b in places:
            assert a == b or math.dist(a, b) > 2 * float(u.table_state.balls.radius[0])
    o = placed_observations(u.table_state, u.observation_type, places)
    assert o.shape == (len(places), len(obs))
    n_game = u.task.n_features
    assert obs[-n_game] == 1.0 and not o[:, -n_game].any()  # in hand in the env's; not in the placed ones
    assert not np.array_equal(o[0], o[-1]) or len(places) == 1
    env.close()


def test_hand_labels_are_the_teachers_place_and_shot():
    """The search player (the teacher) with ball in hand searches from the same places: its label names one of
    them, and the option's shot from there aims where the teacher's does."""
    from billiards_env.players import make_player

    matched = 0
    for seed in range(6):
        env, obs = _in_hand_env(100 + seed)
        u = env.unwrapped
        label = make_player("search", seed=seed, game="nine_ball").act(env, obs)
        obs_p, target = hand_label(u.table_state, u.observation_type, u.action_type, label)
        assert obs_p.shape == (HAND_PLACES, len(obs))
        if target < 0:
            env.close()
            continue
        matched += 1
        p, k = divmod(target, OPTIONS_PER_PLACE)
        places = hand_places(u.table_state, u.action_type)
        teacher = u.action_type.shot(u.table_state, label)
        assert math.dist(places[p], teacher.place) <= 0.01
        with u.table_state.cue_placed(places[p]):
            mine = u.action_type.shot(u.table_state, action_of(k))
        assert abs(math.remainder(mine.angle - teacher.angle, 2 * math.pi)) < 0.05
        assert abs(mine.top - teacher.top) < 0.1  # the teacher's tips are the grid's
        assert 0.55 < mine.speed / teacher.speed < 1.5  # its speed factors 0.6 and 4 are the grid's 1 and 3
        env.close()
    assert matched >= 4


def test_the_scorer_plays_from_its_own_place():
    """With the cue ball in hand it plays from one of the places it weighed and leaves the table as it was; its env
    action puts the cue ball near there; hand=False keeps the older play (the fallback's place)."""
    import torch

    torch.manual_seed(0)
    sc = Scorer([make_net(16)])
    for seed in range(7, 27):  # a table where some place has an option (else it plays predict's shot)
        env, obs = _in_hand_env(seed)
        u = env.unwrapped
        places = hand_places(u.table_state, u.action_type)
        if sc.choose_hand(placed_observations(u.table_state, u.observation_type, places)) is not None:
            break
        env.close()
    else:
        raise AssertionError("no table of seeds 7-26 has an option from a ball-in-hand place")
    view, cue = u.table_state.view, u.table_state.balls.pos[0].copy()
    shot = sc.shot(u.table_state, u.observation_type, u.action_type)
    assert shot.place in places
    assert u.table_state.view is view and np.array_equal(u.table_state.balls.pos[0], cue)
    # the env's candidates action says "behind this ghost ball": near the place (a place pushed off a cushion is
    # not on that line), at the same ghost ball
    played = u.action_type.shot(u.table_state, sc.act(env, obs))
    assert math.dist(played.place, shot.place) < 0.03
    assert abs(math.remainder(played.angle - shot.angle, 2 * math.pi)) < 0.05
    sc.hand = False
    assert sc.shot(u.table_state, u.observation_type, u.action_type).place not in places or len(places) == 0
    env.close()


def test_the_league_plays_the_scorer_with_and_without_its_places(tmp_path):
    from agents.league import load_player

    path = tmp_path / "s.pt"
    Scorer([make_net(8)]).save(path)
    a, pa = load_player(f"scorer:{path}")
    b, pb = load_player(f"scorer-fallback:{path}")
    assert a != b  # one league can hold both
    env, obs = _in_hand_env(5)
    places = hand_places(env.unwrapped.table_state, env.unwrapped.action_type)
    u = env.unwrapped
    pa.prepare(u.table_state, u.action_type)
    pb.prepare(u.table_state, u.action_type)
    assert pa.policy_shot(u.table_state).place in places
    assert pb.policy_shot(u.table_state).place not in places
    env.close()
