"""Table geometry: the playing area, its cushions and its pockets (SI units, origin at a corner)."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from .codes import CUSHION_NAMES  # noqa: F401  (re-exported: the cushion ids of event records)
from .errors import SceneError, check_finite, check_positive, check_unit_interval
from .pocket_specs import POOLTOOL_7FT, SNOOKER_12FT, WPA_9FT, PocketSpecs, build_walls, pocket_circles

#: Default 9-ft pool table playing area (metres).
DEFAULT_LENGTH = 2.54
DEFAULT_WIDTH = 1.27
DEFAULT_CUSHION_RESTITUTION = 0.85
CORNER_POCKET_RADIUS = 0.060
SIDE_POCKET_RADIUS = 0.052



def default_pockets(
    length: float,
    width: float,
    corner_radius: float = CORNER_POCKET_RADIUS,
    side_radius: float = SIDE_POCKET_RADIUS,
) -> tuple[np.ndarray, np.ndarray]:
    """The six standard pockets: four corners and the two middles of the long sides.

    Returns ``(centres (6,2), radii (6,))`` in the fixed order
    bottom-left, bottom-side, bottom-right, top-left, top-side, top-right.
    """
    centres = np.array(
        [
            [0.0, 0.0],
            [length / 2.0, 0.0],
            [length, 0.0],
            [0.0, width],
            [length / 2.0, width],
            [length, width],
        ]
    )
    radii = np.array([corner_radius, side_radius, corner_radius] * 2, dtype=float)
    return centres, radii


#: The pocket models (``table.pockets`` in scene files): ``capture`` four full-length cushions and capture circles
#: on the corners and the middles of the long sides; ``jaws`` rails that stop at the mouths, jaw faces, rounded jaw
#: tips and pocket circles behind the mouths, built from :class:`.pocket_specs.PocketSpecs`.
POCKET_MODELS = ("capture", "jaws")


@dataclass(frozen=True)
class Table:
    """A table ``[0, length] x [0, width]`` (between the cushion lines) with its cushions and pockets.

    Two pocket models (:data:`POCKET_MODELS`). ``capture`` (the default): four straight cushions along the
    whole edges and circular pockets; a ball is pocketed the first instant its centre is within a pocket's capture
    radius of that pocket's centre; ``pocket_xy`` may be empty (a table without pockets). ``jaws``: the geometry of
    ``specs`` (:mod:`.pocket_specs`): ball centres may enter the mouths, the jaws deflect them, and a ball is
    pocketed when its centre enters a pocket circle behind the mouth (``pocket_xy``, ``pocket_radius`` are those
    circles; ``length`` and ``width`` are ``specs.l`` and ``specs.w``).
    """

    length: float = DEFAULT_LENGTH
    width: float = DEFAULT_WIDTH
    cushion_restitution: float = DEFAULT_CUSHION_RESTITUTION
    pocket_xy: np.ndarray = field(default=None)  # type: ignore[arg-type]  # filled in __post_init__
    pocket_radius: np.ndarray = field(default=None)  # type: ignore[arg-type]  # filled in __post_init__
    specs: PocketSpecs | None = None
    pocket_model: str = "capture"

    def __post_init__(self) -> None:
        check_positive("table.length", self.length)
        check_positive("table.width", self.width)
        check_unit_interval("table.cushion_restitution", self.cushion_restitution)
        if self.pocket_model not in POCKET_MODELS:
            raise SceneError(f"table.pockets: unknown pocket model {self.pocket_model!r}; use one of "
                             f"{', '.join(POCKET_MODELS)} (or a list of capture circles)")
        if self.pocket_model == "jaws":
            if self.specs is None:
                raise SceneError("table.pockets: the 'jaws' model needs the table's specs (table.specs or a "
                                 "preset with pockets: wpa, pooltool, snooker_match)")
            if (self.length, self.width) != (self.specs.l, self.specs.w):
                raise SceneError(f"table: length x width {self.length} x {self.width} differs from the specs' "
                                 f"l x w {self.specs.l} x {self.specs.w}; give the size once, in table.specs")
            xy, r = pocket_circles(self.specs)
            given = (self.pocket_xy, self.pocket_radius)
            if (given[0] is not None or given[1] is not None) and not (
                    np.array_equal(np.asarray(given[0], dtype=float).reshape(-1, 2), xy)
                    and np.array_equal(np.asarray(given[1], dtype=float).reshape(-1), r)):
                raise SceneError("table.pockets: a jaw table's pockets are its specs' pocket circles; give "
                                 "corner/side_pocket_radius and _depth in table.specs instead of a pocket list")
        elif self.pocket_xy is None and self.pocket_radius is None:
            xy, r = default_pockets(self.length, self.width)
        elif self.pocket_xy is None or self.pocket_radius is None:
            raise SceneError("table.pockets: give both pocket centres and radii, or neither for the default six")
        else:
            xy = np.array(self.pocket_xy, dtype=float).reshape(-1, 2)
            r = np.array(self.pocket_radius, dtype=float).reshape(-1)
            if len(xy) != len(r):
                raise SceneError(f"table.pockets: {len(xy)} centres but {len(r)} radii; give one radius per pocket")
        for k in range(len(r)):
            check_finite(f"table.pockets[{k}].x", xy[k, 0])
            check_finite(f"table.pockets[{k}].y", xy[k, 1])
            check_positive(f"table.pockets[{k}].radius", r[k])
        xy.setflags(write=False)
        r.setflags(write=False)
        object.__setattr__(self, "pocket_xy", xy)
        object.__setattr__(self, "pocket_radius", r)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Table):
            return NotImplemented
        return (self.length, self.width, self.cushion_restitution, self.specs, self.pocket_model) == (
            other.length, other.width, other.cushion_restitution, other.specs, other.pocket_model) \
            and np.array_equal(self.pocket_xy, other.pocket_xy) \
            and np.array_equal(self.pocket_radius, other.pocket_radius)

    __hash__ = None  # type: ignore[assignment]  # mutable-looking arrays inside: not hashable

    @property
    def n_pockets(self) -> int:
        return int(len(self.pocket_radius))

    @property
    def has_jaws(self) -> bool:
        """The ``jaws`` pocket model: rails, jaw faces and tips instead of four full-length cushions."""
        return self.pocket_model == "jaws"

    def walls(self) -> tuple[np.ndarray, np.ndarray]:
        """The jaw table's cushion geometry ``(segments (S, 6), tips (C, 3))`` (:func:`.pocket_specs.build_walls`,
        built once per table; read-only); empty arrays under the ``capture`` model, whose four cushions are the
        edges of the playing area."""
        got = self.__dict__.get("_walls")
        if got is None:
            if self.has_jaws:
                assert self.specs is not None
                segs, tips = build_walls(self.specs)
            else:
                segs, tips = np.zeros((0, 6)), np.zeros((0, 3))
            segs.setflags(write=False)
            tips.setflags(write=False)
            got = (segs, tips)
            object.__setattr__(self, "_walls", got)
        return got

    def with_pockets(self, pocket_xy: np.ndarray, pocket_radius: np.ndarray) -> "Table":
        """A copy of this table with another pocket list (empty arrays: no pockets) under the capture model."""
        return Table(self.length, self.width, self.cushion_restitution, pocket_xy, pocket_radius)

    def without_pockets(self) -> "Table":
        """A copy of this table with no pockets (a carom table)."""
        return self.with_pockets(np.zeros((0, 2)), np.zeros(0))


# --- pocket sizes: a real pocket's mouth as a capture circle ---------------------------------------------------
# A capture circle is not a pocket with jaws, so its radius is calibrated: the default pool table's circles
# (CORNER_POCKET_RADIUS, SIDE_POCKET_RADIUS) admit a certain fraction of the entry width a WPA pocket of that
# table has; another table's circles admit the same fraction of its own pockets' entry width. The entry width is
# measured on the straight-in shot: a ball heading along the corner's diagonal, or square into a side pocket,
# with its path offset sideways by ``d``; it enters the real pocket while ``d < (mouth - 2R) / 2`` and the capture
# circle while ``d`` is below the half-widths below.

#: Radius of a pool ball (m): the same number as ``balls.BALL_RADIUS`` (that module imports this one).
POOL_BALL_RADIUS = 0.028575
#: WPA pocket mouths (m, jaw to jaw) of the pool table the default capture radii stand for: the middles of the WPA
#: ranges, corner 4 1/2 - 4 5/8 in, side 5 - 5 1/8 in.
POOL_CORNER_MOUTH = 0.1159
POOL_SIDE_MOUTH = 0.1286


def corner_entry_half_width(capture_radius: float, ball_radius: float) -> float:
    """Largest sideways offset ``d`` of a ball heading straight along a corner pocket's diagonal that still enters
    the capture circle (centred on the corner) before its ball touches a cushion: ``(sqrt2 R + d)^2 + d^2 = r^2``
    (the ball meets the cushion at ``sqrt2 R + d`` along the diagonal, ``d`` off it). 0 if even ``d = 0`` fails."""
    a = math.sqrt(2.0) * ball_radius
    disc = 2.0 * capture_radius * capture_radius - a * a
    return max(0.0, 0.5 * (-a + math.sqrt(disc))) if disc > 0.0 else 0.0


def corner_capture_radius(half_width: float, ball_radius: float) -> float:
    """Inverse of :func:`corner_entry_half_width`: the corner capture radius with entry half-width ``half_width``."""
    return math.hypot(math.sqrt(2.0) * ball_radius + half_width, half_width)


def side_entry_half_width(capture_radius: float, ball_radius: float) -> float:
    """Largest sideways offset ``d`` of a ball heading square into a side pocket (capture circle centred on the
    cushion line) that still enters the circle before touching the cushion: ``d^2 + R^2 = r^2``."""
    return math.sqrt(max(capture_radius * capture_radius - ball_radius * ball_radius, 0.0))


def side_capture_radius(half_width: float, ball_radius: float) -> float:
    """Inverse of :func:`side_entry_half_width`."""
    return math.hypot(half_width, ball_radius)


def capture_radii(corner_mouth: float, side_mouth: float, ball_radius: float) -> tuple[float, float]:
    """Capture radii ``(corner, side)`` for pockets with these mouths (m, jaw to jaw) and balls of
    ``ball_radius``, calibrated on the default pool table: each admits the same fraction of its real entry width
    ``(mouth - 2R) / 2`` as the default table's circle of that kind admits of a WPA pocket's."""
    for name, mouth in (("corner_mouth", corner_mouth), ("side_mouth", side_mouth)):
        if not mouth > 2.0 * ball_radius:
            raise SceneError(f"{name}: {mouth} m does not let a ball of radius {ball_radius} m through; "
                             "a mouth must be wider than the ball")
    k_corner = corner_entry_half_width(CORNER_POCKET_RADIUS, POOL_BALL_RADIUS) / (
        0.5 * (POOL_CORNER_MOUTH - 2.0 * POOL_BALL_RADIUS))
    k_side = side_entry_half_width(SIDE_POCKET_RADIUS, POOL_BALL_RADIUS) / (
        0.5 * (POOL_SIDE_MOUTH - 2.0 * POOL_BALL_RADIUS))
    return (corner_capture_radius(k_corner * 0.5 * (corner_mouth - 2.0 * ball_radius), ball_radius),
            side_capture_radius(k_side * 0.5 * (side_mouth - 2.0 * ball_radius), ball_radius))


# --- the snooker table ------------------------------------------------------------------------------------------
#: WPBSA: playing area 11 ft 8 1/2 in x 5 ft 10 in (3569 x 1778 mm) within the cushion faces.
SNOOKER_LENGTH = 3.569
SNOOKER_WIDTH = 1.778
#: WPBSA: balls 52.5 mm across; a set weighs about 142 g a ball (the rules allow 3 g between the balls of a set).
SNOOKER_BALL_RADIUS = 0.02625
SNOOKER_BALL_MASS = 0.142
#: Pocket mouths (m, jaw to jaw). The WPBSA's pocket templates are not published; these are pooltool's generic
#: snooker table (``SnookerTableSpecs``: corner 0.083, side 0.087), within the figures quoted for match tables.
SNOOKER_CORNER_MOUTH = 0.083
SNOOKER_SIDE_MOUTH = 0.087
#: The snooker table's capture radii (m): about 0.047 (corner) and 0.034 (middle), see :func:`capture_radii`.
SNOOKER_CORNER_POCKET_RADIUS, SNOOKER_SIDE_POCKET_RADIUS = capture_radii(
    SNOOKER_CORNER_MOUTH, SNOOKER_SIDE_MOUTH, SNOOKER_BALL_RADIUS)


def snooker_table(cushion_restitution: float = DEFAULT_CUSHION_RESTITUTION) -> Table:
    """The 12 ft snooker table: 3.569 x 1.778 m, six pockets in the pool order (bottom-left, bottom-middle,
    bottom-right, top-left, top-middle, top-right; ``x = 0`` is the baulk cushion) with snooker-sized capture
    circles for balls of :data:`SNOOKER_BALL_RADIUS`."""
    xy, r = default_pockets(SNOOKER_LENGTH, SNOOKER_WIDTH, SNOOKER_CORNER_POCKET_RADIUS, SNOOKER_SIDE_POCKET_RADIUS)
    return Table(SNOOKER_LENGTH, SNOOKER_WIDTH, cushion_restitution, xy, r)


# --- the carom (three-cushion) table ----------------------------------------------------------------------------
#: UMB match billiard: playing area 2.84 x 1.42 m, no pockets.
CAROM_LENGTH = 2.84
CAROM_WIDTH = 1.42
#: UMB: balls 61 - 61.5 mm across, 205 - 220 g.
CAROM_BALL_RADIUS = 0.03075
CAROM_BALL_MASS = 0.21


def carom_table(cushion_restitution: float = DEFAULT_CUSHION_RESTITUTION) -> Table:
    """The match carom table for three-cushion: 2.84 x 1.42 m, no pockets."""
    return Table(CAROM_LENGTH, CAROM_WIDTH, cushion_restitution, np.zeros((0, 2)), np.zeros(0))


def jaw_table(specs: PocketSpecs, cushion_restitution: float = DEFAULT_CUSHION_RESTITUTION) -> Table:
    """The ``jaws`` table of ``specs``: rails, jaw faces, rounded tips and pocket circles."""
    return Table(specs.l, specs.w, cushion_restitution, specs=specs, pocket_model="jaws")


def capture_table(specs: PocketSpecs, ball_radius: float = POOL_BALL_RADIUS,
                  cushion_restitution: float = DEFAULT_CUSHION_RESTITUTION) -> Table:
    """The ``capture`` model of ``specs``' table: its size, full-length cushions and capture circles calibrated on
    its mouths (:func:`capture_radii`) for balls of ``ball_radius``."""
    corner, side = capture_radii(specs.corner_pocket_width, specs.side_pocket_width, ball_radius)
    xy, r = default_pockets(specs.l, specs.w, corner, side)
    return Table(specs.l, specs.w, cushion_restitution, xy, r, specs=specs, pocket_model="capture")


#: The named tables of scene files and env configs (``table: {preset: snooker}``): ``pool`` the 9-ft table with
#: capture circles (the default table), ``snooker`` the 12-ft table with capture circles, ``carom`` no pockets;
#: with jaws: ``wpa`` a WPA 9-ft table, ``pooltool`` pooltool's 7-ft default table, ``snooker_match`` the 12-ft
#: table with its rounded pockets (:mod:`.pocket_specs`).
TABLE_PRESETS: dict[str, Callable[[], Table]] = {
    "pool": Table, "snooker": snooker_table, "carom": carom_table, "wpa": lambda: jaw_table(WPA_9FT),
    "pooltool": lambda: jaw_table(POOLTOOL_7FT), "snooker_match": lambda: jaw_table(SNOOKER_12FT)}
