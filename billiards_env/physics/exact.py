"""The ``exact`` solver: event-driven simulation with closed-form motion between events (numba kernel).

Every ball carries its state at the time of its last event (``t0``, ``p0``, ``v0``) and its absolute stop
time; its position at any later time is the closed form of :mod:`.motion`. The solver keeps the next event
time of every ball (stop, cushion, pocket) and of every pair (collision) and repeatedly jumps to the
earliest one. After an event only the involved balls' times are recomputed, so resting and pocketed
balls cost nothing until something hits them.

Simultaneous events are taken in a fixed order: the earliest time first; among equal times, ball events
(in ball order) before pair events (in ``(i, j)`` order, ``i < j``). A chain of contacts at one instant (a
touching rack, Newton's cradle) therefore unfolds as a deterministic sequence of pairwise collisions.

The event loop's stages (:func:`state_at`, :func:`predict_ball`, :func:`pair_time_s`) are public: the solver
profile (``benchmarks/solver_profile.py``) times them one by one.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .aim import ray_cushion_hit
from .codes import (EV_COLLISION, EV_CUSHION, EV_JAM, EV_POCKET, EV_STOP, ROLLING, STATUS_EVENT_CAP, STATUS_REST,
                    STATUS_TIME_CAP)
from .collide import JAM_EVENTS, resolve_ball_ball, resolve_cushion
from .kernel_io import KernelResult
from .kernel_logs import (contact_cluster, count_burst, inlined, internal, leaf, next_event, pocket_holding,
                          reserve_events, rescan_row, reserve_states, set_pair)
from .motion import (distance, drag_phi, drag_time_for_phi, speed_after, stop_distance, time_for_distance,
                     time_to_stop)
from .roots import first_entry, ray_circle_below
from .walls import (cluster_off_walls, has_walls, path_box_clear, ray_wall_hit, reflect_off, touch_wall,
                    wall_normal_at)

#: A typed (non-literal) integer initial value: a literal 0 passed on to a compiled helper would make numba compile
#: a second specialisation of it for the literal.
_ZERO = np.int64(0)


@inlined
def state_at(i, t, t0, p0, v0, sp0, tstop, law, a, k):
    """Position and velocity of ball ``i`` at time ``t >= t0[i]`` from its last event state (``sp0[i]``: its speed
    then, ``hypot`` of ``v0[i]``, kept with it so that it is not worked out again at every call)."""
    vx = v0[i, 0]
    vy = v0[i, 1]
    s = sp0[i]
    if s == 0.0:
        return p0[i, 0], p0[i, 1], 0.0, 0.0
    tt = min(t, tstop[i]) - t0[i]
    ux = vx / s
    uy = vy / s
    d = distance(s, tt, law, a, k)
    x = p0[i, 0] + ux * d
    y = p0[i, 1] + uy * d
    if t >= tstop[i]:
        return x, y, 0.0, 0.0
    sp = speed_after(s, tt, law, a, k)
    return x, y, ux * sp, uy * sp


@inlined
def _advance(i, t, t0, p0, v0, sp0, tstop, law, a, k):
    """Move ball ``i``'s reference state to time ``t`` (its speed ``sp0[i]`` too: :func:`_advance_only`)."""
    _advance_only(i, t, t0, p0, v0, sp0, tstop, law, a, k)
    sp0[i] = math.hypot(v0[i, 0], v0[i, 1])


@inlined
def _advance_only(i, t, t0, p0, v0, sp0, tstop, law, a, k):
    """:func:`_advance` leaving ``sp0[i]`` stale: for an event that sets the velocity (and with it the speed) anew
    before anything reads the speed (a collision, a cushion, a stop; a jam sets it first)."""
    x, y, vx, vy = state_at(i, t, t0, p0, v0, sp0, tstop, law, a, k)
    p0[i, 0] = x
    p0[i, 1] = y
    v0[i, 0] = vx
    v0[i, 1] = vy
    t0[i] = t


