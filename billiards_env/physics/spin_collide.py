"""Collision laws of the spin model (cue strike, cushion, ball-ball), shared by both solvers (numba).

Velocities ``vel (N, 2)`` and angular velocities ``ang (N, 3)`` are updated in place. ``I = 2/5 m R^2``.

- **Cue strike** (level cue): speed ``v0`` along ``d^``, tip offsets ``side`` (``a``) and ``top`` (``b``) in
  fractions of ``R``: ``wz = 5 a v0 / (2R)``, ``(wx, wy) = 5 b v0 / (2R) z^ x d^`` (``b = 2/5``: natural roll).
- **Cushion** (impulse at the equator, contact point ``-R n``, ``n`` the wall's normal into the table): the
  normal velocity is reversed and scaled by ``e_c``; a friction impulse (per unit mass) ``J`` against the
  contact point's slip ``s = v_t + w x (-R n)`` (three-dimensional: top and back spin move it vertically), of
  size ``min(mu_c J_n, 2|s|/7)`` (Coulomb, capped at the no-slip impulse), gives ``dv = J`` without its
  ``z`` part (the table holds the ball down) and ``dw = -(5 / 2R) n x J``. This is pooltool's
  ``impulse_frictional_inelastic`` cushion with the contact at the equator.
- **Ball-ball**: the normal impulse of :mod:`.collide` (restitution, masses, the same-instant floor), and,
  when ``mu_b > 0``, a friction impulse ``P`` against the contact points' relative slip ``s`` (3-D), of size
  ``min(mu_b J_n, (2/7) |s| / (1/m_i + 1/m_j))``: the Coulomb limit, capped where the contact points would
  stop slipping, were the balls free in ``z``. ``P`` changes both velocities (momentum is conserved; its
  ``z`` part is dropped) and both spins (its torque about each centre); this is the throw of a cut shot.
  Energy, translational plus rotational, never rises: a friction impulse against the slip and at most
  the no-slip one removes energy, and dropping a ``z`` velocity removes more.

Pressed contacts: friction accelerates a sliding ball along its slip, so it can keep pushing into a
cushion or into another ball after a collision has stopped the relative motion. Left to the collision laws
alone, that is an endless chain of ever smaller bounces (inelastic collapse). Two rules end it; neither
adds energy, and the ball-ball one conserves momentum:

- *Pressed on a cushion*: a ball that leaves a cushion slower than ``floor`` while friction drives it back
  into it stays on the cushion: its normal velocity and the spin that drives it into the cushion (about
  the horizontal axis along the cushion) are set to 0. It then slides or rolls along the cushion.
- *Pressed pair*: two touching balls that separate slower than ``floor`` while their accelerations close
  them (the squared distance's second derivative ``|v_rel|^2 + d . a_rel`` is negative) move on as one:
  both get the pair's centre-of-mass velocity and the mass-weighted mean surface velocity ``R (wx, wy)``;
  each keeps its ``wz``. (The rolling law's sticky contact, extended to spin.)
"""
from __future__ import annotations

import math

from numba import njit

from .codes import BB_ALCIATORE
from .spin_motion import classify, piece_of

#: Largest tip offset from the ball's centre, as a fraction of R: beyond it the cue miscues.
MAX_TIP_OFFSET = 0.5


@njit(cache=True)
def strike_spin(angle: float, speed: float, side: float, top: float, r: float) -> tuple:
    """Velocity and angular velocity of a ball struck at ``speed`` along ``angle`` with tip offsets ``side``
    (right english > 0) and ``top`` (follow > 0, draw < 0), fractions of ``r``: ``(vx, vy, wx, wy, wz)``."""
    dx = math.cos(angle)
    dy = math.sin(angle)
    k = 2.5 * speed / r
    return speed * dx, speed * dy, -k * top * dy, k * top * dx, k * side


@njit(cache=True)
def wall_normal(cushion: int) -> tuple:
    """Inward normal of cushion 0 left, 1 right, 2 bottom, 3 top."""
    if cushion == 0:
        return 1.0, 0.0
    if cushion == 1:
        return -1.0, 0.0
    if cushion == 2:
        return 0.0, 1.0
    return 0.0, -1.0


