"""The players' geometry, compiled: every ghost-ball shot of a table in one call, on plain arrays.

A decision of the geometric player (and the candidate lists of the ``candidates`` types, the search player's
candidates and position terms) needs, for every legal ball and pocket: the pocket's entry window, the ghost ball,
the cut, whether the paths are clear, the cue speed under the table's motion law, whether the cue ball would follow
into a pocket, and the shot's ease. These kernels compute them for a whole table in one compiled call (numba,
cached), on arrays: the balls ``pos`` (B, 2), ``on`` (B,), ``radius`` (B,), ``mass`` (B,), the legal ``targets``
(rows) and a :class:`TableModel` (the table and the motion law as plain values). Nothing here reads an env.

The formulas are :mod:`billiards_env.physics.aim`'s (windows, ghost ball, cut, clear paths, the collision, a lone
ball's path) and :mod:`billiards_env.physics.motion`'s (how fast, how far); this module holds the players' choices:
which shots, how hard, how they rank, where to put the cue ball. Each kernel reproduces the Python it replaced
(:func:`billiards_env.players.shots.ghost_ball_shots`, ``choose_placement``, ``GeometricPlayer.act``) choice for
choice: the same shots, the same floating-point operations in the same order (tests/players/test_geometry.py).

A shot is a row of :data:`N_COLS` floats (columns ``COL_*``), ranked easiest first.
"""
from __future__ import annotations

import math
import weakref
from typing import Any, NamedTuple

import numpy as np
from numba import njit

from billiards_env.physics.aim import (WINDOW_SAMPLES, collide_into, cos_between, dot2, ghost_point,
                                       lone_path_pocket_grouped, pocket_windows, segment_blocked_by,
                                       segment_touched_by, window_of)
from billiards_env.physics.kernel_io import wall_groups
from billiards_env.physics.layout import free_discs, nearest_free, py_hypot  # noqa: F401 (re-exported)
from billiards_env.physics.motion import launch_speed, speed_after_distance
from billiards_env.physics.plain import plain
from billiards_env.physics.kernel_logs import leaf_public

#: Columns of a shot row.
COL_TARGET, COL_POCKET, COL_ANGLE, COL_SPEED, COL_NEED, COL_OBJ_ANGLE, COL_CUT, COL_D_CUE, COL_D_OBJ, COL_WINDOW, \
    COL_TOL, COL_CLEAR, COL_REACH, COL_RISK, COL_SCORE, COL_CLEAR_OBJ = range(16)
N_COLS = 16
#: Columns of a window row (:func:`target_windows`): centre direction, half-width, distance, found (1.0 / 0.0).
WIN_ANGLE, WIN_HALF, WIN_DIST, WIN_FOUND = range(4)
#: ``WIN_FOUND`` of a window that a table's cache has not worked out yet (:func:`fill_window`).
WIN_UNKNOWN = -1.0

#: The geometric player's cut limits: the easiest shot up to ``MAX_CUT``, else up to ``FALLBACK_CUT``.
MAX_CUT = math.radians(80.0)
FALLBACK_CUT = math.radians(88.0)
#: Object-ball speed (m/s) a shot leaves at the pocket's capture circle, and the factors tried on it (in order)
#: until the cue ball does not follow into a pocket.
ARRIVE_SPEED = 0.35
SPEED_FACTORS = (1.0, 0.6, 0.3, 1.8, 3.0)
#: The speed of the fallback full-ball hit when there is no pot (clipped to the speed range).
DIRECT_HIT_SPEED = 2.0
#: Ball in hand: the cue ball is tried these distances (m) straight behind each ghost ball.
PLACE_BACKS = (0.25, 0.5)
#: Cushion bounces followed when checking whether the cue ball runs into a pocket.
SCRATCH_BOUNCES = 4


class Model(NamedTuple):
    """The table and the motion law as the compiled code reads them (built inside it by :func:`model`)."""

    length: float
    width: float
    cushion_e: float  #: cushion restitution
    pocket_xy: np.ndarray  #: (K, 2) capture-circle centres
    pocket_r: np.ndarray  #: (K,) capture radii
    law: int  #: the distance-domain motion law (:attr:`billiards_env.physics.Physics.path_args`)
    decel: float
    k: float
    v_min: float  #: the speed below which a ball stops
    ball_e: float  #: ball-ball restitution
    segs: np.ndarray  #: (S, 6) a jaw table's rails and jaw faces (:mod:`billiards_env.physics.walls`); (0, 6) if none
    tips: np.ndarray  #: (C, 3) its jaw tips; (0, 3) if none
    groups: np.ndarray  #: (G, 3) circles holding each pocket's jaw faces and tips (kernel_io.wall_groups); (0, 3)


#: Where a jaw table's walls start in a :class:`TableModel`'s ``params``: ``n_segs, n_tips``, then the segment rows
#: and the tip rows, flattened, then ``n_groups`` and the rows of the walls' groups (:func:`.kernel_io.wall_groups`).
WALLS_AT = 8


class TableModel(NamedTuple):
    """The table and the motion law as plain arrays, what the compiled functions take (:func:`table_model`):
    ``pocket_xy`` (K, 2), ``pocket_r`` (K,) and ``params`` = ``(length, width, cushion restitution, law, a, k,
    min speed, ball restitution)`` (``law, a, k``: :attr:`billiards_env.physics.Physics.path_args`), then a jaw
    table's walls (``n_segs, n_tips``, their rows, ``n_groups`` and the groups' circles; ``0, 0, 0`` on a capture
    table). Three arrays, so that a call
    costs no more than passing three arrays."""

    pocket_xy: np.ndarray
    pocket_r: np.ndarray
    params: np.ndarray


def table_model(table, physics) -> TableModel:
    """The :class:`TableModel` of a :class:`~billiards_env.physics.Table` and a
    :class:`~billiards_env.physics.Physics`."""
    law, a, k = physics.path_args
    segs, tips = table.walls()
    groups = wall_groups(segs, tips)
    params = np.concatenate([np.array([table.length, table.width, table.cushion_restitution, law, a, k,
                                       physics.min_speed, physics.ball_restitution, len(segs), len(tips)],
                                      dtype=np.float64), segs.ravel(), tips.ravel(),
                             np.array([len(groups)], dtype=np.float64), groups.ravel()])
    # Copies: writeable arrays (the table's are read-only), so every caller hits the same compiled signature.
    return TableModel(np.array(table.pocket_xy, dtype=np.float64), np.array(table.pocket_radius, dtype=np.float64),
                      params)


_MODELS: "weakref.WeakKeyDictionary[Any, tuple[Any, Any, TableModel]]" = weakref.WeakKeyDictionary()


def state_model(state: Any) -> TableModel:
    """The :class:`TableModel` of a table state (``state.table``, ``state.physics``), made once per state and kept
    while its table and physics stay the same objects: a decision on a table pays no conversion."""
    got = _MODELS.get(state)
    if got is None or got[0] is not state.table or got[1] is not state.physics:
        got = _MODELS[state] = (state.table, state.physics, table_model(state.table, state.physics))
    return got[2]