@inlined
def _set_stop_time(i, t0, v0, sp0, tstop, law, a, k, v_min):
    """Ball ``i``'s stop time and speed ``sp0[i]`` after its velocity ``v0[i]`` was set (at rest below ``v_min``)."""
    s = math.hypot(v0[i, 0], v0[i, 1])
    if s <= v_min or s == 0.0:
        v0[i, 0] = 0.0
        v0[i, 1] = 0.0
        sp0[i] = 0.0
        tstop[i] = t0[i]
    else:
        sp0[i] = s
        tstop[i] = t0[i] + time_to_stop(s, law, a, k, v_min)


@leaf
def predict_ball(i, t0, p0, v0, sp0, tstop, radius, pocket_xy, pocket_r, prm):
    """Next stop, cushion or pocket event of ball ``i``: ``(time, kind, other)``."""
    vx = v0[i, 0]
    vy = v0[i, 1]
    s = sp0[i]
    if s == 0.0:  # at rest: only a ball placed inside a capture circle has an event (pocketed at once)
        p = pocket_holding(p0[i, 0], p0[i, 1], pocket_xy, pocket_r)
        if p >= 0:
            return t0[i], EV_POCKET, p
        return math.inf, -1, -1
    law = prm.law
    a = prm.decel
    k = prm.drag_k
    ux = vx / s
    uy = vy / s
    x = p0[i, 0]
    y = p0[i, 1]
    r = radius[i]
    # Hits beyond the path left before the ball stops are never its next event (the stop comes first): they are
    # left out by starting the search there (margins far above round-off; inf where the ball never stops).
    best_d = math.inf
    if tstop[i] < math.inf:
        best_d = stop_distance(s, law, a, k, prm.min_speed) * (1.0 + 1e-9) + 1e-12
    kind = -1
    other = -1
    # Pockets first, so that a pocket and a cushion at the same point go to the pocket.
    for p in range(pocket_r.shape[0]):
        d = ray_circle_below(x, y, ux, uy, pocket_xy[p, 0], pocket_xy[p, 1], pocket_r[p], best_d)
        if d < best_d:
            best_d = d
            kind = EV_POCKET
            other = p
    if has_walls(prm):  # a jaw table: rails, jaw faces and tips (only those nearer than the best so far)
        d, cush = ray_wall_hit(x, y, ux, uy, r, prm, best_d)
    else:
        d, cush = ray_cushion_hit(x, y, ux, uy, prm.length, prm.width, r)
    if d < best_d:
        best_d = d
        kind = EV_CUSHION
        other = cush
    t_stop = tstop[i]
    if kind >= 0:
        tau = time_for_distance(s, best_d, law, a, k)
        if t0[i] + tau <= t_stop:
            return t0[i] + tau, kind, other
        if tau == math.inf and t_stop == math.inf:
            return math.inf, -1, -1
    return t_stop, EV_STOP, -1


@leaf
def _predict_pair(i, j, t, t0, p0, v0, sp0, tstop, ball_t, radius, prm):
    """Time of the next collision of balls ``i`` and ``j`` after ``t``; ``inf`` if none before either ball's
    next own event (stop, cushion, pocket), since that event recomputes the pair anyway."""
    law = prm.law
    a = prm.decel
    k = prm.drag_k
    xi, yi, vxi, vyi = state_at(i, t, t0, p0, v0, sp0, tstop, law, a, k)
    xj, yj, vxj, vyj = state_at(j, t, t0, p0, v0, sp0, tstop, law, a, k)
    return _pair_time(i, j, t, xi, yi, vxi, vyi, xj, yj, vxj, vyj, ball_t, radius, prm)


@leaf
def _pair_time(i, j, t, xi, yi, vxi, vyi, xj, yj, vxj, vyj, ball_t, radius, prm):
    """:func:`_predict_pair` from both balls' states at ``t`` (``i < j``), so that a ball's state is computed once
    for all its pairs."""
    return pair_time_s(i, j, t, xi, yi, vxi, vyi, math.hypot(vxi, vyi), xj, yj, vxj, vyj, math.hypot(vxj, vyj),
                        ball_t, radius, prm)


