"""The spin model's cushion laws (numba): which one a scene runs is ``physics.cushion`` (:mod:`.model`), applied by
:func:`cushion_hit` to a ball's velocity ``vel[i]`` and angular velocity ``ang[i]`` in place.

The cushion is the straight wall of the table's edge; the ball meets its nose at height ``h`` above the table
(``cushion_height``; at its equator when it is not given). With ``n`` the wall's inward normal, the contact normal
is three-dimensional when ``h != R``, as pooltool takes it: the unit vector from the nose line to the ball's centre,
``n3 = (R n, R - h) / sqrt(R^2 + (h - R)^2)``, tilted down when the nose is above the centre. Each law gives the
impulse at the contact point ``-R n3`` from the centre and then drops the vertical part of the ball's velocity (the
table holds the ball down; the spin the impulse's torque gives is kept in full).

- ``impulse``: the normal velocity along ``n3`` is reversed and scaled by ``e_c``; a friction impulse against the
  contact point's slip, Coulomb (``mu_c`` times the normal impulse) capped where the slip would stop (the 2/7 rule).
  At the equator this is :func:`.spin_collide.resolve_cushion_spin` (which runs then, unchanged); pooltool's
  ``impulse_frictional_inelastic``.
- ``stronge``: Stronge's compliant impact (:mod:`.stronge`) on the contact point's velocity, normal along ``n3`` and
  tangential along its slip; pooltool's ``StrongeCompliantLinear``.
- ``mathavan``: Mathavan, Jackson and Parkin (2010): the ball slides on the cushion nose and on the cloth at once
  during the impact; their equations integrated over the normal impulse in steps (the same steps as pooltool's
  ``Mathavan2010Linear``: ``max(m v_n / 1000, 0.001)`` N s, the crossing steps refined), compression until the
  normal speed is 0, restitution until the work done along the normal is ``e_c^2`` times the compression's. Its
  nose height enters as ``sin(theta) = (h - R) / R``. A hundred or more steps per impact: see docs/physics.md for
  what it costs.

No energy from nowhere: neither model is guaranteed to conserve or lose energy everywhere. In Stronge's the contact's
tangential spring can give back more than the normal restitution leaves when friction is high and restitution low
or the tangential spring soft (``cushion_friction`` above about 0.4 with ``cushion_restitution`` below 0.4, or above
about 0.3 with ``omega_ratio`` near 1; never at pooltool's 0.2, 0.85 and 1.8); Mathavan's integration lets friction
chatter about zero slip, and its impulse step is coarse for slow hits. A hit that would leave its ball with more
kinetic energy (translation and rotation) than it had is resolved by the ``impulse`` law instead, which never adds
energy (its friction is capped where the slip stops).

Every law returns the normal speed into the cushion before the hit (0 if the ball was not moving into it: then
nothing changes).
"""
from __future__ import annotations

import math

from .codes import CU_IMPULSE, CU_MATHAVAN, CU_STRONGE
from .kernel_logs import internal, leaf
from .spin_collide import resolve_wall_spin, wall_normal
from .stronge import BETA, compliant_impact

#: Mathavan's integration: the impulse step is ``max(m v_n / MATHAVAN_STEPS, MATHAVAN_MIN_STEP)`` (pooltool's).
MATHAVAN_STEPS = 1000
MATHAVAN_MIN_STEP = 0.001
#: Mathavan's integration: at most this many steps per phase (then the phase ends where it is: every shot ends).
MATHAVAN_MAX_STEPS = 10 * MATHAVAN_STEPS
#: A ``stronge`` or ``mathavan`` hit whose ball comes out with more kinetic energy than this fraction above what it
#: went in with is resolved by the ``impulse`` law instead.
ENERGY_GUARD = 1e-13


