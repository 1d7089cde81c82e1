"""The ``exact`` solver of the spin model: event-driven, closed-form motion between events (numba kernel).

The same algorithm as :mod:`.exact` (the ``rolling`` and ``drag`` kernel, which this module leaves alone):
every ball carries its state at its last event and the piece of motion it is on (:mod:`.spin_motion`); the
solver keeps the next event time of every ball and of every pair, jumps to the earliest, applies it, and
recomputes only the times of the balls it changed. Resting and pocketed balls cost nothing.

Events: ball-ball collision (a quartic: both centres on quadratic paths), cushion (a quadratic), pocket
capture (a quartic), and the motion transitions at their closed-form times: a sliding ball starts rolling
(``roll``), a rolling ball stops moving but keeps spinning (``spin``) or comes to rest (``stop``), a spinning
ball comes to rest (``stop``). Simultaneous events are taken as in :mod:`.exact`: ball events (by row) before
pair events (by ``(i, j)``). The inelastic-collapse guards of :mod:`.collide` (same-instant floor, jam) apply
as they are; the pressed-contact rules of :mod:`.spin_collide` replace the rolling law's sticky contact.
The event loop's stages (:func:`state_at`, :func:`predict_ball`, :func:`pair_from_states`) are public, as in
:mod:`.exact`.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .codes import (EV_COLLISION, EV_CUSHION, EV_JAM, EV_POCKET, EV_ROLL, EV_SPIN, EV_STOP, MS_POCKETED,
                    MS_ROLLING, MS_SLIDING, MS_SPINNING, MS_STATIONARY, STATUS_EVENT_CAP, STATUS_REST,
                    STATUS_TIME_CAP)
from .collide import JAM_EVENTS
from .kernel_io import N_STATE_COLS_SPIN, KernelResult
from .kernel_logs import (carve, contact_cluster, count_burst, inlined, internal, leaf, next_event, pocket_holding,
                          rescan_row, reserve_events, reserve_states, set_pair)
from .roots import first_entry
from .cushion_models import wall_hit
from .spin_collide import ball_hit, is_pressed_pair, merge_pair, settle_on_cushion, settle_on_wall, wall_normal
from .walls import (MAX_WALL_PASSES, has_walls, path_box_clear, path_clear_of, path_wall_time, pushes_into_walls,
                    touch_wall, wall_gap,
                    wall_normal_at, wall_time)
from .spin_motion import advance, classify, piece_of, reach, reach_of, roll_on, slide_end, spin_decay_rate, transition
from .plain import plain

#: Typed (non-literal) rows of the two-row scratch arrays: a literal 0 or 1 passed to a compiled law would make
#: numba compile a second specialisation of it.
_ROW0 = np.int64(0)
_ROW1 = np.int64(1)

# Columns of the per-ball motion table ``bs``: the state at the ball's last event (time T0), and its piece.
T0, X, Y, VX, VY, WX, WY, WZ, AX, AY, DWX, DWY, ALPHA, TEND = range(14)
N_COLS = 14
#: The ball's own next event is its motion transition (internal kind; logged as roll, spin or stop).
_TRANSITION = 100


@leaf
def _set_piece(bs, st, i, state, r, f_slide, f_roll, f_spin):
    """Start ball ``i`` on the ``state`` piece from its stored state (made exact by :func:`piece_of`)."""
    c = piece_of(state, bs[i, VX], bs[i, VY], bs[i, WX], bs[i, WY], bs[i, WZ], r, f_slide, f_roll, f_spin)
    bs[i, VX] = c[0]
    bs[i, VY] = c[1]
    bs[i, WX] = c[2]
    bs[i, WY] = c[3]
    bs[i, WZ] = c[4]
    bs[i, AX] = c[5]
    bs[i, AY] = c[6]
    bs[i, DWX] = c[7]
    bs[i, DWY] = c[8]
    bs[i, TEND] = bs[i, T0] + c[9]
    st[i] = state


@leaf
def _classify_piece(bs, st, i, r, f_slide, f_roll, f_spin):
    """Start ball ``i`` on the piece its stored state calls for (a ball found rolling, its slip round-off, is
    put on rolling by :func:`.spin_motion.roll_on`)."""
    state = classify(bs[i, VX], bs[i, VY], bs[i, WX], bs[i, WY], bs[i, WZ], r)
    if state == MS_ROLLING:
        bs[i, VX], bs[i, VY], bs[i, WX], bs[i, WY] = roll_on(bs[i, VX], bs[i, VY], bs[i, WX], bs[i, WY], r)
    _set_piece(bs, st, i, state, r, f_slide, f_roll, f_spin)


@inlined
def state_at(bs, i, t):
    """``(x, y, vx, vy, wx, wy, wz)`` of ball ``i`` at time ``t`` (not past its piece's end)."""
    tau = min(t, bs[i, TEND]) - bs[i, T0]
    if not tau > 0.0:
        return bs[i, X], bs[i, Y], bs[i, VX], bs[i, VY], bs[i, WX], bs[i, WY], bs[i, WZ]
    return advance(tau, bs[i, X], bs[i, Y], bs[i, VX], bs[i, VY], bs[i, WX], bs[i, WY], bs[i, WZ], bs[i, AX],
                   bs[i, AY], bs[i, DWX], bs[i, DWY], bs[i, ALPHA])


@inlined
def _move_to(bs, i, t):
    """Move ball ``i``'s reference state to time ``t`` (on the same piece)."""
    x, y, vx, vy, wx, wy, wz = state_at(bs, i, t)
    bs[i, X] = x
    bs[i, Y] = y
    bs[i, VX] = vx
    bs[i, VY] = vy
    bs[i, WX] = wx
    bs[i, WY] = wy
    bs[i, WZ] = wz
    bs[i, T0] = t


@leaf
def predict_ball(i, bs, st, radius, pocket_xy, pocket_r, length, width, max_time, prm):
    """Next own event of ball ``i``: ``(time, kind, other)``: pocket, cushion, or its motion transition."""
    t0 = bs[i, T0]
    t_end = bs[i, TEND]
    x = bs[i, X]
    y = bs[i, Y]
    if st[i] == MS_STATIONARY or st[i] == MS_SPINNING:
        # Not moving: only a ball placed inside a capture circle has a pocket event (at once).
        q = pocket_holding(x, y, pocket_xy, pocket_r)
        if q >= 0:
            return t0, EV_POCKET, q
        if st[i] == MS_SPINNING:
            return t_end, _TRANSITION, -1
        return math.inf, -1, -1
    vx = bs[i, VX]
    vy = bs[i, VY]
    ax = bs[i, AX]
    ay = bs[i, AY]
    window = min(t_end, max_time) - t0
    far = reach(window, vx, vy, ax, ay) * (1.0 + 1e-9) + 1e-12  # no pocket farther than this can be reached
    best = math.inf
    kind = -1
    other = -1
    # Pockets first, so that a pocket and a cushion at the same instant go to the pocket.
    for q in range(pocket_r.shape[0]):
        dx = x - pocket_xy[q, 0]
        dy = y - pocket_xy[q, 1]
        c0 = dx * dx + dy * dy - pocket_r[q] * pocket_r[q]
        if c0 <= 0.0:
            tau = 0.0
        elif math.sqrt(dx * dx + dy * dy) - pocket_r[q] > far:
            continue
        elif path_box_clear(pocket_xy[q, 0], pocket_xy[q, 1], pocket_r[q], x, y, vx, vy, ax, ay, window) or \
                path_clear_of(pocket_xy[q, 0], pocket_xy[q, 1], pocket_r[q], x, y, vx, vy, ax, ay, window):
            continue
        else:
            tau = first_entry(0.25 * (ax * ax + ay * ay), vx * ax + vy * ay, vx * vx + vy * vy + dx * ax + dy * ay,
                              2.0 * (dx * vx + dy * vy), c0, window, 0.0)
        if tau < best:
            best = tau
            kind = EV_POCKET
            other = q
    r = radius[i]
    tol = 1e-12 + 1e-14 * math.hypot(vx, vy)
    if has_walls(prm):  # a jaw table: rails, jaw faces, tips
        # A ball settled on a slanted wall (the pressed rule) keeps round-off in its slip's normal part, about 1e-16
        # of |v| + R |w|; its acceleration's normal part is that over the slip (sliding) or the speed (rolling), times
        # |a|: below it, the acceleration does not press the ball in (else a storm of hits at one instant).
        wx = bs[i, WX]
        wy = bs[i, WY]
        scale = math.hypot(vx, vy) + r * math.sqrt(wx * wx + wy * wy + bs[i, WZ] * bs[i, WZ])
        slip = math.hypot(vx - r * wy, vy + r * wx) if st[i] == MS_SLIDING else math.hypot(vx, vy)
        acc_tol = tol
        if slip > 0.0:
            acc_tol += 1e-13 * math.hypot(ax, ay) * scale / slip
        tau, wall = path_wall_time(x, y, vx, vy, ax, ay, r, window, tol, acc_tol, far, prm)
        if tau < best:
            best = tau
            kind = EV_CUSHION
            other = wall
        if kind >= 0 and t0 + best <= t_end:
            return t0 + best, kind, other
        return t_end, _TRANSITION, -1
    for cush in range(4):
        if cush == 0:
            tau = wall_time(0.5 * ax, vx, x - r, window, tol)
        elif cush == 1:
            tau = wall_time(-0.5 * ax, -vx, length - r - x, window, tol)
        elif cush == 2:
            tau = wall_time(0.5 * ay, vy, y - r, window, tol)
        else:
            tau = wall_time(-0.5 * ay, -vy, width - r - y, window, tol)
        if tau < best:
            best = tau
            kind = EV_CUSHION
            other = cush
    if kind >= 0 and t0 + best <= t_end:
        return t0 + best, kind, other
    return t_end, _TRANSITION, -1


@leaf
def _predict_pair(i, j, t, bs, ball_t, radius, max_time):
    """Time of the next collision of balls ``i`` and ``j`` after ``t``; ``inf`` if none before either ball's
    next own event (which recomputes the pair anyway)."""
    xi, yi, vxi, vyi, _, _, _ = state_at(bs, i, t)
    xj, yj, vxj, vyj, _, _, _ = state_at(bs, j, t)
    return pair_from_states(i, j, t, xi, yi, vxi, vyi, bs[i, AX], bs[i, AY], math.hypot(vxi, vyi),
                             math.hypot(bs[i, AX], bs[i, AY]), xj, yj, vxj, vyj, bs[j, AX], bs[j, AY],
                             math.hypot(vxj, vyj), math.hypot(bs[j, AX], bs[j, AY]), ball_t, radius, max_time)


@internal
def pair_from_states(i, j, t, xi, yi, vxi, vyi, axi, ayi, hvi, hai, xj, yj, vxj, vyj, axj, ayj, hvj, haj, ball_t,
                      radius, max_time):
    """:func:`_predict_pair` from both balls' states at ``t`` (``i < j``: position, velocity, the piece's
    acceleration, and the ``hypot`` of the velocity and of the acceleration), worked out once per ball for all its
    pairs."""
    if vxi == 0.0 and vyi == 0.0 and vxj == 0.0 and vyj == 0.0 and axi == 0.0 and ayi == 0.0 and axj == 0.0 \
            and ayj == 0.0:
        return math.inf
    window = min(max_time, ball_t[i], ball_t[j]) - t
    if not window > 0.0:
        return math.inf
    dc = radius[i] + radius[j]
    ax = xi - xj
    ay = yi - yj
    # Cull pairs too far apart to meet within the window (spin_motion.reach_of, from the hypots given), on squares
    # (margins far above round-off: a pair left in by round-off at the margin has no root, which the bound below or
    # the root finder says).
    lim = (reach_of(window, hvi, hai) + reach_of(window, hvj, haj)) * (1.0 + 1e-9) + 1e-12
    far = (dc + lim) * (1.0 + 1e-12)
    if ax * ax + ay * ay > far * far * (1.0 + 1e-12):
        return math.inf
    bx = vxi - vxj
    by = vyi - vyj
    cx = 0.5 * (axi - axj)
    cy = 0.5 * (ayi - ayj)
    closing_tol = 2.0 * dc * (1e-12 + 1e-14 * (hvi + hvj))
    # Bound before solving: the relative path over the window lies in the triangle of its control points; clear of
    # the contact circle there (margins far above round-off), the quartic has no root.
    if path_box_clear(0.0, 0.0, dc, ax, ay, bx, by, 2.0 * cx, 2.0 * cy, window):
        return math.inf
    tau = first_entry(cx * cx + cy * cy, 2.0 * (bx * cx + by * cy), bx * bx + by * by + 2.0 * (ax * cx + ay * cy),
                      2.0 * (ax * bx + ay * by), ax * ax + ay * ay - dc * dc, window, closing_tol)
    return t + tau


@internal
def _slow_run(i, j, slow, slow_with, slow_runs):
    """Count a collision of ``i`` and ``j`` towards their run of slow re-contacts (closing slower than the speed
    floor, one after another with no faster one between); returns the run's length (0 after a fast one).

    A ball that keeps pushing another one (friction drives it on, say a rolling ball without rolling
    resistance behind a sliding one) hits it again and again at ever smaller speeds, but with pauses too long
    for the jam's burst count. More than ``JAM_EVENTS`` such hits in a row are a sustained contact: the pair is
    merged by the pressed-pair rule."""
    if not slow:
        slow_runs[i] = 0
        slow_runs[j] = 0
        return 0
    for a, b in ((i, j), (j, i)):
        if slow_with[a] == b:
            slow_runs[a] += 1
        else:
            slow_with[a] = b
            slow_runs[a] = 1
    return min(slow_runs[i], slow_runs[j])


@leaf
def _copy_motion(bs, st, src, dst, radius, f_slide, f_roll, f_spin):
    """Give ball ``dst``, which has the velocity and surface velocity ``R (wx, wy)`` of ``src``, the piece of
    ``src`` (acceleration and end), so a merged pair or cluster moves as one: its gaps stay exactly as they
    are. Each keeps its own ``wz``; so balls that do not move are classified on their own (spinning or not)."""
    if st[src] != MS_SLIDING and st[src] != MS_ROLLING:
        _classify_piece(bs, st, dst, radius[dst], f_slide, f_roll, f_spin)
        return
    k = radius[src] / radius[dst]
    bs[dst, VX] = bs[src, VX]
    bs[dst, VY] = bs[src, VY]
    bs[dst, WX] = bs[src, WX] * k
    bs[dst, WY] = bs[src, WY] * k
    bs[dst, AX] = bs[src, AX]
    bs[dst, AY] = bs[src, AY]
    bs[dst, DWX] = bs[src, DWX] * k
    bs[dst, DWY] = bs[src, DWY] * k
    bs[dst, TEND] = bs[src, TEND]
    st[dst] = st[src]


@internal
def _touching_wall(x, y, r, length, width, wall):
    if wall == 0:
        return x <= r
    if wall == 1:
        return x >= length - r
    if wall == 2:
        return y <= r
    return y >= width - r


@leaf
def _jaw_jam_velocity(bs, radius, involved, count, cx, cy, qx, qy, prm):
    """A jammed cluster's velocity ``(cx, cy)`` and mean surface velocity ``(qx, qy)`` on a jaw table: less any
    component into a wall a member touches, and less the surface velocity's part that drives the cluster into it
    (as the capture table's cushions below). One wall at a time can put back a component into another wall the
    cluster is wedged against (two jaw faces, a face and a rail): the passes repeat (at most ``MAX_WALL_PASSES``),
    and a cluster still pushing into a wall after them has no free direction between its walls: it stops (no
    velocity, no surface velocity; each ball keeps its ``wz``)."""
    for _ in range(MAX_WALL_PASSES):
        for h in range(count):
            m = involved[h]
            for wall in range(prm.n_segs + prm.n_tips):
                g = wall_gap(bs[m, X], bs[m, Y], radius[m], wall, prm)
                if g <= 1e-9 and g > -radius[m]:
                    nx, ny = wall_normal_at(bs[m, X], bs[m, Y], wall, prm)
                    vn = cx * nx + cy * ny
                    if vn < 0.0:  # into the cushion
                        cx -= vn * nx
                        cy -= vn * ny
                    # The surface velocity's part along n, (z^ x q) . n = qx ny - qy nx, if it drives the cluster in,
                    # goes with the normal velocity.
                    sn = qx * ny - qy * nx
                    vn = cx * nx + cy * ny
                    if vn <= prm.speed_floor and vn + sn > 0.0:
                        cx -= vn * nx
                        cy -= vn * ny
                        qx -= sn * ny
                        qy += sn * nx
        free = True
        for h in range(count):
            m = involved[h]
            if pushes_into_walls(bs[m, X], bs[m, Y], radius[m], cx, cy, prm):
                free = False
                break
        if free:
            return cx, cy, qx, qy
    return 0.0, 0.0, 0.0, 0.0


@internal
def _jam_cluster(seed, t, bs, st, radius, mass, on_table, burst, prm, f_slide, f_roll, f_spin, involved):
    """Jam the contact cluster of ball ``seed`` (see :mod:`.collide`): every ball touching it, directly or
    through others, moves on with the cluster's centre-of-mass velocity, less any component into a cushion a
    member touches, and its mass-weighted mean surface velocity ``R (wx, wy)``, less any part that would
    drive it into such a cushion; each keeps its ``wz``. Writes the members into ``involved``; returns their
    count."""
    n = bs.shape[0]
    length = prm.length
    width = prm.width
    pxy = np.empty((2, n))
    px = pxy[0]
    py = pxy[1]
    for m in range(n):
        if on_table[m]:
            px[m], py[m], _, _, _, _, _ = state_at(bs, m, t)
    count = contact_cluster(seed, px, py, radius, on_table, involved)
    total = 0.0
    mom_x = 0.0
    mom_y = 0.0
    qx = 0.0
    qy = 0.0
    for h in range(count):
        m = involved[h]
        _move_to(bs, m, t)
        total += mass[m]
        mom_x += mass[m] * bs[m, VX]
        mom_y += mass[m] * bs[m, VY]
        qx += mass[m] * radius[m] * bs[m, WX]
        qy += mass[m] * radius[m] * bs[m, WY]
    cx = mom_x / total
    cy = mom_y / total
    qx /= total
    qy /= total
    walls = has_walls(prm)
    if walls:
        cx, cy, qx, qy = _jaw_jam_velocity(bs, radius, involved, count, cx, cy, qx, qy, prm)
    for h in range(count):
        m = involved[h]
        r = radius[m] + 1e-9
        if walls:
            continue
        for wall in range(4):
            if _touching_wall(bs[m, X], bs[m, Y], r, length, width, wall):
                nx, ny = wall_normal(wall)
                if cx * nx + cy * ny < 0.0:  # into the cushion
                    if nx != 0.0:
                        cx = 0.0
                    else:
                        cy = 0.0
                # Slip along n (with z^ x q = (-qy, qx)); friction drives the cluster in if it is positive.
                if (cx * nx + cy * ny) <= prm.speed_floor and (cx - qy) * nx + (cy + qx) * ny > 0.0:
                    if nx != 0.0:
                        cx = 0.0
                        qy = 0.0
                    else:
                        cy = 0.0
                        qx = 0.0
    first = involved[0]
    for h in range(count):
        m = involved[h]
        bs[m, VX] = cx
        bs[m, VY] = cy
        bs[m, WX] = qx / radius[m]
        bs[m, WY] = qy / radius[m]
        burst[m] = 0
        if h == 0:
            _classify_piece(bs, st, m, radius[m], f_slide, f_roll, f_spin)
        else:
            _copy_motion(bs, st, first, m, radius, f_slide, f_roll, f_spin)
    return count


@inlined
def _log_state(n_sc, sc_t, sc_ball, sc_state, t, i, bs, st, on_table):
    sc_t[n_sc] = t
    sc_ball[n_sc] = i
    sc_state[n_sc, 0] = bs[i, X]
    sc_state[n_sc, 1] = bs[i, Y]
    sc_state[n_sc, 2] = bs[i, VX]
    sc_state[n_sc, 3] = bs[i, VY]
    sc_state[n_sc, 4] = 1.0 if on_table[i] else 0.0
    sc_state[n_sc, 5] = bs[i, WX]
    sc_state[n_sc, 6] = bs[i, WY]
    sc_state[n_sc, 7] = bs[i, WZ]
    sc_state[n_sc, 8] = st[i]


@njit(cache=True)
def simulate_exact_spin(pos, vel, ang, radius, mass, on_table, pocket_xy, pocket_r, params, max_events, record):
    """Simulate one shot of the spin model from ``pos``/``vel``/``ang`` (updated in place to the final state)
    until rest or a cap.

    ``params``: the parameter record (:mod:`.kernel_io`). Returns a :class:`~.kernel_io.KernelResult`: the
    event log and, when ``record``, the log of state changes (time, ball, ``x y vx vy on_table wx wy wz
    motion_state`` after each event) from which the trajectory is exact.
    """
    prm = params[0]
    n = pos.shape[0]
    g = prm.g
    f_slide = prm.mu_slide * g
    f_roll = prm.mu_roll * g
    f_spin = prm.mu_spin * g
    e_c = prm.e_cushion
    max_time = prm.max_time
    floor = prm.speed_floor
    length = prm.length
    width = prm.width

    # Scratch and logs: one allocation per type (kernel_logs.carve), fewer allocations per shot.
    cap = 64
    sc_cap = 4 * n + 16 if record else 1
    n_cols = N_STATE_COLS_SPIN
    fbuf = np.empty((N_COLS + 10) * n + n * n + 20 + 2 * cap + (1 + n_cols) * sc_cap)
    ibuf = np.empty(9 * n + 3 * cap + sc_cap, np.int64)
    bs = carve(fbuf, 0, n, N_COLS)
    fw = carve(fbuf, N_COLS * n, 4, n)
    t_hit = fw[0]  # time of each ball's last collision (ball or cushion)
    pocket_time = fw[1]
    ball_t = fw[2]
    row_t = fw[3]  # each pair row's earliest collision (kernel_logs.set_pair), at pair (i, row_j[i])
    ps = carve(fbuf, (N_COLS + 4) * n, n, 6)  # the balls' states at the current event: x, y, vx, vy, |v|, |a|
    at = (N_COLS + 10) * n
    pair_t = carve(fbuf, at, n, n)
    at += n * n
    # Scratch rows for the collision laws, which work on (N, 2) / (N, 3) arrays.
    cv = carve(fbuf, at, 2, 2)
    cw = carve(fbuf, at + 4, 2, 3)
    scratch = fbuf[at + 10:at + 20]  # for the cushion laws that integrate
    for c in range(at, at + 20):
        fbuf[c] = 0.0
    at += 20
    ev_t = fbuf[at:at + cap]
    ev_speed = fbuf[at + cap:at + 2 * cap]
    at += 2 * cap
    sc_t = fbuf[at:at + sc_cap]
    sc_state = carve(fbuf, at + sc_cap, sc_cap, n_cols)
    iw = carve(ibuf, 0, 9, n)
    st = iw[0]
    burst = iw[1]  # collisions of each ball in its current contact cluster
    slow_with = iw[2]  # each ball's partner in its current run of slow re-contacts
    slow_runs = iw[3]  # and the length of that run
    pocket_of = iw[4]
    ball_kind = iw[5]
    ball_other = iw[6]
    row_j = iw[7]
    involved = iw[8]
    ev_int = carve(ibuf, 9 * n, cap, 3)
    sc_ball = ibuf[9 * n + 3 * cap:9 * n + 3 * cap + sc_cap]
    for i in range(n):
        for c in range(N_COLS):
            bs[i, c] = 0.0
        st[i] = MS_POCKETED
        t_hit[i] = -math.inf
        burst[i] = 0
        slow_with[i] = -1
        slow_runs[i] = 0
        pocket_of[i] = -1
        pocket_time[i] = np.nan
        ball_t[i] = math.inf
        ball_kind[i] = -1
        ball_other[i] = -1
        row_t[i] = math.inf
        row_j[i] = -1
        for j in range(n):
            pair_t[i, j] = math.inf
    for i in range(n):
        bs[i, X] = pos[i, 0]
        bs[i, Y] = pos[i, 1]
        bs[i, ALPHA] = spin_decay_rate(radius[i], f_spin)
        bs[i, TEND] = math.inf
        if on_table[i]:
            bs[i, VX] = vel[i, 0]
            bs[i, VY] = vel[i, 1]
            bs[i, WX] = ang[i, 0]
            bs[i, WY] = ang[i, 1]
            bs[i, WZ] = ang[i, 2]
            _classify_piece(bs, st, i, radius[i], f_slide, f_roll, f_spin)

    for i in range(n):
        if on_table[i]:
            ball_t[i], ball_kind[i], ball_other[i] = predict_ball(i, bs, st, radius, pocket_xy, pocket_r, length,
                                                                   width, max_time, prm)
    for i in range(n):
        for j in range(i + 1, n):
            if on_table[i] and on_table[j]:
                pair_t[i, j] = _predict_pair(i, j, 0.0, bs, ball_t, radius, max_time)
        rescan_row(pair_t, row_t, row_j, i)

    n_sc = plain(0)  # (plain: reserve_states compiled for int64 only, as simulate_exact calls it)
    if record:
        for i in range(n):
            _log_state(n_sc, sc_t, sc_ball, sc_state, 0.0, i, bs, st, on_table)
            n_sc += 1

    t = 0.0
    n_events = 0
    status = STATUS_REST
    while True:
        best, kind, bi, bj = next_event(ball_t, ball_kind, ball_other, row_t, row_j)
        if not best <= max_time:
            moving = False
            for i in range(n):
                if on_table[i] and st[i] != MS_STATIONARY:
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
            _move_to(bs, bi, t)
            _move_to(bs, bj, t)
            dx = bs[bi, X] - bs[bj, X]
            dy = bs[bi, Y] - bs[bj, Y]
            dist = math.hypot(dx, dy)
            clustered = count_burst(bi, t, t_hit, burst) | count_burst(bj, t, t_hit, burst)
            if burst[bi] > JAM_EVENTS or burst[bj] > JAM_EVENTS:
                n_inv = _jam_cluster(bi, t, bs, st, radius, mass, on_table, burst, prm, f_slide, f_roll, f_spin,
                                     involved)
                kind = EV_JAM
                bj = n_inv
            else:
                for q in range(2):
                    m = bi if q == 0 else bj
                    cv[q, 0] = bs[m, VX]
                    cv[q, 1] = bs[m, VY]
                    cw[q, 0] = bs[m, WX]
                    cw[q, 1] = bs[m, WY]
                    cw[q, 2] = bs[m, WZ]
                merged = False
                if dist > 0.0:
                    speed = ball_hit(cv, cw, _ROW0, _ROW1, dx / dist, dy / dist, mass[bi], mass[bj], radius[bi],
                                     radius[bj], prm, floor, clustered)
                    pushing = _slow_run(bi, bj, speed < floor, slow_with, slow_runs) > JAM_EVENTS
                    if pushing or is_pressed_pair(cv, cw, _ROW0, _ROW1, dx, dy, radius[bi], radius[bj], f_slide, f_roll,
                                                  f_spin, floor):
                        merge_pair(cv, cw, _ROW0, _ROW1, mass[bi], mass[bj], radius[bi], radius[bj])
                        merged = True
                        slow_runs[bi] = 0
                        slow_runs[bj] = 0
                for q in range(2):
                    m = bi if q == 0 else bj
                    bs[m, VX] = cv[q, 0]
                    bs[m, VY] = cv[q, 1]
                    bs[m, WX] = cw[q, 0]
                    bs[m, WY] = cw[q, 1]
                    bs[m, WZ] = cw[q, 2]
                _classify_piece(bs, st, bi, radius[bi], f_slide, f_roll, f_spin)
                if merged:
                    _copy_motion(bs, st, bi, bj, radius, f_slide, f_roll, f_spin)
                else:
                    _classify_piece(bs, st, bj, radius[bj], f_slide, f_roll, f_spin)
                involved[1] = bj
                n_inv = 2
        elif kind == EV_CUSHION:
            _move_to(bs, bi, t)
            r = radius[bi]
            jaws = has_walls(prm)
            if jaws:  # a rail, jaw face or tip: on it exactly, its normal at the contact
                bs[bi, X], bs[bi, Y] = touch_wall(bs[bi, X], bs[bi, Y], r, bj, prm)
                wnx, wny = wall_normal_at(bs[bi, X], bs[bi, Y], bj, prm)
                reach = r if bj < prm.n_segs else r + prm.tips[bj - prm.n_segs, 2]
            else:
                wnx, wny = wall_normal(bj)
                reach = r
                if bj == 0:
                    bs[bi, X] = r
                elif bj == 1:
                    bs[bi, X] = length - r
                elif bj == 2:
                    bs[bi, Y] = r
                else:
                    bs[bi, Y] = width - r
            count_burst(bi, t, t_hit, burst)
            if burst[bi] > JAM_EVENTS:
                n_inv = _jam_cluster(bi, t, bs, st, radius, mass, on_table, burst, prm, f_slide, f_roll, f_spin,
                                     involved)
                kind = EV_JAM
                bj = n_inv
            else:
                cv[0, 0] = bs[bi, VX]
                cv[0, 1] = bs[bi, VY]
                cw[0, 0] = bs[bi, WX]
                cw[0, 1] = bs[bi, WY]
                cw[0, 2] = bs[bi, WZ]
                speed = wall_hit(cv, cw, _ROW0, wnx, wny, reach, r, mass[bi], e_c, prm, scratch)
                bs[bi, VX] = cv[0, 0]
                bs[bi, VY] = cv[0, 1]
                bs[bi, WX] = cw[0, 0]
                bs[bi, WY] = cw[0, 1]
                bs[bi, WZ] = cw[0, 2]
                _classify_piece(bs, st, bi, r, f_slide, f_roll, f_spin)
                nx, ny = wnx, wny
                if bs[bi, VX] * nx + bs[bi, VY] * ny <= floor and bs[bi, AX] * nx + bs[bi, AY] * ny < 0.0:
                    # Pressed on the cushion: it stays on it (see spin_collide).
                    cv[0, 0] = bs[bi, VX]
                    cv[0, 1] = bs[bi, VY]
                    cw[0, 0] = bs[bi, WX]
                    cw[0, 1] = bs[bi, WY]
                    if jaws:
                        settle_on_wall(cv, cw, _ROW0, nx, ny)
                    else:
                        settle_on_cushion(cv, cw, _ROW0, bj)
                    bs[bi, VX] = cv[0, 0]
                    bs[bi, VY] = cv[0, 1]
                    bs[bi, WX] = cw[0, 0]
                    bs[bi, WY] = cw[0, 1]
                    _classify_piece(bs, st, bi, r, f_slide, f_roll, f_spin)
        elif kind == EV_POCKET:
            _move_to(bs, bi, t)
            speed = math.hypot(bs[bi, VX], bs[bi, VY])
            on_table[bi] = False
            for c in range(VX, TEND):
                if c != ALPHA:
                    bs[bi, c] = 0.0
            bs[bi, TEND] = math.inf
            st[bi] = MS_POCKETED
            pocket_of[bi] = bj
            pocket_time[bi] = t
        else:  # the ball's motion transition
            if st[bi] == MS_SLIDING:  # the end of the slide in closed form (T0 is the slide's start)
                x, y, vx, vy, wx, wy, wz = slide_end(bs[bi, X], bs[bi, Y], bs[bi, VX], bs[bi, VY], bs[bi, WX],
                                                     bs[bi, WY], bs[bi, WZ], radius[bi], f_slide, f_spin)
                bs[bi, X] = x
                bs[bi, Y] = y
                bs[bi, VX] = vx
                bs[bi, VY] = vy
                bs[bi, WX] = wx
                bs[bi, WY] = wy
                bs[bi, WZ] = wz
                bs[bi, T0] = t
            else:
                _move_to(bs, bi, t)
            nxt = transition(st[bi], bs[bi, VX], bs[bi, VY], bs[bi, WZ])
            _set_piece(bs, st, bi, nxt, radius[bi], f_slide, f_roll, f_spin)
            kind = EV_ROLL if nxt == MS_ROLLING else (EV_SPIN if nxt == MS_SPINNING else EV_STOP)
            bj = -1

        if n_events >= ev_t.shape[0]:  # (the log written in place; grown by doubling only when full)
            ev_t, ev_int, ev_speed = reserve_events(ev_t, ev_int, ev_speed, n_events + 1)
        ev_t[n_events] = t
        ev_int[n_events, 0] = kind
        ev_int[n_events, 1] = bi
        ev_int[n_events, 2] = bj
        ev_speed[n_events] = speed
        n_events += 1

        for q in range(n_inv):
            i = involved[q]
            if record:
                if n_sc >= sc_t.shape[0]:
                    sc_t, sc_ball, sc_state = reserve_states(sc_t, sc_ball, sc_state, n_sc)
                _log_state(n_sc, sc_t, sc_ball, sc_state, t, i, bs, st, on_table)
                n_sc += 1
            if on_table[i]:
                ball_t[i], ball_kind[i], ball_other[i] = predict_ball(i, bs, st, radius, pocket_xy, pocket_r,
                                                                       length, width, max_time, prm)
            else:
                ball_t[i] = math.inf
        have_states = False
        for q in range(n_inv):
            i = involved[q]
            if on_table[i] and not have_states:  # every ball's state at t, once for all the involved balls' pairs
                for m in range(n):
                    if on_table[m]:
                        x, y, vx, vy, _, _, _ = state_at(bs, m, t)
                        ps[m, 0] = x
                        ps[m, 1] = y
                        ps[m, 2] = vx
                        ps[m, 3] = vy
                        # (hypot of zeros is 0: not called for the balls at rest, most of them)
                        ps[m, 4] = math.hypot(vx, vy) if vx != 0.0 or vy != 0.0 else 0.0
                        axm = bs[m, AX]
                        aym = bs[m, AY]
                        ps[m, 5] = math.hypot(axm, aym) if axm != 0.0 or aym != 0.0 else 0.0
                have_states = True
            for m in range(n):
                if m == i:
                    continue
                lo = min(i, m)
                hi = max(i, m)
                tm = math.inf
                if on_table[i] and on_table[m]:
                    again = False  # a pair of two involved balls: worked out once (the same inputs the second time)
                    for h in range(q):
                        if involved[h] == m:
                            again = True
                    if again:
                        continue
                    tm = pair_from_states(lo, hi, t, ps[lo, 0], ps[lo, 1], ps[lo, 2], ps[lo, 3], bs[lo, AX],
                                           bs[lo, AY], ps[lo, 4], ps[lo, 5], ps[hi, 0], ps[hi, 1], ps[hi, 2],
                                           ps[hi, 3], bs[hi, AX], bs[hi, AY], ps[hi, 4], ps[hi, 5], ball_t, radius,
                                           max_time)
                if lo == i:  # row i is scanned again below, once written
                    pair_t[lo, hi] = tm
                else:
                    set_pair(pair_t, row_t, row_j, lo, hi, tm)
            rescan_row(pair_t, row_t, row_j, i)

    for i in range(n):
        x, y, vx, vy, wx, wy, wz = state_at(bs, i, t)
        pos[i, 0] = x
        pos[i, 1] = y
        vel[i, 0] = vx
        vel[i, 1] = vy
        ang[i, 0] = wx
        ang[i, 1] = wy
        ang[i, 2] = wz
    return KernelResult(status, t, n_events, pocket_of, pocket_time, ev_t[:n_events], ev_int[:n_events],
                        ev_speed[:n_events], sc_t[:n_sc], sc_ball[:n_sc], sc_state[:n_sc], 0, 0)