@njit(cache=True)
def model(pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray) -> Model:
    """The :class:`Model` of a :class:`TableModel`'s arrays."""
    n_segs = int(params[WALLS_AT]) if params.shape[0] > WALLS_AT else 0
    n_tips = int(params[WALLS_AT + 1]) if params.shape[0] > WALLS_AT else 0
    at = WALLS_AT + 2
    segs = params[at:at + 6 * n_segs].reshape((n_segs, 6))
    at += 6 * n_segs
    tips = params[at:at + 3 * n_tips].reshape((n_tips, 3))
    at += 3 * n_tips
    n_groups = int(params[at]) if params.shape[0] > at else 0
    groups = params[at + 1:at + 1 + 3 * n_groups].reshape((n_groups, 3))
    return Model(params[0], params[1], params[2], pocket_xy, pocket_r, int(params[3]), params[4], params[5],
                 params[6], params[7], segs, tips, groups)


# --- windows ----------------------------------------------------------------------------------------------------

@njit(cache=True)
def windows_of(pos: np.ndarray, radius: np.ndarray, targets: np.ndarray, tm: Model,
               samples: int = WINDOW_SAMPLES) -> np.ndarray:
    """The pocket windows of every target: ``(T, K, 4)`` rows ``(centre, half-width, distance, found)``
    (:func:`billiards_env.physics.aim.pocket_windows`)."""
    k_p = tm.pocket_r.shape[0]
    out = np.zeros((targets.shape[0], k_p, 4))
    for t in range(targets.shape[0]):
        j = targets[t]
        pocket_windows(pos[j, 0], pos[j, 1], radius[j], tm.pocket_xy, tm.pocket_r, tm.length, tm.width, samples,
                       out[t], tm.segs, tm.tips)
    return out


@leaf_public
def fill_window(j: int, p: int, pos: np.ndarray, radius: np.ndarray, tm: Model, cache_pos: np.ndarray,
                cache_win: np.ndarray, cache_have: np.ndarray) -> None:
    """Ball ``j``'s window into pocket ``p`` (a row of 4, :func:`~billiards_env.physics.aim.window_of`) in a table's
    cache, read as ``cache_win[j, p]``: ``cache_pos`` (B, 2), ``cache_win`` (B, K, 4), ``cache_have`` (B,) False at
    first. Worked out the first time it is asked for while the ball stands where it is; when ball ``j`` no longer
    stands at ``cache_pos[j]`` (or ``cache_have[j]`` is False), its windows are forgotten first (``WIN_FOUND`` set to
    :data:`WIN_UNKNOWN`). A ball's windows depend on its position alone (the table's model fixed), so a cached window
    is the same numbers as a fresh one; a pocket never asked for costs nothing. Returns nothing (a leaf helper: the
    caller reads the cache), so a call counts no array references."""
    if not (cache_have[j] and cache_pos[j, 0] == pos[j, 0] and cache_pos[j, 1] == pos[j, 1]):
        for q in range(cache_win.shape[1]):
            cache_win[j, q, WIN_FOUND] = WIN_UNKNOWN
        cache_pos[j, 0] = pos[j, 0]
        cache_pos[j, 1] = pos[j, 1]
        cache_have[j] = True
    if cache_win[j, p, WIN_FOUND] == WIN_UNKNOWN:
        c, h, d_in, ok = window_of(pos[j, 0], pos[j, 1], radius[j], tm.pocket_xy[p, 0], tm.pocket_xy[p, 1],
                                   tm.pocket_r[p], tm.length, tm.width, WINDOW_SAMPLES, tm.segs, tm.tips)
        cache_win[j, p, WIN_ANGLE] = c
        cache_win[j, p, WIN_HALF] = h
        cache_win[j, p, WIN_DIST] = d_in
        cache_win[j, p, WIN_FOUND] = 1.0 if ok else 0.0


@njit(cache=True)
def windows_cached(pos: np.ndarray, radius: np.ndarray, targets: np.ndarray, tm: Model, cache_pos: np.ndarray,
                   cache_win: np.ndarray, cache_have: np.ndarray) -> np.ndarray:
    """:func:`windows_of` (its samples) with a table's cache of its balls' windows (:func:`fill_window`): the
    windows of the balls that stand where they stood at an earlier call are not worked out again. The same
    numbers either way."""
    k_p = tm.pocket_r.shape[0]
    out = np.zeros((targets.shape[0], k_p, 4))
    for t in range(targets.shape[0]):
        for p in range(k_p):
            fill_window(targets[t], p, pos, radius, tm, cache_pos, cache_win, cache_have)
            # Element by element: an array assignment compiles numba's shape check and its message formatting
            # (seconds of a cold start).
            for c in range(4):
                out[t, p, c] = cache_win[targets[t], p, c]
    return out


@njit(cache=True)
def target_windows(pos: np.ndarray, radius: np.ndarray, targets: np.ndarray, pocket_xy: np.ndarray,
                   pocket_r: np.ndarray, params: np.ndarray) -> np.ndarray:
    """:func:`windows_of` on a :class:`TableModel`'s arrays (41 samples)."""
    return windows_of(pos, radius, targets, model(pocket_xy, pocket_r, params))


# --- one ghost-ball shot ----------------------------------------------------------------------------------------

@njit(cache=True)
def _speed_to_travel(d: float, v_end: float, tm: Model) -> float:
    """Launch speed to roll ``d`` and still move at ``v_end`` (raised to just above the stopping speed)."""
    v_end = max(v_end, tm.v_min * 1.05 + 1e-6)
    return launch_speed(d, v_end, tm.law, tm.decel, tm.k)


