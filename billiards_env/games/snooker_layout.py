"""Snooker's table markings and opening layout (WPBSA): the baulk line, the D, the colours' spots, the reds'
triangle, the re-spotting of colours and the cue ball in hand in the D.

The snooker game owns these (its session racks, respots and places by them; its players and referee read them);
the physics keeps the generic geometry they stand on (:mod:`billiards_env.physics.layout`: a triangle rack, a
half-disc area). The balls' ids are the rules' (:data:`~billiards_env.rules.snooker.SNOOKER_IDS`).
"""
from __future__ import annotations

import numpy as np

from billiards_env.physics.balls import Balls
from billiards_env.physics.errors import SceneError
from billiards_env.physics.layout import (half_disc_point, in_half_disc, nearest_point_in_half_disc,
                                          triangle_positions)
from billiards_env.physics.table import (SNOOKER_BALL_MASS, SNOOKER_BALL_RADIUS, SNOOKER_LENGTH, SNOOKER_WIDTH,
                                         Table)
from billiards_env.rules.snooker import SNOOKER_COLOURS, SNOOKER_IDS, SNOOKER_REDS
from billiards_env.table_state import HalfDiscArea

# WPBSA markings, measured on the 3569 x 1778 mm table from the baulk cushion (``x = 0``) and scaled with the table's
# length (along x) and width (across) on any other table. Viewed from the baulk end (looking along +x), the yellow
# spot is on the right (``y < width/2``) and the green on the left.

#: The baulk line: 737 mm (29 in) from the face of the baulk cushion.
SNOOKER_BAULK_LINE = 0.737
#: The radius of the D (a half-disc on the baulk side of the baulk line, centred on its middle): 292 mm (11 1/2 in).
SNOOKER_D_RADIUS = 0.292
#: The black spot: 324 mm (12 3/4 in) from the face of the top cushion.
SNOOKER_BLACK_FROM_TOP = 0.324
#: Gap (m) between the pink and the apex red: "as near as possible without touching".
SNOOKER_PINK_GAP = 0.002


def _snooker_scale(table: Table) -> tuple[float, float]:
    return table.length / SNOOKER_LENGTH, table.width / SNOOKER_WIDTH


def baulk_line_x(table: Table) -> float:
    """x of the baulk line (737 mm from the baulk cushion on the standard table)."""
    return SNOOKER_BAULK_LINE * _snooker_scale(table)[0]


def d_geometry(table: Table) -> tuple[float, float, float]:
    """The D as ``(cx, cy, r)``: the half-disc of radius ``r`` centred on the middle of the baulk line
    ``(cx, cy)``, on its baulk side (``x <= cx``)."""
    return baulk_line_x(table), 0.5 * table.width, SNOOKER_D_RADIUS * _snooker_scale(table)[1]


def snooker_spots(table: Table) -> dict[str, tuple[float, float]]:
    """The colours' spots by colour id: yellow and green at the ends of the D, brown in the middle of the baulk
    line, blue in the centre of the table, pink midway between the blue spot and the top cushion, black 324 mm
    from the top cushion."""
    cx, cy, r = d_geometry(table)
    sx = _snooker_scale(table)[0]
    return {"yellow": (cx, cy - r), "green": (cx, cy + r), "brown": (cx, cy),
            "blue": (0.5 * table.length, cy), "pink": (0.75 * table.length, cy),
            "black": (table.length - SNOOKER_BLACK_FROM_TOP * sx, cy)}


def in_d(x: float, y: float, table: Table, tol: float = 1e-9) -> bool:
    """Whether ``(x, y)`` is on or within the lines of the D."""
    return in_half_disc(x, y, *d_geometry(table), tol)


def d_point(u: float, v: float, table: Table) -> tuple[float, float]:
    """The point of the D for ``(u, v)`` in ``[-1, 1]^2`` (clipped): ``u`` across the table (``-1`` the yellow end
    of the D, ``+1`` the green), ``v`` from the arc (``-1``) to the baulk line (``+1``) along the line ``y``
    fixed. A continuous one-to-one map of the square onto the half-disc, for an action's placement dims."""
    return half_disc_point(u, v, *d_geometry(table))


def snooker_rack(table: Table, radius: float = SNOOKER_BALL_RADIUS) -> dict[str, tuple[float, float]]:
    """Where the object balls start: the colours on their spots and the 15 reds in a touching triangle whose apex
    red sits behind the pink spot (towards the top cushion) without touching the pink, its back row parallel to
    the top cushion. Ids :data:`SNOOKER_REDS` (row by row from the apex) and :data:`SNOOKER_COLOURS`."""
    spots = snooker_spots(table)
    px, py = spots["pink"]
    reds = triangle_positions((px + 2.0 * radius + SNOOKER_PINK_GAP, py), radius)
    out = {rid: (float(x), float(y)) for rid, (x, y) in zip(SNOOKER_REDS, reds)}
    out.update(spots)
    return out


