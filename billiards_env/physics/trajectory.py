"""Positions of every ball at any time of a simulated shot, from the solver's log of state changes."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from .motion import advance


@njit(cache=True)
def _sample(sc_t, sc_ball, sc_state, n_balls, times, law, a, k, v_min, interpolate):
    n_t = times.shape[0]
    pos = np.empty((n_t, n_balls, 2))
    on = np.zeros((n_t, n_balls), np.bool_)
    last = np.full(n_balls, -1, np.int64)
    nxt = np.full(n_balls, -1, np.int64)
    e = 0
    for q in range(n_t):
        tq = times[q]
        while e < sc_t.shape[0] and sc_t[e] <= tq:
            last[sc_ball[e]] = e
            e += 1
        for b in range(n_balls):
            r = last[b]
            if r < 0:
                pos[q, b, 0] = np.nan
                pos[q, b, 1] = np.nan
                continue
            x = sc_state[r, 0]
            y = sc_state[r, 1]
            vx = sc_state[r, 2]
            vy = sc_state[r, 3]
            on[q, b] = sc_state[r, 4] > 0.5
            dt = tq - sc_t[r]
            if interpolate:
                # Snapshot log (step solver): linear interpolation to the ball's next snapshot.
                m = nxt[b] if nxt[b] > r else r + 1
                while m < sc_t.shape[0] and sc_ball[m] != b:
                    m += 1
                nxt[b] = m
                if m < sc_t.shape[0] and sc_t[m] > sc_t[r] and on[q, b]:
                    w = dt / (sc_t[m] - sc_t[r])
                    x += w * (sc_state[m, 0] - x)
                    y += w * (sc_state[m, 1] - y)
            else:
                x, y, _, _ = advance(x, y, vx, vy, dt, law, a, k, v_min)
            pos[q, b, 0] = x
            pos[q, b, 1] = y
    return pos, on


@dataclass(frozen=True)
class Trajectory:
    """A shot's motion. ``exact`` trajectories are evaluated in closed form from each ball's last event;
    ``step`` trajectories interpolate the solver's snapshots."""

    times: np.ndarray  #: time of each logged state (s), ascending
    ball: np.ndarray  #: ball row of each logged state
    state: np.ndarray  #: ``x, y, vx, vy, on_table`` after each logged change, shape ``(M, 5)``
    n_balls: int
    duration: float
    law: int
    deceleration: float
    drag_k: float
    min_speed: float
    interpolate: bool = False

    def sample(self, times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Positions ``(T, N, 2)`` and on-table flags ``(T, N)`` at ascending ``times`` (s)."""
        t = np.clip(np.asarray(times, dtype=float).reshape(-1), 0.0, self.duration)
        if np.any(np.diff(t) < 0):
            raise ValueError("Trajectory.sample: times must be ascending")
        return _sample(self.times, self.ball, self.state, self.n_balls, t, self.law, self.deceleration,
                       self.drag_k, self.min_speed, self.interpolate)
