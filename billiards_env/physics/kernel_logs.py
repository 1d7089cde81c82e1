"""What every solver kernel shares (compiled): the growable event and state logs, keeping balls on the table, the
pocket capture test, the exact solvers' choice of the next event, burst count and contact clusters, and the step
solvers' cushion overshoot, tunnelling and rewind geometry. The kernels (:mod:`.exact`, :mod:`.exact_spin`,
:mod:`.step`, :mod:`.step_spin`) call these instead of each writing its own (or importing another's private
helpers)."""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .codes import EV_COLLISION
from .collide import CONTACT_TIME

#: Compile options of kernel helpers: called only from compiled code, so they need no Python entry wrappers
#: (which would be compiled, optimised and cached for each of them: a good part of a cold compile).
internal = njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
#: The same, inlined into the caller by numba (in its own IR): for small helpers of the kernels' hot loops, which
#: a call would slow down.
inlined = njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
#: Like :data:`internal`, for hot helpers that read and write arrays but never make, keep or return one (nor get one
#: from a call): compiled without numba's reference counting (``_nrt=False``), so a call no longer increments and
#: decrements the count of each array argument (an atomic operation each, which numba's pruning leaves in a function
#: of several exits: a tenth of a one-ball shot's time). The caller holds the arrays for the call. numba refuses an
#: allocation in such a function; ``tests/physics/test_leaf_helpers.py`` checks that none returns an array.
leaf = njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, _nrt=False)
#: :data:`leaf` with its Python entry kept, for such helpers that Python calls too (the players, the tests).
leaf_public = njit(cache=True, _nrt=False)


@inlined
def carve(buf, at, rows, cols):
    """``rows x cols`` of the flat scratch buffer ``buf`` from offset ``at``, as a 2-D (C-contiguous) view: a kernel
    makes its scratch arrays from one allocation per type (an allocation costs about as much as an event's
    bookkeeping)."""
    return buf[at:at + rows * cols].reshape((rows, cols))


@internal
def grow(arr):
    """``arr`` (1-D) copied into an array twice as long."""
    out = np.empty(arr.shape[0] * 2, arr.dtype)
    for r in range(arr.shape[0]):
        out[r] = arr[r]
    return out


@internal
def grow_rows(arr):
    """``arr`` (2-D) copied into an array with twice the rows."""
    out = np.empty((arr.shape[0] * 2, arr.shape[1]), arr.dtype)
    for r in range(arr.shape[0]):
        for c in range(arr.shape[1]):
            out[r, c] = arr[r, c]
    return out


@internal
def reserve_events(ev_t, ev_int, ev_speed, need):
    """The event log's arrays with room for ``need`` events (grown by doubling)."""
    while ev_t.shape[0] < need:
        ev_t = grow(ev_t)
        ev_int = grow_rows(ev_int)
        ev_speed = grow(ev_speed)
    return ev_t, ev_int, ev_speed


@internal
def reserve_states(sc_t, sc_ball, sc_state, n):
    """The state log's arrays with room for row ``n`` (grown by doubling when full)."""
    if n >= sc_t.shape[0]:
        sc_t = grow(sc_t)
        sc_ball = grow(sc_ball)
        sc_state = grow_rows(sc_state)
    return sc_t, sc_ball, sc_state


@internal
def keep_on_table(pos, on_table, radius, length, width):
    """Put every ball on the table back inside ``[r, L - r] x [r, W - r]`` (a push can leave one past a cushion)."""
    for i in range(pos.shape[0]):
        if on_table[i]:
            r = radius[i]
            pos[i, 0] = min(max(pos[i, 0], r), length - r)
            pos[i, 1] = min(max(pos[i, 1], r), width - r)


@internal
def pocket_holding(x, y, pocket_xy, pocket_r):
    """The first pocket whose capture circle holds the point ``(x, y)``, or -1."""
    for p in range(pocket_r.shape[0]):
        dx = x - pocket_xy[p, 0]
        dy = y - pocket_xy[p, 1]
        if dx * dx + dy * dy <= pocket_r[p] * pocket_r[p]:
            return p
    return -1


@internal
def put_event(ev_t, ev_int, ev_speed, n, t, kind, ball, other, speed):
    """Write event ``n`` into a log with room for it (the step solvers reserve a step's room at once, so their hot
    loops never reallocate)."""
    ev_t[n] = t
    ev_int[n, 0] = kind
    ev_int[n, 1] = ball
    ev_int[n, 2] = other
    ev_speed[n] = speed


@internal
def snapshot(n_sc, sc_t, sc_ball, sc_state, t, pos, vel, ang, on, code, only):
    """Log the state of every ball (or of ball ``only`` if it is >= 0) at ``t`` (step solvers): ``x y vx vy
    on_table``, and when the log has the spin model's columns, ``wx wy wz motion_state`` (from ``ang``, ``code``).
    Returns the log's row count and arrays (grown when full)."""
    n = pos.shape[0]
    spin_cols = sc_state.shape[1] > 5
    for i in range(n):
        if only >= 0 and i != only:
            continue
        sc_t, sc_ball, sc_state = reserve_states(sc_t, sc_ball, sc_state, n_sc)
        sc_t[n_sc] = t
        sc_ball[n_sc] = i
        sc_state[n_sc, 0] = pos[i, 0]
        sc_state[n_sc, 1] = pos[i, 1]
        sc_state[n_sc, 2] = vel[i, 0]
        sc_state[n_sc, 3] = vel[i, 1]
        sc_state[n_sc, 4] = 1.0 if on[i] else 0.0
        if spin_cols:
            sc_state[n_sc, 5] = ang[i, 0]
            sc_state[n_sc, 6] = ang[i, 1]
            sc_state[n_sc, 7] = ang[i, 2]
            sc_state[n_sc, 8] = code[i]
        n_sc += 1
    return n_sc, sc_t, sc_ball, sc_state