@leaf_public
def shot_row(out: np.ndarray, cx: float, cy: float, j: int, p: int, w_angle: float, w_half: float, w_dist: float,
             pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray, cue: int, tm: Model,
             lo: float, hi: float, max_cut: float, arrive: float, factors: np.ndarray, check_scratch: bool,
             scratch: np.ndarray, floor: float, obj_clear: int) -> bool:
    """The ghost-ball shot from the cue ball at ``(cx, cy)`` sending ball ``j`` into pocket ``p`` through its
    window ``(w_angle, w_half, w_dist)``, written into ``out`` (a row of :data:`N_COLS`); False (and ``out``
    untouched) when there is none: the ghost ball on the cue ball, a cut beyond ``max_cut``, or the ghost ball off
    the table.

    The cue speed gets the object ball to the capture circle still moving at ``arrive`` under the motion law; if
    the cue ball would then follow into a pocket (its deflected path with up to :data:`SCRATCH_BOUNCES` cushion
    bounces, ``check_scratch``), the arrival speed is scaled by the next of ``factors`` until one is safe. The
    ease (``COL_TOL``): the pocket window seen from the ball scaled by ``(rc + ro) cos(cut) / (d_cue + rc + ro)``;
    the score divides it by 10 when a path is blocked, by 3 when the speed is out of range and by 2 for the
    scratch risk. ``scratch``: a (2, 2) work array. ``floor``: skip (return False) a shot whose ease cannot
    beat it (the score is at most the tolerance), before its paths and speeds are worked out, or whose path is
    blocked and a tenth of its ease cannot beat it, before its speeds (``-inf``: no floor). ``obj_clear``: the
    object ball's clear path (:func:`object_path_clear`) when known (0 or 1; -1: work it out), the same from every
    cue position. No defaults: every compiled caller passes all of them, as plain values, so this is compiled for
    one signature (:mod:`billiards_env.physics.plain`)."""
    rc = radius[cue]
    mc = mass[cue]
    ox = pos[j, 0]
    oy = pos[j, 1]
    ro = radius[j]
    mo = mass[j]
    e = tm.ball_e
    ux = math.cos(w_angle)
    uy = math.sin(w_angle)
    gx, gy = ghost_point(ox, oy, w_angle, rc + ro)
    cgx = gx - cx
    cgy = gy - cy
    d_cue = math.hypot(cgx, cgy)
    if d_cue < 1e-9:
        return False
    cdx = cgx / d_cue
    cdy = cgy / d_cue
    cos_cut = cos_between(cdx, cdy, ux, uy)
    cut = math.acos(cos_cut)
    if cut > max_cut:
        return False
    if not (rc <= gx <= tm.length - rc and rc <= gy <= tm.width - rc):
        return False
    tol = w_half * (rc + ro) * cos_cut / (d_cue + rc + ro)
    if tol <= floor:
        return False
    if obj_clear < 0:
        clear_obj = object_path_clear(ox, oy, ux, uy, w_dist, pos, on, radius, cue, j)
    else:
        clear_obj = obj_clear != 0
    clear = clear_obj and not segment_blocked_by(cx, cy, gx, gy, pos, on, radius, cue, j, rc)
    if not clear and tol / 10.0 <= floor:  # its score is at most tol / 10: it cannot beat the floor either
        return False
    collide_into(scratch, 1.0 * cos_cut, 0.0, 0.0, 0.0, -1.0, 0.0, mc, mo, e)
    transfer = scratch[1, 0]  # object ball speed per unit impact speed
    speed = hi
    v0 = math.inf
    risk = True
    reachable = False
    for f in range(factors.shape[0]):
        v_obj = _speed_to_travel(w_dist, arrive * factors[f], tm)
        v_impact = v_obj / max(transfer, 1e-6)
        v_need = _speed_to_travel(d_cue, v_impact, tm)
        if v_need > hi:
            if not reachable and factors[f] == factors[0]:
                v0 = v_need
            continue
        s_try = max(v_need, lo)
        v_imp = max(speed_after_distance(s_try, d_cue, tm.law, tm.decel, tm.k), 1e-6)
        r_try = False
        if check_scratch:
            collide_into(scratch, v_imp * cdx, v_imp * cdy, 0.0, 0.0, -ux, -uy, mc, mo, e)
            r_try = lone_path_pocket_grouped(gx, gy, scratch[0, 0], scratch[0, 1], rc, tm.length, tm.width,
                                             tm.cushion_e, tm.pocket_xy, tm.pocket_r, tm.law, tm.decel, tm.k,
                                             tm.v_min, SCRATCH_BOUNCES, tm.segs, tm.tips, tm.groups) >= 0
        if not reachable or (risk and not r_try):
            speed = s_try
            v0 = v_need
            risk = r_try
            reachable = True
        if not risk:
            break
    if not reachable:
        speed = hi
    score = tol
    if not clear:
        score /= 10.0
    if not reachable:
        score /= 3.0
    if risk:
        score /= 2.0
    out[COL_TARGET] = j
    out[COL_POCKET] = p
    out[COL_ANGLE] = math.atan2(gy - cy, gx - cx)
    out[COL_SPEED] = speed
    out[COL_NEED] = v0
    out[COL_OBJ_ANGLE] = w_angle
    out[COL_CUT] = cut
    out[COL_D_CUE] = d_cue
    out[COL_D_OBJ] = w_dist
    out[COL_WINDOW] = w_half
    out[COL_TOL] = tol
    out[COL_CLEAR] = 1.0 if clear else 0.0
    out[COL_REACH] = 1.0 if reachable else 0.0
    out[COL_RISK] = 1.0 if risk else 0.0
    out[COL_SCORE] = score
    out[COL_CLEAR_OBJ] = 1.0 if clear_obj else 0.0
    return True


@leaf_public
def object_path_clear(ox: float, oy: float, ux: float, uy: float, w_dist: float, pos: np.ndarray, on: np.ndarray,
                      radius: np.ndarray, cue: int, j: int) -> bool:
    """Whether ball ``j`` at ``(ox, oy)`` rolls ``w_dist`` along ``(ux, uy)`` (its pocket window's centre) without
    touching a ball of the table other than the cue ball: the object ball's half of :func:`shot_row`'s clear path,
    the same from wherever the cue ball is."""
    return not segment_blocked_by(ox, oy, ox + ux * w_dist, oy + uy * w_dist, pos, on, radius, cue, j, radius[j])


@njit(cache=True)
def rank_rows(rows: np.ndarray) -> np.ndarray:
    """``rows`` sorted by score, highest first; equal scores keep their order (a stable sort)."""
    order = np.argsort(-rows[:, COL_SCORE], kind="mergesort")
    return rows[order]


# --- every shot of a table ---------------------------------------------------------------------------------------

@njit(cache=True)
def ghost_shots_from(cx: float, cy: float, pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray,
                     cue: int, targets: np.ndarray, windows: np.ndarray, tm: Model, lo: float, hi: float,
                     max_cut: float, arrive: float, factors: np.ndarray, check_scratch: bool) -> np.ndarray:
    """Every ghost-ball shot (:func:`shot_row`) from the cue ball at ``(cx, cy)`` at every ball of ``targets`` on
    the table (``windows``: theirs, :func:`target_windows`) into every pocket, easiest first: ``(M, N_COLS)``."""
    k_p = tm.pocket_r.shape[0]
    out = np.empty((targets.shape[0] * k_p, N_COLS))
    scratch = np.empty((2, 2))
    n = 0
    for t in range(targets.shape[0]):
        j = targets[t]
        if not on[j] or j == cue:
            continue
        for p in range(k_p):
            w = windows[t, p]
            if w[WIN_FOUND] == 0.0:
                continue
            if shot_row(out[n], cx, cy, j, p, w[WIN_ANGLE], w[WIN_HALF], w[WIN_DIST], pos, on, radius, mass, cue,
                        tm, lo, hi, max_cut, arrive, factors, check_scratch, scratch, -math.inf, plain(-1)):
                n += 1
    return rank_rows(out[:n])


@njit(cache=True)
def ghost_shots(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray, cue: int,
                targets: np.ndarray, pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray, lo: float,
                hi: float, max_cut: float, arrive: float, factors: np.ndarray, check_scratch: bool) -> np.ndarray:
    """Every ghost-ball shot of the table (a :class:`TableModel`'s arrays) from where the cue ball lies
    (:func:`ghost_shots_from`), easiest first, windows included: :func:`billiards_env.players.shots.ghost_ball_shots`
    as rows."""
    tm = model(pocket_xy, pocket_r, params)
    return ghost_shots_windowed(pos[cue, 0], pos[cue, 1], pos, on, radius, mass, cue, targets, tm, lo, hi, max_cut,
                                arrive, factors, check_scratch)