@njit(cache=True)
def resolve_cushion_spin(vel, ang, i: int, cushion: int, r: float, e_c: float, mu_c: float) -> float:
    """The cushion impulse on ball ``i`` (cushion 0 left, 1 right, 2 bottom, 3 top); returns the normal
    speed into the cushion before the hit (0 if the ball was not moving into it: then nothing changes)."""
    nx, ny = wall_normal(cushion)
    return resolve_wall_spin(vel, ang, i, nx, ny, r, e_c, mu_c)


@njit(cache=True)
def resolve_wall_spin(vel, ang, i: int, nx: float, ny: float, r: float, e_c: float, mu_c: float) -> float:
    """The cushion impulse at the equator on ball ``i`` against a cushion of unit horizontal normal ``(nx, ny)``
    (into the table); returns the normal speed into the cushion before the hit (0 if the ball was not moving into
    it: then nothing changes)."""
    vx = vel[i, 0]
    vy = vel[i, 1]
    vn = vx * nx + vy * ny
    if not vn < 0.0:
        return 0.0
    jn = -(1.0 + e_c) * vn  # normal impulse per unit mass
    wx = ang[i, 0]
    wy = ang[i, 1]
    wz = ang[i, 2]
    # Slip of the equator contact point, s = v_t + w x (-R n) (n has no z part).
    sx = vx - vn * nx + r * wz * ny
    sy = vy - vn * ny - r * wz * nx
    sz = -r * (wx * ny - wy * nx)
    ss = math.sqrt(sx * sx + sy * sy + sz * sz)
    vel[i, 0] = vx + jn * nx
    vel[i, 1] = vy + jn * ny
    if ss > 0.0 and mu_c > 0.0:
        size = min(mu_c * jn, 2.0 * ss / 7.0)
        jx = -size * sx / ss
        jy = -size * sy / ss
        jz = -size * sz / ss
        vel[i, 0] += jx
        vel[i, 1] += jy
        k = -2.5 / r  # dw = -(5 / 2R) n x J
        ang[i, 0] += k * ny * jz
        ang[i, 1] += k * (-nx * jz)
        ang[i, 2] += k * (nx * jy - ny * jx)
    return -vn


@njit(cache=True)
def settle_on_cushion(vel, ang, i: int, cushion: int) -> None:
    """The pressed-on-a-cushion rule (see the module docstring) for ball ``i`` touching ``cushion``: its
    normal velocity and its spin about the horizontal axis along the cushion become 0, so its slip has no
    normal part and friction no longer drives it into the cushion. The caller decides when it applies: the
    ball leaves slower than the speed floor while its acceleration points into the cushion."""
    if cushion < 2:
        vel[i, 0] = 0.0
        ang[i, 1] = 0.0
    else:
        vel[i, 1] = 0.0
        ang[i, 0] = 0.0


@njit(cache=True)
def settle_on_wall(vel, ang, i: int, nx: float, ny: float) -> None:
    """:func:`settle_on_cushion` on a cushion of unit horizontal normal ``(nx, ny)`` (a rail, jaw face or tip): the
    normal velocity and the spin about the horizontal axis along the cushion, ``(-ny, nx)``, become 0."""
    vn = vel[i, 0] * nx + vel[i, 1] * ny
    vel[i, 0] -= vn * nx
    vel[i, 1] -= vn * ny
    wt = -ang[i, 0] * ny + ang[i, 1] * nx
    ang[i, 0] += wt * ny
    ang[i, 1] -= wt * nx