@inlined
def next_event(ball_t, ball_kind, ball_other, row_t, row_j):
    """The earliest pending event of the exact solvers: ``(time, kind, ball, other)``, from the balls' own event
    times and each pair row's earliest collision (``row_t[i]``, with ``j = row_j[i]``: :func:`set_pair`,
    :func:`rescan_row`), so that no pair is scanned. Ties go to ball events (by row) before pair events (by
    ``(i, j)``, ``i < j``): the fixed order of simultaneous events, as a scan of every pair in that order gives.
    ``time`` is ``inf`` when nothing is pending."""
    n = ball_t.shape[0]
    best = math.inf
    kind = np.int64(-1)
    bi = np.int64(-1)
    bj = np.int64(-1)
    for i in range(n):
        if ball_t[i] < best:
            best = ball_t[i]
            kind = ball_kind[i]
            bi = i
            bj = ball_other[i]
    for i in range(n):
        if row_t[i] < best:
            best = row_t[i]
            kind = np.int64(EV_COLLISION)
            bi = i
            bj = row_j[i]
    return best, kind, bi, bj


@inlined
def rescan_row(pair_t, row_t, row_j, i):
    """Row ``i``'s earliest collision (its first pair ``(i, j)``, ``j > i``, on a tie) into ``row_t[i]``,
    ``row_j[i]`` (``inf``, -1 if none): after the whole row was written."""
    best = math.inf
    bj = np.int64(-1)
    for j in range(i + 1, pair_t.shape[0]):
        if pair_t[i, j] < best:
            best = pair_t[i, j]
            bj = j
    row_t[i] = best
    row_j[i] = bj


@inlined
def set_pair(pair_t, row_t, row_j, lo, hi, v):
    """Write the collision time ``v`` of the pair ``(lo, hi)`` (``lo < hi``) and keep row ``lo``'s earliest
    collision: taken over when earlier (or as early and before it in the row), the row scanned again only when its
    earliest pair gets later."""
    pair_t[lo, hi] = v
    if v < row_t[lo] or (v == row_t[lo] and hi < row_j[lo]):
        row_t[lo] = v
        row_j[lo] = hi
    elif hi == row_j[lo] and v != row_t[lo]:
        rescan_row(pair_t, row_t, row_j, lo)


@internal
def count_burst(i, t, t_hit, burst):
    """Record a collision of ball ``i`` at ``t``; True if it follows its previous one within ``CONTACT_TIME`` (one
    contact cluster; see :mod:`.collide`)."""
    clustered = t - t_hit[i] <= CONTACT_TIME
    burst[i] = burst[i] + 1 if clustered else 0
    t_hit[i] = t
    return clustered


@internal
def contact_cluster(seed, px, py, radius, on_table, involved):
    """The balls touching ball ``seed``, directly or through others (centres ``px``, ``py``; touching: within
    ``1e-9`` m of contact), in breadth-first order from ``seed``, written into ``involved``; returns their count."""
    n = px.shape[0]
    member = np.zeros(n, np.bool_)
    member[seed] = True
    involved[0] = seed
    count = 1
    head = 0
    while head < count:
        q = involved[head]
        head += 1
        for m in range(n):
            if on_table[m] and not member[m]:
                if math.hypot(px[q] - px[m], py[q] - py[m]) <= radius[q] + radius[m] + 1e-9:
                    member[m] = True
                    involved[count] = m
                    count += 1
    return count


@internal
def tunnelled(dx, dy, bx, by, dc, dt):
    """Step solvers: whether two balls ``d`` apart now (at least ``dc`` apart), with relative velocity ``b`` over
    the last step, passed through each other within it (their closest approach along the step's straight-line
    relative motion was below ``dc``)."""
    bb = bx * bx + by * by
    if not bb > 0.0:
        return False
    s_min = min(max((dx * bx + dy * by) / bb, 0.0), dt)  # seconds back from now
    mx = dx - bx * s_min
    my = dy - by * s_min
    return 0.0 < s_min < dt and mx * mx + my * my < dc * dc


@internal
def rewind_time(dx, dy, bx, by, dc, dt):
    """Step solvers, contact treatment ``rewind``: how many seconds back (within the step of ``dt``) two
    overlapping balls ``d`` apart, with relative velocity ``b``, touched (``|d - b s| = dc`` for the smallest
    ``s >= 0``); -1 if not within the step."""
    bb = bx * bx + by * by
    if not bb > 0.0:
        return -1.0
    db = dx * bx + dy * by
    disc = db * db - bb * (dx * dx + dy * dy - dc * dc)
    s_hit = (db + math.sqrt(max(disc, 0.0))) / bb
    if 0.0 <= s_hit <= dt:
        return s_hit
    return -1.0


@internal
def cushion_overshoot(pos, i, cush, r, length, width):
    """Step solvers: ``(axis, wall, over)`` of ball ``i`` against cushion ``cush`` (0 left, 1 right, 2 bottom,
    3 top): the coordinate axis, the centre's limit there, and how far the centre is past it (> 0: overlapping)."""
    axis = 0 if cush < 2 else 1
    lim = r if cush % 2 == 0 else (length if axis == 0 else width) - r
    over = (lim - pos[i, axis]) if cush % 2 == 0 else (pos[i, axis] - lim)
    return axis, lim, over