@njit(cache=True)
def ghost_shots_windowed(cx: float, cy: float, pos: np.ndarray, on: np.ndarray, radius: np.ndarray,
                         mass: np.ndarray, cue: int, targets: np.ndarray, tm: Model, lo: float, hi: float,
                         max_cut: float, arrive: float, factors: np.ndarray, check_scratch: bool) -> np.ndarray:
    """:func:`ghost_shots_from` working out the windows it needs itself: a (ball, pocket) window only when
    :func:`tolerance_bound` allows that shot a cut within ``max_cut`` for some window (else :func:`shot_row` would
    refuse it whatever the window: its cut is beyond ``max_cut``, by the bound's margins far above round-off). The
    same rows, without the windows of the pockets behind a ball (on a jaw table, most of a decision's time)."""
    k_p = tm.pocket_r.shape[0]
    out = np.empty((targets.shape[0] * k_p, N_COLS))
    scratch = np.empty((2, 2))
    cos_max = math.cos(max_cut)
    rc = radius[cue]
    n = 0
    for t in range(targets.shape[0]):
        j = targets[t]
        if not on[j] or j == cue:
            continue
        ox = pos[j, 0]
        oy = pos[j, 1]
        contact = rc + radius[j]
        d_co = math.hypot(ox - cx, oy - cy)
        a_co = math.atan2(oy - cy, ox - cx)
        for p in range(k_p):
            if tolerance_bound(ox, oy, contact, d_co, a_co, tm.pocket_xy[p, 0], tm.pocket_xy[p, 1], tm.pocket_r[p],
                               WINDOW_SAMPLES, cos_max) < 0.0:
                continue
            c, h, d_in, ok = window_of(ox, oy, radius[j], tm.pocket_xy[p, 0], tm.pocket_xy[p, 1], tm.pocket_r[p],
                                       tm.length, tm.width, WINDOW_SAMPLES, tm.segs, tm.tips)
            if ok and shot_row(out[n], cx, cy, j, p, c, h, d_in, pos, on, radius, mass, cue, tm, lo, hi, max_cut,
                               arrive, factors, check_scratch, scratch, -math.inf, plain(-1)):
                n += 1
    return rank_rows(out[:n])


@njit(cache=True)
def best_shot_row(rows: np.ndarray, max_cut: float, fallback_cut: float) -> int:
    """The geometric player's shot among ranked ``rows``: the first with a cut up to ``max_cut``, else the first
    up to ``fallback_cut``; -1 if none."""
    for i in range(rows.shape[0]):
        if rows[i, COL_CUT] <= max_cut:
            return i
    for i in range(rows.shape[0]):
        if rows[i, COL_CUT] <= fallback_cut:
            return i
    return -1


@njit(cache=True)
def best_shot_cached(cx: float, cy: float, pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray,
                     cue: int, targets: np.ndarray, tm: Model, lo: float, hi: float, max_cut: float, arrive: float,
                     factors: np.ndarray, cache_pos: np.ndarray, cache_win: np.ndarray,
                     cache_have: np.ndarray) -> np.ndarray:
    """The shot :func:`best_shot_row` picks among the rows of :func:`ghost_shots_from` from ``(cx, cy)`` with cuts
    up to ``max(max_cut, FALLBACK_CUT)`` (the easiest within ``max_cut``, else the easiest), as a ``(1, N_COLS)``
    array (``(0, N_COLS)``: no shot), without working out the shots that cannot be it. The windows come from a
    table's cache (:func:`fill_window`), each worked out only when its shot is tried.

    The (ball, pocket) shots are tried in :func:`ghost_shots_from`'s order. Before any shot within ``max_cut`` is
    found, a shot is passed over, window and all, when :func:`tolerance_bound` allows it no cut within the 88 deg
    limit (as :func:`ghost_shots_windowed` does). Once one is found, a shot is passed over when its bound (worked out
    without the window: an upper bound of its ease, so of its score) does not beat the best score so far or allows
    it no cut within ``max_cut``, and :func:`shot_row` skips it (its ``floor``) before its paths and speeds when its
    ease does not. A shot passed over could not have been picked: its score is at most the best so far, and of
    equal scores :func:`rank_rows` (a stable sort) ranks the earlier shot first. So the row is the one the
    unbounded search picks, bit for bit (tests/players/test_geometry.py)."""
    k_p = tm.pocket_r.shape[0]
    lim = max(max_cut, FALLBACK_CUT)
    cos_lim = math.cos(lim)
    cos_max = math.cos(max_cut)
    out = np.empty((1, N_COLS))
    row = np.empty(N_COLS)
    scratch = np.empty((2, 2))
    rc = radius[cue]
    found = False
    within = False  # the shot found is within max_cut
    best = -math.inf  # its score
    for t in range(targets.shape[0]):
        j = targets[t]
        if not on[j] or j == cue:
            continue
        ox = pos[j, 0]
        oy = pos[j, 1]
        contact = rc + radius[j]
        d_co = math.hypot(ox - cx, oy - cy)
        a_co = math.atan2(oy - cy, ox - cx)
        for p in range(k_p):
            bound = tolerance_bound(ox, oy, contact, d_co, a_co, tm.pocket_xy[p, 0], tm.pocket_xy[p, 1],
                                    tm.pocket_r[p], WINDOW_SAMPLES, cos_max if within else cos_lim)
            if bound < 0.0 or (within and bound <= best):
                continue
            fill_window(j, p, pos, radius, tm, cache_pos, cache_win, cache_have)
            if cache_win[j, p, WIN_FOUND] == 0.0:
                continue
            if not shot_row(row, cx, cy, j, p, cache_win[j, p, WIN_ANGLE], cache_win[j, p, WIN_HALF],
                            cache_win[j, p, WIN_DIST], pos, on, radius, mass, cue, tm,
                            lo, hi, max_cut if within else lim, arrive, factors, plain(True), scratch,
                            best if within else -math.inf, plain(-1)):
                continue
            if within:  # (shot_row refused cuts beyond max_cut and eases that cannot beat the best)
                take = row[COL_SCORE] > best
            elif row[COL_CUT] <= max_cut:
                take = within = True
            else:
                take = not found or row[COL_SCORE] > best
            if take:
                for c in range(N_COLS):
                    out[0, c] = row[c]
                best = row[COL_SCORE]
                found = True
    return out if found else np.empty((0, N_COLS))


@njit(cache=True)
def nearest_target(cx: float, cy: float, pos: np.ndarray, on: np.ndarray, cue: int, targets: np.ndarray) -> int:
    """The ball of ``targets`` on the table (not the cue ball) nearest to ``(cx, cy)`` (the first of equals);
    -1 if none."""
    best = -1
    best_d = math.inf
    for t in range(targets.shape[0]):
        j = targets[t]
        if not on[j] or j == cue:
            continue
        d = math.hypot(pos[j, 0] - cx, pos[j, 1] - cy)
        if d < best_d:
            best = j
            best_d = d
    return best


# --- ball in hand: the nearest legal point (physics/layout.py's nearest_free, on the pockets as holes) ----------

@njit(cache=True)
def pocket_holes(tm: Model) -> np.ndarray:
    """The pockets' capture circles as holes ``(K, 3)`` (x, y, r) for :func:`free_discs`."""
    k_p = tm.pocket_r.shape[0]
    out = np.empty((k_p, 3))
    for p in range(k_p):
        out[p, 0] = tm.pocket_xy[p, 0]
        out[p, 1] = tm.pocket_xy[p, 1]
        out[p, 2] = tm.pocket_r[p]
    return out


# --- ball in hand: where to put the cue ball -------------------------------------------------------------------------

