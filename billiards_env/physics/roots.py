"""Robust real-root finding for the low-degree polynomials of event prediction (compiled with numba).

Event times are the first time a polynomial ``f(t)`` (distance squared minus contact distance squared)
falls from above zero to zero inside a window ``[0, T]``. Roots are isolated by the critical points of
``f`` (roots of ``f'``, found the same way one degree lower), so every monotone piece holds at most one
root and no crossing is missed; each bracketed root is then polished by Newton steps kept inside the
bracket (bisection when Newton leaves it). Coefficients are highest degree first: ``c[0] t^n + ...``.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

_MAX_ITER = 200


@njit(cache=True, inline="always")
def poly4(c4: float, c3: float, c2: float, c1: float, c0: float, t: float) -> float:
    return (((c4 * t + c3) * t + c2) * t + c1) * t + c0


@njit(cache=True)
def bracketed_root(c4: float, c3: float, c2: float, c1: float, c0: float, lo: float, hi: float) -> tuple:
    """Root of the quartic in ``[lo, hi]`` where ``f(lo)`` and ``f(hi)`` differ in sign (or one is zero).

    Returns ``(lo', hi')``: a bracket at most a few ulps wide. Callers pick the end they need
    (for a contact, ``lo'``: the last time before overlap).
    """
    flo = poly4(c4, c3, c2, c1, c0, lo)
    fhi = poly4(c4, c3, c2, c1, c0, hi)
    if flo == 0.0:
        return lo, lo
    if fhi == 0.0:
        return hi, hi
    x = 0.5 * (lo + hi)
    for _ in range(_MAX_ITER):
        fx = poly4(c4, c3, c2, c1, c0, x)
        if fx == 0.0:
            return x, x
        if (fx > 0.0) == (flo > 0.0):
            lo = x
            flo = fx
        else:
            hi = x
        if hi - lo <= 4e-16 * max(1.0, abs(lo)):
            break
        d = ((4.0 * c4 * x + 3.0 * c3) * x + 2.0 * c2) * x + c1
        xn = x - fx / d if d != 0.0 else lo - 1.0
        if not (lo < xn < hi) or abs(xn - x) > 0.5 * (hi - lo):
            xn = 0.5 * (lo + hi)
        if xn == x:
            xn = 0.5 * (lo + hi)
            if xn == x:
                break
        x = xn
    return lo, hi


@njit(cache=True)
def quadratic_roots_in(a: float, b: float, c: float, lo: float, hi: float, out: np.ndarray) -> int:
    """Real roots of ``a t^2 + b t + c`` strictly inside ``(lo, hi)``, ascending, into ``out``; returns the count."""
    n = 0
    if a == 0.0:
        if b != 0.0:
            r = -c / b
            if lo < r < hi:
                out[0] = r
                n = 1
        return n
    disc = b * b - 4.0 * a * c
    if disc < 0.0:
        return 0
    sq = math.sqrt(disc)
    q = -0.5 * (b + sq) if b >= 0.0 else -0.5 * (b - sq)
    if q == 0.0:
        r1 = 0.0
        r2 = 0.0
    else:
        r1 = q / a
        r2 = c / q
    if r1 > r2:
        r1, r2 = r2, r1
    if lo < r1 < hi:
        out[n] = r1
        n += 1
    if lo < r2 < hi and r2 != r1:
        out[n] = r2
        n += 1
    return n


@njit(cache=True)
def cubic_roots_in(a: float, b: float, c: float, d: float, lo: float, hi: float, out: np.ndarray) -> int:
    """Real roots of ``a t^3 + b t^2 + c t + d`` inside ``(lo, hi)``, ascending; isolated by the derivative."""
    if a == 0.0:
        return quadratic_roots_in(b, c, d, lo, hi, out)
    crit = np.empty(2)
    nc = quadratic_roots_in(3.0 * a, 2.0 * b, c, lo, hi, crit)
    n = 0
    left = lo
    f_left = ((a * left + b) * left + c) * left + d
    for k in range(nc + 1):
        right = crit[k] if k < nc else hi
        f_right = ((a * right + b) * right + c) * right + d
        if f_left == 0.0 and left > lo:
            out[n] = left
            n += 1
        elif (f_left < 0.0 < f_right) or (f_right < 0.0 < f_left):
            r_lo, r_hi = bracketed_root(0.0, a, b, c, d, left, right)
            out[n] = 0.5 * (r_lo + r_hi)
            n += 1
        left = right
        f_left = f_right
    return n


@njit(cache=True)
def first_entry(c4: float, c3: float, c2: float, c1: float, c0: float, t_max: float, closing_tol: float) -> float:
    """First time in ``[0, t_max]`` at which the quartic ``f`` enters ``f <= 0`` from above; ``inf`` if none.

    At ``t = 0`` an already-touching pair (``f(0) <= 0``) counts only if it is closing,
    ``f'(0) = c1 < -closing_tol``; otherwise the search starts where ``f`` is next positive.
    Returns the left end of the final bracket, so ``f`` at the returned time is not negative.
    """
    if not t_max > 0.0:
        return np.inf
    f0 = c0
    if f0 <= 0.0 and c1 < -closing_tol:
        return 0.0
    crit = np.empty(3)
    nc = cubic_roots_in(4.0 * c4, 3.0 * c3, 2.0 * c2, c1, 0.0, t_max, crit)
    left = 0.0
    f_left = f0
    for k in range(nc + 1):
        right = crit[k] if k < nc else t_max
        f_right = poly4(c4, c3, c2, c1, c0, right)
        if f_left > 0.0 and f_right <= 0.0:
            r_lo, _ = bracketed_root(c4, c3, c2, c1, c0, left, right)
            return r_lo
        left = right
        f_left = f_right
    return np.inf
