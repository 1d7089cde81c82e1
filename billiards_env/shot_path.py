"""The one shot path: a cue shot on a table state -> the shot as played (noise added) -> the simulated outcome.

Every shot of every env goes through :func:`play_shot`: the agent's, the built-in opponent's, the two-player
env's, the ``ball_in_hand`` opening's break. It places a ball in hand, adds the shot noise (drawn by the caller in
:func:`draw_noise`'s order, so a seed replays bit for bit), strikes the cue ball, simulates until every ball rests
(the compiled exact solver in place, or ``Simulator.run`` when the trajectory is kept for drawing or the step
solver runs), and reads the event log once into a :class:`~billiards_env.physics.outcome.ShotOutcome`. What the
shot means (reward, the rules' call, info) is the task's. The native vector env runs the same arithmetic for N
tables in one compiled call (:mod:`billiards_env.envs._vector_kernels`, which calls :func:`noisy_shot`).
No Gymnasium here.
"""
from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np
from numba import njit

from billiards_env.physics.outcome import ShotOutcome
from billiards_env.physics.spin_collide import strike_ball
from billiards_env.table_state import ShotSettings, TableState

#: The largest tip offset a noisy shot keeps (the miscue limit 0.5 R, less a hair).
TIP_LIMIT = 0.5 * (1.0 - 1e-12)


class CueShot(NamedTuple):
    """One shot as played (before noise): cue direction ``angle`` (rad, 0 = +x, counter-clockwise), ``speed``
    (m/s), tip offsets ``side`` and ``top`` (fractions of R), and the cue ball's placement ``place`` (x, y) when
    the shooter has ball in hand (else None); ``calls``: the game's declarations as ``(name, value)`` pairs (the
    game's :class:`~billiards_env.games.declarations.Declaration` names: e.g. the pocket called for the 8, a 9-ball
    push-out, straight pool's called ball and pocket); read them with :meth:`call`."""

    angle: float
    speed: float
    side: float = 0.0
    top: float = 0.0
    place: tuple[float, float] | None = None
    calls: tuple[tuple[str, Any], ...] = ()

    def call(self, name: str, default: Any = None) -> Any:
        """The value declared as ``name``, or ``default`` when the shot does not declare it."""
        for key, value in self.calls:
            if key == name:
                return value
        return default

    def with_calls(self, **given: Any) -> "CueShot":
        """This shot with the declarations it carries set from ``given`` (names it does not carry are ignored)."""
        if not self.calls:
            return self
        return self._replace(calls=tuple((k, given.get(k, v)) for k, v in self.calls))


@njit(cache=True)
def noisy_shot(angle: float, speed: float, side: float, top: float, n_angle: float, n_speed: float,
               n_side: float, n_top: float, use_angle: bool, use_speed: bool, use_tip: bool,
               speed_absolute: bool = False) -> tuple:
    """The shot as played: the angle noise added, the speed scaled by ``1 + n_speed`` (``speed_absolute``:
    ``n_speed`` m/s added; never below 0), the tip noise added and the tip kept inside the miscue limit
    (:data:`TIP_LIMIT`). The noise values are drawn by the caller from its generator, in this order, only for the
    noises in use (:func:`draw_noise`)."""
    if use_angle:
        angle += n_angle
    if use_speed:
        if speed_absolute:
            speed = max(0.0, speed + n_speed)
        else:
            speed *= max(0.0, 1.0 + n_speed)
    if use_tip:
        side += n_side
        top += n_top
        r = math.hypot(side, top)
        if r > TIP_LIMIT:  # keep it a legal tip position (no miscue)
            side = side * TIP_LIMIT / r
            top = top * TIP_LIMIT / r
    return angle, speed, side, top


def draw_noise(rng: np.random.Generator, s: ShotSettings) -> tuple[float, float, float, float]:
    """One shot's noise ``(angle, speed, side, top)`` from ``rng``: a normal draw for each noise in use, in that
    order (none drawn for a noise that is off)."""
    n_angle = float(rng.normal(0.0, s.angle_noise)) if s.angle_noise > 0.0 else 0.0
    n_speed = float(rng.normal(0.0, s.speed_noise)) if s.speed_noise > 0.0 else 0.0
    n_side = float(rng.normal(0.0, s.tip_noise)) if s.tip_noise > 0.0 else 0.0
    n_top = float(rng.normal(0.0, s.tip_noise)) if s.tip_noise > 0.0 else 0.0
    return n_angle, n_speed, n_side, n_top


class PlayedShot(NamedTuple):
    """A shot played by :func:`play_shot`: its ``outcome``, its ``trajectory`` (when recorded, else None), the
    ``shot`` as played (noise included, the declarations kept) and the cue ball's ``start`` ``(x, y)``."""

    outcome: ShotOutcome
    trajectory: Any
    shot: CueShot
    start: tuple[float, float]


def play_shot(state: TableState, shot: CueShot, rng: np.random.Generator, record: bool = False) -> PlayedShot:
    """Play ``shot`` on ``state`` (its balls change in place): the cue ball placed (``shot.place``), the noise of
    ``state.settings`` drawn from ``rng``, the strike, the simulation until rest (or a cap), the balls stopped.
    Returns a :class:`PlayedShot`. Compiled twin (the native vector env's pool tables, on the exact solver):
    ``billiards_env.envs._game_kernels._play``."""
    s = state.settings
    b = state.balls
    if shot.place is not None:
        b.pos[0] = shot.place
    noise = draw_noise(rng, s) if s.noisy else (0.0, 0.0, 0.0, 0.0)
    angle, speed, side, top = noisy_shot(shot.angle, shot.speed, shot.side, shot.top, *noise,
                                         s.angle_noise > 0.0, s.speed_noise > 0.0, s.tip_noise > 0.0,
                                         s.speed_noise_absolute)
    start = (float(b.pos[0, 0]), float(b.pos[0, 1]))
    b.vel[0, 0] = speed * math.cos(angle)
    b.vel[0, 1] = speed * math.sin(angle)
    p = state.physics
    spin = p.has_spin
    if spin:  # the tip offsets' spin, and the squirt of the physics
        b.vel[0, 0], b.vel[0, 1], b.ang[0, 0], b.ang[0, 1], b.ang[0, 2] = strike_ball(
            angle, speed, side, top, float(b.radius[0]), float(b.mass[0]), p.squirt, p.cue_end_mass)
    sim = state.simulator
    trajectory = None
    if sim.solver == "exact" and not record:
        status, sim_time, n_events, pocket_of, ev_int = sim.run_in_place(b)
    else:
        res = sim.run(b, record=record, validate=False)
        fb = res.balls
        b.pos[...] = fb.pos
        b.on_table[...] = fb.on_table
        status, sim_time, n_events, pocket_of = res.status, res.time, res.n_events, res.pocket
        ev = res.events
        ev_int = np.stack([ev.kind, ev.ball, ev.other], axis=1) if len(ev) else np.zeros((0, 3), np.int64)
        trajectory = res.trajectory
    b.vel.fill(0.0)  # at rest (a capped shot is stopped where it is)
    if spin:
        b.ang.fill(0.0)
    state.changed()
    outcome = ShotOutcome.from_arrays(status, sim_time, n_events, pocket_of, ev_int)
    return PlayedShot(outcome, trajectory, CueShot(angle, speed, side, top, shot.place, shot.calls), start)


__all__ = ["CueShot", "PlayedShot", "noisy_shot", "draw_noise", "play_shot", "TIP_LIMIT"]