@njit(cache=True)
def place_for_shot(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray, cue: int,
                   targets: np.ndarray, windows: np.ndarray, tm: Model, lo: float, hi: float, max_cut: float,
                   area: np.ndarray, backs: np.ndarray, arrive: float, factors: np.ndarray) -> tuple:
    """Ball in hand: the legal cue position (in ``area`` = (x0, x1, y0, y1), off the other balls and the pockets'
    capture circles) that leaves the easiest ghost-ball shot. The places tried: ``backs`` metres straight behind
    the ghost ball of every target and pocket with a window, moved to the nearest legal point; each scored by the
    best ghost-ball shot at that target from there (:func:`shot_row`; the first best wins). Without any window: the
    middle of the area. Returns ``(x, y, found)`` (found False: no legal point at all)."""
    x0, x1, y0, y1 = area[0], area[1], area[2], area[3]
    discs = free_discs(pos, on, radius, cue, pocket_holes(tm), 1e-6)
    k_p = tm.pocket_r.shape[0]
    row = np.empty(N_COLS)
    scratch = np.empty((2, 2))
    best_x = 0.0
    best_y = 0.0
    best_score = -1.0
    have = False
    r = radius[cue]
    obj_clear = np.full(k_p, -1, np.int64)  # the object ball's clear path to each pocket (-1: not worked out yet)
    for t in range(targets.shape[0]):
        j = targets[t]
        contact = r + radius[j]
        obj_clear[:] = -1
        for p in range(k_p):
            w = windows[t, p]
            if w[WIN_FOUND] == 0.0:
                continue
            gx, gy = ghost_point(pos[j, 0], pos[j, 1], w[WIN_ANGLE], contact)
            for b in range(backs.shape[0]):
                x = gx - backs[b] * math.cos(w[WIN_ANGLE])
                y = gy - backs[b] * math.sin(w[WIN_ANGLE])
                px, py, ok = nearest_free(min(max(x, x0), x1), min(max(y, y0), y1), discs, x0, x1, y0, y1)
                if not ok:
                    return px, py, False
                score = -1.0
                if on[j] and j != cue:
                    for q in range(k_p):
                        wq = windows[t, q]
                        if wq[WIN_FOUND] == 0.0:
                            continue
                        if obj_clear[q] < 0:
                            obj_clear[q] = object_path_clear(pos[j, 0], pos[j, 1], math.cos(wq[WIN_ANGLE]),
                                                             math.sin(wq[WIN_ANGLE]), wq[WIN_DIST], pos, on, radius,
                                                             cue, j)
                        # A shot whose ease cannot beat the best place so far, nor this place's best shot, cannot
                        # change the choice: skipped before its paths and speeds.
                        if shot_row(row, px, py, j, q, wq[WIN_ANGLE], wq[WIN_HALF], wq[WIN_DIST], pos, on, radius,
                                    mass, cue, tm, lo, hi, max_cut, arrive, factors, plain(True), scratch,
                                    max(best_score, score), obj_clear[q]):
                            if row[COL_SCORE] > score:
                                score = row[COL_SCORE]
                if score < 0.0:
                    score = 0.0
                if score > best_score:
                    best_x, best_y, best_score, have = px, py, score, True
    if not have:
        return nearest_free(0.5 * (x0 + x1), 0.5 * (y0 + y1), discs, x0, x1, y0, y1)
    return best_x, best_y, True


@njit(cache=True)
def choose_place(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray, cue: int,
                 targets: np.ndarray, pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray, lo: float,
                 hi: float, max_cut: float, area: np.ndarray, backs: np.ndarray) -> tuple:
    """:func:`place_for_shot` on a :class:`TableModel`'s arrays (the default arrival speed and factors)."""
    tm = model(pocket_xy, pocket_r, params)
    return place_for_shot(pos, on, radius, mass, cue, targets, windows_of(pos, radius, targets, tm), tm, lo, hi,
                          max_cut, area, backs, ARRIVE_SPEED, np.array(SPEED_FACTORS))


# --- the geometric player's decision ---------------------------------------------------------------------------

@njit(cache=True)
def geometric_decision_arrays(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray, cue: int,
                              targets: np.ndarray, pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray,
                              lo: float, hi: float, area: np.ndarray, in_hand: bool, is_break: bool,
                              max_cut: float) -> tuple:
    """The geometric player's shot (see :func:`geometric_decision`) as
    ``(place_x, place_y, placed, angle, speed, shot_row, rows, status)``: ``placed`` whether the cue ball is placed
    (ball in hand), ``rows`` the ranked ghost-ball shots from where it is played (cut up to
    ``max(max_cut, 88 deg)``), ``shot_row`` the index of the one played (-1: the break or the fallback direct hit),
    ``status`` 0, or 1 when ball in hand found no legal point."""
    return _decision(pos, on, radius, mass, cue, targets, pocket_xy, pocket_r, params, lo, hi, area, in_hand, is_break,
                     max_cut, np.zeros((0, 2)), np.zeros((0, 1, 4)), np.zeros(0, np.bool_), plain(False))  # (no cache)


@njit(cache=True)
def geometric_decision_cached(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray, cue: int,
                              targets: np.ndarray, pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray,
                              lo: float, hi: float, area: np.ndarray, in_hand: bool, is_break: bool, max_cut: float,
                              cache_pos: np.ndarray, cache_win: np.ndarray, cache_have: np.ndarray) -> tuple:
    """:func:`geometric_decision_arrays` with a table's cache of its balls' pocket windows (:func:`fill_window`:
    ``cache_pos`` (B, 2), ``cache_win`` (B, K, 4), ``cache_have`` (B,) False at first), kept between the decisions
    on one table: the balls that have not moved keep theirs. The same decision, bit for bit, and the same ranked
    shots (:func:`geometric_choice_cached` gives the decision alone, faster)."""
    return _decision(pos, on, radius, mass, cue, targets, pocket_xy, pocket_r, params, lo, hi, area, in_hand, is_break,
                     max_cut, cache_pos, cache_win, cache_have, plain(False))


@njit(cache=True)
def geometric_choice_cached(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray, cue: int,
                            targets: np.ndarray, pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray,
                            lo: float, hi: float, area: np.ndarray, in_hand: bool, is_break: bool, max_cut: float,
                            cache_pos: np.ndarray, cache_win: np.ndarray, cache_have: np.ndarray) -> tuple:
    """:func:`geometric_decision_cached` without the shots that cannot be played (the native games' opponent):
    the same ``(place_x, place_y, placed, angle, speed, shot_row, rows, status)`` bit for bit, except that ``rows``
    holds the played ghost-ball shot alone (``shot_row`` 0; no row and -1 when none is played), found by
    :func:`best_shot_cached`: the shots whose bound cannot beat the best so far are passed over, and their windows
    not worked out."""
    return _decision(pos, on, radius, mass, cue, targets, pocket_xy, pocket_r, params, lo, hi, area, in_hand, is_break,
                     max_cut, cache_pos, cache_win, cache_have, plain(True))


