"""Where the cue ball comes to rest after a ghost-ball shot, in closed form (no simulation), with top or draw.

The position a shot leaves is what a pool player chooses a shot by; this module states it from the engine's own
formulas, for the ``candidates_position`` observation (:mod:`billiards_env.envs.position`):

1. **To the contact** (:func:`speed_spin_at`): the cue ball is struck along the line to the ghost point at ``speed``
   with tip offset ``top`` (fraction of R; :func:`.spin_collide.strike_spin`: ``R w = 2.5 top speed`` about the
   horizontal axis across the line). Under the spin model (:mod:`.spin_motion`) it slides while its slip
   ``u = v - R w`` is not 0: ``v`` changes at ``-mu_slide g sign(u)``, ``R w`` at ``+5/2 mu_slide g sign(u)``, so
   the slip closes at ``7/2 mu_slide g`` and the slide ends after ``2 |u0| / (7 mu_slide g)``; then it rolls
   (``R w = v``), slowing at ``mu_roll g``. This gives the speed ``v`` and the spin ``R w`` at the contact.
   Under the ``rolling`` and ``drag`` laws (no spin) the speed follows :mod:`.motion` and ``top`` does nothing.
2. **The collision** (:func:`.aim.collide_into`, the solvers' frictionless law): the cue ball keeps the tangent
   part of its velocity (and a ``(1 - e) / 2`` share of the normal part at equal masses); its spin passes the
   contact unchanged.
   Under the spin model the collision is the scene's own ball-ball law (:func:`.spin_collide.ball_hit`: throw and
   spin transfer when the physics has them).
3. **After the contact**, the lone cue ball piece by piece (:mod:`.spin_motion`, :func:`lone_ball_rest`): the slip
   ``u = V0 - R w`` (vectors in the table plane) is constant in direction while the ball slides, so its centre
   follows the parabola ``p = g + V0 t - mu_slide g u^ t^2 / 2`` for ``2 |u| / (7 mu_slide g)`` seconds, and it
   leaves the slide rolling with ``V1 = V0 - 2 u / 7`` (:func:`.spin_motion.roll_on`: the 2/7 law; a stun shot
   ``w = 0`` keeps ``5/7`` of ``V0``, a rolling ball follows through, a drawn ball comes back); it rolls in a
   straight line until it stops. A cushion met on the way (the parabola's or the line's first crossing of a
   cushion line) is the scene's cushion law (:func:`.cushion_models.wall_hit`), after which the ball slides
   again. A pocket is entered when the line (or one of the chords the slide's parabola is cut into) crosses its capture
   circle (a scratch).
   Under the ``rolling`` and ``drag`` laws the path is straight lines reflected off the cushions (normal
   component times the cushion restitution), as in :mod:`.cue_path`.

Not modelled: a second collision (with the object ball again or with another ball on the way). The tests compare
straight shots (stun, follow, draw), cut shots off a cushion and a scratch with the engine's own simulation.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .aim import bounce_off, collide_into, cushion_ahead, first_pocket_on_ray
from .codes import ROLLING, SPIN
from .cushion_models import wall_hit
from .spin_collide import wall_normal
from .walls import has_walls, normal_at, path_wall_time, walls_of
from .motion import launch_speed, speed_after_distance, stop_distance
from .plain import plain
from .spin_collide import ball_hit
from .spin_motion import slip, spin_decay_rate, wz_after

#: Cushion bounces followed along the cue ball's path after contact.
MAX_BOUNCES = 12
#: Chords a slide's parabola is cut into for the pocket test.
_SLIDE_CHORDS = 4
#: A slip below this (m/s) ends the slide (round-off).
_SLIP_TOL = 1e-9
#: The arrival speed (m/s) below which the object ball is taken not to drop (as :mod:`.cue_path`: just moving).
_ARRIVE = 1e-6


@njit(cache=True)
def speed_spin_at(speed: float, w0: float, d: float, law: int, a: float, k: float, v_min: float) -> tuple:
    """A ball launched at ``speed`` along a line with rolling-equivalent spin ``w0`` (``R w`` about the axis across
    the line, m/s; ``w0 = speed`` rolls, 0 is stun, negative is draw), after path length ``d``: ``(v, R w, reached,
    travelled)``. ``reached`` False: it stops after ``travelled < d`` (``v = R w = 0``). Under ``law`` SPIN, ``a``
    is ``mu_roll g`` and ``k`` ``mu_slide g`` (:attr:`.model.Physics.path_args`); under the other laws the spin is
    ignored (returned as ``v``)."""
    if law != SPIN:
        reach = stop_distance(speed, law, a, k, v_min)
        if reach <= d:
            return 0.0, 0.0, False, reach
        v = speed_after_distance(speed, d, law, a, k)
        return v, v, True, d
    u0 = speed - w0
    sigma = 1.0 if u0 > 0.0 else -1.0
    tau = 2.0 * abs(u0) / (7.0 * k) if k > 0.0 else 0.0
    d_slide = tau * (speed - 0.5 * sigma * k * tau)
    if d <= d_slide:
        if sigma > 0.0:
            t = (speed - math.sqrt(max(speed * speed - 2.0 * k * d, 0.0))) / k
        else:
            t = (math.sqrt(speed * speed + 2.0 * k * d) - speed) / k
        return speed - sigma * k * t, w0 + 2.5 * sigma * k * t, True, d
    v1 = speed - sigma * k * tau
    v2 = v1 * v1 - 2.0 * a * (d - d_slide)
    if v2 <= v_min * v_min:
        return 0.0, 0.0, False, d_slide + stop_distance(v1, plain(ROLLING), a, 0.0, v_min)
    v = math.sqrt(v2)
    return v, v, True, d


@njit(cache=True)
def _walk(x: float, y: float, ux: float, uy: float, length: float, speed: float, fixed: bool, radius: float,
          table_l: float, table_w: float, e_cushion: float, pocket_xy: np.ndarray, pocket_r: np.ndarray, a: float,
          v_min: float, max_bounces: int, segs: np.ndarray, tips: np.ndarray) -> tuple:
    """Walk a ball from ``(x, y)`` along ``(ux, uy)``: a fixed path ``length`` (``fixed``; the slide's chord) or
    rolling at ``speed`` until it stops (deceleration ``a``), reflected off the cushions (normal component times
    ``e_cushion``; rolling, the speed too). Returns ``(x, y, ux, uy, flip_x, flip_y, pocket)``: where it ends, its
    direction there, the factors the cushions put on each component of its velocity (sign and restitution), and
    the pocket whose capture circle it entered (-1: none; ``(x, y)`` is then the entry point). On a jaw table
    (``segs``, ``tips``) it reflects off the rails, jaw faces and tips, and the flip factors stay 1."""
    fx = 1.0
    fy = 1.0
    s = speed
    left = length
    for _ in range(max_bounces + 1):
        reach = left if fixed else stop_distance(s, plain(ROLLING), a, 0.0, v_min)
        t_wall, cushion = cushion_ahead(x, y, ux, uy, table_l, table_w, radius, segs, tips)
        pocket, best = first_pocket_on_ray(x, y, ux, uy, t_wall + 1e-9, pocket_xy, pocket_r)
        if pocket >= 0 and best < reach:
            return x + ux * best, y + uy * best, ux, uy, fx, fy, pocket
        if reach <= t_wall:
            return x + ux * reach, y + uy * reach, ux, uy, fx, fy, -1
        x += ux * t_wall
        y += uy * t_wall
        vx = ux
        vy = uy
        if segs.shape[0] > 0 or tips.shape[0] > 0:
            vx, vy = bounce_off(vx, vy, x, y, cushion, table_l, table_w, radius, e_cushion, segs, tips)
        elif cushion <= 1:
            vx = -e_cushion * vx
            fx = -e_cushion * fx
        else:
            vy = -e_cushion * vy
            fy = -e_cushion * fy
        f = math.hypot(vx, vy)
        if f < 1e-12:
            return x, y, ux, uy, fx, fy, -1
        if fixed:
            left -= t_wall
        else:
            s = speed_after_distance(s, t_wall, plain(ROLLING), a, 0.0) * f
        ux = vx / f
        uy = vy / f
    return x, y, ux, uy, fx, fy, -1


@njit(cache=True)
def _first_wall(x: float, y: float, vx: float, vy: float, ax: float, ay: float, tmax: float, radius: float,
                table_l: float, table_w: float) -> tuple:
    """The first time in ``(0, tmax]`` at which ``p + v t + a t^2 / 2`` reaches a cushion line (moving into it), and
    which cushion: ``(t, cushion)``, ``(inf, -1)`` if none."""
    best = math.inf
    cushion = -1
    for c in range(4):
        if c == 0:
            p0, v, acc, wall, sgn = x, vx, ax, radius, -1.0
        elif c == 1:
            p0, v, acc, wall, sgn = x, vx, ax, table_l - radius, 1.0
        elif c == 2:
            p0, v, acc, wall, sgn = y, vy, ay, radius, -1.0
        else:
            p0, v, acc, wall, sgn = y, vy, ay, table_w - radius, 1.0
        # solve 0.5 acc t^2 + v t + (p0 - wall) = 0 for the least t > 0 with the ball moving into the wall there
        c0 = p0 - wall
        if sgn * c0 >= 0.0:  # at or past the line already: a hit now if moving into it
            if sgn * v > 0.0:
                return 0.0, c
            continue
        r0 = math.inf
        r1 = math.inf
        if abs(acc) < 1e-15:
            if v != 0.0:
                r0 = -c0 / v
        else:
            disc = v * v - 2.0 * acc * c0
            if disc >= 0.0:
                sq = math.sqrt(disc)
                q = -0.5 * (v + (sq if v >= 0.0 else -sq))
                if q != 0.0:
                    r0 = q / (0.5 * acc)
                    r1 = c0 / q
        for t in (r0, r1):
            if 0.0 < t <= tmax and t < best and sgn * (v + acc * t) > 0.0:
                best = t
                cushion = c
    return best, cushion


@njit(cache=True)
def _pocket_on_segment(x: float, y: float, ex: float, ey: float, pocket_xy: np.ndarray, pocket_r: np.ndarray
                       ) -> tuple:
    """The first pocket whose capture circle the segment from ``(x, y)`` to ``(ex, ey)`` enters: ``(pocket, t)``
    with ``t`` the fraction along it; ``(-1, inf)`` if none."""
    dx = ex - x
    dy = ey - y
    d = math.hypot(dx, dy)
    if d < 1e-15:
        return -1, math.inf
    pocket, best = first_pocket_on_ray(x, y, dx / d, dy / d, d, pocket_xy, pocket_r)
    return pocket, best / d


@njit(cache=True)
def lone_ball_rest(x: float, y: float, vx: float, vy: float, wx: float, wy: float, wz: float, r: float, m: float,
                   table_l: float, table_w: float, pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray,
                   max_bounces: int) -> tuple:
    """Where a lone ball in this state comes to rest under the spin model (step 3 of the module docstring; ``params``:
    the simulator's kernel parameters, :func:`.kernel_io.kernel_params`): ``(x, y, pocket)``, ``pocket`` the
    pocket it enters (-1: none; ``(x, y)`` is then where it enters the capture circle)."""
    prm = params[0]
    f_slide = prm.mu_slide * prm.g
    f_roll = prm.mu_roll * prm.g
    alpha = spin_decay_rate(r, prm.mu_spin * prm.g)
    e_c = prm.e_cushion
    vel = np.empty((1, 2))
    ang = np.empty((1, 3))
    scratch = np.zeros(10)
    bounces = 0
    for _ in range(2 * max_bounces + 4):
        ux, uy = slip(vx, vy, wx, wy, r)
        su = math.hypot(ux, uy)
        s = math.hypot(vx, vy)
        if su > _SLIP_TOL and f_slide > 0.0:
            hx = ux / su
            hy = uy / su
            ax = -f_slide * hx
            ay = -f_slide * hy
            kw = 2.5 * f_slide / r
            dwx = -kw * hy
            dwy = kw * hx
            tau = 2.0 * su / (7.0 * f_slide)
        elif s > 1e-12 and f_roll > 0.0:
            ax = -f_roll * vx / s
            ay = -f_roll * vy / s
            wx = -vy / r
            wy = vx / r
            dwx = -ay / r
            dwy = ax / r
            tau = s / f_roll
        else:
            return x, y, -1
        if has_walls(prm):  # a jaw table: its rails, jaw faces and tips
            t_hit, cushion = path_wall_time(x, y, vx, vy, ax, ay, r, tau, 1e-12, 1e-12, math.inf, prm)
        else:
            t_hit, cushion = _first_wall(x, y, vx, vy, ax, ay, tau, r, table_l, table_w)
        t_end = min(t_hit, tau)
        nx = x + t_end * (vx + 0.5 * ax * t_end)
        ny = y + t_end * (vy + 0.5 * ay * t_end)
        sub = 1 if su <= _SLIP_TOL else _SLIDE_CHORDS  # the slide's parabola as chords, the roll's line as one
        px = x
        py = y
        for q in range(1, sub + 1):
            tq = t_end * q / sub
            qx = x + tq * (vx + 0.5 * ax * tq)
            qy = y + tq * (vy + 0.5 * ay * tq)
            pocket, frac = _pocket_on_segment(px, py, qx, qy, pocket_xy, pocket_r)
            if pocket >= 0:
                return px + frac * (qx - px), py + frac * (qy - py), pocket
            px = qx
            py = qy
        x = nx
        y = ny
        vx += ax * t_end
        vy += ay * t_end
        wx += dwx * t_end
        wy += dwy * t_end
        wz = wz_after(wz, t_end, alpha)
        if t_hit <= tau:
            if bounces >= max_bounces:
                return x, y, -1
            bounces += 1
            vel[0, 0] = vx
            vel[0, 1] = vy
            ang[0, 0] = wx
            ang[0, 1] = wy
            ang[0, 2] = wz
            if has_walls(prm):
                segs, tips = walls_of(prm)
                nx_, ny_ = normal_at(x, y, cushion, segs, tips)
                d = r if cushion < segs.shape[0] else r + tips[cushion - segs.shape[0], 2]
            else:
                nx_, ny_ = wall_normal(cushion)
                d = r
            wall_hit(vel, ang, plain(0), nx_, ny_, d, r, m, e_c, prm, scratch)
            vx, vy = vel[0, 0], vel[0, 1]
            wx, wy, wz = ang[0, 0], ang[0, 1], ang[0, 2]
        elif su <= _SLIP_TOL or f_slide <= 0.0:
            return x, y, -1  # the roll ended
    return x, y, -1


@njit(cache=True)
def cue_rest(cx: float, cy: float, gx: float, gy: float, obj_angle: float, d_obj: float, speed: float, top: float,
             rc: float, mc: float, mo: float, table_l: float, table_w: float, e_cushion: float, e_ball: float,
             pocket_xy: np.ndarray, pocket_r: np.ndarray, law: int, a: float, k: float, v_min: float,
             params: np.ndarray, max_bounces: int) -> tuple:
    """The ghost-ball shot from the cue ball at ``(cx, cy)`` through the ghost point ``(gx, gy)`` (the object ball
    sent along ``obj_angle``, ``d_obj`` from its pocket's capture circle), struck at ``speed`` with tip offset
    ``top`` (fraction of R): ``(x, y, pocket, pots)``: where the cue ball comes to rest (steps 1-3 of the module
    docstring), the pocket it runs into (-1: none; ``(x, y)`` is then where it enters the capture circle), and
    whether the object ball reaches its capture circle. ``law, a, k``: :attr:`.model.Physics.path_args`;
    ``params``: the simulator's kernel parameters (the spin model's collision and cushion laws). A shot that stops
    before the contact rests on its line."""
    dx = gx - cx
    dy = gy - cy
    d_cue = math.hypot(dx, dy)
    if d_cue < 1e-12:
        return cx, cy, -1, False
    ex = dx / d_cue
    ey = dy / d_cue
    w0 = 2.5 * top * speed if law == SPIN else speed
    v, w, reached, travelled = speed_spin_at(speed, w0, d_cue, law, a, k, v_min)
    if not reached:
        return cx + ex * travelled, cy + ey * travelled, -1, False
    ox = math.cos(obj_angle)
    oy = math.sin(obj_angle)
    if law == SPIN:
        vel = np.zeros((2, 2))
        ang = np.zeros((2, 3))
        vel[0, 0] = v * ex
        vel[0, 1] = v * ey
        ang[0, 0] = -w * ey / rc  # rolling-equivalent spin R w along the line: (wx, wy) = z^ x (w e) / R
        ang[0, 1] = w * ex / rc
        ball_hit(vel, ang, plain(0), plain(1), -ox, -oy, mc, mo, rc, rc, params[0], params[0].speed_floor,
                 plain(False))
        v_obj = math.hypot(vel[1, 0], vel[1, 1])
        pots = v_obj > 0.0 and v_obj >= launch_speed(d_obj, _ARRIVE, law, a, k)
        x, y, pocket = lone_ball_rest(gx, gy, vel[0, 0], vel[0, 1], ang[0, 0], ang[0, 1], ang[0, 2], rc, mc,
                                      table_l, table_w, pocket_xy, pocket_r, params, max_bounces)
        return x, y, pocket, pots
    vel = np.empty((2, 2))
    collide_into(vel, v * ex, v * ey, 0.0, 0.0, -ox, -oy, mc, mo, e_ball)
    v_obj = math.hypot(vel[1, 0], vel[1, 1])
    pots = v_obj > 0.0 and v_obj >= launch_speed(d_obj, _ARRIVE, law, a, k)
    s = math.hypot(vel[0, 0], vel[0, 1])
    if s <= max(v_min, 1e-12):
        return gx, gy, -1, pots
    if law != ROLLING:  # drag: walk the drag law's stop distance as a fixed path
        reach = stop_distance(s, law, a, k, v_min)
        x, y, _, _, _, _, pocket = _walk(gx, gy, vel[0, 0] / s, vel[0, 1] / s, reach, 0.0, True, rc, table_l,
                                         table_w, e_cushion, pocket_xy, pocket_r, a, v_min, max_bounces,
                                         *walls_of(params[0]))
        return x, y, pocket, pots
    x, y, _, _, _, _, pocket = _walk(gx, gy, vel[0, 0] / s, vel[0, 1] / s, 0.0, s, False, rc, table_l, table_w,
                                     e_cushion, pocket_xy, pocket_r, a, v_min, max_bounces, *walls_of(params[0]))
    return x, y, pocket, pots


__all__ = ["MAX_BOUNCES", "speed_spin_at", "lone_ball_rest", "cue_rest"]
