"""Where a ball sent off a collision goes: the first pocket on its path off the cushions, and the least speeds at
which a ghost-ball shot pots its object ball and at which the deflected cue ball follows into a pocket.

Closed form from the engine's own formulas, no simulation: the collision (:func:`.aim.collide_into`, the solvers'
law) per unit impact speed; the path as straight lines reflected off the cushions with the table's restitution (the
normal component scaled, the tangential kept: under the ``rolling`` and ``drag`` laws its shape does not depend on
the speed; under ``spin`` the cue ball slides and curves after contact and the straight path is the players' stun
approximation), up to ``max_bounces`` cushions, to the first pocket whose capture circle it enters
(:func:`.aim.ray_circle_entry`, :func:`.aim.ray_cushion_hit`); the motion law (:mod:`.motion`) for the speeds,
backwards along the path (each cushion divides the speed by its factor). A second collision (the cue ball coming
back into the object ball) is not modelled. The ``candidates_path`` observation
(:class:`billiards_env.envs.observations.CuePathFeatures`) states these thresholds.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .aim import bounce_off, collide_into, cushion_ahead, first_pocket_on_ray
from .motion import launch_speed, speed_after_distance, stop_distance

#: Cushion bounces followed along the cue ball's path (it stops long before them at the speeds the envs allow).
MAX_BOUNCES = 40
#: A threshold beyond every speed (no pocket on the path, or out of reach): reads as +1.
NEVER = math.inf


@njit(cache=True)
def path_pocket_speed(x: float, y: float, ux: float, uy: float, s_max: float, radius: float, length: float,
                      width: float, e_cushion: float, pocket_xy: np.ndarray, pocket_r: np.ndarray, law: int, a: float,
                      k: float, v_min: float, max_bounces: int, segs: np.ndarray, tips: np.ndarray) -> tuple:
    """The first pocket a lone ball leaving ``(x, y)`` along the unit direction ``(ux, uy)`` at speed ``s_max``
    would enter (straight lines reflected off the cushions: the normal component scaled by ``e_cushion``; up to
    ``max_bounces`` cushions), the least speed it needs at ``(x, y)`` to reach that pocket's capture circle, and the
    cushions it meets first: ``(pocket, speed, bounces)``; ``(-1, inf, -1)`` when it stops first. The path's shape
    does not depend on the speed, so at any speed below the one returned the ball stops on the table. ``segs``,
    ``tips``: a jaw table's walls (empty on a capture table)."""
    lengths = np.empty(max_bounces + 1)
    factors = np.empty(max_bounces + 1)  # speed after / before each bounce
    s = s_max
    for n in range(max_bounces + 1):
        if s <= v_min or s < 1e-9:
            return -1, math.inf, -1
        reach = stop_distance(s, law, a, k, v_min)
        t_wall, wall = cushion_ahead(x, y, ux, uy, length, width, radius, segs, tips)
        pocket, best = first_pocket_on_ray(x, y, ux, uy, t_wall + 1e-9, pocket_xy, pocket_r)
        if pocket >= 0 and best < reach:
            # backwards: the speed to arrive (just moving), then each segment and bounce before it
            need = launch_speed(best, v_min * 1.05 + 1e-6, law, a, k)
            for m in range(n - 1, -1, -1):
                need = launch_speed(lengths[m], need / factors[m], law, a, k)
            return pocket, need, n
        if reach <= t_wall:
            return -1, math.inf, -1
        s = speed_after_distance(s, t_wall, law, a, k)
        x = x + ux * t_wall
        y = y + uy * t_wall
        vx, vy = bounce_off(ux, uy, x, y, wall, length, width, radius, e_cushion, segs, tips)
        f = math.hypot(vx, vy)
        if f < 1e-9:
            return -1, math.inf, -1
        lengths[n] = t_wall
        factors[n] = f
        s *= f
        ux = vx / f
        uy = vy / f
    return -1, math.inf, -1


@njit(cache=True)
def shot_thresholds(cx: float, cy: float, gx: float, gy: float, obj_angle: float, d_obj: float, v_top: float,
                    rc: float, mc: float, mo: float, length: float, width: float, e_cushion: float, e_ball: float,
                    pocket_xy: np.ndarray, pocket_r: np.ndarray, law: int, a: float, k: float, v_min: float,
                    max_bounces: int, segs: np.ndarray, tips: np.ndarray) -> tuple:
    """For the ghost-ball shot from the cue ball at ``(cx, cy)`` through the ghost point ``(gx, gy)``, sending the
    object ball along ``obj_angle`` for ``d_obj`` to its capture circle: ``(pot, scratch, pocket, bounces)``: the
    least cue launch speed that gets the object ball there, the least at which the cue ball, deflected, reaches a
    pocket (inf: launched at ``v_top``, the top of the speed range, it stops first), that pocket and the cushions
    before it."""
    dx = gx - cx
    dy = gy - cy
    d_cue = math.hypot(dx, dy)
    if d_cue < 1e-12:
        return math.inf, 0.0, -1, 0
    ux = math.cos(obj_angle)
    uy = math.sin(obj_angle)
    vel = np.empty((2, 2))
    collide_into(vel, dx / d_cue, dy / d_cue, 0.0, 0.0, -ux, -uy, mc, mo, e_ball)  # per unit impact speed
    v_obj = math.hypot(vel[1, 0], vel[1, 1])
    v_cue = math.hypot(vel[0, 0], vel[0, 1])
    pot = math.inf
    if v_obj > 1e-9:
        pot = launch_speed(d_cue, launch_speed(d_obj, v_min * 1.05 + 1e-6, law, a, k) / v_obj, law, a, k)
    if v_cue < 1e-9:
        return pot, math.inf, -1, -1
    s_max = v_cue * speed_after_distance(v_top, d_cue, law, a, k)
    pocket, s, bounces = path_pocket_speed(gx, gy, vel[0, 0] / v_cue, vel[0, 1] / v_cue, s_max, rc, length, width,
                                           e_cushion, pocket_xy, pocket_r, law, a, k, v_min, max_bounces, segs,
                                           tips)
    if pocket < 0:
        return pot, math.inf, -1, -1
    return pot, launch_speed(d_cue, s / v_cue, law, a, k), pocket, bounces


@njit(cache=True)
def rows_thresholds(cx: float, cy: float, rows: np.ndarray, v_top: float, rc: float, mc: float, mo: float,
                    length: float, width: float, e_cushion: float, e_ball: float, pocket_xy: np.ndarray,
                    pocket_r: np.ndarray, law: int, a: float, k: float, v_min: float, max_bounces: int,
                    segs: np.ndarray, tips: np.ndarray) -> np.ndarray:
    """:func:`shot_thresholds` of many shots from the cue ball at ``(cx, cy)``: ``rows`` ``(N, 4)`` of ghost point
    ``x, y``, object-ball direction and distance to its capture circle (a NaN row: no shot); ``(N, 2)`` of ``pot``
    and ``scratch`` launch speeds (inf: never)."""
    out = np.full((rows.shape[0], 2), np.inf)
    for i in range(rows.shape[0]):
        if not math.isfinite(rows[i, 3]):
            continue
        r = shot_thresholds(cx, cy, rows[i, 0], rows[i, 1], rows[i, 2], rows[i, 3], v_top, rc, mc, mo, length,
                            width, e_cushion, e_ball, pocket_xy, pocket_r, law, a, k, v_min, max_bounces, segs, tips)
        out[i, 0] = r[0]
        out[i, 1] = r[1]
    return out


__all__ = ["MAX_BOUNCES", "NEVER", "path_pocket_speed", "shot_thresholds", "rows_thresholds"]
