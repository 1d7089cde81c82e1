"""Playing snooker and three-cushion on plain physics objects, without an env: one shot applied to a table the way
an env applies it (the cue ball placed in the D, the shot simulated, the rules' call, the colours re-spotted, the
table put back after a miss), so players can play frames and games against each other in tests and benchmarks.

:func:`snooker_turn` and :func:`three_cushion_turn` update the balls in place and return the call and the next
state. They are the reference for what an env's step does with these games' calls.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from billiards_env.games.snooker_layout import d_geometry, nearest_point_in_d, spot_snooker_colours
from billiards_env.physics import Balls, Simulator
from billiards_env.physics.spin_collide import MAX_TIP_OFFSET
from billiards_env.rules.snooker import (VALUE_NAMES, Snooker, SnookerCall, SnookerShotInfo, SnookerState,
                                         snookered, summarize_snooker)
from billiards_env.rules.three_cushion import (ThreeCushion, ThreeCushionCall, ThreeCushionState, carom_rows,
                                               summarize_carom)

from .snooker import SnookerShot
from .three_cushion import CaromShot


@dataclass(frozen=True)
class SnookerTurn:
    """What :func:`snooker_turn` returns: the call, the next state, and whether the next striker is snookered
    (for the free ball and the miss rule)."""

    call: SnookerCall
    state: SnookerState
    snookered: bool


def _set(balls: Balls, other: Balls) -> None:
    balls.pos[...] = other.pos
    balls.vel[...] = other.vel
    balls.on_table[...] = other.on_table
    balls.ang[...] = other.ang


def noisy(angle: float, speed: float, side: float, top: float, rng: np.random.Generator | None,
          noise: tuple[float, float, float]) -> tuple[float, float, float, float]:
    """The shot as played under Gaussian shot noise ``(angle rad, speed relative, tip ball radii)`` (as the envs
    draw it: the tip kept inside the miscue limit, the speed at least 0)."""
    if rng is None or not any(noise):
        return angle, speed, side, top
    a_n, s_n, t_n = noise
    angle = angle + float(rng.normal(0.0, a_n)) if a_n else angle
    speed = max(speed * (1.0 + float(rng.normal(0.0, s_n))), 0.0) if s_n else speed
    if t_n:
        side, top = side + float(rng.normal(0.0, t_n)), top + float(rng.normal(0.0, t_n))
        r = float(np.hypot(side, top))
        lim = 0.98 * MAX_TIP_OFFSET
        if r > lim:
            side, top = side * lim / r, top * lim / r
    return angle, speed, side, top


def snooker_turn(sim: Simulator, balls: Balls, values: np.ndarray, state: SnookerState, shot: SnookerShot,
                 rules: Snooker | None = None, is_snookered: bool = False, rng: np.random.Generator | None = None,
                 noise: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> SnookerTurn:
    """Play ``shot`` from ``state`` on ``balls`` (updated in place): with the cue ball in hand it goes to the legal
    point of the D nearest ``shot.place`` (the D's middle if None); the shot is played with ``noise`` drawn from
    ``rng`` (:func:`noisy`); after the call the colours of ``call.respot`` go back on their spots and, with
    ``call.replace``, every ball goes back where it was. ``is_snookered``: the striker is snookered now
    (:func:`~billiards_env.rules.snooker.snookered`)."""
    rules = rules or Snooker()
    values = np.asarray(values)
    cue = int(np.flatnonzero(values == 0)[0])
    before = balls.copy()
    if state.ball_in_hand:
        cx, cy, r = d_geometry(sim.table)
        x, y = shot.place if shot.place is not None else (cx - 0.5 * r, cy)
        others = balls.on_table.copy()
        others[cue] = False
        balls.pos[cue] = nearest_point_in_d(x, y, balls.pos, others, balls.radius, cue, sim.table)
        balls.on_table[cue] = True
        balls.vel[cue] = 0.0
        balls.ang[cue] = 0.0
    spin = sim.physics.has_spin
    a, v, sd, tp = noisy(shot.angle, shot.speed, shot.side, shot.top, rng, noise if spin else (*noise[:2], 0.0))
    _set(balls, balls.strike(cue, a, v, **({"side": sd, "top": tp} if spin else {}), physics=sim.physics))
    _, _, _, pocket, events = sim.run_in_place(balls)
    info = SnookerShotInfo(nominated=shot.nominated if state.on == "colour" else None,
                           free_ball=shot.free_ball if rules.free_ball_available(state, is_snookered) else None,
                           snookered=is_snookered)
    call = rules.call(state, summarize_snooker(events, pocket, values), info)
    nxt = rules.next_state(state, call)
    if call.replace:
        _set(balls, before)
    else:
        balls.vel[...] = 0.0
        balls.ang[...] = 0.0
        rows = {VALUE_NAMES[int(v)]: r for r, v in enumerate(values) if v >= 2}
        if call.respot:
            spot_snooker_colours(balls.pos, balls.on_table, balls.radius, sim.table,
                                 {c: rows[c] for c in call.respot})
    snk = bool(not nxt.frame_over and not nxt.ball_in_hand and balls.on_table[cue]
               and snookered(balls.pos, balls.on_table, balls.radius, values, nxt.on, cue))
    return SnookerTurn(call, nxt, snk)


def three_cushion_turn(sim: Simulator, balls: Balls, state: ThreeCushionState, shot: CaromShot,
                       rules: ThreeCushion | None = None, rng: np.random.Generator | None = None,
                       noise: tuple[float, float, float] = (0.0, 0.0, 0.0)
                       ) -> tuple[ThreeCushionCall, ThreeCushionState]:
    """Play ``shot`` with the shooter's cue ball from ``state`` on ``balls`` (updated in place), with ``noise``
    drawn from ``rng`` (:func:`noisy`); returns the call and the next state. The balls are played as they lie (no
    re-spotting in three-cushion)."""
    rules = rules or ThreeCushion()
    rows = carom_rows(balls.ids, state.shooter)
    spin = sim.physics.has_spin
    a, v, sd, tp = noisy(shot.angle, shot.speed, shot.side, shot.top, rng, noise if spin else (*noise[:2], 0.0))
    _set(balls, balls.strike(rows[0], a, v, **({"side": sd, "top": tp} if spin else {}), physics=sim.physics))
    _, _, _, _, events = sim.run_in_place(balls)
    balls.vel[...] = 0.0
    balls.ang[...] = 0.0
    call = rules.call(state, summarize_carom(events, rows))
    return call, rules.next_state(state, call)


__all__ = ["SnookerTurn", "noisy", "snooker_turn", "three_cushion_turn"]
