"""Standard ball layouts: the 15-ball triangle rack and the head-string cue position."""
from __future__ import annotations

import math

import numpy as np

from .balls import BALL_RADIUS, Balls
from .table import Table

#: Ball numbers of the 15-ball rack, row by row from the apex (8-ball in the middle of the third row).
RACK_ORDER = (1, 9, 2, 10, 8, 3, 11, 4, 12, 5, 13, 6, 14, 7, 15)


def triangle_positions(apex: tuple[float, float], radius: float = BALL_RADIUS, rows: int = 5,
                       gap: float = 0.0) -> np.ndarray:
    """Centres of a triangle rack of ``rows`` rows pointing to ``-x`` with its apex at ``apex``.

    Neighbours touch (``gap = 0``) or sit ``gap`` metres apart. Rows are filled bottom to top.
    """
    d = 2.0 * radius + gap
    pts = []
    for row in range(rows):
        x = apex[0] + row * d * math.sqrt(3.0) / 2.0
        for k in range(row + 1):
            pts.append((x, apex[1] + (k - row / 2.0) * d))
    return np.array(pts)


def rack_balls(table: Table | None = None, cue_xy: tuple[float, float] | None = None, gap: float = 0.0,
               radius: float = BALL_RADIUS) -> Balls:
    """Cue ball plus a 15-ball triangle at the foot spot (apex at ``3/4`` of the length, centred).

    The cue ball defaults to the head spot (``1/4`` of the length, centred). Ids are ``cue, 1..15``.
    """
    table = table or Table()
    apex = (0.75 * table.length, 0.5 * table.width)
    rack = triangle_positions(apex, radius, gap=gap)
    cue = cue_xy if cue_xy is not None else (0.25 * table.length, 0.5 * table.width)
    pos = np.vstack([np.asarray(cue, dtype=float)[None, :], rack])
    ids = ["cue"] + [str(n) for n in RACK_ORDER]
    return Balls.from_positions(pos, ids=ids, radius=radius)