@internal
def pair_time_s(i, j, t, xi, yi, vxi, vyi, si, xj, yj, vxj, vyj, sj, ball_t, radius, prm):
    """:func:`_pair_time` with both balls' speeds (``hypot`` of their velocities) given."""
    law = prm.law
    a = prm.decel
    k = prm.drag_k
    if si == 0.0 and sj == 0.0:
        return math.inf
    window = min(prm.max_time, ball_t[i], ball_t[j]) - t
    if not window > 0.0:
        return math.inf
    dc = radius[i] + radius[j]
    ax = xi - xj
    ay = yi - yj
    # Cull pairs too far apart to meet within the window: the gap exceeds both balls' remaining paths.
    reach = 0.0
    if si > 0.0:
        reach += distance(si, window, law, a, k)
    if sj > 0.0:
        reach += distance(sj, window, law, a, k)
    lim = reach * (1.0 + 1e-9) + 1e-12
    # On squares, no square root (margins far above round-off): a pair left in by round-off at the margin has no
    # root in the window, which the tests below or the root finder say.
    far = (dc + lim) * (1.0 + 1e-12)
    if ax * ax + ay * ay > far * far * (1.0 + 1e-12):
        return math.inf
    if si == 0.0 or sj == 0.0:
        # One ball at rest: the other's centre runs along a straight segment of length ``reach`` (its direction is
        # fixed between events). If that segment stays clear of the resting ball's contact circle (margins far
        # above round-off), the quartic below has no root in the window either: most pairs end here.
        if si > 0.0:
            rx, ry, ux, uy = -ax, -ay, vxi / si, vyi / si
        else:
            rx, ry, ux, uy = ax, ay, vxj / sj, vyj / sj
        along = rx * ux + ry * uy
        clear = dc * (1.0 + 1e-9) + 1e-9
        if along <= 0.0:
            if rx * rx + ry * ry > clear * clear:  # (on squares: the same margins, no square root)
                return math.inf
        elif along >= reach:
            ex = rx - ux * reach
            ey = ry - uy * reach
            if ex * ex + ey * ey > clear * clear:
                return math.inf
        elif abs(rx * uy - ry * ux) > clear:
            return math.inf
    bx = vxi - vxj
    by = vyi - vyj
    closing_tol = 2.0 * dc * (1e-12 + 1e-14 * (si + sj))
    c0 = ax * ax + ay * ay - dc * dc
    c1 = 2.0 * (ax * bx + ay * by)
    if law == ROLLING and a > 0.0:
        cx = 0.0
        cy = 0.0
        if si > 0.0:
            cx -= 0.5 * a * vxi / si
            cy -= 0.5 * a * vyi / si
        if sj > 0.0:
            cx += 0.5 * a * vxj / sj
            cy += 0.5 * a * vyj / sj
        c4 = cx * cx + cy * cy
        c3 = 2.0 * (bx * cx + by * cy)
        c2 = bx * bx + by * by + 2.0 * (ax * cx + ay * cy)
        # Bound before solving: the relative path A + B t + C t^2 over the window lies in the triangle of its control
        # points; clear of the contact circle there (margins far above round-off), the quartic has no root.
        if path_box_clear(0.0, 0.0, dc, ax, ay, bx, by, 2.0 * cx, 2.0 * cy, window):
            return math.inf
        tau = first_entry(c4, c3, c2, c1, c0, window, closing_tol)
        return t + tau
    # Drag or no friction: both balls follow p + v * phi(t) with the same phi, so |A + B phi|^2 is quadratic.
    c2 = bx * bx + by * by
    phi = first_entry(0.0, 0.0, c2, c1, c0, drag_phi(window, k), closing_tol)
    if phi == math.inf:
        return math.inf
    return t + min(drag_time_for_phi(phi, k), window)


