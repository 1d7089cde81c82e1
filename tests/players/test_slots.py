"""The ``candidates`` slots as arrays (players/slots.py) and the lists the env builds on them (envs/candidates.py)
equal the Python they replaced (benchmarks/reference_players.py, through its recorded results: the ``golden``
fixture), bit for bit, on the tables of seeded 9-ball and 8-ball games:
the pot slots from where the cue ball lies and in hand, the kicks worth simulating, the kick chosen by simulation and
the next-shot ease."""
from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401  (registers the ids)
from billiards_env.envs import candidates as envc
from billiards_env.players import make_player
from billiards_env.players.geometry import (COL_CLEAR_OBJ, COL_D_OBJ, COL_OBJ_ANGLE, COL_POCKET, COL_SCORE,
                                            COL_TARGET, COL_WINDOW, table_model)
from billiards_env.players.slots import in_hand_slots, kick_candidates, next_shot_ease, shot_slots
from golden import reference_players


def _fields(slot) -> tuple:
    return (slot.target, slot.pocket, slot.obj_angle, slot.half, slot.d_obj, slot.clear_obj, slot.shot)


def _slot_lists(slots) -> list[tuple]:
    return [_fields(s) for s in slots]


def _same_lists(a, b) -> bool:
    """Slot lists equal field for field (NaN equal to NaN: a kick's object angle)."""
    return len(a) == len(b) and all((x != x and y != y) or x == y for u, v in zip(a, b) for x, y in zip(u, v))


@pytest.mark.parametrize("env_id, seeds", [("Billiards9Ball-v0", range(0, 4)), ("Billiards8Ball-v0", range(10, 13))])
def test_slots_as_arrays_equal_the_python_lists(env_id, seeds, golden):
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
            targets = tuple(u.table_state.view.targets)
            speed_range = (float(u.config.speed_min), float(u.config.speed_max))
            tm = table_model(u.table, u.physics)
            arrays = (b.pos, b.on_table, b.radius)
            tg = np.array(targets, dtype=np.int64)
            rows = shot_slots(*arrays, b.mass, tg, *tm, *speed_range)
            golden.check([(int(r[COL_TARGET]), int(r[COL_POCKET]), r[COL_OBJ_ANGLE], r[COL_WINDOW], r[COL_D_OBJ],
                           bool(r[COL_CLEAR_OBJ]), r[COL_SCORE]) for r in rows],
                         lambda: [(s.target, s.pocket, s.obj_angle, s.half, s.d_obj, s.clear_obj, s.shot.score)
                                  for s in reference_players().reference_shot_slots(u.table_state, targets, speed_range)])
            hand = in_hand_slots(*arrays, tg, *tm)
            golden.check([(int(r[0]), int(r[1]), r[2], r[3], r[4], bool(r[5])) for r in hand],
                         lambda: [(s.target, s.pocket, s.obj_angle, s.half, s.d_obj, s.clear_obj)
                                  for s in reference_players().reference_in_hand_slots(u.table_state, targets)])
            kick = kick_candidates(*arrays, tg, *tm, *speed_range, envc.KICK_ARRIVAL, envc.KICK_MARGIN)
            golden.check([(r[0], int(r[1]), r[2], r[3]) for r in kick],
                         lambda: reference_players().reference_kick_candidates(u.table_state, targets, speed_range))
            kicks += len(kick)
            # The env's lists (the kick verified lazily, shortest first) equal the Python (all kicks in one batch).
            for n in (1, 4, 6):
                got = envc.candidate_slots(u.table_state, n, speed_range)

                def want(n=n):
                    slots, kick = reference_players().reference_candidate_slots(u.table_state, n, speed_range)
                    return _slot_lists(slots), None if kick is None else _fields(kick)

                golden.check((_slot_lists(got.slots), None if got.kick is None else _fields(got.kick)), want,
                             same=lambda a, b: _same_lists(a[0], b[0]) and (a[1] is None) == (b[1] is None)
                             and (a[1] is None or _same_lists([a[1]], [b[1]])))
                chosen_kicks += got.kick is not None
            ease = envc.next_shot_ease(u.table_state, u.config.candidate_slots)
            golden.check(ease, lambda: reference_players().reference_next_shot_ease(u.table_state, u.config.candidate_slots))
            view = u.table_state.view
            if view.place_area is None and not view.break_shot:
                sigma = max(u.config.angle_noise, envc.EASE_SPREAD)
                assert next_shot_ease(*arrays, b.mass, tg, *tm, *speed_range, sigma) == ease
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


def _check_kick(u, golden) -> bool:
    """The env's slots and kick equal the Python's on the table now; whether there is a kick."""
    got = envc.candidate_slots(u.table_state, 4)

    def want():
        slots, kick = reference_players().reference_candidate_slots(u.table_state, 4)
        return _slot_lists(slots), None if kick is None else _fields(kick)

    golden.check((_slot_lists(got.slots), None if got.kick is None else _fields(got.kick)), want,
                 same=lambda a, b: _same_lists(a[0], b[0]) and (a[1] is None) == (b[1] is None)
                 and (a[1] is None or _same_lists([a[1]], [b[1]])))
    return got.kick is not None


@pytest.mark.parametrize("friction", ["rolling", "spin"])
def test_kicks_chosen_by_simulation_equal_the_python_on_blocked_tables(friction, golden):
    """The env's kick (envs/candidates.py ``kick_of``: its candidates simulated shortest first in compiled code,
    stopping at the first that hits) is the Python's (every candidate simulated in one batch by ``run_shots``, the
    first that hits kept)."""
    chosen = sum(_check_kick(u, golden) for u in _blocked_tables(40, friction=friction))
    assert chosen >= 10
