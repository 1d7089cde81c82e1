"""Candidate shots: the (ball, pocket) shots the ``candidates`` action and observation types are built on.

Pool programs (CueCard, PickPocket) do not search raw cue angles: they list the shots that can pocket a legal ball
in some pocket, then choose among them and set the speed and spin for position. :func:`candidate_slots` lists them
for the env's table now, ranked as the geometric player ranks them, and keeps the best ``n`` as *slots*:

- the cue ball where it lies: every ghost-ball shot at a legal ball into a pocket (cut <= 80 deg, or <= 88 deg when
  there is none), easiest first (its ``score``: the cue-angle tolerance, cut down when a path is blocked, the speed
  out of range or the cue ball heading for a pocket);
- the cue ball in hand: every (legal ball, pocket) with an entry window, widest window first, those whose path to
  the pocket is blocked after the others; the cue ball's place is the action's to choose (see
  :class:`billiards_env.envs.actions.CandidateShots`);
- the break: no slots (the break is a full hit on the nearest legal ball).

The last of the ``n`` slots is kept for a *kick* (the cue ball where it lies), offered when no pot has clear
paths: a one-rail kick at a legal ball (a foul gives the opponent the cue ball in hand; a legal contact does not).
The kick aims at the cushion point from which the ball, reflected with the cushion's restitution, runs into the
legal ball full; kicks whose paths are blocked, or that would pass a pocket's mouth, are dropped, the others are
simulated at a fan of aims around that one (:data:`KICK_FAN`, :func:`billiards_env.physics.batch.run_shots`),
shortest first, until one hits its ball first without a scratch at some aim (the middle of those is played): that
one is the slot. The other ``n - 1`` slots are the pots.

The lists are the compiled players' geometry (:mod:`billiards_env.players.slots`: one call per list, on the table
state's arrays); this module turns their rows into :class:`Slot` objects. A slot list is computed once per shot
(kept in the table state's view memo), so the action type and the observation type of one step share it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from billiards_env.physics.aim import ghost_ball_position
from billiards_env.physics.batch import run_shots
from billiards_env.players.geometry import COL_CLEAR, COL_CLEAR_OBJ, state_model
from billiards_env.players.shots import ShotCandidate, candidate_of
from billiards_env.players.slots import in_hand_slots, kick_candidates, shot_slots
from billiards_env.players.slots import next_shot_ease as _next_shot_ease

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
_FAN = np.asarray(KICK_FAN)
_FAN_ORDER = np.argsort(_FAN)
_FAN_SORTED = _FAN[_FAN_ORDER]


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


def _targets(state: "TableState") -> np.ndarray:
    """The view's legal balls as an int64 array, in the view's order (made once per view)."""
    memo = state.view.memo
    got = memo.get("targets_array")
    if got is None:
        got = memo["targets_array"] = np.asarray(state.view.targets, dtype=np.int64).reshape(-1)
    return got


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
    keep = max(n - 1, 1)
    if brk:
        slots: tuple[Slot, ...] = ()
    elif area is not None:
        rows = in_hand_slots(b.pos, b.on_table, b.radius, _targets(state), *state_model(state))
        slots = tuple(Slot(int(r[0]), int(r[1]), r[2], r[3], r[4], r[5] != 0.0) for r in rows[:keep].tolist())
    else:
        lo, hi = float(speed_range[0]), float(speed_range[1])
        rows = shot_slots(b.pos, b.on_table, b.radius, b.mass, _targets(state), *state_model(state), lo, hi)[:keep]
        slots = tuple(_pot_slot(r) for r in rows)
        if n > 1 and not rows[:, COL_CLEAR].any():
            kick = _kick_slot(state, lo, hi)
    out = Slots(slots, area is not None, brk, targets, kick)
    view.memo[key] = out
    return out


def _pot_slot(row: np.ndarray) -> Slot:
    """The slot of a shot row of :func:`billiards_env.players.slots.shot_slots`."""
    s = candidate_of(row)
    return Slot(s.target, s.pocket, s.obj_angle, s.window, s.d_obj, bool(row[COL_CLEAR_OBJ] != 0.0), s)


def _kick_slot(state: "TableState", lo: float, hi: float) -> Slot | None:
    """The kick (see the module docstring): the candidates of
    :func:`billiards_env.players.slots.kick_candidates`, shortest first, each simulated at the fan of aims until
    one hits its ball first without a scratch; None if none does."""
    b = state.balls
    rows = kick_candidates(b.pos, b.on_table, b.radius, _targets(state), *state_model(state), lo, hi, KICK_ARRIVAL,
                           KICK_MARGIN)
    for d, target, angle, speed in rows.tolist():
        j = int(target)
        res = run_shots(state.simulator, b, angle + _FAN, np.full(len(_FAN), speed), validate=False)
        hits = (res.first_contact == j) & (res.pocket[:, 0] < 0)
        ok = np.flatnonzero(hits[_FAN_ORDER])
        if len(ok) == 0:
            continue
        a = float(angle + _FAN_SORTED[ok[len(ok) // 2]])  # the middle of the aims that hit it
        shot = ShotCandidate(j, -1, a, speed, speed, math.nan, 0.0, d, 0.0, 0.0, 0.0, True, True, False, 0.0)
        return Slot(j, -1, math.nan, 0.0, 0.0, True, shot)
    return None


def next_shot_ease(state: "TableState", n: int) -> float:
    """The chance of potting the easiest shot on the table now from where the cue ball lies: the best candidate
    slot's score (the geometric player's tolerance, penalised for blocked paths, speeds out of range, scratch risk)
    through :func:`~billiards_env.players.shots.pot_probability` with the angle noise (at least
    :data:`EASE_SPREAD`). 0 when no pot exists, with the cue ball in hand and on the break. The ``position_reward``
    shaping of the games (one compiled call: :func:`billiards_env.players.slots.next_shot_ease`)."""
    view = state.view
    if view.break_shot or view.place_area is not None or n < 1:
        return 0.0
    b = state.balls
    lo, hi = state.settings.speed_range
    return float(_next_shot_ease(b.pos, b.on_table, b.radius, b.mass, _targets(state), *state_model(state),
                                 float(lo), float(hi), max(state.settings.angle_noise, EASE_SPREAD)))


__all__ = ["Slot", "Slots", "candidate_slots", "next_shot_ease", "EASE_SPREAD", "FALLBACK_CUT", "KICK_ARRIVAL",
           "KICK_MARGIN", "KICK_FAN"]
