"""A jaw table's cushions in the compiled solvers: when a ball meets a rail, a jaw face or a jaw tip, and the
contact normal there (numba).

The geometry is the parameter record's ``segs`` (one-sided straight cushions: ``ax, ay, bx, by, nx, ny``, the unit
normal pointing to the open side) and ``tips`` (rounded jaw tips: ``cx, cy, radius``), built by
:func:`.pocket_specs.build_walls`. A wall index is a segment's row, or ``n_segs`` plus a tip's row.

- A ball of radius ``r`` meets a segment when its centre is ``r`` from the segment's line, moving towards it, with
  the centre's projection on the segment (between its ends, inclusive).
- It meets a tip when its centre is ``r + radius`` from the tip's centre, moving towards it.
- The contact normal (into the table, away from the wall) is the segment's normal, or the unit vector from the
  tip's centre to the ball's centre. The collision laws take this normal as they take a straight cushion's.

A table under the ``capture`` model has no rows here (``n_segs = n_tips = 0``): its four cushions are the edges of
the playing area, handled by :func:`.aim.ray_cushion_hit`.
"""
from __future__ import annotations

import math

from .kernel_logs import internal

#: A ball whose centre's projection lies this far (m) beyond a segment's end still counts as on the segment: the
#: rounding of a projection computed at the contact point (a ball meeting a rail exactly where its jaw tip begins).
END_SLACK = 1e-12


@internal
def has_walls(prm):
    """Whether the table is a jaw table (its cushions are the record's segments and tips)."""
    return prm.n_segs > 0 or prm.n_tips > 0


@internal
def on_segment(x, y, k, prm):
    """Whether the projection of ``(x, y)`` on segment ``k``'s line lies between its ends."""
    ax = prm.segs[k, 0]
    ay = prm.segs[k, 1]
    dx = prm.segs[k, 2] - ax
    dy = prm.segs[k, 3] - ay
    ll = dx * dx + dy * dy
    s = ((x - ax) * dx + (y - ay) * dy) / ll
    slack = END_SLACK / math.sqrt(ll)
    return -slack <= s <= 1.0 + slack


@internal
def ray_segment_hit(px, py, ux, uy, r, k, prm):
    """Distance along the ray ``p + d u`` (``u`` a unit vector) until a ball of radius ``r`` meets segment ``k``;
    ``inf`` if it never does. A ball already within ``r`` of the line and moving into it meets it at once."""
    nx = prm.segs[k, 4]
    ny = prm.segs[k, 5]
    un = ux * nx + uy * ny
    if not un < 0.0:
        return math.inf
    gap = (px - prm.segs[k, 0]) * nx + (py - prm.segs[k, 1]) * ny - r
    if gap < -r:  # the centre is behind the line: the ball is not on this segment's side
        return math.inf
    d = max(gap / -un, 0.0)
    if on_segment(px + d * ux, py + d * uy, k, prm):
        return d
    return math.inf


@internal
def ray_tip_hit(px, py, ux, uy, r, k, prm):
    """Distance along the ray until a ball of radius ``r`` meets tip ``k`` (its centre ``r + radius`` from the tip's
    centre), moving towards it; ``inf`` if it never does. A ball already that close and approaching meets it at
    once."""
    dx = px - prm.tips[k, 0]
    dy = py - prm.tips[k, 1]
    rho = r + prm.tips[k, 2]
    b = ux * dx + uy * dy
    if not b < 0.0:
        return math.inf
    c = dx * dx + dy * dy - rho * rho
    if c <= 0.0:
        return 0.0
    disc = b * b - c
    if disc < 0.0:
        return math.inf
    return c / (-b + math.sqrt(disc))


