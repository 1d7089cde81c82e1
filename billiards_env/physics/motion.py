"""Closed-form motion of one ball between events, for both friction laws (compiled with numba).

A moving ball keeps its direction ``u`` between events; only its speed changes. Its path is
``p(t) = p0 + u * dist(t)``, with ``dist`` increasing:

- rolling: ``dist = s t - a t^2 / 2`` until ``t_stop = (s - v_min) / a`` (``a = mu g``);
- drag:    ``dist = s (1 - e^{-k t}) / k`` until the speed ``s e^{-k t}`` falls to ``v_min``.

``law``: :data:`.codes.ROLLING` or :data:`.codes.DRAG`.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .codes import DRAG, ROLLING, SPIN  # noqa: F401  (DRAG re-exported for callers of the motion law)


_SERIES = 1e-5  # below this k*t, the drag formulas use their series (exact to round-off, and safe for tiny k)


@njit(cache=True)
def _expm1_ratio(x: float) -> float:
    """``(1 - e^{-x}) / x`` for ``x >= 0``, accurate also for tiny (even subnormal) ``x``."""
    if x < _SERIES:
        return 1.0 - x * (0.5 - x / 6.0)
    return -math.expm1(-x) / x


@njit(cache=True)
def _log1p_ratio(x: float) -> float:
    """``-ln(1 - x) / x`` for ``0 <= x < 1``, accurate also for tiny ``x``."""
    if x < _SERIES:
        return 1.0 + x * (0.5 + x / 3.0)
    return -math.log1p(-x) / x


@njit(cache=True)
def time_to_stop(speed: float, law: int, a: float, k: float, v_min: float) -> float:
    """Seconds until a ball moving at ``speed`` stops (``inf`` if it never does)."""
    if speed <= v_min:
        return 0.0
    if law == ROLLING:
        if a > 0.0:
            return (speed - v_min) / a
        return math.inf
    if k > 0.0 and v_min > 0.0:
        return math.log(speed / v_min) / k
    return math.inf


@njit(cache=True)
def distance(speed: float, t: float, law: int, a: float, k: float) -> float:
    """Path length covered in ``t`` seconds (``t`` not past the stop)."""
    if law == ROLLING:
        return t * (speed - 0.5 * a * t)
    return speed * t * _expm1_ratio(k * t)


@njit(cache=True)
def speed_after(speed: float, t: float, law: int, a: float, k: float) -> float:
    """Speed after ``t`` seconds of motion (``t`` not past the stop)."""
    if law == ROLLING:
        return max(speed - a * t, 0.0)
    if k > 0.0:
        return speed * math.exp(-k * t)
    return speed


@njit(cache=True)
def time_for_distance(speed: float, d: float, law: int, a: float, k: float) -> float:
    """Seconds to cover path length ``d`` (``inf`` if the ball never gets that far)."""
    if d <= 0.0:
        return 0.0
    if law == ROLLING:
        disc = speed * speed - 2.0 * a * d
        if disc < 0.0:
            return math.inf
        return 2.0 * d / (speed + math.sqrt(disc))
    x = k * d / speed
    if x >= 1.0:
        return math.inf
    return d / speed * _log1p_ratio(x)


@njit(cache=True)
def drag_phi(t: float, k: float) -> float:
    """The drag law's common path parameter ``(1 - e^{-k t}) / k`` (``t`` when ``k = 0``)."""
    return t * _expm1_ratio(k * t)


@njit(cache=True)
def drag_time_for_phi(phi: float, k: float) -> float:
    """Inverse of :func:`drag_phi`."""
    x = k * phi
    if x >= 1.0:
        return math.inf
    return phi * _log1p_ratio(x)


# --- distance domain: how far, how fast, how hard (players, aiming) -------------------------------------------
# Under the spin model these describe a ball set moving WITHOUT spin (a stun strike, an object ball hit without
# throw): it slides at the deceleration ``k = mu_slide g`` until its speed is 5/7 of the start (the slip is gone
# after ``24/49 v0^2 / (2 k)`` metres), then rolls at ``a = mu_roll g``. See :meth:`.model.Physics.path_args`.
_ROLL_FRACTION2 = 25.0 / 49.0  #: (5/7)^2: the speed a stunned ball keeps when it starts rolling, squared
_SLIDE_FRACTION2 = 24.0 / 49.0  #: 1 - (5/7)^2