@njit(cache=True)
def resolve_ball_ball_spin(vel, ang, i: int, j: int, nx: float, ny: float, mi: float, mj: float, ri: float,
                           rj: float, e: float, mu_b: float, speed_floor: float, clustered: bool) -> float:
    """Collide balls ``i`` and ``j`` (unit normal ``n`` from ``j`` to ``i``): the normal impulse with
    restitution ``e`` (separating at least at ``min(v_close, speed_floor)`` when ``clustered``, as in
    :func:`.collide.resolve_ball_ball`), then the friction impulse if ``mu_b > 0``.

    Returns the closing speed before the hit (0 if the pair was not closing: then nothing changes).
    """
    rvx = vel[i, 0] - vel[j, 0]
    rvy = vel[i, 1] - vel[j, 1]
    v_close = -(rvx * nx + rvy * ny)
    if not v_close > 0.0:
        return 0.0
    v_sep = e * v_close
    if clustered and v_sep < speed_floor:
        v_sep = min(v_close, speed_floor)
    jn = mi * mj / (mi + mj) * (v_close + v_sep)
    if mu_b > 0.0:
        # Relative slip of the contact points (before the impulses; the normal impulse does not change it):
        # s = (v_i - v_j)_t + w_i x (-R_i n) - w_j x (R_j n), with w x n = (-wz ny, wz nx, wx ny - wy nx).
        rvn = rvx * nx + rvy * ny
        wxi, wyi, wzi = ang[i, 0], ang[i, 1], ang[i, 2]
        wxj, wyj, wzj = ang[j, 0], ang[j, 1], ang[j, 2]
        sx = rvx - rvn * nx + (ri * wzi + rj * wzj) * ny
        sy = rvy - rvn * ny - (ri * wzi + rj * wzj) * nx
        sz = -(ri * (wxi * ny - wyi * nx) + rj * (wxj * ny - wyj * nx))
        ss = math.sqrt(sx * sx + sy * sy + sz * sz)
        if ss > 0.0:
            size = min(mu_b * jn, (2.0 / 7.0) * ss / (1.0 / mi + 1.0 / mj))
            _friction_impulse(vel, ang, i, j, nx, ny, mi, mj, ri, rj, sx, sy, sz, ss, size)
    vel[i, 0] += jn / mi * nx
    vel[i, 1] += jn / mi * ny
    vel[j, 0] -= jn / mj * nx
    vel[j, 1] -= jn / mj * ny
    return v_close


@njit(cache=True)
def _contact_slip(vel, ang, i, j, nx, ny, ri, rj):
    """Relative slip of the contact points of balls ``i`` and ``j`` (normal ``n`` from ``j`` to ``i``; the normal
    impulse does not change it): ``s = (v_i - v_j)_t + w_i x (-R_i n) - w_j x (R_j n)``, with
    ``w x n = (-wz ny, wz nx, wx ny - wy nx)``. Returns ``(sx, sy, sz, |s|)``."""
    rvx = vel[i, 0] - vel[j, 0]
    rvy = vel[i, 1] - vel[j, 1]
    rvn = rvx * nx + rvy * ny
    sx = rvx - rvn * nx + (ri * ang[i, 2] + rj * ang[j, 2]) * ny
    sy = rvy - rvn * ny - (ri * ang[i, 2] + rj * ang[j, 2]) * nx
    sz = -(ri * (ang[i, 0] * ny - ang[i, 1] * nx) + rj * (ang[j, 0] * ny - ang[j, 1] * nx))
    return sx, sy, sz, math.sqrt(sx * sx + sy * sy + sz * sz)


@njit(cache=True)
def _friction_impulse(vel, ang, i, j, nx, ny, mi, mj, ri, rj, sx, sy, sz, ss, size):
    """Apply the friction impulse ``P`` of magnitude ``size`` against the slip ``s`` (``|s| = ss > 0``) to balls
    ``i`` (``+P``) and ``j`` (``-P``): velocities without its vertical part, and spins by its torques."""
    px = -size * sx / ss
    py = -size * sy / ss
    pz = -size * sz / ss
    vel[i, 0] += px / mi
    vel[i, 1] += py / mi
    vel[j, 0] -= px / mj
    vel[j, 1] -= py / mj
    # Torques: dw_i = (-R_i n) x P / I_i, dw_j = (R_j n) x (-P) / I_j; both -(5 / 2 m R) n x P.
    cx = ny * pz
    cy = -nx * pz
    cz = nx * py - ny * px
    ki = -2.5 / (mi * ri)
    kj = -2.5 / (mj * rj)
    ang[i, 0] += ki * cx
    ang[i, 1] += ki * cy
    ang[i, 2] += ki * cz
    ang[j, 0] += kj * cx
    ang[j, 1] += kj * cy
    ang[j, 2] += kj * cz