@internal
def ray_wall_hit(px, py, ux, uy, r, prm):
    """The first wall the ray meets: ``(distance, wall index)``, ``(inf, -1)`` if none; the lower index on a tie."""
    best = math.inf
    wall = -1
    for k in range(prm.n_segs):
        d = ray_segment_hit(px, py, ux, uy, r, k, prm)
        if d < best:
            best = d
            wall = k
    for k in range(prm.n_tips):
        d = ray_tip_hit(px, py, ux, uy, r, k, prm)
        if d < best:
            best = d
            wall = prm.n_segs + k
    return best, wall


@internal
def wall_normal_at(x, y, wall, prm):
    """The unit contact normal (away from the wall) of a ball centred at ``(x, y)`` touching ``wall``."""
    if wall < prm.n_segs:
        return prm.segs[wall, 4], prm.segs[wall, 5]
    k = wall - prm.n_segs
    dx = x - prm.tips[k, 0]
    dy = y - prm.tips[k, 1]
    d = math.hypot(dx, dy)
    return dx / d, dy / d


@internal
def touch_wall(x, y, r, wall, prm):
    """The point where a ball of radius ``r`` centred near ``(x, y)`` exactly touches ``wall``: the centre moved along
    the contact normal to distance ``r`` (segment) or ``r + radius`` (tip). Keeps round-off from building up."""
    if wall < prm.n_segs:
        nx = prm.segs[wall, 4]
        ny = prm.segs[wall, 5]
        gap = (x - prm.segs[wall, 0]) * nx + (y - prm.segs[wall, 1]) * ny - r
        return x - gap * nx, y - gap * ny
    k = wall - prm.n_segs
    dx = x - prm.tips[k, 0]
    dy = y - prm.tips[k, 1]
    d = math.hypot(dx, dy)
    rho = r + prm.tips[k, 2]
    return prm.tips[k, 0] + dx * (rho / d), prm.tips[k, 1] + dy * (rho / d)


@internal
def wall_gap(x, y, r, wall, prm):
    """How far a ball of radius ``r`` at ``(x, y)`` is from touching ``wall`` (< 0: overlapping it); ``inf`` for a
    segment whose line the centre does not project onto."""
    if wall < prm.n_segs:
        if not on_segment(x, y, wall, prm):
            return math.inf
        return (x - prm.segs[wall, 0]) * prm.segs[wall, 4] + (y - prm.segs[wall, 1]) * prm.segs[wall, 5] - r
    k = wall - prm.n_segs
    return math.hypot(x - prm.tips[k, 0], y - prm.tips[k, 1]) - r - prm.tips[k, 2]


@internal
def without_push_into_walls(x, y, r, vx, vy, prm):
    """``(vx, vy)`` less its component into every wall that a ball of radius ``r`` at ``(x, y)`` touches (within
    1e-9 m): the velocity a jammed cluster keeps against the jaws."""
    for wall in range(prm.n_segs + prm.n_tips):
        g = wall_gap(x, y, r, wall, prm)
        if g <= 1e-9 and g > -r:
            nx, ny = wall_normal_at(x, y, wall, prm)
            vn = vx * nx + vy * ny
            if vn < 0.0:
                vx -= vn * nx
                vy -= vn * ny
    return vx, vy


@internal
def reflect_off(vel, i, nx, ny, e_c):
    """Reverse the normal component of ``vel[i]`` against a wall of unit normal ``n`` (away from the wall), scaled
    by ``e_c``; the tangential component is kept. Returns the normal speed into the wall before the hit (0 if
    moving away: then nothing changes)."""
    vn = vel[i, 0] * nx + vel[i, 1] * ny
    if not vn < 0.0:
        return 0.0
    k = (1.0 + e_c) * vn
    vel[i, 0] -= k * nx
    vel[i, 1] -= k * ny
    return -vn


__all__ = ["has_walls", "on_segment", "ray_segment_hit", "ray_tip_hit", "ray_wall_hit", "wall_normal_at",
           "touch_wall", "wall_gap", "without_push_into_walls", "reflect_off", "END_SLACK"]
