"""The ``candidates`` slots as arrays (players/slots.py) and the lists the env builds on them (envs/candidates.py)
equal the Python they replaced (benchmarks/reference_players.py), bit for bit, on the tables of seeded 9-ball and 8-ball games:
the pot slots from where the cue ball lies and in hand, the kicks worth simulating, the kick chosen by simulation and
the next-shot ease."""
from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401  (registers the ids)
from billiards_env.envs import candidates as envc
from benchmarks import reference_players as ref
from billiards_env.players import make_player
from billiards_env.players.geometry import (COL_CLEAR_OBJ, COL_D_OBJ, COL_OBJ_ANGLE, COL_POCKET, COL_SCORE,
                                            COL_TARGET, COL_WINDOW, table_model)
from billiards_env.players.slots import in_hand_slots, kick_candidates, next_shot_ease, shot_slots


def _fields(slot) -> tuple:
    return (slot.target, slot.pocket, slot.obj_angle, slot.half, slot.d_obj, slot.clear_obj, slot.shot)


def _same(a, b) -> bool:
    """Slots equal field for field (NaN equal to NaN: a kick's object angle)."""
    return all((x != x and y != y) or x == y for x, y in zip(_fields(a), _fields(b)))


@pytest.mark.parametrize("env_id, seeds", [("Billiards9Ball-v0", range(0, 4)), ("Billiards8Ball-v0", range(10, 13))])
def test_slots_as_arrays_equal_the_python_lists(env_id, seeds):
    env = gym.make(env_id)
    geo = make_player("geometric")
    rng = np.random.default_rng(seeds.start)
    env.action_space.seed(seeds.start)
    checked = kicks = chosen_kicks = 0
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
            expected = ref.reference_shot_slots(u.state, targets, speed_range)
            assert [(int(r[COL_TARGET]), int(r[COL_POCKET]), r[COL_OBJ_ANGLE], r[COL_WINDOW], r[COL_D_OBJ],
                     bool(r[COL_CLEAR_OBJ]), r[COL_SCORE]) for r in rows] == \
                [(s.target, s.pocket, s.obj_angle, s.half, s.d_obj, s.clear_obj, s.shot.score) for s in expected]
            hand = in_hand_slots(*arrays, tg, *tm)
            assert [(int(r[0]), int(r[1]), r[2], r[3], r[4], bool(r[5])) for r in hand] == \
                [(s.target, s.pocket, s.obj_angle, s.half, s.d_obj, s.clear_obj)
                 for s in ref.reference_in_hand_slots(u.state, targets)]
            kick = kick_candidates(*arrays, tg, *tm, *speed_range, envc.KICK_ARRIVAL, envc.KICK_MARGIN)
            assert [(r[0], int(r[1]), r[2], r[3]) for r in kick] == \
                ref.reference_kick_candidates(u.state, targets, speed_range)
            kicks += len(kick)
            # The env's lists (the kick verified lazily, shortest first) equal the Python (all kicks in one batch).
            for n in (1, 4, 6):
                got = envc.candidate_slots(u.state, n, speed_range)
                want_slots, want_kick = ref.reference_candidate_slots(u.state, n, speed_range)
                assert len(got.slots) == len(want_slots) and all(map(_same, got.slots, want_slots))
                assert (got.kick is None) == (want_kick is None)
                if got.kick is not None:
                    assert _same(got.kick, want_kick)
                    chosen_kicks += 1
            assert envc.next_shot_ease(u.state, u.config.candidate_slots) == \
                ref.reference_next_shot_ease(u.state, u.config.candidate_slots)
            view = u.state.view
            if view.place_area is None and not view.break_shot:
                sigma = max(u.config.angle_noise, envc.EASE_SPREAD)
                assert next_shot_ease(*arrays, b.mass, tg, *tm, *speed_range, sigma) == \
                    ref.reference_next_shot_ease(u.state, u.config.candidate_slots)
            checked += 1
            action = env.action_space.sample() if rng.random() < 0.3 else geo.act(env, obs)
            obs, _, term, trunc, _ = env.step(action)
            if term or trunc:
                break
    assert checked >= 2 * len(seeds) and kicks > 0


def _blocked_tables(n: int, seed: int = 3, **kw):
    """9-ball tables with the 1 hidden behind the 2 (every pot blocked), the other balls at random: the env at each."""
    from billiards_env.physics.layout import place_random

    env = gym.make("Billiards9Ball-v0", opponent=None, **kw)
    u = env.unwrapped
    rng = np.random.default_rng(seed)
    t = u.table
    r = u.config.ball_radius
    region = (r + 0.01, t.length - 2 * r - 0.02, r + 0.01, t.width - 2 * r - 0.02)
    for _ in range(n):
        pos = np.zeros((10, 2))
        place_random(rng, pos, [0, 1], [region] * 2, [], t.pocket_xy, 0.08, 0.5)
        pos[2] = 0.5 * (pos[0] + pos[1])
        place_random(rng, pos, range(3, 10), [region] * 7, pos[:3], t.pocket_xy, 0.08, 2 * r + 0.002)
        env.reset(seed=0, options={"positions": pos})
        yield u


def _check_kick(u) -> bool:
    """The env's slots and kick equal the Python's on the table now; whether there is a kick."""
    got = envc.candidate_slots(u.state, 4)
    want_slots, want_kick = ref.reference_candidate_slots(u.state, 4)
    assert len(got.slots) == len(want_slots) and all(map(_same, got.slots, want_slots))
    assert (got.kick is None) == (want_kick is None)
    if got.kick is not None:
        assert _same(got.kick, want_kick)
    return got.kick is not None


@pytest.mark.parametrize("friction", ["rolling", "spin"])
def test_kicks_chosen_by_simulation_equal_the_python_on_blocked_tables(friction):
    """The env's kick (envs/candidates.py ``kick_of``: its candidates simulated shortest first in compiled code,
    stopping at the first that hits) is the Python's (every candidate simulated in one batch by ``run_shots``, the
    first that hits kept)."""
    chosen = sum(_check_kick(u) for u in _blocked_tables(40, friction=friction))
    assert chosen >= 10
