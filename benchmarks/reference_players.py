"""The players' Python before their compiled geometry, kept as the reference the compiled code is held to: the
benchmark (benchmarks/players.py) times both, and the tests (tests/players/test_geometry.py, test_search_fast.py,
test_slots.py, tests/envs/test_candidates.py) compare the compiled results with records of this code's
(tests/golden.py; recording runs this module and asserts equality first): ``ghost_ball_shots``, ``geometric_shot``, ``break_shot``, ``choose_placement``, the geometric
player's decision (:func:`reference_geometric_act`), the search player (:class:`ReferenceSearchPlayer`) and the
``candidates`` types' slot lists (:func:`reference_candidate_slots` and its parts), with the numpy ``pocket_window``
(41 sampled directions), ``segment_blocked`` and ``cut_cosine`` they called. Verbatim copies (the search's and the
slots' imports pointed at the copies here), except that their 2-vector dot products (``np.dot``, ``@``: OpenBLAS's
rounding, which depends on the CPU's kernel) are :func:`_dot2` (:func:`billiards_env.physics.aim.dot2`: one rounding,
the one the compiled code and OpenBLAS's Haswell kernel give), so compiled and reference agree on every machine.
Kept with the benchmarks, outside the package: not part of the API."""
from __future__ import annotations

import contextlib
import math
from dataclasses import dataclass
from typing import Any, Callable, Sequence

import numpy as np

from billiards_env.physics import Balls, Physics, Table
from billiards_env.physics.batch import BatchResult, run_shots
from billiards_env.rules import ShotInfo, summarize_arrays
from billiards_env.physics.aim import (WINDOW_SAMPLES, aim_angle, dot2, angular_radius, deflected_cue_velocity,
                                       direction_vector, ghost_ball_position, object_ball_speed, path_enters_pocket,
                                       ray_circle_entries, ray_circle_entry, ray_cushion_distances,
                                       cushion_ahead)
from billiards_env.physics.layout import head_spot
from billiards_env.physics.pocket_specs import N_RAILS
from billiards_env.physics.walls import on_rail_span
from billiards_env.physics.motion import launch_speed, speed_after_distance, stop_distance
from billiards_env.players.context import ShotContext, shot_context
from billiards_env.players.shots import MAX_CUT, ShotCandidate, pot_probability


def to_action(env: Any, angle: float, speed: float, place: tuple[float, float] | None = None,
              pocket: int | None = None, side: float = 0.0, top: float = 0.0) -> np.ndarray:
    """The env's action for a shot, as the players made it before the games were compiled (2026-12-02) (through the env's action type, the
    tip offsets dropped without spin dims, clipped to the action space)."""
    u = env.unwrapped
    at = u.action_type
    tip = {"side": side, "top": top} if at.spin else {}
    a = np.asarray(at.action(u.table_state, angle, speed, place=place, pocket=pocket, **tip), dtype=np.float32)
    return np.clip(a, env.action_space.low, env.action_space.high)

Vec2 = Any


def _dot2(a: Any, b: Any) -> Any:
    """The dot product of 2-vectors ``a`` and ``b`` rounded as :func:`billiards_env.physics.aim.dot2`; ``a`` may
    be rows ``(N, 2)`` (then ``(N,)``)."""
    a = np.asarray(a, dtype=float)
    bx, by = float(b[0]), float(b[1])
    if a.ndim == 1:
        return dot2(float(a[0]), float(a[1]), bx, by)
    return np.array([dot2(float(x), float(y), bx, by) for x, y in a], dtype=float)

def cut_cosine(aim_direction: Vec2, object_direction: Vec2) -> float:
    """Cosine of the cut angle: between the cue ball's direction at impact and the object ball's direction
    (both unit vectors), clipped to [-1, 1]."""
    return float(np.clip(_dot2(aim_direction, object_direction), -1.0, 1.0))


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
    segs, tips = table.walls()
    if len(segs) or len(tips):  # a jaw table: the first rail, jaw face or tip along each direction
        t_wall = np.array([cushion_ahead(float(obj[0]), float(obj[1]), float(x), float(y), table.length, table.width,
                                         radius, segs, tips)[0] for x, y in zip(ux, uy)])
    else:
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
    L2 = float(_dot2(ab, ab))
    if L2 == 0.0:
        d = np.hypot(*(others - a).T)
    else:
        t = np.clip(_dot2(others - a, ab) / L2, 0.0, 1.0)
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
        Obj = balls.pos[j]
        ro = float(balls.radius[j])
        mo = float(balls.mass[j])
        others_c = [k for k in range(len(balls)) if on[k] and k not in (cue, j)]
        opos = balls.pos[others_c] if others_c else np.zeros((0, 2))
        orad = balls.radius[others_c] if others_c else np.zeros(0)
        for p in range(table.n_pockets):
            win = pocket_window(Obj, ro, table, p)
            if win is None:
                continue
            obj_angle, half, d_obj = win
            u = direction_vector(obj_angle)
            G = ghost_ball_position(Obj, obj_angle, rc + ro)
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
                not segment_blocked(Obj, Obj + u * d_obj, opos, orad + ro)
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
    """``GeometricPlayer.act`` before the games were compiled (2026-12-02), without the final action: ``(place, angle, speed, candidate)``."""
    ctx = shot_context(env)
    u = env.unwrapped
    if ctx.game is not None and ctx.game.game_state.break_shot:
        place, angle, speed = break_shot(ctx)
        return place, angle, speed, None
    place = choose_placement(env, ctx, max_cut) if ctx.place_area is not None else None
    with u.cue_moved_to(place) if place is not None else contextlib.nullcontext():
        angle, speed, last = geometric_shot(ctx, max_cut)
    return place, angle, speed, last


