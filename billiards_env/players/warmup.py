"""Compile (or load from numba's cache) the players' kernels once: :func:`warm_up`.

A cold numba cache compiles them in about half a minute (the geometric decision's call tree, the slots, the search's
position terms); with this run at set-up, a user's first decision loads compiled code.
"""
from __future__ import annotations

import time

import numpy as np


def warm_up() -> float:
    """One call of every compiled player function with the argument types the players and envs pass; returns the
    seconds it took."""
    from billiards_env.physics import Balls, Physics, Simulator, Table
    from billiards_env.physics.batch import run_shots

    from . import search, slots
    from .geometry import geometric_decision, table_model

    start = time.perf_counter()
    table, physics = Table(), Physics()
    balls = Balls.from_positions([[0.6, 0.6], [1.9, 0.9], [1.2, 0.3], [2.2, 1.1]])
    tm = table_model(table, physics)
    targets = np.array([1, 2, 3], dtype=np.int64)
    arrays = (balls.pos, balls.on_table, balls.radius, balls.mass)
    area = (balls.radius[0], table.length / 4, balls.radius[0], table.width - balls.radius[0])
    for place_area, is_break in ((None, False), (area, False), (area, True)):
        geometric_decision(*arrays, targets, tm, (0.5, 5.0), place_area, is_break)
    slots.shot_slots(*arrays, targets, *tm, 0.5, 5.0)
    slots.in_hand_slots(balls.pos, balls.on_table, balls.radius, targets, *tm)
    slots.kick_candidates(balls.pos, balls.on_table, balls.radius, targets, *tm, 0.5, 5.0, 0.8, 1.15)
    slots.next_shot_ease(*arrays, targets, *tm, 0.5, 5.0, 0.002)
    res = run_shots(Simulator(table, physics), balls, np.array([0.1, 1.0]), np.array([2.0, 3.0]), validate=False)
    numbers = np.arange(len(balls), dtype=np.int64)
    for detail in (True, False):
        keys, masks, _ = search.shot_keys(res.first_contact, res.rail_after_contact, res.pocket, res.pocketed_at,
                                          numbers, 0, detail)
    _judge_rows(keys, masks)
    search.next_shot_ease(table, balls.radius, res.pos, res.on_table, 0, [[1, 2], [3]], 0.002)
    from .geometry import places_ease, search_places

    places, _ = search_places(balls.pos, balls.on_table, balls.radius, 0, targets, *tm, np.asarray(area),
                              np.array([0.25, 0.5]), np.array([0.0, 0.4]))
    places_ease(places, balls.pos, balls.on_table, balls.radius, 0, targets, *tm, 0.002, 1.39)
    return time.perf_counter() - start


def _judge_rows(keys: np.ndarray, masks: np.ndarray) -> None:
    """The search's compiled 9-ball and 8-ball verdicts (:func:`~.search.judge_rows`) on outcome keys."""
    from billiards_env.rules import NineBall
    from billiards_env.rules import pool_judge as pj

    from .search import judge_rows

    rules = NineBall()
    state, options = np.zeros(1, pj.GAME_STATE_ROW), np.zeros(1, pj.RULE_OPTIONS)
    state[0], options[0] = pj.state_row(rules.initial_state(0, on_table=(1, 2, 3))), pj.options_row(rules)
    n, b = len(keys), (keys.shape[1] - 4) // 2
    judge_rows(np.ascontiguousarray(keys), masks, np.arange(n, dtype=np.int64), state, options,
               np.arange(b, dtype=np.int64), np.zeros(1, pj.CALL_ROW), np.zeros(1, pj.GAME_STATE_ROW), np.empty(n),
               np.empty(n, np.int64), np.empty(n, np.int64), np.empty((n, b), np.int64))


__all__ = ["warm_up"]
