"""Snooker players: geometric (:func:`snooker_geometric_shot`) and search (:func:`snooker_search_shot`).

Both are decision functions over plain physics objects (the balls, the simulator with its table and physics) and
the rules' :class:`~billiards_env.rules.snooker.SnookerState`, no env. A decision is a :class:`SnookerShot`: the cue
direction, speed and tip offsets, where to place the cue ball when it is in hand (in the D), and the declarations
(the colour nominated, the free ball).

- **geometric**: ghost-ball aiming (:func:`billiards_env.players.shots.ghost_ball_shots`) at every ball on, the shot
  with the most expected points (the pot probability of its angular tolerance under the angle noise, times the
  ball's value: the black before the yellow when on a colour); with the cue ball in hand, the place in the D
  that leaves the easiest pot.
- **search**: candidate shots (the best ghost-ball shots at several speeds and, under the spin model, with stun,
  draw, follow and side, plus a sweep of soft directions for safeties) simulated in one batch
  (:func:`billiards_env.physics.batch.run_shots`), judged by the rules' compiled judge
  (:func:`billiards_env.rules.snooker.judge_batch`: points, penalty, the next ball on), and valued by the points
  plus the position they leave: the chance of potting the next ball on (the striker's when he keeps the table, the
  opponent's when he does not; :func:`pot_chances`, compiled). The best few are re-run under
  small errors and the most robust is played; with the cue ball in hand the search runs from the best places in
  the D.
"""
from __future__ import annotations

import math
from typing import Any
from dataclasses import dataclass

import numpy as np
from numba import njit

from billiards_env.games.snooker_layout import SNOOKER_COLOURS, d_point, nearest_point_in_d, spot_snooker_colours
from billiards_env.physics import Balls, Simulator, Table
from billiards_env.physics.aim import aim_angle, direction_vector, ghost_ball_position, pocket_window, segment_blocked
from billiards_env.physics.batch import run_shots
from billiards_env.physics.spin_collide import MAX_TIP_OFFSET
from billiards_env.rules.snooker import (COLOUR_VALUES, VALUE_NAMES, Snooker, SnookerState, ball_on_mask,
                                         judge_batch)

from .context import BasePlayer, to_action
from .shots import MAX_CUT, ghost_ball_shots, pot_probability, speed_to_travel

#: Default speed range of snooker shots (m/s).
SPEED_RANGE = (0.2, 7.0)
#: Grid (m) of the object-ball positions whose pocket windows the next-pot chances cache: a window is the same to
#: well within the noise for balls less than a millimetre apart.
WINDOW_GRID = 5e-4


@dataclass(frozen=True)
class SnookerShot:
    """A snooker decision: strike the cue ball along ``angle`` (rad) at ``speed`` (m/s) with tip offsets ``side``,
    ``top`` (spin model), from ``place`` when the cue ball is in hand (a point of the D, else None), declaring
    ``nominated`` (the colour, when on a colour) and ``free_ball``. ``target``: the row aimed at (-1: none);
    ``value``: the player's estimate of the shot (points for the geometric player, the search's total)."""

    angle: float
    speed: float
    side: float = 0.0
    top: float = 0.0
    place: tuple[float, float] | None = None
    nominated: str | None = None
    free_ball: str | None = None
    target: int = -1
    value: float = 0.0


def _cue_row(values: np.ndarray) -> int:
    return int(np.flatnonzero(np.asarray(values) == 0)[0])


def target_rows(balls: Balls, values: np.ndarray, state: SnookerState, free_ball: bool = False) -> list[int]:
    """Rows of the balls the striker may aim at: the balls on (:func:`~billiards_env.rules.snooker.ball_on_mask`),
    and with a free ball every colour on the table."""
    mask = ball_on_mask(values, state.on) & balls.on_table
    if free_ball:
        mask |= (np.asarray(values) >= 2) & balls.on_table
    return [int(j) for j in np.flatnonzero(mask)]


def _declarations(state: SnookerState, value: int, free: bool) -> tuple[str | None, str | None]:
    """``(nominated, free_ball)`` for a shot at a ball of ``value``."""
    if value < 2:
        return None, None
    name = VALUE_NAMES[value]
    if state.on == "colour":
        return name, None
    if free and (state.on == "red" or name != state.on):
        return None, name
    return None, None