@internal
def contact_normal(nx, ny, d, r, h):
    """The contact normal ``n3 = (c nx, c ny, -s)`` of a ball of radius ``r`` on a cushion of horizontal normal
    ``(nx, ny)`` whose nose is at height ``h`` (< 0: at the ball's equator, ``c = 1, s = 0``) and ``d`` from the
    ball's centre across the table (``r`` for a straight cushion's nose line; ``r`` plus the tip's radius for a jaw
    tip's axis, as pooltool takes it): the unit vector from the nose to the centre. Returns ``(nx, ny, c, s)``."""
    if h < 0.0:
        return nx, ny, 1.0, 0.0
    rho = math.hypot(d, h - r)
    return nx, ny, d / rho, (h - r) / rho


@internal
def _apply_contact_impulse(vel, ang, i, r, n3x, n3y, n3z, jx, jy, jz):
    """Give ball ``i`` the impulse per unit mass ``J`` at its contact point ``-R n3``: ``dv = J`` (its vertical
    part dropped), ``dw = -(5 / 2R) n3 x J``."""
    vel[i, 0] += jx
    vel[i, 1] += jy
    k = -2.5 / r
    ang[i, 0] += k * (n3y * jz - n3z * jy)
    ang[i, 1] += k * (n3z * jx - n3x * jz)
    ang[i, 2] += k * (n3x * jy - n3y * jx)


@leaf
def _impulse_tilted(vel, ang, i, nx, ny, d, r, e_c, mu_c, h):
    """The ``impulse`` law with the nose at height ``h``, ``d`` across (the contact normal tilted)."""
    nx, ny, c, s = contact_normal(nx, ny, d, r, h)
    n3x, n3y, n3z = c * nx, c * ny, -s
    vx = vel[i, 0]
    vy = vel[i, 1]
    vn = vx * n3x + vy * n3y
    if not vn < 0.0:
        return 0.0
    wx = ang[i, 0]
    wy = ang[i, 1]
    wz = ang[i, 2]
    jn = -(1.0 + e_c) * vn  # normal impulse per unit mass
    # Slip of the contact point, u = v_t + w x (-R n3) (v_t: v less its part along n3).
    ux = vx - vn * n3x - r * (wy * n3z - wz * n3y)
    uy = vy - vn * n3y - r * (wz * n3x - wx * n3z)
    uz = -vn * n3z - r * (wx * n3y - wy * n3x)
    su = math.sqrt(ux * ux + uy * uy + uz * uz)
    jx = jn * n3x
    jy = jn * n3y
    vel[i, 0] += jx
    vel[i, 1] += jy
    if su > 0.0 and mu_c > 0.0:
        size = min(mu_c * jn, 2.0 * su / 7.0)
        _apply_contact_impulse(vel, ang, i, r, n3x, n3y, n3z, -size * ux / su, -size * uy / su, -size * uz / su)
    return -(vx * nx + vy * ny)


@leaf
def _stronge(vel, ang, i, nx, ny, d, r, e_c, mu_c, h, omega_ratio):
    """The ``stronge`` law (see the module docstring)."""
    nx, ny, c, s = contact_normal(nx, ny, d, r, h)
    n3x, n3y, n3z = c * nx, c * ny, -s
    vx = vel[i, 0]
    vy = vel[i, 1]
    vn = vx * n3x + vy * n3y  # the contact point's normal velocity (the spin adds none along n3)
    if not vn < 0.0:
        return 0.0
    wx = ang[i, 0]
    wy = ang[i, 1]
    wz = ang[i, 2]
    # Tangential velocity of the contact point, u = v + w x (-R n3) less its part along n3.
    ux = vx - vn * n3x - r * (wy * n3z - wz * n3y)
    uy = vy - vn * n3y - r * (wz * n3x - wx * n3z)
    uz = -vn * n3z - r * (wx * n3y - wy * n3x)
    su = math.sqrt(ux * ux + uy * uy + uz * uz)
    v_t, v_n = compliant_impact(-su, vn, mu_c, e_c, omega_ratio)
    dn = v_n - vn  # along n3 (beta_n = 1)
    vel[i, 0] += dn * n3x
    vel[i, 1] += dn * n3y
    if su > 0.0:
        # The tangent direction is -u / |u| (v_t <= 0 measures the slip along it): dv = (v_t - v_t0) / beta along it.
        k = (v_t + su) / BETA / su
        _apply_contact_impulse(vel, ang, i, r, n3x, n3y, n3z, -k * ux, -k * uy, -k * uz)
    return -(vx * nx + vy * ny)


