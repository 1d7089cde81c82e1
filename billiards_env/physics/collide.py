"""Instantaneous collision laws shared by both solvers (compiled with numba).

Ball-ball: impulse along the line of centres ``n``; the normal relative speed ``v_close`` becomes a
separation speed ``e * v_close``; tangential components are kept. With masses ``m1, m2`` and
``mu = m1 m2 / (m1 + m2)`` the impulse is ``J = mu (1 + e) v_close``: momentum is conserved exactly
and kinetic energy drops by ``mu (1 - e^2) v_close^2 / 2`` (none at ``e = 1``).

Two guards keep the event-driven solver out of inelastic collapse (endless collisions in finite time);
both conserve momentum and never add energy:

- *Same-instant floor*: a collision of a ball that already collided within ``CONTACT_TIME`` (a cluster
  resolved pair by pair, a ball wedged against a cushion) separates at least at ``min(v_close, floor)``
  instead of ``e * v_close`` (never faster than it approached). Chains then end in finitely many hits.
- *Sticky contact* (rolling friction only): two touching balls that barely separate (below ``floor``) while
  their decelerations, each along its own direction of motion, press them together would slide into each
  other. Such a pair is given its common centre-of-mass velocity: it rolls on together, as pushed balls do.
- *Jam* (in ``exact``): a ball caught in a burst of more than ``JAM_EVENTS`` collisions, each within
  ``CONTACT_TIME`` of the previous one (a cluster of touching balls with restitution near 0, a ball wedged in a
  crevice between a cushion and a ball that cannot move), jams its contact cluster: every ball touching it,
  directly or through others, moves on with the cluster's centre-of-mass velocity, less any component into a
  cushion a member touches.
"""
from __future__ import annotations

import math

from numba import njit

#: Collisions of a ball within this many seconds of its previous collision count as one contact cluster.
CONTACT_TIME = 1e-6
#: A ball in more than this many collisions of one cluster is jammed (see the module docstring).
JAM_EVENTS = 64


@njit(cache=True)
def resolve_ball_ball(
    vel, i: int, j: int, nx: float, ny: float, dist: float, mi: float, mj: float, e: float, decel: float,
    speed_floor: float, clustered: bool,
) -> float:
    """Apply the collision of balls ``i`` and ``j`` to ``vel`` for unit normal ``n`` (from j to i) at centre
    distance ``dist``. ``decel``: rolling deceleration (0 under drag or without friction: no sticky contact).
    ``clustered``: one of the balls collided within ``CONTACT_TIME`` (the same-instant floor applies).

    Returns the closing speed before the hit (0 if the pair was not closing).
    """
    rvx = vel[i, 0] - vel[j, 0]
    rvy = vel[i, 1] - vel[j, 1]
    v_close = -(rvx * nx + rvy * ny)
    if v_close > 0.0:
        v_sep = e * v_close
        if clustered and v_sep < speed_floor:
            v_sep = min(v_close, speed_floor)
        j_imp = mi * mj / (mi + mj) * (v_close + v_sep)
        vel[i, 0] += j_imp / mi * nx
        vel[i, 1] += j_imp / mi * ny
        vel[j, 0] -= j_imp / mj * nx
        vel[j, 1] -= j_imp / mj * ny
    if decel > 0.0 and is_sticky(vel, i, j, nx, ny, dist, decel, speed_floor):
        tot = mi + mj
        cx = (mi * vel[i, 0] + mj * vel[j, 0]) / tot
        cy = (mi * vel[i, 1] + mj * vel[j, 1]) / tot
        vel[i, 0] = cx
        vel[i, 1] = cy
        vel[j, 0] = cx
        vel[j, 1] = cy
    return max(v_close, 0.0)


@njit(cache=True)
def is_sticky(vel, i: int, j: int, nx: float, ny: float, dist: float, decel: float, speed_floor: float) -> bool:
    """Whether touching balls ``i``, ``j`` separate slower than ``speed_floor`` while rolling friction closes
    the gap: the squared distance's second derivative ``|v_rel|^2 - decel * dist * (u_i - u_j).n`` is negative."""
    rvx = vel[i, 0] - vel[j, 0]
    rvy = vel[i, 1] - vel[j, 1]
    if rvx * nx + rvy * ny >= speed_floor:
        return False
    si = math.hypot(vel[i, 0], vel[i, 1])
    sj = math.hypot(vel[j, 0], vel[j, 1])
    ui_n = (vel[i, 0] * nx + vel[i, 1] * ny) / si if si > 0.0 else 0.0
    uj_n = (vel[j, 0] * nx + vel[j, 1] * ny) / sj if sj > 0.0 else 0.0
    closing = decel * dist * (ui_n - uj_n)
    return closing > 0.0 and rvx * rvx + rvy * rvy < closing * (1.0 + 1e-9)


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
