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

A slot is a :class:`Slot`; the list is cached on the env per table state (positions, the legal balls, ball in hand),
so the action type and the observation type of one step compute it once.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from billiards_env.physics.aim import direction_vector, ghost_ball_position, pocket_window, segment_blocked
from billiards_env.players.shots import MAX_CUT, ShotCandidate, ghost_ball_shots

if TYPE_CHECKING:  # pragma: no cover
    from .base import BilliardsEnv

#: The cut limit of the fallback list when no shot has a cut <= MAX_CUT (as the geometric player).
FALLBACK_CUT = math.radians(88.0)


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
    """The candidate list of one table state: ``slots`` (best first, at most ``n``), whether the cue ball is in hand
    (``in_hand``), whether the shot is a break (``break_shot``), and the legal balls (rows, ``targets``)."""

    slots: tuple[Slot, ...]
    in_hand: bool
    break_shot: bool
    targets: tuple[int, ...]


def legal_rows(env: "BilliardsEnv") -> list[int]:
    """Rows of the balls the shooter may hit first, on the table: a game's legal balls, else every object ball."""
    task = env.task
    on = env.balls.on_table
    rows = task.legal_rows() if hasattr(task, "legal_rows") else range(1, env.n_balls)
    return [int(i) for i in rows if on[i] and i != 0]


def candidate_slots(env: "BilliardsEnv", n: int, speed_range: tuple[float, float] | None = None) -> Slots:
    """The best ``n`` candidate shots for the env's table now (see the module docstring), their speeds within
    ``speed_range`` (default the env's ``speed_min``, ``speed_max``); cached per state."""
    b = env.balls
    if speed_range is None:
        speed_range = (float(env.config.speed_min), float(env.config.speed_max))
    task = env.task
    targets = tuple(legal_rows(env))
    area = task.ball_in_hand_area(env)
    brk = bool(task.is_break(env))
    key = (b.pos.tobytes(), b.on_table.tobytes(), targets, area, brk, n, speed_range)
    cached = getattr(env, "_candidate_cache", None)
    if cached is not None and cached[0] == key:
        return cached[1]
    if brk:
        slots: tuple[Slot, ...] = ()
    elif area is not None:
        slots = tuple(_in_hand_slots(env, targets)[:n])
    else:
        slots = tuple(_shot_slots(env, targets, speed_range)[:n])
    out = Slots(slots, area is not None, brk, targets)
    env._candidate_cache = (key, out)
    return out


def _shot_slots(env: "BilliardsEnv", targets: tuple[int, ...], rng: tuple[float, float]) -> list[Slot]:
    b = env.balls
    shots: list[ShotCandidate] = []
    for cut in (MAX_CUT, FALLBACK_CUT):
        shots = ghost_ball_shots(b, env.table, env.physics, 0, list(targets), rng, cut)
        if shots:
            break
    return [Slot(s.target, s.pocket, s.obj_angle, s.window, s.d_obj,
                 _path_clear(b, s.target, s.obj_angle, s.d_obj), s) for s in shots]


def _in_hand_slots(env: "BilliardsEnv", targets: tuple[int, ...]) -> list[Slot]:
    b = env.balls
    out: list[tuple[float, Slot]] = []
    for j in targets:
        r = float(b.radius[j])
        for p in range(env.table.n_pockets):
            win = pocket_window(b.pos[j], r, env.table, p)
            if win is None:
                continue
            obj_angle, half, d_obj = win
            clear = _path_clear(b, j, obj_angle, d_obj)
            out.append((half * (1.0 if clear else 0.1), Slot(j, p, obj_angle, half, d_obj, clear)))
    out.sort(key=lambda t: -t[0])  # stable: ties keep (ball, pocket) order
    return [s for _, s in out]


def _path_clear(b: Any, j: int, obj_angle: float, d_obj: float) -> bool:
    """Whether ball ``j`` rolls ``d_obj`` along ``obj_angle`` without touching another object ball."""
    others = [k for k in range(len(b.ids)) if b.on_table[k] and k not in (0, j)]
    if not others:
        return True
    o = b.pos[j]
    return not segment_blocked(o, o + direction_vector(obj_angle) * d_obj, b.pos[others],
                               b.radius[others] + float(b.radius[j]))


__all__ = ["Slot", "Slots", "candidate_slots", "legal_rows", "FALLBACK_CUT"]
