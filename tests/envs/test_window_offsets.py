"""The cue ball's path after contact (physics/cue_path.py, envs/cue_path.py): the closed-form speed thresholds
against the engine's own simulation of the same shots, the window offset of the ``candidates_aim`` action type, and
the ``candidates_path`` observation's layout."""
from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401
from billiards_env.envs.window_offsets import OFFSETS, PATH_FEATURES, offset_ghost, offset_of, offset_rows, thresholds
from billiards_env.physics.cue_path import path_pocket_speed
from billiards_env.envs.candidates import candidate_slots
from billiards_env.physics.batch import run_shots


#: A capture table's (no) jaw walls: segments and tips.
NO_WALLS = (np.zeros((0, 6)), np.zeros((0, 3)))


def _env(**kw):
    return gym.make("BilliardsOneBall-v0", action_type="candidates_aim", observation_type="candidates_path",
                    candidate_slots=7, candidate_speed_factor=3.0, **kw)


def test_a_ball_rolled_at_a_pocket_needs_the_speed_of_its_distance():
    # straight at the corner pocket (0, 0) from (0.5, 0.5) along the diagonal: no cushion on the way
    u = -1.0 / math.sqrt(2.0)
    pocket_xy = np.array([[0.0, 0.0]])
    pocket_r = np.array([0.06])
    a = 0.098  # rolling deceleration
    p, s, bounces = path_pocket_speed(0.5, 0.5, u, u, 5.0, 0.028575, 2.54, 1.27, 0.85, pocket_xy, pocket_r, 0, a,
                                      0.0, 0.0, 40, *NO_WALLS)
    d = math.hypot(0.5, 0.5) - 0.06
    assert p == 0 and bounces == 0
    assert s == pytest.approx(math.sqrt(2 * a * d + (1.05e-6) ** 2), rel=1e-6)
    # too slow to get there: it stops first
    assert path_pocket_speed(0.5, 0.5, u, u, 0.9 * s, 0.028575, 2.54, 1.27, 0.85, pocket_xy, pocket_r, 0, a, 0.0,
                             0.0, 40, *NO_WALLS)[0] == -1


def test_after_a_cushion_the_speed_needed_counts_the_bounce():
    # along y = 0.3 towards the right cushion, which sends it back (normal component * e) into a pocket at (0.5, 0.3)
    e, a, r = 0.85, 0.098, 0.028575
    pocket_xy = np.array([[0.5, 0.3]])
    p, s, bounces = path_pocket_speed(1.0, 0.3, 1.0, 0.0, 10.0, r, 2.54, 1.27, e, pocket_xy, np.array([0.05]), 0, a,
                                      0.0, 0.0, 40, *NO_WALLS)
    to_wall = 2.54 - r - 1.0
    back = 2.54 - r - 0.5 - 0.05
    arrive = math.sqrt((1.05e-6) ** 2 + 2 * a * back)
    assert (p, bounces) == (0, 1)
    assert s == pytest.approx(math.sqrt((arrive / e) ** 2 + 2 * a * to_wall), rel=1e-9)


@pytest.mark.parametrize("seed", [100_004, 100_130, 100_208, 100_550])
def test_thresholds_match_the_engine(seed):
    """Below ``pot`` the object ball stops short, above it drops; below ``scratch`` the cue ball stays up, above it
    drops (shots 3% either side of each threshold, simulated by the engine). The thresholds follow each ball's lone
    path: a shot in which the cue ball comes back into the object ball (two collisions) is not what they
    describe, and is left out."""
    env = _env()
    env.reset(seed=seed)
    u = env.unwrapped
    state = u.table_state
    cands = candidate_slots(state, 7, (0.5, 5.0))
    rows = offset_rows(state, cands, (0.0,))
    thr = thresholds(state, rows, 5.0)
    cases = []  # (angle, speed, what to check)
    for k, s in enumerate(cands.slots):
        if not np.isfinite(rows[k, 0]):
            continue
        angle = math.atan2(rows[k, 1] - u.balls.pos[0, 1], rows[k, 0] - u.balls.pos[0, 0])
        pot, scratch = thr[k]
        cases += [(angle, 0.97 * pot, ("obj stays", None))]
        if 1.03 * pot < 0.97 * scratch:
            cases += [(angle, 1.03 * pot, ("obj drops", s.pocket))]
        if np.isfinite(scratch):
            cases += [(angle, 0.97 * scratch, ("cue stays", None)), (angle, 1.03 * scratch, ("cue drops", None))]
    cases = [c for c in cases if 0.05 < c[1] < 12.0]
    assert len(cases) >= 3
    res = run_shots(u.simulator, u.balls, np.array([c[0] for c in cases]), np.array([c[1] for c in cases]),
                    events=True)
    single = [sum(e["kind"] == "collision" for e in res.events.row(k).as_dicts(u.balls.ids)) == 1
              for k in range(len(cases))]
    assert sum(single) >= 2
    for (angle, v, (what, pocket)), obj, cue, one in zip(cases, res.pocket[:, 1], res.pocket[:, 0], single):
        if not one:
            continue
        if what == "obj stays":
            assert obj < 0 or cue >= 0, (what, v)  # (or the cue ball dropped first and ended the shot's count)
        elif what == "obj drops":
            assert obj == pocket, (what, v)
        elif what == "cue stays":
            assert cue < 0, (what, v)
        else:
            assert cue >= 0, (what, v)


def test_the_offset_moves_the_object_ball_across_its_window():
    env = _env()
    env.reset(seed=100_001)
    u = env.unwrapped
    state = u.table_state
    slot = candidate_slots(state, 7, (0.5, 5.0)).slots[0]
    at = u.action_type
    assert [offset_of(a) for a in (-1.0, -0.61, -0.59, 0.0, 0.19, 0.21, 1.0)] == [-1.0, -1.0, -0.5, 0.0, 0.0, 0.5, 1.0]
    for m, off in enumerate(OFFSETS):
        g = offset_ghost(state, slot, off)
        assert g is not None
        assert g[2] == pytest.approx(slot.obj_angle + off * 0.8 * slot.half)
        action = np.array([0.5 / 7, 0.0, 2.0 * (m + 0.5) / len(OFFSETS) - 1.0], np.float32)
        shot = at.shot(state, action)
        back = at.action(state, shot.angle, shot.speed)
        assert back[0] == pytest.approx(action[0]) and back[2] == pytest.approx(action[2])
        assert back[1] == pytest.approx(0.0, abs=1e-5)


def test_the_observation_and_its_layout():
    env = _env()
    obs, _ = env.reset(seed=3)
    n = 7
    assert env.observation_space.contains(obs)
    assert obs.shape == (6 + 12 * n + PATH_FEATURES * n,)
    assert env.action_space.shape == (3,)
    path = obs[6 + 12 * n:].reshape(n, PATH_FEATURES)
    has = obs[6:6 + 12 * n].reshape(n, 12)[:, 0]
    assert PATH_FEATURES == 2 * len(OFFSETS) + 1
    for k in range(n - 1):
        if has[k]:
            assert np.all(path[k, 0:-1:2] <= 1.0) and path[k, -1] <= 1.0  # pot_at, top
        else:
            assert np.all(path[k] == 0.0)
    obs2, r, term, trunc, info = env.step(env.action_space.sample())
    assert term and env.observation_space.contains(obs2)
