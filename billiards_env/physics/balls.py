"""Ball sets as arrays (positions ``(N,2)``, velocities ``(N,2)``, radii, masses, on-table flags) and their checks."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from .errors import SceneError
from .table import Table

BALL_RADIUS = 0.028575  #: pool ball radius (m)
BALL_MASS = 0.17  #: pool ball mass (kg)
#: Largest overlap (m) accepted between two balls in an input scene: touching balls built from rounded
#: decimal coordinates may overlap by rounding error, anything beyond is a placement error.
OVERLAP_TOLERANCE = 1e-9


@dataclass
class Balls:
    """The balls of a scene: one row per ball. ``ids`` name them (``"cue"``, ``"1"``, ...)."""

    ids: tuple[str, ...]
    pos: np.ndarray
    vel: np.ndarray
    radius: np.ndarray
    mass: np.ndarray
    on_table: np.ndarray

    @classmethod
    def from_positions(
        cls,
        positions: Sequence[Sequence[float]] | np.ndarray,
        ids: Sequence[str] | None = None,
        velocities: Sequence[Sequence[float]] | np.ndarray | None = None,
        radius: float | Sequence[float] = BALL_RADIUS,
        mass: float | Sequence[float] = BALL_MASS,
    ) -> "Balls":
        """Balls at ``positions`` (``(N,2)``), at rest unless ``velocities`` are given; ids default to 0..N-1
        with ball 0 named ``"cue"``."""
        pos = np.array(positions, dtype=float).reshape(-1, 2)
        n = len(pos)
        if ids is None:
            ids = ["cue"] + [str(k) for k in range(1, n)]
        vel = np.zeros((n, 2)) if velocities is None else np.array(velocities, dtype=float).reshape(n, 2)
        return cls(
            ids=tuple(str(i) for i in ids),
            pos=pos,
            vel=vel,
            radius=np.broadcast_to(np.asarray(radius, dtype=float), (n,)).copy(),
            mass=np.broadcast_to(np.asarray(mass, dtype=float), (n,)).copy(),
            on_table=np.ones(n, dtype=bool),
        )

    def __len__(self) -> int:
        return len(self.ids)

    def copy(self) -> "Balls":
        return Balls(self.ids, self.pos.copy(), self.vel.copy(), self.radius.copy(), self.mass.copy(),
                     self.on_table.copy())

    def index(self, ball_id: str | int) -> int:
        """Row of the ball named ``ball_id`` (or the row itself if an int is given)."""
        if isinstance(ball_id, (int, np.integer)) and not isinstance(ball_id, bool):
            if not 0 <= ball_id < len(self):
                raise SceneError(f"ball index {ball_id} out of range: the scene has {len(self)} balls")
            return int(ball_id)
        try:
            return self.ids.index(str(ball_id))
        except ValueError:
            raise SceneError(f"unknown ball id {ball_id!r}; the scene's balls are {', '.join(self.ids)}") from None

    def strike(self, ball_id: str | int, angle: float, speed: float) -> "Balls":
        """A copy with ball ``ball_id`` given speed ``speed`` (m/s) in direction ``angle`` (rad, 0 = +x, CCW)."""
        i = self.index(ball_id)
        for name, v in (("shot.angle", angle), ("shot.speed", speed)):
            if not isinstance(v, (int, float, np.floating, np.integer)) or not math.isfinite(v):
                raise SceneError(f"{name}: must be a finite number, got {v!r}")
        if speed < 0:
            raise SceneError(f"shot.speed: must be >= 0, got {speed}")
        if not self.on_table[i]:
            raise SceneError(f"shot.ball: ball {self.ids[i]!r} is pocketed and cannot be struck")
        out = self.copy()
        out.vel[i] = (speed * math.cos(angle), speed * math.sin(angle))
        return out


def _raise_ball_error(balls: Balls, table: Table, i: int) -> None:
    """Raise the SceneError that names what is wrong with ball row ``i``."""
    bid = balls.ids[i]
    for what, vals in (("x, y", balls.pos[i]), ("vx, vy", balls.vel[i]),
                       ("radius", balls.radius[i:i + 1]), ("mass", balls.mass[i:i + 1])):
        if not np.all(np.isfinite(vals)):
            raise SceneError(f"ball {bid!r}: {what} must be finite numbers, got {vals.tolist()}")
    if balls.radius[i] <= 0:
        raise SceneError(f"ball {bid!r}: radius must be > 0, got {balls.radius[i]}")
    if balls.mass[i] <= 0:
        raise SceneError(f"ball {bid!r}: mass must be > 0, got {balls.mass[i]}")
    r = balls.radius[i]
    if 2 * r > min(table.length, table.width):
        raise SceneError(f"ball {bid!r}: radius {r} is too large for a {table.length} x {table.width} table")
    x, y = balls.pos[i]
    raise SceneError(
        f"ball {bid!r}: centre ({x}, {y}) is off the table; it must lie in "
        f"[{r}, {table.length - r}] x [{r}, {table.width - r}] (radius {r} from each cushion)"
    )


def validate_balls(balls: Balls, table: Table) -> None:
    """Raise :class:`SceneError` naming the first bad ball: non-finite values, non-positive radius or mass,
    a centre off the table, two balls overlapping, or repeated ids."""
    n = len(balls)
    if n == 0:
        raise SceneError("balls: the scene has no balls; add at least one")
    if len(set(balls.ids)) != n:
        dup = sorted({i for i in balls.ids if balls.ids.count(i) > 1})
        raise SceneError(f"balls: repeated ids {dup}; every ball needs its own id")
    for arr, name, shape in ((balls.pos, "position", (n, 2)), (balls.vel, "velocity", (n, 2)),
                             (balls.radius, "radius", (n,)), (balls.mass, "mass", (n,)),
                             (balls.on_table, "on_table", (n,))):
        if np.shape(arr) != shape:
            raise SceneError(f"balls: {name} array has shape {np.shape(arr)}, expected {shape}")
    finite = (np.isfinite(balls.pos).all(axis=1) & np.isfinite(balls.vel).all(axis=1)
              & np.isfinite(balls.radius) & np.isfinite(balls.mass))
    r = balls.radius
    x, y = balls.pos[:, 0], balls.pos[:, 1]
    with np.errstate(invalid="ignore"):
        bad = ~finite | (r <= 0) | (balls.mass <= 0)
        bad |= balls.on_table & ((2 * r > min(table.length, table.width))
                                 | ~((r <= x) & (x <= table.length - r) & (r <= y) & (y <= table.width - r)))
    if bad.any():
        _raise_ball_error(balls, table, int(np.argmax(bad)))
    on = np.flatnonzero(balls.on_table)
    if len(on) > 1:
        p = balls.pos[on]
        d = np.sqrt(((p[:, None, :] - p[None, :, :]) ** 2).sum(-1))
        need = balls.radius[on][:, None] + balls.radius[on][None, :]
        bad = (d < need - OVERLAP_TOLERANCE) & ~np.eye(len(on), dtype=bool)
        if bad.any():
            a, b = np.argwhere(bad)[0]
            i, j = on[a], on[b]
            raise SceneError(
                f"balls {balls.ids[i]!r} and {balls.ids[j]!r} overlap: centres {d[a, b]:.6g} m apart, "
                f"less than the sum of radii {need[a, b]:.6g} m; move them apart"
            )