def _worth(values: np.ndarray, state: SnookerState) -> np.ndarray:
    """Points a pot of each row scores: its value when it is on, else (a free ball) the value of the ball on."""
    on = ball_on_mask(values, state.on)
    return np.where(on, np.maximum(values, 1), 1 if state.on == "red" else max(state.on_value, 1))


def _with_cue(balls: Balls, cue: int, place: tuple[float, float] | None) -> Balls:
    if place is None:
        return balls
    b = balls.copy()
    b.pos[cue] = place
    b.on_table[cue] = True
    return b


def d_placements(balls: Balls, sim: Simulator, cue: int, targets: list[int], n: int, sigma: float = 0.003,
                 windows: dict | None = None) -> list[tuple[float, float]]:
    """Ball in hand: up to ``n`` legal places in the D (at least a ball apart) that leave the easiest pot of a ball
    of ``targets``, best first. Tried: a grid over the D (:func:`~billiards_env.games.snooker_layout.d_point`) and, for
    every target and pocket, the points behind its ghost ball moved into the D; scored by
    :func:`pot_chances`."""
    table = sim.table
    b = balls
    r = float(b.radius[cue])
    others_on = b.on_table.copy()
    others_on[cue] = False
    places: list[tuple[float, float]] = []

    def legal(x: float, y: float) -> tuple[float, float]:
        return nearest_point_in_d(x, y, b.pos, others_on, b.radius, cue, table)

    for u in np.linspace(-0.9, 0.9, 7):
        for v in (-0.6, 0.0, 0.7):
            places.append(legal(*d_point(u, v, table)))
    for j in targets:
        for p in range(table.n_pockets):
            win = pocket_window(b.pos[j], float(b.radius[j]), table, p)
            if win is None:
                continue
            ghost = ghost_ball_position(b.pos[j], win[0], r + float(b.radius[j]))
            for back in (0.3, 0.8):
                x, y = ghost - back * direction_vector(win[0])
                places.append(legal(float(x), float(y)))
    pos = np.repeat(b.pos[None], len(places), axis=0)
    pos[:, cue] = places
    on = np.repeat(b.on_table[None], len(places), axis=0)
    on[:, cue] = True
    mask = np.zeros(on.shape, bool)
    mask[:, targets] = True
    ease = pot_chances(table, b.radius, pos, on, cue, mask, sigma, windows)
    out: list[tuple[float, float]] = []
    for k in np.argsort(-ease, kind="stable"):
        p = places[k]
        if all(math.hypot(p[0] - q[0], p[1] - q[1]) > 2.0 * r for q in out):
            out.append(p)
        if len(out) >= n:
            break
    return out


# --- the chance of the next pot (compiled) ---------------------------------------------------------------------------

def _windows_array(table: Table, radius: np.ndarray, pos: np.ndarray, on: np.ndarray, targets: np.ndarray,
                   windows: dict) -> np.ndarray:
    """``(N, B, P, 3)``: each target's pocket windows (direction, half-width, distance; NaN: no window) in each
    layout, from :func:`~billiards_env.physics.aim.pocket_window` through the cache ``windows`` (keyed as
    :func:`~billiards_env.players.search.next_shot_ease` keys it: a window per ``WINDOW_GRID`` cell)."""
    n, b = on.shape
    out = np.full((n, b, table.n_pockets, 3), np.nan)
    q = WINDOW_GRID
    for k, j in zip(*np.nonzero(targets & on)):
        rj = float(radius[j])
        o = pos[k, j]
        cell = (rj, round(float(o[0]) / q), round(float(o[1]) / q))
        wins = windows.get(cell)
        if wins is None:
            wins = [(p, w) for p in range(table.n_pockets) if (w := pocket_window(o, rj, table, p)) is not None]
            windows[cell] = wins
        for p, w in wins:
            out[k, j, p] = w
    return out


@njit(cache=True)
def _blocked(ax, ay, bx, by, pos_k, on_k, radius, skip1, skip2, clear):
    """Whether a ball of ``pos_k`` on the table (but ``skip1``, ``skip2``) comes closer than ``clear + r`` to the
    segment ``a -> b``."""
    dx = bx - ax
    dy = by - ay
    l2 = max(dx * dx + dy * dy, 1e-24)
    for m in range(pos_k.shape[0]):
        if m == skip1 or m == skip2 or not on_k[m]:
            continue
        t = min(max(((pos_k[m, 0] - ax) * dx + (pos_k[m, 1] - ay) * dy) / l2, 0.0), 1.0)
        ex = pos_k[m, 0] - ax - t * dx
        ey = pos_k[m, 1] - ay - t * dy
        need = clear + radius[m]
        if ex * ex + ey * ey < need * need:
            return True
    return False