# --- the search player (billiards_env/players/search.py before the games were compiled (2026-12-02)) --------------------------------------------

#: Tip offsets ``(side, top)`` (fractions of R) tried with every ghost-ball shot under the spin model: stun, draw,
#: follow, left and right english.
SPIN_VARIANTS: tuple[tuple[float, float], ...] = ((0.0, 0.0), (0.0, -0.35), (0.0, 0.35), (-0.3, 0.0), (0.3, 0.0))

#: Grid (m) of the object-ball positions whose pocket windows :func:`next_shot_ease` caches: a window is the same
#: to well within the noise for balls less than a millimetre apart.
WINDOW_GRID = 5e-4

#: Rules values of a candidate in a game (before position): won, lost, a foul, the turn kept (+ per ball).
WIN_VALUE = 10.0
FOUL_VALUE = -3.0
KEEP_VALUE = 1.0
BALL_VALUE = 0.1


@dataclass
class Outcome:
    """A candidate shot and what the search made of it."""

    angle: float
    speed: float
    pots: int
    scratch: bool
    hit: bool
    value: float  #: the outcome's value: in a game the rules' verdict (:func:`_judge`), else pots - 3 scratch - ...
    robust: float = math.nan  #: mean total (value + position term) over the unperturbed and the noisy shots
    position: float = 0.0  #: pot probability of the next shot (the opponent's after a miss) from the final layout
    side: float = 0.0
    top: float = 0.0
    source: str = ""
    total: float = math.nan  #: value + the position term, unperturbed


@dataclass
class SearchSettings:
    n_geometric: int = 6  #: ghost-ball candidates refined
    angle_offsets: tuple[float, ...] = (0.0, 0.0015, -0.0015, 0.004, -0.004, 0.01, -0.01)
    speed_factors: tuple[float, ...] = (0.6, 1.0, 1.6, 2.5, 4.0)  #: times the ghost-ball speed
    spins: tuple[tuple[float, float], ...] = SPIN_VARIANTS  #: tip offsets tried under the spin model
    sweep_angles: int = 72  #: coarse sweep over all directions...
    sweep_speeds: tuple[float, ...] = (0.25, 0.6, 1.0)  #: ...at these fractions of the speed range
    top_k: int = 6  #: best candidates re-simulated under noise
    robust_samples: int = 10
    robust_angle: float = 0.002  #: perturbation (rad) when the env has no angle noise
    robust_speed: float = 0.05  #: relative perturbation when the env has no speed noise
    robust_tip: float = 0.02  #: tip perturbation (fraction of R) under the spin model when the env has no tip noise
    position_weight: float = 2.0  #: value of a sure next shot (pot probability 1) on top of keeping the turn (1)
    safety_weight: float = 1.0  #: cost of leaving the opponent a sure shot after a miss
    ease_noise: float = 0.002  #: angle spread (rad) the next shot's pot probability assumes without angle noise
    placements: int = 3  #: ball in hand: places searched from


# --- simulation and judgement ---------------------------------------------------------------------------------

def _simulate(ctx: ShotContext, angles: Any, speeds: Any, sides: Any = None, tops: Any = None
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, BatchResult]:
    """Play candidate shots, all in one batch (:func:`~billiards_env.physics.batch.run_shots`; each row is the
    single ``Simulator.run`` of its shot): ``(pots, scratch, hit, value, batch result)`` per candidate. Without a
    game the value is :func:`_value`; in a game it is the rules' verdict (:func:`_judge`)."""
    return _simulate_judged(ctx, angles, speeds, sides, tops)[:5]


def _simulate_judged(ctx: ShotContext, angles: Any, speeds: Any, sides: Any = None, tops: Any = None
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, BatchResult, np.ndarray,
                                list[list[int]]]:
    """:func:`_simulate`, plus per candidate who shoots next (1 the shooter, 0 the opponent from where the cue ball
    lies, -1 nobody or ball in hand) and the rows of the balls that player may hit first."""
    game = ctx.game is not None
    spin = ctx.physics.friction == "spin"
    res = run_shots(ctx.simulator, ctx.balls, angles, speeds, ball=ctx.cue, validate=False, events=game,
                    side=sides if spin else None, top=tops if spin else None)
    targets = np.asarray(ctx.targets, dtype=np.int64)
    pots = (res.pocket[:, targets] >= 0).sum(axis=1)
    scratch = res.pocket[:, ctx.cue] >= 0
    hit = res.first_contact >= 0
    n = len(res.time)
    if not game:
        # Without rules the shooter plays on only after a pot without a scratch: a miss earns no position (it
        # must never outrank a pot), and a cleared table has no next shot.
        left = [[j for j in ctx.targets if res.on_table[k, j]] for k in range(n)]
        nxt = np.where((pots > 0) & ~scratch & np.array([bool(t) for t in left]), 1, -1)
        return pots, scratch, hit, _value(pots, scratch, hit), res, nxt, left
    ev = res.events
    table = np.stack([ev.kind, ev.ball, ev.other], axis=1)
    memo: dict[tuple[bytes, bytes], tuple[float, int, list[int]]] = {}
    judged = []
    for k in range(n):
        rows = table[int(ev.offsets[k]):int(ev.offsets[k + 1])]
        key = (rows.tobytes(), res.pocket[k].tobytes())  # the rules read only these: equal logs, equal calls
        j = memo.get(key)
        if j is None:
            j = memo[key] = _judge_arrays(ctx, rows, res.pocket[k])
        judged.append(j)
    values = np.array([j[0] for j in judged])
    return pots, scratch, hit, values, res, np.array([j[1] for j in judged]), [j[2] for j in judged]


