"""The position map of the ``candidates_position`` observation type
(:class:`billiards_env.envs.observations.CuePositionFeatures`): for every pot slot of the ``candidates`` types, on a
small grid of the action's own ``power`` and ``top`` values, where the cue ball comes to rest, whether it scratches
on the way, whether the ball drops, and how easy the next shot is from there.

A pool player (and the search player the 9-ball agent is distilled from) chooses among the pots by the position each
one leaves; the ``candidates`` observation does not say where the cue ball goes. Here every grid point is the
closed form of :func:`billiards_env.physics.cue_rest.cue_rest` (no simulation) and the next shot's ease is the
search player's own position term (:func:`billiards_env.players.geometry.places_ease`: the easiest ghost-ball shot's
chance from the rest point, blocked paths cut down) at the *next* legal balls: the legal balls other than the one
potted, or, when it was the only one, the lowest-numbered ball left (the 9-ball rotation rule; in 8-ball after the
group's last ball this reads the lowest ball left, not the 8); a shot that clears the table reads ease 1.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from numba import njit

from billiards_env.physics.aim import ghost_point
from billiards_env.physics.cue_rest import MAX_BOUNCES, cue_rest
from billiards_env.physics.plain import plain
from billiards_env.players.geometry import (COL_D_OBJ, COL_OBJ_ANGLE, COL_SPEED, COL_TARGET, MAX_CUT, places_ease,
                                            state_model)

from .candidates import EASE_SPREAD, _numbers, _targets

if TYPE_CHECKING:  # pragma: no cover
    from billiards_env.table_state import TableState

#: The ``power`` values (a[1] of the ``candidates`` actions: the slot's own speed times
#: ``candidate_speed_factor ** a``, clipped to the speed range) of the grid: at the default factor 3, the slot's own
#: speed and 1.6, 2.5 and 3 times it (the search player's speed factors, where its labels lie).
POWERS = (0.0, 0.43, 0.83, 1.0)
#: The ``top`` values (a[3]; side 0: a tip offset of ``top * max_tip_offset`` R, draw below 0) of the grid: draw,
#: none, follow (the search player's tip offsets at the default ``max_tip_offset``).
TOPS = (-0.7, 0.0, 0.7)
#: Values per grid point: the ball drops, the cue ball scratches, its rest x / length, y / width, the next ease.
POINT_VALUES = 5
#: Values per slot appended by the ``candidates_position`` observation (power-major: ``POWERS[i], TOPS[j]`` at
#: ``POINT_VALUES * (i * len(TOPS) + j)``).
POSITION_FEATURES = POINT_VALUES * len(POWERS) * len(TOPS)
_POWERS = np.asarray(POWERS)
_TOPS = np.asarray(TOPS)


@njit(cache=True)
def rest_grid(cx: float, cy: float, rows: np.ndarray, opos: np.ndarray, contact: np.ndarray, lo: float, hi: float,
              log_factor: float, max_tip: float, powers: np.ndarray, tops: np.ndarray, rc: float, mc: float, mo: float,
              length: float, width: float, e_cushion: float, e_ball: float, pocket_xy: np.ndarray,
              pocket_r: np.ndarray, law: int, a: float, k: float, v_min: float, params: np.ndarray) -> np.ndarray:
    """For each pot row of ``rows`` (shot rows of :mod:`billiards_env.players.geometry`; ``opos``: its target's
    position, ``contact``: the cue ball's and the target's radii summed) and each grid point: ``(pots, pocket, x,
    y)`` of :func:`~billiards_env.physics.cue_rest.cue_rest` at the row's speed times ``exp(power * log_factor)``
    (clipped to ``[lo, hi]``, as the ``candidates`` action plays it) and tip offset ``top * max_tip``:
    ``(N, len(powers) * len(tops), 4)``."""
    n_t = tops.shape[0]
    out = np.zeros((rows.shape[0], powers.shape[0] * n_t, 4))
    for i in range(rows.shape[0]):
        r = rows[i]
        gx, gy = ghost_point(opos[i, 0], opos[i, 1], r[COL_OBJ_ANGLE], contact[i])
        for p in range(powers.shape[0]):
            speed = min(max(r[COL_SPEED] * math.exp(powers[p] * log_factor), lo), hi)
            for t in range(n_t):
                x, y, pocket, pots = cue_rest(cx, cy, gx, gy, r[COL_OBJ_ANGLE], r[COL_D_OBJ], speed,
                                              tops[t] * max_tip, rc, mc, mo, length, width, e_cushion, e_ball,
                                              pocket_xy, pocket_r, law, a, k, v_min, params, plain(MAX_BOUNCES))
                o = out[i, p * n_t + t]
                o[0] = 1.0 if pots else 0.0
                o[1] = pocket
                o[2] = x
                o[3] = y
    return out


@njit(cache=True)
def next_rows(targets: np.ndarray, numbers: np.ndarray, on: np.ndarray, target: int) -> np.ndarray:
    """The legal balls after ``target`` drops (see the module docstring): the legal balls ``targets`` other than it,
    else the lowest-numbered ball left on the table (rows, int64; empty when none is left)."""
    n = 0
    for t in targets:
        if t != target:
            n += 1
    if n:
        out = np.empty(n, np.int64)
        n = 0
        for t in targets:
            if t != target:
                out[n] = t
                n += 1
        return out
    best = -1
    for i in range(1, on.shape[0]):
        if on[i] and i != target and (best < 0 or numbers[i] < numbers[best]):
            best = i
    if best < 0:
        return np.empty(0, np.int64)
    out = np.empty(1, np.int64)
    out[0] = best
    return out


def next_targets(state: "TableState", target: int) -> np.ndarray:
    """:func:`next_rows` of a table state."""
    return next_rows(_targets(state), _numbers(state), state.balls.on_table, int(target))


@njit(cache=True)
def _position_map(grid: np.ndarray, rows: np.ndarray, pos: np.ndarray, on: np.ndarray, radius: np.ndarray,
                  targets: np.ndarray, numbers: np.ndarray, length: float, width: float, pocket_xy: np.ndarray,
                  pocket_r: np.ndarray, params: np.ndarray, sigma: float, n_slots: int) -> np.ndarray:
    """The observation's values (see :func:`position_features`) of :func:`rest_grid`'s ``grid``."""
    g = grid.shape[1]
    out = np.zeros((n_slots, g * POINT_VALUES), np.float32)
    on2 = on.copy()
    places = np.empty((g, 2))
    for i in range(min(rows.shape[0], n_slots)):
        j = int(rows[i, COL_TARGET])
        nxt = next_rows(targets, numbers, on, j)
        for b in range(on.shape[0]):  # (element by element: no shape check and its message compiled)
            on2[b] = on[b]
        on2[j] = False
        for q in range(g):
            places[q, 0] = grid[i, q, 2]
            places[q, 1] = grid[i, q, 3]
        if nxt.shape[0]:
            ease = places_ease(places, pos, on2, radius, plain(0), nxt, pocket_xy, pocket_r, params, sigma, MAX_CUT)
        else:
            ease = np.ones(g)  # the pot clears the table
        for q in range(g):
            o = q * POINT_VALUES
            scratch = grid[i, q, 1] >= 0.0
            out[i, o] = grid[i, q, 0]
            out[i, o + 1] = 1.0 if scratch else 0.0
            out[i, o + 2] = min(max(grid[i, q, 2] / length, 0.0), 1.0)
            out[i, o + 3] = min(max(grid[i, q, 3] / width, 0.0), 1.0)
            out[i, o + 4] = 0.0 if scratch else ease[q]
    return out


def position_features(state: "TableState", cands: object, n_slots: int, speed_range: tuple[float, float],
                      log_factor: float, max_tip: float) -> np.ndarray:
    """``(n_slots, POSITION_FEATURES)`` float32: per pot slot of ``cands`` (the cue ball where it lies) and grid
    point, ``POINT_VALUES`` values: ``1`` if the ball reaches its pocket else 0; ``1`` if the cue ball runs into a
    pocket else 0; its rest x / length and y / width (a scratch: where it enters the pocket); the next shot's ease
    from there (0 after a scratch, 1 when the pot clears the table). Slots without a shot from where the cue ball
    lies (ball in hand, the break, the kick, empty) read 0. Two compiled calls."""
    rows = getattr(cands, "rows", None)
    if rows is None or cands.in_hand or cands.break_shot or rows.shape[0] == 0:
        return np.zeros((n_slots, POSITION_FEATURES), np.float32)
    b = state.balls
    t = state.table
    ph = state.physics
    law, acc, kk = ph.path_args
    sim = state.simulator
    targets = rows[:, COL_TARGET].astype(np.int64)
    contact = b.radius[0] + b.radius[targets]
    mo = float(b.mass[1]) if len(b.mass) > 1 else float(b.mass[0])
    grid = rest_grid(float(b.pos[0, 0]), float(b.pos[0, 1]), rows, b.pos[targets], contact, float(speed_range[0]),
                     float(speed_range[1]), float(log_factor), float(max_tip), _POWERS, _TOPS, float(b.radius[0]),
                     float(b.mass[0]), mo, float(t.length), float(t.width), float(t.cushion_restitution),
                     float(ph.ball_restitution), sim.pocket_xy, sim.pocket_r, int(law), float(acc), float(kk),
                     float(ph.min_speed), sim.params)
    tm = state_model(state)
    sigma = max(float(state.settings.angle_noise), EASE_SPREAD)
    return _position_map(grid, rows, b.pos, b.on_table, b.radius, _targets(state), _numbers(state), float(t.length),
                         float(t.width), tm.pocket_xy, tm.pocket_r, tm.params, sigma, int(n_slots))


__all__ = ["POWERS", "TOPS", "POINT_VALUES", "POSITION_FEATURES", "rest_grid", "next_rows", "next_targets",
           "position_features"]
