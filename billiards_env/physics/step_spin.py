"""The ``step`` solver of the spin model: the per-frame algorithm of :mod:`.step` with spin (numba kernel).

Each step of ``dt``, in this order (semi-implicit Euler: new velocities, then positions):

1. friction, per ball and motion state (:mod:`.spin_motion`): a sliding ball's velocity changes by
   ``-mu_slide g dt u^`` and its ``(wx, wy)`` by ``(5 mu_slide g dt / 2R) z^ x u^`` (if its slip would reach
   0 within the step it rolls from then on: ``v -= 2u/7``, ``(wx, wy) = z^ x v / R``); a rolling ball's speed
   falls by ``mu_roll g dt`` with ``(wx, wy) = z^ x v / R``; ``|wz|`` falls by ``5 mu_spin g dt / 2R``;
2. position update ``x += v dt``;
3. cushions (overshoot repositioning and the cushion law of :mod:`.spin_collide`);
4. ball pairs in ``(i, j)`` order (overlap resolution and the ball-ball law of :mod:`.spin_collide`);
5. pocket test.

On a jaw table the walls are met as in :mod:`.step` and resolved with the exact solver's laws:
:func:`.cushion_models.wall_hit` with the contact normal (a tip's ``d`` its radius plus the ball's), then the
pressed-on-a-cushion rule with :func:`.spin_collide.settle_on_wall`.

The contact treatments ``lecture`` and ``rewind`` are those of :mod:`.step`, and so are the pressed-contact
rules of :mod:`.spin_collide` (a ball pressed on a cushion stays on it; a pressed pair moves on as one), so
that both solvers compute the same model. Motion transitions are logged as events (``roll``, ``spin``,
``stop``) at the end of the step in which they happen.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .codes import (EV_COLLISION, EV_CUSHION, EV_POCKET, EV_ROLL, EV_SPIN, EV_STOP, MS_POCKETED, MS_ROLLING,
                    MS_SLIDING, MS_SPINNING, MS_STATIONARY, STATUS_REST, STATUS_TIME_CAP)
from .kernel_io import N_STATE_COLS_SPIN, KernelResult
from .kernel_logs import (cushion_overshoot, internal, keep_on_table, pocket_holding, put_event, reserve_events,
                          rewind_time, snapshot, tunnelled)
from .cushion_models import cushion_hit, wall_hit
from .spin_collide import (acceleration, ball_hit, is_pressed_pair, merge_pair, settle_on_cushion, settle_on_wall,
                           wall_normal)
from .walls import MAX_WALL_PASSES, back_onto_wall, deepest_overlap, has_walls, keep_on_jaw_table, wall_reach
from .spin_motion import classify, roll_on, slip, spin_decay_rate, wz_after
from .plain import plain




@internal
def _friction_step(vel, ang, i, r, dt, f_slide, f_roll, alpha):
    """Step 1 for ball ``i``: returns its motion state after the step."""
    vx = vel[i, 0]
    vy = vel[i, 1]
    wx = ang[i, 0]
    wy = ang[i, 1]
    wz = wz_after(ang[i, 2], dt, alpha)
    ang[i, 2] = wz
    state = classify(vx, vy, wx, wy, wz, r)
    if state == MS_SLIDING:
        ux, uy = slip(vx, vy, wx, wy, r)
        su = math.hypot(ux, uy)
        if 3.5 * f_slide * dt >= su:  # the slip ends within the step: the ball rolls on
            vx, vy, wx, wy = roll_on(vx, vy, wx, wy, r)
            state = MS_ROLLING
        else:
            hx = ux / su
            hy = uy / su
            k = 2.5 * f_slide * dt / r
            vel[i, 0] = vx - f_slide * dt * hx
            vel[i, 1] = vy - f_slide * dt * hy
            ang[i, 0] = wx - k * hy
            ang[i, 1] = wy + k * hx
            return state
    elif state == MS_ROLLING:  # put exactly on rolling (its slip is round-off)
        vx, vy, wx, wy = roll_on(vx, vy, wx, wy, r)
    if state == MS_ROLLING:
        s = math.hypot(vx, vy)
        s_new = s - f_roll * dt
        if s == 0.0 or s_new <= 0.0:
            vx = 0.0
            vy = 0.0
            state = MS_SPINNING if wz != 0.0 else MS_STATIONARY
        else:
            vx *= s_new / s
            vy *= s_new / s
        vel[i, 0] = vx
        vel[i, 1] = vy
        ang[i, 0] = -vy / r
        ang[i, 1] = vx / r
        return state
    if state == MS_SPINNING and wz == 0.0:
        state = MS_STATIONARY
    return state


@njit(cache=True)
def simulate_step_spin(pos, vel, ang, radius, mass, on_table, pocket_xy, pocket_r, params, dt, contact, record_dt):
    """Run the per-frame algorithm of the spin model from ``pos``/``vel``/``ang`` (updated in place) until
    every ball rests or ``max_time``.

    Returns a :class:`~.kernel_io.KernelResult` like ``simulate_exact_spin`` (snapshots every ``record_dt`` s as
    the state log when ``record_dt > 0``), with ``n_steps`` and ``n_tunnelled`` set.
    """
    n = pos.shape[0]
    prm = params[0]
    g = prm.g
    f_slide = prm.mu_slide * g
    f_roll = prm.mu_roll * g
    f_spin = prm.mu_spin * g
    e_c = prm.e_cushion
    length = prm.length
    width = prm.width
    max_time = prm.max_time
    floor = prm.speed_floor
    max_steps = int(math.ceil(max_time / dt - 1e-9))
    jaws = has_walls(prm)

    scratch = np.zeros(10)  # for the cushion laws that integrate
    code = np.full(n, MS_POCKETED, np.int64)
    alpha = np.empty(n)
    for i in range(n):
        alpha[i] = spin_decay_rate(radius[i], f_spin)
        if on_table[i]:
            code[i] = classify(vel[i, 0], vel[i, 1], ang[i, 0], ang[i, 1], ang[i, 2], radius[i])
        else:
            vel[i, 0] = 0.0
            vel[i, 1] = 0.0
            ang[i, 0] = 0.0
            ang[i, 1] = 0.0
            ang[i, 2] = 0.0
    pocket_of = np.full(n, -1, np.int64)
    pocket_time = np.full(n, np.nan)
    ev_t = np.empty(64)
    ev_int = np.empty((64, 3), np.int64)
    ev_speed = np.empty(64)
    n_ev = plain(0)  # (plain: the helpers below are compiled for int64, not once per literal)
    record = record_dt > 0.0
    sc_t = np.empty(4 * n + 16)
    sc_ball = np.empty(4 * n + 16, np.int64)
    sc_state = np.empty((4 * n + 16, N_STATE_COLS_SPIN))
    n_sc = plain(0)
    if record:
        n_sc, sc_t, sc_ball, sc_state = snapshot(n_sc, sc_t, sc_ball, sc_state, 0.0, pos, vel, ang, on_table,
                                                  code, plain(-1))
    next_record = record_dt

    t = 0.0
    step = 0
    n_tunnelled = 0
    status = STATUS_REST
    moving = np.zeros(n, np.bool_)
    while True:
        any_moving = False
        for i in range(n):
            moving[i] = on_table[i] and code[i] != MS_STATIONARY
            any_moving = any_moving or moving[i]
        if not any_moving:
            status = STATUS_REST
            break
        if step >= max_steps:
            status = STATUS_TIME_CAP
            break
        step += 1
        t = step * dt
        # Room for this step's events: a transition, 4 cushions and a pocket per ball, one per pair.
        need = n_ev + 6 * n + n * (n - 1) // 2 + 1
        ev_t, ev_int, ev_speed = reserve_events(ev_t, ev_int, ev_speed, need)

        # 1. friction; 2. position update.
        for i in range(n):
            if not moving[i]:
                continue
            before = code[i]
            after = _friction_step(vel, ang, i, radius[i], dt, f_slide, f_roll, alpha[i])
            code[i] = after
            if after != before and (after == MS_ROLLING or after == MS_SPINNING or after == MS_STATIONARY):
                kind = EV_ROLL if after == MS_ROLLING else (EV_SPIN if after == MS_SPINNING else EV_STOP)
                put_event(ev_t, ev_int, ev_speed, n_ev, t, kind, i, plain(-1), 0.0)
                n_ev += 1
            pos[i, 0] += vel[i, 0] * dt
            pos[i, 1] += vel[i, 1] * dt

        # 3. cushions: overshoot repositioning, the cushion law, the pressed-on-a-cushion rule.
        for i in range(n):
            if not moving[i]:
                continue
            r = radius[i]
            if jaws:  # rails, jaw faces and tips (walls.py)
                for _ in range(MAX_WALL_PASSES):
                    _, wall = deepest_overlap(pos[i, 0], pos[i, 1], r, prm)
                    if wall < 0:
                        break
                    back, nx, ny = back_onto_wall(pos, vel, i, r, wall, dt, contact == 1, prm)  # rewind: to contact
                    speed = wall_hit(vel, ang, i, nx, ny, wall_reach(r, wall, prm), r, mass[i], e_c, prm, scratch)
                    if vel[i, 0] * nx + vel[i, 1] * ny <= floor:
                        ax, ay = acceleration(vel[i, 0], vel[i, 1], ang[i, 0], ang[i, 1], ang[i, 2], r, f_slide,
                                              f_roll, f_spin)
                        if ax * nx + ay * ny < 0.0:
                            settle_on_wall(vel, ang, i, nx, ny)
                    code[i] = classify(vel[i, 0], vel[i, 1], ang[i, 0], ang[i, 1], ang[i, 2], r)
                    if back >= 0.0:
                        pos[i, 0] += vel[i, 0] * back
                        pos[i, 1] += vel[i, 1] * back
                    if speed > 0.0:
                        put_event(ev_t, ev_int, ev_speed, n_ev, t, plain(EV_CUSHION), i, wall, speed)
                        n_ev += 1
                continue
            for cush in range(4):
                axis, lim, over = cushion_overshoot(pos, i, cush, r, length, width)
                if over > 0.0:
                    speed = cushion_hit(vel, ang, i, cush, r, mass[i], e_c, prm, scratch)
                    if contact == 1 and speed > 0.0:
                        pos[i, axis] = lim + (over if cush % 2 == 0 else -over) * e_c
                    else:
                        pos[i, axis] = lim
                    nx, ny = wall_normal(cush)
                    if vel[i, 0] * nx + vel[i, 1] * ny <= floor:
                        ax, ay = acceleration(vel[i, 0], vel[i, 1], ang[i, 0], ang[i, 1], ang[i, 2], r, f_slide,
                                              f_roll, f_spin)
                        if ax * nx + ay * ny < 0.0:
                            settle_on_cushion(vel, ang, i, cush)
                    code[i] = classify(vel[i, 0], vel[i, 1], ang[i, 0], ang[i, 1], ang[i, 2], r)
                    if speed > 0.0:
                        put_event(ev_t, ev_int, ev_speed, n_ev, t, plain(EV_CUSHION), i, cush, speed)
                        n_ev += 1

        # 4. ball pairs in (i, j) order.
        for i in range(n):
            if not on_table[i]:
                continue
            for j in range(i + 1, n):
                if not on_table[j] or not (moving[i] or moving[j]):
                    continue
                dx = pos[i, 0] - pos[j, 0]
                dy = pos[i, 1] - pos[j, 1]
                dc = radius[i] + radius[j]
                dist2 = dx * dx + dy * dy
                bx = vel[i, 0] - vel[j, 0]
                by = vel[i, 1] - vel[j, 1]
                if dist2 >= dc * dc:
                    if tunnelled(dx, dy, bx, by, dc, dt):
                        n_tunnelled += 1
                    continue
                dist = math.sqrt(dist2)
                back = -1.0
                if contact == 1:  # rewind to the time of impact
                    back = rewind_time(dx, dy, bx, by, dc, dt)
                if back >= 0.0:
                    for m in (i, j):
                        pos[m, 0] -= vel[m, 0] * back
                        pos[m, 1] -= vel[m, 1] * back
                else:
                    half = 0.5 * (dc - dist)
                    nx0 = dx / dist if dist > 0.0 else 1.0
                    ny0 = dy / dist if dist > 0.0 else 0.0
                    pos[i, 0] += nx0 * half
                    pos[i, 1] += ny0 * half
                    pos[j, 0] -= nx0 * half
                    pos[j, 1] -= ny0 * half
                dx = pos[i, 0] - pos[j, 0]
                dy = pos[i, 1] - pos[j, 1]
                dist = math.hypot(dx, dy)
                nx = dx / dist if dist > 0.0 else 1.0
                ny = dy / dist if dist > 0.0 else 0.0
                speed = ball_hit(vel, ang, i, j, nx, ny, mass[i], mass[j], radius[i], radius[j], prm, floor,
                               plain(False))
                merged = is_pressed_pair(vel, ang, i, j, dx, dy, radius[i], radius[j], f_slide, f_roll, f_spin,
                                         floor)
                if merged:
                    merge_pair(vel, ang, i, j, mass[i], mass[j], radius[i], radius[j])
                if back >= 0.0:
                    for m in (i, j):
                        pos[m, 0] += vel[m, 0] * back
                        pos[m, 1] += vel[m, 1] * back
                if speed > 0.0 or merged:
                    for m in (i, j):
                        moving[m] = True
                        code[m] = classify(vel[m, 0], vel[m, 1], ang[m, 0], ang[m, 1], ang[m, 2], radius[m])
                if speed > 0.0:
                    put_event(ev_t, ev_int, ev_speed, n_ev, t, plain(EV_COLLISION), i, j, speed)
                    n_ev += 1

        # Pushes can leave a ball past a cushion: put it back on the table.
        if jaws:
            keep_on_jaw_table(pos, on_table, radius, pocket_xy, pocket_r, prm)
        else:
            keep_on_table(pos, on_table, radius, length, width)

        # 5. pockets.
        for i in range(n):
            if not on_table[i]:
                continue
            q = pocket_holding(pos[i, 0], pos[i, 1], pocket_xy, pocket_r)
            if q >= 0:
                speed = math.hypot(vel[i, 0], vel[i, 1])
                on_table[i] = False
                vel[i, 0] = 0.0
                vel[i, 1] = 0.0
                ang[i, 0] = 0.0
                ang[i, 1] = 0.0
                ang[i, 2] = 0.0
                code[i] = MS_POCKETED
                pocket_of[i] = q
                pocket_time[i] = t
                put_event(ev_t, ev_int, ev_speed, n_ev, t, plain(EV_POCKET), i, q, speed)
                n_ev += 1
                if record:
                    n_sc, sc_t, sc_ball, sc_state = snapshot(n_sc, sc_t, sc_ball, sc_state, t, pos, vel, ang,
                                                              on_table, code, i)

        if record and t >= next_record - 1e-12:
            n_sc, sc_t, sc_ball, sc_state = snapshot(n_sc, sc_t, sc_ball, sc_state, t, pos, vel, ang, on_table,
                                                      code, plain(-1))
            next_record += record_dt

    if record:
        n_sc, sc_t, sc_ball, sc_state = snapshot(n_sc, sc_t, sc_ball, sc_state, t, pos, vel, ang, on_table, code,
                                                  plain(-1))
    return KernelResult(status, t, n_ev, pocket_of, pocket_time, ev_t[:n_ev], ev_int[:n_ev], ev_speed[:n_ev],
                        sc_t[:n_sc], sc_ball[:n_sc], sc_state[:n_sc], step, n_tunnelled)