def _value(pots: Any, scratch: Any, hit: Any) -> Any:
    """``pots - 3 scratch - 0.5 (no ball hit)``, for one candidate or arrays of them."""
    return pots - 3.0 * scratch - np.where(hit, 0.0, 0.5)


def _judge(ctx: ShotContext, events: Any, pocket: np.ndarray) -> tuple[float, int, list[int]]:
    """A candidate under the game's rules (from its event log and pockets): its value (+10 won, -10 lost, -3 a
    foul, +1 for keeping the turn plus 0.1 per ball that counts, 0 for a legal miss), who shoots next (1: the
    shooter again, 0: the opponent without ball in hand, -1: nobody or ball in hand) and the rows of the balls that
    player may hit first."""
    return _judge_arrays(ctx, np.stack([events.kind, events.ball, events.other], axis=1), pocket)


def _judge_arrays(ctx: ShotContext, events: np.ndarray, pocket: np.ndarray) -> tuple[float, int, list[int]]:
    """:func:`_judge` from the ``(M, 3)`` event array (kind, ball, other)."""
    game = ctx.game
    summary = summarize_arrays(events, pocket, game.numbers)
    eight = pocket[game.row_of[8]] if game.needs_called_pocket() and 8 in game.row_of else None
    state = game.game_state
    call = game.rules.call(state, summary, ShotInfo(called_pocket=None if eight is None or eight < 0
                                                    else int(eight)))
    if call.game_over:
        return (WIN_VALUE if call.winner == call.shooter else -WIN_VALUE), -1, []
    if call.foul:
        return FOUL_VALUE, -1, []
    nxt = game.rules.next_state(state, call)
    rows = [game.row_of[n] for n in game.rules.legal_targets(nxt)]
    if call.turn_over:
        return 0.0, 0, rows
    return KEEP_VALUE + BALL_VALUE * len(set(call.pocketed) - set(call.respot)), 1, rows


# --- position: the ease of the next shot -------------------------------------------------------------------------

def next_shot_ease(table: Any, radius: np.ndarray, pos: np.ndarray, on: np.ndarray, cue: int,
                   targets: Sequence[Sequence[int]], sigma: float, max_cut: float = MAX_CUT,
                   windows: dict | None = None) -> np.ndarray:
    """For ``N`` layouts (``pos`` (N, B, 2), ``on`` (N, B)), the probability of potting the easiest ghost-ball shot
    from the cue ball at one of the layout's ``targets[k]`` (rows), when the cue angle errs with spread ``sigma``
    (rad): :func:`~.shots.pot_probability` of its tolerance, the tolerance being the geometric player's (the pocket window seen
    from the ball, scaled by ``(r_c + r_o) cos(cut) / (d_cue + r_c + r_o)``, divided by 10 when the cue ball's or the
    ball's path is blocked; cuts beyond ``max_cut`` and ghost balls off the table do not count). Vectorised over the
    layouts. Pocket windows are computed once per target position, to ``WINDOW_GRID`` (``windows``: a cache that
    may be shared between calls on one table)."""
    n = len(pos)
    best = np.zeros(n)
    if n == 0:
        return best
    windows = {} if windows is None else windows
    rc = float(radius[cue])
    groups: dict[tuple[int, bytes], list[int]] = {}
    for k in range(n):
        for j in targets[k]:
            if on[k, j] and on[k, cue]:
                groups.setdefault((int(j), pos[k, j].tobytes()), []).append(k)
    q = WINDOW_GRID
    cos_max = math.cos(max_cut)
    lo = np.array([rc, rc])
    hi = np.array([table.length - rc, table.width - rc])
    for (j, key), rows in groups.items():
        rows_a = np.asarray(rows)
        o = pos[rows[0], j]
        rj = float(radius[j])
        contact = rc + rj
        cell = (rj, round(float(o[0]) / q), round(float(o[1]) / q))
        wins = windows.get(cell)
        if wins is None:
            wins = [(p, w) for p in range(table.n_pockets) if (w := pocket_window(o, rj, table, p)) is not None]
            windows[cell] = wins
        c = pos[rows_a, cue]  # (n, 2)
        others = on[rows_a].copy()
        others[:, cue] = False
        others[:, j] = False
        balls = pos[rows_a]  # (n, B, 2)
        for p, (obj_angle, half, d_obj) in wins:
            u = direction_vector(obj_angle)
            g = ghost_ball_position(o, obj_angle, contact)
            if not (np.all(g >= lo) and np.all(g <= hi)):
                continue
            v = g - c
            d = np.hypot(v[:, 0], v[:, 1])
            cos_cut = _dot2(v, u) / np.maximum(d, 1e-12)
            ok = cos_cut >= cos_max
            if not ok.any():
                continue
            tol = half * contact * cos_cut / (d + contact)
            blocked = _segments_blocked(c, np.broadcast_to(g, c.shape), balls, others, rc + radius) | \
                _segments_blocked(np.broadcast_to(o, c.shape), np.broadcast_to(o + u * d_obj, c.shape), balls,
                                  others, rj + radius)
            tol = np.where(blocked, tol / 10.0, tol)
            tol = np.where(ok, tol, 0.0)
            best[rows_a] = np.maximum(best[rows_a], tol)
    return np.array([pot_probability(t, sigma) for t in best.tolist()])


