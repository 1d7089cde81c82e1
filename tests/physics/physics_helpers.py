"""Scene builders and invariant checks shared by the physics tests (imported as a plain module).

The name is unique on purpose: ``tests/`` has no ``__init__.py`` files, so test-support modules in different
test folders must not share a basename.
"""
from __future__ import annotations

import math

import numpy as np

from billiards_env.physics import G, Balls, Physics, Table, simulate
from billiards_env.physics.codes import EV_COLLISION, EV_CUSHION, EV_JAM, EV_POCKET, EV_STOP  # noqa: F401

R = 0.028575  #: default ball radius (m)
M = 0.17  #: default ball mass (kg)
L = 2.54
W = 1.27
A_ROLL = 0.01 * G  #: default rolling deceleration (m/s^2)


def frictionless(e_ball: float = 1.0) -> Physics:
    """No friction at all (balls never stop; every run ends at the time cap)."""
    return Physics(friction="rolling", mu_roll=0.0, ball_restitution=e_ball)


def rolling(mu: float = 0.01, e_ball: float = 0.95, min_speed: float = 0.0) -> Physics:
    return Physics(friction="rolling", mu_roll=mu, ball_restitution=e_ball, min_speed=min_speed)


def drag(k: float, v_min: float, e_ball: float = 0.95) -> Physics:
    return Physics(friction="drag", drag_k=k, min_speed=v_min, ball_restitution=e_ball)


def carom(e_c: float = 0.85, length: float = L, width: float = W) -> Table:
    """A pocketless table."""
    return Table(length=length, width=width, cushion_restitution=e_c).without_pockets()


def pool(e_c: float = 0.85) -> Table:
    """The default table with its six pockets."""
    return Table(cushion_restitution=e_c)


def balls(positions, velocities=None, mass=M, radius=R, ids=None) -> Balls:
    return Balls.from_positions(positions, ids=ids, velocities=velocities, mass=mass, radius=radius)


def one_ball(x, y, angle, speed) -> Balls:
    return balls([[x, y]]).strike("cue", angle, speed)


def polar(angle: float, speed: float) -> list[float]:
    return [speed * math.cos(angle), speed * math.sin(angle)]


def events_of(result, kind: int) -> np.ndarray:
    """Indices (into the event log) of the events of one kind."""
    return np.flatnonzero(result.events.kind == kind)


def collisions(result) -> list[tuple[float, int, int]]:
    ev = result.events
    return [(float(ev.time[q]), int(ev.ball[q]), int(ev.other[q])) for q in events_of(result, EV_COLLISION)]


def rolling_time_for_distance(v: float, d: float, a: float) -> float:
    """Time for a ball starting at speed ``v`` under constant deceleration ``a`` to cover ``d`` (closed form)."""
    return (v - math.sqrt(v * v - 2.0 * a * d)) / a


def assert_valid_final_state(result, table: Table, overlap_tol: float = 1e-9) -> None:
    """The spec's invariants: finite numbers, every ball on the table inside its bounds, no overlaps."""
    b = result.balls
    assert np.all(np.isfinite(b.pos)), b.pos
    assert np.all(np.isfinite(b.vel)), b.vel
    assert math.isfinite(result.time)
    on = b.on_table
    r = b.radius
    eps = 1e-12
    assert np.all(b.pos[on, 0] >= r[on] - eps), b.pos[on]
    assert np.all(b.pos[on, 0] <= table.length - r[on] + eps), b.pos[on]
    assert np.all(b.pos[on, 1] >= r[on] - eps), b.pos[on]
    assert np.all(b.pos[on, 1] <= table.width - r[on] + eps), b.pos[on]
    assert max_overlap(b.pos[on], r[on]) <= overlap_tol


def max_overlap(pos: np.ndarray, radius: np.ndarray) -> float:
    """Largest pairwise overlap ``r_i + r_j - |p_i - p_j|`` (0 if none)."""
    if len(pos) < 2:
        return 0.0
    d = np.sqrt(((pos[:, None, :] - pos[None, :, :]) ** 2).sum(-1))
    need = radius[:, None] + radius[None, :]
    ov = need - d
    np.fill_diagonal(ov, -np.inf)
    return float(max(ov.max(), 0.0))


def run(table, physics, b, solver="exact", **kw):
    return simulate(table, physics, b, solver, **kw)


def speed_after(s: float, dt: float, physics: Physics) -> float:
    """Closed-form speed after ``dt`` s of free motion from speed ``s`` (either law, ``min_speed`` stop)."""
    if physics.friction == "rolling":
        s2 = s - physics.deceleration * dt
    else:
        s2 = s * math.exp(-physics.drag_rate * dt)
    return s2 if s2 > physics.min_speed else 0.0


def collision_velocities(result, physics: Physics):
    """For every ball-ball collision in an ``exact`` result recorded with ``record=True``: the event index, the
    two balls, and their velocities just before and just after the hit.

    Walks the trajectory's state log (one row per ball per state change: the initial state of every ball, then
    after each event the rows of the balls involved, in event order); the velocity just before an event is the
    ball's previous logged state carried forward by the closed-form friction law. Asserts the log has that
    layout, so a change of format fails loudly instead of silently pairing the wrong rows.
    """
    tr = result.trajectory
    ev = result.events
    n = len(result.balls)
    times, who, state = tr.times, tr.ball, tr.state
    n_rows = np.where(ev.kind == EV_COLLISION, 2, np.where(ev.kind == EV_JAM, ev.other, 1))
    assert len(times) == n + int(np.sum(n_rows))
    cur_t = np.array(times[:n], dtype=float)
    cur = np.array(state[:n], dtype=float)
    assert np.array_equal(who[:n], np.arange(n))
    p = n
    out = []
    for q in range(len(ev)):
        t = float(ev.time[q])
        if ev.kind[q] == EV_JAM:  # a jammed cluster: its rows name its members
            inv = [int(b) for b in who[p:p + int(ev.other[q])]]
        else:
            inv = [int(ev.ball[q])] + ([int(ev.other[q])] if ev.kind[q] == EV_COLLISION else [])
        before = {}
        for b in inv:
            v = cur[b, 2:4]
            s = math.hypot(*v)
            s2 = speed_after(s, t - cur_t[b], physics) if s > 0 else 0.0
            before[b] = v * (s2 / s) if s > 0 else np.zeros(2)
        after = {}
        for b in inv:
            assert who[p] == b and times[p] == t, (q, p, who[p], b, times[p], t)
            cur_t[b] = t
            cur[b] = state[p]
            after[b] = np.array(state[p, 2:4])
            p += 1
        if ev.kind[q] == EV_COLLISION:
            i, j = inv
            out.append((q, i, j, before[i], before[j], after[i], after[j]))
    return out
