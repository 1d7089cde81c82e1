"""The window offsets and speed thresholds of the ``candidates_aim`` action and ``candidates_path`` observation types
(:class:`billiards_env.envs.actions.CandidateAim`, :class:`billiards_env.envs.observations.CuePathFeatures`).

The ``candidates`` types choose a (ball, pocket) shot and its speed; where the object ball enters its pocket's window
moves the cut, and with it the line the cue ball leaves on after contact. These helpers give the shot of a slot at
an offset across its window (:func:`offset_ghost`), the speeds at which it pots and at which the deflected cue ball
follows into a pocket (:func:`thresholds`, on :mod:`billiards_env.physics.cue_path`), and both in the units of the
``candidates`` action's ``power`` dim (:func:`power_of`).
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from billiards_env.physics.aim import ray_circle_entry
from billiards_env.physics.cue_path import MAX_BOUNCES, rows_thresholds

if TYPE_CHECKING:  # pragma: no cover
    from billiards_env.table_state import TableState

#: Values per slot appended by :class:`~billiards_env.envs.observations.CuePathFeatures`: two per offset of
#: :data:`OFFSETS`, then ``top``.
PATH_FEATURES = 11
#: The ``offset`` dim of :class:`~billiards_env.envs.actions.CandidateAim`: ``a = +-1`` sends the object ball this fraction of its pocket
#: window's half-width off the window's middle (the edges are left: the window is sampled).
OFFSET_SPAN = 0.8
#: The offsets at which :class:`~billiards_env.envs.observations.CuePathFeatures` states the thresholds.
OFFSETS = (-1.0, -0.5, 0.0, 0.5, 1.0)
#: The largest cut an offset may ask for (beyond it the shot is not played: the window's middle is).
MAX_OFFSET_CUT = math.radians(88.0)


def offset_ghost(state: "TableState", slot: Any, offset: float) -> tuple[float, float, float, float] | None:
    """The shot of pot ``slot`` (cue ball where it lies) sending the object ball ``offset * OFFSET_SPAN`` of its
    window's half-width off the window's middle: ``(ghost x, ghost y, object direction, distance to the capture
    circle)``; None when that direction misses the pocket, asks for a cut beyond :data:`MAX_OFFSET_CUT` or puts the
    ghost ball off the table."""
    b = state.balls
    t = state.table
    j = slot.target
    contact = float(b.radius[0] + b.radius[j])
    direction = slot.obj_angle + offset * OFFSET_SPAN * slot.half
    ux, uy = math.cos(direction), math.sin(direction)
    ox, oy = float(b.pos[j, 0]), float(b.pos[j, 1])
    d_obj = ray_circle_entry(ox, oy, ux, uy, float(t.pocket_xy[slot.pocket, 0]), float(t.pocket_xy[slot.pocket, 1]),
                             float(t.pocket_radius[slot.pocket]))
    if not math.isfinite(d_obj):
        return None
    gx, gy = ox - contact * ux, oy - contact * uy
    rc = float(b.radius[0])
    if not (rc <= gx <= t.length - rc and rc <= gy <= t.width - rc):
        return None
    cx, cy = float(b.pos[0, 0]), float(b.pos[0, 1])
    d = math.hypot(gx - cx, gy - cy)
    if d < 1e-9 or ((gx - cx) * ux + (gy - cy) * uy) / d < math.cos(MAX_OFFSET_CUT):
        return None
    return gx, gy, direction, d_obj


def offset_rows(state: "TableState", slots: Any, offsets: Any = OFFSETS) -> np.ndarray:
    """``(len(slots.slots) * len(offsets), 4)``: :func:`offset_ghost` of every pot slot (cue ball where it lies) at
    every offset, NaN rows where there is none."""
    rows = np.full((len(slots.slots) * len(offsets), 4), np.nan)
    for i, s in enumerate(slots.slots):
        if s.shot is None:
            continue
        for m, off in enumerate(offsets):
            g = offset_ghost(state, s, float(off))
            if g is not None:
                rows[i * len(offsets) + m] = g
    return rows


def thresholds(state: "TableState", rows: np.ndarray, v_top: float) -> np.ndarray:
    """:func:`rows_thresholds` of ``rows`` on the table state now (the cue ball row 0, the object ball of each row:
    the masses are all the cue ball's and ball 1's; the one-ball and pool tables have equal masses)."""
    b = state.balls
    t = state.table
    ph = state.physics
    law, acc, kk = ph.path_args
    mo = float(b.mass[1]) if len(b.mass) > 1 else float(b.mass[0])
    return rows_thresholds(float(b.pos[0, 0]), float(b.pos[0, 1]), np.ascontiguousarray(rows, dtype=np.float64),
                           float(v_top), float(b.radius[0]), float(b.mass[0]), mo, float(t.length), float(t.width),
                           float(t.cushion_restitution), float(ph.ball_restitution),
                           np.ascontiguousarray(t.pocket_xy, dtype=np.float64),
                           np.ascontiguousarray(t.pocket_radius, dtype=np.float64), int(law), float(acc), float(kk),
                           float(ph.min_speed), MAX_BOUNCES, *t.walls())


def power_of(speed: Any, base: Any, log_factor: float) -> np.ndarray:
    """The ``candidates`` action's ``power`` value that plays ``speed`` on a shot of own speed ``base`` (+inf for
    an infinite speed)."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        return np.log(np.maximum(speed, 1e-12) / np.maximum(base, 1e-12)) / log_factor


def offset_of(a: float) -> float:
    """The offset of :data:`OFFSETS` an ``offset`` action value picks (equal bins over ``[-1, 1]``)."""
    k = min(int(0.5 * (min(max(a, -1.0), 1.0) + 1.0) * len(OFFSETS)), len(OFFSETS) - 1)
    return OFFSETS[k]


__all__ = ["PATH_FEATURES", "OFFSET_SPAN", "OFFSETS", "MAX_OFFSET_CUT", "offset_ghost", "offset_rows", "thresholds",
           "power_of", "offset_of"]
