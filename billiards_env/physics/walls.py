"""A jaw table's cushions in the compiled solvers: when a ball meets a rail, a jaw face or a jaw tip, and the
contact normal there (numba).

The geometry is two arrays, ``segs`` (one-sided straight cushions: ``ax, ay, bx, by, nx, ny``, the unit normal
pointing to the open side) and ``tips`` (rounded jaw tips: ``cx, cy, radius``), built by
:func:`.pocket_specs.build_walls`; the solvers read them from the parameter record (``prm.segs[:prm.n_segs]``,
through the ``prm`` forms below), the players from their table model. A wall index is a segment's row, or the
number of segments plus a tip's row.

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

import numpy as np
from numba import njit

from .kernel_logs import inlined, internal, leaf, rewind_time
from .roots import first_entry, quadratic_roots_in, ray_circle_below

#: A ball whose centre's projection lies this far (m) beyond a segment's end still counts as on the segment: the
#: rounding of a projection computed at the contact point (a ball meeting a rail exactly where its jaw tip begins).
END_SLACK = 1e-12


#: A ball counts as moving into a wall only if its direction's component along the wall's normal is below
#: ``-GRAZE`` (a tip: the cosine between its direction and the line of centres). A reflection off a slanted wall with
#: no restitution, or a jam, leaves the normal velocity at round-off, possibly ``-1e-17`` into the wall: counted as a
#: hit, that is an endless storm of zero-speed hits at one instant (the fuzz found it). A ball running at under
#: ``GRAZE`` rad into a wall goes at most ``GRAZE`` m into it per metre it runs.
GRAZE = 1e-12


@internal
def has_walls(prm):
    """Whether the table is a jaw table (its cushions are the record's segments and tips)."""
    return prm.n_segs > 0 or prm.n_tips > 0


@internal
def walls_of(prm):
    """The record's walls as ``(segs, tips)`` arrays (views)."""
    return prm.segs[:prm.n_segs], prm.tips[:prm.n_tips]


@internal
def on_segment(x, y, k, prm):
    """Whether the projection of ``(x, y)`` on segment ``k``'s line lies between its ends."""
    return on_seg(x, y, prm.segs[k])


@internal
def on_seg(x, y, seg):
    """:func:`on_segment` for the segment row ``seg``."""
    ax = seg[0]
    ay = seg[1]
    dx = seg[2] - ax
    dy = seg[3] - ay
    ll = dx * dx + dy * dy
    s = ((x - ax) * dx + (y - ay) * dy) / ll
    slack = END_SLACK / math.sqrt(ll)
    return -slack <= s <= 1.0 + slack


@internal
def ray_line_hit(px, py, ux, uy, r, seg):
    """:func:`ray_segment_hit` before its test that the contact lies on the segment: the distance along the ray
    until a ball of radius ``r`` meets the segment row ``seg``'s line (from its open side), ``inf`` if it never
    does. Callers that keep only a nearer hit test the segment (:func:`on_seg`) only then."""
    nx = seg[4]
    ny = seg[5]
    un = ux * nx + uy * ny
    if not un < -GRAZE:
        return math.inf
    gap = (px - seg[0]) * nx + (py - seg[1]) * ny - r
    if gap < -r:  # the centre is behind the line: the ball is not on this segment's side
        return math.inf
    return max(gap / -un, 0.0)


@internal
def ray_segment_hit(px, py, ux, uy, r, seg):
    """Distance along the ray ``p + d u`` (``u`` a unit vector) until a ball of radius ``r`` meets the segment row
    ``seg``; ``inf`` if it never does. A ball already within ``r`` of the line and moving into it meets it at
    once."""
    d = ray_line_hit(px, py, ux, uy, r, seg)
    if d < math.inf and on_seg(px + d * ux, py + d * uy, seg):
        return d
    return math.inf


@internal
def ray_tip_hit(px, py, ux, uy, r, tip):
    """Distance along the ray until a ball of radius ``r`` meets the tip row ``tip`` (its centre ``r + radius``
    from the tip's centre), moving towards it; ``inf`` if it never does. A ball already that close and approaching
    meets it at once."""
    return ray_tip_below(px, py, ux, uy, r, tip, math.inf)


@internal
def ray_tip_below(px, py, ux, uy, r, tip, limit):
    """:func:`ray_tip_hit`, or ``inf`` early when the hit is surely not nearer than ``limit``: the root
    ``c / (-b + sqrt(b^2 - c))`` is at least ``c / (-2 b)`` (a margin far above round-off), so beyond that bound
    no square root is taken."""
    dx = px - tip[0]
    dy = py - tip[1]
    rho = r + tip[2]
    b = ux * dx + uy * dy
    if not b < -GRAZE * rho:
        return math.inf
    c = dx * dx + dy * dy - rho * rho
    if c <= 0.0:
        return 0.0
    if c >= -2.0 * b * limit * (1.0 + 1e-12):
        return math.inf
    disc = b * b - c
    if disc < 0.0:
        return math.inf
    return c / (-b + math.sqrt(disc))


@internal
def ray_wall_hit(px, py, ux, uy, r, prm, limit):
    """The first wall of the record ``prm`` the ray meets nearer than ``limit`` (:func:`ray_walls_below`): the same
    answer, with a pocket's jaw faces and tips passed over when the ray does not reach their group's circle
    (:func:`.kernel_io.wall_groups`, widened by ``r``: a ball touching one of them has its centre in it) nearer
    than the best hit so far."""
    if prm.n_groups == 0:
        return ray_walls_below(px, py, ux, uy, r, prm.segs[:prm.n_segs], prm.tips[:prm.n_tips], limit)
    best = limit
    wall = -1
    n_rails = prm.n_segs - prm.n_tips
    pad = r * (1.0 + 1e-9) + 1e-9
    for k in range(n_rails):
        d = ray_line_hit(px, py, ux, uy, r, prm.segs[k])
        if d < best and on_seg(px + d * ux, py + d * uy, prm.segs[k]):
            best = d
            wall = k
    for g in range(prm.n_groups):
        if not ray_circle_below(px, py, ux, uy, prm.groups[g, 0], prm.groups[g, 1], prm.groups[g, 2] + pad,
                                best) < best:
            continue
        for k in range(n_rails + 2 * g, n_rails + 2 * g + 2):
            d = ray_line_hit(px, py, ux, uy, r, prm.segs[k])
            if d < best and on_seg(px + d * ux, py + d * uy, prm.segs[k]):
                best = d
                wall = k
    for g in range(prm.n_groups):
        if not ray_circle_below(px, py, ux, uy, prm.groups[g, 0], prm.groups[g, 1], prm.groups[g, 2] + pad,
                                best) < best:
            continue
        for k in range(2 * g, 2 * g + 2):
            d = ray_tip_below(px, py, ux, uy, r, prm.tips[k], best)
            if d < best:
                best = d
                wall = prm.n_segs + k
    return best, wall


@internal
def ray_walls_hit(px, py, ux, uy, r, segs, tips):
    """The first wall the ray meets: ``(distance, wall index)``, ``(inf, -1)`` if none; the lower index on a tie."""
    return ray_walls_below(px, py, ux, uy, r, segs, tips, math.inf)


@leaf
def ray_walls_below(px, py, ux, uy, r, segs, tips, limit):
    """:func:`ray_walls_hit` among the hits nearer than ``limit``: ``(limit, -1)`` if none. A segment's line hit is
    tested for lying on the segment only when it is the nearest so far (the same answer, fewer tests)."""
    best = limit
    wall = -1
    for k in range(segs.shape[0]):
        d = ray_line_hit(px, py, ux, uy, r, segs[k])
        if d < best and on_seg(px + d * ux, py + d * uy, segs[k]):
            best = d
            wall = k
    for k in range(tips.shape[0]):
        d = ray_tip_below(px, py, ux, uy, r, tips[k], best)
        if d < best:
            best = d
            wall = segs.shape[0] + k
    return best, wall


@internal
def wall_normal_at(x, y, wall, prm):
    """The unit contact normal (away from the wall) of a ball centred at ``(x, y)`` touching ``wall``."""
    return normal_at(x, y, wall, prm.segs[:prm.n_segs], prm.tips[:prm.n_tips])


@internal
def normal_at(x, y, wall, segs, tips):
    """:func:`wall_normal_at` on the arrays."""
    if wall < segs.shape[0]:
        return segs[wall, 4], segs[wall, 5]
    k = wall - segs.shape[0]
    dx = x - tips[k, 0]
    dy = y - tips[k, 1]
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
def pushes_into_walls(x, y, r, vx, vy, prm):
    """Whether ``(vx, vy)`` has a component into a wall that a ball of radius ``r`` at ``(x, y)`` touches (within
    1e-9 m) beyond round-off (``1e-12`` of the speed)."""
    tol = 1e-12 * math.hypot(vx, vy)
    for wall in range(prm.n_segs + prm.n_tips):
        g = wall_gap(x, y, r, wall, prm)
        if g <= 1e-9 and g > -r:
            nx, ny = wall_normal_at(x, y, wall, prm)
            if vx * nx + vy * ny < -tol:
                return True
    return False


@leaf
def cluster_off_walls(px, py, radius, involved, count, cx, cy, prm):
    """The velocity ``(cx, cy)`` of a jammed cluster (members ``involved[:count]``, centres ``px``, ``py``) with no
    component into any wall a member touches. :func:`without_push_into_walls` member by member takes out one wall's
    component at a time, which can put back one into another wall the cluster is wedged against (two jaw faces of a
    throat, a jaw face and a rail): the passes repeat (at most ``MAX_WALL_PASSES``), and a cluster they leave still
    pushing into a wall has no free direction between its walls: it stops (the fuzz's storms of a pair wedged in a
    mouth)."""
    for _ in range(MAX_WALL_PASSES):
        for h in range(count):
            m = involved[h]
            cx, cy = without_push_into_walls(px[m], py[m], radius[m], cx, cy, prm)
        free = True
        for h in range(count):
            m = involved[h]
            if pushes_into_walls(px[m], py[m], radius[m], cx, cy, prm):
                free = False
                break
        if free:
            return cx, cy
    return 0.0, 0.0


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


#: Step solvers: at most this many walls are resolved per ball and step (a ball in a throat can touch a jaw face and
#: its tip, or both jaw faces, at once); every step kernel reserves room for this many cushion events per ball.
MAX_WALL_PASSES = 4
#: Step solvers: a ball overlapping a wall by less than this (m) touches it: the round-off :func:`touch_wall` leaves.
WALL_SLOP = 1e-12


@internal
def deepest_overlap(x, y, r, prm):
    """Step solvers: ``(gap, wall)`` of the wall a ball of radius ``r`` at ``(x, y)`` overlaps most (``gap <
    -WALL_SLOP``), ``(0, -1)`` if none. A segment counts while the centre projects onto it and lies at most ``r``
    behind its line (a step's overshoot; further behind, the ball is on the segment's other side); a tip counts
    whenever the ball overlaps it."""
    best = -WALL_SLOP
    wall = -1
    for k in range(prm.n_segs + prm.n_tips):
        g = wall_gap(x, y, r, k, prm)
        if g < best and (k >= prm.n_segs or g > -2.0 * r):
            best = g
            wall = k
    if wall < 0:
        return 0.0, wall
    return best, wall


@internal
def wall_reach(r, wall, prm):
    """The distance across the table from the centre of a ball of radius ``r`` touching ``wall`` to the wall's
    contact line: ``r`` for a segment, ``r`` plus the radius for a tip (the ``d`` of the cushion laws)."""
    if wall < prm.n_segs:
        return r
    return r + prm.tips[wall - prm.n_segs, 2]


@internal
def wall_rewind_time(x, y, vx, vy, r, wall, dt, prm):
    """Step solvers, contact treatment ``rewind``: how many seconds back (within the step of ``dt``) a ball of radius
    ``r`` now at ``(x, y)`` overlapping ``wall``, moving with ``(vx, vy)`` over the step, touched it; -1 if it was
    not moving into the wall or the touch lies outside the step."""
    if wall < prm.n_segs:
        vn = vx * prm.segs[wall, 4] + vy * prm.segs[wall, 5]
        if not vn < 0.0:
            return -1.0
        gap = (x - prm.segs[wall, 0]) * prm.segs[wall, 4] + (y - prm.segs[wall, 1]) * prm.segs[wall, 5] - r
        s = gap / vn
        return s if 0.0 <= s <= dt else -1.0
    # A tip: the ball-ball rewind against a resting circle of radius r + the tip's (|d - v s| = rho).
    k = wall - prm.n_segs
    return rewind_time(x - prm.tips[k, 0], y - prm.tips[k, 1], vx, vy, r + prm.tips[k, 2], dt)


@internal
def in_mouth_region(x, y, pocket_xy, pocket_r, prm):
    """Whether a ball centre at ``(x, y)`` lies in a pocket's mouth and throat (the convex hull of its jaw faces'
    ends and the rail ends nearest its tips, as :func:`.pocket_specs.mouth_polygons`) or in a pocket circle."""
    for p in range(pocket_r.shape[0]):
        dx = x - pocket_xy[p, 0]
        dy = y - pocket_xy[p, 1]
        if dx * dx + dy * dy <= pocket_r[p] * pocket_r[p]:
            return True
    n_rails = prm.n_segs - prm.n_tips
    if n_rails < 0 or prm.n_tips != 2 * pocket_r.shape[0]:
        return False
    pts = np.empty((6, 2))
    for p in range(pocket_r.shape[0]):
        a = n_rails + 2 * p
        for c in range(2):
            pts[0, c] = prm.segs[a, c]
            pts[1, c] = prm.segs[a, 2 + c]
            pts[4, c] = prm.segs[a + 1, 2 + c]
            pts[5, c] = prm.segs[a + 1, c]
        for k in range(2):  # where the rails stop: the rail end nearest each of the pocket's tips
            tx = prm.tips[2 * p + k, 0]
            ty = prm.tips[2 * p + k, 1]
            best = math.inf
            for q in range(n_rails):
                for e in range(2):
                    d = math.hypot(prm.segs[q, 2 * e] - tx, prm.segs[q, 2 * e + 1] - ty)
                    if d < best:
                        best = d
                        pts[2 + k, 0] = prm.segs[q, 2 * e]
                        pts[2 + k, 1] = prm.segs[q, 2 * e + 1]
        # In the convex hull: on the inner side of every line through two points that has all the others on one
        # side (a hull edge).
        inside = True
        for u in range(6):
            for v in range(u + 1, 6):
                ex = pts[v, 0] - pts[u, 0]
                ey = pts[v, 1] - pts[u, 1]
                if ex == 0.0 and ey == 0.0:
                    continue
                side = 0.0
                edge = True
                for w in range(6):
                    c = ex * (pts[w, 1] - pts[u, 1]) - ey * (pts[w, 0] - pts[u, 0])
                    if c != 0.0:
                        if side == 0.0:
                            side = c
                        elif (c > 0.0) != (side > 0.0):
                            edge = False
                            break
                if edge and side != 0.0:
                    c = ex * (y - pts[u, 1]) - ey * (x - pts[u, 0])
                    if c != 0.0 and (c > 0.0) != (side > 0.0):
                        inside = False
                        break
            if not inside:
                break
        if inside:
            return True
    return False


@internal
def back_onto_wall(pos, vel, i, r, wall, dt, rewind, prm):
    """Step solvers: put ball ``i`` (radius ``r``), which has overshot ``wall`` within the step ``dt``, back on it:
    with ``rewind``, first back along its velocity to the time of contact (:func:`wall_rewind_time`), then onto the
    wall along the contact normal (:func:`touch_wall`). Returns ``(back, nx, ny)``: how long it was taken back (< 0:
    not at all; the caller runs it on for as long with its new velocity) and the contact normal."""
    back = -1.0
    if rewind:
        back = wall_rewind_time(pos[i, 0], pos[i, 1], vel[i, 0], vel[i, 1], r, wall, dt, prm)
    if back >= 0.0:
        pos[i, 0] -= vel[i, 0] * back
        pos[i, 1] -= vel[i, 1] * back
    pos[i, 0], pos[i, 1] = touch_wall(pos[i, 0], pos[i, 1], r, wall, prm)
    nx, ny = wall_normal_at(pos[i, 0], pos[i, 1], wall, prm)
    return back, nx, ny


@internal
def push_out_of_walls(pos, i, r, prm):
    """Put ball ``i`` (radius ``r``) back on every wall it overlaps, the deepest first (at most
    ``MAX_WALL_PASSES``), moving its centre along the contact normal; velocities are not touched."""
    for _ in range(MAX_WALL_PASSES):
        _, wall = deepest_overlap(pos[i, 0], pos[i, 1], r, prm)
        if wall < 0:
            return
        pos[i, 0], pos[i, 1] = touch_wall(pos[i, 0], pos[i, 1], r, wall, prm)


@internal
def keep_on_jaw_table(pos, on_table, radius, pocket_xy, pocket_r, prm):
    """:func:`.kernel_logs.keep_on_table` of a jaw table (step solvers, after the pushes of ball pairs): a ball on
    the table overlapping a wall is put back on it (:func:`push_out_of_walls`); one whose centre then lies beyond the
    cushion lines and outside every mouth (:func:`in_mouth_region`) is put back inside ``[r, L - r] x [r, W - r]``
    (and off the walls again). A ball in a mouth stays where it is."""
    length = prm.length
    width = prm.width
    for i in range(pos.shape[0]):
        if not on_table[i]:
            continue
        r = radius[i]
        push_out_of_walls(pos, i, r, prm)
        x = pos[i, 0]
        y = pos[i, 1]
        if not (0.0 <= x <= length and 0.0 <= y <= width) and not in_mouth_region(x, y, pocket_xy, pocket_r, prm):
            pos[i, 0] = min(max(x, r), length - r)
            pos[i, 1] = min(max(y, r), width - r)
            push_out_of_walls(pos, i, r, prm)


@internal
def _segment_distance(px, py, x0, y0, x1, y1):
    """Distance from the point ``p`` to the segment from ``(x0, y0)`` to ``(x1, y1)``."""
    ex = x1 - x0
    ey = y1 - y0
    ee = ex * ex + ey * ey
    s = 0.0
    if ee > 0.0:
        s = min(max(((px - x0) * ex + (py - y0) * ey) / ee, 0.0), 1.0)
    return math.hypot(px - x0 - s * ex, py - y0 - s * ey)


@inlined
def path_box_clear(cx, cy, r, x, y, vx, vy, ax, ay, window):
    """:func:`path_clear_of` on the bounding box of the control points' triangle: a cheaper, weaker test (no
    division or square root), for the callers that run it on most of their candidates before the exact one."""
    if not window < math.inf:
        return False
    x1 = x + 0.5 * vx * window
    y1 = y + 0.5 * vy * window
    x2 = x + window * (vx + 0.5 * ax * window)
    y2 = y + window * (vy + 0.5 * ay * window)
    gx = max(min(x, x1, x2) - cx, cx - max(x, x1, x2), 0.0)
    gy = max(min(y, y1, y2) - cy, cy - max(y, y1, y2), 0.0)
    lim = r * (1.0 + 1e-9) + 1e-9
    return gx * gx + gy * gy > lim * lim


@internal
def path_clear_of(cx, cy, r, x, y, vx, vy, ax, ay, window):
    """Whether a ball's centre on ``p + v t + a t^2 / 2``, ``t`` in ``[0, window]``, stays farther than ``r`` (and a
    margin far above round-off) from ``c``: then the pocket's quartic has no root and need not be solved. The path
    is a quadratic Bezier curve, inside the triangle of its control points ``p``, ``p + v T / 2`` and its end
    (``T = window``); the test is the distance from ``c`` to that triangle (0 if ``c`` is inside)."""
    if not window < math.inf:
        return False
    x1 = x + 0.5 * vx * window
    y1 = y + 0.5 * vy * window
    x2 = x + window * (vx + 0.5 * ax * window)
    y2 = y + window * (vy + 0.5 * ay * window)
    # Inside the triangle (or on its edge): the same side of all three edges.
    d0 = (x1 - x) * (cy - y) - (y1 - y) * (cx - x)
    d1 = (x2 - x1) * (cy - y1) - (y2 - y1) * (cx - x1)
    d2 = (x - x2) * (cy - y2) - (y - y2) * (cx - x2)
    if (d0 >= 0.0 and d1 >= 0.0 and d2 >= 0.0) or (d0 <= 0.0 and d1 <= 0.0 and d2 <= 0.0):
        return False
    d = min(_segment_distance(cx, cy, x, y, x1, y1), _segment_distance(cx, cy, x1, y1, x2, y2),
            _segment_distance(cx, cy, x, y, x2, y2))
    return d > r * (1.0 + 1e-9) + 1e-9


@internal
def wall_time(c2, c1, c0, window, tol):
    """First time in ``[0, window]`` at which the wall distance ``c2 t^2 + c1 t + c0`` (positive on the table)
    reaches 0 from above; ``inf`` if none. A ball touching the wall (``c0 <= 0``) counts at once if it moves
    into it, or if it is not moving away (``|c1| <= tol``) while its acceleration presses it in (``c2 < 0``)."""
    if c0 <= 0.0:
        if c1 < -tol or (c2 < 0.0 and c1 <= tol):
            return 0.0
        if c2 < 0.0:  # moving away now, pulled back later: the larger root
            disc = c1 * c1 - 4.0 * c2 * c0
            root = (-c1 - math.sqrt(max(disc, 0.0))) / (2.0 * c2)
            return root if root <= window else math.inf
        return math.inf
    n, r1, _ = quadratic_roots_in(c2, c1, c0, 0.0, window)
    return r1 if n > 0 else math.inf


@internal
def path_wall_time(x, y, vx, vy, ax, ay, r, window, tol, acc_tol, far, prm):
    """First time in ``[0, window]`` at which a ball on ``p + v t + a t^2 / 2`` meets a jaw table's wall
    (:mod:`.walls`): ``(time, wall)``, ``(inf, -1)`` if none. A segment's distance is a quadratic in ``t``, met
    where its projection lies on the segment; a tip's is a quartic. Walls farther than ``far`` are skipped; a
    segment's normal acceleration within ``acc_tol`` of 0 is round-off (does not press the ball in)."""
    best = math.inf
    wall = -1
    # The path within the window lies in the triangle of its control points (a quadratic Bezier curve): a segment
    # whose line all three clear (margins far above round-off) is not met, without solving for it.
    bounded = window < math.inf
    x1 = x + 0.5 * vx * window if bounded else 0.0
    y1 = y + 0.5 * vy * window if bounded else 0.0
    x2 = x + window * (vx + 0.5 * ax * window) if bounded else 0.0
    y2 = y + window * (vy + 0.5 * ay * window) if bounded else 0.0
    # A pocket's jaw faces and tips (their group's circle, kernel_io.wall_groups, widened by r) that the path's
    # bounding box clears are not met either: passed over together.
    n_rails = prm.n_segs - prm.n_tips
    pad = r * (1.0 + 1e-9) + 1e-9
    clear = False
    for k in range(prm.n_segs):
        if prm.n_groups > 0 and k >= n_rails:
            if (k - n_rails) % 2 == 0:
                g = (k - n_rails) // 2
                clear = path_box_clear(prm.groups[g, 0], prm.groups[g, 1], prm.groups[g, 2] + pad, x, y, vx, vy, ax,
                                       ay, window)
            if clear:
                continue
        nx = prm.segs[k, 4]
        ny = prm.segs[k, 5]
        c0 = (x - prm.segs[k, 0]) * nx + (y - prm.segs[k, 1]) * ny - r
        if c0 > far or c0 < -2.0 * r:  # out of reach, or the centre behind the line (not on this side)
            continue
        if bounded and c0 > 1e-9 and (x1 - prm.segs[k, 0]) * nx + (y1 - prm.segs[k, 1]) * ny - r > 1e-9 and \
                (x2 - prm.segs[k, 0]) * nx + (y2 - prm.segs[k, 1]) * ny - r > 1e-9:
            continue
        an = ax * nx + ay * ny
        if abs(an) <= acc_tol:  # round-off of a ball settled on a slanted wall (the pressed rule): not pressing
            an = 0.0
        tau = wall_time(0.5 * an, vx * nx + vy * ny, c0, window, tol)
        if tau < best and on_segment(x + tau * (vx + 0.5 * ax * tau), y + tau * (vy + 0.5 * ay * tau), k, prm):
            best = tau
            wall = k
    for k in range(prm.n_tips):
        if prm.n_groups > 0:
            if k % 2 == 0:
                g = k // 2
                clear = path_box_clear(prm.groups[g, 0], prm.groups[g, 1], prm.groups[g, 2] + pad, x, y, vx, vy, ax,
                                       ay, window)
            if clear:
                continue
        dx = x - prm.tips[k, 0]
        dy = y - prm.tips[k, 1]
        rho = r + prm.tips[k, 2]
        if math.sqrt(dx * dx + dy * dy) - rho > far or \
                path_box_clear(prm.tips[k, 0], prm.tips[k, 1], rho, x, y, vx, vy, ax, ay, window) or \
                path_clear_of(prm.tips[k, 0], prm.tips[k, 1], rho, x, y, vx, vy, ax, ay, window):
            continue
        tau = first_entry(0.25 * (ax * ax + ay * ay), vx * ax + vy * ay, vx * vx + vy * vy + dx * ax + dy * ay,
                          2.0 * (dx * vx + dy * vy), dx * dx + dy * dy - rho * rho, window, tol)
        if tau < best:
            best = tau
            wall = prm.n_segs + k
    return best, wall


@njit(cache=True)
def on_rail_span(x, y, r, segs, n_rails, margin):
    """Whether a ball of radius ``r`` centred at ``(x, y)`` touching a cushion line bounces off a rail (one of the
    first ``n_rails`` segments) at least ``margin`` from the rail's ends, not in a pocket's mouth: where a one-rail
    kick on a jaw table may meet the cushion."""
    for k in range(n_rails):
        nx = segs[k, 4]
        ny = segs[k, 5]
        if abs((x - segs[k, 0]) * nx + (y - segs[k, 1]) * ny - r) > 1e-9:
            continue
        dx = segs[k, 2] - segs[k, 0]
        dy = segs[k, 3] - segs[k, 1]
        length = math.hypot(dx, dy)
        s = ((x - segs[k, 0]) * dx + (y - segs[k, 1]) * dy) / length
        if margin <= s <= length - margin:
            return True
    return False


__all__ = ["back_onto_wall", "walls_of", "on_seg", "ray_walls_hit", "ray_walls_below", "ray_line_hit", "normal_at", "path_clear_of", "wall_time", "path_wall_time",
           "on_rail_span", "has_walls", "on_segment", "ray_segment_hit", "deepest_overlap", "wall_reach",
           "wall_rewind_time", "in_mouth_region", "push_out_of_walls", "keep_on_jaw_table", "MAX_WALL_PASSES",
           "WALL_SLOP", "GRAZE", "pushes_into_walls", "cluster_off_walls", "ray_tip_hit", "ray_tip_below", "path_box_clear", "ray_wall_hit", "wall_normal_at",
           "touch_wall", "wall_gap", "without_push_into_walls", "reflect_off", "END_SLACK"]