@internal
def _mathavan_step(m, r, mu_s, mu_w, sin_t, cos_t, s, dp):
    """One impulse step ``dp`` (N s) of Mathavan's equations on ``s = [vx, vy, wx, wy, wz]`` (cushion frame: ``y``
    towards the cushion, ``x`` along it), in place."""
    vx, vy, wx, wy, wz = s[0], s[1], s[2], s[3], s[4]
    phi = math.atan2(-vy * sin_t + wx * r, vx + wy * r * sin_t - wz * r * cos_t)  # slip at the cushion
    phc = math.atan2(vy + wx * r, vx - wy * r)  # slip on the cloth
    sp, cp = math.sin(phi), math.cos(phi)
    spc, cpc = math.sin(phc), math.cos(phc)
    k = sin_t + mu_w * sp * cos_t
    s[0] = vx - (mu_w * cp + mu_s * cpc * k) * dp / m
    s[1] = vy - (cos_t - mu_w * sin_t * sp + mu_s * spc * k) * dp / m
    f = 5.0 / (2.0 * m * r)
    s[2] = wx - f * (mu_w * sp + mu_s * spc * k) * dp
    s[3] = wy - f * (mu_w * cp * sin_t - mu_s * cpc * k) * dp
    s[4] = wz + f * mu_w * cp * cos_t * dp


@leaf
def _mathavan_solve(m, r, h, e_c, mu_s, mu_w, s, scratch):
    """Mathavan's impact on ``s = [vx, vy, wx, wy, wz]`` (cushion frame, ``vy > 0`` into it), in place."""
    sin_t = (h - r) / r
    cos_t = math.sqrt(max(1.0 - sin_t * sin_t, 0.0))
    # Compression: until vy reaches 0, the last step refined by 8 halvings.
    dp = max(m * s[1] / MATHAVAN_STEPS, MATHAVAN_MIN_STEP)
    work = 0.0
    for _ in range(MATHAVAN_MAX_STEPS):
        if not s[1] > 0.0:
            break
        for q in range(5):
            scratch[q] = s[q]
        _mathavan_step(m, r, mu_s, mu_w, sin_t, cos_t, scratch, dp)
        if scratch[1] <= 0.0:
            step = dp
            for _ in range(8):
                step *= 0.5
                for q in range(5):
                    scratch[q] = s[q]
                _mathavan_step(m, r, mu_s, mu_w, sin_t, cos_t, scratch, step)
                if scratch[1] <= 0.0:
                    continue
                for q in range(5):
                    s[q] = scratch[q]
                work += step * abs(s[1]) * cos_t
            break
        for q in range(5):
            s[q] = scratch[q]
        work += dp * abs(s[1]) * cos_t
    # Restitution: until the work along the normal is e_c^2 times the compression's.
    target = e_c * e_c * work
    dp = max(target / MATHAVAN_STEPS, MATHAVAN_MIN_STEP)
    done = 0.0
    for _ in range(MATHAVAN_MAX_STEPS):
        if not done < target:
            break
        dw = dp * abs(s[1]) * cos_t
        if done + dw > target:
            last = (target - done) / (abs(s[1]) * cos_t)
            _mathavan_step(m, r, mu_s, mu_w, sin_t, cos_t, s, last)
            break
        _mathavan_step(m, r, mu_s, mu_w, sin_t, cos_t, s, dp)
        done += dp * abs(s[1]) * cos_t


