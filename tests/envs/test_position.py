"""The ``candidates_position`` observation (envs/position.py): its layout, that each grid point packs the closed
form of physics/cue_rest.py and the search player's position term, the next legal ball of 9-ball, and the slots
without a shot reading 0."""
from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401
from billiards_env.envs.candidates import EASE_SPREAD, SLOT_FEATURES, candidate_slots
from billiards_env.envs.position import POINT_VALUES, POSITION_FEATURES, POWERS, TOPS, next_targets
from billiards_env.physics.aim import ghost_point
from billiards_env.physics.cue_rest import MAX_BOUNCES, cue_rest
from billiards_env.players.geometry import (COL_D_OBJ, COL_OBJ_ANGLE, COL_SPEED, COL_TARGET, MAX_CUT, places_ease,
                                            state_model)


def _env(**kw):
    return gym.make("Billiards9Ball-v0", action_type="candidates", observation_type="candidates_position",
                    friction="spin", spin_action=True, opponent=None, **kw)


def _split(env, obs):
    u = env.unwrapped
    n = u.config.candidate_slots
    nb = 3 * u.n_balls
    slots = obs[nb:nb + SLOT_FEATURES * n].reshape(n, SLOT_FEATURES)
    pos = obs[nb + SLOT_FEATURES * n:nb + (SLOT_FEATURES + POSITION_FEATURES) * n]
    return slots, pos.reshape(n, len(POWERS) * len(TOPS), POINT_VALUES)


def _a_table_with_pots(env):
    """Reset and play until the shooter has the cue ball where it lies and at least one pot slot."""
    for seed in range(40):
        obs, _ = env.reset(seed=seed)
        for _ in range(6):
            c = candidate_slots(env.unwrapped.table_state, env.unwrapped.config.candidate_slots)
            if not c.in_hand and not c.break_shot and c.count:
                return obs
            obs, _, term, trunc, _ = env.step(np.zeros(env.action_space.shape, np.float32))
            if term or trunc:
                break
    raise AssertionError("no table with a pot slot")


def test_layout_and_range():
    env = _env()
    obs, _ = env.reset(seed=0)
    u = env.unwrapped
    n = u.config.candidate_slots
    assert POSITION_FEATURES == POINT_VALUES * len(POWERS) * len(TOPS)
    assert obs.shape == (3 * u.n_balls + (SLOT_FEATURES + POSITION_FEATURES) * n + u.task.session.n_features,)
    assert env.observation_space.contains(obs)
    # the break: no slots, and no position map
    assert np.all(_split(env, obs)[1] == 0.0)
    obs = _a_table_with_pots(env)
    assert env.observation_space.contains(obs)
    slots, grid = _split(env, obs)
    assert np.all((grid >= 0.0) & (grid <= 1.0))
    for k in range(n):
        if slots[k, 0] == 0.0 or slots[k, 2] == -1.0:  # an empty slot or the kick (no pocket): no map
            assert np.all(grid[k] == 0.0)
    assert grid[0, :, 2:4].any()  # the first pot has rest points


def test_each_grid_point_is_the_closed_form_and_the_search_players_position_term():
    env = _env()
    obs = _a_table_with_pots(env)
    u = env.unwrapped
    state = u.table_state
    b, t, ph = u.balls, u.table, u.physics
    law, a, k = ph.path_args
    slots, grid = _split(env, obs)
    c = candidate_slots(state, u.config.candidate_slots)
    row = c.rows[0]
    j = int(row[COL_TARGET])
    gx, gy = ghost_point(b.pos[j, 0], b.pos[j, 1], row[COL_OBJ_ANGLE], float(b.radius[0] + b.radius[j]))
    lf = math.log(u.config.candidate_speed_factor)
    lo, hi = u.config.speed_min, u.config.speed_max
    nxt = next_targets(state, j)
    on = b.on_table.copy()
    on[j] = False
    tm = state_model(state)
    for p, power in enumerate(POWERS):
        for q, top in enumerate(TOPS):
            speed = min(max(row[COL_SPEED] * math.exp(power * lf), lo), hi)
            x, y, pocket, pots = cue_rest(b.pos[0, 0], b.pos[0, 1], gx, gy, row[COL_OBJ_ANGLE], row[COL_D_OBJ], speed,
                                          top * u.config.max_tip_offset, b.radius[0], b.mass[0], b.mass[1], t.length,
                                          t.width, t.cushion_restitution, ph.ball_restitution,
                                          np.ascontiguousarray(t.pocket_xy), np.ascontiguousarray(t.pocket_radius),
                                          law, a, k, ph.min_speed, u.simulator._params, MAX_BOUNCES)
            g = grid[0, p * len(TOPS) + q]
            assert g[0] == float(pots) and g[1] == float(pocket >= 0)
            assert g[2] == pytest.approx(min(max(x / t.length, 0.0), 1.0), abs=1e-6)
            assert g[3] == pytest.approx(min(max(y / t.width, 0.0), 1.0), abs=1e-6)
            ease = 0.0 if pocket >= 0 else places_ease(np.array([[x, y]]), b.pos, on, b.radius, 0, nxt,
                                                       tm.pocket_xy, tm.pocket_r, tm.params,
                                                       max(u.config.angle_noise, EASE_SPREAD), MAX_CUT)[0]
            assert g[4] == pytest.approx(ease, abs=1e-6)


def test_the_next_legal_ball_of_nine_ball_is_the_lowest_left():
    env = _env()
    env.reset(seed=3)
    u = env.unwrapped
    state = u.table_state
    nums = state.numbers
    on = [i for i in range(1, u.n_balls) if u.balls.on_table[i]]
    lowest = min(on, key=lambda i: nums[i])
    second = min((i for i in on if i != lowest), key=lambda i: nums[i])
    assert state.view.targets == (lowest,)
    assert next_targets(state, lowest).tolist() == [second]


def test_ball_in_hand_reads_zero():
    env = _env(opening="ball_in_hand")
    obs, _ = env.reset(seed=5)
    assert env.unwrapped.table_state.view.place_area is not None
    assert np.all(_split(env, obs)[1] == 0.0)
