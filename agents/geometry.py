"""Shot geometry on the physics engine's model, for the baseline players (no Gymnasium here).

Ghost-ball aiming: to send object ball ``O`` in direction ``u`` the cue ball must touch it from the ghost-ball
position ``G = O - (r_cue + r_obj) u``. The cut angle is the angle between the cue's path ``C -> G`` and ``u``.
Pockets are capture circles (:class:`billiards_env.physics.Table`): the direction ``u`` is taken from the middle
of the window of directions along which the object ball enters the capture circle before touching a cushion, so
corner and side pockets approached at a shallow angle are aimed correctly (or rejected when the window is empty).

All angles are radians (0 = +x, counter-clockwise), speeds m/s, distances m.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from billiards_env.physics import Balls, Physics, Table

#: Samples across a pocket's angular size when computing its entry window.
WINDOW_SAMPLES = 41
#: Default largest cut angle the aimer accepts (beyond it the shot is too thin to be reliable).
MAX_CUT = math.radians(80.0)


@dataclass(frozen=True)
class ShotCandidate:
    """One ghost-ball shot: strike the cue at ``angle``/``speed`` to send ball ``target`` into ``pocket``."""

    target: int  #: row of the object ball
    pocket: int  #: pocket index
    angle: float  #: cue direction
    speed: float  #: cue speed (clipped to the allowed range)
    speed_needed: float  #: cue speed the object ball needs to reach the pocket with the margin (unclipped)
    obj_angle: float  #: direction the object ball must take
    cut: float  #: cut angle
    d_cue: float  #: cue ball travel to the ghost position
    d_obj: float  #: object ball travel to the pocket's capture circle
    window: float  #: half-width of the object ball's direction window into the pocket
    tolerance: float  #: estimated cue-angle error that still pots (rad): the difficulty measure
    clear: bool  #: both paths free of other balls
    reachable: bool  #: speed needed within the allowed range
    scratch_risk: bool  #: the cue ball's deflected straight path runs into a pocket
    score: float  #: ease score (higher is easier); see :func:`ghost_ball_shots`


def speed_to_travel(d: float, v_end: float, physics: Physics) -> float:
    """Launch speed for a ball to roll ``d`` metres and still move at ``v_end`` (both friction laws)."""
    v_end = max(v_end, physics.min_speed * 1.05 + 1e-6)
    if physics.friction == "rolling":
        return math.sqrt(v_end * v_end + 2.0 * physics.deceleration * max(d, 0.0))
    return v_end + physics.drag_rate * max(d, 0.0)  # drag: dv/dx = -k


def travel_distance(speed: float, physics: Physics) -> float:
    """How far a ball launched at ``speed`` rolls before stopping (inf if it never stops)."""
    if speed <= physics.min_speed:
        return 0.0
    if physics.friction == "rolling":
        a = physics.deceleration
        return (speed * speed - physics.min_speed ** 2) / (2.0 * a) if a > 0 else math.inf
    k = physics.drag_rate
    return (speed - physics.min_speed) / k if k > 0 else math.inf


def _ray_circle_entry(p: np.ndarray, u: np.ndarray, c: np.ndarray, r: float) -> np.ndarray:
    """Distance along rays ``p + t u`` (``u``: (K,2) unit vectors) to enter the circle (c, r); inf if missed."""
    d = p - c
    b = u @ d  # (K,)
    cc = float(d @ d) - r * r
    if cc <= 0.0:
        return np.zeros(len(u))
    disc = b * b - cc
    t = -b - np.sqrt(np.maximum(disc, 0.0))
    return np.where((disc >= 0.0) & (b < 0.0), t, np.inf)


def _ray_wall_distance(p: np.ndarray, u: np.ndarray, table: Table, r: float) -> np.ndarray:
    """Distance along rays ``p + t u`` until a ball of radius ``r`` touches a cushion."""
    with np.errstate(divide="ignore", invalid="ignore"):
        tx = np.where(u[:, 0] > 0, (table.length - r - p[0]) / u[:, 0],
                      np.where(u[:, 0] < 0, (r - p[0]) / u[:, 0], np.inf))
        ty = np.where(u[:, 1] > 0, (table.width - r - p[1]) / u[:, 1],
                      np.where(u[:, 1] < 0, (r - p[1]) / u[:, 1], np.inf))
    return np.maximum(np.minimum(tx, ty), 0.0)


def pocket_window(obj: np.ndarray, radius: float, table: Table, pocket: int,
                  samples: int = WINDOW_SAMPLES) -> tuple[float, float, float] | None:
    """The directions along which a ball at ``obj`` enters pocket ``pocket`` before touching a cushion.

    Returns ``(centre angle, half-width, distance to the capture circle along the centre)`` of the widest
    contiguous window, or None if there is none.
    """
    c = table.pocket_xy[pocket]
    pr = float(table.pocket_radius[pocket])
    v = c - obj
    dist = float(np.hypot(*v))
    if dist <= pr:
        return float(math.atan2(v[1], v[0])), math.pi / 2, 0.0
    theta_c = math.atan2(v[1], v[0])
    half = math.asin(min(1.0, pr / dist))
    angles = theta_c + np.linspace(-half, half, samples)
    u = np.stack([np.cos(angles), np.sin(angles)], axis=1)
    t_in = _ray_circle_entry(obj, u, c, pr)
    t_wall = _ray_wall_distance(obj, u, table, radius)
    ok = np.isfinite(t_in) & (t_in <= t_wall + 1e-9)
    if not ok.any():
        return None
    # Widest run of consecutive feasible samples.
    best_len, best_start, run_start = 0, 0, None
    for k, flag in enumerate(list(ok) + [False]):
        if flag and run_start is None:
            run_start = k
        elif not flag and run_start is not None:
            if k - run_start > best_len:
                best_len, best_start = k - run_start, run_start
            run_start = None
    lo, hi = best_start, best_start + best_len - 1
    step = 2.0 * half / (samples - 1)
    centre = 0.5 * (angles[lo] + angles[hi])
    width = 0.5 * ((hi - lo) * step + step)  # a lone sample still counts as a sliver of width step/2
    uc = np.array([[math.cos(centre), math.sin(centre)]])
    d_in = float(_ray_circle_entry(obj, uc, c, pr)[0])
    if not math.isfinite(d_in):
        d_in = dist
    return float(centre), float(width), d_in


def segment_blocked(a: np.ndarray, b: np.ndarray, others: np.ndarray, clearance: np.ndarray) -> bool:
    """Whether any point of ``others`` (M,2) lies closer than ``clearance`` (M,) to the segment ``a -> b``."""
    if len(others) == 0:
        return False
    ab = b - a
    L2 = float(ab @ ab)
    if L2 == 0.0:
        d = np.hypot(*(others - a).T)
    else:
        t = np.clip(((others - a) @ ab) / L2, 0.0, 1.0)
        proj = a + t[:, None] * ab
        d = np.hypot(*(others - proj).T)
    return bool(np.any(d < clearance - 1e-9))


def _path_enters_pocket(start: np.ndarray, velocity: np.ndarray, radius: float, table: Table, physics: Physics,
                        max_bounces: int = 4) -> bool:
    """Does a lone ball launched from ``start`` with ``velocity`` roll into a pocket (straight lines, cushion
    reflections with the table's restitution, the friction law's stopping distance)?"""
    p = np.array(start, dtype=float)
    v = np.array(velocity, dtype=float)
    for _ in range(max_bounces + 1):
        s = float(np.hypot(*v))
        if s < 1e-6:
            return False
        u = (v / s)[None, :]
        reach = travel_distance(s, physics)
        t_wall = float(_ray_wall_distance(p, u, table, radius)[0])
        for k in range(table.n_pockets):
            t = float(_ray_circle_entry(p, u, table.pocket_xy[k], float(table.pocket_radius[k]))[0])
            if t <= min(reach, t_wall + 1e-9):
                return True
        if reach <= t_wall:
            return False
        # Roll to the cushion, then reflect.
        p = p + u[0] * t_wall
        s_wall = math.sqrt(max(s * s - 2.0 * physics.deceleration * t_wall, 0.0)) \
            if physics.friction == "rolling" else max(s - physics.drag_rate * t_wall, 0.0)
        v = u[0] * s_wall
        if p[0] <= radius + 1e-9 or p[0] >= table.length - radius - 1e-9:
            v[0] = -table.cushion_restitution * v[0]
        if p[1] <= radius + 1e-9 or p[1] >= table.width - radius - 1e-9:
            v[1] = -table.cushion_restitution * v[1]
    return False


def cue_after_hit(cue_dir: np.ndarray, obj_dir: np.ndarray, v_impact: float, e: float, m_cue: float,
                  m_obj: float) -> np.ndarray:
    """The cue ball's velocity right after hitting a resting ball along line of centres ``obj_dir``."""
    vn = v_impact * float(cue_dir @ obj_dir)
    return v_impact * cue_dir - m_obj * (1.0 + e) / (m_cue + m_obj) * vn * obj_dir


