"""Ball sets as arrays (positions ``(N,2)``, velocities ``(N,2)``, radii, masses, on-table flags, angular
velocities ``(N,3)``) and their checks."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Sequence

import numpy as np
from numba import njit

from .errors import SceneError
from .spin_collide import MAX_TIP_OFFSET, strike_ball, strike_spin
from .pocket_specs import in_mouth, throat_leak
from .table import Table

if TYPE_CHECKING:  # pragma: no cover
    from .model import Physics

BALL_RADIUS = 0.028575  #: pool ball radius (m)
BALL_MASS = 0.17  #: pool ball mass (kg)
#: Largest overlap (m) accepted between two balls in an input scene: touching balls built from rounded
#: decimal coordinates may overlap by rounding error, anything beyond is a placement error.
OVERLAP_TOLERANCE = 1e-9
#: The fastest a ball may move (m/s): a shot's speed and every ball's velocity in a scene are at most this. The
#: hardest cue shots (a power break) reach about 12-15 m/s, so 50 m/s leaves room for any real shot and refuses
#: absurd values (1e300 m/s would otherwise "run" to rest in zero time, its motion lost to rounding).
MAX_BALL_SPEED = 50.0


@dataclass
class Balls:
    """The balls of a scene: one row per ball. ``ids`` name them (``"cue"``, ``"1"``, ...).

    ``ang``: angular velocities ``(wx, wy, wz)`` in rad/s (table frame, ``z`` up), used by the spin model only
    (zeros when not given; the ``rolling`` and ``drag`` laws refuse balls that spin)."""

    ids: tuple[str, ...]
    pos: np.ndarray
    vel: np.ndarray
    radius: np.ndarray
    mass: np.ndarray
    on_table: np.ndarray
    ang: np.ndarray = None  # type: ignore[assignment]

    def __post_init__(self) -> None:
        if self.ang is None:
            self.ang = np.zeros((len(self.ids), 3))

    @classmethod
    def from_positions(
        cls,
        positions: Sequence[Sequence[float]] | np.ndarray,
        ids: Sequence[str] | None = None,
        velocities: Sequence[Sequence[float]] | np.ndarray | None = None,
        radius: float | Sequence[float] = BALL_RADIUS,
        mass: float | Sequence[float] = BALL_MASS,
        spins: Sequence[Sequence[float]] | np.ndarray | None = None,
    ) -> "Balls":
        """Balls at ``positions`` (``(N,2)``), at rest unless ``velocities`` (``(N,2)``) or ``spins`` (angular
        velocities ``(N,3)``, spin model) are given; ids default to 0..N-1 with ball 0 named ``"cue"``."""
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
            ang=np.zeros((n, 3)) if spins is None else np.array(spins, dtype=float).reshape(n, 3),
        )

    def __len__(self) -> int:
        return len(self.ids)

    def copy(self) -> "Balls":
        return Balls(self.ids, self.pos.copy(), self.vel.copy(), self.radius.copy(), self.mass.copy(),
                     self.on_table.copy(), self.ang.copy())

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

    def strike(self, ball_id: str | int, angle: float, speed: float, side: float = 0.0,
               top: float = 0.0, physics: "Physics | None" = None) -> "Balls":
        """A copy with ball ``ball_id`` given speed ``speed`` (m/s) in direction ``angle`` (rad, 0 = +x, CCW).

        ``side`` and ``top`` (spin model) are the cue tip's offsets from the ball's centre in fractions of its
        radius: ``side > 0`` right english (spins counter-clockwise seen from above), ``top > 0`` follow,
        ``top < 0`` draw, ``top = 0.4`` natural roll; ``side^2 + top^2 <= 0.25`` (beyond, the cue miscues).
        The struck ball's angular velocity becomes ``wz = 5 side v / 2R``, ``(wx, wy) = 5 top v / 2R (z^ x d^)``.
        ``physics``: the model the shot is played in; its ``squirt`` turns the ball's path off ``angle`` when it
        has side english (:func:`.spin_collide.strike_ball`; the cue's direction, and so the spin, stay ``angle``).
        """
        i = self.index(ball_id)
        for name, v in (("shot.angle", angle), ("shot.speed", speed), ("shot.side", side), ("shot.top", top)):
            if not isinstance(v, (int, float, np.floating, np.integer)) or not math.isfinite(v):
                raise SceneError(f"{name}: must be a finite number, got {v!r}")
        if speed < 0:
            raise SceneError(f"shot.speed: must be >= 0, got {speed}")
        check_speed("shot.speed", speed)
        if side * side + top * top > MAX_TIP_OFFSET ** 2:
            raise SceneError(f"shot.side, shot.top: the tip offset ({side}, {top}) is {math.hypot(side, top):.4g} "
                             f"ball radii from the centre; it must be at most {MAX_TIP_OFFSET} "
                             f"(side^2 + top^2 <= {MAX_TIP_OFFSET ** 2}), beyond that the cue miscues")
        if not self.on_table[i]:
            raise SceneError(f"shot.ball: ball {self.ids[i]!r} is pocketed and cannot be struck")
        out = self.copy()
        out.vel[i] = (speed * math.cos(angle), speed * math.sin(angle))
        if side != 0.0 or top != 0.0:
            if physics is not None and physics.squirt != 0.0:
                vx, vy, wx, wy, wz = strike_ball(float(angle), float(speed), float(side), float(top),
                                                 float(self.radius[i]), float(self.mass[i]), float(physics.squirt),
                                                 float(physics.cue_end_mass))
                out.vel[i] = (vx, vy)
                out.ang[i] = (wx, wy, wz)
            else:
                out.ang[i] = strike_spin(float(angle), float(speed), float(side), float(top),
                                         float(self.radius[i]))[2:]
        else:
            out.ang[i] = 0.0
        return out


@njit(cache=True)
def _first_problem(pos, vel, radius, mass, on_table, ang, allow_spin, length, width, tol, in_mouth):
    """``(0, -1, -1, 0)`` if every ball is valid; ``(1, i, -1, 0)`` for the first ball with a bad value or off
    the table (``in_mouth[i]``: ball ``i`` lies in a jaw table's pocket mouth, which is on the table); ``(2, i, j, d)`` for the first overlapping pair (centres ``d`` apart); ``(3, i, -1, 0)`` for the
    first ball that spins when ``allow_spin`` is False."""
    n = pos.shape[0]
    for i in range(n):
        r = radius[i]
        ok = (math.isfinite(pos[i, 0]) and math.isfinite(pos[i, 1]) and math.isfinite(vel[i, 0])
              and math.isfinite(vel[i, 1]) and math.isfinite(r) and math.isfinite(mass[i]) and r > 0.0
              and mass[i] > 0.0 and math.isfinite(ang[i, 0]) and math.isfinite(ang[i, 1])
              and math.isfinite(ang[i, 2]))
        if ok and on_table[i]:
            ok = (2.0 * r <= min(length, width) and ((r <= pos[i, 0] <= length - r and r <= pos[i, 1] <= width - r)
                                                     or in_mouth[i]))
        if not ok:
            return 1, i, -1, 0.0
        if not allow_spin and (ang[i, 0] != 0.0 or ang[i, 1] != 0.0 or ang[i, 2] != 0.0):
            return 3, i, -1, 0.0
    for i in range(n):
        if not on_table[i]:
            continue
        for j in range(i + 1, n):
            if on_table[j]:
                d = math.hypot(pos[i, 0] - pos[j, 0], pos[i, 1] - pos[j, 1])
                if d < radius[i] + radius[j] - tol:
                    return 2, i, j, d
    return 0, -1, -1, 0.0


def _raise_ball_error(balls: Balls, table: Table, i: int) -> None:
    """Raise the SceneError that names what is wrong with ball row ``i``."""
    bid = balls.ids[i]
    for what, vals in (("x, y", balls.pos[i]), ("vx, vy", balls.vel[i]), ("wx, wy, wz", balls.ang[i]),
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
    mouths = " or in a pocket's mouth, clear of its jaws" if table.has_jaws else ""
    raise SceneError(
        f"ball {bid!r}: centre ({x}, {y}) is off the table; it must lie in "
        f"[{r}, {table.length - r}] x [{r}, {table.width - r}] (radius {r} from each cushion){mouths}"
    )


def mouth_mask(balls: Balls, table: Table) -> np.ndarray:
    """Which balls lie in a jaw table's pocket mouths (outside the playing area's ``[r, L - r] x [r, W - r]`` but
    on the table, clear of the jaws); all False under the capture model."""
    mask = np.zeros(len(balls), dtype=np.bool_)
    if not table.has_jaws:
        return mask
    segs, tips = table.walls()
    for i in range(len(balls)):
        x, y = (float(v) for v in balls.pos[i])
        r = float(balls.radius[i])
        if not (r <= x <= table.length - r and r <= y <= table.width - r) and math.isfinite(x) and \
                math.isfinite(y) and math.isfinite(r):
            mask[i] = in_mouth(segs, tips, table.pocket_xy, table.pocket_radius, x, y, r, OVERLAP_TOLERANCE)
    return mask


def check_speed(name: str, speed: float) -> float:
    """``speed`` (m/s) if at most :data:`MAX_BALL_SPEED`, else a :class:`SceneError` with the bound."""
    if speed > MAX_BALL_SPEED:
        raise SceneError(f"{name}: {speed:g} m/s is faster than any ball can move here (at most {MAX_BALL_SPEED:g} "
                         "m/s; the hardest break is about 15 m/s)")
    return speed


def validate_balls(balls: Balls, table: Table, allow_spin: bool = True) -> None:
    """Raise :class:`SceneError` naming the first bad ball: non-finite values, non-positive radius or mass,
    a centre off the table, two balls overlapping, repeated ids, or (``allow_spin`` False: a friction law
    without spin) a ball with angular velocity."""
    n = len(balls)
    if n == 0:
        raise SceneError("balls: the scene has no balls; add at least one")
    if len(set(balls.ids)) != n:
        dup = sorted({i for i in balls.ids if balls.ids.count(i) > 1})
        raise SceneError(f"balls: repeated ids {dup}; every ball needs its own id")
    for arr, name, shape in ((balls.pos, "position", (n, 2)), (balls.vel, "velocity", (n, 2)),
                             (balls.radius, "radius", (n,)), (balls.mass, "mass", (n,)),
                             (balls.on_table, "on_table", (n,)), (balls.ang, "angular velocity", (n, 3))):
        if np.shape(arr) != shape:
            raise SceneError(f"balls: {name} array has shape {np.shape(arr)}, expected {shape}")
    speeds = np.hypot(balls.vel[:, 0], balls.vel[:, 1])
    fast = np.flatnonzero(np.isfinite(speeds) & (speeds > MAX_BALL_SPEED))  # non-finite: reported below
    if fast.size:
        check_speed(f"ball {balls.ids[int(fast[0])]!r}: velocity", float(speeds[fast[0]]))
    bad, i, j, dist = _first_problem(np.ascontiguousarray(balls.pos, dtype=float),
                                     np.ascontiguousarray(balls.vel, dtype=float),
                                     np.ascontiguousarray(balls.radius, dtype=float),
                                     np.ascontiguousarray(balls.mass, dtype=float),
                                     np.ascontiguousarray(balls.on_table, dtype=np.bool_),
                                     np.ascontiguousarray(balls.ang, dtype=float), bool(allow_spin),
                                     float(table.length), float(table.width), OVERLAP_TOLERANCE,
                                     mouth_mask(balls, table))
    if bad == 1:
        _raise_ball_error(balls, table, i)
    if table.has_jaws:
        assert table.specs is not None  # a jaw table has specs (Table.__post_init__)
        on = np.asarray(balls.on_table, bool)
        if on.any():
            leak = throat_leak(table.specs, float(np.min(np.asarray(balls.radius)[on])))
            if leak is not None:
                raise SceneError(leak)
    if bad == 3:
        raise SceneError(f"ball {balls.ids[i]!r}: spins (wx, wy, wz) = {tuple(balls.ang[i].tolist())} rad/s, but "
                         "only the spin model has spin: set physics.friction to 'spin' (or give the ball no spin, "
                         "and strike with side = top = 0)")
    if bad == 2:
        need = balls.radius[i] + balls.radius[j]
        raise SceneError(
            f"balls {balls.ids[i]!r} and {balls.ids[j]!r} overlap: centres {dist:.6g} m apart, "
            f"less than the sum of radii {need:.6g} m; move them apart"
        )