@njit(cache=True)
def _decision(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray, cue: int, targets: np.ndarray,
              pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray, lo: float, hi: float, area: np.ndarray,
              in_hand: bool, is_break: bool, max_cut: float, cache_pos: np.ndarray, cache_win: np.ndarray,
              cache_have: np.ndarray, bounded: bool) -> tuple:
    """:func:`geometric_decision_arrays`, with the windows from the cache when one is given (``cache_have`` not
    empty); ``bounded`` (with a cache): the played shot alone (:func:`best_shot_cached`), not every shot ranked."""
    tm = model(pocket_xy, pocket_r, params)
    factors = np.array(SPEED_FACTORS)
    empty = np.empty((0, N_COLS))
    px = 0.0
    py = 0.0
    if is_break:
        if in_hand:
            px = min(max(0.25 * tm.length, area[0]), area[1])
            py = min(max(0.5 * tm.width, area[2]), area[3])
            cx, cy = px, py
        else:
            cx, cy = pos[cue, 0], pos[cue, 1]
        j = -1
        best_d = math.inf
        for t in range(targets.shape[0]):
            d = math.hypot(pos[targets[t], 0] - cx, pos[targets[t], 1] - cy)
            if d < best_d:
                j = targets[t]
                best_d = d
        if j < 0:
            j = cue
        return px, py, in_hand, math.atan2(pos[j, 1] - cy, pos[j, 0] - cx), hi, -1, empty, 0
    cached = cache_have.shape[0] > 0
    if not in_hand and not cached:  # only the windows its shots need
        cx, cy = pos[cue, 0], pos[cue, 1]
        rows = ghost_shots_windowed(cx, cy, pos, on, radius, mass, cue, targets, tm, lo, hi,
                                    max(max_cut, FALLBACK_CUT), ARRIVE_SPEED, factors, plain(True))
        return _played(rows, px, py, in_hand, cx, cy, pos, on, cue, targets, lo, hi, max_cut)
    if not cached:
        windows = windows_of(pos, radius, targets, tm)
    elif in_hand or not bounded:
        windows = windows_cached(pos, radius, targets, tm, cache_pos, cache_win, cache_have)
    else:  # (best_shot_cached asks the cache for the windows it needs)
        windows = np.zeros((0, 1, 4))
    if in_hand:
        backs = np.array(PLACE_BACKS)
        px, py, ok = place_for_shot(pos, on, radius, mass, cue, targets, windows, tm, lo, hi, max_cut, area, backs,
                                  ARRIVE_SPEED, factors)
        if not ok:
            return px, py, in_hand, 0.0, hi, -1, empty, 1
        cx, cy = px, py
        on2 = on.copy()
        on2[cue] = True
    else:
        cx, cy = pos[cue, 0], pos[cue, 1]
        on2 = on
    if bounded:
        rows = best_shot_cached(cx, cy, pos, on2, radius, mass, cue, targets, tm, lo, hi, max_cut, ARRIVE_SPEED,
                                factors, cache_pos, cache_win, cache_have)
    else:
        rows = ghost_shots_from(cx, cy, pos, on2, radius, mass, cue, targets, windows, tm, lo, hi,
                                max(max_cut, FALLBACK_CUT), ARRIVE_SPEED, factors, plain(True))
    return _played(rows, px, py, in_hand, cx, cy, pos, on2, cue, targets, lo, hi, max_cut)


@njit(cache=True)
def _played(rows: np.ndarray, px: float, py: float, in_hand: bool, cx: float, cy: float, pos: np.ndarray,
            on: np.ndarray, cue: int, targets: np.ndarray, lo: float, hi: float, max_cut: float) -> tuple:
    """:func:`_decision`'s answer from the ranked shots ``rows`` from ``(cx, cy)``: the easiest within ``max_cut``
    (else within 88 deg), else a firm full-ball hit on the nearest target."""
    k = best_shot_row(rows, max_cut, FALLBACK_CUT)
    if k >= 0:
        return px, py, in_hand, rows[k, COL_ANGLE], rows[k, COL_SPEED], k, rows, 0
    angle = 0.0
    j = nearest_target(cx, cy, pos, on, cue, targets)
    if j >= 0:
        angle = math.atan2(pos[j, 1] - cy, pos[j, 0] - cx)
    return px, py, in_hand, angle, min(max(DIRECT_HIT_SPEED, lo), hi), -1, rows, 0


# --- the ease of the next shot (the search player's position term) ------------------------------------------------

@njit(cache=True)
def _base_windows(j: int, pos: np.ndarray, radius: np.ndarray, tm: Model, base_win: np.ndarray,
                  base_have: np.ndarray) -> np.ndarray:
    """Ball ``j``'s pocket windows ``(K, 4)`` on the base table (``base_win[j]``, worked out on first use)."""
    if not base_have[j]:
        pocket_windows(pos[j, 0], pos[j, 1], radius[j], tm.pocket_xy, tm.pocket_r, tm.length, tm.width,
                       WINDOW_SAMPLES, base_win[j], tm.segs, tm.tips)
        base_have[j] = True
    return base_win[j]


@njit(cache=True)
def tolerance_bound(ox: float, oy: float, contact: float, d_co: float, a_co: float, px: float, py: float,
                    pr: float, samples: int, cos_max: float) -> float:
    """An upper bound, worked out without the window, of the tolerance :func:`layout_tolerance` finds for the ball
    at ``(ox, oy)`` into the capture circle ``(px, py, pr)`` (``contact``: the two radii summed); -1 when that
    shot cannot count (its cut is beyond ``cos_max`` whatever the window). The cue ball is ``d_co`` from the ball,
    seen from it in the direction ``a_co`` (``atan2`` of ball minus cue).

    Why it holds (:func:`~billiards_env.physics.aim.window_of`): the window's centre ``u`` lies within ``half =
    asin(pr / dist)`` of the direction to the circle's centre, and its half-width is at most ``half * samples /
    (samples - 1)``. With ``phi`` the angle between ``u`` and the cue-to-ball line, the ghost ball is
    ``d = sqrt(D^2 + c^2 - 2 D c cos(phi))`` from the cue ball (``D = d_co``, ``c = contact``) and the cut's cosine
    is ``(D cos(phi) - c) / d``; both that cosine and ``1 / (d + c)`` fall as ``phi`` grows (for ``D > c``), so
    the tolerance ``w c cos(cut) / (d + c)`` is at most its value at the least ``phi`` the window allows. Margins
    (1e-7 rad on ``phi``, 1e-9 relative on the bound) cover the round-off: a shot skipped because its bound does
    not beat the best so far could not have beaten it, so the tolerance found is the same number."""
    dist = math.hypot(px - ox, py - oy)
    if dist <= pr * (1.0 + 1e-9) + 1e-12:
        return math.inf  # from inside the circle (or next to it): the window is pi / 2 wide, no bound
    half = math.asin(min(1.0, pr / dist))
    w_max = half * samples / (samples - 1)
    if d_co <= contact * (1.0 + 1e-9):
        return w_max * (1.0 + 1e-9)  # cos(cut) <= 1 and d + c >= c
    diff = abs(math.atan2(py - oy, px - ox) - a_co)
    if diff > math.pi:
        diff = 2.0 * math.pi - diff
    phi = diff - half - 1e-7
    x = math.cos(phi) if phi > 0.0 else 1.0
    d = math.sqrt(max(d_co * d_co + contact * contact - 2.0 * d_co * contact * x, 0.0))
    cos_hi = (d_co * x - contact) / d if d > 0.0 else 1.0
    if cos_hi < cos_max:
        return -1.0
    return w_max * contact * min(cos_hi, 1.0) / (d + contact) * (1.0 + 1e-9)


