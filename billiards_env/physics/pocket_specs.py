"""Pockets as real tables build them: rails that stop at the mouths, straight jaw faces, rounded jaw tips, and a
pocket circle behind each mouth.

A pocket table is given by the same parameters as pooltool's ``PocketTableSpecs`` (SI units, angles in degrees),
so that a pooltool table can be copied field by field; ``l`` runs along ``x`` here (pooltool's ``l`` runs along its
``y``). :func:`build_walls` turns them into the cushion geometry the solvers read:

- **segments** (one-sided lines at cushion height): 6 rails, then 2 jaw faces per pocket in pocket order. A ball
  meets a segment when its centre is ``R`` from the segment's line on the open side (the side its normal points
  to) *and* the centre's projection lies on the segment.
- **tips** (vertical cylinders): 2 per pocket, in pocket order, where a rail turns into a jaw face. A ball meets a
  tip when its centre is ``R + radius`` from the tip's centre.
- **pocket circles**: a moving ball is pocketed when its centre enters one (pooltool's criterion).

Wall indices (the ``other`` of a cushion event on a jaw table): rails 0-5 (bottom left of the middle pocket,
bottom right, top left, top right, the left end ``x = 0``, the right end ``x = l``), jaw faces 6-17 and tips
18-29, two each per pocket in the pocket order bottom-left, bottom-middle, bottom-right, top-left, top-middle,
top-right. The construction is pooltool's ``create_pocket_table_cushion_segments`` and
``create_pocket_table_pockets`` (``objects/table/layout.py``), mapped to this frame: the same points.
"""
from __future__ import annotations

import difflib
import math
from dataclasses import asdict, dataclass, fields
from typing import Any, Mapping

import numpy as np

from .errors import SceneError, check_finite, check_non_negative, check_positive

#: Number of rails, jaw faces and tips of a six-pocket table (the wall index ranges above).
N_RAILS = 6
N_JAWS = 12
N_TIPS = 12
N_SEGMENTS = N_RAILS + N_JAWS
N_WALLS = N_SEGMENTS + N_TIPS
#: Pocket names in the pocket order, and each wall's name (a cushion event's ``other`` on a jaw table).
POCKET_NAMES = ("bottom-left", "bottom-middle", "bottom-right", "top-left", "top-middle", "top-right")
WALL_NAMES = (("rail bottom-left", "rail bottom-right", "rail top-left", "rail top-right", "rail left", "rail right")
              + tuple(f"jaw {p} {side}" for p in POCKET_NAMES for side in ("a", "b"))
              + tuple(f"tip {p} {side}" for p in POCKET_NAMES for side in ("a", "b")))
#: Columns of a segment row: its end points, then its unit normal towards the open side.
SEG_COLS = 6
#: Columns of a tip row: centre and radius.
TIP_COLS = 3
#: Pocket angles (degrees) are accepted in this open interval: at -45 the jaw face is square to its rail, at +45
#: it would lie along the rail.
ANGLE_LIMIT = 45.0


