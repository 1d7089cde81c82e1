"""Robust real-root finding for the low-degree polynomials of event prediction (compiled with numba).

Event times are the first time a polynomial ``f(t)`` (distance squared minus contact distance squared)
falls from above zero to zero inside a window ``[0, T]``. Roots are isolated by the critical points of
``f`` (roots of ``f'``, found the same way one degree lower), so every monotone piece holds at most one
root and no crossing is missed; each bracketed root is then polished by Newton steps kept inside the
bracket (bisection when Newton leaves it). Coefficients are highest degree first: ``c[0] t^n + ...``.
"""
from __future__ import annotations

import math

from numba import njit

_MAX_ITER = 200
#: Squared-distance excess (m^2) below which a touching pair has not really separated: a gap of ~1e-15 m.
_OPEN_TOL = 1e-16


@njit(cache=True)
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
def quadratic_roots_in(a: float, b: float, c: float, lo: float, hi: float) -> tuple:
    """Real roots of ``a t^2 + b t + c`` strictly inside ``(lo, hi)``: ``(count, r1, r2)`` ascending."""
    r1 = math.inf
    r2 = math.inf
    if a == 0.0:
        if b != 0.0:
            r = -c / b
            if lo < r < hi:
                return 1, r, r2
        return 0, r1, r2
    disc = b * b - 4.0 * a * c
    if disc < 0.0:
        return 0, r1, r2
    sq = math.sqrt(disc)
    q = -0.5 * (b + sq) if b >= 0.0 else -0.5 * (b - sq)
    if q == 0.0:
        x1 = 0.0
        x2 = 0.0
    else:
        x1 = q / a
        x2 = c / q
    if x1 > x2:
        x1, x2 = x2, x1
    n = 0
    if lo < x1 < hi:
        r1 = x1
        n = 1
    if lo < x2 < hi and x2 != x1:
        if n == 0:
            r1 = x2
        else:
            r2 = x2
        n += 1
    return n, r1, r2


@njit(cache=True)
def cubic_roots_in(a: float, b: float, c: float, d: float, lo: float, hi: float) -> tuple:
    """Real roots of ``a t^3 + b t^2 + c t + d`` inside ``(lo, hi)``: ``(count, r1, r2, r3)`` ascending,
    isolated by the derivative's roots (each monotone piece holds at most one)."""
    if a == 0.0:
        n, r1, r2 = quadratic_roots_in(b, c, d, lo, hi)
        return n, r1, r2, math.inf
    nc, c1, c2 = quadratic_roots_in(3.0 * a, 2.0 * b, c, lo, hi)
    ra = math.inf
    rb = math.inf
    rc = math.inf
    n = 0
    left = lo
    f_left = ((a * left + b) * left + c) * left + d
    for k in range(nc + 1):
        right = hi if k == nc else (c1 if k == 0 else c2)
        f_right = ((a * right + b) * right + c) * right + d
        root = math.inf
        if f_left == 0.0 and left > lo:
            root = left
        elif (f_left < 0.0 < f_right) or (f_right < 0.0 < f_left):
            r_lo, r_hi = bracketed_root(0.0, a, b, c, d, left, right)
            root = 0.5 * (r_lo + r_hi)
        if root < math.inf:
            if n == 0:
                ra = root
            elif n == 1:
                rb = root
            else:
                rc = root
            n += 1
        left = right
        f_left = f_right
    return n, ra, rb, rc


@njit(cache=True)
def first_entry(c4: float, c3: float, c2: float, c1: float, c0: float, t_max: float, closing_tol: float) -> float:
    """First time in ``[0, t_max]`` at which the quartic ``f`` enters ``f <= 0`` from above; ``inf`` if none.

    At ``t = 0`` an already-touching pair (``f(0) <= 0``) counts if it is closing (``f'(0) = c1 < -closing_tol``)
    or neither closing nor separating while ``f'' < 0`` (friction presses it together); otherwise the search
    starts where ``f`` is next positive.
    Returns the left end of the final bracket, so ``f`` at the returned time is not negative.
    """
    if not t_max > 0.0:
        return math.inf
    if c0 <= 0.0:
        if c1 < -closing_tol:
            return 0.0  # touching and closing
        if c2 < 0.0 and (c1 <= closing_tol or c0 + c1 * c1 / (-4.0 * c2) <= _OPEN_TOL):
            # Touching, and friction presses the pair together before a gap opens beyond round-off
            # (sticky contact): the collision law merges it now rather than let it overlap.
            return 0.0
    nc, k1, k2, k3 = cubic_roots_in(4.0 * c4, 3.0 * c3, 2.0 * c2, c1, 0.0, t_max)
    left = 0.0
    f_left = c0
    for k in range(nc + 1):
        if k == nc:
            right = t_max
        elif k == 0:
            right = k1
        elif k == 1:
            right = k2
        else:
            right = k3
        f_right = poly4(c4, c3, c2, c1, c0, right)
        if f_left > 0.0 and f_right <= 0.0:
            r_lo, _ = bracketed_root(c4, c3, c2, c1, c0, left, right)
            return r_lo
        left = right
        f_left = f_right
    return math.inf


@njit(cache=True)
def ray_circle_below(px: float, py: float, ux: float, uy: float, cx: float, cy: float, r: float,
                     limit: float) -> float:
    """Distance along the ray ``p + t u`` (``u`` a unit vector) to where it enters the circle of centre ``c``, radius
    ``r`` (:func:`.aim.ray_circle_entry`: the smaller root of ``t^2 + 2 b t + c``), or ``inf`` early when the entry
    is surely not nearer than ``limit``: the root is at least ``c / (-2 b)`` (a margin far above round-off), so
    beyond that bound no square root is taken."""
    dx = px - cx
    dy = py - cy
    c = dx * dx + dy * dy - r * r
    if c <= 0.0:
        return 0.0
    b = ux * dx + uy * dy
    if b >= 0.0:
        return math.inf
    if c >= -2.0 * b * limit * (1.0 + 1e-12):
        return math.inf
    disc = b * b - c
    if disc < 0.0:
        return math.inf
    return c / (-b + math.sqrt(disc))
