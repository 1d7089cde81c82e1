"""Stronge's compliant frictional impact of a sphere on a half-space, as pooltool's ``StrongeCompliant`` cushion
(compiled with numba).

The contact is a pair of springs, normal and tangential (Stronge, *Impact Mechanics*, 2000, ch. 8; Thornton et al.
2012): the normal spring compresses for ``t_c = pi / (2 w_n)`` and restores, with restitution ``e``, for ``e t_c``
more; the tangential spring sticks while the force it needs stays within Coulomb's ``mu`` times the normal force,
and slips otherwise. Everything depends on four numbers: ``r = v_t0 / v_n0`` (the incoming tangential to normal
speed of the contact point, ``v_t0 <= 0 < -v_n0``), ``mu``, ``e``, and the frequency ratio ``Omega = w_t / w_n``
in (1, 2) (pooltool's ``omega_ratio``; ``eta^2 = beta / Omega^2`` is the normal to tangential stiffness ratio and
``beta = beta_t / beta_n = 7/2`` the sphere's tangential to normal inverse inertia, ``1 + R^2 m / I``). Three
regimes:

- *gross slip* (``r > mu ((1 + e) beta - eta^2 / e)``): it slips throughout:
  ``v_t = v_t0 - mu beta (1 + e) v_n0``, in closed form;
- *slip, stick, slip* (between): it slips until the closed-form time it sticks (``acos``), then sticks until the
  tangential spring's force reaches the friction limit, a root of ``|spring force| = mu N`` (two sines of different
  frequencies: no closed form), then slips to the end;
- *stick, slip* (``r < mu eta^2``): it sticks from the start until that root, then slips.

The final normal speed is ``-e v_n0``. Times here are in units of ``1 / w_n`` (``w_n = 1``: the result does not
depend on the stiffness). The root is the first one after ``t_c`` (the stick ends the first time the spring's force
reaches the limit): found by scanning ``[t_c, t_f]`` in :data:`SCAN` pieces for the first change of sign and
narrowing that piece by the Illinois method to a few ulps (some 15 to 25 evaluations of two sines). pooltool finds it
with ``scipy.optimize.toms748`` on the whole of ``[t_c, t_f]``.
"""
from __future__ import annotations

import math

from .kernel_logs import internal
from .plain import plain

#: Tangential to normal inverse inertia of a sphere on a half-space: ``beta_t / beta_n = 1 + 5/2``.
BETA = 3.5
#: Pieces of ``[t_c, t_f]`` scanned for the first change of sign of the stick-end function.
SCAN = 8


@internal
def _phase_restitution(t, e):
    """The normal spring's phase in restitution: ``pi`` at the end ``t_f = (1 + e) pi / 2``."""
    return t / e + 0.5 * math.pi * (1.0 - 1.0 / e)


@internal
def _stick_end(t, mode, r, mu, e, eta2, omega, u_s, v_s, t_s, v_n0):
    """The function whose first root after ``t_c`` ends the stick: the tangential spring's force less the friction
    limit. ``mode`` 0: stuck from the start; 1: stuck since ``t_s`` with displacement ``u_s`` and speed ``v_s``."""
    if mode == 0:
        return abs(r * math.sin(omega * t)) - mu * eta2 * omega * math.sin(_phase_restitution(t, e))
    d = t - t_s
    return abs((u_s * math.cos(omega * d) - v_s / omega * math.sin(omega * d)) / (mu * v_n0)) \
        - eta2 * math.sin(_phase_restitution(t, e))