@njit(cache=True)
def layout_tolerance(cx: float, cy: float, pos: np.ndarray, on: np.ndarray, radius: np.ndarray, cue: int,
                     targets: np.ndarray, tm: Model, cos_max: float, base_pos: np.ndarray, base_win: np.ndarray,
                     base_have: np.ndarray, fresh: np.ndarray, bounds: np.ndarray, pairs: np.ndarray) -> float:
    """The easiest ghost-ball shot's cue-angle tolerance from the cue ball at ``(cx, cy)`` on the layout ``pos``,
    ``on`` at a ball of ``targets``: the pocket window seen from the ball scaled by ``(rc + ro) cos(cut) /
    (d_cue + rc + ro)``, divided by 10 when the cue ball's or the ball's path is blocked; cuts with a cosine below
    ``cos_max`` and ghost balls off the table do not count (0 if nothing counts). No speeds: the position term of
    the search player; a ball touching a path blocks it (:func:`~billiards_env.physics.aim.segment_touched_by`).

    Windows of balls still where they were on the base table come from ``base_win``; a ball that moved has its
    window into a pocket worked out (into ``fresh`` (T, K, 4)) only when that shot's :func:`tolerance_bound` beats
    the best tolerance so far. The (ball, pocket) shots are tried in the order of their bounds, highest first, and
    the search stops at the first bound that does not beat the best: the best is a maximum, the same in any order,
    and a shot skipped could not have raised it. ``bounds``, ``pairs``: work arrays of T * K entries."""
    rc = radius[cue]
    best = 0.0
    if not on[cue]:
        return best
    k_p = tm.pocket_r.shape[0]
    n = 0
    for t in range(targets.shape[0]):
        j = targets[t]
        if not on[j] or j == cue:
            continue
        contact = rc + radius[j]
        ox = pos[j, 0]
        oy = pos[j, 1]
        d_co = math.hypot(ox - cx, oy - cy)
        a_co = math.atan2(oy - cy, ox - cx)
        for p in range(k_p):
            b = tolerance_bound(ox, oy, contact, d_co, a_co, tm.pocket_xy[p, 0], tm.pocket_xy[p, 1], tm.pocket_r[p],
                                WINDOW_SAMPLES, cos_max)
            if b <= 0.0:
                continue
            i = n  # insertion, highest bound first
            while i > 0 and bounds[i - 1] < b:
                bounds[i] = bounds[i - 1]
                pairs[i] = pairs[i - 1]
                i -= 1
            bounds[i] = b
            pairs[i] = t * k_p + p
            n += 1
    for i in range(n):
        if bounds[i] <= best:
            break
        t = pairs[i] // k_p
        p = pairs[i] - t * k_p
        j = targets[t]
        rj = radius[j]
        contact = rc + rj
        ox = pos[j, 0]
        oy = pos[j, 1]
        if ox == base_pos[j, 0] and oy == base_pos[j, 1]:
            w = _base_windows(j, pos, radius, tm, base_win, base_have)[p]
        else:
            w = fresh[t, p]
            c, h, d_in, ok = window_of(ox, oy, rj, tm.pocket_xy[p, 0], tm.pocket_xy[p, 1], tm.pocket_r[p],
                                       tm.length, tm.width, WINDOW_SAMPLES, tm.segs, tm.tips)
            w[WIN_ANGLE] = c
            w[WIN_HALF] = h
            w[WIN_DIST] = d_in
            w[WIN_FOUND] = 1.0 if ok else 0.0
        if w[WIN_FOUND] == 0.0:
            continue
        wa = w[WIN_ANGLE]
        gx, gy = ghost_point(ox, oy, wa, contact)
        if not (rc <= gx <= tm.length - rc and rc <= gy <= tm.width - rc):
            continue
        ux = math.cos(wa)
        uy = math.sin(wa)
        vx = gx - cx
        vy = gy - cy
        d = math.hypot(vx, vy)
        cos_cut = dot2(vx, vy, ux, uy) / max(d, 1e-12)
        if cos_cut < cos_max:
            continue
        tol = w[WIN_HALF] * contact * cos_cut / (d + contact)
        if tol <= best:  # a blocked path only lowers it
            continue
        wd = w[WIN_DIST]
        if segment_touched_by(cx, cy, gx, gy, pos, on, radius, cue, j, rc) or \
                segment_touched_by(ox, oy, ox + ux * wd, oy + uy * wd, pos, on, radius, cue, j, rj):
            tol /= 10.0
        if tol > best:
            best = tol
    return best


@njit(cache=True)
def pot_chance(tolerance: float, sigma: float) -> float:
    """The chance a shot with cue-angle ``tolerance`` pots when the cue angle errs by a normal spread ``sigma``:
    ``erf(tolerance / (sqrt(2) sigma))`` (:func:`billiards_env.players.shots.pot_probability`)."""
    return math.erf(max(tolerance, 0.0) / (math.sqrt(2.0) * max(sigma, 1e-12)))


@njit(cache=True)
def _tolerance_work(n_targets: int, n_pockets: int) -> tuple:
    """:func:`layout_tolerance`'s work arrays for up to ``n_targets`` targets: ``fresh`` (T, K, 4), ``bounds`` and
    ``pairs`` (T * K,)."""
    t = max(n_targets, 1)
    return (np.zeros((t, n_pockets, 4)), np.zeros(t * n_pockets), np.zeros(t * n_pockets, np.int64))


@njit(cache=True)
def layouts_ease(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, cue: int, rows: np.ndarray,
                 group: np.ndarray, t_flat: np.ndarray, t_off: np.ndarray, pocket_xy: np.ndarray,
                 pocket_r: np.ndarray, params: np.ndarray, sigma: float, max_cut: float,
                 base_pos: np.ndarray) -> np.ndarray:
    """For the layouts ``rows`` of ``pos`` (N, B, 2) / ``on`` (N, B) (e.g. the final tables of a batch of shots),
    the chance of potting the easiest next shot (:func:`layout_tolerance` through :func:`pot_chance`) at one of
    that layout's targets: ``t_flat[t_off[g]:t_off[g + 1]]`` for its group ``g = group[k]``. Windows are worked out
    once per ball for balls still at ``base_pos`` (the table the shots were played from)."""
    tm = model(pocket_xy, pocket_r, params)
    nb = radius.shape[0]
    base_win = np.zeros((nb, pocket_r.shape[0], 4))
    base_have = np.zeros(nb, np.bool_)
    fresh, bounds, pairs = _tolerance_work(t_flat.shape[0], pocket_r.shape[0])
    cos_max = math.cos(max_cut)
    out = np.zeros(rows.shape[0])
    for i in range(rows.shape[0]):
        k = rows[i]
        g = group[k]
        tol = layout_tolerance(pos[k, cue, 0], pos[k, cue, 1], pos[k], on[k], radius, cue,
                               t_flat[t_off[g]:t_off[g + 1]], tm, cos_max, base_pos, base_win, base_have, fresh,
                               bounds, pairs)
        out[i] = pot_chance(tol, sigma)
    return out