@dataclass(frozen=True)
class PocketSpecs:
    """A six-pocket table's geometry in pooltool's parameters (m; angles in degrees). Defaults: pooltool's 7-ft
    table (``pt.Table.default()``, ``PocketTableSpecs``).

    ``l`` x ``w``: the playing area between the cushion lines; ``cushion_width``: how deep the jaw faces reach
    into the cushion; ``cushion_height``: the nose height (kept for pooltool's tables; the cushion laws read
    ``physics.cushion_height``, which the ``pooltool`` physics preset sets to this table's 0.64 * 2R); ``*_pocket_width``: the mouth, jaw point to jaw point (corner: across
    the 45-degree line); ``*_pocket_angle``: how far the jaw faces turn from the pocket's axis (corner) or from the
    rail's normal (side), narrowing the throat when positive; ``*_pocket_depth``: how far behind the cushion line
    the pocket circle's centre lies (corner: along the diagonal); ``*_pocket_radius``: the pocket circle;
    ``*_jaw_radius``: the rounding of the jaw tip where the rail meets the jaw face.
    """

    l: float = 1.9812  # noqa: E741  (pooltool's name)
    w: float = 1.9812 / 2
    cushion_width: float = 2 * 2.54 / 100
    cushion_height: float = 0.64 * 2 * 0.028575
    corner_pocket_width: float = 0.118
    corner_pocket_angle: float = 5.3
    corner_pocket_depth: float = 0.0417
    corner_pocket_radius: float = 0.062
    corner_jaw_radius: float = 0.02095
    side_pocket_width: float = 0.137
    side_pocket_angle: float = 7.14
    side_pocket_depth: float = 0.0685
    side_pocket_radius: float = 0.0645
    side_jaw_radius: float = 0.00795

    def __post_init__(self) -> None:
        for name in ("l", "w", "cushion_width", "cushion_height", "corner_pocket_width", "corner_pocket_radius",
                     "side_pocket_width", "side_pocket_radius"):
            check_positive(f"table.specs.{name}", getattr(self, name))
        for name in ("corner_pocket_depth", "side_pocket_depth", "corner_jaw_radius", "side_jaw_radius"):
            check_non_negative(f"table.specs.{name}", getattr(self, name))
        for name in ("corner_pocket_angle", "side_pocket_angle"):
            a = check_finite(f"table.specs.{name}", getattr(self, name))
            if not -ANGLE_LIMIT < a < ANGLE_LIMIT:
                raise SceneError(f"table.specs.{name}: {a} degrees is outside (-{ANGLE_LIMIT:g}, {ANGLE_LIMIT:g}); "
                                 "0 is a jaw along the pocket's axis, positive angles narrow the throat")
        _check_fits(self)

    @classmethod
    def from_dict(cls, value: Any, where: str = "table.specs") -> "PocketSpecs":
        """Specs from a mapping of the fields above (every field optional; an unknown one is refused)."""
        if isinstance(value, PocketSpecs):
            return value
        if not isinstance(value, Mapping):
            raise SceneError(f"{where}: expected a mapping of pocket-table fields ({', '.join(SPEC_FIELDS)}), "
                             f"got {type(value).__name__}")
        unknown = [k for k in value if k not in SPEC_FIELDS]
        if unknown:
            k = unknown[0]
            near = difflib.get_close_matches(str(k), SPEC_FIELDS, n=1)
            hint = f"; did you mean {near[0]!r}?" if near else ""
            raise SceneError(f"{where}: unknown field {k!r}{hint} Valid fields: {', '.join(SPEC_FIELDS)}")
        kw = {}
        for k, v in value.items():
            kw[k] = check_finite(f"{where}.{k}", v)
        return cls(**kw)

    def to_dict(self) -> dict[str, float]:
        return {k: float(v) for k, v in asdict(self).items()}

    def mouths(self) -> tuple[float, float]:
        """``(corner, side)`` mouth widths, jaw point to jaw point (m)."""
        return self.corner_pocket_width, self.side_pocket_width


SPEC_FIELDS = tuple(f.name for f in fields(PocketSpecs))


def _corner_setback(s: PocketSpecs) -> tuple[float, float]:
    """``(ca, dc)``: the corner jaw's angle from the rail's normal (rad) and the distance from the jaw point (where
    rail and jaw face lines meet) to the tangent points of the tip's rounding."""
    ca = math.radians(s.corner_pocket_angle + 45.0)
    return ca, s.corner_jaw_radius / math.tan((math.pi / 2 + ca) / 2)


def _side_setback(s: PocketSpecs) -> tuple[float, float]:
    sa = math.radians(s.side_pocket_angle)
    return sa, s.side_jaw_radius / math.tan((math.pi / 2 + sa) / 2)