@njit(cache=True)
def _pot_chances(pos, on, radius, cue, targets, win, length, width, cos_max, sigma):
    """Per layout, the pot chance of its easiest ghost-ball shot at a ball of ``targets``: the tolerance of
    :func:`~billiards_env.players.search.next_shot_ease` (the window's half-width scaled by ``(r_c + r_o)
    cos(cut) / (d + r_c + r_o)``, a tenth when a path is blocked; cuts beyond ``acos(cos_max)`` and ghost balls off
    the table do not count) through ``erf(tol / (sqrt2 sigma))``."""
    n = pos.shape[0]
    out = np.zeros(n)
    rc = radius[cue]
    for k in range(n):
        if not on[k, cue]:
            continue
        cx = pos[k, cue, 0]
        cy = pos[k, cue, 1]
        best = 0.0
        for j in range(pos.shape[1]):
            if j == cue or not targets[k, j] or not on[k, j]:
                continue
            ox = pos[k, j, 0]
            oy = pos[k, j, 1]
            contact = rc + radius[j]
            for p in range(win.shape[2]):
                ang = win[k, j, p, 0]
                if ang != ang:
                    continue
                ux = math.cos(ang)
                uy = math.sin(ang)
                gx = ox - contact * ux
                gy = oy - contact * uy
                if gx < rc or gx > length - rc or gy < rc or gy > width - rc:
                    continue
                vx = gx - cx
                vy = gy - cy
                d = math.hypot(vx, vy)
                cos_cut = (vx * ux + vy * uy) / max(d, 1e-12)
                if cos_cut < cos_max:
                    continue
                tol = win[k, j, p, 1] * contact * cos_cut / (d + contact)
                if tol <= best:
                    continue
                dobj = win[k, j, p, 2]
                if _blocked(cx, cy, gx, gy, pos[k], on[k], radius, cue, j, rc) or \
                        _blocked(ox, oy, ox + ux * dobj, oy + uy * dobj, pos[k], on[k], radius, cue, j, radius[j]):
                    tol /= 10.0
                best = max(best, tol)
        out[k] = math.erf(best / (math.sqrt(2.0) * max(sigma, 1e-12)))
    return out


def pot_chances(table: Table, radius: np.ndarray, pos: np.ndarray, on: np.ndarray, cue: int,
                targets: np.ndarray, sigma: float, windows: dict | None = None,
                max_cut: float = MAX_CUT) -> np.ndarray:
    """For ``N`` layouts (``pos`` (N, B, 2), ``on`` (N, B)), the chance of potting the easiest ghost-ball shot at a
    ball of ``targets`` ((N, B) bool) when the cue angle errs with spread ``sigma`` (rad): the compiled
    equivalent of :func:`~billiards_env.players.search.next_shot_ease` (the same tolerance and window cache)."""
    windows = {} if windows is None else windows
    pos = np.ascontiguousarray(pos, dtype=float)
    on = np.ascontiguousarray(on, dtype=np.bool_)
    targets = np.ascontiguousarray(targets, dtype=np.bool_)
    if len(pos) == 0:
        return np.zeros(0)
    win = _windows_array(table, radius, pos, on, targets, windows)
    return _pot_chances(pos, on, np.ascontiguousarray(radius, dtype=float), int(cue), targets, win,
                        float(table.length), float(table.width), math.cos(max_cut), float(sigma))


# --- geometric -------------------------------------------------------------------------------------------------------

