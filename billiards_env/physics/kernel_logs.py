"""What every solver kernel shares (compiled): the growable event and state logs, keeping balls on the table, and
the pocket capture test. The kernels (:mod:`.exact`, :mod:`.exact_spin`, :mod:`.step`, :mod:`.step_spin`) call
these instead of each writing its own."""
from __future__ import annotations

import numpy as np
from numba import njit

#: Compile options of kernel helpers: called only from compiled code, so they need no Python entry wrappers
#: (which would be compiled, optimised and cached for each of them: a good part of a cold compile).
internal = njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)


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
def append_event(ev_t, ev_int, ev_speed, n, t, kind, ball, other, speed):
    """Write event ``n`` (time, kind, ball, other, speed), growing the log if it is full; returns the arrays."""
    ev_t, ev_int, ev_speed = reserve_events(ev_t, ev_int, ev_speed, n + 1)
    ev_t[n] = t
    ev_int[n, 0] = kind
    ev_int[n, 1] = ball
    ev_int[n, 2] = other
    ev_speed[n] = speed
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