def _check_fits(s: PocketSpecs) -> None:
    """Refuse specs that make no table: rails of no length, jaw roundings larger than their mouth, a pocket circle
    that a ball coming through the mouth cannot reach."""
    ca, dc = _corner_setback(s)
    sa, ds = _side_setback(s)
    corner_end = s.corner_pocket_width / math.sqrt(2.0) + dc  # where a rail leaves a corner's jaw tip
    long_half = (s.l - s.side_pocket_width) / 2.0 - ds
    if not corner_end < long_half:
        raise SceneError(
            f"table.specs: the long rails have no length: a corner mouth of {s.corner_pocket_width} m and a side "
            f"mouth of {s.side_pocket_width} m with their jaw roundings take up more than half of l = {s.l} m; "
            "make the pockets narrower, the jaw radii smaller or the table longer")
    if not 2.0 * corner_end < s.w:
        raise SceneError(
            f"table.specs: the end rails have no length: two corner mouths of {s.corner_pocket_width} m with their "
            f"jaw roundings take up more than w = {s.w} m; make the pockets narrower or the table wider")
    # A jaw's rounding must fit its mouth: it runs from the jaw point along the rail and along the jaw face for no
    # more than the mouth is wide (pooltool's snooker pockets, the roundest here, use 80 % of theirs).
    for kind, setback, width, radius in (("corner", dc, s.corner_pocket_width, s.corner_jaw_radius),
                                         ("side", ds, s.side_pocket_width, s.side_jaw_radius)):
        if not setback <= width:
            raise SceneError(
                f"table.specs.{kind}_jaw_radius: {radius} m does not fit a {kind} mouth of {width} m: its rounding "
                f"runs {setback:.4f} m along the rail, more than the mouth is wide; the largest that fits is "
                f"{radius * width / setback:.4f} m")
    # Reachable: the pocket circle covers the throat's axis where the jaw faces end (cushion_width behind the
    # cushion line), so a ball running down the axis enters it before it leaves the jaws.
    corner_gap = math.sqrt(2.0) * abs(s.cushion_width - s.corner_pocket_depth / math.sqrt(2.0))
    if not corner_gap < s.corner_pocket_radius:
        raise SceneError(
            f"table.specs.corner_pocket_radius: a circle of {s.corner_pocket_radius} m at depth "
            f"{s.corner_pocket_depth} m cannot be reached: it misses the throat's axis where the jaws end "
            f"({corner_gap:.4f} m away); use a radius above {corner_gap:.4f} m or move it closer")
    side_gap = abs(s.cushion_width - s.side_pocket_depth)
    if not side_gap < s.side_pocket_radius:
        raise SceneError(
            f"table.specs.side_pocket_radius: a circle of {s.side_pocket_radius} m at depth "
            f"{s.side_pocket_depth} m cannot be reached: it misses the throat's axis where the jaws end "
            f"({side_gap:.4f} m away); use a radius above {side_gap:.4f} m or move it closer")


def pocket_circles(s: PocketSpecs) -> tuple[np.ndarray, np.ndarray]:
    """The six pocket circles ``(centres (6, 2), radii (6,))`` in the pocket order."""
    c = s.corner_pocket_depth / math.sqrt(2.0)
    d = s.side_pocket_depth
    xy = np.array([[-c, -c], [s.l / 2, -d], [s.l + c, -c], [-c, s.w + c], [s.l / 2, s.w + d], [s.l + c, s.w + c]])
    r = np.array([s.corner_pocket_radius, s.side_pocket_radius, s.corner_pocket_radius] * 2)
    return xy, r


def _segment(ax: float, ay: float, bx: float, by: float, towards: tuple[float, float]) -> list[float]:
    """A segment row ``[ax, ay, bx, by, nx, ny]``, its unit normal pointing to the side of ``towards``."""
    dx, dy = bx - ax, by - ay
    n = math.hypot(dx, dy)
    nx, ny = -dy / n, dx / n
    if (towards[0] - ax) * nx + (towards[1] - ay) * ny < 0.0:
        nx, ny = -nx, -ny
    return [ax, ay, bx, by, nx, ny]


