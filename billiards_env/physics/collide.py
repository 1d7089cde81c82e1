"""Instantaneous collision laws shared by both solvers (compiled with numba).

Ball-ball: impulse along the line of centres ``n``; the normal relative speed ``v_close`` becomes a
separation speed ``e * v_close``; tangential components are kept. With masses ``m1, m2`` and
``mu = m1 m2 / (m1 + m2)`` the impulse is ``J = mu (1 + e) v_close``: momentum is conserved exactly
and kinetic energy drops by ``mu (1 - e^2) v_close^2 / 2`` (none at ``e = 1``).

Inelastic-collapse guard (rolling friction with ``mu_roll > 0`` only): after an oblique inelastic hit the two balls
decelerate along different directions and can close on each other again at once, which with
``e -> 0`` means endless zero-speed contacts. When the separation speed would be below
``speed_floor`` and their decelerations close the gap, the pair separates at
``min(v_close, speed_floor)`` instead: momentum is still conserved and energy never rises
(separation is never faster than approach).
"""
from __future__ import annotations

import math

from numba import njit



@njit(cache=True)
def resolve_ball_ball(
    vel, i: int, j: int, nx: float, ny: float, mi: float, mj: float, e: float, decel: float, speed_floor: float
) -> float:
    """Apply the ball-ball impulse to ``vel[i]``, ``vel[j]`` for unit normal ``n`` (from j to i).

    ``decel`` is the rolling deceleration (0 under drag or without friction: no guard needed).
    Returns the closing speed before the hit (0 and no change if the pair is not closing).
    """
    rvx = vel[i, 0] - vel[j, 0]
    rvy = vel[i, 1] - vel[j, 1]
    v_close = -(rvx * nx + rvy * ny)
    if not v_close > 0.0:
        return 0.0
    v_sep = e * v_close
    mu = mi * mj / (mi + mj)
    if decel > 0.0 and v_sep < speed_floor and e < 1.0:
        # Would the decelerations (along each ball's new direction) close the gap again?
        j_imp = mu * (v_close + v_sep)
        uix = vel[i, 0] + j_imp / mi * nx
        uiy = vel[i, 1] + j_imp / mi * ny
        ujx = vel[j, 0] - j_imp / mj * nx
        ujy = vel[j, 1] - j_imp / mj * ny
        si = math.hypot(uix, uiy)
        sj = math.hypot(ujx, ujy)
        ui_n = (uix * nx + uiy * ny) / si if si > 0.0 else 0.0
        uj_n = (ujx * nx + ujy * ny) / sj if sj > 0.0 else 0.0
        if ui_n - uj_n > 0.0:  # the gap's opening speed d/dt = -a (u_i - u_j).n is falling
            v_sep = min(v_close, speed_floor)
    j_imp = mu * (v_close + v_sep)
    vel[i, 0] += j_imp / mi * nx
    vel[i, 1] += j_imp / mi * ny
    vel[j, 0] -= j_imp / mj * nx
    vel[j, 1] -= j_imp / mj * ny
    return v_close


@njit(cache=True)
def resolve_cushion(vel, i: int, cushion: int, e_c: float) -> float:
    """Reflect the normal component of ``vel[i]`` off cushion ``cushion`` (0 left, 1 right, 2 bottom, 3 top),
    scaled by ``e_c``; returns the normal speed into the cushion before the hit (0 if moving away)."""
    axis = 0 if cushion < 2 else 1
    sign = -1.0 if cushion % 2 == 0 else 1.0  # outward normal of the wall
    vn = vel[i, axis] * sign
    if not vn > 0.0:
        return 0.0
    vel[i, axis] = -e_c * vel[i, axis]
    return vn
