"""Three-cushion players: search over spin shots (:func:`three_cushion_shot`), and a geometric baseline
(:func:`three_cushion_geometric_shot`).

Scoring in three-cushion is a matter of exact paths: the cue ball must meet both object balls with three cushions
before the second, and side spin bends every rebound. So the player simulates: a sweep of directions (and aims at
each object ball from full to thin) at several speeds and tip offsets (running and reverse side, follow and draw),
all in one batch (:func:`billiards_env.physics.batch.run_shots` with the event logs), and reads each shot's
outcome with the rules' compiled scan (:func:`billiards_env.rules.three_cushion.scan_carom_batch`). Shots that
nearly score (both balls met with too few cushions, or one ball and three cushions) are refined with finer angles
and speeds. Among the shots that score, the one whose neighbours (small errors of angle, speed and tip) score most
often is played: a robust point, not a lucky one. Without a point, the shot that came closest.

Decision functions over plain physics objects (a simulator and the balls), no env::

    from billiards_env.games.carom_layout import carom_balls
    from billiards_env.physics import Physics, Simulator
    from billiards_env.physics.table import carom_table
    from billiards_env.players.three_cushion import three_cushion_shot

    sim = Simulator(carom_table(), Physics(friction="spin"))
    balls = carom_balls(sim.table)
    shot = three_cushion_shot(sim, balls, cue=0, opponent=1, red=2)
    shot.angle, shot.speed, shot.side, shot.top, shot.point
"""
from __future__ import annotations

import math
from typing import Any
from dataclasses import dataclass

import numpy as np

from billiards_env.physics import Balls, Physics, Simulator, Table
from billiards_env.physics.aim import aim_angle, deflected_cue_velocity, offset_aim_angle, ray_cushion_hit
from billiards_env.physics.batch import run_shots
from billiards_env.physics.codes import ROLLING
from billiards_env.physics.motion import launch_speed, speed_after_distance, stop_distance
from billiards_env.physics.spin_collide import MAX_TIP_OFFSET
from billiards_env.rules.three_cushion import CUSHIONS_NEEDED, scan_carom_batch

from .context import BasePlayer, to_action

#: Tip offset (ball radii above the centre) that sets a struck ball rolling at once (``2/5 R``).
NATURAL_ROLL = 0.4
#: Under the spin model: how many of its scoring aims the geometric player has the engine play (one batch).
GEOMETRIC_CHECKED = 40


@dataclass(frozen=True)
class CaromSearchSettings:
    """How wide the three-cushion search looks (defaults: about 4,000 shots, then refinement)."""

    sweep_angles: int = 240  #: directions of the uniform sweep
    cut_aims: int = 13  #: aims at each object ball, from one thin edge to the other
    speeds: tuple[float, ...] = (2.5, 4.0, 5.5)  #: m/s (clipped to the speed range)
    #: tip offsets (side, top) in ball radii: running and reverse side with follow and with draw, and centre follow
    tips: tuple[tuple[float, float], ...] = ((0.0, 0.2), (0.3, 0.2), (-0.3, 0.2), (0.3, -0.2), (-0.3, -0.2))
    refine_rows: int = 48  #: near-scoring shots refined when the sweep finds no point
    refine_angles: tuple[float, ...] = (-0.012, -0.006, -0.003, 0.003, 0.006, 0.012)  #: rad
    refine_speeds: tuple[float, ...] = (0.85, 1.0, 1.15)  #: times the shot's speed
    refine_sides: tuple[float, ...] = (-0.1, 0.0, 0.1)  #: added to the side offset
    robust_top: int = 24  #: scoring shots checked for robustness
    robust_angle: float = 0.004  #: rad: the perturbation when the env has no angle noise
    robust_speed: float = 0.05  #: relative
    robust_tip: float = 0.03  #: ball radii


@dataclass(frozen=True)
class CaromShot:
    """The shot chosen: strike the cue ball along ``angle`` (rad) at ``speed`` (m/s) with tip offsets ``side``,
    ``top``. ``point``: it scores when played as given. ``robustness``: the fraction of its perturbed copies that
    score. ``cushions``: the cue ball's cushions before the second ball. ``simulated``: shots the search ran."""

    angle: float
    speed: float
    side: float
    top: float
    point: bool
    robustness: float
    cushions: int
    simulated: int