def build_walls(s: PocketSpecs) -> tuple[np.ndarray, np.ndarray]:
    """The cushion geometry of ``s``: ``segments (18, 6)`` and ``tips (12, 3)`` in the documented order."""
    L, W, cw = s.l, s.w, s.cushion_width
    ca, dc = _corner_setback(s)
    sa, ds = _side_setback(s)
    pc = s.corner_pocket_width / math.sqrt(2.0)
    sw = s.side_pocket_width
    rc, rs = s.corner_jaw_radius, s.side_jaw_radius
    centre = (L / 2, W / 2)
    segs = [
        _segment(pc + dc, 0.0, (L - sw) / 2 - ds, 0.0, centre),
        _segment((L + sw) / 2 + ds, 0.0, L - pc - dc, 0.0, centre),
        _segment(pc + dc, W, (L - sw) / 2 - ds, W, centre),
        _segment((L + sw) / 2 + ds, W, L - pc - dc, W, centre),
        _segment(0.0, pc + dc, 0.0, W - pc - dc, centre),
        _segment(L, pc + dc, L, W - pc - dc, centre),
    ]
    tips = []
    # The bottom-left corner and the bottom-middle pocket in local coordinates; the others are mirror images.
    corner_jaws = [  # (deep end, tip end) of the jaw face on the bottom rail, then on the left rail
        ((pc - cw * math.tan(ca), -cw), (pc - dc * math.sin(ca), -dc * math.cos(ca))),
        ((-cw, pc - cw * math.tan(ca)), (-dc * math.cos(ca), pc - dc * math.sin(ca))),
    ]
    corner_tips = [(pc + dc, -rc), (-rc, pc + dc)]
    side_jaws = [
        (((L - sw) / 2 + cw * math.sin(sa), -cw), ((L - sw) / 2 + ds * math.sin(sa), -ds * math.cos(sa))),
        (((L + sw) / 2 - cw * math.sin(sa), -cw), ((L + sw) / 2 - ds * math.sin(sa), -ds * math.cos(sa))),
    ]
    side_tips = [(L / 2 - sw / 2 - ds, -rs), (L / 2 + sw / 2 + ds, -rs)]
    pockets_xy, _ = pocket_circles(s)
    mirrors = [(False, False), (None, False), (True, False), (False, True), (None, True), (True, True)]
    for p, (flip_x, flip_y) in enumerate(mirrors):
        jaws, tip_xy, rad = (side_jaws, side_tips, rs) if flip_x is None else (corner_jaws, corner_tips, rc)

        def m(x: float, y: float, fx: bool | None = flip_x, fy: bool = flip_y) -> tuple[float, float]:
            return (L - x if fx else x), (W - y if fy else y)

        towards = tuple(pockets_xy[p])
        for (a, b) in jaws:
            (ax, ay), (bx, by) = m(*a), m(*b)
            segs.append(_segment(ax, ay, bx, by, towards))
        for (x, y) in tip_xy:
            tips.append([*m(x, y), rad])
    return np.array(segs, dtype=float), np.array(tips, dtype=float)


#: pooltool's 7-ft table (its ``pt.Table.default()``).
POOLTOOL_7FT = PocketSpecs()
#: A WPA 9-ft table: 100 x 50 in between the cushion noses, mouths in the middle of the WPA ranges (corner
#: 4 1/2 - 4 5/8 in, side 5 - 5 1/8 in), jaw angles from the WPA's 142 degrees (corner) and 104 degrees (side)
#: between the cushion nose and the jaw face, nose height 63.5 % of the ball's diameter; depths, pocket circles and
#: jaw roundings as pooltool's 7-ft table (the WPA does not fix them).
WPA_9FT = PocketSpecs(l=2.54, w=1.27, cushion_height=0.635 * 2 * 0.028575, corner_pocket_width=0.1159,
                      corner_pocket_angle=7.0, side_pocket_width=0.1286, side_pocket_angle=14.0)
#: A snooker table with its rounded pockets: pooltool's generic snooker table (``SNOOKER_GENERIC``).
SNOOKER_12FT = PocketSpecs(l=3.569, w=1.778, cushion_width=47.63 / 1000, cushion_height=0.039,
                           corner_pocket_width=80.14 / 1000, corner_pocket_angle=0.0,
                           corner_pocket_depth=67.35 / 1000, corner_pocket_radius=88.9 / 1000,
                           corner_jaw_radius=88.90 / 1000, side_pocket_width=84.57 / 1000, side_pocket_angle=0.0,
                           side_pocket_depth=51.59 / 1000, side_pocket_radius=53.19 / 1000,
                           side_jaw_radius=66.90 / 1000)