def snooker_balls(table: Table, cue_xy: tuple[float, float] | None = None, radius: float = SNOOKER_BALL_RADIUS,
                  mass: float = SNOOKER_BALL_MASS) -> Balls:
    """A snooker frame's opening layout (:func:`snooker_rack`) with the cue ball at ``cue_xy`` (default: on the
    baulk line halfway between the brown and yellow spots, a point of the D). Ids :data:`SNOOKER_IDS`."""
    rack = snooker_rack(table, radius)
    if cue_xy is None:
        cx, cy, r = d_geometry(table)
        cue_xy = (cx, cy - 0.5 * r)
    pos = [tuple(cue_xy)] + [rack[i] for i in SNOOKER_IDS[1:]]
    return Balls.from_positions(pos, ids=SNOOKER_IDS, radius=radius, mass=mass)


def _spot_free(x: float, y: float, pos: np.ndarray, on_table: np.ndarray, rad: np.ndarray, row: int) -> bool:
    """No ball on the table (but ``row``) would touch a ball of row ``row`` placed at ``(x, y)``."""
    for k in range(len(pos)):
        if k != row and on_table[k]:
            need = rad[row] + rad[k] + 1e-6
            if (x - pos[k, 0]) ** 2 + (y - pos[k, 1]) ** 2 < need * need:
                return False
    return True


def spot_snooker_colours(pos: np.ndarray, on_table: np.ndarray, radius: np.ndarray | float, table: Table,
                         colours: dict[str, int]) -> None:
    """Re-spot snooker colours (``colours``: colour id -> ball row), as the WPBSA rules say: each on its own spot
    if that is free (a spot is taken when a ball placed there would touch another); the others, the highest value
    first, on the highest-value free spot; if every spot is taken, as near its own spot as possible between it and
    the top cushion (on the line parallel to the long cushions through the spot), and for the pink and black,
    when that is full too, as near as possible below their spot on the centre line. Sets ``pos`` and
    ``on_table`` of those rows."""
    unknown = sorted(set(colours) - set(SNOOKER_COLOURS))
    if unknown:
        raise SceneError(f"colours: {unknown} are not snooker colours; use {', '.join(SNOOKER_COLOURS)}")
    rad = np.broadcast_to(np.asarray(radius, dtype=float), (len(pos),))
    spots = snooker_spots(table)
    order = sorted(colours, key=SNOOKER_COLOURS.index, reverse=True)  # highest value first
    for name in order:  # rows being respotted are not on the table while the others are placed
        on_table[colours[name]] = False
    left = []
    for name in order:
        row = colours[name]
        x, y = spots[name]
        if _spot_free(x, y, pos, on_table, rad, row):
            pos[row] = (x, y)
            on_table[row] = True
        else:
            left.append(name)
    for name in left:
        row = colours[name]
        for spot in reversed(SNOOKER_COLOURS):
            x, y = spots[spot]
            if _spot_free(x, y, pos, on_table, rad, row):
                pos[row] = (x, y)
                on_table[row] = True
                break
        else:
            x0, y0 = spots[name]
            step = rad[row] / 8.0
            up = [x0 + k * step for k in range(1, int((table.length - rad[row] - x0) / step) + 1)]
            down = [x0 - k * step for k in range(1, int((x0 - rad[row]) / step) + 1)] \
                if name in ("pink", "black") else []
            for x in up + down:
                if _spot_free(x, y0, pos, on_table, rad, row):
                    pos[row] = (x, y0)
                    on_table[row] = True
                    break
            else:
                raise SceneError(f"could not re-spot the {name}: its line is full")  # pragma: no cover


def nearest_point_in_d(x: float, y: float, pos: np.ndarray, on_table: np.ndarray, radius: np.ndarray | float,
                       row: int, table: Table, clearance: float = 1e-6) -> tuple[float, float]:
    """The legal point for the cue ball in hand (row ``row``) nearest to ``(x, y)``: in the D (:func:`in_d`) and
    at least ``r_row + r_other + clearance`` from every other ball on the table
    (:func:`~billiards_env.physics.layout.nearest_point_in_half_disc` on the D). Raises :class:`SceneError` if the
    D is covered."""
    return nearest_point_in_half_disc(x, y, pos, on_table, radius, row, *d_geometry(table), clearance, "the D")


class DArea(HalfDiscArea):
    """The D as a ball-in-hand area (a :class:`~billiards_env.table_state.HalfDiscArea` by its bounding box): its
    nearest legal point is taken on the D's own geometry (:func:`d_geometry`), which the bounding box may round by
    an ulp."""

    __slots__ = ()

    @classmethod
    def of(cls, table: Table) -> "DArea":
        """The D of ``table``."""
        cx, cy, r = d_geometry(table)
        return cls(cx - r, cx, cy - r, cy + r)

    def nearest(self, x: float, y: float, balls: Balls, table: Table) -> tuple[float, float]:
        return nearest_point_in_d(x, y, balls.pos, balls.on_table, balls.radius, 0, table)


__all__ = ["SNOOKER_BAULK_LINE", "SNOOKER_D_RADIUS", "SNOOKER_BLACK_FROM_TOP", "SNOOKER_PINK_GAP", "SNOOKER_COLOURS",
           "SNOOKER_REDS", "SNOOKER_IDS", "baulk_line_x", "d_geometry", "snooker_spots", "in_d", "d_point",
           "snooker_rack", "snooker_balls", "spot_snooker_colours", "nearest_point_in_d", "DArea"]