@internal
def _jam_cluster(seed, t, t0, p0, v0, sp0, tstop, radius, mass, on_table, burst, prm, involved):
    """Jam the contact cluster of ball ``seed`` (see :mod:`.collide`): every ball touching it, directly or
    through others, moves on with the cluster's centre-of-mass velocity, less any component into a cushion a
    member touches. Writes the members into ``involved``; returns their count."""
    n = p0.shape[0]
    law = prm.law
    a = prm.decel
    k = prm.drag_k
    pxy = np.empty((2, n))
    px = pxy[0]
    py = pxy[1]
    for m in range(n):
        if on_table[m]:
            px[m], py[m], _, _ = state_at(m, t, t0, p0, v0, sp0, tstop, law, a, k)
    count = contact_cluster(seed, px, py, radius, on_table, involved)
    total = 0.0
    mom_x = 0.0
    mom_y = 0.0
    for h in range(count):
        m = involved[h]
        _advance_only(m, t, t0, p0, v0, sp0, tstop, law, a, k)  # (its velocity and speed are set below)
        total += mass[m]
        mom_x += mass[m] * v0[m, 0]
        mom_y += mass[m] * v0[m, 1]
    cx = mom_x / total
    cy = mom_y / total
    walls = has_walls(prm)
    if walls:
        cx, cy = cluster_off_walls(p0[:, 0], p0[:, 1], radius, involved, count, cx, cy, prm)
    for h in range(count):
        m = involved[h]
        if walls:
            continue
        r = radius[m] + 1e-9
        if (p0[m, 0] <= r and cx < 0.0) or (p0[m, 0] >= prm.length - r and cx > 0.0):
            cx = 0.0
        if (p0[m, 1] <= r and cy < 0.0) or (p0[m, 1] >= prm.width - r and cy > 0.0):
            cy = 0.0
    for h in range(count):
        m = involved[h]
        v0[m, 0] = cx
        v0[m, 1] = cy
        burst[m] = 0
        _set_stop_time(m, t0, v0, sp0, tstop, law, a, k, prm.min_speed)
    return count


@inlined
def _log_state(n_sc, sc_t, sc_ball, sc_state, t, i, p0, v0, on_table):
    sc_t[n_sc] = t
    sc_ball[n_sc] = i
    sc_state[n_sc, 0] = p0[i, 0]
    sc_state[n_sc, 1] = p0[i, 1]
    sc_state[n_sc, 2] = v0[i, 0]
    sc_state[n_sc, 3] = v0[i, 1]
    sc_state[n_sc, 4] = 1.0 if on_table[i] else 0.0


#: Events the event log has room for before it grows (by doubling, in the shot that needs it).
_EVENT_ROOM = 64


@internal
def exact_scratch(n):
    """The rolling kernel's scratch arrays for ``n`` balls, one allocation per array (:func:`simulate_exact_in`
    reads and writes them; every value is set in a shot before it is read, so one scratch serves shot after shot):
    the per-ball float and int rows, the start positions and velocities, the pairs' times, the balls' states at the
    current event, the event log, and the state log of a shot not recorded (a shot recorded makes its own)."""
    return (np.empty((7, n)), np.empty((6, n), np.int64), np.empty((n, 2)), np.empty((n, 2)), np.empty((n, n)),
            np.empty((n, 5)), np.empty(_EVENT_ROOM), np.empty((_EVENT_ROOM, 3), np.int64), np.empty(_EVENT_ROOM),
            np.empty(1), np.empty(1, np.int64), np.empty((1, 5)))


@njit(cache=True)
def simulate_exact(pos, vel, ang, radius, mass, on_table, pocket_xy, pocket_r, params, max_events, record):
    """Simulate one shot from ``pos``/``vel`` (updated in place to the final state) until rest or a cap.

    ``ang`` (angular velocities) is not read: the rolling and drag laws have no spin; it is there so that every
    exact kernel takes the same arguments (:mod:`.kernels`).

    ``params``: the parameter record (:mod:`.kernel_io`). Returns a :class:`~.kernel_io.KernelResult`: the
    event log (time; kind, ball, other; impact speed) and, when ``record``, the log of state changes (time,
    ball, ``x y vx vy on_table`` after each event) from which the trajectory is exact.
    """
    return simulate_exact_in(exact_scratch(pos.shape[0]), pos, vel, ang, radius, mass, on_table, pocket_xy, pocket_r,
                             params, max_events, record)