def _segments_blocked(a: np.ndarray, b: np.ndarray, q: np.ndarray, mask: np.ndarray, clearance: np.ndarray
                      ) -> np.ndarray:
    """Per row: does a ball of ``q`` (n, B, 2) selected by ``mask`` (n, B) come closer than ``clearance`` (B,) to the
    segment ``a -> b`` (n, 2)?"""
    ab = b - a
    L2 = np.maximum((ab * ab).sum(axis=1), 1e-24)
    aq = q - a[:, None, :]
    t = np.clip((aq * ab[:, None, :]).sum(axis=2) / L2[:, None], 0.0, 1.0)
    closest = a[:, None, :] + t[:, :, None] * ab[:, None, :]
    dq = q - closest
    d2 = (dq * dq).sum(axis=2)
    return (mask & (d2 < clearance[None, :] ** 2)).any(axis=1)


# --- the search -------------------------------------------------------------------------------------------------

def _candidates(ctx: ShotContext, st: SearchSettings) -> list[tuple[float, float, float, float, str]]:
    """``(angle, speed, side, top, source)`` of every candidate: each ghost-ball shot at the angle offsets (stun, its
    own speed), at the speed factors with every tip variant (when the shooter sets tip offsets: the spin model and an
    action with spin dims; else stun only), then the sweep."""
    lo, hi = ctx.speed_range
    spins = st.spins if ctx.tip_offsets else ((0.0, 0.0),)
    out: list[tuple[float, float, float, float, str]] = []
    shots = ghost_ball_shots(ctx.balls, ctx.table, ctx.physics, ctx.cue, ctx.targets, ctx.speed_range,
                             math.radians(85.0))
    for s in shots[: st.n_geometric]:
        src = f"ghost:{s.target}->{s.pocket}"
        for da in st.angle_offsets:
            out.append((s.angle + da, min(max(s.speed, lo), hi), 0.0, 0.0, src))
        for f in st.speed_factors:
            for side, top in spins:
                if f == 1.0 and side == 0.0 and top == 0.0:
                    continue  # already in (offset 0)
                out.append((s.angle, min(max(s.speed * f, lo), hi), side, top, src))
    base = direct_hit(ctx.balls, ctx.cue, ctx.targets)[0]
    for k in range(st.sweep_angles):
        a = base + 2.0 * math.pi * k / st.sweep_angles
        for f in st.sweep_speeds:
            out.append((a, lo + f * (hi - lo), 0.0, 0.0, "sweep"))
    return out


def _positions(ctx: ShotContext, st: SearchSettings, res: BatchResult, values: np.ndarray, nxt: np.ndarray,
               targets: list[list[int]], rows: np.ndarray, windows: dict) -> tuple[np.ndarray, np.ndarray]:
    """Position term and pot probability of the next shot (the shooter's when he keeps the turn, the opponent's
    after a legal miss, 0 otherwise) for batch rows ``rows`` (see :func:`search_shot`)."""
    term = np.zeros(len(values))
    ease = np.zeros(len(values))
    rows = np.asarray(rows, dtype=np.int64)
    rows = rows[nxt[rows] >= 0]
    if len(rows) == 0:
        return term, ease
    sigma = max(ctx.angle_noise, st.ease_noise)
    e = next_shot_ease(ctx.table, ctx.balls.radius, res.pos[rows], res.on_table[rows], ctx.cue,
                       [targets[k] for k in rows], sigma, windows=windows)
    ease[rows] = e
    term[rows] = np.where(nxt[rows] == 1, st.position_weight, -st.safety_weight) * e
    return term, ease


