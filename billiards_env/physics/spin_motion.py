"""Closed-form motion of one ball under the spin model (``"friction": "spin"``), compiled with numba.

The model is Leckie & Greenspan's (2006), as in pooltool, for a level cue. Frame: right-handed, ``z`` up;
angular velocity ``w = (wx, wy, wz)`` (rad/s) in the table frame. A ball rolling in ``+x`` has ``wy = +v/R``.

- Slip of the cloth contact point: ``u = v + R z^ x w = (vx - R wy, vy + R wx)``.
- Motion states (:data:`.codes.MOTION_STATES`): stationary, spinning (``v = 0``, ``wz != 0``), sliding
  (``u != 0``), rolling (``u = 0``, ``v != 0``), pocketed.
- Sliding: friction ``mu_slide m g`` against ``u^ = u0/|u0|``, constant during the slide:
  ``a = -mu_slide g u^`` and ``d(wx, wy)/dt = (5 mu_slide g / 2R) z^ x u^``; the slip shrinks along ``u^`` at
  ``7 mu_slide g / 2``, so the slide ends after ``2 |u0| / (7 mu_slide g)``.
- Rolling: ``a = -mu_roll g v^``, ``(wx, wy) = z^ x v / R``; it ends after ``|v0| / (mu_roll g)``.
- ``|wz|`` falls at ``5 mu_spin g / (2R)`` in every state until it is 0 (no event when it reaches 0 while the
  ball moves); a ball with ``v = 0`` and ``wz != 0`` spins until ``|wz0| / (5 mu_spin g / 2R)``.

So between two events every ball's centre follows ``p0 + v0 t + a t^2 / 2`` with a constant ``a`` (a straight
line or a parabola): pair contact is a quartic in time, a cushion a quadratic, a pocket circle a quartic.
A *piece* is the state at its start (``p, v, w``), its state code, ``a``, the rate of ``(wx, wy)`` and its
duration: :func:`classify` gives the code, :func:`piece_of` the rest, :func:`advance` evaluates it and
:func:`transition` names the state after its end.

The friction constants enter as decelerations: ``f_slide = mu_slide g``, ``f_roll = mu_roll g``,
``f_spin = mu_spin g`` (m/s^2).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .codes import MS_POCKETED, MS_ROLLING, MS_SLIDING, MS_SPINNING, MS_STATIONARY

#: Typed (non-literal) state codes for calls with a fixed state: a literal would make numba compile a second
#: specialisation of the callee.
_SLIDING = np.int64(MS_SLIDING)
_POCKETED = np.int64(MS_POCKETED)
#: A slip below this fraction of ``|v| + R |(wx, wy)|`` is round-off: the ball rolls (or spins, or rests).
#: (Putting such a ball on rolling, :func:`roll_on`, changes its momentum by at most 4/7 of this, relative.)
SLIP_TOL = 1e-13


@njit(cache=True)
def slip(vx: float, vy: float, wx: float, wy: float, r: float) -> tuple:
    """Velocity of the cloth contact point, ``u = v + R z^ x w``."""
    return vx - r * wy, vy + r * wx


@njit(cache=True)
def classify(vx: float, vy: float, wx: float, wy: float, wz: float, r: float) -> int:
    """The motion state of a ball on the table with this velocity and angular velocity."""
    ux, uy = slip(vx, vy, wx, wy, r)
    su = math.hypot(ux, uy)
    code = MS_STATIONARY
    if su > SLIP_TOL * (math.hypot(vx, vy) + r * math.hypot(wx, wy)):
        code = MS_SLIDING
    elif vx != 0.0 or vy != 0.0:
        code = MS_ROLLING
    elif wz != 0.0:
        code = MS_SPINNING
    return code


@njit(cache=True)
def spin_decay_rate(r: float, f_spin: float) -> float:
    """How fast ``|wz|`` falls (rad/s^2): ``5 mu_spin g / (2R)``."""
    return 2.5 * f_spin / r


@njit(cache=True)
def wz_after(wz: float, t: float, alpha: float) -> float:
    """``wz`` after ``t`` seconds of decay at ``alpha`` rad/s^2 (it stops at 0)."""
    if wz == 0.0 or t <= 0.0:
        return wz
    m = abs(wz) - alpha * t
    if m <= 0.0:
        return 0.0
    return m if wz > 0.0 else -m


@njit(cache=True)
def piece_of(state: int, vx: float, vy: float, wx: float, wy: float, wz: float, r: float, f_slide: float,
             f_roll: float, f_spin: float) -> tuple:
    """The motion piece of a ball in motion state ``state`` that starts from this velocity and spin.

    Returns ``(vx, vy, wx, wy, wz, ax, ay, dwx, dwy, duration)``: the start state with its round-off removed
    (a rolling ball's ``(wx, wy)`` set to ``z^ x v / R``, a spinning ball's ``v`` and ``(wx, wy)`` to 0), the
    acceleration, the rate of ``(wx, wy)``, and how long the piece lasts (``inf``: for ever, when the friction
    that would end it is 0).
    """
    inf = math.inf
    if state == MS_SLIDING:
        ux, uy = slip(vx, vy, wx, wy, r)
        su = math.hypot(ux, uy)
        hx = ux / su
        hy = uy / su
        k = 2.5 * f_slide / r
        duration = 2.0 * su / (7.0 * f_slide) if f_slide > 0.0 else inf
        return vx, vy, wx, wy, wz, -f_slide * hx, -f_slide * hy, -k * hy, k * hx, duration
    if state == MS_ROLLING:
        s = math.hypot(vx, vy)
        ax = -f_roll * vx / s
        ay = -f_roll * vy / s
        duration = s / f_roll if f_roll > 0.0 else inf
        return vx, vy, -vy / r, vx / r, wz, ax, ay, -ay / r, ax / r, duration
    if state == MS_SPINNING:
        alpha = spin_decay_rate(r, f_spin)
        duration = abs(wz) / alpha if alpha > 0.0 else inf
        return 0.0, 0.0, 0.0, 0.0, wz, 0.0, 0.0, 0.0, 0.0, duration
    return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, inf


@njit(cache=True)
def advance(t: float, x: float, y: float, vx: float, vy: float, wx: float, wy: float, wz: float, ax: float,
            ay: float, dwx: float, dwy: float, alpha: float) -> tuple:
    """The state ``(x, y, vx, vy, wx, wy, wz)`` ``t`` seconds into a piece (``t`` not past its end)."""
    return (x + t * (vx + 0.5 * ax * t), y + t * (vy + 0.5 * ay * t), vx + ax * t, vy + ay * t,
            wx + dwx * t, wy + dwy * t, wz_after(wz, t, alpha))


@njit(cache=True)
def roll_on(vx: float, vy: float, wx: float, wy: float, r: float) -> tuple:
    """The rolling state ``(vx, vy, wx, wy)`` a slip ``u`` ends in: the friction impulse that stops the slip
    changes ``v`` by ``-2u/7`` and ``R z^ x w`` by ``-5u/7`` (``I = 2/5 m R^2``), so ``(wx, wy) = z^ x v / R``
    after it. This is where a slide ends, whatever its duration (``v0 - mu g t_slide u^ = v0 - 2 u0 / 7``),
    and how a ball whose slip is round-off is put on rolling: the impulse never adds energy, as snapping
    ``w`` to ``v`` could."""
    ux, uy = slip(vx, vy, wx, wy, r)
    vx -= ux * (2.0 / 7.0)
    vy -= uy * (2.0 / 7.0)
    return vx, vy, -vy / r, vx / r


@njit(cache=True)
def slide_end(x: float, y: float, vx: float, vy: float, wx: float, wy: float, wz: float, r: float, f_slide: float,
              f_spin: float) -> tuple:
    """The state ``(x, y, vx, vy, wx, wy, wz)`` at the end of the slide that starts from this state, in closed
    form (the velocity by :func:`roll_on`, exact whatever the rounding of the end time)."""
    c = piece_of(_SLIDING, vx, vy, wx, wy, wz, r, f_slide, 0.0, f_spin)
    tau = c[9]
    nx, ny, nwx, nwy = roll_on(vx, vy, wx, wy, r)
    ux, uy = slip(vx, vy, wx, wy, r)
    if math.hypot(nx, ny) <= 1e-15 * (math.hypot(vx, vy) + math.hypot(ux, uy)):
        # v0 and 2 u0 / 7 cancel to round-off: the slide ends at rest (a perfect stop shot), not with a speed
        # (and an energy) made of rounding errors.
        nx = ny = nwx = nwy = 0.0
    return (x + tau * (vx + 0.5 * c[5] * tau), y + tau * (vy + 0.5 * c[6] * tau), nx, ny, nwx, nwy,
            wz_after(wz, tau, spin_decay_rate(r, f_spin)))


@njit(cache=True)
def transition(state: int, vx: float, vy: float, wz: float) -> int:
    """The motion state after the end of a ``state`` piece, from the ``v`` and ``wz`` :func:`advance` gives
    there. Sliding ends in rolling (the slip is 0 there), or, if ``v`` is exactly 0 then, like rolling ends: in
    spinning if ``wz != 0``, else at rest. Spinning ends at rest. :func:`piece_of` then makes the state exact.
    """
    nxt = MS_STATIONARY
    if state == MS_SLIDING and (vx != 0.0 or vy != 0.0):
        nxt = MS_ROLLING
    elif (state == MS_SLIDING or state == MS_ROLLING) and wz != 0.0:
        nxt = MS_SPINNING
    return nxt


@njit(cache=True)
def reach_of(t: float, speed: float, accel: float) -> float:
    """An upper bound of how far a ball on a piece moves in ``t`` seconds, from its speed and the magnitude of its
    acceleration: ``|v| t + |a| t^2 / 2``."""
    return t * (speed + 0.5 * accel * t)


@njit(cache=True)
def reach(t: float, vx: float, vy: float, ax: float, ay: float) -> float:
    """:func:`reach_of` from the velocity and acceleration vectors."""
    return reach_of(t, math.hypot(vx, vy), math.hypot(ax, ay))


@njit(cache=True)
def kinetic_energy(m: float, r: float, vx: float, vy: float, wx: float, wy: float, wz: float) -> float:
    """Translational plus rotational kinetic energy (J) of a ball (``I = 2/5 m R^2``)."""
    return 0.5 * m * (vx * vx + vy * vy) + 0.2 * m * r * r * (wx * wx + wy * wy + wz * wz)


@njit(cache=True)
def sample_states(sc_t, sc_ball, sc_state, radius, n_balls, times, f_slide, f_roll, f_spin):
    """Every ball's full state at ascending ``times`` from the exact spin solver's state log.

    ``sc_state`` rows: ``x y vx vy on_table wx wy wz motion_state`` after each logged change (every event,
    transitions included, so a ball is on one piece between two of its rows). Returns ``(T, N, 7)`` states
    ``x y vx vy wx wy wz``, ``(T, N)`` on-table flags and ``(T, N)`` motion-state codes (NaN and -1 before a
    ball's first row).
    """
    n_t = times.shape[0]
    out = np.full((n_t, n_balls, 7), np.nan)
    on = np.zeros((n_t, n_balls), np.bool_)
    code = np.full((n_t, n_balls), -1, np.int64)
    last = np.full(n_balls, -1, np.int64)
    e = 0
    for q in range(n_t):
        tq = times[q]
        while e < sc_t.shape[0] and sc_t[e] <= tq:
            last[sc_ball[e]] = e
            e += 1
        for b in range(n_balls):
            row = last[b]
            if row < 0:
                continue
            s = sc_state[row]
            on[q, b] = s[4] > 0.5
            st = int(s[8])
            code[q, b] = st
            r = radius[b]
            c = piece_of(st, s[2], s[3], s[5], s[6], s[7], r, f_slide, f_roll, f_spin)
            dt = min(tq - sc_t[row], c[9])
            x = advance(dt, s[0], s[1], c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8],
                        spin_decay_rate(r, f_spin))
            for k in range(7):
                out[q, b, k] = x[k]
    return out, on, code


@njit(cache=True)
def classify_all(vel, ang, radius, on_table):
    """Every ball's motion state code (pocketed for a ball off the table)."""
    n = vel.shape[0]
    out = np.full(n, MS_POCKETED, np.int64)
    for i in range(n):
        if on_table[i]:
            out[i] = classify(vel[i, 0], vel[i, 1], ang[i, 0], ang[i, 1], ang[i, 2], radius[i])
    return out


@njit(cache=True)
def carry_rows(sc_t, sc_state, radius_of_row, prev, rows, f_slide, f_roll, f_spin):
    """For each logged row ``rows[q]`` of the exact spin solver, the state ``x y vx vy wx wy wz`` its ball had
    just before it: its previous row ``prev[q]`` carried forward by the closed form (for the invariant checks:
    continuity, and energy and momentum before each event). ``radius_of_row[q]``: that ball's radius."""
    out = np.empty((rows.shape[0], 7))
    for q in range(rows.shape[0]):
        s = sc_state[prev[q]]
        r = radius_of_row[q]
        if s[4] <= 0.5:  # pocketed: it does not move
            c = piece_of(_POCKETED, 0.0, 0.0, 0.0, 0.0, 0.0, r, f_slide, f_roll, f_spin)
        else:
            c = piece_of(int(s[8]), s[2], s[3], s[5], s[6], s[7], r, f_slide, f_roll, f_spin)
        dt = min(sc_t[rows[q]] - sc_t[prev[q]], c[9])
        x = advance(dt, s[0], s[1], c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], spin_decay_rate(r, f_spin))
        for k in range(7):
            out[q, k] = x[k]
    return out
