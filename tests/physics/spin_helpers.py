"""Helpers of the spin-model tests (imported as a plain module; the basename is unique on purpose)."""
from __future__ import annotations

import math

import numpy as np

from billiards_env.physics import G, Balls, Physics, Simulator, Table
from billiards_env.physics.codes import EV_COLLISION, EV_JAM
from billiards_env.physics.spin_motion import advance, piece_of, spin_decay_rate

R = 0.028575
M = 0.17
F_SLIDE = 0.2 * G
F_ROLL = 0.01 * G
F_SPIN = 0.0127 * G
ALPHA = 2.5 * F_SPIN / R  #: spin decay rate (rad/s^2)


def spin_physics(**kw) -> Physics:
    return Physics(friction="spin", **kw)


def long_table(length: float = 20.0, width: float = 1.27) -> Table:
    """A pocketless table long enough that straight shots never reach a cushion."""
    return Table(length=length, width=width).without_pockets()


def run(table, physics, balls, solver="exact", record=True, **kw):
    return Simulator(table, physics, solver=solver, **kw).run(balls, record=record)


def energy_of(m, r, st) -> float:
    """Kinetic energy of a ball from a state row ``x y vx vy wx wy wz``."""
    return 0.5 * m * (st[2] ** 2 + st[3] ** 2) + 0.2 * m * r * r * (st[4] ** 2 + st[5] ** 2 + st[6] ** 2)


def event_states(result, physics: Physics):
    """For every event of an exact spin result recorded with ``record=True``: ``(q, balls, before, after)`` with
    the involved balls' full states (``x y vx vy wx wy wz``) just before the event (their previous logged state
    carried forward by the closed form) and just after it (the logged state).

    The state log holds every ball's initial state, then after each event the rows of the balls it involves, in
    event order (asserted, so a change of layout fails loudly)."""
    tr = result.trajectory
    ev = result.events
    n = len(result.balls)
    radius = result.balls.radius
    times, who, state = tr.times, tr.ball, tr.state
    fs, fr, fp = physics.mu_slide * G, physics.mu_roll * G, physics.mu_spin * G
    n_rows = np.where(ev.kind == EV_COLLISION, 2, np.where(ev.kind == EV_JAM, ev.other, 1))
    assert len(times) == n + int(np.sum(n_rows))
    assert np.array_equal(who[:n], np.arange(n))
    cur_t = np.array(times[:n], dtype=float)
    cur = np.array(state[:n], dtype=float)
    p = n
    out = []
    for q in range(len(ev)):
        t = float(ev.time[q])
        k = int(n_rows[q])
        inv = [int(b) for b in who[p:p + k]]
        before, after = {}, {}
        for b in inv:
            row = cur[b]
            c = piece_of(int(row[8]), row[2], row[3], row[5], row[6], row[7], radius[b], fs, fr, fp)
            dt = min(t - cur_t[b], c[9])
            before[b] = np.array(advance(dt, row[0], row[1], c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8],
                                         spin_decay_rate(radius[b], fp)))
        for b in inv:
            assert who[p] == b and times[p] == t, (q, p, who[p], b, times[p], t)
            cur_t[b] = t
            cur[b] = state[p]
            r = state[p]
            after[b] = np.array([r[0], r[1], r[2], r[3], r[5], r[6], r[7]])
            p += 1
        out.append((q, inv, before, after))
    return out


def mirror_balls(balls: Balls, width: float) -> Balls:
    """The mirror image about the line ``y = width / 2``: ``y -> W - y``, ``vy -> -vy`` and, for the angular
    velocity (a pseudovector), ``(wx, wy, wz) -> (-wx, wy, -wz)``."""
    out = balls.copy()
    out.pos[:, 1] = width - out.pos[:, 1]
    out.vel[:, 1] *= -1.0
    out.ang[:, 0] *= -1.0
    out.ang[:, 2] *= -1.0
    return out


def sliding_position(x0, v0, u0, t, f=F_SLIDE):
    """Closed form of a sliding ball: ``r0 + v0 t - f t^2 u^ / 2``."""
    uh = np.asarray(u0, float) / np.linalg.norm(u0)
    return np.asarray(x0, float) + np.asarray(v0, float) * t - 0.5 * f * t * t * uh


def slide_time(u, f=F_SLIDE) -> float:
    return 2.0 * float(np.linalg.norm(u)) / (7.0 * f)


def speed(v) -> float:
    return math.hypot(float(v[0]), float(v[1]))
