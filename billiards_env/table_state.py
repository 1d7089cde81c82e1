"""The table state: the one object the parts of an env read (action types, observation types, tasks, players).

A :class:`TableState` is the balls as arrays (:class:`~billiards_env.physics.Balls`, updated in place by every
shot), the table, the physics and the solver, the shot settings (speed range, noise, tip offsets), and a
:class:`ShotView`: who is to shoot and what they may do (the balls they may hit first, the aim types' target ball,
where they may place the cue ball, a break, a pocket to call). The view is computed once per shot by the task
(``view_source``) and dropped when the balls change (:meth:`TableState.changed`), so every part of one step reads
the same facts; facts derived from it once per shot (the candidate shots) are kept in its ``memo``.

Parts never see the env: the single env holds one state, the native vector env one per table (views of its batch
arrays), the two-player env its game env's, and a player needs nothing else to choose a shot.
No Gymnasium and no pygame here.
"""
from __future__ import annotations

import contextlib
import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any, Callable, Iterator, NamedTuple

import numpy as np

from billiards_env.physics.balls import Balls
from billiards_env.physics.layout import half_disc_point, nearest_free_point, nearest_point_in_half_disc
from billiards_env.physics.model import Physics
from billiards_env.physics.simulate import Simulator
from billiards_env.physics.table import Table

class RectArea(NamedTuple):
    """Where the cue ball may be placed: the rectangle ``x0 <= x <= x1, y0 <= y <= y1`` of ball centres (the
    kitchen, the whole table). Unpacks as ``(x0, x1, y0, y1)``, the bounding box every area has."""

    x0: float
    x1: float
    y0: float
    y1: float

    def point(self, u: float, v: float) -> tuple[float, float]:
        """The point of ``(u, v)`` in ``[-1, 1]^2`` (an action's placement dims), linearly."""
        return self.x0 + 0.5 * (u + 1.0) * (self.x1 - self.x0), self.y0 + 0.5 * (v + 1.0) * (self.y1 - self.y0)

    def square(self, x: float, y: float) -> tuple[float, float]:
        """``(u, v)`` of the point ``(x, y)`` (the inverse of :meth:`point`)."""
        return (2.0 * (x - self.x0) / max(self.x1 - self.x0, 1e-12) - 1.0,
                2.0 * (y - self.y0) / max(self.y1 - self.y0, 1e-12) - 1.0)

    def contains(self, x: float, y: float, tol: float = 1e-9) -> bool:
        return self.x0 - tol <= x <= self.x1 + tol and self.y0 - tol <= y <= self.y1 + tol

    def nearest(self, x: float, y: float, balls: Balls, holes: np.ndarray) -> tuple[float, float]:
        """The legal point nearest ``(x, y)``: in the area, off the other balls and the pockets' capture circles."""
        return nearest_free_point(x, y, balls.pos, balls.on_table, balls.radius, 0,
                                  (self.x0, self.x1, self.y0, self.y1), holes=holes)

    def describe(self) -> str:
        return f"x in [{self.x0:.4g}, {self.x1:.4g}], y in [{self.y0:.4g}, {self.y1:.4g}] m"


class HalfDiscArea(NamedTuple):
    """Where the cue ball may be placed: the half-disc of radius ``x1 - x0`` centred on ``(x1, (y0 + y1) / 2)`` on its
    ``x <= x1`` side (snooker's D is one: :class:`billiards_env.games.snooker_layout.DArea`). Unpacks as its
    bounding box."""

    x0: float
    x1: float
    y0: float
    y1: float

    @property
    def geometry(self) -> tuple[float, float, float]:
        """``(cx, cy, r)``: the centre of the straight side and the radius."""
        return self.x1, 0.5 * (self.y0 + self.y1), self.x1 - self.x0

    def point(self, u: float, v: float) -> tuple[float, float]:
        """The point of ``(u, v)`` in ``[-1, 1]^2``: ``u`` across (``y``), ``v`` from the arc (-1) to the straight
        side (+1) along the line ``y`` fixed; continuous and one to one."""
        return half_disc_point(u, v, *self.geometry)

    def square(self, x: float, y: float) -> tuple[float, float]:
        cx, cy, r = self.geometry
        u = min(max((y - cy) / r, -1.0), 1.0)
        depth = math.sqrt(max(r * r - (r * u) ** 2, 0.0))
        v = 1.0 - 2.0 * (cx - x) / depth if depth > 1e-12 else 1.0
        return u, min(max(v, -1.0), 1.0)

    def contains(self, x: float, y: float, tol: float = 1e-9) -> bool:
        cx, cy, r = self.geometry
        return x <= cx + tol and math.hypot(x - cx, y - cy) <= r + tol

    def nearest(self, x: float, y: float, balls: Balls, table: Table) -> tuple[float, float]:
        """The legal point nearest ``(x, y)``: in the half-disc, off the other balls (``table``: the game's area
        may place by the table's own markings, as the D does)."""
        return nearest_point_in_half_disc(x, y, balls.pos, balls.on_table, balls.radius, 0, *self.geometry)

    def describe(self) -> str:
        cx, cy, r = self.geometry
        return f"the half-disc of radius {r:.4g} m on ({cx:.4g}, {cy:.4g}), x <= {cx:.4g}"