@internal
def simulate_exact_in(scratch, pos, vel, ang, radius, mass, on_table, pocket_xy, pocket_r, params, max_events,
                      record):
    """:func:`simulate_exact` in the scratch arrays ``scratch`` (:func:`exact_scratch` of the balls' count): callers
    that simulate shot after shot (the batch rows, the pot scenes' step) make them once, not a dozen arrays a shot.
    The result's arrays are views of the scratch (or of a grown event log): read them before the next shot."""
    prm = params[0]
    n = pos.shape[0]
    law = prm.law
    a = prm.decel
    k = prm.drag_k
    v_min = prm.min_speed
    e_c = prm.e_cushion
    e_b = prm.e_ball
    max_time = prm.max_time
    floor = prm.speed_floor
    decel = a if law == ROLLING else 0.0

    # The scratch's arrays (exact_scratch), as rows per ball: a few arrays rather than one per quantity (fewer to make
    # and to pass). (Not one buffer for everything, as the spin kernel's: here its views' reshapes cost more.)
    fw, iw, p0, v0, pair_t, st, ev_t, ev_int, ev_speed, sc_t, sc_ball, sc_state = scratch
    t0 = fw[0]
    t_hit = fw[1]  # time of each ball's last collision (ball or cushion)
    tstop = fw[2]
    pocket_time = fw[3]
    ball_t = fw[4]
    row_t = fw[5]  # each pair row's earliest collision (kernel_logs.set_pair), at pair (i, row_j[i])
    sp0 = fw[6]  # each ball's speed at its last event: hypot of v0 (set with it)
    burst = iw[0]  # collisions of each ball in its current contact cluster
    pocket_of = iw[1]
    ball_kind = iw[2]
    ball_other = iw[3]
    involved = iw[4]
    row_j = iw[5]
    for i in range(n):
        t0[i] = 0.0
        t_hit[i] = -math.inf
        tstop[i] = 0.0
        pocket_time[i] = np.nan
        ball_t[i] = math.inf
        burst[i] = 0
        pocket_of[i] = -1
        ball_kind[i] = -1
        ball_other[i] = -1
    for i in range(n):
        p0[i, 0] = pos[i, 0]
        p0[i, 1] = pos[i, 1]
        v0[i, 0] = vel[i, 0]
        v0[i, 1] = vel[i, 1]
    for i in range(n):
        if on_table[i]:
            _set_stop_time(i, t0, v0, sp0, tstop, law, a, k, v_min)
        else:
            v0[i, 0] = 0.0
            v0[i, 1] = 0.0
            sp0[i] = 0.0

    # pair_t: the pairs' collision times; st: the balls' states at the current event (x, y, vx, vy, speed).
    for i in range(n):
        for j in range(n):
            pair_t[i, j] = math.inf
    for i in range(n):
        if on_table[i]:
            ball_t[i], ball_kind[i], ball_other[i] = predict_ball(i, t0, p0, v0, sp0, tstop, radius, pocket_xy,
                                                                   pocket_r, prm)
    for i in range(n):
        rest_i = v0[i, 0] == 0.0 and v0[i, 1] == 0.0
        for j in range(i + 1, n):
            # Two balls at rest never meet (the pair stays at inf, as _pair_time would say).
            if on_table[i] and on_table[j] and not (rest_i and v0[j, 0] == 0.0 and v0[j, 1] == 0.0):
                pair_t[i, j] = _predict_pair(i, j, 0.0, t0, p0, v0, sp0, tstop, ball_t, radius, prm)
        rescan_row(pair_t, row_t, row_j, i)

    if record:  # room for every ball's start and a few events (grown by doubling when full)
        sc_t = np.empty(2 * n + 16)
        sc_ball = np.empty(2 * n + 16, np.int64)
        sc_state = np.empty((2 * n + 16, 5))
    n_sc = _ZERO
    if record:
        for i in range(n):
            _log_state(n_sc, sc_t, sc_ball, sc_state, 0.0, i, p0, v0, on_table)
            n_sc += 1

    t = 0.0
    n_events = 0
    status = STATUS_REST
    while True:
        best, kind, bi, bj = next_event(ball_t, ball_kind, ball_other, row_t, row_j)
        if not best <= max_time:
            moving = False
            for i in range(n):
                if on_table[i] and (v0[i, 0] != 0.0 or v0[i, 1] != 0.0):
                    moving = True
            if moving:
                status = STATUS_TIME_CAP
                t = max_time
            else:
                status = STATUS_REST
            break
        if n_events >= max_events:
            status = STATUS_EVENT_CAP
            break
        t = max(best, t)
        n_inv = 1
        involved[0] = bi
        speed = 0.0
        if kind == EV_COLLISION:
            _advance_only(bi, t, t0, p0, v0, sp0, tstop, law, a, k)
            _advance_only(bj, t, t0, p0, v0, sp0, tstop, law, a, k)
            dx = p0[bi, 0] - p0[bj, 0]
            dy = p0[bi, 1] - p0[bj, 1]
            dist = math.hypot(dx, dy)
            clustered = count_burst(bi, t, t_hit, burst) | count_burst(bj, t, t_hit, burst)
            if burst[bi] > JAM_EVENTS or burst[bj] > JAM_EVENTS:
                sp0[bi] = math.hypot(v0[bi, 0], v0[bi, 1])
                sp0[bj] = math.hypot(v0[bj, 0], v0[bj, 1])
                n_inv = _jam_cluster(bi, t, t0, p0, v0, sp0, tstop, radius, mass, on_table, burst, prm, involved)
                kind = EV_JAM
                bj = n_inv
            else:
                if dist > 0.0:
                    speed = resolve_ball_ball(v0, bi, bj, dx / dist, dy / dist, dist, mass[bi], mass[bj], e_b,
                                              decel, floor, clustered)
                _set_stop_time(bi, t0, v0, sp0, tstop, law, a, k, v_min)
                _set_stop_time(bj, t0, v0, sp0, tstop, law, a, k, v_min)
                involved[1] = bj
                n_inv = 2
        elif kind == EV_CUSHION:
            _advance_only(bi, t, t0, p0, v0, sp0, tstop, law, a, k)
            r = radius[bi]
            if has_walls(prm):
                p0[bi, 0], p0[bi, 1] = touch_wall(p0[bi, 0], p0[bi, 1], r, bj, prm)
            elif bj == 0:
                p0[bi, 0] = r
            elif bj == 1:
                p0[bi, 0] = prm.length - r
            elif bj == 2:
                p0[bi, 1] = r
            else:
                p0[bi, 1] = prm.width - r
            count_burst(bi, t, t_hit, burst)
            if burst[bi] > JAM_EVENTS:
                sp0[bi] = math.hypot(v0[bi, 0], v0[bi, 1])
                n_inv = _jam_cluster(bi, t, t0, p0, v0, sp0, tstop, radius, mass, on_table, burst, prm, involved)
                kind = EV_JAM
                bj = n_inv
            else:
                if has_walls(prm):
                    nx, ny = wall_normal_at(p0[bi, 0], p0[bi, 1], bj, prm)
                    speed = reflect_off(v0, bi, nx, ny, e_c)
                else:
                    speed = resolve_cushion(v0, bi, bj, e_c)
                _set_stop_time(bi, t0, v0, sp0, tstop, law, a, k, v_min)
        elif kind == EV_POCKET:
            _advance(bi, t, t0, p0, v0, sp0, tstop, law, a, k)
            speed = sp0[bi]
            on_table[bi] = False
            v0[bi, 0] = 0.0
            v0[bi, 1] = 0.0
            sp0[bi] = 0.0
            tstop[bi] = t
            pocket_of[bi] = bj
            pocket_time[bi] = t
        else:  # EV_STOP
            _advance_only(bi, t, t0, p0, v0, sp0, tstop, law, a, k)
            v0[bi, 0] = 0.0
            v0[bi, 1] = 0.0
            sp0[bi] = 0.0
            tstop[bi] = t

        if n_events >= ev_t.shape[0]:  # (the log written in place; grown by doubling only when full)
            ev_t, ev_int, ev_speed = reserve_events(ev_t, ev_int, ev_speed, n_events + 1)
        ev_t[n_events] = t
        ev_int[n_events, 0] = kind
        ev_int[n_events, 1] = bi
        ev_int[n_events, 2] = bj
        ev_speed[n_events] = speed
        n_events += 1

        have_states = False
        for q in range(n_inv):
            i = involved[q]
            if record:
                if n_sc >= sc_t.shape[0]:
                    sc_t, sc_ball, sc_state = reserve_states(sc_t, sc_ball, sc_state, n_sc)
                _log_state(n_sc, sc_t, sc_ball, sc_state, t, i, p0, v0, on_table)
                n_sc += 1
            if not on_table[i]:
                ball_t[i] = math.inf
                for m in range(i):
                    set_pair(pair_t, row_t, row_j, m, i, math.inf)
                for m in range(i + 1, n):
                    pair_t[i, m] = math.inf
                row_t[i] = math.inf
                row_j[i] = -1
                continue
            ball_t[i], ball_kind[i], ball_other[i] = predict_ball(i, t0, p0, v0, sp0, tstop, radius, pocket_xy,
                                                                   pocket_r, prm)
            if not have_states:  # every ball's state at t, once for all the involved balls' pairs
                for m in range(n):
                    if not on_table[m]:
                        continue
                    if v0[m, 0] == 0.0 and v0[m, 1] == 0.0:  # at rest (what state_at says, without its hypot)
                        st[m, 0] = p0[m, 0]
                        st[m, 1] = p0[m, 1]
                        st[m, 2] = 0.0
                        st[m, 3] = 0.0
                        st[m, 4] = 0.0
                    else:
                        st[m, 0], st[m, 1], st[m, 2], st[m, 3] = state_at(m, t, t0, p0, v0, sp0, tstop, law, a,
                                                                           k)
                        st[m, 4] = math.hypot(st[m, 2], st[m, 3])
                have_states = True
            xi = st[i, 0]
            yi = st[i, 1]
            vxi = st[i, 2]
            vyi = st[i, 3]
            rest_i = vxi == 0.0 and vyi == 0.0
            # The pair of two involved balls (a collision's) is worked out once, at the second (whose own prediction,
            # which the pair's window reads, is new by then): at the first, the pair holds inf meanwhile.
            later = involved[1] if q == 0 and n_inv == 2 else -1
            for m in range(n):
                if m == i:
                    continue
                tm = math.inf
                if m == later:
                    pass
                elif on_table[m]:
                    xm = st[m, 0]
                    ym = st[m, 1]
                    vxm = st[m, 2]
                    vym = st[m, 3]
                    if rest_i and vxm == 0.0 and vym == 0.0:  # two balls at rest never meet
                        tm = math.inf
                    elif i < m:
                        tm = pair_time_s(i, m, t, xi, yi, vxi, vyi, st[i, 4], xm, ym, vxm, vym, st[m, 4], ball_t,
                                          radius, prm)
                    else:
                        tm = pair_time_s(m, i, t, xm, ym, vxm, vym, st[m, 4], xi, yi, vxi, vyi, st[i, 4], ball_t,
                                          radius, prm)
                if i < m:  # row i is scanned again below, once written
                    pair_t[i, m] = tm
                else:
                    set_pair(pair_t, row_t, row_j, m, i, tm)
            rescan_row(pair_t, row_t, row_j, i)

    for i in range(n):
        if on_table[i]:
            x, y, vx, vy = state_at(i, t, t0, p0, v0, sp0, tstop, law, a, k)
            pos[i, 0] = x
            pos[i, 1] = y
            vel[i, 0] = vx
            vel[i, 1] = vy
        else:
            pos[i, 0] = p0[i, 0]
            pos[i, 1] = p0[i, 1]
            vel[i, 0] = 0.0
            vel[i, 1] = 0.0
    return KernelResult(status, t, n_events, pocket_of, pocket_time, ev_t[:n_events], ev_int[:n_events],
                        ev_speed[:n_events], sc_t[:n_sc], sc_ball[:n_sc], sc_state[:n_sc], 0, 0)