def snooker_geometric_shot(balls: Balls, sim: Simulator, state: SnookerState, values: np.ndarray,
                           speed_range: tuple[float, float] = SPEED_RANGE, snookered: bool = False,
                           rules: Snooker | None = None, sigma: float = 0.003) -> SnookerShot:
    """The geometric player's shot: the ghost-ball shot with clear paths at a ball on with the most expected
    points (pot probability under an angle error ``sigma`` times the ball's value; a free ball when ``snookered``
    and the rules allow one), from the best place in the D when the cue ball is in hand; without one, a firm
    full-ball hit on the nearest ball on in plain view."""
    rules = rules or Snooker()
    values = np.asarray(values)
    cue = _cue_row(values)
    free = rules.free_ball_available(state, snookered)
    targets = target_rows(balls, values, state, free)
    place = None
    if state.ball_in_hand:
        place = d_placements(balls, sim, cue, targets, 1, sigma)[0]
    b = _with_cue(balls, cue, place)
    worth = _worth(values, state)
    best, best_value = None, -1.0
    for cut in (MAX_CUT, math.radians(88.0)):
        for s in ghost_ball_shots(b, sim.table, sim.physics, cue, targets, speed_range, cut):
            v = pot_probability(s.score, sigma) * worth[s.target]
            if s.clear and v > best_value:
                best, best_value = s, v
        if best is not None:
            break
    if best is not None:
        nom, fb = _declarations(state, int(values[best.target]), free)
        return SnookerShot(best.angle, best.speed, place=place, nominated=nom, free_ball=fb, target=best.target,
                           value=best_value)
    # no clear pot: a firm full-ball contact on the nearest ball on in plain view (else the nearest)
    others = [k for k in range(len(b)) if b.on_table[k] and k != cue]

    def in_view(j: int) -> bool:
        rest = [k for k in others if k != j]
        return not segment_blocked(b.pos[cue], b.pos[j], b.pos[rest], b.radius[rest] + b.radius[cue])

    dist = {j: float(np.hypot(*(b.pos[j] - b.pos[cue]))) for j in targets}
    seen = [j for j in targets if in_view(j)]
    j = min(seen or targets, key=dist.__getitem__)
    speed = min(max(speed_to_travel(dist[j] + 1.0, 0.3, sim.physics), speed_range[0]), speed_range[1])
    nom, fb = _declarations(state, int(values[j]), free)
    return SnookerShot(aim_angle(b.pos[cue], b.pos[j]), float(speed), place=place, nominated=nom, free_ball=fb,
                       target=j, value=0.0)


# --- search ----------------------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class SnookerSearchSettings:
    """How wide the snooker search looks and how it values a shot."""

    n_geometric: int = 8  #: ghost-ball shots refined
    angle_offsets: tuple[float, ...] = (0.0, 0.0015, -0.0015)  #: rad
    speed_factors: tuple[float, ...] = (0.7, 1.0, 1.5, 2.3)  #: times the ghost-ball speed
    #: tip offsets (side, top) tried under the spin model: stun, draw, follow, left and right side
    spins: tuple[tuple[float, float], ...] = ((0.0, 0.0), (0.0, -0.3), (0.0, 0.3), (-0.25, 0.0), (0.25, 0.0))
    sweep_angles: int = 48  #: soft shots in every direction (safeties)
    sweep_speeds: tuple[float, ...] = (0.08, 0.2)  #: fractions of the speed range
    top_k: int = 6  #: best candidates re-run under small errors
    robust_samples: int = 6  #: re-runs of each of the best without shot noise in the env...
    noisy_samples: int = 16  #: ...and with it
    robust_angle: float = 0.0015  #: rad, when the env has no angle noise
    robust_speed: float = 0.03  #: relative
    robust_tip: float = 0.02  #: ball radii
    keep_value: float = 2.0  #: worth of keeping the table (before position)
    position_weight: float = 4.0  #: worth of a sure next pot when keeping the table
    safety_weight: float = 4.0  #: cost of leaving the opponent a sure pot
    in_hand_ease: float = 0.7  #: the opponent's assumed pot chance with the cue ball in hand after an in-off
    missed_pot_value: float = -2.0  #: worth of a pot that misses under the shot noise (the opponent's chance)
    win_value: float = 100.0  #: a won (lost) frame
    ease_noise: float = 0.003  #: angle spread (rad) the next shot's pot chance assumes
    placements: int = 3  #: places in the D searched from