def search_shot(ctx: ShotContext, settings: SearchSettings | None = None,
                rng: np.random.Generator | None = None, windows: dict | None = None,
                playable: Callable[[list[tuple[float, float, float, float, str]]],
                                   list[tuple[float, float, float, float, str]]] | None = None
                ) -> tuple[float, float, Outcome]:
    """Simulate candidate shots with the exact solver (in batches: one compiled call for all candidates, one for
    the noisy re-runs of the best) and pick the best.

    Candidates (:func:`_candidates`): the ghost-ball shots at angle offsets, speed factors and, under the spin model,
    tip offsets (stun, draw, follow, english), plus a sweep of directions and speeds (kicks and safeties). Each
    candidate's total is its value (in a game the rules' verdict: win, loss, foul, turn kept or lost) plus a
    position term from its final layout: ``position_weight`` times the pot probability of the next shot when the
    turn is kept (:func:`next_shot_ease`), minus ``safety_weight`` times the opponent's when it is lost without a
    foul. The ``top_k`` best totals are re-simulated ``robust_samples`` times under the shot noise (the env's, or the
    small ``robust_*`` defaults), and the shot with the best mean total (the unperturbed run counted as one sample)
    is played; in an env without shot noise the unperturbed total comes first and the mean only breaks ties.
    Returns ``(angle, speed, outcome)``; the outcome holds the tip offsets. ``windows``: a pocket-window cache for
    :func:`next_shot_ease` (one per table, kept by the player across its decisions). ``playable``: maps
    the candidates to the shots an action type can express (see :func:`playable_shots`), so the search values what
    will be played.
    """
    st = settings or SearchSettings()
    rng = rng or np.random.default_rng(0)
    lo, hi = ctx.speed_range
    spin = ctx.physics.friction == "spin"
    cands = _candidates(ctx, st)
    if playable is not None:
        cands = playable(cands)
    c_arr = np.array([c[:4] for c in cands], dtype=float)
    pots, scratch, hit, values, res, nxt, nxt_targets = _simulate_judged(ctx, c_arr[:, 0], c_arr[:, 1],
                                                                         c_arr[:, 2], c_arr[:, 3])
    windows = {} if windows is None else windows
    # Position terms move a total by less than the gap between outcome classes (win 10 > kept 1-1.9 + 2 >
    # missed 0 - 1 > foul -3): only the best class's candidates need them.
    near = np.flatnonzero(values >= values.max() - 0.95)
    term, ease = _positions(ctx, st, res, values, nxt, nxt_targets, near, windows)
    totals = values + term
    order = np.argsort(-totals, kind="stable")
    shortlist: list[Outcome] = []
    for k in order:
        angle, speed, side, top, src = cands[k]
        if all(abs(angle - q.angle) > 1e-3 or abs(speed - q.speed) > 0.05 or side != q.side or top != q.top
               for q in shortlist):
            shortlist.append(Outcome(angle, speed, int(pots[k]), bool(scratch[k]), bool(hit[k]), float(values[k]),
                                     position=float(ease[k]), side=side, top=top, source=src,
                                     total=float(totals[k])))
        if len(shortlist) >= st.top_k:
            break
    sa = ctx.angle_noise if ctx.angle_noise > 0 else st.robust_angle
    ss = ctx.speed_noise if ctx.speed_noise > 0 else st.robust_speed
    stn = (ctx.tip_noise if ctx.tip_noise > 0 else st.robust_tip) if spin else 0.0
    # Robustness: the noisy re-runs of the whole shortlist in one batch (drawn in the order of a loop).
    noisy = []
    for o in shortlist:
        for _ in range(st.robust_samples):
            a = o.angle + rng.normal(0.0, sa)
            v = min(max(float(o.speed * (1.0 + rng.normal(0.0, ss))), lo), hi)
            sd, tp = o.side, o.top
            if stn > 0.0:
                sd, tp = _tip_inside(sd + rng.normal(0.0, stn), tp + rng.normal(0.0, stn))
            noisy.append((a, v, sd, tp))
    if noisy:
        n_arr = np.array(noisy, dtype=float)
        _, _, _, n_values, n_res, n_nxt, n_targets = _simulate_judged(ctx, n_arr[:, 0], n_arr[:, 1], n_arr[:, 2],
                                                                      n_arr[:, 3])
        n_term, _ = _positions(ctx, st, n_res, n_values, n_nxt, n_targets, np.arange(len(noisy)), windows)
        n_totals = n_values + n_term
        # Without shot noise in the env the unperturbed outcome is what happens: the noisy runs only break ties
        # (towards shots with margin); with noise, every run is a sample of what may happen.
        exact = ctx.angle_noise == 0.0 and ctx.speed_noise == 0.0 and (not spin or ctx.tip_noise == 0.0)
        for q, o in enumerate(shortlist):
            block = n_totals[q * st.robust_samples:(q + 1) * st.robust_samples]
            mean = float((o.total + block.sum()) / (1 + len(block)))
            o.robust = o.total + 0.5 * mean if exact else mean
    else:
        for o in shortlist:
            o.robust = o.total
    best = max(shortlist, key=lambda o: o.robust)  # the first of equals (a stable choice)
    return best.angle, best.speed, best


def _tip_inside(side: float, top: float, limit: float = 0.5 * (1.0 - 1e-12)) -> tuple[float, float]:
    """A tip offset moved onto the miscue limit if beyond it (as the env keeps noisy tips legal)."""
    r = math.hypot(side, top)
    if r > limit:
        return side * limit / r, top * limit / r
    return side, top


# --- ball in hand ------------------------------------------------------------------------------------------------

def placement_candidates(env: Any, ctx: ShotContext, n: int, backs: tuple[float, ...] = (0.25, 0.5),
                         cuts: tuple[float, ...] = (0.0, math.radians(25.0), -math.radians(25.0)),
                         sigma: float = 0.002) -> list[tuple[float, float]]:
    """Ball in hand: up to ``n`` legal places (at least a ball apart) that leave the easiest shot, best first. The
    places tried: ``backs`` metres behind the ghost ball of every legal ball and pocket, straight in and at the
    ``cuts`` (for position after the pot), moved to the nearest legal point; each scored by :func:`next_shot_ease`."""
    u = env.unwrapped
    b = ctx.balls
    r = float(b.radius[ctx.cue])
    x0, x1, y0, y1 = ctx.place_area
    places: list[tuple[float, float]] = []
    for j in ctx.targets:
        obj = b.pos[j]
        for p in range(ctx.table.n_pockets):
            win = pocket_window(obj, float(b.radius[j]), ctx.table, p)
            if win is None:
                continue
            ghost = ghost_ball_position(obj, win[0], r + float(b.radius[j]))
            for back in backs:
                for cut in cuts:
                    x, y = ghost - back * direction_vector(win[0] + cut)
                    places.append(u.legal_cue_position(min(max(x, x0), x1), min(max(y, y0), y1)))
    if not places:
        return [u.legal_cue_position(0.5 * (x0 + x1), 0.5 * (y0 + y1))]
    pos = np.repeat(b.pos[None], len(places), axis=0)
    pos[:, ctx.cue] = places
    on = np.repeat(b.on_table[None], len(places), axis=0)
    on[:, ctx.cue] = True
    ease = next_shot_ease(ctx.table, b.radius, pos, on, ctx.cue, [ctx.targets] * len(places), sigma)
    out: list[tuple[float, float]] = []
    for k in np.argsort(-ease, kind="stable"):
        p = places[k]
        if all(math.hypot(p[0] - q[0], p[1] - q[1]) > 2.0 * r for q in out):
            out.append(p)
        if len(out) >= n:
            break
    return out


