"""Today's Python players (before the compiled geometry of issue 21), kept as the reference the compiled kernels
are tested against: ``ghost_ball_shots``, ``geometric_shot``, ``break_shot``, ``choose_placement`` and the
geometric player's decision (:func:`reference_geometric_act`), with the numpy ``pocket_window`` (41 sampled
directions), ``segment_blocked`` and ``cut_cosine`` they called. Verbatim copies; remove when the lead says so."""
from __future__ import annotations

import contextlib
import math
from typing import Any

import numpy as np

from billiards_env.physics import Balls, Physics, Table
from billiards_env.physics.aim import (WINDOW_SAMPLES, aim_angle, angular_radius, deflected_cue_velocity,
                                       direction_vector, ghost_ball_position, object_ball_speed, path_enters_pocket,
                                       ray_circle_entries, ray_circle_entry, ray_cushion_distances)
from billiards_env.physics.layout import head_spot
from billiards_env.physics.motion import launch_speed, speed_after_distance, stop_distance
from billiards_env.players.context import ShotContext, shot_context
from billiards_env.players.shots import MAX_CUT, ShotCandidate

Vec2 = Any

def cut_cosine(aim_direction: Vec2, object_direction: Vec2) -> float:
    """Cosine of the cut angle: between the cue ball's direction at impact and the object ball's direction
    (both unit vectors), clipped to [-1, 1]."""
    return float(np.clip(np.dot(np.asarray(aim_direction, dtype=float), np.asarray(object_direction, dtype=float)),
                         -1.0, 1.0))


def cut_angle(aim_direction: Vec2, object_direction: Vec2) -> float:
    """The cut angle (rad, in [0, pi]) between the cue ball's direction at impact and the direction the object
    ball takes (both unit vectors): 0 for a full (straight) hit; a pot needs it below ``pi / 2``."""
    return math.acos(cut_cosine(aim_direction, object_direction))


def pocket_window(obj: Vec2, radius: float, table: Table, pocket: int,
                  samples: int = WINDOW_SAMPLES) -> tuple[float, float, float] | None:
    """The directions along which a ball of ``radius`` at ``obj`` rolls into the capture circle of ``pocket``
    before touching a cushion.

    ``samples`` directions across the circle's angular size are tested with the engine's own ray tests. Returns
    ``(centre direction, half-width, distance to the capture circle along the centre)`` of the widest contiguous
    run of good directions (a lone good sample counts as a sliver ``step / 2`` wide), or None if there is none.
    From inside the circle: ``(direction to its centre, pi / 2, 0)``.
    """
    obj = np.asarray(obj, dtype=float)
    c = table.pocket_xy[pocket]
    pr = float(table.pocket_radius[pocket])
    v = c - obj
    dist = float(np.hypot(*v))
    theta_c = aim_angle(obj, c)
    if dist <= pr:
        return float(theta_c), math.pi / 2, 0.0
    half = angular_radius(pr, dist)
    angles = theta_c + np.linspace(-half, half, samples)
    ux, uy = np.cos(angles), np.sin(angles)
    t_in = ray_circle_entries(obj[0], obj[1], ux, uy, c[0], c[1], pr)
    t_wall = ray_cushion_distances(obj[0], obj[1], ux, uy, table.length, table.width, radius)
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
    width = 0.5 * ((hi - lo) * step + step)
    d_in = ray_circle_entry(obj[0], obj[1], math.cos(centre), math.sin(centre), c[0], c[1], pr)
    if not math.isfinite(d_in):
        d_in = dist
    return float(centre), float(width), float(d_in)


def segment_blocked(a: Vec2, b: Vec2, others: np.ndarray, clearance: np.ndarray) -> bool:
    """Whether any centre of ``others`` (M, 2) comes closer than its ``clearance`` (M,) to the segment ``a -> b``
    (for a ball rolling from ``a`` to ``b``: clearance = the two radii summed)."""
    if len(others) == 0:
        return False
    a = np.asarray(a, dtype=float)
    ab = np.asarray(b, dtype=float) - a
    L2 = float(ab @ ab)
    if L2 == 0.0:
        d = np.hypot(*(others - a).T)
    else:
        t = np.clip(((others - a) @ ab) / L2, 0.0, 1.0)
        proj = a + t[:, None] * ab
        d = np.hypot(*(others - proj).T)
    return bool(np.any(d < clearance - 1e-9))


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