def _candidates(b: Balls, sim: Simulator, cue: int, targets: list[int], values: np.ndarray, state: SnookerState,
                speed_range: tuple[float, float], st: SnookerSearchSettings, spin: bool,
                sigma: float) -> tuple[np.ndarray, np.ndarray]:
    """``(angle, speed, side, top)`` rows: each of the best ghost-ball shots at the angle offsets and speed factors
    (with the tip variants under the spin model), then the sweep; and per row the pot chance of its ghost-ball
    shot under an angle error ``sigma`` (1 for the sweep)."""
    lo, hi = speed_range
    shots = ghost_ball_shots(b, sim.table, sim.physics, cue, targets, speed_range, math.radians(85.0))
    worth = _worth(values, state)
    shots.sort(key=lambda s: -pot_probability(s.score, st.ease_noise) * worth[s.target])
    spins = st.spins if spin else ((0.0, 0.0),)
    out = []
    chance = []
    for s in shots[:st.n_geometric]:
        p = pot_probability(s.score, sigma)
        for da in st.angle_offsets:
            out.append((s.angle + da, min(max(s.speed, lo), hi), 0.0, 0.0))
            chance.append(p)
        for f in st.speed_factors:
            for side, top in spins:
                if f != 1.0 or side or top:
                    out.append((s.angle, min(max(s.speed * f, lo), hi), side, top))
                    chance.append(p)
    base = aim_angle(b.pos[cue], b.pos[targets[0]]) if targets else 0.0
    for k in range(st.sweep_angles):
        for f in st.sweep_speeds:
            out.append((base + 2.0 * math.pi * k / st.sweep_angles, lo + f * (hi - lo), 0.0, 0.0))
            chance.append(1.0)
    return np.array(out, dtype=float).reshape(-1, 4), np.array(chance, dtype=float)


def _evaluate(b: Balls, sim: Simulator, state: SnookerState, values: np.ndarray, cue: int, free: int,
              shots: np.ndarray, st: SnookerSearchSettings, sigma: float, windows: dict,
              full: bool) -> tuple[np.ndarray, np.ndarray]:
    """Simulate ``shots`` (N, 4) in one batch (``free``: the value of the nominated free ball, 0: none) and value
    each: ``(totals, scored)`` (N,), ``scored`` the shots that score without a foul. The value is the
    points scored minus the penalty, plus ``keep_value`` and the position term when the striker keeps the table,
    minus the opponent's chances when he does not, or +-``win_value`` when the frame ends. Position terms are
    computed for the rows within reach of the best (``full``: for every row)."""
    spin = sim.physics.has_spin
    res = run_shots(sim, b, shots[:, 0], shots[:, 1], ball=cue, side=shots[:, 2] if spin else None,
                    top=shots[:, 3] if spin else None, validate=False)
    fouls, penalty, points, _, respot, next_on, _, _, frame_end = judge_batch(
        res.first_contact, res.pocket, values, cue, state.on_value, 0, free, state.reds, state.colour_mask)
    me = state.shooter
    base = (points - penalty).astype(float)
    keep = (points > 0) & (fouls == 0) & ~frame_end
    my = state.score[me] + points
    their = state.score[1 - me] + penalty
    ended = np.where(my > their, st.win_value, np.where(my < their, -st.win_value, 0.0)) + base
    total = np.where(frame_end, ended, base + np.where(keep, st.keep_value, 0.0))
    in_off = res.pocket[:, cue] >= 0
    total = np.where(in_off & ~frame_end, total - st.safety_weight * st.in_hand_ease, total)
    live = ~frame_end & ~in_off
    near = np.flatnonzero(live & ((total >= total.max() - st.keep_value - st.position_weight) | full))
    if len(near):
        pos = res.pos[near].copy()
        on = res.on_table[near].copy()
        col_rows = {VALUE_NAMES[int(v)]: int(r) for r, v in enumerate(values) if v >= 2}
        targets = np.zeros(on.shape, bool)
        for q, k in enumerate(near):
            if respot[k]:
                spot = {c: col_rows[c] for c in SNOOKER_COLOURS if respot[k] & (1 << COLOUR_VALUES[c])}
                spot_snooker_colours(pos[q], on[q], b.radius, sim.table, spot)
            code = int(next_on[k])
            targets[q] = (values == 1) if code == 1 else ((values >= 2) if code == 0 else (values == code))
        ease = pot_chances(sim.table, b.radius, pos, on, cue, targets, sigma, windows)
        term = np.where(keep[near], st.position_weight, -st.safety_weight) * ease
        total[near] += term
    return total, keep | (frame_end & (points > 0) & (fouls == 0))


