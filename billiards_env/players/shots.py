"""Ghost-ball shot selection for the baseline players, on the engine's model (no Gymnasium here).

Ghost-ball aiming: to send object ball ``O`` in direction ``u`` the cue ball must touch it from the ghost-ball
position ``G = O - (r_cue + r_obj) u``. The cut angle is the angle between the cue's path ``C -> G`` and ``u``.
Pockets are capture circles (:class:`billiards_env.physics.Table`): the direction ``u`` is taken from the middle
of the window of directions along which the object ball enters the capture circle before touching a cushion, so
corner and side pockets approached at a shallow angle are aimed correctly (or rejected when the window is empty).

Every formula (rays, pocket windows, ghost ball, cut, clear paths, the collision, the cue ball's path) is
:mod:`billiards_env.physics.aim`'s and the motion law :mod:`billiards_env.physics.motion`'s; this module holds the
players' choices: which shots to consider, how hard to hit them, how to score them.

All angles are radians (0 = +x, counter-clockwise), speeds m/s, distances m.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from billiards_env.physics import Balls, Physics, Table
from billiards_env.physics.aim import (aim_angle, cut_angle, cut_cosine, deflected_cue_velocity, direction_vector,
                                       ghost_ball_position, object_ball_speed, path_enters_pocket, pocket_window,
                                       segment_blocked)
from billiards_env.physics.motion import launch_speed, speed_after_distance, stop_distance

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
    """Launch speed for a ball to roll ``d`` metres and still move at ``v_end`` (both friction laws); ``v_end`` is
    raised to just above the law's stopping speed."""
    v_end = max(v_end, physics.min_speed * 1.05 + 1e-6)
    return launch_speed(d, v_end, *physics.path_args)


def travel_distance(speed: float, physics: Physics) -> float:
    """How far a ball launched at ``speed`` rolls before stopping (inf if it never stops)."""
    return stop_distance(speed, *physics.path_args, physics.min_speed)


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
            u = direction_vector(obj_angle)
            G = ghost_ball_position(O, obj_angle, rc + ro)
            cg = G - C
            d_cue = float(np.hypot(*cg))
            if d_cue < 1e-9:
                continue
            cue_dir = cg / d_cue
            cos_cut = cut_cosine(cue_dir, u)
            cut = cut_angle(cue_dir, u)
            if cut > max_cut:
                continue
            # The ghost position must be on the table.
            if not (rc <= G[0] <= table.length - rc and rc <= G[1] <= table.width - rc):
                continue
            clear = not segment_blocked(C, G, opos, orad + rc) and \
                not segment_blocked(O, O + u * d_obj, opos, orad + ro)
            transfer = object_ball_speed(1.0, cos_cut, e, mc, mo)  # object ball speed per unit impact speed
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
                v_imp = max(speed_after_distance(s_try, d_cue, *physics.path_args), 1e-6)
                r_try = check_scratch and path_enters_pocket(
                    G, deflected_cue_velocity(v_imp * cue_dir, u, e, mc, mo), rc, table, physics)
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
            out.append(ShotCandidate(j, p, float(aim_angle(C, G)), speed, float(v0), obj_angle, cut,
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
    return float(aim_angle(balls.pos[cue], balls.pos[j])), j


def pot_probability(tolerance: float, sigma: float) -> float:
    """The chance that a shot with cue-angle ``tolerance`` (rad, see :func:`ghost_ball_shots`) pots when the cue
    angle errs by a normal spread ``sigma``: ``erf(tolerance / (sqrt(2) sigma))``."""
    return math.erf(max(tolerance, 0.0) / (math.sqrt(2.0) * max(sigma, 1e-12)))


def position_score(balls: Balls, table: Table, physics: Physics, cue: int = 0,
                   targets: list[int] | None = None, speed_range: tuple[float, float] = (0.05, 6.0)) -> float:
    """How good the next shot is from this layout: the best ghost-ball shot's score (0 if none)."""
    shots = ghost_ball_shots(balls, table, physics, cue, targets, speed_range)
    return shots[0].score if shots else 0.0
