"""The ``step`` solver: the lecture's per-frame algorithm with a fixed time step ``dt`` (numba kernel).

Each step, in this order: friction and minimum speed (rolling: speed minus ``a dt``; drag: velocity times
``e^{-k dt}``, the lecture's friction factor), position update ``x += v dt``, cushions (overshoot
repositioning and bounce), ball pairs in ``(i, j)`` order (overlap resolution and the collision law of
:mod:`.collide`), pocket test. Two contact treatments:

- ``lecture``: as the seed does — cushions put the ball back on the wall; overlapping balls are pushed
  apart by half the overlap each along the line of centres, then their normal velocities are exchanged.
- ``rewind``: go back to the time of impact inside the step (linear motion over the step), resolve the
  collision there and finish the step with the new velocities: a cushion reflects the overshoot, a ball pair
  is moved back to touching, bounced, and moved on.

On a jaw table (:mod:`.walls`) the cushions are its rails, jaw faces and tips: a ball overlapping one is put back on
it along the contact normal (``rewind``: back to the time of contact, then on with the reflected velocity), the
deepest first, at most ``MAX_WALL_PASSES`` a step, and reflected by :func:`.walls.reflect_off` (the exact solver's
law); after the pairs, :func:`.walls.keep_on_jaw_table` keeps balls off the walls and on the table, its mouths
included. The pocket test is the pocket circles'.

Neither sees a pair that passes through each other within one step; those are counted as tunnelled
(``n_tunnelled``) by checking each pair's closest approach along the step's straight-line motion.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .collide import resolve_ball_ball, resolve_cushion
from .codes import EV_COLLISION, EV_CUSHION, EV_POCKET, EV_STOP, ROLLING, STATUS_REST, STATUS_TIME_CAP
from .kernel_io import N_STATE_COLS, KernelResult
from .kernel_logs import (cushion_overshoot, keep_on_table, pocket_holding, put_event, reserve_events, rewind_time,
                          snapshot, tunnelled)
from .walls import MAX_WALL_PASSES, back_onto_wall, deepest_overlap, has_walls, keep_on_jaw_table, reflect_off
from .plain import plain

CONTACT_MODES = ("lecture", "rewind")
LECTURE, REWIND = 0, 1


@njit(cache=True)
def simulate_step(pos, vel, ang, radius, mass, on_table, pocket_xy, pocket_r, params, dt, contact, record_dt):
    """Run the per-frame algorithm from ``pos``/``vel`` (updated in place) until rest or ``max_time``.

    ``ang`` (angular velocities) is not read: the rolling and drag laws have no spin; it is there so that every
    step kernel takes the same arguments (:mod:`.kernels`).

    ``params``: the parameter record (:mod:`.kernel_io`). Returns a :class:`~.kernel_io.KernelResult` like
    ``simulate_exact`` (snapshots every ``record_dt`` s as the state log when ``record_dt > 0``), with
    ``n_steps`` and ``n_tunnelled`` set.
    """
    n = pos.shape[0]
    prm = params[0]
    law = prm.law
    a = prm.decel
    k = prm.drag_k
    v_min = prm.min_speed
    e_c = prm.e_cushion
    e_b = prm.e_ball
    length = prm.length
    width = prm.width
    max_time = prm.max_time
    floor = prm.speed_floor
    drag_factor = math.exp(-k * dt)
    max_steps = int(math.ceil(max_time / dt - 1e-9))
    jaws = has_walls(prm)

    pocket_of = np.full(n, -1, np.int64)
    pocket_time = np.full(n, np.nan)
    ev_t = np.empty(64)
    ev_int = np.empty((64, 3), np.int64)
    ev_speed = np.empty(64)
    n_ev = plain(0)  # (plain: the helpers below are compiled for int64, not once per literal)
    record = record_dt > 0.0
    sc_t = np.empty(4 * n + 16)
    sc_ball = np.empty(4 * n + 16, np.int64)
    sc_state = np.empty((4 * n + 16, N_STATE_COLS))
    n_sc = plain(0)
    no_code = np.empty(0, np.int64)  # (motion-state codes: the spin model's; not logged here)
    if record:
        n_sc, sc_t, sc_ball, sc_state = snapshot(n_sc, sc_t, sc_ball, sc_state, 0.0, pos, vel, ang, on_table, no_code,
                                                 plain(-1))
    next_record = record_dt

    for i in range(n):
        if not on_table[i]:
            vel[i, 0] = 0.0
            vel[i, 1] = 0.0

    t = 0.0
    step = 0
    n_tunnelled = 0
    status = STATUS_REST
    moving = np.zeros(n, np.bool_)
    while True:
        any_moving = False
        for i in range(n):
            moving[i] = on_table[i] and (vel[i, 0] != 0.0 or vel[i, 1] != 0.0)
            any_moving = any_moving or moving[i]
        if not any_moving:
            status = STATUS_REST
            break
        if step >= max_steps:
            status = STATUS_TIME_CAP
            break
        step += 1
        t = step * dt
        # Reserve room for this step's events (at most a stop, 4 cushions and a pocket per ball, one per pair)
        # and snapshots, so the loops below never reallocate.
        need = n_ev + 6 * n + n * (n - 1) // 2 + 1
        ev_t, ev_int, ev_speed = reserve_events(ev_t, ev_int, ev_speed, need)

        # 1. friction and minimum speed; 2. position update.
        for i in range(n):
            if not moving[i]:
                continue
            s = math.hypot(vel[i, 0], vel[i, 1])
            if law == ROLLING:
                s_new = max(s - a * dt, 0.0)
                f = s_new / s
            else:
                f = drag_factor
                s_new = s * f
            if s_new <= v_min or s_new == 0.0:
                vel[i, 0] = 0.0
                vel[i, 1] = 0.0
                put_event(ev_t, ev_int, ev_speed, n_ev, t, plain(EV_STOP), i, plain(-1), 0.0)
                n_ev += 1
                continue
            vel[i, 0] *= f
            vel[i, 1] *= f
            pos[i, 0] += vel[i, 0] * dt
            pos[i, 1] += vel[i, 1] * dt

        # 3. cushions: overshoot repositioning and bounce.
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
                    speed = reflect_off(vel, i, nx, ny, e_c)
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
                    speed = resolve_cushion(vel, i, cush, e_c)
                    if contact == 1 and speed > 0.0:
                        pos[i, axis] = lim + (over if cush % 2 == 0 else -over) * e_c
                    else:
                        pos[i, axis] = lim
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
                if dist2 >= dc * dc:
                    if tunnelled(dx, dy, vel[i, 0] - vel[j, 0], vel[i, 1] - vel[j, 1], dc, dt):
                        n_tunnelled += 1
                    continue
                dist = math.sqrt(dist2)
                if dist == 0.0:
                    nx, ny = 1.0, 0.0
                else:
                    nx = dx / dist
                    ny = dy / dist
                back = -1.0
                if contact == 1:  # rewind to the time of impact
                    back = rewind_time(dx, dy, vel[i, 0] - vel[j, 0], vel[i, 1] - vel[j, 1], dc, dt)
                if back >= 0.0:
                    pos[i, 0] -= vel[i, 0] * back
                    pos[i, 1] -= vel[i, 1] * back
                    pos[j, 0] -= vel[j, 0] * back
                    pos[j, 1] -= vel[j, 1] * back
                    dx = pos[i, 0] - pos[j, 0]
                    dy = pos[i, 1] - pos[j, 1]
                    dist = math.hypot(dx, dy)
                    nx = dx / dist
                    ny = dy / dist
                    speed = resolve_ball_ball(vel, i, j, nx, ny, dist, mass[i], mass[j], e_b, 0.0, floor, plain(False))
                    pos[i, 0] += vel[i, 0] * back
                    pos[i, 1] += vel[i, 1] * back
                    pos[j, 0] += vel[j, 0] * back
                    pos[j, 1] += vel[j, 1] * back
                else:
                    half = 0.5 * (dc - dist)
                    pos[i, 0] += nx * half
                    pos[i, 1] += ny * half
                    pos[j, 0] -= nx * half
                    pos[j, 1] -= ny * half
                    speed = resolve_ball_ball(vel, i, j, nx, ny, dist, mass[i], mass[j], e_b, 0.0, floor, plain(False))
                if speed > 0.0:
                    moving[i] = True
                    moving[j] = True
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
            p = pocket_holding(pos[i, 0], pos[i, 1], pocket_xy, pocket_r)
            if p >= 0:
                speed = math.hypot(vel[i, 0], vel[i, 1])
                on_table[i] = False
                vel[i, 0] = 0.0
                vel[i, 1] = 0.0
                pocket_of[i] = p
                pocket_time[i] = t
                put_event(ev_t, ev_int, ev_speed, n_ev, t, plain(EV_POCKET), i, p, speed)
                n_ev += 1
                if record:
                    n_sc, sc_t, sc_ball, sc_state = snapshot(n_sc, sc_t, sc_ball, sc_state, t, pos, vel, ang, on_table,
                                                             no_code, i)

        if record and t >= next_record - 1e-12:
            n_sc, sc_t, sc_ball, sc_state = snapshot(n_sc, sc_t, sc_ball, sc_state, t, pos, vel, ang, on_table, no_code,
                                                     plain(-1))
            next_record += record_dt

    if record:
        n_sc, sc_t, sc_ball, sc_state = snapshot(n_sc, sc_t, sc_ball, sc_state, t, pos, vel, ang, on_table, no_code,
                                                 plain(-1))
    return KernelResult(status, t, n_ev, pocket_of, pocket_time, ev_t[:n_ev], ev_int[:n_ev], ev_speed[:n_ev],
                        sc_t[:n_sc], sc_ball[:n_sc], sc_state[:n_sc], step, n_tunnelled)