#: Where a cue ball in hand may go (both unpack as their bounding box ``(x0, x1, y0, y1)``).
Area = RectArea | HalfDiscArea


@dataclass(frozen=True, eq=False)
class ShotView:
    """Who is to shoot and what they may do, for the shot to play now (rows index the balls; 0 is the cue ball).

    ``targets``: rows the shooter may hit first (on the table). ``target``: the ball the relative and ghost aim and
    the ``features`` observation take as the target (the lowest-numbered ball on the table, or a game's lowest legal
    ball), None when there is none. ``place_area``: where the shooter may put the cue ball (ball in hand), else
    None. ``break_shot``: the shot is a game's opening break. ``call_pocket``: the shooter must call a pocket (the
    8). ``push_out``: a push-out may be declared. ``shooter``: the player to shoot (0 in one-player scenes).
    ``memo``: facts derived from this view once (e.g. the candidate shots), filled by whoever computes them."""

    targets: tuple[int, ...]
    target: int | None
    place_area: Area | None = None
    break_shot: bool = False
    call_pocket: bool = False
    push_out: bool = False
    shooter: int = 0
    memo: dict[Any, Any] = field(default_factory=dict)


def free_view(balls: Balls) -> ShotView:
    """The view of a scene without rules: every object ball on the table may be hit, the lowest row is the target."""
    on = balls.on_table
    rows = tuple(i for i in range(1, len(on)) if on[i])
    return ShotView(rows, rows[0] if rows else None)


@dataclass(frozen=True)
class ShotSettings:
    """What a shooter may do with the cue: the speed range (m/s), the shot noise (Gaussian standard deviations:
    angle rad, speed relative or, with ``speed_noise_absolute``, m/s, tip offset fraction of R), whether tip offsets
    are set (spin model and spin dims) and their largest offset (fraction of R)."""

    speed_min: float
    speed_max: float
    angle_noise: float = 0.0
    speed_noise: float = 0.0
    tip_noise: float = 0.0
    tip_offsets: bool = False
    max_tip_offset: float = 0.5
    speed_noise_absolute: bool = False

    @property
    def speed_range(self) -> tuple[float, float]:
        return self.speed_min, self.speed_max

    @property
    def noisy(self) -> bool:
        return self.angle_noise > 0.0 or self.speed_noise > 0.0 or self.tip_noise > 0.0