def playable_shots(env: Any, place: tuple[float, float] | None = None
                   ) -> Callable[[list[tuple[float, float, float, float, str]]],
                                 list[tuple[float, float, float, float, str]]] | None:
    """The map of candidates ``(angle, speed, side, top, source)`` to the shots their actions play: through the
    env's action type and back, float32 as every action is. The search then values exactly what the env will
    play: a break or a hard shot through a cluster is chaotic (a 1e-8 rad change of the cue angle, the float32
    rounding of an action, can drop the 8), and an action type may not express every direction (``ghost`` aim:
    only direct hits, within ``ghost_max_angle``). None for an env without action types."""
    u = env.unwrapped
    if getattr(u, "action_type", None) is None:
        return None

    def play(cands: list[tuple[float, float, float, float, str]]) -> list[tuple[float, float, float, float, str]]:
        out = []
        for angle, speed, side, top, src in cands:
            action = to_action(env, angle, speed, place=place, side=side, top=top)
            s = u.action_type.shot(u.table_state, action)
            out.append((s.angle, s.speed, s.side, s.top, src))
            play.actions[(s.angle, s.speed, s.side, s.top)] = action
        return out

    #: The action of every shot returned (a round trip is not always exact: near a full hit the ghost aim's
    #: float32 resolution is finer than its inverse), so the player plays the very action it searched.
    play.actions = {}  # type: ignore[attr-defined]
    return play


class ReferenceSearchPlayer:
    """Simulates candidate shots with the env's exact solver and plays the best for the position it leaves (see
    :func:`search_shot`)."""

    name = "search"

    def __init__(self, seed: int | None = 0, settings: SearchSettings | None = None):
        self.settings = settings or SearchSettings()
        self.rng = np.random.default_rng(seed)
        self.last: Outcome | None = None
        self._windows: dict = {}
        self._table: Any = None

    def reset(self, seed: int | None = None) -> None:
        if seed is not None:
            self.rng = np.random.default_rng(seed)
        self._windows = {}

    def act(self, env: Any, obs: Any) -> np.ndarray:
        """In a game it plays by the rules (candidates valued by the rules' call and the position they leave),
        breaks at full power, and with the cue ball in hand searches from the best few places
        (:func:`placement_candidates`) and plays the best shot of all."""
        ctx = shot_context(env)
        u = env.unwrapped
        if ctx.game is not None and ctx.game.game_state.break_shot:
            place, angle, speed = break_shot(ctx)
            self.last = None
            return to_action(env, angle, speed, place=place)
        if ctx.table is not self._table or len(self._windows) > 50_000:
            self._table, self._windows = ctx.table, {}
        places: list[Any] = [None]
        if ctx.place_area is not None:
            sigma = max(ctx.angle_noise, self.settings.ease_noise)
            places = placement_candidates(env, ctx, max(self.settings.placements, 1), sigma=sigma)
        best: tuple[Any, float, float, Outcome] | None = None
        for place in places:
            play = playable_shots(env, place)
            with u.cue_moved_to(place) if place is not None else contextlib.nullcontext():
                angle, speed, out = search_shot(ctx, self.settings, self.rng, self._windows, play)
            if best is None or out.robust > best[3].robust:
                best = (place, angle, speed, out, play)
        assert best is not None
        place, angle, speed, self.last, play = best
        with u.cue_moved_to(place) if place is not None else contextlib.nullcontext():
            pocket = self._called_pocket(ctx, angle, speed, self.last)
        action = to_action(env, angle, speed, place=place, pocket=pocket, side=self.last.side, top=self.last.top)
        searched = None if play is None else play.actions.get((angle, speed, self.last.side, self.last.top))
        if searched is not None:  # the shot dims of the very action searched (the call and place stay)
            shot_dims = 4 if getattr(u.action_type, "spin", False) else 2
            action[:shot_dims] = searched[:shot_dims]
        return action

    @staticmethod
    def _called_pocket(ctx: ShotContext, angle: float, speed: float, out: Outcome) -> int | None:
        """On the 8: the pocket the chosen shot sends it into (None if it does not)."""
        if ctx.game is None or not ctx.game.needs_called_pocket():
            return None
        spin = ctx.physics.friction == "spin"
        shot = ctx.balls.strike(ctx.cue, angle, speed, **({"side": out.side, "top": out.top} if spin else {}))
        res = ctx.simulator.run(shot, validate=False)
        k = int(res.pocket[ctx.game.row_of[8]])
        return k if k >= 0 else None