@internal
def _first_root(mode, r, mu, e, eta2, omega, u_s, v_s, t_s, v_n0):
    """When the stick ends: the first time after ``t_c`` and after the stick's start (``t_s``, mode 1) at which
    :func:`_stick_end` turns from negative to non-negative (``t_f`` if it does not). The stick starts where the
    function is 0 (mode 1: the spring's force is the friction limit when the contact point stops slipping), so a
    first stretch of non-negative values is skipped; if it never turns negative, the contact slips again at once.
    :data:`SCAN` pieces locate the first crossing, the Illinois method (false position that halves a stale end's
    value) narrows it to adjacent doubles."""
    t_c = 0.5 * math.pi
    t_f = (1.0 + e) * t_c
    start = max(t_c, t_s) if mode == 1 else t_c
    h = (t_f - start) / SCAN
    lo = start
    f_lo = _stick_end(lo, mode, r, mu, e, eta2, omega, u_s, v_s, t_s, v_n0)
    negative = f_lo < 0.0
    for k in range(1, SCAN + 1):
        hi = start + k * h if k < SCAN else t_f
        f_hi = _stick_end(hi, mode, r, mu, e, eta2, omega, u_s, v_s, t_s, v_n0)
        if not negative:
            negative = f_hi < 0.0
            lo = hi
            f_lo = f_hi
            continue
        if f_hi < 0.0:
            lo = hi
            f_lo = f_hi
            continue
        side = 0
        for _ in range(100):
            if f_hi == 0.0:
                return hi
            mid = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
            if not lo < mid < hi:
                mid = 0.5 * (lo + hi)
                if not lo < mid < hi:  # adjacent doubles
                    return hi
            f_mid = _stick_end(mid, mode, r, mu, e, eta2, omega, u_s, v_s, t_s, v_n0)
            if f_mid >= 0.0:
                hi = mid
                f_hi = f_mid
                if side == 1:
                    f_lo *= 0.5
                side = 1
            else:
                lo = mid
                f_lo = f_mid
                if side == -1:
                    f_hi *= 0.5
                side = -1
            if hi - lo <= 4e-16 * hi:
                return hi
        return hi
    return t_f if negative else start


@internal
def compliant_impact(v_t0, v_n0, mu, e, omega):
    """Final ``(v_t, v_n)`` of the contact point of a sphere hitting a compliant half-space with contact-point
    velocity ``v_t0 <= 0`` (tangential) and ``v_n0 < 0`` (normal, into the surface), friction ``mu``, restitution
    ``e`` (> 0) and frequency ratio ``omega`` in (1, 2) (see the module docstring)."""
    beta = BETA
    eta2 = beta / (omega * omega)
    r = v_t0 / v_n0
    v_n = -e * v_n0
    if mu <= 0.0:
        return v_t0, v_n
    if e <= 0.0 or r > mu * ((1.0 + e) * beta - eta2 / e):  # gross slip (always, in the limit e -> 0)
        return v_t0 - mu * beta * (1.0 + e) * v_n0, v_n
    t_c = 0.5 * math.pi
    if r < mu * eta2:  # stick, then slip
        t_slip = _first_root(plain(0), r, mu, e, eta2, omega, 0.0, 0.0, 0.0, v_n0)
        return v_t0 * math.cos(omega * t_slip) \
            + mu * v_n0 * beta * e * (1.0 + math.cos(_phase_restitution(t_slip, e))), v_n
    # slip, stick (at a closed-form time), slip
    if r <= mu * beta:
        x = min(max((r / mu - beta) / (eta2 - beta), -1.0), 1.0)
        t_stick = t_c * (2.0 / math.pi) * math.acos(x)
    else:
        x = min(max((r / mu - beta) / (eta2 / e - e * beta), -1.0), 1.0)
        t_stick = t_c * (2.0 / math.pi) * (math.acos(x) - 0.5 * math.pi * (1.0 - 1.0 / e)) * e
    if t_stick <= t_c:  # the spring's displacement and the contact's speed when it sticks, in closed form
        u_s = -mu * v_n0 * eta2 * math.sin(t_stick)
        v_s = v_t0 - mu * beta * v_n0 * (1.0 - math.cos(t_stick))
    else:
        ph = _phase_restitution(t_stick, e)
        u_s = -mu * v_n0 * eta2 * math.sin(ph)
        v_s = v_t0 - mu * beta * v_n0 * (1.0 - e * math.cos(ph))
    t_slip = _first_root(plain(1), r, mu, e, eta2, omega, u_s, v_s, t_stick, v_n0)
    d = t_slip - t_stick
    v_stick = omega * u_s * math.sin(omega * d) + v_s * math.cos(omega * d)
    return v_stick + beta * mu * v_n0 * e * (1.0 + math.cos(_phase_restitution(t_slip, e))), v_n