def snooker_search_shot(balls: Balls, sim: Simulator, state: SnookerState, values: np.ndarray,
                        settings: SnookerSearchSettings | None = None,
                        speed_range: tuple[float, float] = SPEED_RANGE, snookered: bool = False,
                        rules: Snooker | None = None, angle_noise: float = 0.0, speed_noise: float = 0.0,
                        tip_noise: float = 0.0, rng: np.random.Generator | None = None,
                        windows: dict | None = None) -> SnookerShot:
    """The search player's shot (see the module docstring). ``angle_noise``, ``speed_noise``, ``tip_noise``: the
    env's shot noise (the robustness runs use it, or the settings' small defaults). ``windows``: a pocket-window
    cache for one table, kept across decisions."""
    st = settings or SnookerSearchSettings()
    rules = rules or Snooker()
    rng = rng or np.random.default_rng(0)
    windows = {} if windows is None else windows
    values = np.ascontiguousarray(values, dtype=np.int64)
    cue = _cue_row(values)
    spin = sim.physics.has_spin
    lo, hi = speed_range
    free_ok = rules.free_ball_available(state, snookered)
    targets = target_rows(balls, values, state, free_ok)
    sigma = max(angle_noise, st.ease_noise)
    places: list[tuple[float, float] | None] = [None]
    if state.ball_in_hand:
        places = list(d_placements(balls, sim, cue, targets, max(st.placements, 1), sigma, windows))
    best: SnookerShot | None = None
    best_score = -math.inf
    for place in places:
        b = _with_cue(balls, cue, place)
        exact = angle_noise == 0.0 and speed_noise == 0.0 and (not spin or tip_noise == 0.0)
        shots, chance = _candidates(b, sim, cue, targets, values, state, speed_range, st, spin, sigma)
        totals, scored = _evaluate(b, sim, state, values, cue, 0, shots, st, sigma, windows, False)
        if free_ok:  # a free ball: each shot judged with the ball it hits first (if not on) as the free ball
            f_tot, f_scored = _evaluate_free(b, sim, state, values, cue, shots, st, sigma, windows)
            better = f_tot > totals
            totals, scored = np.where(better, f_tot, totals), np.where(better, f_scored, scored)
        # under shot noise a pot goes in with the chance of its ghost-ball shot's tolerance
        expected = totals if exact else np.where(scored, chance * totals + (1.0 - chance) * st.missed_pot_value,
                                                 totals)
        order = np.argsort(-expected, kind="stable")[:st.top_k]
        samples = st.robust_samples if exact else st.noisy_samples
        sa = angle_noise or st.robust_angle
        ss = speed_noise or st.robust_speed
        stn = (tip_noise or st.robust_tip) if spin else 0.0
        noisy = np.repeat(shots[order], samples, axis=0)
        m = len(noisy)
        noisy[:, 0] += rng.normal(0.0, sa, m)
        noisy[:, 1] = np.clip(noisy[:, 1] * (1.0 + rng.normal(0.0, ss, m)), lo, hi)
        if stn:
            noisy[:, 2] += rng.normal(0.0, stn, m)
            noisy[:, 3] += rng.normal(0.0, stn, m)
            r = np.hypot(noisy[:, 2], noisy[:, 3])
            f = np.where(r > 0.98 * MAX_TIP_OFFSET, 0.98 * MAX_TIP_OFFSET / np.maximum(r, 1e-12), 1.0)
            noisy[:, 2:] *= f[:, None]
        n_tot = _evaluate(b, sim, state, values, cue, 0, noisy, st, sigma, windows, True)[0]
        if free_ok:
            n_tot = np.maximum(n_tot, _evaluate_free(b, sim, state, values, cue, noisy, st, sigma, windows,
                                                     True)[0])
        means = n_tot.reshape(len(order), samples).mean(axis=1)
        # without noise the unperturbed outcome is what happens (the re-runs break ties towards margin); with
        # noise the re-runs sample what may happen, and the pot-chance estimate steadies them
        robust = totals[order] + 0.5 * means if exact else 0.5 * (expected[order] + means)
        q = int(np.argmax(robust))
        if robust[q] > best_score:
            k = int(order[q])
            a, s, sd, tp = shots[k]
            first = _first_row(b, sim, cue, shots[k])
            value = int(values[first]) if first >= 0 else 0
            nomd, fb = _declarations(state, value, free_ok)
            best_score = float(robust[q])
            best = SnookerShot(float(a), float(s), float(sd), float(tp), place, nomd, fb, first, float(totals[k]))
    assert best is not None
    return best