# --- the candidates types' slots (billiards_env/envs/candidates.py before the games were compiled (2026-12-02)) ---------------------------------
# The Python slot lists of the ``candidates`` action and observation types, kept for tests/players/test_slots.py
# (the compiled players/slots.py must equal them). They run on a table state and the reference geometry above.

#: The cut limit of the fallback list when no shot has a cut <= MAX_CUT (as the geometric player).
FALLBACK_CUT = math.radians(88.0)
#: The least angle spread (rad) :func:`reference_next_shot_ease` assumes.
EASE_SPREAD = 0.002
#: A kick's speed: the launch speed that would still roll at ``KICK_ARRIVAL`` m/s over the path, times ``KICK_MARGIN``.
KICK_ARRIVAL = 0.8
KICK_MARGIN = 1.15
#: Aim offsets (rad) simulated around each kick's reflected aim.
KICK_FAN = (0.0, -0.008, 0.008, -0.02, 0.02, -0.04, 0.04, -0.07, 0.07)


@dataclass(frozen=True)
class Slot:
    """One candidate: pot ball ``target`` (row) in ``pocket`` (as ``envs/candidates.py`` ``Slot``)."""

    target: int
    pocket: int
    obj_angle: float
    half: float
    d_obj: float
    clear_obj: bool
    shot: ShotCandidate | None = None


def reference_shot_slots(state: Any, targets: tuple[int, ...], rng: tuple[float, float]) -> list[Slot]:
    """The pot slots with the cue ball where it lies (``_shot_slots``)."""
    b = state.balls
    shots: list[ShotCandidate] = []
    for cut in (MAX_CUT, FALLBACK_CUT):
        shots = ghost_ball_shots(b, state.table, state.physics, 0, list(targets), rng, cut)
        if shots:
            break
    return [Slot(s.target, s.pocket, s.obj_angle, s.window, s.d_obj,
                 _path_clear(b, s.target, s.obj_angle, s.d_obj), s) for s in shots]


def reference_in_hand_slots(state: Any, targets: tuple[int, ...]) -> list[Slot]:
    """The pot slots with the cue ball in hand (``_in_hand_slots``)."""
    b = state.balls
    out: list[tuple[float, Slot]] = []
    for j in targets:
        r = float(b.radius[j])
        for p in range(state.table.n_pockets):
            win = pocket_window(b.pos[j], r, state.table, p)
            if win is None:
                continue
            obj_angle, half, d_obj = win
            clear = _path_clear(b, j, obj_angle, d_obj)
            out.append((half * (1.0 if clear else 0.1), Slot(j, p, obj_angle, half, d_obj, clear)))
    out.sort(key=lambda t: -t[0])  # stable: ties keep (ball, pocket) order
    return [s for _, s in out]


def kick_points(cue: np.ndarray, target: np.ndarray, table: Any, radius: float, restitution: float
                ) -> list[tuple[int, np.ndarray]]:
    """``(cushion, point)`` for each one-rail kick from ``cue`` to ``target`` (ball centres)."""
    out: list[tuple[int, np.ndarray]] = []
    cx, cy = float(cue[0]), float(cue[1])
    tx, ty = float(target[0]), float(target[1])
    e = restitution
    lines = ((0, radius), (1, table.length - radius), (2, radius), (3, table.width - radius))
    for k, w in lines:
        if k < 2:  # vertical cushion x = w: (tx - w)(py - cy) = -e (w - cx)(ty - py)
            den = (tx - w) - e * (w - cx)
            if abs(den) < 1e-12 or (w - cx) * (w - tx) <= 0.0:
                continue
            p = np.array([w, ((tx - w) * cy - e * (w - cx) * ty) / den])
            if not (radius < p[1] < table.width - radius):
                continue
        else:
            den = (ty - w) - e * (w - cy)
            if abs(den) < 1e-12 or (w - cy) * (w - ty) <= 0.0:
                continue
            p = np.array([((ty - w) * cx - e * (w - cy) * tx) / den, w])
            if not (radius < p[0] < table.length - radius):
                continue
        out.append((k, p))
    return out


def reference_kick_candidates(state: Any, targets: tuple[int, ...], rng: tuple[float, float]
                              ) -> list[tuple[float, int, float, float]]:
    """The kicks worth simulating, ``(length, target, angle, speed)`` sorted (``_kick_slots`` before its batch)."""
    b = state.balls
    t = state.table
    rc = float(b.radius[0])
    cue = b.pos[0]
    cands: list[tuple[float, int, float, float]] = []  # (length, target, angle, speed)
    for j in targets:
        others = [k for k in range(len(b.ids)) if b.on_table[k] and k not in (0, j)]
        opos, orad = b.pos[others], b.radius[others] + rc
        for _, p in kick_points(cue, b.pos[j], t, rc, t.cushion_restitution):
            if np.any(np.hypot(*(t.pocket_xy - p).T) < t.pocket_radius + 2.0 * rc):
                continue  # the bounce would pass a pocket's mouth
            segs, _ = t.walls()
            if len(segs) and not on_rail_span(float(p[0]), float(p[1]), rc, segs, N_RAILS, 2.0 * rc):
                continue  # on a jaw table: the bounce point must be on a rail, clear of its ends
            if segment_blocked(cue, p, opos, orad) or segment_blocked(p, b.pos[j], opos, orad):
                continue
            d = float(np.hypot(*(p - cue))) + float(np.hypot(*(b.pos[j] - p)))
            v = KICK_MARGIN * launch_speed(d, KICK_ARRIVAL, *state.physics.path_args)
            cands.append((d, j, aim_angle(cue, p), min(max(v, rng[0]), rng[1])))
    cands.sort()
    return cands


