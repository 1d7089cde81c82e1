"""Aiming geometry on the engine's model: rays to pockets and cushions, the ghost ball, cut angles, pocket entry
windows, clear paths, what a collision does to the cue ball, and a lone ball's straight path (with cushion
bounces) into a pocket.

This module is the one home of these formulas. The exact solver calls its compiled ray tests
(:func:`ray_circle_entry`, :func:`ray_cushion_hit`) to find every pocket and cushion event, so a player aiming
with them sees pockets and cushions exactly as the engine does. The baseline players (:mod:`billiards_env.players`),
the envs' action and observation types and the renderer's aim line call it too. How far a ball rolls and how fast it still goes come
from :mod:`.motion`; what a collision does comes from :mod:`.collide` (the same code the solvers run).

Conventions: SI units (m, m/s, kg); angles in radians, 0 = +x, counter-clockwise; points and vectors are
``(x, y)`` pairs (sequences or arrays); a *direction* vector has unit length. The table is
``[0, length] x [0, width]``: a ball of radius ``r`` touches a cushion when its centre comes within ``r`` of it,
and a pocket captures a ball the instant its centre enters the pocket's capture circle. No spin, no throw.

    import numpy as np
    from billiards_env.physics import BALL_RADIUS, Table, aim

    table = Table()
    cue, obj = np.array([1.0, 0.4]), np.array([2.0, 0.9])
    window = aim.pocket_window(obj, BALL_RADIUS, table, pocket=5)     # (direction, half-width, distance) or None
    ghost = aim.ghost_ball_position(obj, window[0], 2 * BALL_RADIUS)  # where the cue ball must touch it
    angle = aim.aim_angle(cue, ghost)                                 # strike the cue ball this way
    cut = aim.cut_angle(aim.direction_vector(angle), aim.direction_vector(window[0]))
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Sequence, Union

import numpy as np
from llvmlite import ir
from numba import njit, types
from numba.extending import intrinsic

from .collide import resolve_ball_ball
from .motion import speed_after_distance, stop_distance
from .roots import ray_circle_below
from .plain import plain
from .walls import GRAZE, normal_at, on_seg, ray_line_hit, ray_tip_below, ray_walls_hit
from .kernel_logs import leaf_public

if TYPE_CHECKING:
    from .model import Physics
    from .table import Table

#: A point or vector ``(x, y)``.
Vec2 = Union[Sequence[float], np.ndarray]

#: Directions sampled across a pocket's angular size when computing its entry window.
WINDOW_SAMPLES = 41


# --- rays (compiled: the exact solver calls these) -------------------------------------------------------------

@njit(cache=True)
def ray_circle_entry(px: float, py: float, ux: float, uy: float, cx: float, cy: float, r: float) -> float:
    """Distance along the ray ``p + t u`` (``u`` a direction) to where it enters the circle of centre ``c`` and
    radius ``r``: 0 if ``p`` is inside or on the circle, ``inf`` if the ray misses it or points away from it.

    The root ``t = c / (-b + sqrt(b^2 - c))`` of ``t^2 + 2 b t + c = 0`` is the smaller one, written without the
    cancellation of ``-b - sqrt(...)``.
    """
    return ray_circle_below(px, py, ux, uy, cx, cy, r, math.inf)



@leaf_public
def first_pocket_on_ray(x: float, y: float, ux: float, uy: float, limit: float, pocket_xy: np.ndarray,
                        pocket_r: np.ndarray) -> tuple:
    """The first pocket whose capture circle the ray from ``(x, y)`` along the unit ``(ux, uy)`` enters within
    ``limit`` (:func:`ray_circle_entry`; the lower index on a tie): ``(pocket, distance)``, ``(-1, inf)`` if none."""
    best = math.inf
    pocket = -1
    for p in range(pocket_r.shape[0]):
        t = ray_circle_entry(x, y, ux, uy, pocket_xy[p, 0], pocket_xy[p, 1], pocket_r[p])
        if t <= limit and t < best:
            best = t
            pocket = p
    return pocket, best


@njit(cache=True)
def ray_cushion_hit(px: float, py: float, ux: float, uy: float, length: float, width: float,
                    r: float) -> tuple[float, int]:
    """Distance along the ray ``p + t u`` until a ball of radius ``r`` centred on it touches a cushion, and which
    cushion (0 left, 1 right, 2 bottom, 3 top). A ball already at or past a cushion it moves into hits it at once
    (distance 0); a tie goes to the left/right cushion; ``u = 0`` gives ``(inf, -1)``."""
    best = math.inf
    cushion = -1
    if ux != 0.0:
        wall = length - r if ux > 0.0 else r
        best = max((wall - px) / ux, 0.0)
        cushion = 1 if ux > 0.0 else 0
    if uy != 0.0:
        wall = width - r if uy > 0.0 else r
        d = max((wall - py) / uy, 0.0)
        if d < best:
            best = d
            cushion = 3 if uy > 0.0 else 2
    return best, cushion


@njit(cache=True)
def cushion_ahead(px: float, py: float, ux: float, uy: float, length: float, width: float, r: float,
                  segs: np.ndarray, tips: np.ndarray) -> tuple[float, int]:
    """The first cushion a ball of radius ``r`` rolling along the ray meets, as the exact solver sees it:
    :func:`ray_cushion_hit` on a capture table (no ``segs`` or ``tips``), the first rail, jaw face or jaw tip
    (:func:`.walls.ray_walls_hit`) on a jaw table. ``(distance, cushion or wall index)``."""
    if segs.shape[0] > 0 or tips.shape[0] > 0:
        return ray_walls_hit(px, py, ux, uy, r, segs, tips)
    return ray_cushion_hit(px, py, ux, uy, length, width, r)


@leaf_public
def bounce_off(vx: float, vy: float, x: float, y: float, cushion: int, length: float, width: float, r: float,
               e_cushion: float, segs: np.ndarray, tips: np.ndarray) -> tuple[float, float]:
    """A rolling ball's velocity after it meets ``cushion`` (from :func:`cushion_ahead`) at ``(x, y)``: the normal
    part reversed and scaled by ``e_cushion`` (the linear model's law, :func:`.walls.reflect_off`)."""
    if segs.shape[0] > 0 or tips.shape[0] > 0:
        nx, ny = normal_at(x, y, cushion, segs, tips)
        vn = vx * nx + vy * ny
        if vn < 0.0:
            vx -= (1.0 + e_cushion) * vn * nx
            vy -= (1.0 + e_cushion) * vn * ny
        return vx, vy
    if x <= r + 1e-9 or x >= length - r - 1e-9:
        vx = -e_cushion * vx
    if y <= r + 1e-9 or y >= width - r - 1e-9:
        vy = -e_cushion * vy
    return vx, vy


@njit(cache=True)
def ray_cushion_distance(px: float, py: float, ux: float, uy: float, length: float, width: float,
                         r: float) -> float:
    """Distance along the ray ``p + t u`` until a ball of radius ``r`` touches a cushion (see
    :func:`ray_cushion_hit`)."""
    return ray_cushion_hit(px, py, ux, uy, length, width, r)[0]


@njit(cache=True)
def ray_circle_entries(px: float, py: float, ux: np.ndarray, uy: np.ndarray, cx: float, cy: float,
                       r: float) -> np.ndarray:
    """:func:`ray_circle_entry` for many directions ``(ux[k], uy[k])`` from one point."""
    out = np.empty(ux.shape[0])
    for k in range(ux.shape[0]):
        out[k] = ray_circle_entry(px, py, ux[k], uy[k], cx, cy, r)
    return out


@njit(cache=True)
def ray_cushion_distances(px: float, py: float, ux: np.ndarray, uy: np.ndarray, length: float, width: float,
                          r: float) -> np.ndarray:
    """:func:`ray_cushion_distance` for many directions ``(ux[k], uy[k])`` from one point."""
    out = np.empty(ux.shape[0])
    for k in range(ux.shape[0]):
        out[k] = ray_cushion_hit(px, py, ux[k], uy[k], length, width, r)[0]
    return out


# --- directions and angles -------------------------------------------------------------------------------------

def aim_angle(start: Vec2, target: Vec2) -> float:
    """Direction (rad) from point ``start`` to point ``target``."""
    return math.atan2(target[1] - start[1], target[0] - start[0])


def direction_vector(angle: float) -> np.ndarray:
    """The direction ``(cos, sin)`` of an angle."""
    return np.array([math.cos(angle), math.sin(angle)])


def wrap_angle(angle):
    """An angle (or array of angles) moved into ``[-pi, pi)``."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def angular_radius(radius: float, distance: float) -> float:
    """Half the angle a circle of ``radius`` fills seen from ``distance`` away from its centre (``pi / 2`` from
    inside it): the directions from the viewpoint that cross it lie within this of the direction to its centre."""
    return math.asin(min(1.0, radius / distance))


# --- ghost ball, cut -------------------------------------------------------------------------------------------

@njit(cache=True)
def ghost_point(ox: float, oy: float, direction: float, contact: float) -> tuple:
    """The ghost-ball position ``(gx, gy)``: where the cue ball's centre must be when it touches the object ball at
    ``(ox, oy)`` to send it off in ``direction`` (rad): ``contact`` (the sum of the two radii) behind it."""
    return ox - contact * math.cos(direction), oy - contact * math.sin(direction)


@njit(cache=True)
def ghost_ball_aim(cx: float, cy: float, ox: float, oy: float, direction: float, contact: float) -> float:
    """The cue direction (rad) from ``(cx, cy)`` that sends the object ball at ``(ox, oy)`` off in ``direction``:
    towards its ghost-ball position (:func:`ghost_point`)."""
    gx, gy = ghost_point(ox, oy, direction, contact)
    return math.atan2(gy - cy, gx - cx)


def ghost_ball_position(obj: Vec2, direction: float, contact: float) -> np.ndarray:
    """:func:`ghost_point` as an array: where the cue ball's centre must be when it touches the object ball at
    ``obj`` to send it off in ``direction`` (rad)."""
    return np.array(ghost_point(float(obj[0]), float(obj[1]), float(direction), float(contact)))


@intrinsic
def _fma(typingctx, a, b, c):
    """``a * b + c`` rounded once (LLVM's ``fma``), for :func:`dot2`."""
    sig = types.float64(types.float64, types.float64, types.float64)

    def codegen(context, builder, signature, args):
        d = ir.DoubleType()
        fn = builder.module.declare_intrinsic("llvm.fma", [d], ir.FunctionType(d, [d, d, d]))
        return builder.call(fn, args)

    return sig, codegen


@njit(cache=True)
def dot2(ax: float, ay: float, bx: float, by: float) -> float:
    """The dot product of ``(ax, ay)`` and ``(bx, by)``: ``ax * bx`` rounded, then ``ay * by`` added with one
    rounding (a fused multiply-add; as OpenBLAS's Haswell ddot rounds a 2-vector dot, which the compiled players
    replaced). Fixed here, so results do not depend on the BLAS build nor on the kernel a CPU selects (on some CPUs
    ``numpy.dot`` rounds each product)."""
    return _fma(ay, by, ax * bx)


@njit(cache=True)
def cos_between(ax: float, ay: float, bx: float, by: float) -> float:
    """:func:`cut_cosine` of the unit vectors ``(ax, ay)`` and ``(bx, by)`` (compiled)."""
    return min(max(dot2(ax, ay, bx, by), -1.0), 1.0)


def cut_cosine(aim_direction: Vec2, object_direction: Vec2) -> float:
    """Cosine of the cut angle: between the cue ball's direction at impact and the object ball's direction
    (both unit vectors), clipped to [-1, 1]."""
    return float(cos_between(float(aim_direction[0]), float(aim_direction[1]), float(object_direction[0]),
                             float(object_direction[1])))


def cut_angle(aim_direction: Vec2, object_direction: Vec2) -> float:
    """The cut angle (rad, in [0, pi]) between the cue ball's direction at impact and the direction the object
    ball takes (both unit vectors): 0 for a full (straight) hit; a pot needs it below ``pi / 2``."""
    return math.acos(cut_cosine(aim_direction, object_direction))


def offset_aim_angle(cue: Vec2, obj: Vec2, offset: float) -> float:
    """The cue direction whose line passes the object ball's centre at the signed distance ``offset``: 0 aims at
    the centre (a full hit), ``offset > 0`` turns the aim clockwise (the object ball goes off to the left of the
    cue's line), and ``|offset| = r_cue + r_obj`` is a graze. The offset is clipped to the cue-object distance."""
    dx = obj[0] - cue[0]
    dy = obj[1] - cue[1]
    d = math.hypot(dx, dy)
    return math.atan2(dy, dx) - math.asin(max(-1.0, min(1.0, offset / max(d, 1e-12))))


def aim_offset(cue: Vec2, obj: Vec2, angle: float) -> float:
    """Inverse of :func:`offset_aim_angle`: the signed distance at which the cue's line in direction ``angle``
    passes the object ball's centre."""
    dx = obj[0] - cue[0]
    dy = obj[1] - cue[1]
    return math.hypot(dx, dy) * math.sin(wrap_angle(math.atan2(dy, dx) - angle))


# --- pockets ---------------------------------------------------------------------------------------------------

@njit(cache=True)
def _window_sample(k: int, div: int, theta_c: float, half: float, step: float) -> float:
    """Direction of sample ``k`` of ``div + 1`` across ``[theta_c - half, theta_c + half]``, rounded exactly as
    ``theta_c + numpy.linspace(-half, half, div + 1)`` rounds it (``k * step - half``, the last one ``half``)."""
    if k == div:
        return theta_c + half
    if step == 0.0:
        return theta_c + (k / div * (2.0 * half) - half)
    return theta_c + (k * step - half)


@njit(cache=True)
def _window_sample_ok(ox: float, oy: float, a: float, cx: float, cy: float, pr: float, length: float,
                      width: float, radius: float) -> bool:
    """Whether a ball of ``radius`` at ``(ox, oy)`` rolling along direction ``a`` enters the capture circle
    ``(cx, cy, pr)`` before it touches a cushion of a capture table (the engine's ray tests, 1e-9 m of slack)."""
    ux = math.cos(a)
    uy = math.sin(a)
    t_in = ray_circle_entry(ox, oy, ux, uy, cx, cy, pr)
    if not math.isfinite(t_in):
        return False
    return t_in <= ray_cushion_hit(ox, oy, ux, uy, length, width, radius)[0] + 1e-9


#: How far (m) beyond a window's reach, on top of the ball's radius, a wall still counts as in its way
#: (:func:`_window_walls`): far above the round-off of the ray tests (and of a segment's end slack, 1e-12 m).
WALL_PAD = 1e-6


@njit(cache=True)
def _point_segment_distance(px: float, py: float, ax: float, ay: float, bx: float, by: float) -> float:
    """The distance from ``(px, py)`` to the segment from ``(ax, ay)`` to ``(bx, by)``."""
    dx = bx - ax
    dy = by - ay
    ll = dx * dx + dy * dy
    s = 0.0 if ll == 0.0 else min(max(((px - ax) * dx + (py - ay) * dy) / ll, 0.0), 1.0)
    return math.hypot(px - (ax + s * dx), py - (ay + s * dy))


@njit(cache=True)
def _segments_distance(ax: float, ay: float, bx: float, by: float, cx: float, cy: float, dx: float,
                       dy: float) -> float:
    """The distance between the segments ``a b`` and ``c d``: 0 when they cross or touch (as the signs of the
    orientations tell: a crossing that round-off hides lies at an end, which the ends' distances catch), else the
    least distance from an end to the other segment."""
    o1 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    o2 = (bx - ax) * (dy - ay) - (by - ay) * (dx - ax)
    o3 = (dx - cx) * (ay - cy) - (dy - cy) * (ax - cx)
    o4 = (dx - cx) * (by - cy) - (dy - cy) * (bx - cx)
    if (o1 <= 0.0 <= o2 or o2 <= 0.0 <= o1) and (o3 <= 0.0 <= o4 or o4 <= 0.0 <= o3):
        return 0.0
    return min(_point_segment_distance(ax, ay, cx, cy, dx, dy), _point_segment_distance(bx, by, cx, cy, dx, dy),
               _point_segment_distance(cx, cy, ax, ay, bx, by), _point_segment_distance(dx, dy, ax, ay, bx, by))


@leaf_public
def _window_walls(ox: float, oy: float, radius: float, cx: float, cy: float, pr: float, segs: np.ndarray,
                  tips: np.ndarray) -> int:
    """The walls of a jaw table a ball of ``radius`` rolling from ``(ox, oy)`` into the circle ``(cx, cy, pr)`` may
    touch on the way, as bits (segment ``k``: bit ``k``; tip ``k``: bit ``n_segs + k``); -1 (all) beyond 63 walls.

    Until it enters the circle the ball's centre stays within the convex hull of ``(ox, oy)`` and the circle, whose
    every point is within ``pr`` of the segment from ``(ox, oy)`` to ``(cx, cy)``; a wall it touches lies within
    ``radius`` of that hull. So a wall farther than ``pr + radius`` (and :data:`WALL_PAD`) from that segment (first
    by bounding boxes, then exactly) cannot be met, and its ray tests cannot change a sample's answer."""
    n_s = segs.shape[0]
    n_t = tips.shape[0]
    if n_s + n_t > 63:
        return -1
    pad = radius + WALL_PAD
    reach = pr + pad
    x0 = min(ox, cx - pr) - pad
    x1 = max(ox, cx + pr) + pad
    y0 = min(oy, cy - pr) - pad
    y1 = max(oy, cy + pr) + pad
    walls = 0
    for k in range(n_s):
        if max(segs[k, 0], segs[k, 2]) < x0 or min(segs[k, 0], segs[k, 2]) > x1 or \
                max(segs[k, 1], segs[k, 3]) < y0 or min(segs[k, 1], segs[k, 3]) > y1:
            continue
        if _segments_distance(segs[k, 0], segs[k, 1], segs[k, 2], segs[k, 3], ox, oy, cx, cy) > reach:
            continue
        walls |= 1 << k
    for k in range(n_t):
        tx = tips[k, 0]
        ty = tips[k, 1]
        tr = tips[k, 2]
        if tx + tr < x0 or tx - tr > x1 or ty + tr < y0 or ty - tr > y1:
            continue
        if _point_segment_distance(tx, ty, ox, oy, cx, cy) > reach + tr:
            continue
        walls |= 1 << (n_s + k)
    return walls


@leaf_public
def _window_sample_clear(ox: float, oy: float, a: float, cx: float, cy: float, pr: float, radius: float,
                         segs: np.ndarray, tips: np.ndarray, walls: int) -> bool:
    """:func:`_window_sample_ok` on a jaw table: whether the ball enters the pocket's circle before it touches a rail,
    jaw face or tip of ``walls`` (:func:`_window_walls`' bits). The same answer as testing the first wall ahead
    (:func:`.walls.ray_walls_hit`, ``t_in <= distance + 1e-9``): a wall fails the sample exactly when its own
    distance does (the test is monotone in the distance), so the first such wall decides, and a tip is solved
    only when it may be nearer than the circle (:func:`.walls.ray_tip_below`)."""
    ux = math.cos(a)
    uy = math.sin(a)
    t_in = ray_circle_entry(ox, oy, ux, uy, cx, cy, pr)
    if not math.isfinite(t_in):
        return False
    n_s = segs.shape[0]
    for k in range(n_s):
        if walls != -1:
            if walls >> k == 0:  # no wall left
                return True
            if not (walls >> k) & 1:
                continue
        d = ray_line_hit(ox, oy, ux, uy, radius, segs[k])
        if d + 1e-9 < t_in and on_seg(ox + d * ux, oy + d * uy, segs[k]):
            return False
    for k in range(tips.shape[0]):
        if walls != -1:
            if walls >> (n_s + k) == 0:
                return True
            if not (walls >> (n_s + k)) & 1:
                continue
        if ray_tip_below(ox, oy, ux, uy, radius, tips[k], t_in) + 1e-9 < t_in:
            return False
    return True


#: Samples of a window that :func:`window_of` tracks in one 64-bit mask (more: every sample is ray-tested).
_MASK_SAMPLES = 62
#: Margin (in samples) around a crossing direction: its computed position is off by far less (round-off, and the
#: 1e-9 m slack of the ray test seen as an angle).
_CROSS_MARGIN = 0.25


@njit(cache=True)
def _mark_crossing(mask: int, angle: float, theta_c: float, half: float, step: float, div: int) -> int:
    """``mask`` with the bits of the samples that must be ray-tested because direction ``angle`` (where a sample's
    feasibility may change) lies between them and the sample before: the samples ``k`` with the crossing in
    ``[k - 1, k]``, give or take :data:`_CROSS_MARGIN`."""
    d = angle - theta_c
    if d > math.pi:
        d -= 2.0 * math.pi
    elif d < -math.pi:
        d += 2.0 * math.pi
    s = (d + half) / step
    lo = max(int(math.ceil(s - _CROSS_MARGIN)), 0)
    hi = min(int(math.floor(s + 1.0 + _CROSS_MARGIN)), div)
    for k in range(lo, hi + 1):
        mask |= 1 << k
    return mask


@leaf_public
def window_of(ox: float, oy: float, radius: float, cx: float, cy: float, pr: float, length: float, width: float,
              samples: int, segs: np.ndarray, tips: np.ndarray) -> tuple:
    """:func:`pocket_window` for the capture circle ``(cx, cy, pr)``: ``(centre, half-width, distance, found)``.

    The window is the one sampled by ``samples`` directions across the circle's angular size (the widest run of
    directions that reach the circle before a cushion), found in closed form. From a ball inside the cushion lines,
    a direction reaches the circle first exactly when its entry point lies inside them, so feasibility changes only
    at the directions of the points where the circle crosses a cushion segment (from a ball on or beyond a cushion
    line: also where the direction crosses an axis, as the cushion ahead changes). Only the first sample after
    each such direction, and the first, second and last samples (the tangent directions, decided by round-off), are
    ray-tested (:func:`_window_sample_ok`); every other sample has the test of the one before. The result is
    bit-identical to ray-testing every sample. On a jaw table (``segs``, ``tips``: its walls) the window is the run
    of directions that pass the mouth, and the samples to ray-test against the rails, jaw faces and tips are chosen
    the same way, next to the directions where a wall's verdict may change (:func:`_window_jaws`). The table model
    is chosen once per window, so a capture table's loops carry no walls.
    """
    if segs.shape[0] > 0 or tips.shape[0] > 0:
        return _window_jaws(ox, oy, radius, cx, cy, pr, samples, segs, tips)
    return _window_capture(ox, oy, radius, cx, cy, pr, length, width, samples)


@njit(cache=True)
def _window_capture(ox: float, oy: float, radius: float, cx: float, cy: float, pr: float, length: float,
                    width: float, samples: int) -> tuple:
    """:func:`window_of` on a capture table (the four cushion lines): the closed-form choice of the samples to
    ray-test. No wall arrays reach its loops."""
    vx = cx - ox
    vy = cy - oy
    dist = math.hypot(vx, vy)
    theta_c = math.atan2(cy - oy, cx - ox)
    if dist <= pr:
        return theta_c, math.pi / 2, 0.0, True
    half = math.asin(min(1.0, pr / dist))
    div = samples - 1
    step = (half - (-half)) / div
    # The samples to ray-test, as bits.
    if samples > _MASK_SAMPLES or not step > 0.0:
        mask = -1
    else:
        mask = 1 | 2 | (1 << div)
        x_lo, x_hi, y_lo, y_hi = radius, length - radius, radius, width - radius
        inside = x_lo < ox < x_hi and y_lo < oy < y_hi
        tol = 1e-7
        for m in range(4):
            w = (x_lo, x_hi, y_lo, y_hi)[m]
            off = w - (cx if m < 2 else cy)
            if abs(off) > pr + tol:
                continue
            h = math.sqrt(max(pr * pr - off * off, 0.0))
            for sgn in (-1.0, 1.0):
                if m < 2:
                    qx, qy = w, cy + sgn * h
                    on_edge = y_lo - tol <= qy <= y_hi + tol
                else:
                    qx, qy = cx + sgn * h, w
                    on_edge = x_lo - tol <= qx <= x_hi + tol
                if on_edge or not inside:
                    mask = _mark_crossing(mask, math.atan2(qy - oy, qx - ox), theta_c, half, step, div)
        if not inside:  # the cushion ahead changes where the direction crosses an axis
            for m in range(-2, 3):
                mask = _mark_crossing(mask, 0.5 * math.pi * m, theta_c, half, step, div)
    # One pass over the samples: the widest run of feasible ones (the first of equals).
    best_len = plain(0)  # (plain: _window_sample and _window_result compiled for int64 only)
    best_start = plain(0)
    run_start = plain(-1)
    flag = False
    for k in range(div + 2):
        if k > div:
            flag = False
        elif mask == -1 or (mask >> k) & 1:
            flag = _window_sample_ok(ox, oy, _window_sample(k, div, theta_c, half, step), cx, cy, pr, length,
                                     width, radius)
        run_start, best_start, best_len = _track_run(flag, k, run_start, best_start, best_len)
    return _window_result(best_start, best_len, div, theta_c, half, step, ox, oy, cx, cy, pr, dist)


@leaf_public
def _window_jaws(ox: float, oy: float, radius: float, cx: float, cy: float, pr: float, samples: int,
                 segs: np.ndarray, tips: np.ndarray) -> tuple:
    """:func:`window_of` on a jaw table: the samples next to a direction where a wall's verdict may change
    (:func:`_jaw_crossings`), and the first, second and last, are ray-tested (:func:`_window_sample_clear`) against
    the walls that may lie in the window's way (:func:`_window_walls`, worked out once for all the samples); every
    other sample has the test of the one before."""
    vx = cx - ox
    vy = cy - oy
    dist = math.hypot(vx, vy)
    theta_c = math.atan2(cy - oy, cx - ox)
    if dist <= pr:
        return theta_c, math.pi / 2, 0.0, True
    half = math.asin(min(1.0, pr / dist))
    div = samples - 1
    step = (half - (-half)) / div
    walls = _window_walls(ox, oy, radius, cx, cy, pr, segs, tips)
    if samples > _MASK_SAMPLES or not step > 0.0 or dist - pr < JAW_EXACT_NEAR:
        mask = -1
    else:
        mask = _jaw_crossings(1 | 2 | (1 << div), ox, oy, radius, cx, cy, pr, segs, tips, walls, theta_c, half,
                              step, div)
    best_len = plain(0)  # (plain: _window_sample and _window_result compiled for int64 only)
    best_start = plain(0)
    run_start = plain(-1)
    flag = False
    for k in range(div + 2):
        if k > div:
            flag = False
        elif mask == -1 or (mask >> k) & 1:
            flag = _window_sample_clear(ox, oy, _window_sample(k, div, theta_c, half, step), cx, cy, pr, radius,
                                        segs, tips, walls)
        run_start, best_start, best_len = _track_run(flag, k, run_start, best_start, best_len)
    return _window_result(best_start, best_len, div, theta_c, half, step, ox, oy, cx, cy, pr, dist)


#: A ball nearer than this (m) to a pocket's circle has every sample of its jaw window ray-tested: its circle entry
#: is then within the 1e-9 m slack of the ray test, where :func:`_jaw_crossings`' directions do not hold.
JAW_EXACT_NEAR = 1e-6
#: How far (m) a point may lie on the wrong side of a circle or beyond a segment's end and still be taken as a
#: direction where a wall's verdict may change (:func:`_jaw_crossings`): far above round-off and the ends' slack.
JAW_TOL = 1e-6


@leaf_public
def _jaw_crossings(mask: int, ox: float, oy: float, radius: float, cx: float, cy: float, pr: float,
                   segs: np.ndarray, tips: np.ndarray, walls: int, theta_c: float, half: float, step: float,
                   div: int) -> int:
    """``mask`` with the samples of a jaw window marked (:func:`_mark_crossing`) next to every direction where a
    wall of ``walls`` (:func:`_window_walls`' bits) may change its verdict on a sample (:func:`_window_sample_clear`).

    A wall fails a direction when the ball meets it before it enters the circle. Between the directions below that
    verdict cannot change, as the contact point moves continuously along the wall and cannot pass the circle or
    the wall's end unseen:

    - a segment (the line ``radius`` off it, where the ball's centre touches it): the directions parallel to it
      (where the ray starts or stops approaching it), to its ends when they lie outside the circle, and to where
      it crosses the circle within its ends; a ball already within ``radius`` of its line meets it at once, so only
      the parallel directions count;
    - a tip (the circle ``radius + tip radius`` round it): the directions where the ray starts approaching it, its
      tangents when they touch it outside the pocket's circle, and where the two circles cross.

    Directions outside the window (give or take two samples) mark nothing and are passed over before their angle
    is worked out (two cross products against the window's widened edges)."""
    reach = half + 2.0 * step
    wide = reach >= 0.5 * math.pi - 1e-3  # (the edge test needs a range narrower than a half turn)
    lo_x = math.cos(theta_c - reach)
    lo_y = math.sin(theta_c - reach)
    hi_x = math.cos(theta_c + reach)
    hi_y = math.sin(theta_c + reach)
    n_s = segs.shape[0]
    for k in range(n_s):
        if walls != -1 and not (walls >> k) & 1:
            continue
        ax = segs[k, 0]
        ay = segs[k, 1]
        bx = segs[k, 2]
        by = segs[k, 3]
        nx = segs[k, 4]
        ny = segs[k, 5]
        gap = (ox - ax) * nx + (oy - ay) * ny - radius
        if gap < -radius:  # behind the line: the segment never meets the ball
            continue
        for sgn in (-1.0, 1.0):
            mask = _mark_toward(mask, ox - sgn * ny, oy + sgn * nx, ox, oy, lo_x, lo_y, hi_x, hi_y, wide, theta_c,
                                half, step, div)
        if gap <= 0.0:
            continue
        for e in range(2):
            ex = (ax if e == 0 else bx) + radius * nx
            ey = (ay if e == 0 else by) + radius * ny
            if (ex - cx) ** 2 + (ey - cy) ** 2 >= (pr - JAW_TOL) ** 2:
                mask = _mark_toward(mask, ex, ey, ox, oy, lo_x, lo_y, hi_x, hi_y, wide, theta_c, half, step, div)
        off = (cx - ax) * nx + (cy - ay) * ny - radius  # the circle's centre from the contact line
        if abs(off) > pr + JAW_TOL:
            continue
        chord = math.sqrt(max(pr * pr - off * off, 0.0))
        length = math.sqrt((bx - ax) ** 2 + (by - ay) ** 2)
        for sgn in (-1.0, 1.0):
            qx = cx - off * nx - sgn * chord * ny
            qy = cy - off * ny + sgn * chord * nx
            along = ((qx - ax) * (bx - ax) + (qy - ay) * (by - ay)) / length
            if -JAW_TOL <= along <= length + JAW_TOL:
                mask = _mark_toward(mask, qx, qy, ox, oy, lo_x, lo_y, hi_x, hi_y, wide, theta_c, half, step, div)
    for k in range(tips.shape[0]):
        if walls != -1 and not (walls >> (n_s + k)) & 1:
            continue
        tx = tips[k, 0]
        ty = tips[k, 1]
        rho = radius + tips[k, 2]
        dx = ox - tx
        dy = oy - ty
        d = math.sqrt(dx * dx + dy * dy)
        if d == 0.0:  # (the ray never approaches a tip it is centred on)
            continue
        if d < rho:  # already touching: met at once while approaching; the switch is exactly where it starts
            g = math.acos(min(1.0, max(-1.0, -GRAZE * rho / d)))
            phi = math.atan2(dy, dx)
            mask = _mark_crossing(mask, phi + g, theta_c, half, step, div)
            mask = _mark_crossing(mask, phi - g, theta_c, half, step, div)
            continue
        for sgn in (-1.0, 1.0):  # (starts approaching: perpendicular to the tip, to far below a sample)
            mask = _mark_toward(mask, ox - sgn * dy, oy + sgn * dx, ox, oy, lo_x, lo_y, hi_x, hi_y, wide, theta_c,
                                half, step, div)
        # The tangent points: rho / d of the way along (o - tip) turned by the tangent angle.
        along = rho * rho / d
        across = rho * math.sqrt(max(d * d - rho * rho, 0.0)) / d
        ux = dx / d
        uy = dy / d
        for sgn in (-1.0, 1.0):
            qx = tx + along * ux - sgn * across * uy
            qy = ty + along * uy + sgn * across * ux
            if (qx - cx) ** 2 + (qy - cy) ** 2 >= (pr - JAW_TOL) ** 2:
                mask = _mark_toward(mask, qx, qy, ox, oy, lo_x, lo_y, hi_x, hi_y, wide, theta_c, half, step, div)
        # Where the tip's circle crosses the pocket's.
        ex = cx - tx
        ey = cy - ty
        sep = math.sqrt(ex * ex + ey * ey)
        if sep == 0.0 or sep > rho + pr + JAW_TOL or sep < abs(rho - pr) - JAW_TOL:
            continue
        a = (rho * rho - pr * pr + sep * sep) / (2.0 * sep)
        h = math.sqrt(max(rho * rho - a * a, 0.0))
        for sgn in (-1.0, 1.0):
            qx = tx + (a * ex - sgn * h * ey) / sep
            qy = ty + (a * ey + sgn * h * ex) / sep
            mask = _mark_toward(mask, qx, qy, ox, oy, lo_x, lo_y, hi_x, hi_y, wide, theta_c, half, step, div)
    return mask


@njit(cache=True)
def _mark_toward(mask: int, qx: float, qy: float, ox: float, oy: float, lo_x: float, lo_y: float, hi_x: float,
                 hi_y: float, wide: bool, theta_c: float, half: float, step: float, div: int) -> int:
    """``mask`` with the samples next to the direction from ``(ox, oy)`` to ``(qx, qy)`` marked
    (:func:`_mark_crossing`), when that direction lies between the edges ``lo`` and ``hi`` (unit vectors; always
    when ``wide``)."""
    vx = qx - ox
    vy = qy - oy
    if not wide and (lo_x * vy - lo_y * vx < 0.0 or vx * hi_y - vy * hi_x < 0.0):
        return mask
    return _mark_crossing(mask, math.atan2(vy, vx), theta_c, half, step, div)


@njit(cache=True)
def _track_run(flag: bool, k: int, run_start: int, best_start: int, best_len: int) -> tuple:
    """One sample ``k`` of the scan for a window's widest run of feasible samples (the first of equals):
    ``(run_start, best_start, best_len)`` after it (``run_start`` -1 outside a run)."""
    if flag and run_start < 0:
        run_start = k
    elif not flag and run_start >= 0:
        if k - run_start > best_len:
            best_len = k - run_start
            best_start = run_start
        run_start = -1
    return run_start, best_start, best_len


@njit(cache=True)
def _window_result(best_start: int, best_len: int, div: int, theta_c: float, half: float, step: float, ox: float,
                   oy: float, cx: float, cy: float, pr: float, dist: float) -> tuple:
    """A window's ``(centre, half-width, distance, found)`` from its widest run of feasible samples."""
    if best_len == 0:
        return 0.0, 0.0, 0.0, False
    lo = best_start
    hi = best_start + best_len - 1
    step2 = 2.0 * half / div
    centre = 0.5 * (_window_sample(lo, div, theta_c, half, step) + _window_sample(hi, div, theta_c, half, step))
    width_ = 0.5 * ((hi - lo) * step2 + step2)
    d_in = ray_circle_entry(ox, oy, math.cos(centre), math.sin(centre), cx, cy, pr)
    if not math.isfinite(d_in):
        d_in = dist
    return centre, width_, d_in, True


@leaf_public
def pocket_windows(ox: float, oy: float, radius: float, pocket_xy: np.ndarray, pocket_r: np.ndarray, length: float,
                   width: float, samples: int, out: np.ndarray, segs: np.ndarray, tips: np.ndarray) -> None:
    """:func:`window_of` for every pocket: ``out[p] = (centre, half-width, distance, found)`` (``found`` 1.0 or
    0.0; the other columns are 0 without a window)."""
    for p in range(pocket_r.shape[0]):
        c, h, d, ok = window_of(ox, oy, radius, pocket_xy[p, 0], pocket_xy[p, 1], pocket_r[p], length, width,
                                samples, segs, tips)
        out[p, 0] = c
        out[p, 1] = h
        out[p, 2] = d
        out[p, 3] = 1.0 if ok else 0.0


def pocket_window(obj: Vec2, radius: float, table: Table, pocket: int,
                  samples: int = WINDOW_SAMPLES) -> tuple[float, float, float] | None:
    """The directions along which a ball of ``radius`` at ``obj`` rolls into the capture circle of ``pocket``
    before touching a cushion (on a jaw table: into the pocket circle through the mouth, touching no jaw).

    ``samples`` directions across the circle's angular size, as tested by the engine's own ray tests. Returns
    ``(centre direction, half-width, distance to the capture circle along the centre)`` of the widest contiguous
    run of good directions (a lone good sample counts as a sliver ``step / 2`` wide), or None if there is none.
    From inside the circle: ``(direction to its centre, pi / 2, 0)``. Compiled (:func:`window_of`): which samples
    are good follows from where the circle crosses the cushion lines, so few are ray-tested.
    """
    if samples < 2:
        raise ValueError(f"samples: need at least 2 directions across the pocket, got {samples}")
    c = table.pocket_xy[pocket]
    segs, tips = table.walls()
    centre, half, d_in, found = window_of(float(obj[0]), float(obj[1]), float(radius), float(c[0]), float(c[1]),
                                          float(table.pocket_radius[pocket]), float(table.length),
                                          float(table.width), int(samples), segs, tips)
    return (float(centre), float(half), float(d_in)) if found else None


def pocket_mouth_axes(table: Table) -> np.ndarray:
    """Unit vector per pocket (K, 2) pointing from the table's middle side of it into it: diagonal for a corner
    pocket, perpendicular to the rail for a side pocket (the direction a ball enters it most squarely)."""
    centre = np.array([table.length / 2.0, table.width / 2.0])
    axis = np.zeros((table.n_pockets, 2))
    for k, (px, py) in enumerate(table.pocket_xy):
        ax = np.sign(px - centre[0]) if abs(px - centre[0]) > 1e-9 else 0.0
        ay = np.sign(py - centre[1]) if abs(py - centre[1]) > 1e-9 else 0.0
        v = np.array([ax, ay], dtype=float)
        axis[k] = v / max(np.hypot(*v), 1e-12)
    return axis


def pocket_bearings(point: Vec2, table: Table,
                    mouth_axes: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Seen from ``point``, every pocket's direction (rad), distance to its centre, and squareness: the cosine
    between that direction and the pocket's mouth axis (1: straight in). ``mouth_axes``: from
    :func:`pocket_mouth_axes` (computed if None)."""
    axes = pocket_mouth_axes(table) if mouth_axes is None else mouth_axes
    w = table.pocket_xy - np.asarray(point, dtype=float)
    dist = np.hypot(w[:, 0], w[:, 1])
    square = (w[:, 0] * axes[:, 0] + w[:, 1] * axes[:, 1]) / np.maximum(dist, 1e-12)
    return np.arctan2(w[:, 1], w[:, 0]), dist, square


# --- clear paths -----------------------------------------------------------------------------------------------

@njit(cache=True)
def segment_distance(px: float, py: float, ax: float, ay: float, abx: float, aby: float, l2: float) -> float:
    """Distance from the point ``(px, py)`` to the segment from ``(ax, ay)`` along ``(abx, aby)`` (``l2``: that
    vector's squared length, 0 for a point)."""
    if l2 == 0.0:
        return math.hypot(px - ax, py - ay)
    t = min(max(dot2(px - ax, py - ay, abx, aby) / l2, 0.0), 1.0)
    return math.hypot(px - (ax + t * abx), py - (ay + t * aby))


@leaf_public
def segment_blocked_by(ax: float, ay: float, bx: float, by: float, pos: np.ndarray, on: np.ndarray,
                       radius: np.ndarray, skip1: int, skip2: int, r_moving: float) -> bool:
    """Whether a ball of ``radius`` ``r_moving`` rolling from ``a`` to ``b`` touches a ball of the table
    (``pos`` (B, 2), ``on`` (B,), ``radius`` (B,)) other than rows ``skip1`` and ``skip2``: a centre closer than
    the two radii summed (less 1e-9 m) to the segment."""
    abx = bx - ax
    aby = by - ay
    l2 = dot2(abx, aby, abx, aby)
    for k in range(pos.shape[0]):
        if on[k] and k != skip1 and k != skip2:
            if segment_distance(pos[k, 0], pos[k, 1], ax, ay, abx, aby, l2) < (radius[k] + r_moving) - 1e-9:
                return True
    return False


@njit(cache=True)
def segment_touched_by(ax: float, ay: float, bx: float, by: float, pos: np.ndarray, on: np.ndarray,
                       radius: np.ndarray, skip1: int, skip2: int, r_moving: float) -> bool:
    """:func:`segment_blocked_by` measured on squared distances and without slack: a ball whose centre is
    exactly at (or, by round-off, a hair inside) the two radii from the segment blocks it. Balls at rest after a
    shot often touch exactly; this is the test the search player's position term has always used, kept so that
    its choices do not change at such ties."""
    abx = bx - ax
    aby = by - ay
    l2 = max(abx * abx + aby * aby, 1e-24)
    for k in range(pos.shape[0]):
        if on[k] and k != skip1 and k != skip2:
            qx = pos[k, 0] - ax
            qy = pos[k, 1] - ay
            t = min(max((qx * abx + qy * aby) / l2, 0.0), 1.0)
            dx = pos[k, 0] - (ax + t * abx)
            dy = pos[k, 1] - (ay + t * aby)
            c = r_moving + radius[k]
            if dx * dx + dy * dy < c * c:
                return True
    return False


@njit(cache=True)
def _segment_blocked(ax: float, ay: float, bx: float, by: float, others: np.ndarray, clearance: np.ndarray) -> bool:
    abx = bx - ax
    aby = by - ay
    l2 = dot2(abx, aby, abx, aby)
    for k in range(others.shape[0]):
        if segment_distance(others[k, 0], others[k, 1], ax, ay, abx, aby, l2) < clearance[k] - 1e-9:
            return True
    return False


def segment_blocked(a: Vec2, b: Vec2, others: np.ndarray, clearance: np.ndarray) -> bool:
    """Whether any centre of ``others`` (M, 2) comes closer than its ``clearance`` (M,) to the segment ``a -> b``
    (for a ball rolling from ``a`` to ``b``: clearance = the two radii summed)."""
    others = np.asarray(others, dtype=float).reshape(-1, 2)
    clearance = np.broadcast_to(np.asarray(clearance, dtype=float), (len(others),))
    return bool(_segment_blocked(float(a[0]), float(a[1]), float(b[0]), float(b[1]), others, clearance))


def path_clear(a: Vec2, b: Vec2, others: np.ndarray, clearance: np.ndarray) -> bool:
    """Not :func:`segment_blocked`: no ball of ``others`` in the way from ``a`` to ``b``."""
    return not segment_blocked(a, b, others, clearance)


# --- collisions (the engine's law, :mod:`.collide`) --------------------------------------------------------------

@leaf_public
def collide_into(vel: np.ndarray, v1x: float, v1y: float, v2x: float, v2y: float, nx: float, ny: float, m1: float,
                 m2: float, e: float) -> None:
    """Velocities after balls 1, 2 collide along the unit normal ``n`` (from 2 to 1), by the solvers' own law,
    written into the caller's ``(2, 2)`` array ``vel`` (rows: ball 1, ball 2)."""
    vel[0, 0] = v1x
    vel[0, 1] = v1y
    vel[1, 0] = v2x
    vel[1, 1] = v2y
    resolve_ball_ball(vel, plain(0), plain(1), nx, ny, 1.0, m1, m2, e, 0.0, 0.0, plain(False))


@njit(cache=True)
def _collide(v1x, v1y, v2x, v2y, nx, ny, m1, m2, e):
    """Velocities after balls 1, 2 collide along the unit normal ``n`` (from 2 to 1), by the solvers' own law."""
    vel = np.empty((2, 2))
    collide_into(vel, v1x, v1y, v2x, v2y, nx, ny, m1, m2, e)
    return vel[0, 0], vel[0, 1], vel[1, 0], vel[1, 1]


def collision_velocities(v_cue: Vec2, v_obj: Vec2, line_of_centres: Vec2, e: float, m_cue: float,
                         m_obj: float) -> tuple[np.ndarray, np.ndarray]:
    """Velocities of two balls right after they collide: ``line_of_centres`` is the unit vector from the first
    ball's centre to the second's at contact, ``e`` the ball-ball restitution. The solvers' collision law (an
    impulse along the line of centres; nothing happens if the balls are not closing)."""
    v1x, v1y, v2x, v2y = _collide(float(v_cue[0]), float(v_cue[1]), float(v_obj[0]), float(v_obj[1]),
                                  -float(line_of_centres[0]), -float(line_of_centres[1]), m_cue, m_obj, e)
    return np.array([v1x, v1y]), np.array([v2x, v2y])


def deflected_cue_velocity(velocity: Vec2, line_of_centres: Vec2, e: float, m_cue: float,
                           m_obj: float) -> np.ndarray:
    """The cue ball's velocity right after it hits a resting ball with ``velocity``, ``line_of_centres`` being
    the unit vector from its centre to the object ball's (at ``e = 1`` and equal masses it leaves at 90 degrees
    to the object ball's path)."""
    return collision_velocities(velocity, (0.0, 0.0), line_of_centres, e, m_cue, m_obj)[0]


def object_ball_speed(impact_speed: float, cut_cos: float, e: float, m_cue: float, m_obj: float) -> float:
    """Speed a resting object ball leaves with when the cue ball hits it at ``impact_speed`` with a cut whose
    cosine is ``cut_cos`` (proportional to ``impact_speed``: divide by it to invert a shot)."""
    return _collide(impact_speed * cut_cos, 0.0, 0.0, 0.0, -1.0, 0.0, m_cue, m_obj, e)[2]


# --- a lone ball's path ----------------------------------------------------------------------------------------

@njit(cache=True)
def lone_path_pocket(x, y, vx, vy, radius, length, width, e_cushion, pocket_xy, pocket_r, law, a, k, v_min,
                     max_bounces, segs, tips):
    """:func:`path_pocket` on plain values (compiled): the pocket index, or -1. ``segs``, ``tips``: a jaw table's
    walls (empty on a capture table). Callers that keep the walls' groups pass them to
    :func:`lone_path_pocket_grouped` (the same pocket, fewer ray tests)."""
    if segs.shape[0] == 0 and tips.shape[0] == 0:
        return _lone_path_capture(x, y, vx, vy, radius, length, width, e_cushion, pocket_xy, pocket_r, law, a, k,
                                  v_min, max_bounces)
    return lone_path_pocket_grouped(x, y, vx, vy, radius, length, width, e_cushion, pocket_xy, pocket_r, law, a, k,
                                    v_min, max_bounces, segs, tips, np.zeros((0, 3)))


@leaf_public
def lone_path_pocket_grouped(x, y, vx, vy, radius, length, width, e_cushion, pocket_xy, pocket_r, law, a, k, v_min,
                             max_bounces, segs, tips, groups):
    """:func:`lone_path_pocket` with a jaw table's wall groups (``groups``: :func:`.kernel_io.wall_groups`, or
    (0, 3) for none): the first wall ahead by :func:`walls_ahead`. On a capture table its own loop, which carries
    no walls."""
    if segs.shape[0] == 0 and tips.shape[0] == 0:
        return _lone_path_capture(x, y, vx, vy, radius, length, width, e_cushion, pocket_xy, pocket_r, law, a, k,
                                  v_min, max_bounces)
    for _ in range(max_bounces + 1):
        s = math.hypot(vx, vy)
        if s < 1e-6:
            return -1
        ux = vx / s
        uy = vy / s
        reach = stop_distance(s, law, a, k, v_min)
        t_wall, wall = walls_ahead(x, y, ux, uy, radius, segs, tips, groups)
        pocket = first_pocket_on_ray(x, y, ux, uy, min(reach, t_wall + 1e-9), pocket_xy, pocket_r)[0]
        if pocket >= 0:
            return pocket
        if reach <= t_wall:
            return -1
        # Roll to the wall, then reflect.
        x = x + ux * t_wall
        y = y + uy * t_wall
        s_wall = speed_after_distance(s, t_wall, law, a, k)
        vx, vy = bounce_off(ux * s_wall, uy * s_wall, x, y, wall, length, width, radius, e_cushion, segs, tips)
    return -1


@leaf_public
def _lone_path_capture(x, y, vx, vy, radius, length, width, e_cushion, pocket_xy, pocket_r, law, a, k, v_min,
                       max_bounces):
    """:func:`lone_path_pocket` on a capture table: the four cushion lines (:func:`ray_cushion_hit`), each bounce
    reversing the velocity's part across the cushion met (:func:`bounce_off`'s capture law)."""
    for _ in range(max_bounces + 1):
        s = math.hypot(vx, vy)
        if s < 1e-6:
            return -1
        ux = vx / s
        uy = vy / s
        reach = stop_distance(s, law, a, k, v_min)
        t_wall = ray_cushion_hit(x, y, ux, uy, length, width, radius)[0]
        pocket = first_pocket_on_ray(x, y, ux, uy, min(reach, t_wall + 1e-9), pocket_xy, pocket_r)[0]
        if pocket >= 0:
            return pocket
        if reach <= t_wall:
            return -1
        # Roll to the cushion, then reflect.
        x = x + ux * t_wall
        y = y + uy * t_wall
        s_wall = speed_after_distance(s, t_wall, law, a, k)
        vx = ux * s_wall
        vy = uy * s_wall
        if x <= radius + 1e-9 or x >= length - radius - 1e-9:
            vx = -e_cushion * vx
        if y <= radius + 1e-9 or y >= width - radius - 1e-9:
            vy = -e_cushion * vy
    return -1


@leaf_public
def walls_ahead(px: float, py: float, ux: float, uy: float, r: float, segs: np.ndarray, tips: np.ndarray,
                groups: np.ndarray) -> tuple:
    """The first wall of a jaw table a ball of radius ``r`` rolling along the ray meets: :func:`.walls.ray_walls_hit`'s
    ``(distance, wall index)``, the same answer, with a pocket's jaw faces and tips passed over when the ray does not
    reach their group's circle (``groups``: :func:`.kernel_io.wall_groups`, widened by ``r``) nearer than the best
    hit so far (as the exact solvers' :func:`.walls.ray_wall_hit`). The rails, faces and tips are visited in their
    index order, so a tie goes to the lower index as there. Without groups: :func:`.walls.ray_walls_hit`."""
    if groups.shape[0] == 0:
        return ray_walls_hit(px, py, ux, uy, r, segs, tips)
    n_s = segs.shape[0]
    n_rails = n_s - tips.shape[0]
    best = math.inf
    wall = -1
    for q in range(n_rails):
        d = ray_line_hit(px, py, ux, uy, r, segs[q])
        if d < best and on_seg(px + d * ux, py + d * uy, segs[q]):
            best = d
            wall = q
    pad = r * (1.0 + 1e-9) + 1e-9
    for g in range(groups.shape[0]):
        if not ray_circle_below(px, py, ux, uy, groups[g, 0], groups[g, 1], groups[g, 2] + pad, best) < best:
            continue
        for q in range(n_rails + 2 * g, n_rails + 2 * g + 2):
            d = ray_line_hit(px, py, ux, uy, r, segs[q])
            if d < best and on_seg(px + d * ux, py + d * uy, segs[q]):
                best = d
                wall = q
    for g in range(groups.shape[0]):
        if not ray_circle_below(px, py, ux, uy, groups[g, 0], groups[g, 1], groups[g, 2] + pad, best) < best:
            continue
        for q in range(2 * g, 2 * g + 2):
            d = ray_tip_below(px, py, ux, uy, r, tips[q], best)
            if d < best:
                best = d
                wall = n_s + q
    return best, wall


def path_pocket(start: Vec2, velocity: Vec2, radius: float, table: Table, physics: Physics,
                max_bounces: int = 4) -> int:
    """The pocket a lone ball launched from ``start`` with ``velocity`` rolls into (-1: none) on straight lines,
    reflecting off up to ``max_bounces`` cushions with the table's restitution, slowing by the friction law, and
    stopping where the law stops it (no other balls)."""
    return int(lone_path_pocket(float(start[0]), float(start[1]), float(velocity[0]), float(velocity[1]),
                            float(radius), float(table.length), float(table.width),
                            float(table.cushion_restitution), table.pocket_xy, table.pocket_radius,
                            *physics.path_args, physics.min_speed, int(max_bounces), *table.walls()))


def path_enters_pocket(start: Vec2, velocity: Vec2, radius: float, table: Table, physics: Physics,
                       max_bounces: int = 4) -> bool:
    """Whether a lone ball launched from ``start`` with ``velocity`` rolls into a pocket (see
    :func:`path_pocket`)."""
    return path_pocket(start, velocity, radius, table, physics, max_bounces) >= 0


__all__ = [
    "WINDOW_SAMPLES", "window_of", "pocket_windows", "dot2", "cos_between", "segment_distance",
    "segment_blocked_by", "segment_touched_by", "collide_into", "lone_path_pocket", "lone_path_pocket_grouped",
    "walls_ahead", "ray_circle_entry",
    "ray_cushion_hit", "cushion_ahead", "bounce_off", "ray_cushion_distance", "ray_circle_entries", "ray_cushion_distances", "aim_angle",
    "direction_vector", "wrap_angle", "angular_radius", "ghost_ball_position", "cut_cosine", "cut_angle",
    "offset_aim_angle", "aim_offset", "pocket_window", "pocket_mouth_axes", "pocket_bearings", "segment_blocked",
    "path_clear", "collision_velocities", "deflected_cue_velocity", "object_ball_speed", "path_pocket",
    "path_enters_pocket",
]