__all__ = ["POCKET_NAMES", "WALL_NAMES", "PocketSpecs", "SPEC_FIELDS", "build_walls", "pocket_circles", "throat_leak",
           "wall_overlaps", "wall_gaps", "mouth_polygons", "in_mouth_region", "in_mouth", "clear_of_walls",
           "POOLTOOL_7FT", "WPA_9FT", "SNOOKER_12FT",
           "N_RAILS", "N_JAWS", "N_TIPS", "N_SEGMENTS", "N_WALLS"]


def wall_overlaps(segs: np.ndarray, tips: np.ndarray, x: Any, y: Any, r: Any) -> tuple[np.ndarray, np.ndarray]:
    """How deep balls of radius ``r`` centred at ``(x, y)`` (arrays of one shape) overlap the walls: ``(overlap,
    wall)``, the deepest overlap of each ball (m; <= 0: clear of every wall) and that wall's index (-1 if none is
    near). A segment counts while the centre projects onto it and lies at most ``r`` behind its line; a tip always.
    The vectorised Python form of the compiled :func:`.walls.wall_gap` (the invariant checks use it)."""
    x, y, r = np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float), np.asarray(r, float))
    best = np.full(x.shape, -np.inf)
    wall = np.full(x.shape, -1, dtype=np.int64)
    for k, (ax, ay, bx, by, nx, ny) in enumerate(segs):
        dx, dy = bx - ax, by - ay
        s = ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy)
        gap = (x - ax) * nx + (y - ay) * ny
        ov = np.where((s >= 0.0) & (s <= 1.0) & (gap > -r), r - gap, -np.inf)
        wall = np.where(ov > best, k, wall)
        best = np.maximum(best, ov)
    for k, (cx, cy, rad) in enumerate(tips):
        ov = r + rad - np.hypot(x - cx, y - cy)
        wall = np.where(ov > best, len(segs) + k, wall)
        best = np.maximum(best, ov)
    return best, wall


def throat_leak(s: PocketSpecs, r: float) -> str | None:
    """Why a ball of radius ``r`` could leave a pocket's throat past the ends of its jaw faces without its centre
    entering the pocket circle (the model has no wall behind the jaws: such a ball would run on off the table), or
    None if every pocket catches it. A centre leaving between the faces' deep ends lies at least ``r`` from each
    end along the line across them, so the circle must hold that line inset by ``r`` at both ends."""
    segs, tips = build_walls(s)
    xy, pr = pocket_circles(s)
    for p in range(len(pr)):
        a = segs[N_RAILS + 2 * p, 0:2]
        b = segs[N_RAILS + 2 * p + 1, 0:2]
        width = float(np.hypot(*(b - a)))
        if width <= 2.0 * r:
            continue  # no ball fits between the deep ends
        u = (b - a) / width
        far = max(float(np.hypot(*(a + r * u - xy[p]))), float(np.hypot(*(b - r * u - xy[p]))))
        if far > pr[p]:
            kind = "side" if p in (1, 4) else "corner"
            return (f"table.specs: a ball of radius {r} m can leave pocket {p}'s throat between its jaws' deep ends "
                    f"{far:.4f} m from the pocket circle's centre, outside its radius {pr[p]} m, and run off the "
                    f"table; make {kind}_pocket_radius at least {far:.4f} m, or the {kind} pocket narrower or its "
                    f"jaws longer (cushion_width)")
    return None


def wall_gaps(segs: np.ndarray, tips: np.ndarray, x: Any, y: Any, r: Any, wall: Any) -> np.ndarray:
    """How far balls of radius ``r`` at ``(x, y)`` are from touching wall ``wall`` (arrays of one shape; < 0:
    overlapping), measured along its normal (segment) or from its centre (tip): the Python form of
    :func:`.walls.wall_gap` without its projection test."""
    x, y, r, wall = np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float), np.asarray(r, float),
                                        np.asarray(wall, np.int64))
    out = np.full(x.shape, np.nan)
    seg = wall < len(segs)
    if seg.any():
        row = segs[wall[seg]]
        out[seg] = (x[seg] - row[:, 0]) * row[:, 4] + (y[seg] - row[:, 1]) * row[:, 5] - r[seg]
    tip = ~seg
    if tip.any():
        row = tips[wall[tip] - len(segs)]
        out[tip] = np.hypot(x[tip] - row[:, 0], y[tip] - row[:, 1]) - r[tip] - row[:, 2]
    return out