def reference_kick_slots(state: Any, targets: tuple[int, ...], rng: tuple[float, float]) -> list[Slot]:
    """Kicks at the legal balls, each verified by a fan of simulated aims, shortest first (``_kick_slots``)."""
    b = state.balls
    cands = reference_kick_candidates(state, targets, rng)
    if not cands:
        return []
    fan = np.asarray(KICK_FAN)
    angles = np.concatenate([c[2] + fan for c in cands])
    speeds = np.repeat([c[3] for c in cands], len(fan))
    res = run_shots(state.simulator, b, angles, speeds, validate=False)
    hits = (res.first_contact.reshape(len(cands), len(fan)) == np.array([c[1] for c in cands])[:, None]) & \
        (res.pocket[:, 0] < 0).reshape(len(cands), len(fan))
    out = []
    for k, (d, j, angle, speed) in enumerate(cands):
        ok = np.flatnonzero(hits[k][np.argsort(fan)])
        if len(ok) == 0:
            continue
        a = float(angle + np.sort(fan)[ok[len(ok) // 2]])  # the middle of the aims that hit it
        shot = ShotCandidate(j, -1, a, speed, speed, math.nan, 0.0, d, 0.0, 0.0, 0.0, True, True, False, 0.0)
        out.append(Slot(j, -1, math.nan, 0.0, 0.0, True, shot))
    return out


def reference_candidate_slots(state: Any, n: int, speed_range: tuple[float, float] | None = None
                              ) -> tuple[tuple[Slot, ...], Slot | None]:
    """``(slots, kick)`` of ``candidate_slots`` (no memo)."""
    if speed_range is None:
        speed_range = state.settings.speed_range
    view = state.view
    targets = view.targets
    kick: Slot | None = None
    if view.break_shot:
        slots: tuple[Slot, ...] = ()
    elif view.place_area is not None:
        slots = tuple(reference_in_hand_slots(state, targets)[:max(n - 1, 1)])
    else:
        slots = tuple(reference_shot_slots(state, targets, speed_range)[:max(n - 1, 1)])
        if n > 1 and not any(s.shot.clear for s in slots):
            kicks = reference_kick_slots(state, targets, speed_range)
            kick = kicks[0] if kicks else None
    return slots, kick


def reference_next_shot_ease(state: Any, n: int) -> float:
    """``next_shot_ease``: the best slot's score through ``pot_probability`` (0 without a pot)."""
    slots, _ = reference_candidate_slots(state, n)
    best = max((s.shot.score for s in slots if s.shot is not None), default=0.0)
    return pot_probability(best, max(state.settings.angle_noise, EASE_SPREAD))


def _path_clear(b: Any, j: int, obj_angle: float, d_obj: float) -> bool:
    """Whether ball ``j`` rolls ``d_obj`` along ``obj_angle`` without touching another object ball."""
    others = [k for k in range(len(b.ids)) if b.on_table[k] and k not in (0, j)]
    if not others:
        return True
    o = b.pos[j]
    return not segment_blocked(o, o + direction_vector(obj_angle) * d_obj, b.pos[others],
                               b.radius[others] + float(b.radius[j]))


def reference_slot_values(state: Any, cands: Any, n_slots: int, speed_max: float) -> np.ndarray:
    """The ``candidates`` observation's slot values as the Python loop over the slots made them (before the games were compiled (2026-12-02))."""
    from billiards_env.envs.candidates import EASY_TOLERANCE, SLOT_FEATURES
    from billiards_env.physics.aim import wrap_angle

    out = np.zeros((n_slots, SLOT_FEATURES), np.float32)
    t = state.table
    px, py = t.pocket_xy[:, 0] / t.length, t.pocket_xy[:, 1] / t.width
    numbers = state.numbers
    if cands.kick is not None:
        s = cands.kick
        row = out[n_slots - 1]
        row[0] = 1.0
        row[1] = numbers[s.target] / 15.0
        row[2] = row[3] = -1.0
        row[5] = min(s.shot.d_cue / t.length, 1.0)
        row[8] = row[9] = 1.0
        row[11] = s.shot.speed / speed_max
    for k, s in enumerate(cands.slots):
        row = out[k]
        row[0] = 1.0
        row[1] = numbers[s.target] / 15.0
        row[2], row[3] = px[s.pocket], py[s.pocket]
        row[6] = min(s.d_obj / t.length, 1.0)
        shot = s.shot
        if shot is None:
            row[7] = min(s.half / (math.pi / 8.0), 1.0)
            row[8] = 1.0 if s.clear_obj else 0.0
            continue
        row[4] = wrap_angle(s.obj_angle - shot.angle) / (math.pi / 2.0)
        row[5] = min(shot.d_cue / t.length, 1.0)
        row[7] = min(shot.tolerance / EASY_TOLERANCE, 1.0)
        row[8] = 1.0 if shot.clear else 0.0
        row[9] = 1.0 if shot.reachable else 0.0
        row[10] = 1.0 if shot.scratch_risk else 0.0
        row[11] = shot.speed / speed_max
    return np.clip(out.reshape(-1), -1.0, 1.0)