@njit(cache=True)
def resolve_ball_ball_alciatore(vel, ang, i: int, j: int, nx: float, ny: float, mi: float, mj: float, ri: float,
                                rj: float, e: float, a: float, b: float, c: float, speed_floor: float,
                                clustered: bool) -> float:
    """The ``alciatore`` ball-ball law (pooltool's ``FrictionalInelastic`` with Alciatore's friction): the normal
    impulse of :func:`resolve_ball_ball_spin`, and a friction impulse against the contact points' slip ``s`` of
    size ``min(mu 2 m_r v_sep, (2/7) |s| / (1/m_i + 1/m_j))``, with ``mu = a + b exp(-c |s|)`` (TP A-14's fit),
    ``v_sep`` the separation speed and ``m_r`` the reduced mass: for equal balls ``mu v_sep`` per unit mass, as
    pooltool scales its Coulomb limit.

    Returns the closing speed before the hit (0 if the pair was not closing: then nothing changes).
    """
    rvx = vel[i, 0] - vel[j, 0]
    rvy = vel[i, 1] - vel[j, 1]
    v_close = -(rvx * nx + rvy * ny)
    if not v_close > 0.0:
        return 0.0
    v_sep = e * v_close
    if clustered and v_sep < speed_floor:
        v_sep = min(v_close, speed_floor)
    m_r = mi * mj / (mi + mj)
    jn = m_r * (v_close + v_sep)
    sx, sy, sz, ss = _contact_slip(vel, ang, i, j, nx, ny, ri, rj)
    if ss > 0.0:
        mu = a + b * math.exp(-c * ss)
        size = min(mu * 2.0 * m_r * v_sep, (2.0 / 7.0) * ss / (1.0 / mi + 1.0 / mj))
        _friction_impulse(vel, ang, i, j, nx, ny, mi, mj, ri, rj, sx, sy, sz, ss, size)
    vel[i, 0] += jn / mi * nx
    vel[i, 1] += jn / mi * ny
    vel[j, 0] -= jn / mj * nx
    vel[j, 1] -= jn / mj * ny
    return v_close


@njit(cache=True)
def ball_hit(vel, ang, i: int, j: int, nx: float, ny: float, mi: float, mj: float, ri: float, rj: float, prm,
             speed_floor: float, clustered: bool) -> float:
    """Collide balls ``i`` and ``j`` under the ball-ball law of the parameter record ``prm`` (:mod:`.kernel_io`):
    :func:`resolve_ball_ball_spin` or :func:`resolve_ball_ball_alciatore`. Returns the closing speed before the hit."""
    if prm.ball_ball == BB_ALCIATORE:
        return resolve_ball_ball_alciatore(vel, ang, i, j, nx, ny, mi, mj, ri, rj, prm.e_ball, prm.alciatore_a,
                                           prm.alciatore_b, prm.alciatore_c, speed_floor, clustered)
    return resolve_ball_ball_spin(vel, ang, i, j, nx, ny, mi, mj, ri, rj, prm.e_ball, prm.ball_friction, speed_floor,
                                  clustered)


@njit(cache=True)
def squirt_angle(side: float, ball_mass: float, end_mass: float, throttle: float) -> float:
    """The squirt of a level strike with side english ``side`` (fraction of R; > 0 right english): the angle (rad,
    counter-clockwise) between the cue ball's path and the cue, ``throttle`` times TP A-31's
    ``atan(5/2 a sqrt(1 - a^2) / (1 + m_ball / m_end + 5/2 (1 - a^2)))`` with ``a = side`` and ``m_end`` the
    cue tip's end mass. Right english squirts the ball to the left (positive), left english to the right."""
    if throttle == 0.0 or side == 0.0:
        return 0.0
    a2 = 1.0 - side * side
    return throttle * math.atan2(2.5 * side * math.sqrt(a2), 1.0 + ball_mass / end_mass + 2.5 * a2)