def _evaluate_free(b, sim, state, values, cue, shots, st, sigma, windows, full=False
                   ) -> tuple[np.ndarray, np.ndarray]:
    """:func:`_evaluate` of ``shots`` when a ball not on that the cue ball hits first is the nominated free ball
    (-inf for the shots that hit a ball on first or nothing)."""
    out = np.full(len(shots), -math.inf)
    scored = np.zeros(len(shots), bool)
    spin = sim.physics.has_spin
    res = run_shots(sim, b, shots[:, 0], shots[:, 1], ball=cue, side=shots[:, 2] if spin else None,
                    top=shots[:, 3] if spin else None, validate=False)
    first_val = np.where(res.first_contact >= 0, values[np.maximum(res.first_contact, 0)], -1)
    for c in state.colours:
        v = COLOUR_VALUES[c]
        if c == state.on:
            continue
        rows = np.flatnonzero(first_val == v)
        if len(rows):
            out[rows], scored[rows] = _evaluate(b, sim, state, values, cue, v, shots[rows], st, sigma, windows, full)
    return out, scored


def _first_row(b: Balls, sim: Simulator, cue: int, shot: np.ndarray) -> int:
    """The row the shot's cue ball hits first (-1: none)."""
    spin = sim.physics.has_spin
    res = run_shots(sim, b, shot[0:1], shot[1:2], ball=cue, side=shot[2:3] if spin else None,
                    top=shot[3:4] if spin else None, validate=False)
    return int(res.first_contact[0])



# --- as players of the env (state in, shot out) ----------------------------------------------------------------------

class _SnookerPlayer(BasePlayer):
    """A snooker decision function as a player (:class:`~billiards_env.players.context.BasePlayer`: ``shot(state,
    obs, codec)``, ``act(state, obs, codec)``): it reads the frame from the table state's game session and plays its
    shot as ``codec`` expresses it."""

    name = "snooker"

    def __init__(self, seed: int | None = 0) -> None:
        self.rng = np.random.default_rng(seed)
        self.last: SnookerShot | None = None

    def reset(self, seed: int | None = None) -> None:
        if seed is not None:
            self.rng = np.random.default_rng(seed)

    def _shot(self, state: Any, session: Any, snookered_now: bool) -> SnookerShot:
        raise NotImplementedError

    def choose(self, state: Any, obs: Any, codec: Any) -> np.ndarray:
        """The action (in ``codec``) of the decision function's shot on ``state``."""
        from billiards_env.rules.snooker import snookered

        session = state.game
        s = session.game_state
        b = state.balls
        snk = bool(not s.ball_in_hand and snookered(b.pos, b.on_table, b.radius, session.values, s.on, 0))
        self.last = shot = self._shot(state, session, snk)
        return to_action(codec, state, shot.angle, shot.speed, place=shot.place, side=shot.side, top=shot.top)


class SnookerGeometricPlayer(_SnookerPlayer):
    """:func:`snooker_geometric_shot` as a player."""

    name = "geometric"

    def _shot(self, state: Any, session: Any, snookered_now: bool) -> SnookerShot:
        st = state.settings
        return snooker_geometric_shot(state.balls, state.simulator, session.game_state, session.values, st.speed_range,
                                      snookered_now, session.rules, max(st.angle_noise, 0.003))


class SnookerSearchPlayer(_SnookerPlayer):
    """:func:`snooker_search_shot` as a player (its pocket windows cached per table)."""

    name = "search"

    def __init__(self, seed: int | None = 0, settings: SnookerSearchSettings | None = None) -> None:
        super().__init__(seed)
        self.settings = settings
        self._windows: dict = {}

    def reset(self, seed: int | None = None) -> None:
        super().reset(seed)
        self._windows = {}

    def _shot(self, state: Any, session: Any, snookered_now: bool) -> SnookerShot:
        st = state.settings
        return snooker_search_shot(state.balls, state.simulator, session.game_state, session.values, self.settings,
                                   st.speed_range, snookered_now, session.rules, st.angle_noise, st.speed_noise,
                                   st.tip_noise, self.rng, self._windows)


__all__ = ["SPEED_RANGE", "SnookerGeometricPlayer", "SnookerSearchPlayer", "SnookerShot", "target_rows", "pot_chances", "d_placements", "snooker_geometric_shot",
           "SnookerSearchSettings", "snooker_search_shot"]