def geometric_shot(ctx: ShotContext, max_cut: float = MAX_CUT) -> tuple[float, float, ShotCandidate | None]:
    """The easiest ghost-ball shot ``(angle, speed, candidate)``; falls back to thinner cuts (up to 88 deg) and
    then to a firm full-ball hit on the nearest ball (candidate None)."""
    for cut in (max_cut, math.radians(88.0)):
        shots = ghost_ball_shots(ctx.balls, ctx.table, ctx.physics, ctx.cue, ctx.targets, ctx.speed_range, cut)
        if shots:
            s = shots[0]
            return s.angle, s.speed, s
    angle, _ = direct_hit(ctx.balls, ctx.cue, ctx.targets)
    lo, hi = ctx.speed_range
    return angle, float(min(max(2.0, lo), hi)), None



def break_shot(ctx: ShotContext) -> tuple[tuple[float, float] | None, float, float]:
    """The opening break: the cue ball on the head string (where the shooter may place it), struck at full speed
    into the middle of the lowest legal ball (the apex). Returns ``(place, angle, speed)``."""
    b = ctx.balls
    place = None
    if ctx.place_area is not None:
        x0, x1, y0, y1 = ctx.place_area
        place = (min(max(head_spot(ctx.table)[0], x0), x1), min(max(0.5 * ctx.table.width, y0), y1))
    cue = b.pos[ctx.cue] if place is None else np.asarray(place)
    target = min(ctx.targets, key=lambda j: float(np.hypot(*(b.pos[j] - cue)))) if ctx.targets else ctx.cue
    return place, aim_angle(cue, b.pos[target]), float(ctx.speed_range[1])


def choose_placement(env: Any, ctx: ShotContext, max_cut: float = MAX_CUT,
                     backs: tuple[float, ...] = (0.25, 0.5)) -> tuple[float, float]:
    """Ball in hand: the legal cue position (in ``ctx.place_area``, off the other balls) that leaves the easiest
    ghost-ball shot. Candidates are the straight-in positions ``backs`` metres behind the ghost ball of every
    legal target and pocket (moved to the nearest legal point); each is scored by :func:`ghost_ball_shots`."""
    u = env.unwrapped
    b = ctx.balls
    r = float(b.radius[ctx.cue])
    x0, x1, y0, y1 = ctx.place_area
    best, best_score = None, -1.0
    for j in ctx.targets:
        obj = b.pos[j]
        contact = r + float(b.radius[j])
        for p in range(ctx.table.n_pockets):
            win = pocket_window(obj, float(b.radius[j]), ctx.table, p)
            if win is None:
                continue
            ghost = ghost_ball_position(obj, win[0], contact)
            for back in backs:
                x, y = ghost - back * direction_vector(win[0])
                place = u.legal_cue_position(min(max(x, x0), x1), min(max(y, y0), y1))
                with u.cue_moved_to(place):
                    shots = ghost_ball_shots(b, ctx.table, ctx.physics, ctx.cue, [j], ctx.speed_range, max_cut)
                score = shots[0].score if shots else 0.0
                if score > best_score:
                    best, best_score = place, score
    if best is None:  # nothing makeable from anywhere: the middle of the area
        best = u.legal_cue_position(0.5 * (x0 + x1), 0.5 * (y0 + y1))
    return best


def reference_geometric_act(env: Any, max_cut: float = MAX_CUT):
    """``GeometricPlayer.act`` before issue 21, without the final action: ``(place, angle, speed, candidate)``."""
    ctx = shot_context(env)
    u = env.unwrapped
    if ctx.game is not None and ctx.game.state.break_shot:
        place, angle, speed = break_shot(ctx)
        return place, angle, speed, None
    place = choose_placement(env, ctx, max_cut) if ctx.place_area is not None else None
    with u.cue_moved_to(place) if place is not None else contextlib.nullcontext():
        angle, speed, last = geometric_shot(ctx, max_cut)
    return place, angle, speed, last
