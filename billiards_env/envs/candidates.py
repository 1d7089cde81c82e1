"""Candidate shots: the (ball, pocket) shots the ``candidates`` action and observation types are built on.

Pool programs (CueCard, PickPocket) do not search raw cue angles: they list the shots that can pocket a legal ball
in some pocket, then choose among them and set the speed and spin for position. :func:`candidate_slots` lists them
for the env's table now, ranked as the geometric player ranks them, and keeps the best ``n`` as *slots*:

- the cue ball where it lies: every ghost-ball shot at a legal ball into a pocket
  (:func:`billiards_env.players.shots.ghost_ball_shots`, cut <= 80 deg, or <= 88 deg when there is none), easiest
  first (its ``score``: the cue-angle tolerance, cut down when a path is blocked, the speed out of range or the
  cue ball heading for a pocket);
- the cue ball in hand: every (legal ball, pocket) with an entry window (:func:`~billiards_env.physics.aim.pocket_window`),
  widest window first, those whose path to the pocket is blocked after the others; the cue ball's place is the
  action's to choose (see :class:`billiards_env.envs.actions.CandidateShots`);
- the break: no slots (the break is a full hit on the nearest legal ball).

The last of the ``n`` slots is kept for a *kick* (the cue ball where it lies), offered when no pot has clear
paths: a one-rail kick at a legal ball (a foul gives the opponent the cue ball in hand; a legal contact does not).
The kick aims at the cushion point from which the ball, reflected with the cushion's restitution, runs into the
legal ball full; kicks whose paths are blocked, or that would pass a pocket's mouth, are dropped, the others are
simulated at a fan of aims around that one (:data:`KICK_FAN`, one batch:
:func:`billiards_env.physics.batch.run_shots`) and kept if some aim hits that ball first without a scratch (the
middle of those is played); the shortest is the slot. The other ``n - 1`` slots are the pots.

A slot is a :class:`Slot`; the list is computed once per shot (kept in the table state's view memo), so the action
type and the observation type of one step share it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from billiards_env.physics.aim import (aim_angle, direction_vector, ghost_ball_position, pocket_window,
                                       segment_blocked)
from billiards_env.physics.batch import run_shots
from billiards_env.physics.motion import launch_speed
from billiards_env.players.shots import MAX_CUT, ShotCandidate, ghost_ball_shots, pot_probability

if TYPE_CHECKING:  # pragma: no cover
    from billiards_env.table_state import TableState

#: The cut limit of the fallback list when no shot has a cut <= MAX_CUT (as the geometric player).
FALLBACK_CUT = math.radians(88.0)
#: The least angle spread (rad) :func:`next_shot_ease` assumes (a shot's chance without noise is 1 or 0).
EASE_SPREAD = 0.002
#: A kick's speed: the launch speed that would still roll at ``KICK_ARRIVAL`` m/s over the path's length, times
#: ``KICK_MARGIN`` for the energy the cushion takes (the ``power`` dim scales it as any slot's).
KICK_ARRIVAL = 0.8
KICK_MARGIN = 1.15
#: Aim offsets (rad) simulated around each kick's reflected aim (the cushion's friction and the balls' spin bend the
#: bounce); the kick plays the middle of those that hit the ball first.
KICK_FAN = (0.0, -0.008, 0.008, -0.02, 0.02, -0.04, 0.04, -0.07, 0.07)


@dataclass(frozen=True)
class Slot:
    """One candidate: pocket ball ``target`` (row) in ``pocket``. ``obj_angle``: the direction the ball must take
    (the middle of its entry window), ``half``: the window's half-width (rad), ``d_obj``: the ball's distance to the
    pocket's capture circle, ``clear_obj``: its path there is free of other balls. ``shot``: the ghost-ball shot from
    the cue ball where it lies (angle, speed, cut, tolerance...), None with the cue ball in hand."""

    target: int
    pocket: int
    obj_angle: float
    half: float
    d_obj: float
    clear_obj: bool
    shot: ShotCandidate | None = None

    def ghost(self, contact: float, pos: np.ndarray) -> np.ndarray:
        """The ghost-ball position (where the cue ball must touch the target) for balls ``pos``."""
        return ghost_ball_position(pos[self.target], self.obj_angle, contact)


@dataclass(frozen=True)
class Slots:
    """The candidate list of one table state: the pots ``slots`` (best first, at most ``n - 1``), the ``kick``,
    whether the cue ball is in hand (``in_hand``), whether the shot is a break (``break_shot``), and the legal balls
    (rows, ``targets``)."""

    slots: tuple[Slot, ...]
    in_hand: bool
    break_shot: bool
    targets: tuple[int, ...]
    kick: Slot | None = None  #: the kick slot (the last of ``n``), if there is a kick


def candidate_slots(state: "TableState", n: int, speed_range: tuple[float, float] | None = None) -> Slots:
    """The best ``n`` candidate shots for the table now (see the module docstring), their speeds within
    ``speed_range`` (default the state's speed range); computed once per shot (kept in ``state.view.memo``)."""
    b = state.balls
    if speed_range is None:
        speed_range = state.settings.speed_range
    view = state.view
    targets = view.targets
    area = view.place_area
    brk = view.break_shot
    key = ("candidates", b.pos.tobytes(), b.on_table.tobytes(), n, speed_range)
    cached = view.memo.get(key)
    if cached is not None:
        return cached
    kick: Slot | None = None
    if brk:
        slots: tuple[Slot, ...] = ()
    elif area is not None:
        slots = tuple(_in_hand_slots(state, targets)[:max(n - 1, 1)])
    else:
        slots = tuple(_shot_slots(state, targets, speed_range)[:max(n - 1, 1)])
        if n > 1 and not any(s.shot.clear for s in slots):
            kicks = _kick_slots(state, targets, speed_range)
            kick = kicks[0] if kicks else None
    out = Slots(slots, area is not None, brk, targets, kick)
    view.memo[key] = out
    return out


def next_shot_ease(state: "TableState", n: int) -> float:
    """The chance of potting the easiest shot on the table now from where the cue ball lies: the best of the ``n``
    candidate slots' scores (the geometric player's tolerance, penalised for blocked paths, speeds out of range,
    scratch risk) through :func:`~billiards_env.players.shots.pot_probability` with the angle noise (at least
    :data:`EASE_SPREAD`). 0 when no pot exists. The ``position_reward`` shaping of the games."""
    slots = candidate_slots(state, n).slots
    best = max((s.shot.score for s in slots if s.shot is not None), default=0.0)
    return pot_probability(best, max(state.settings.angle_noise, EASE_SPREAD))


def _shot_slots(state: "TableState", targets: tuple[int, ...], rng: tuple[float, float]) -> list[Slot]:
    b = state.balls
    shots: list[ShotCandidate] = []
    for cut in (MAX_CUT, FALLBACK_CUT):
        shots = ghost_ball_shots(b, state.table, state.physics, 0, list(targets), rng, cut)
        if shots:
            break
    return [Slot(s.target, s.pocket, s.obj_angle, s.window, s.d_obj,
                 _path_clear(b, s.target, s.obj_angle, s.d_obj), s) for s in shots]


def _in_hand_slots(state: "TableState", targets: tuple[int, ...]) -> list[Slot]:
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
    """``(cushion, point)`` for each one-rail kick from ``cue`` to ``target`` (ball centres): the point on the line
    the cue ball's centre touches a cushion on (0 left, 1 right, 2 bottom, 3 top) from which the path, its normal
    component scaled by ``restitution`` at the bounce, runs into ``target``. A point outside that cushion's span is
    not returned."""
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


def _kick_slots(state: "TableState", targets: tuple[int, ...], rng: tuple[float, float]) -> list[Slot]:
    """Kicks at the legal balls (see the module docstring), shortest first."""
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
            if segment_blocked(cue, p, opos, orad) or segment_blocked(p, b.pos[j], opos, orad):
                continue
            d = float(np.hypot(*(p - cue))) + float(np.hypot(*(b.pos[j] - p)))
            v = KICK_MARGIN * launch_speed(d, KICK_ARRIVAL, *state.physics.path_args)
            cands.append((d, j, aim_angle(cue, p), min(max(v, rng[0]), rng[1])))
    if not cands:
        return []
    cands.sort()
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


def _path_clear(b: Any, j: int, obj_angle: float, d_obj: float) -> bool:
    """Whether ball ``j`` rolls ``d_obj`` along ``obj_angle`` without touching another object ball."""
    others = [k for k in range(len(b.ids)) if b.on_table[k] and k not in (0, j)]
    if not others:
        return True
    o = b.pos[j]
    return not segment_blocked(o, o + direction_vector(obj_angle) * d_obj, b.pos[others],
                               b.radius[others] + float(b.radius[j]))


__all__ = ["Slot", "Slots", "candidate_slots", "kick_points", "next_shot_ease", "EASE_SPREAD", "FALLBACK_CUT", "KICK_ARRIVAL",
           "KICK_MARGIN", "KICK_FAN"]