def _clip_tips(side: np.ndarray, top: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Tip offsets pulled inside the legal disc (a little inside ``MAX_TIP_OFFSET``)."""
    r = np.hypot(side, top)
    lim = 0.98 * MAX_TIP_OFFSET
    f = np.where(r > lim, lim / np.maximum(r, 1e-12), 1.0)
    return side * f, top * f


def _simulate(sim: Simulator, balls: Balls, cue: int, opp: int, red: int, a, s, sd, tp, opening: bool):
    """Run the shots in one batch and scan them: ``(second, cushions, total, first, point)`` per shot; on the
    ``opening`` shot only a point that met the red first, before any cushion, counts (the UMB rule)."""
    res = run_shots(sim, balls, a, s, ball=cue, side=sd, top=tp, events=True, validate=False)
    ev = res.events
    first, second, cush, total, before, point = scan_carom_batch(ev.offsets, ev.kind, ev.ball, ev.other, cue, opp,
                                                                 red)
    if opening:
        legal = (first == red) & (before == 0)
        point = point & legal
        first = np.where(legal, first, -1)  # an illegal opening is as far from a point as a miss
        second = np.where(legal, second, -1)
    return second, cush, total, first, point


def _closeness(second: np.ndarray, cush: np.ndarray, total: np.ndarray, first: np.ndarray) -> np.ndarray:
    """How near a shot came to scoring (higher is nearer; 10 a point): both balls met with ``c`` cushions before
    the second scores ``5 + c``; one ball met with ``t`` cushions in all scores ``min(t, 3) + 1``."""
    both = second >= 0
    return np.where(both & (cush >= CUSHIONS_NEEDED), 10.0,
                    np.where(both, 5.0 + cush, np.where(first >= 0, np.minimum(total, CUSHIONS_NEEDED) + 1.0, 0.0)))


def three_cushion_shot(sim: Simulator, balls: Balls, cue: int, opponent: int, red: int,
                       settings: CaromSearchSettings | None = None, speed_range: tuple[float, float] = (0.5, 6.0),
                       angle_noise: float = 0.0, speed_noise: float = 0.0, tip_noise: float = 0.0,
                       opening: bool = False) -> CaromShot:
    """The best shot for the cue ball (row ``cue``; ``opponent`` and ``red`` the object balls' rows) from
    ``balls`` on ``sim``'s table. ``speed_range`` clips the speeds; the noise figures (the env's shot noise: rad,
    relative, ball radii) set the robustness perturbations when larger than the settings'. ``opening``: the shot
    is the game's opening shot, which must meet the red first (``ThreeCushionState.break_shot`` with the rules'
    option ``break_red_first``)."""
    st = settings or CaromSearchSettings()
    lo, hi = speed_range
    c = balls.pos[cue]
    base = np.linspace(-math.pi, math.pi, st.sweep_angles, endpoint=False)
    contact = float(balls.radius[cue] + balls.radius[opponent])
    aims = [offset_aim_angle(c, balls.pos[j], f * contact)
            for j in (opponent, red) for f in np.linspace(-0.95, 0.95, st.cut_aims)]
    angles = np.concatenate([base, np.asarray(aims)])
    speeds = np.clip(np.asarray(st.speeds, float), lo, hi)
    tips = np.asarray(st.tips, float)
    a, s, k = np.meshgrid(angles, speeds, np.arange(len(tips)), indexing="ij")
    a, s, k = a.ravel(), s.ravel(), k.ravel()
    sd, tp = tips[k, 0], tips[k, 1]
    second, cush, total, first, point = _simulate(sim, balls, cue, opponent, red, a, s, sd, tp, opening)
    n_sim = len(a)
    close = _closeness(second, cush, total, first)
    if not point.any() and st.refine_rows:
        rows = np.argsort(-close, kind="stable")[:st.refine_rows]
        rows = rows[close[rows] > 0]
        if len(rows):
            da, fs, ds = np.meshgrid(np.asarray(st.refine_angles), np.asarray(st.refine_speeds),
                                     np.asarray(st.refine_sides), indexing="ij")
            ra = (a[rows, None] + da.ravel()[None, :]).ravel()
            rs = np.clip((s[rows, None] * fs.ravel()[None, :]).ravel(), lo, hi)
            rsd, rtp = _clip_tips((sd[rows, None] + ds.ravel()[None, :]).ravel(), np.repeat(tp[rows], da.size))
            r2 = _simulate(sim, balls, cue, opponent, red, ra, rs, rsd, rtp, opening)
            n_sim += len(ra)
            a, s, sd, tp = (np.concatenate(x) for x in ((a, ra), (s, rs), (sd, rsd), (tp, rtp)))
            second, cush, total, first, point = (np.concatenate(x) for x in zip(
                (second, cush, total, first, point), r2))
            close = _closeness(second, cush, total, first)
    if not point.any():
        k = int(np.argmax(close))
        return CaromShot(float(a[k]), float(s[k]), float(sd[k]), float(tp[k]), False, 0.0, int(cush[k]), n_sim)
    # robustness: each scoring shot under small errors of angle, speed and tip
    cand = np.flatnonzero(point)[:max(st.robust_top, 1)] if point.sum() <= st.robust_top else \
        np.flatnonzero(point)[np.linspace(0, point.sum() - 1, st.robust_top).astype(int)]
    ea = max(angle_noise, st.robust_angle)
    es = max(speed_noise, st.robust_speed)
    et = max(tip_noise, st.robust_tip)
    pert = np.array([(ea, 0, 0, 0), (-ea, 0, 0, 0), (0, es, 0, 0), (0, -es, 0, 0), (0, 0, et, 0), (0, 0, -et, 0),
                     (0, 0, 0, et), (0, 0, 0, -et), (0.5 * ea, 0.5 * es, 0, 0), (-0.5 * ea, -0.5 * es, 0, 0)])
    pa = (a[cand, None] + pert[None, :, 0]).ravel()
    ps = np.clip((s[cand, None] * (1.0 + pert[None, :, 1])).ravel(), lo, hi)
    psd, ptp = _clip_tips((sd[cand, None] + pert[None, :, 2]).ravel(), (tp[cand, None] + pert[None, :, 3]).ravel())
    p_point = _simulate(sim, balls, cue, opponent, red, pa, ps, psd, ptp, opening)[4].reshape(len(cand), len(pert))
    n_sim += len(pa)
    score = p_point.mean(axis=1)
    best = int(np.argmax(score))  # ties: the first (the sweep's order)
    k = int(cand[best])
    return CaromShot(float(a[k]), float(s[k]), float(sd[k]), float(tp[k]), True, float(score[best]),
                     int(cush[k]), n_sim)


# --- the geometric baseline ------------------------------------------------------------------------------------------

def _trace(x: float, y: float, ux: float, uy: float, speed: float, bx: float, by: float, contact: float,
           table: Table, r: float, decel: float, max_bounces: int) -> tuple[int, float, float]:
    """A lone ball from ``(x, y)`` along ``(ux, uy)`` at ``speed`` on straight lines, reflecting off the cushions
    (the normal component scaled by the table's restitution) and slowing by the rolling law: ``(cushions, miss,
    path)``: the cushions it touched before it first came within ``contact`` of ``(bx, by)`` (-1 if it never did
    before stopping or ``max_bounces``), how far inside ``contact`` its path passed (the margin), and the path
    length to there."""
    e = table.cushion_restitution
    path = 0.0
    for bounce in range(max_bounces + 1):
        reach = stop_distance(speed, ROLLING, decel, 0.0, 0.0)
        t_wall, wall = ray_cushion_hit(x, y, ux, uy, table.length, table.width, r)
        seg = min(reach, t_wall)
        t = min(max((bx - x) * ux + (by - y) * uy, 0.0), seg)  # closest approach on this segment
        d = math.hypot(x + t * ux - bx, y + t * uy - by)
        if d < contact:
            back = math.sqrt(max(contact * contact - d * d, 0.0))  # where it first touches
            return bounce, contact - d, path + max(t - back, 0.0)
        if reach <= t_wall:
            return -1, 0.0, path
        speed = speed_after_distance(speed, t_wall, ROLLING, decel, 0.0)
        x, y = x + t_wall * ux, y + t_wall * uy
        path += t_wall
        vx, vy = speed * ux, speed * uy
        if wall in (0, 1):
            vx = -e * vx
        else:
            vy = -e * vy
        speed = math.hypot(vx, vy)
        if speed <= 1e-6:
            return -1, 0.0, path
        ux, uy = vx / speed, vy / speed
    return -1, 0.0, path


def three_cushion_geometric_shot(balls: Balls, table: Table, physics: Physics, cue: int, opponent: int, red: int,
                                 speed_range: tuple[float, float] = (0.5, 6.0), cuts: int = 61,
                                 after_speeds: tuple[float, ...] = (1.2, 2.0, 3.0),
                                 max_bounces: int = 6, red_first: bool = False,
                                 sim: Simulator | None = None, checked: int = GEOMETRIC_CHECKED) -> CaromShot:
    """The geometric player's three-cushion shot, without the simulator: ball-first shots cutting each object
    ball from thin to full (``cuts`` aims), the cue ball leaving along the collision law's deflection
    (:func:`~billiards_env.physics.aim.deflected_cue_velocity`, no spin, no throw) at each of ``after_speeds``,
    then bouncing off the cushions in straight lines (the table's restitution, the rolling law). A shot scores in
    this model when that path meets the other ball after three cushions or more. Of each run of neighbouring
    scoring aims the middle one is played, from the widest run (the margin for error). ``red_first``: only shots
    that meet the red first (the opening shot). Under the rolling law the tip stays in the centre. Under the spin
    model the cue ball rolls (top ``NATURAL_ROLL``) and its straight lines are only a guess (it slides and curves
    after contact and off each cushion): with ``sim`` given, the model's scoring aims, widest run and middle first
    (at most ``checked``), are played in one batch of the engine and the first that scores is chosen (else the
    model's own choice). The search player simulates far more shots, with spin."""
    c = balls.pos[cue]
    rc = float(balls.radius[cue])
    mc = float(balls.mass[cue])
    e_ball = physics.ball_restitution
    decel = physics.deceleration
    spin = physics.has_spin
    top = NATURAL_ROLL if spin else 0.0
    lo, hi = speed_range
    best: tuple[int, float, float, float] | None = None  # (run length, angle, speed, cushions)
    ranked: list[tuple[int, float, int, float, float, int]] = []  # (-run, off the middle, order, angle, speed, cushions)
    for first, second in ((red, opponent), (opponent, red)) if not red_first else ((red, opponent),):
        a = balls.pos[first]
        b = balls.pos[second]
        contact_a = rc + float(balls.radius[first])
        contact_b = rc + float(balls.radius[second])
        for v_after in after_speeds:
            ok = np.zeros(cuts, bool)
            shots = [(0.0, 0.0, 0)] * cuts
            for q, f in enumerate(np.linspace(-0.95, 0.95, cuts)):
                ang = offset_aim_angle(c, a, f * contact_a)
                ux, uy = math.cos(ang), math.sin(ang)
                along = (a[0] - c[0]) * ux + (a[1] - c[1]) * uy
                off2 = contact_a * contact_a - ((a[0] - c[0]) * uy - (a[1] - c[1]) * ux) ** 2
                if along <= 0.0 or off2 < 0.0:
                    continue
                d_cg = along - math.sqrt(off2)  # to the ghost ball
                gx, gy = c[0] + d_cg * ux, c[1] + d_cg * uy
                # the other ball must not be in the way to the first
                t = min(max((b[0] - c[0]) * ux + (b[1] - c[1]) * uy, 0.0), d_cg)
                if math.hypot(c[0] + t * ux - b[0], c[1] + t * uy - b[1]) < contact_b:
                    continue
                n = np.array([a[0] - gx, a[1] - gy]) / contact_a
                w = deflected_cue_velocity(np.array([ux, uy]), n, e_ball, mc, float(balls.mass[first]))
                if spin:  # a rolling cue ball keeps its roll: it curves to 5/7 of its new velocity + 2/7 of the old
                    w = 5.0 / 7.0 * w + 2.0 / 7.0 * np.array([ux, uy])
                keep = float(np.hypot(*w))  # cue speed kept per unit impact speed
                if keep < 0.05:
                    continue
                cushions, _, _ = _trace(gx, gy, w[0] / keep, w[1] / keep, v_after, b[0], b[1], contact_b, table, rc,
                                        decel, max_bounces)
                if cushions < CUSHIONS_NEEDED:
                    continue
                v0 = launch_speed(d_cg, v_after / keep, ROLLING, decel, 0.0) if spin else \
                    launch_speed(d_cg, v_after / keep, *physics.path_args)
                if v0 > hi:
                    continue
                ok[q] = True
                shots[q] = (ang, max(v0, lo), cushions)
            k = 0
            while k < cuts:  # runs of scoring aims: the middle of each
                if not ok[k]:
                    k += 1
                    continue
                start = k
                while k < cuts and ok[k]:
                    k += 1
                mid = shots[(start + k - 1) // 2]
                if best is None or k - start > best[0]:
                    best = (k - start, mid[0], mid[1], mid[2])
                for q in range(start, k):
                    ranked.append((start - k, abs(q - (start + k - 1) / 2), len(ranked), *shots[q]))
    if best is None:  # nothing in the model: a firm full hit on the red
        return CaromShot(aim_angle(c, balls.pos[red]), float(min(max(3.0, lo), hi)), 0.0, top, False, 0.0, 0, 0)
    run, angle, speed, cushions = best
    if sim is not None and spin:
        ranked.sort()
        rows = ranked[:checked]
        a = np.array([r[3] for r in rows])
        v = np.array([r[4] for r in rows])
        _, cush, _, _, point = _simulate(sim, balls, cue, opponent, red, a, v, np.zeros(len(rows)),
                                         np.full(len(rows), top), red_first)
        hit = np.flatnonzero(point)
        if hit.size:
            r = rows[int(hit[0])]
            return CaromShot(float(r[3]), float(r[4]), 0.0, top, True, -r[0] / cuts, int(cush[hit[0]]), len(rows))
        return CaromShot(float(angle), float(speed), 0.0, top, False, run / cuts, int(cushions), len(rows))
    return CaromShot(float(angle), float(speed), 0.0, top, True, run / cuts, int(cushions), 0)


# --- as players of the env (state in, shot out) ----------------------------------------------------------------------

class _CaromPlayer(BasePlayer):
    """A three-cushion decision function as a player (:class:`~billiards_env.players.context.BasePlayer`:
    ``shot(state, obs, codec)``, ``act(state, obs, codec)``): it plays the table state's row 0 (the shooter's cue
    ball) against rows 1 (the opponent's) and 2 (the red), its shot as ``codec`` expresses it."""

    name = "carom"

    def __init__(self, seed: int | None = 0) -> None:
        self.last: CaromShot | None = None

    def reset(self, seed: int | None = None) -> None:
        self.last = None

    def _shot(self, state: Any, opening: bool) -> CaromShot:
        raise NotImplementedError

    def choose(self, state: Any, obs: Any, codec: Any) -> np.ndarray:
        """The action (in ``codec``) of the decision function's shot on ``state``."""
        session = state.game
        opening = bool(session.game_state.break_shot and session.rules.options.break_red_first)
        self.last = shot = self._shot(state, opening)
        return to_action(codec, state, shot.angle, shot.speed, side=shot.side, top=shot.top)


class CaromSearchPlayer(_CaromPlayer):
    """:func:`three_cushion_shot` (search over spin shots) as a player."""

    name = "search"

    def __init__(self, seed: int | None = 0, settings: CaromSearchSettings | None = None) -> None:
        super().__init__(seed)
        self.settings = settings

    def _shot(self, state: Any, opening: bool) -> CaromShot:
        st = state.settings
        return three_cushion_shot(state.simulator, state.balls, 0, 1, 2, self.settings, st.speed_range,
                                  st.angle_noise, st.speed_noise, st.tip_noise, opening)


class CaromGeometricPlayer(_CaromPlayer):
    """:func:`three_cushion_geometric_shot` (straight lines off the cushions) as a player."""

    name = "geometric"

    def _shot(self, state: Any, opening: bool) -> CaromShot:
        return three_cushion_geometric_shot(state.balls, state.table, state.physics, 0, 1, 2,
                                            state.settings.speed_range, red_first=opening, sim=state.simulator)


__all__ = ["CaromSearchSettings", "CaromShot", "three_cushion_shot", "three_cushion_geometric_shot",
           "CaromSearchPlayer", "CaromGeometricPlayer"]
