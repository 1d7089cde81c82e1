"""The candidate shots of the ``candidates`` action and observation types, as arrays (compiled, one call each).

The geometric parts of :mod:`billiards_env.envs.candidates` (the pot slots from where the cue ball lies and in hand,
the kicks worth simulating, the next shot's ease) on plain arrays, for a caller holding the table state (balls as
arrays, a :class:`~billiards_env.players.geometry.TableModel`, the legal ``targets`` in the view's order): the same
lists in the same order, bit for bit, as the Python they replaced (``benchmarks/reference_players.py``:
``reference_shot_slots``, ``reference_in_hand_slots``, ``reference_kick_candidates``, ``reference_next_shot_ease``;
tests/players/test_slots.py). The cue ball is row 0. Verifying the kicks by simulation stays a
:func:`billiards_env.physics.batch.run_shots` call of the caller (``envs/candidates.py``).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from billiards_env.physics.aim import segment_blocked_by
from billiards_env.physics.motion import launch_speed
from billiards_env.physics.plain import plain
from billiards_env.physics.pocket_specs import N_RAILS
from billiards_env.physics.walls import on_rail_span

from .geometry import (ARRIVE_SPEED, COL_CUT, COL_SCORE, FALLBACK_CUT, MAX_CUT, N_COLS, SPEED_FACTORS, WIN_ANGLE,
                       WIN_DIST, WIN_FOUND, WIN_HALF, ghost_shots_windowed, model, pot_chance, windows_of)
from billiards_env.physics.kernel_logs import leaf_public

#: Columns of an in-hand slot row: target, pocket, object-ball direction, window half-width, distance to the
#: capture circle, the object ball's path clear (1.0 / 0.0).
HAND_TARGET, HAND_POCKET, HAND_OBJ_ANGLE, HAND_HALF, HAND_D_OBJ, HAND_CLEAR = range(6)
#: Columns of a kick row: path length, target, cue direction, speed.
KICK_LENGTH, KICK_TARGET, KICK_ANGLE, KICK_SPEED = range(4)


@njit(cache=True)
def shot_slots(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray, targets: np.ndarray,
               pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """The pot slots with the cue ball where it lies: every ghost-ball shot at a legal ball (``targets``) with a
    cut up to 80 degrees, easiest first, or up to 88 degrees when there is none: rows of
    :data:`billiards_env.players.geometry.N_COLS` columns; a slot's ``clear_obj`` is
    ``COL_CLEAR_OBJ``. A (ball, pocket) window is worked out only for a shot whose cut can be played
    (:func:`~billiards_env.players.geometry.ghost_shots_windowed`: the same rows as with every window)."""
    tm = model(pocket_xy, pocket_r, params)
    rows = ghost_shots_windowed(pos[0, 0], pos[0, 1], pos, on, radius, mass, plain(0), targets, tm, lo, hi,
                                FALLBACK_CUT, ARRIVE_SPEED, np.array(SPEED_FACTORS), plain(True))
    keep = rows[:, COL_CUT] <= MAX_CUT
    if keep.any():
        return rows[keep]
    return rows


@njit(cache=True)
def in_hand_slots(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, targets: np.ndarray, pocket_xy: np.ndarray,
                  pocket_r: np.ndarray, params: np.ndarray) -> np.ndarray:
    """The pot slots with the cue ball in hand: every (legal ball, pocket) with an entry window, widest window
    first, those whose path to the pocket is blocked (by a ball other than the cue ball) after the others (their
    width counted a tenth), ties in (ball, pocket) order: rows of
    ``HAND_*`` columns."""
    tm = model(pocket_xy, pocket_r, params)
    windows = windows_of(pos, radius, targets, tm)
    k_p = pocket_r.shape[0]
    out = np.empty((targets.shape[0] * k_p, 6))
    key = np.empty(targets.shape[0] * k_p)
    n = 0
    for t in range(targets.shape[0]):
        j = targets[t]
        for p in range(k_p):
            w = windows[t, p]
            if w[WIN_FOUND] == 0.0:
                continue
            ox = pos[j, 0]
            oy = pos[j, 1]
            d = w[WIN_DIST]
            clear = not segment_blocked_by(ox, oy, ox + math.cos(w[WIN_ANGLE]) * d, oy + math.sin(w[WIN_ANGLE]) * d,
                                           pos, on, radius, plain(0), j, radius[j])
            out[n, HAND_TARGET] = j
            out[n, HAND_POCKET] = p
            out[n, HAND_OBJ_ANGLE] = w[WIN_ANGLE]
            out[n, HAND_HALF] = w[WIN_HALF]
            out[n, HAND_D_OBJ] = d
            out[n, HAND_CLEAR] = 1.0 if clear else 0.0
            key[n] = -(w[WIN_HALF] * (1.0 if clear else 0.1))
            n += 1
    order = np.argsort(key[:n], kind="mergesort")
    return out[:n][order]


@njit(cache=True)
def _kick_before(a: np.ndarray, b: np.ndarray) -> bool:
    """Tuple order of kick rows (length, target, angle, speed), as Python sorts ``(d, j, angle, speed)``."""
    for c in range(4):
        if a[c] < b[c]:
            return True
        if a[c] > b[c]:
            return False
    return False


@njit(cache=True)
def kick_candidates(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, targets: np.ndarray, pocket_xy: np.ndarray,
                    pocket_r: np.ndarray, params: np.ndarray, lo: float, hi: float, arrival: float,
                    margin: float) -> np.ndarray:
    """The one-rail kicks at the legal balls worth simulating, shortest first: for each legal ball and cushion, the
    point on the cushion line from
    which the cue ball's path, its normal component scaled by the cushion's restitution, runs into the ball full
    (``kick_points``); dropped if it lies outside the cushion's span, passes within two ball radii of a pocket's
    capture circle, or either leg is blocked. Rows of ``KICK_*`` columns: the path length, the target, the cue
    direction, and the speed that would still roll at ``arrival`` over the path, times ``margin``, within
    ``[lo, hi]``; sorted as tuples."""
    tm = model(pocket_xy, pocket_r, params)
    rc = radius[0]
    cx = pos[0, 0]
    cy = pos[0, 1]
    e = tm.cushion_e
    out = np.empty((targets.shape[0] * 4, 4))
    n = 0
    for t in range(targets.shape[0]):
        j = targets[t]
        tx = pos[j, 0]
        ty = pos[j, 1]
        for k in range(4):
            w = (rc, tm.length - rc, rc, tm.width - rc)[k]
            if k < 2:  # vertical cushion x = w: (tx - w)(py - cy) = -e (w - cx)(ty - py)
                den = (tx - w) - e * (w - cx)
                if abs(den) < 1e-12 or (w - cx) * (w - tx) <= 0.0:
                    continue
                px = w
                py = ((tx - w) * cy - e * (w - cx) * ty) / den
                if not (rc < py < tm.width - rc):
                    continue
            else:
                den = (ty - w) - e * (w - cy)
                if abs(den) < 1e-12 or (w - cy) * (w - ty) <= 0.0:
                    continue
                px = ((ty - w) * cx - e * (w - cy) * tx) / den
                py = w
                if not (rc < px < tm.length - rc):
                    continue
            # Near a pocket: within two ball radii of its capture circle, or on a jaw table off the rails' spans
            # (in a mouth, or nearer than two ball radii to where a rail ends).
            near_pocket = tm.segs.shape[0] > 0 and not on_rail_span(px, py, rc, tm.segs, N_RAILS, 2.0 * rc)
            for q in range(tm.pocket_r.shape[0]):
                if math.hypot(tm.pocket_xy[q, 0] - px, tm.pocket_xy[q, 1] - py) < tm.pocket_r[q] + 2.0 * rc:
                    near_pocket = True
                    break
            if near_pocket:
                continue
            if segment_blocked_by(cx, cy, px, py, pos, on, radius, plain(0), j, rc) or \
                    segment_blocked_by(px, py, tx, ty, pos, on, radius, plain(0), j, rc):
                continue
            d = math.hypot(px - cx, py - cy) + math.hypot(tx - px, ty - py)
            v = margin * launch_speed(d, arrival, tm.law, tm.decel, tm.k)
            row = out[n]
            row[KICK_LENGTH] = d
            row[KICK_TARGET] = j
            row[KICK_ANGLE] = math.atan2(py - cy, px - cx)
            row[KICK_SPEED] = min(max(v, lo), hi)
            i = n  # insertion in tuple order
            while i > 0 and _kick_before(row, out[i - 1]):
                i -= 1
            if i < n:
                keep = row.copy()
                for m in range(n, i, -1):
                    out[m] = out[m - 1]
                out[i] = keep
            n += 1
    return out[:n]


@leaf_public
def next_shot_ease(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray, targets: np.ndarray,
                   pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray, lo: float, hi: float,
                   sigma: float) -> float:
    """The chance of potting the easiest shot from where the cue ball lies: the best pot slot's score
    (:func:`shot_slots`) through :func:`~billiards_env.players.geometry.pot_chance` with spread ``sigma``; 0 when no
    pot exists (the caller, ``envs/candidates.py`` ``next_shot_ease``, passes ``sigma = max(angle_noise,
    EASE_SPREAD)`` and answers 0 itself for ball in hand and the break)."""
    rows = shot_slots(pos, on, radius, mass, targets, pocket_xy, pocket_r, params, lo, hi)
    best = rows[0, COL_SCORE] if rows.shape[0] else 0.0
    return pot_chance(best, sigma)


__all__ = ["shot_slots", "in_hand_slots", "kick_candidates", "next_shot_ease", "N_COLS", "HAND_TARGET",
           "HAND_POCKET", "HAND_OBJ_ANGLE", "HAND_HALF", "HAND_D_OBJ", "HAND_CLEAR", "KICK_LENGTH", "KICK_TARGET",
           "KICK_ANGLE", "KICK_SPEED"]