def ghost_ball_shots(
    balls: Balls,
    table: Table,
    physics: Physics,
    cue: int = 0,
    targets: list[int] | None = None,
    speed_range: tuple[float, float] = (0.05, 6.0),
    max_cut: float = MAX_CUT,
    arrive_speed: float = 0.35,
    speed_factors: tuple[float, ...] = (1.0, 0.6, 0.3, 1.8, 3.0),
    check_scratch: bool = True,
) -> list[ShotCandidate]:
    """Every ghost-ball shot at every object ball (``targets``, default all others on the table) into every
    pocket, easiest first.

    A shot needs a pocket window, a cut below ``max_cut``; it is scored by ``tolerance`` (the cue-angle error
    that still pots: the pocket window seen from the object ball, scaled by ``2R cos(cut) / d_cue``), divided
    by 10 when a path is blocked, by 3 when the cue speed needed is out of range and by 2 when the cue ball's
    deflected path (with cushion bounces) runs into a pocket. The cue speed gets the object ball to the capture
    circle still moving at ``arrive_speed`` under the table's friction law; if the cue ball would then follow into
    a pocket, the arrival speed is scaled by the next of ``speed_factors`` until one is safe.
    """
    on = balls.on_table
    if targets is None:
        targets = [i for i in range(len(balls)) if i != cue and on[i]]
    C = balls.pos[cue]
    rc = float(balls.radius[cue])
    mc = float(balls.mass[cue])
    e = physics.ball_restitution
    lo, hi = speed_range
    out: list[ShotCandidate] = []
    for j in targets:
        if not on[j] or j == cue:
            continue
        O = balls.pos[j]
        ro = float(balls.radius[j])
        mo = float(balls.mass[j])
        others_c = [k for k in range(len(balls)) if on[k] and k not in (cue, j)]
        opos = balls.pos[others_c] if others_c else np.zeros((0, 2))
        orad = balls.radius[others_c] if others_c else np.zeros(0)
        for p in range(table.n_pockets):
            win = pocket_window(O, ro, table, p)
            if win is None:
                continue
            obj_angle, half, d_obj = win
            u = np.array([math.cos(obj_angle), math.sin(obj_angle)])
            G = O - (rc + ro) * u
            cg = G - C
            d_cue = float(np.hypot(*cg))
            if d_cue < 1e-9:
                continue
            cue_dir = cg / d_cue
            cos_cut = float(np.clip(cue_dir @ u, -1.0, 1.0))
            cut = math.acos(cos_cut)
            if cut > max_cut:
                continue
            # The ghost position must be on the table.
            if not (rc <= G[0] <= table.length - rc and rc <= G[1] <= table.width - rc):
                continue
            clear = not segment_blocked(C, G, opos, orad + rc) and \
                not segment_blocked(O, O + u * d_obj, opos, orad + ro)
            transfer = mc * (1.0 + e) / (mc + mo) * cos_cut
            speed, v0, risk, reachable = hi, math.inf, True, False
            # Softest arrival that leaves the cue ball out of the pockets (tried in order).
            for factor in speed_factors:
                v_obj = speed_to_travel(d_obj, arrive_speed * factor, physics)
                v_impact = v_obj / max(transfer, 1e-6)
                v_need = speed_to_travel(d_cue, v_impact, physics)
                if v_need > hi:
                    if not reachable and factor == speed_factors[0]:
                        v0 = v_need
                    continue
                s_try = float(max(v_need, lo))
                v_imp = math.sqrt(max(s_try ** 2 - 2.0 * physics.deceleration * d_cue, 1e-12)) \
                    if physics.friction == "rolling" else max(s_try - physics.drag_rate * d_cue, 1e-6)
                r_try = check_scratch and _path_enters_pocket(
                    G, cue_after_hit(cue_dir, u, v_imp, e, mc, mo), rc, table, physics)
                if not reachable or (risk and not r_try):
                    speed, v0, risk, reachable = s_try, v_need, r_try, True
                if not risk:
                    break
            if not reachable:
                speed = float(hi)
            tol = half * (rc + ro) * cos_cut / (d_cue + rc + ro)
            score = tol
            if not clear:
                score /= 10.0
            if not reachable:
                score /= 3.0
            if risk:
                score /= 2.0
            out.append(ShotCandidate(j, p, float(math.atan2(cg[1], cg[0])), speed, float(v0), obj_angle, cut,
                                     d_cue, d_obj, half, tol, clear, reachable, risk, score))
    out.sort(key=lambda s: -s.score)
    return out


def direct_hit(balls: Balls, cue: int = 0, targets: list[int] | None = None) -> tuple[float, int]:
    """Angle of a full-ball hit on the nearest target (the fallback when no pocket shot exists)."""
    on = balls.on_table
    if targets is None:
        targets = [i for i in range(len(balls)) if i != cue and on[i]]
    targets = [j for j in targets if on[j] and j != cue]
    if not targets:
        return 0.0, -1
    d = [float(np.hypot(*(balls.pos[j] - balls.pos[cue]))) for j in targets]
    j = targets[int(np.argmin(d))]
    v = balls.pos[j] - balls.pos[cue]
    return float(math.atan2(v[1], v[0])), j


def position_score(balls: Balls, table: Table, physics: Physics, cue: int = 0,
                   targets: list[int] | None = None, speed_range: tuple[float, float] = (0.05, 6.0)) -> float:
    """How good the next shot is from this layout: the best ghost-ball shot's score (0 if none)."""
    shots = ghost_ball_shots(balls, table, physics, cue, targets, speed_range)
    return shots[0].score if shots else 0.0
