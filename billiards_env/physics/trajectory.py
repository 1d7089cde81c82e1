"""Positions (and full states: velocities, spins, motion states) of every ball at any time of a simulated shot,
from the solver's log of state changes."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from numba import njit

from .codes import MS_POCKETED, MS_ROLLING, MS_STATIONARY, SPIN
from .motion import advance
from .spin_motion import sample_states as _sample_spin_states


@njit(cache=True)
def _sample_full(sc_t, sc_ball, sc_state, n_balls, times, law, a, k, v_min, interpolate):
    """Full states ``x y vx vy wx wy wz`` (T, N, 7), on-table flags and motion-state codes from a log of the
    rolling or drag law (exact: closed form; the spins are 0 and a moving ball counts as rolling) or from a
    step solver's snapshots of any law (linear interpolation; spins and codes when the log has them)."""
    n_t = times.shape[0]
    out = np.full((n_t, n_balls, 7), np.nan)
    on = np.zeros((n_t, n_balls), np.bool_)
    code = np.full((n_t, n_balls), -1, np.int64)
    last = np.full(n_balls, -1, np.int64)
    nxt = np.full(n_balls, -1, np.int64)
    has_spin = sc_state.shape[1] >= 9
    e = 0
    for q in range(n_t):
        tq = times[q]
        while e < sc_t.shape[0] and sc_t[e] <= tq:
            last[sc_ball[e]] = e
            e += 1
        for b in range(n_balls):
            r = last[b]
            if r < 0:
                continue
            on[q, b] = sc_state[r, 4] > 0.5
            st = np.empty(7)
            for c in range(4):
                st[c] = sc_state[r, c]
            for c in range(3):
                st[4 + c] = sc_state[r, 5 + c] if has_spin else 0.0
            if interpolate:
                m = nxt[b] if nxt[b] > r else r + 1
                while m < sc_t.shape[0] and sc_ball[m] != b:
                    m += 1
                nxt[b] = m
                if m < sc_t.shape[0] and sc_t[m] > sc_t[r] and on[q, b]:
                    w = (tq - sc_t[r]) / (sc_t[m] - sc_t[r])
                    for c in range(4):
                        st[c] += w * (sc_state[m, c] - st[c])
                    if has_spin:
                        for c in range(3):
                            st[4 + c] += w * (sc_state[m, 5 + c] - st[4 + c])
            else:
                st[0], st[1], st[2], st[3] = advance(st[0], st[1], st[2], st[3], tq - sc_t[r], law, a, k, v_min)
            if has_spin:
                code[q, b] = int(sc_state[r, 8])
            elif not on[q, b]:
                code[q, b] = MS_POCKETED
            else:
                code[q, b] = MS_ROLLING if (st[2] != 0.0 or st[3] != 0.0) else MS_STATIONARY
            for c in range(7):
                out[q, b, c] = st[c]
    return out, on, code


@dataclass(frozen=True)
class Trajectory:
    """A shot's motion. ``exact`` trajectories are evaluated in closed form from each ball's last event;
    ``step`` trajectories interpolate the solver's snapshots."""

    times: np.ndarray  #: time of each logged state (s), ascending
    ball: np.ndarray  #: ball row of each logged state
    #: ``x, y, vx, vy, on_table`` after each logged change, shape ``(M, 5)``; the spin model adds
    #: ``wx, wy, wz, motion_state`` (``(M, 9)``)
    state: np.ndarray
    n_balls: int
    duration: float
    law: int
    deceleration: float
    drag_k: float
    min_speed: float
    interpolate: bool = False
    radius: np.ndarray | None = None  #: ball radii (the spin model's closed form needs them)
    #: spin model: the sliding, rolling and spinning decelerations ``mu_slide g, mu_roll g, mu_spin g`` (m/s^2)
    spin_decel: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def _times(self, times: npt.ArrayLike, who: str) -> np.ndarray:
        t = np.clip(np.asarray(times, dtype=float).reshape(-1), 0.0, self.duration)
        if np.any(np.diff(t) < 0):
            raise ValueError(f"Trajectory.{who}: times must be ascending")
        return t

    def sample(self, times: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        """Positions ``(T, N, 2)`` and on-table flags ``(T, N)`` at ascending ``times`` (s)."""
        states, on, _ = self.sample_states(self._times(times, "sample"))
        return np.ascontiguousarray(states[:, :, :2]), on

    def sample_states(self, times: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Full states at ascending ``times`` (s): ``(T, N, 7)`` columns ``x, y, vx, vy, wx, wy, wz`` (angular
        velocities 0 outside the spin model), on-table flags ``(T, N)`` and motion-state codes ``(T, N)``
        (:data:`.codes.MOTION_STATES`; under ``rolling``/``drag`` a moving ball counts as rolling)."""
        t = self._times(times, "sample_states")
        if self.law == SPIN and not self.interpolate:
            f_slide, f_roll, f_spin = self.spin_decel
            return _sample_spin_states(self.times, self.ball, self.state, np.ascontiguousarray(self.radius, float),
                                       self.n_balls, t, f_slide, f_roll, f_spin)
        return _sample_full(self.times, self.ball, self.state, self.n_balls, t, self.law, self.deceleration,
                            self.drag_k, self.min_speed, self.interpolate)
