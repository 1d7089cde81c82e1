"""Compiled array code of the native vector env (:mod:`.vector`): N tables reset, struck and scored per call.

Each function does for every sub-env what the single env does in Python, with the same floating-point operations
in the same order, so that sub-env ``k`` of a vector env equals a single env with the same seed bit for bit (the
test ``tests/envs/test_vector_env.py`` checks it):

- :func:`place_tables` is :func:`billiards_env.physics.layout.place_random` (and the fixed rows of a rack);
- :func:`prepare_shots` is ``ActionType.shot`` (absolute, relative and ghost aim; power; tip offsets) followed
  by ``BilliardsEnv.play_shot``'s noise and strike;
- :func:`finish_shots` is the rest of ``play_shot`` and ``PotTask.on_shot`` (re-spotting a pocketed cue ball as
  :func:`~billiards_env.physics.layout.spot_cue_ball` does), and the positions observation.

Random numbers come from each sub-env's own ``numpy.random.Generator`` (numba draws from the same bit generator
state, with numpy's algorithms), in the single env's order.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from billiards_env.physics.spin_collide import strike_spin

from ._kernels import observation

AIM_ABSOLUTE = 0
AIM_RELATIVE = 1
AIM_GHOST = 2
#: ``place_tables`` status: every table placed.
PLACED = -1


@njit(cache=True)
def place_tables(rows, gens, pos, vel, ang, on, fixed_rows, fixed_xy, rand_rows, regions, pockets, pocket_margin,
                 min_dist, batch, tries):
    """Reset tables ``rows``: balls at rest on the table, the fixed rows at ``fixed_xy``, each random row drawn
    uniformly in its region ``(x0, x_span, y0, y_span)`` away from pockets and placed balls (rejection sampling in
    batches of ``batch`` candidates, as ``place_random``). Returns :data:`PLACED`, or the first table that could
    not be placed."""
    nf = fixed_rows.shape[0]
    nr = rand_rows.shape[0]
    pm2 = pocket_margin * pocket_margin
    d2 = min_dist * min_dist
    placed = np.empty((nf + nr, 2))
    for q in range(rows.shape[0]):
        k = rows[q]
        vel[k] = 0.0
        ang[k] = 0.0
        on[k] = True
        for f in range(nf):
            pos[k, fixed_rows[f], 0] = fixed_xy[f, 0]
            pos[k, fixed_rows[f], 1] = fixed_xy[f, 1]
            placed[f, 0] = fixed_xy[f, 0]
            placed[f, 1] = fixed_xy[f, 1]
        if nr == 0:
            continue
        g = gens[k]
        first = g.random(2 * batch * nr)
        n_placed = nf
        for m in range(nr):
            x0 = regions[m, 0]
            sx = regions[m, 1]
            y0 = regions[m, 2]
            sy = regions[m, 3]
            u = first[2 * batch * m: 2 * batch * (m + 1)]
            found = False
            x = 0.0
            y = 0.0
            for attempt in range(tries):
                if attempt:
                    u = g.random(2 * batch)
                for c in range(0, 2 * batch, 2):
                    x = x0 + sx * u[c]
                    y = y0 + sy * u[c + 1]
                    ok = True
                    for p in range(pockets.shape[0]):
                        if (x - pockets[p, 0]) * (x - pockets[p, 0]) + (y - pockets[p, 1]) * (y - pockets[p, 1]) < pm2:
                            ok = False
                            break
                    if ok:
                        for h in range(n_placed):
                            qx = placed[h, 0]
                            qy = placed[h, 1]
                            if (x - qx) * (x - qx) + (y - qy) * (y - qy) < d2:
                                ok = False
                                break
                    if ok:
                        found = True
                        break
                if found:
                    break
            if not found:
                return k
            row = rand_rows[m]
            pos[k, row, 0] = x
            pos[k, row, 1] = y
            placed[n_placed, 0] = x
            placed[n_placed, 1] = y
            n_placed += 1
    return PLACED


@njit(cache=True)
def _target(on):
    """Row of the lowest-numbered object ball on the table (the pot task's target), -1 if none."""
    for i in range(1, on.shape[0]):
        if on[i]:
            return i
    return -1


@njit(cache=True)
def prepare_shots(act, active, aim_kind, max_ghost, pos, on, radius, speed_lo, speed_span, spin_action, max_tip,
                  angle_noise, speed_noise, tip_noise, gens, spin_model, vel, ang, played, start):
    """Turn each active table's action (clipped float64) into the cue ball's velocity (and spin), as the single
    env does: the aim type's angle, the power's speed, the tip offsets, then the shot noise drawn from the table's
    generator. Writes ``played[k] = (angle, speed, side, top)`` and ``start[k] = (x, y)`` of the cue ball."""
    for k in range(act.shape[0]):
        if not active[k]:
            continue
        a0 = act[k, 0]
        speed = speed_lo + 0.5 * (act[k, 1] + 1.0) * speed_span
        side = 0.0
        top = 0.0
        if spin_action:
            x = act[k, 2]
            y = act[k, 3]
            side = max_tip * (x * math.sqrt(1.0 - 0.5 * y * y))
            top = max_tip * (y * math.sqrt(1.0 - 0.5 * x * x))
        p = pos[k]
        if aim_kind == AIM_ABSOLUTE:
            angle = math.pi * a0
        else:
            t = _target(on[k])
            if aim_kind == AIM_RELATIVE:
                base = 0.0
                if t >= 0:
                    base = math.atan2(p[t, 1] - p[0, 1], p[t, 0] - p[0, 0])
                angle = math.pi * a0 + base
            elif t < 0:
                angle = 0.0
            else:
                theta = math.atan2(p[t, 1] - p[0, 1], p[t, 0] - p[0, 0]) + a0 * max_ghost
                contact = radius[0] + radius[t]
                gx = p[t, 0] - contact * math.cos(theta)
                gy = p[t, 1] - contact * math.sin(theta)
                angle = math.atan2(gy - p[0, 1], gx - p[0, 0])
        g = gens[k]
        if angle_noise > 0.0:
            angle += g.normal(0.0, angle_noise)
        if speed_noise > 0.0:
            speed *= max(0.0, 1.0 + g.normal(0.0, speed_noise))
        if tip_noise > 0.0:
            side += g.normal(0.0, tip_noise)
            top += g.normal(0.0, tip_noise)
            r = math.hypot(side, top)
            if r > 0.5 * (1.0 - 1e-12):  # keep it a legal tip position (no miscue)
                side = side * 0.5 * (1.0 - 1e-12) / r
                top = top * 0.5 * (1.0 - 1e-12) / r
        start[k, 0] = p[0, 0]
        start[k, 1] = p[0, 1]
        vel[k, 0, 0] = speed * math.cos(angle)
        vel[k, 0, 1] = speed * math.sin(angle)
        if spin_model:
            _, _, wx, wy, wz = strike_spin(angle, speed, side, top, radius[0])
            ang[k, 0, 0] = wx
            ang[k, 0, 1] = wy
            ang[k, 0, 2] = wz
        played[k, 0] = angle
        played[k, 1] = speed
        played[k, 2] = side
        played[k, 3] = top


@njit(cache=True)
def _spot_cue(pos, on, radius, hx, hy, width):
    """Put the pocketed cue ball (row 0) on the head spot or the nearest free point of the head string, as
    :func:`billiards_env.physics.layout.spot_cue_ball` does. Returns False if the head of the table is full."""
    n = pos.shape[0]
    need2 = (2.0 * radius + 1e-6) ** 2
    step = radius / 4.0
    k_max = int((0.5 * width - radius) / step)
    x = hx
    while x >= radius:
        for c in range(2 * k_max + 1):
            y = hy + step * ((c + 1) // 2) * (1 if c % 2 else -1)
            free = True
            for q in range(1, n):
                if on[q] and (x - pos[q, 0]) * (x - pos[q, 0]) + (y - pos[q, 1]) * (y - pos[q, 1]) < need2:
                    free = False
                    break
            if free:
                pos[0, 0] = x
                pos[0, 1] = y
                on[0] = True
                return True
        x -= 2.0 * radius
    return False


@njit(cache=True)
def finish_shots(active, pocket, first, pos, on, vel, ang, shots, ball_radius, hx, hy, width, pot_reward,
                 scratch_penalty, miss_penalty, step_penalty, single_shot, max_shots, reward, terminated, truncated,
                 success, scratch, pocketed_mask):
    """Score each active table's shot as ``PotTask.on_shot``: balls at rest, a pocketed cue ball re-spotted,
    reward, termination, truncation and success; ``pocketed_mask[k]`` has bit ``i`` set for each ball row ``i``
    pocketed by the shot. Returns False if a cue ball could not be re-spotted."""
    ok = True
    for k in range(pos.shape[0]):
        if not active[k]:
            continue
        vel[k] = 0.0
        ang[k] = 0.0
        shots[k] += 1
        n_pocketed = 0
        mask = 0
        for i in range(pos.shape[1]):
            if pocket[k, i] >= 0:
                n_pocketed += 1
                mask |= 1 << i
        pocketed_mask[k] = mask
        sc = pocket[k, 0] >= 0
        scratch[k] = sc
        if sc:
            ok = _spot_cue(pos[k], on[k], ball_radius, hx, hy, width) and ok
        n_potted = n_pocketed - (1 if sc else 0)
        cleared = True
        for i in range(1, pos.shape[1]):
            if on[k, i]:
                cleared = False
                break
        r = pot_reward * n_potted - step_penalty
        if sc:
            r -= scratch_penalty
        if first[k] < 0:
            r -= miss_penalty
        reward[k] = r
        term = cleared or single_shot
        terminated[k] = term
        truncated[k] = (not term) and shots[k] >= max_shots
        success[k] = cleared and not sc
    return ok


@njit(cache=True)
def observe_positions(rows, pos, on, sx, sy, out):
    """The positions observation of tables ``rows`` into ``out[rows]`` (``envs._kernels.observation``)."""
    for q in range(rows.shape[0]):
        k = rows[q]
        out[k] = observation(pos[k], on[k], sx, sy)


__all__ = ["AIM_ABSOLUTE", "AIM_RELATIVE", "AIM_GHOST", "PLACED", "place_tables", "prepare_shots", "finish_shots",
           "observe_positions"]