@leaf
def _mathavan(vel, ang, i, nx, ny, r, m, e_c, mu_c, mu_s, h, scratch):
    """The ``mathavan`` law (see the module docstring); ``scratch``: 10 floats."""
    vx = vel[i, 0]
    vy = vel[i, 1]
    vin = -(vx * nx + vy * ny)
    if not vin > 0.0:
        return 0.0
    # Cushion frame: y' = -n (towards the cushion), x' = (y'_y, -y'_x) (so that x' x y' = z).
    yx, yy = -nx, -ny
    xx, xy = yy, -yx
    s = scratch[0:5]
    s[0] = vx * xx + vy * xy
    s[1] = vx * yx + vy * yy
    s[2] = ang[i, 0] * xx + ang[i, 1] * xy
    s[3] = ang[i, 0] * yx + ang[i, 1] * yy
    s[4] = ang[i, 2]
    _mathavan_solve(m, r, h if h >= 0.0 else r, e_c, mu_s, mu_c, s, scratch[5:10])
    vel[i, 0] = s[0] * xx + s[1] * yx
    vel[i, 1] = s[0] * xy + s[1] * yy
    ang[i, 0] = s[2] * xx + s[3] * yx
    ang[i, 1] = s[2] * xy + s[3] * yy
    ang[i, 2] = s[4]
    return vin


@internal
def cushion_hit(vel, ang, i, cushion, r, m, e_c, prm, scratch):
    """Ball ``i`` (radius ``r``, mass ``m``) hits cushion ``cushion`` (0 left, 1 right, 2 bottom, 3 top) of a
    capture table: :func:`wall_hit` with that cushion's normal."""
    nx, ny = wall_normal(cushion)
    return wall_hit(vel, ang, i, nx, ny, r, r, m, e_c, prm, scratch)


@leaf
def wall_hit(vel, ang, i, nx, ny, d, r, m, e_c, prm, scratch):
    """Ball ``i`` (radius ``r``, mass ``m``) hits a cushion whose horizontal contact normal (into the table, away
    from the cushion) is the unit ``(nx, ny)`` (a straight cushion, a rail, a jaw face, or a jaw tip's normal at the
    contact) ``d`` from the ball's centre across the table (``r``; a tip's: ``r`` plus its radius), under the cushion
    law of the parameter record ``prm`` (:mod:`.kernel_io`); ``scratch``: 10 floats. Returns the normal speed into the cushion before the hit (0: not moving into it, nothing changed)."""
    model = prm.cushion
    h = prm.cushion_height
    mu_c = prm.cushion_friction
    if model == CU_IMPULSE:
        if h < 0.0:
            return resolve_wall_spin(vel, ang, i, nx, ny, r, e_c, mu_c)
        return _impulse_tilted(vel, ang, i, nx, ny, d, r, e_c, mu_c, h)
    vx = vel[i, 0]
    vy = vel[i, 1]
    wx = ang[i, 0]
    wy = ang[i, 1]
    wz = ang[i, 2]
    if model == CU_STRONGE:
        speed = _stronge(vel, ang, i, nx, ny, d, r, e_c, mu_c, h, prm.omega_ratio)
    elif model == CU_MATHAVAN:
        speed = _mathavan(vel, ang, i, nx, ny, r, m, e_c, mu_c, prm.mu_slide, h, scratch)
    else:
        return 0.0
    # Never more energy out than in: else the impulse law (see the module docstring).
    if _energy(vel[i, 0], vel[i, 1], ang[i, 0], ang[i, 1], ang[i, 2], r) > \
            _energy(vx, vy, wx, wy, wz, r) * (1.0 + ENERGY_GUARD):
        vel[i, 0] = vx
        vel[i, 1] = vy
        ang[i, 0] = wx
        ang[i, 1] = wy
        ang[i, 2] = wz
        if h < 0.0:
            return resolve_wall_spin(vel, ang, i, nx, ny, r, e_c, mu_c)
        return _impulse_tilted(vel, ang, i, nx, ny, d, r, e_c, mu_c, h)
    return speed


@internal
def _energy(vx, vy, wx, wy, wz, r):
    """Kinetic energy per unit mass of a ball, ``|v|^2 / 2 + R^2 |w|^2 / 5`` (``I = 2/5 m R^2``)."""
    return 0.5 * (vx * vx + vy * vy) + 0.2 * r * r * (wx * wx + wy * wy + wz * wz)