class TableState:
    """One table now (see the module docstring).

    ``balls`` (cue ball row 0; updated in place by every shot: ``copy()`` it to keep a snapshot), ``table``,
    ``physics``, ``simulator`` (to try shots: ``simulator.run(balls.strike(0, angle, speed), validate=False)`` or the
    batch API), ``numbers`` (ball number of each row, 0 the cue ball), ``settings`` (:class:`ShotSettings`),
    ``view`` (:class:`ShotView`, computed on first read after each change by ``view_source``), ``game`` (the
    game's session when the scene is a game, else None: its rules and rules state)."""

    def __init__(self, balls: Balls, table: Table, physics: Physics, simulator: Simulator,
                 numbers: tuple[int, ...], settings: ShotSettings,
                 view_source: Callable[["TableState"], ShotView] | None = None) -> None:
        self.balls = balls
        self.table = table
        self.physics = physics
        self.simulator = simulator
        self.numbers = tuple(int(n) for n in numbers)
        self.settings = settings
        self.view_source: Callable[[TableState], ShotView] = view_source or (lambda s: free_view(s.balls))
        self.game: Any = None
        self._view: ShotView | None = None
        self._holes = np.column_stack([table.pocket_xy, table.pocket_radius]) if table.n_pockets else \
            np.zeros((0, 3))

    # --- the view ------------------------------------------------------------------------------------------------
    @property
    def view(self) -> ShotView:
        """Who is to shoot and what they may do now (computed once per change of the table)."""
        v = self._view
        if v is None:
            v = self._view = self.view_source(self)
        return v

    def attach_game(self, game: Any, view_source: Callable[["TableState"], ShotView]) -> None:
        """Play ``game`` (a game's session) on this table: ``game`` is then the state's ``game`` and ``view_source``
        says who is to shoot and what they may do. The task that runs the game attaches it (the session does not
        install itself)."""
        self.game = game
        self.view_source = view_source
        self.changed()

    def changed(self) -> None:
        """The balls or the game moved on (a shot, a reset, a respot): the view is computed again on next read."""
        self._view = None

    @property
    def n_balls(self) -> int:
        return len(self.balls)

    @property
    def ids(self) -> tuple[str, ...]:
        return tuple(self.balls.ids)

    # --- ball in hand ---------------------------------------------------------------------------------------------
    def table_area(self) -> RectArea:
        """Every legal cue-ball centre on the table (the placement area of a scene without ball in hand)."""
        r = float(self.balls.radius[0])
        return RectArea(r, self.table.length - r, r, self.table.width - r)

    def legal_cue_position(self, x: float, y: float) -> tuple[float, float]:
        """Where a ball-in-hand cue ball asked for at ``(x, y)`` goes: the nearest point of the view's placement
        area (the table without ball in hand) not overlapping another ball nor inside a pocket's capture circle,
        where it would drop at once (:func:`~billiards_env.physics.layout.nearest_free_point`). Compiled twin (the
        native vector env's pool tables): ``billiards_env.envs._action_kernels.legal_place``."""
        area = self.view.place_area
        if area is None:
            area = self.table_area()
        if isinstance(area, HalfDiscArea):
            return area.nearest(x, y, self.balls, self.table)
        return area.nearest(x, y, self.balls, self._holes)

    @contextlib.contextmanager
    def cue_moved_to(self, place: tuple[float, float] | None) -> Iterator[None]:
        """Within the block the cue ball stands at ``place`` (on the table), e.g. to aim from a ball-in-hand
        position; None leaves it where it is. The view is unaffected (it does not depend on the cue ball)."""
        if place is None:
            yield
            return
        b = self.balls
        saved, on = b.pos[0].copy(), bool(b.on_table[0])
        b.pos[0] = place
        b.on_table[0] = True
        try:
            yield
        finally:
            b.pos[0] = saved
            b.on_table[0] = on

    @contextlib.contextmanager
    def cue_placed(self, place: tuple[float, float]) -> Iterator[None]:
        """Within the block the cue ball lies at ``place`` and is played from there: moved (as
        :meth:`cue_moved_to`) and the view is this one without the ball in hand (its own memo, so facts derived
        from it, e.g. the candidate shots, are those of the cue ball at ``place``). For players that choose where to
        put a cue ball in hand by the shots each place leaves."""
        view = self.view
        with self.cue_moved_to(place):
            self._view = dataclasses.replace(view, place_area=None, memo={})
            try:
                yield
            finally:
                self._view = view


def state_of(source: Any) -> TableState:
    """The :class:`TableState` of ``source``: itself, or a billiards env's (wrapped or not; ``.unwrapped.table_state``)."""
    if isinstance(source, TableState):
        return source
    state = getattr(getattr(source, "unwrapped", source), "table_state", None)
    if not isinstance(state, TableState):
        raise TypeError(f"expected a TableState or a billiards env, got {type(source).__name__}")
    return state


__all__ = ["TableState", "ShotView", "ShotSettings", "Area", "RectArea", "HalfDiscArea", "free_view", "state_of"]