@njit(cache=True)
def stop_distance(speed: float, law: int, a: float, k: float, v_min: float) -> float:
    """Path length a ball moving at ``speed`` covers before it stops (``inf`` if it never does)."""
    if speed <= v_min:
        return 0.0
    if law == ROLLING:
        return (speed * speed - v_min * v_min) / (2.0 * a) if a > 0.0 else math.inf
    if law == SPIN:
        if a <= 0.0 or k <= 0.0:
            return math.inf
        return _SLIDE_FRACTION2 * speed * speed / (2.0 * k) + _ROLL_FRACTION2 * speed * speed / (2.0 * a)
    return (speed - v_min) / k if k > 0.0 else math.inf


@njit(cache=True)
def speed_after_distance(speed: float, d: float, law: int, a: float, k: float) -> float:
    """Speed left after covering path length ``d`` (0 if the ball stops first): rolling ``sqrt(s^2 - 2 a d)``,
    drag ``s - k d`` (under drag the speed falls linearly with distance), spin: sliding then rolling."""
    if law == ROLLING:
        return math.sqrt(max(speed * speed - 2.0 * a * d, 0.0))
    if law == SPIN:
        d_slide = _SLIDE_FRACTION2 * speed * speed / (2.0 * k) if k > 0.0 else 0.0
        if d <= d_slide:
            return math.sqrt(max(speed * speed - 2.0 * k * d, 0.0))
        v_roll2 = (speed * speed if k <= 0.0 else _ROLL_FRACTION2 * speed * speed)
        return math.sqrt(max(v_roll2 - 2.0 * a * (d - d_slide), 0.0))
    return max(speed - k * d, 0.0)


@njit(cache=True)
def launch_speed(d: float, v_end: float, law: int, a: float, k: float) -> float:
    """Speed a ball needs to cover path length ``d`` and still move at ``v_end`` (inverse of
    :func:`speed_after_distance`)."""
    d = max(d, 0.0)
    if law == ROLLING:
        return math.sqrt(v_end * v_end + 2.0 * a * d)
    if law == SPIN:
        if k <= 0.0:
            return math.sqrt(v_end * v_end + 2.0 * a * d)
        # Arriving while rolling: v_end^2 = 25/49 v0^2 - 2 a (d - 24/49 v0^2 / 2k).
        v0 = math.sqrt((v_end * v_end + 2.0 * a * d) / (_ROLL_FRACTION2 + _SLIDE_FRACTION2 * a / k))
        if _SLIDE_FRACTION2 * v0 * v0 / (2.0 * k) <= d:
            return v0
        return math.sqrt(v_end * v_end + 2.0 * k * d)  # still sliding on arrival
    return v_end + k * d


@njit(cache=True)
def advance(x: float, y: float, vx: float, vy: float, dt: float, law: int, a: float, k: float,
            v_min: float) -> tuple:
    """Position and velocity ``(x, y, vx, vy)`` of a ball ``dt >= 0`` seconds after the state ``x, y, vx, vy``,
    with no event in between (it stops at :func:`time_to_stop`)."""
    s = math.hypot(vx, vy)
    if s == 0.0 or dt <= 0.0:
        return x, y, vx, vy
    t_stop = time_to_stop(s, law, a, k, v_min)
    tt = min(dt, t_stop)
    d = distance(s, tt, law, a, k)
    ux = vx / s
    uy = vy / s
    if dt >= t_stop:
        return x + ux * d, y + uy * d, 0.0, 0.0
    sp = speed_after(s, tt, law, a, k)
    return x + ux * d, y + uy * d, ux * sp, uy * sp


@njit(cache=True)
def advance_many(x, y, vx, vy, dt, law: int, a: float, k: float, v_min: float) -> tuple:
    """:func:`advance` for arrays of states (element-wise): positions and velocities ``dt`` after each."""
    n = x.shape[0]
    ox = np.empty(n)
    oy = np.empty(n)
    ovx = np.empty(n)
    ovy = np.empty(n)
    for i in range(n):
        ox[i], oy[i], ovx[i], ovy[i] = advance(x[i], y[i], vx[i], vy[i], dt[i], law, a, k, v_min)
    return ox, oy, ovx, ovy
