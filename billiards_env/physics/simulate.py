"""The Python entry point to both solvers: ``Simulator(table, physics, ...).run(balls)`` or ``simulate(...)``."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .balls import Balls, validate_balls
from .codes import STATUS_NAMES
from .errors import SceneError, check_positive
from .kernel_io import kernel_params
from .kernels import kernels_for
from .model import G, Physics
from .result import EventLog, ShotResult
from .spin_motion import classify_all
from .step import CONTACT_MODES
from .table import Table
from .trajectory import Trajectory

SOLVERS = ("exact", "step")
DEFAULT_MAX_TIME = 600.0  #: simulated-time cap per shot (s)
DEFAULT_MAX_EVENTS = 100_000  #: event cap per shot (exact solver)
DEFAULT_DT = 1e-3  #: step solver time step (s)
@dataclass(frozen=True)
class SolverSettings:
    """Which solver runs a scene: ``name`` ``"exact"`` or ``"step"``, and the step solver's time step ``dt`` (s)
    and contact treatment ``contact`` (``"lecture"`` or ``"rewind"``). The ``solver`` section of scene files and
    env configs (:func:`.scene.parse_solver`)."""

    name: str = "exact"
    dt: float = DEFAULT_DT
    contact: str = "lecture"

    def __post_init__(self) -> None:
        if self.name not in SOLVERS:
            raise SceneError(f"solver.name: unknown solver {self.name!r}; use one of {', '.join(SOLVERS)}")
        if self.contact not in CONTACT_MODES:
            raise SceneError(f"solver.contact: unknown contact treatment {self.contact!r}; "
                             f"use one of {', '.join(CONTACT_MODES)}")
        check_positive("solver.dt", self.dt)


@dataclass
class Simulator:
    """A table, its physics and a solver, ready to run shots.

    ``solver="exact"`` (event-driven, the reference) or ``"step"`` (the lecture's per-frame algorithm with
    time step ``dt`` and ``contact="lecture"`` push-apart or ``"rewind"`` to the time of impact).
    ``max_time`` caps simulated seconds; ``max_events`` caps events (exact) — a capped shot says so in its status.
    """

    table: Table
    physics: Physics
    solver: str = "exact"
    dt: float = DEFAULT_DT
    contact: str = "lecture"
    max_time: float = DEFAULT_MAX_TIME
    max_events: int = DEFAULT_MAX_EVENTS

    def __post_init__(self) -> None:
        SolverSettings(self.solver, self.dt, self.contact)  # checks the name, contact and dt
        check_positive("max_time", self.max_time)
        if isinstance(self.max_events, bool) or not isinstance(self.max_events, (int, np.integer)) \
                or self.max_events < 1:
            raise SceneError(f"max_events: must be a positive integer, got {self.max_events!r}")
        if self.solver == "step" and self.max_time / self.dt > 1e10:
            raise SceneError(f"solver.dt: {self.dt} s with max_time {self.max_time} s needs over 1e10 steps; "
                             "raise dt or lower max_time")
        self._params = kernel_params(self.table, self.physics, self.max_time)
        self._pocket_xy = np.ascontiguousarray(self.table.pocket_xy, dtype=float)
        self._pocket_r = np.ascontiguousarray(self.table.pocket_radius, dtype=float)
        self._kernels = kernels_for(self.physics)
        self._spin = self._kernels.spin  # balls carry spin (the spin model's kernels)

    @property
    def name(self) -> str:
        return "exact" if self.solver == "exact" else f"step-{self.contact}"

    @property
    def params(self) -> np.ndarray:
        """The kernels' parameter record of this table, physics and time cap (:func:`~.kernel_io.kernel_params`):
        what compiled callers (the native vector env, the players' batches) pass the kernels."""
        return self._params

    @property
    def pocket_xy(self) -> np.ndarray:
        """The pockets' centres ``(P, 2)`` as the kernels take them (C-contiguous float64)."""
        return self._pocket_xy

    @property
    def pocket_r(self) -> np.ndarray:
        """The pockets' capture radii ``(P,)`` as the kernels take them."""
        return self._pocket_r

    @property
    def kernels(self) -> Any:
        """The compiled kernels of this physics (:func:`~.kernels.kernels_for`: exact, step, rows, spin)."""
        return self._kernels

    @property
    def has_spin(self) -> bool:
        """The balls carry spin (the spin model's kernels)."""
        return bool(self._spin)

    def run_in_place(self, balls: Balls) -> tuple[str, float, int, np.ndarray, np.ndarray]:
        """The hot path for RL: simulate ``balls`` in place (its ``pos``/``vel``/``on_table`` arrays become the
        final state; they must be C-contiguous float64/bool arrays) with no validation, copies or result objects.

        Returns ``(status, time, n_events, pocket (N,), events (M, 3) int: kind, ball, other)``.
        """
        if self.solver != "exact":
            res = self.run(balls, validate=False)
            balls.pos[...] = res.balls.pos
            balls.vel[...] = res.balls.vel
            balls.on_table[...] = res.balls.on_table
            balls.ang[...] = res.balls.ang
            ev = res.events
            return res.status, res.time, res.n_events, res.pocket, np.stack([ev.kind, ev.ball, ev.other], axis=1)
        # Under the spin model the angular velocities ``balls.ang`` (C-contiguous float64) are updated too.
        out = self._kernels.exact(balls.pos, balls.vel, balls.ang, balls.radius, balls.mass, balls.on_table,
                                  self._pocket_xy, self._pocket_r, self._params, self.max_events, False)
        return STATUS_NAMES[out.status], out.time, out.n_events, out.pocket, out.ev_int

    def run(self, balls: Balls, record: bool = False, validate: bool = True) -> ShotResult:
        """Simulate from ``balls`` (not modified) until rest or a cap. ``record`` keeps the trajectory."""
        if validate:
            validate_balls(balls, self.table, allow_spin=self._spin)
            self.physics.check_cushion_height(balls.radius)
        out = balls.copy()
        pos = np.ascontiguousarray(out.pos, dtype=float)
        vel = np.ascontiguousarray(out.vel, dtype=float)
        on = np.ascontiguousarray(out.on_table, dtype=np.bool_)
        radius = np.ascontiguousarray(out.radius, dtype=float)
        mass = np.ascontiguousarray(out.mass, dtype=float)
        ang = np.ascontiguousarray(out.ang, dtype=float)
        if self.solver == "exact":
            k = self._kernels.exact(pos, vel, ang, radius, mass, on, self._pocket_xy, self._pocket_r, self._params,
                                    self.max_events, record)
        else:
            k = self._kernels.step(pos, vel, ang, radius, mass, on, self._pocket_xy, self._pocket_r, self._params,
                                   self.dt, CONTACT_MODES.index(self.contact), 1.0 / 240.0 if record else 0.0)
        final = Balls(out.ids, pos, vel, radius, mass, on, ang)
        traj = None
        if record:
            traj = Trajectory(k.sc_time, k.sc_ball, k.sc_state, len(out), float(k.time), self.physics.law_code,
                              self.physics.deceleration, self.physics.drag_rate, self.physics.min_speed,
                              interpolate=self.solver != "exact", radius=radius,
                              spin_decel=(self.physics.mu_slide * G, self.physics.mu_roll * G,
                                          self.physics.mu_spin * G))
        ev_int = k.ev_int
        events = EventLog(k.ev_time, ev_int[:, 0], ev_int[:, 1], ev_int[:, 2], k.ev_speed)
        return ShotResult(STATUS_NAMES[k.status], float(k.time), int(k.n_events), final, k.pocket, k.pocketed_at,
                          events, self.name, traj, int(k.n_steps), int(k.n_tunnelled),
                          motion_state=classify_all(vel, ang, radius, on) if self._spin else None)


def simulate(
    table: Table,
    physics: Physics,
    balls: Balls,
    solver: str = "exact",
    *,
    dt: float = DEFAULT_DT,
    contact: str = "lecture",
    max_time: float = DEFAULT_MAX_TIME,
    max_events: int = DEFAULT_MAX_EVENTS,
    record: bool = False,
) -> ShotResult:
    """Simulate one shot (see :class:`Simulator`)."""
    sim = Simulator(table, physics, solver=solver, dt=dt, contact=contact, max_time=max_time,
                    max_events=max_events)
    return sim.run(balls, record=record)


def kinetic_energy(balls: Balls) -> float:
    """Total translational kinetic energy of the balls on the table (J)."""
    on = balls.on_table
    return float(0.5 * np.sum(balls.mass[on] * np.sum(balls.vel[on] ** 2, axis=1)))


def momentum(balls: Balls) -> np.ndarray:
    """Total momentum ``(px, py)`` of the balls on the table (kg m/s)."""
    on = balls.on_table
    return (balls.mass[on, None] * balls.vel[on]).sum(axis=0)


__all__ = ["Simulator", "SolverSettings", "simulate", "kinetic_energy", "momentum", "SOLVERS"]
