"""The ``candidates`` slots as arrays (players/slots.py) equal envs/candidates.py's lists, bit for bit, on the tables
of seeded 9-ball and 8-ball games: the pot slots from where the cue ball lies and in hand, the kicks worth simulating
and the next-shot ease."""
from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401  (registers the ids)
from billiards_env.envs import candidates as envc
from billiards_env.physics.aim import aim_angle, segment_blocked
from billiards_env.physics.motion import launch_speed
from billiards_env.players import make_player
from billiards_env.players.geometry import (COL_CLEAR_OBJ, COL_D_OBJ, COL_OBJ_ANGLE, COL_POCKET, COL_SCORE,
                                            COL_TARGET, COL_WINDOW, table_model)
from billiards_env.players.slots import in_hand_slots, kick_candidates, next_shot_ease, shot_slots


def _python_kicks(env, targets, rng):
    """The candidate list of envs/candidates.py ``_kick_slots`` before its batch check (its loop, verbatim)."""
    b, t = env.balls, env.table
    rc = float(b.radius[0])
    cue = b.pos[0]
    cands = []
    for j in targets:
        others = [k for k in range(len(b.ids)) if b.on_table[k] and k not in (0, j)]
        opos, orad = b.pos[others], b.radius[others] + rc
        for _, p in envc.kick_points(cue, b.pos[j], t, rc, t.cushion_restitution):
            if np.any(np.hypot(*(t.pocket_xy - p).T) < t.pocket_radius + 2.0 * rc):
                continue
            if segment_blocked(cue, p, opos, orad) or segment_blocked(p, b.pos[j], opos, orad):
                continue
            d = float(np.hypot(*(p - cue))) + float(np.hypot(*(b.pos[j] - p)))
            v = envc.KICK_MARGIN * launch_speed(d, envc.KICK_ARRIVAL, *env.physics.path_args)
            cands.append((d, j, aim_angle(cue, p), min(max(v, rng[0]), rng[1])))
    cands.sort()
    return cands


@pytest.mark.parametrize("env_id, seeds", [("Billiards9Ball-v0", range(0, 4)), ("Billiards8Ball-v0", range(10, 13))])
def test_slots_as_arrays_equal_the_envs_lists(env_id, seeds):
    env = gym.make(env_id)
    geo = make_player("geometric")
    rng = np.random.default_rng(seeds.start)
    env.action_space.seed(seeds.start)
    checked = kicks = 0
    for seed in seeds:
        obs, _ = env.reset(seed=seed)
        for _ in range(12):
            u = env.unwrapped
            b = u.balls
            targets = tuple(u.state.view.targets)
            speed_range = (float(u.config.speed_min), float(u.config.speed_max))
            tm = table_model(u.table, u.physics)
            arrays = (b.pos, b.on_table, b.radius)
            tg = np.array(targets, dtype=np.int64)
            rows = shot_slots(*arrays, b.mass, tg, *tm, *speed_range)
            expected = envc._shot_slots(u.state, targets, speed_range)
            assert [(int(r[COL_TARGET]), int(r[COL_POCKET]), r[COL_OBJ_ANGLE], r[COL_WINDOW], r[COL_D_OBJ],
                     bool(r[COL_CLEAR_OBJ]), r[COL_SCORE]) for r in rows] == \
                [(s.target, s.pocket, s.obj_angle, s.half, s.d_obj, s.clear_obj, s.shot.score) for s in expected]
            hand = in_hand_slots(*arrays, tg, *tm)
            assert [(int(r[0]), int(r[1]), r[2], r[3], r[4], bool(r[5])) for r in hand] == \
                [(s.target, s.pocket, s.obj_angle, s.half, s.d_obj, s.clear_obj) for s in envc._in_hand_slots(u.state, targets)]
            kick = kick_candidates(*arrays, tg, *tm, *speed_range, envc.KICK_ARRIVAL, envc.KICK_MARGIN)
            assert [(r[0], int(r[1]), r[2], r[3]) for r in kick] == _python_kicks(u, targets, speed_range)
            kicks += len(kick)
            view = u.state.view
            if view.place_area is None and not view.break_shot:
                sigma = max(u.config.angle_noise, envc.EASE_SPREAD)
                assert next_shot_ease(*arrays, b.mass, tg, *tm, *speed_range, sigma) == \
                    envc.next_shot_ease(u.state, u.config.candidate_slots)
            checked += 1
            action = env.action_space.sample() if rng.random() < 0.3 else geo.act(env, obs)
            obs, _, term, trunc, _ = env.step(action)
            if term or trunc:
                break
    assert checked >= 2 * len(seeds) and kicks > 0
