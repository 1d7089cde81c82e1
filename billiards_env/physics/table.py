"""Table geometry: the playing area, its cushions and its pockets (SI units, origin at a corner)."""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .codes import CUSHION_NAMES  # noqa: F401  (re-exported: the cushion ids of event records)
from .errors import SceneError, check_finite, check_positive, check_unit_interval

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


@dataclass(frozen=True)
class Table:
    """A rectangular table ``[0, length] x [0, width]`` with straight cushions and circular pockets.

    A ball is pocketed the first instant its centre is within a pocket's capture radius
    of that pocket's centre. ``pocket_xy`` may be empty (a table without pockets).
    """

    length: float = DEFAULT_LENGTH
    width: float = DEFAULT_WIDTH
    cushion_restitution: float = DEFAULT_CUSHION_RESTITUTION
    pocket_xy: np.ndarray = field(default=None)  # type: ignore[assignment]
    pocket_radius: np.ndarray = field(default=None)  # type: ignore[assignment]

    def __post_init__(self) -> None:
        check_positive("table.length", self.length)
        check_positive("table.width", self.width)
        check_unit_interval("table.cushion_restitution", self.cushion_restitution)
        if self.pocket_xy is None and self.pocket_radius is None:
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
        return (self.length, self.width, self.cushion_restitution) == (other.length, other.width,
                                                                       other.cushion_restitution) \
            and np.array_equal(self.pocket_xy, other.pocket_xy) \
            and np.array_equal(self.pocket_radius, other.pocket_radius)

    __hash__ = None  # type: ignore[assignment]  (mutable-looking arrays inside: not hashable)

    @property
    def n_pockets(self) -> int:
        return int(len(self.pocket_radius))

    def with_pockets(self, pocket_xy: np.ndarray, pocket_radius: np.ndarray) -> "Table":
        """A copy of this table with another pocket list (empty arrays: no pockets)."""
        return Table(self.length, self.width, self.cushion_restitution, pocket_xy, pocket_radius)

    def without_pockets(self) -> "Table":
        """A copy of this table with no pockets (a carom table)."""
        return self.with_pockets(np.zeros((0, 2)), np.zeros(0))