@njit(cache=True)
def strike_ball(angle: float, speed: float, side: float, top: float, r: float, m: float, squirt: float,
                end_mass: float) -> tuple:
    """Velocity and angular velocity of a ball (radius ``r``, mass ``m``) struck with a cue along ``angle`` at
    ``speed`` with tip offsets ``side`` and ``top`` (:func:`strike_spin`), the path turned by the squirt
    (:func:`squirt_angle`; its spin is the cue's: the squirt turns the path, not the spin axis, as pooltool's
    ``InstantaneousPoint``): ``(vx, vy, wx, wy, wz)``. Without squirt it is :func:`strike_spin`."""
    vx, vy, wx, wy, wz = strike_spin(angle, speed, side, top, r)
    if squirt != 0.0 and side != 0.0:
        path = angle + squirt_angle(side, m, end_mass, squirt)
        vx = speed * math.cos(path)
        vy = speed * math.sin(path)
    return vx, vy, wx, wy, wz


@njit(cache=True)
def acceleration(vx: float, vy: float, wx: float, wy: float, wz: float, r: float, f_slide: float, f_roll: float,
                 f_spin: float) -> tuple:
    """The acceleration of a free ball in this state (the start of its next piece)."""
    st = classify(vx, vy, wx, wy, wz, r)
    c = piece_of(st, vx, vy, wx, wy, wz, r, f_slide, f_roll, f_spin)
    return c[5], c[6]


@njit(cache=True)
def is_pressed_pair(vel, ang, i: int, j: int, dx: float, dy: float, ri: float, rj: float, f_slide: float,
                    f_roll: float, f_spin: float, speed_floor: float) -> bool:
    """Whether touching balls ``i``, ``j`` (centre offset ``d = p_i - p_j``) separate slower than
    ``speed_floor`` while their accelerations close them: ``|v_rel|^2 + d . a_rel < 0``."""
    dist = math.hypot(dx, dy)
    rvx = vel[i, 0] - vel[j, 0]
    rvy = vel[i, 1] - vel[j, 1]
    if dist == 0.0 or (rvx * dx + rvy * dy) >= speed_floor * dist:
        return False
    aix, aiy = acceleration(vel[i, 0], vel[i, 1], ang[i, 0], ang[i, 1], ang[i, 2], ri, f_slide, f_roll, f_spin)
    ajx, ajy = acceleration(vel[j, 0], vel[j, 1], ang[j, 0], ang[j, 1], ang[j, 2], rj, f_slide, f_roll, f_spin)
    closing = -((aix - ajx) * dx + (aiy - ajy) * dy)
    return closing > 0.0 and rvx * rvx + rvy * rvy < closing * (1.0 + 1e-9)


@njit(cache=True)
def merge_pair(vel, ang, i: int, j: int, mi: float, mj: float, ri: float, rj: float) -> None:
    """The pressed-pair rule: both balls get the centre-of-mass velocity and the mass-weighted mean surface
    velocity ``R (wx, wy)``; each keeps its ``wz``. Momentum is conserved; neither energy rises."""
    tot = mi + mj
    vx = (mi * vel[i, 0] + mj * vel[j, 0]) / tot
    vy = (mi * vel[i, 1] + mj * vel[j, 1]) / tot
    qx = (mi * ri * ang[i, 0] + mj * rj * ang[j, 0]) / tot
    qy = (mi * ri * ang[i, 1] + mj * rj * ang[j, 1]) / tot
    vel[i, 0] = vx
    vel[i, 1] = vy
    vel[j, 0] = vx
    vel[j, 1] = vy
    ang[i, 0] = qx / ri
    ang[i, 1] = qy / ri
    ang[j, 0] = qx / rj
    ang[j, 1] = qy / rj