@njit(cache=True)
def places_ease(places: np.ndarray, pos: np.ndarray, on: np.ndarray, radius: np.ndarray, cue: int,
                targets: np.ndarray, pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray, sigma: float,
                max_cut: float) -> np.ndarray:
    """:func:`layouts_ease` for one table with the cue ball put at each of ``places`` (M, 2) in turn."""
    tm = model(pocket_xy, pocket_r, params)
    nb = radius.shape[0]
    base_win = np.zeros((nb, pocket_r.shape[0], 4))
    base_have = np.zeros(nb, np.bool_)
    fresh, bounds, pairs = _tolerance_work(targets.shape[0], pocket_r.shape[0])
    on2 = on.copy()
    on2[cue] = True
    cos_max = math.cos(max_cut)
    out = np.zeros(places.shape[0])
    for i in range(places.shape[0]):
        tol = layout_tolerance(places[i, 0], places[i, 1], pos, on2, radius, cue, targets, tm, cos_max, pos,
                               base_win, base_have, fresh, bounds, pairs)
        out[i] = pot_chance(tol, sigma)
    return out


@njit(cache=True)
def search_places(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, cue: int, targets: np.ndarray,
                  pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray, area: np.ndarray,
                  backs: np.ndarray, cuts: np.ndarray) -> tuple:
    """Ball in hand, the places the search player tries: ``backs`` metres behind the ghost ball of every target
    and pocket with a window, straight in and turned by each of ``cuts``, moved to the nearest legal point (off the
    balls and the pockets' capture circles, in ``area``). Returns ``(places (M, 2), status)``: 0, or 1 when there
    is no window (the one place is then the middle of the area, moved to the nearest legal point), or 2 when the
    area has no legal point."""
    tm = model(pocket_xy, pocket_r, params)
    x0, x1, y0, y1 = area[0], area[1], area[2], area[3]
    discs = free_discs(pos, on, radius, cue, pocket_holes(tm), 1e-6)
    windows = windows_of(pos, radius, targets, tm)
    k_p = pocket_r.shape[0]
    out = np.empty((targets.shape[0] * k_p * backs.shape[0] * cuts.shape[0] + 1, 2))
    n = 0
    r = radius[cue]
    for t in range(targets.shape[0]):
        j = targets[t]
        for p in range(k_p):
            w = windows[t, p]
            if w[WIN_FOUND] == 0.0:
                continue
            gx, gy = ghost_point(pos[j, 0], pos[j, 1], w[WIN_ANGLE], r + radius[j])
            for b in range(backs.shape[0]):
                for c in range(cuts.shape[0]):
                    a = w[WIN_ANGLE] + cuts[c]
                    x = gx - backs[b] * math.cos(a)
                    y = gy - backs[b] * math.sin(a)
                    px, py, ok = nearest_free(min(max(x, x0), x1), min(max(y, y0), y1), discs, x0, x1, y0, y1)
                    if not ok:
                        return out[:0], 2
                    out[n, 0] = px
                    out[n, 1] = py
                    n += 1
    if n == 0:
        px, py, ok = nearest_free(0.5 * (x0 + x1), 0.5 * (y0 + y1), discs, x0, x1, y0, y1)
        out[0, 0] = px
        out[0, 1] = py
        return out[:1], 1 if ok else 2
    return out[:n], 0


class Decision(NamedTuple):
    """A geometric decision: strike at ``angle``, ``speed`` from ``place`` (ball in hand, else None); ``pocket``:
    the pocket of the ghost-ball shot played (-1: none: the break or the direct hit); ``shot``: its row in ``rows``
    (the ranked ghost-ball shots, :data:`N_COLS` columns), or -1."""

    place: tuple[float, float] | None
    angle: float
    speed: float
    pocket: int
    shot: int
    rows: np.ndarray


def geometric_decision(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray,
                       targets: np.ndarray, tm: TableModel, speed_range: tuple[float, float],
                       place_area: tuple[float, float, float, float] | None = None, is_break: bool = False,
                       max_cut: float = MAX_CUT, cue: int = 0) -> Decision:
    """The geometric player's shot on a table given as arrays, in one compiled call.

    - the break (``is_break``): the cue ball on the head spot moved into ``place_area`` (if in hand), struck at
      the top of ``speed_range`` at the nearest of ``targets``;
    - ball in hand (``place_area`` given): the place that leaves the easiest ghost-ball shot (:func:`choose_place`);
    - the easiest ghost-ball shot (:func:`ghost_shots_from`) with a cut up to ``max_cut``, else up to 88 deg;
    - else a firm full-ball hit (2 m/s, within the range) on the nearest target.

    ``targets``: the rows the shooter may hit first, on the table (a game's legal balls). Raises
    :class:`~billiards_env.physics.SceneError` when ball in hand finds no legal point in the area."""
    from billiards_env.physics.errors import SceneError

    in_hand = place_area is not None
    area = np.asarray(place_area if in_hand else (0.0, 0.0, 0.0, 0.0), dtype=np.float64)
    px, py, placed, angle, speed, k, rows, status = geometric_decision_arrays(
        np.ascontiguousarray(pos, dtype=np.float64), np.ascontiguousarray(on, dtype=np.bool_),
        np.ascontiguousarray(radius, dtype=np.float64), np.ascontiguousarray(mass, dtype=np.float64), int(cue),
        np.ascontiguousarray(targets, dtype=np.int64), tm.pocket_xy, tm.pocket_r, tm.params, float(speed_range[0]),
        float(speed_range[1]), area, in_hand, bool(is_break), float(max_cut))
    if status == 1:
        raise SceneError(f"no legal point for ball row {cue} in the area {tuple(place_area)}: it is covered by "
                         "other balls")
    pocket = int(rows[k, COL_POCKET]) if k >= 0 else -1
    return Decision((float(px), float(py)) if placed else None, float(angle), float(speed), pocket, int(k), rows)


__all__ = ["Model", "TableModel", "table_model", "state_model", "model", "windows_of", "windows_cached",
           "geometric_decision_cached", "geometric_choice_cached", "fill_window", "target_windows", "shot_row",
           "rank_rows", "ghost_shots_from", "ghost_shots", "ghost_shots_windowed", "best_shot_row", "best_shot_cached",
           "nearest_target", "py_hypot", "free_discs",
           "nearest_free", "pocket_holes", "place_for_shot", "choose_place", "layout_tolerance", "tolerance_bound",
           "pot_chance",
           "layouts_ease", "places_ease", "search_places", "geometric_decision_arrays", "geometric_decision",
           "Decision", "N_COLS", "MAX_CUT", "FALLBACK_CUT", "ARRIVE_SPEED", "SPEED_FACTORS", "DIRECT_HIT_SPEED",
           "PLACE_BACKS", "COL_TARGET", "COL_POCKET", "COL_ANGLE", "COL_SPEED", "COL_NEED", "COL_OBJ_ANGLE", "COL_CUT",
           "COL_D_CUE", "COL_D_OBJ", "COL_WINDOW", "COL_TOL", "COL_CLEAR", "COL_REACH", "COL_RISK", "COL_SCORE",
           "COL_CLEAR_OBJ", "WIN_ANGLE", "WIN_HALF", "WIN_DIST", "WIN_FOUND", "WIN_UNKNOWN"]