def clear_of_walls(segs: np.ndarray, tips: np.ndarray, x: float, y: float, r: float, tol: float = 0.0) -> bool:
    """Whether a ball of radius ``r`` at ``(x, y)`` overlaps no rail, jaw face or tip by more than ``tol``."""
    return bool(wall_overlaps(segs, tips, x, y, r)[0] <= tol)


def mouth_polygons(segs: np.ndarray, tips: np.ndarray) -> list[np.ndarray]:
    """Each pocket's mouth and throat as a convex polygon: the convex hull of its jaw faces' ends and the points
    where the rails stop (the rail ends nearest the pocket's tips). On most tables that is the polygon from one jaw
    face's deep end along it, across to the rail stops and back along the other face; where a jaw's rounding
    reaches deeper than its face's deep end (pooltool's snooker table), the hull still holds the whole mouth."""
    rail_ends = np.concatenate([segs[:N_RAILS, 0:2], segs[:N_RAILS, 2:4]])
    out = []
    for p in range(len(tips) // 2):
        stops = [rail_ends[np.argmin(np.hypot(*(rail_ends - tips[2 * p + k, 0:2]).T))] for k in range(2)]
        pts = np.array([segs[N_RAILS + 2 * p, 0:2], segs[N_RAILS + 2 * p, 2:4], stops[0], stops[1],
                        segs[N_RAILS + 2 * p + 1, 2:4], segs[N_RAILS + 2 * p + 1, 0:2]])
        out.append(_hull(pts))
    return out


def _hull(pts: np.ndarray) -> np.ndarray:
    """The convex hull of ``pts`` (counter-clockwise; Andrew's monotone chain)."""
    order = sorted(map(tuple, pts.tolist()))

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    lower: list = []
    for q in order:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], q) <= 0.0:
            lower.pop()
        lower.append(q)
    upper: list = []
    for q in reversed(order):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], q) <= 0.0:
            upper.pop()
        upper.append(q)
    return np.array(lower[:-1] + upper[:-1])


def in_mouth_region(segs: np.ndarray, tips: np.ndarray, pocket_xy: np.ndarray, pocket_r: np.ndarray, x: float,
                    y: float) -> bool:
    """Whether the point ``(x, y)`` lies in a pocket's mouth and throat (:func:`mouth_polygons`) or in a pocket
    circle (the Python form of the compiled :func:`.walls.in_mouth_region`)."""
    for p in range(len(pocket_r)):
        if math.hypot(x - pocket_xy[p, 0], y - pocket_xy[p, 1]) <= pocket_r[p]:
            return True
    return any(_in_convex(poly, x, y) for poly in mouth_polygons(segs, tips))


def in_mouth(segs: np.ndarray, tips: np.ndarray, pocket_xy: np.ndarray, pocket_r: np.ndarray, x: float, y: float,
             r: float, tol: float = 0.0) -> bool:
    """Whether a ball centre at ``(x, y)`` outside the playing area ``[r, l - r] x [r, w - r]`` still lies on a
    jaw table: within the cushion lines ``[0, l] x [0, w]`` (a mouth's entrance, where a rail has stopped; the
    rails lie on those lines: rail 5 at ``x = l``, rail 2 at ``y = w``), within a pocket's mouth and throat
    (:func:`mouth_polygons`) or in its pocket circle, and clear of every wall."""
    length, width = segs[5, 0], segs[2, 1]
    if (0.0 <= x <= length and 0.0 <= y <= width) or in_mouth_region(segs, tips, pocket_xy, pocket_r, x, y):
        return clear_of_walls(segs, tips, x, y, r, tol)
    return False


def _in_convex(poly: np.ndarray, x: float, y: float) -> bool:
    """Whether ``(x, y)`` lies in the convex polygon ``poly`` (vertices in order, either orientation)."""
    sign = 0.0
    for k in range(len(poly)):
        ax, ay = poly[k]
        bx, by = poly[(k + 1) % len(poly)]
        c = (bx - ax) * (y - ay) - (by - ay) * (x - ax)
        if c != 0.0:
            if sign == 0.0:
                sign = c
            elif (c > 0.0) != (sign > 0.0):
                return False
    return True
