"""Ghost-ball shot selection for the baseline players, on the engine's model (no Gymnasium here).

Ghost-ball aiming: to send object ball ``O`` in direction ``u`` the cue ball must touch it from the ghost-ball
position ``G = O - (r_cue + r_obj) u``. The cut angle is the angle between the cue's path ``C -> G`` and ``u``.
Pockets are capture circles (:class:`billiards_env.physics.Table`): the direction ``u`` is taken from the middle
of the window of directions along which the object ball enters the capture circle before touching a cushion, so
corner and side pockets approached at a shallow angle are aimed correctly (or rejected when the window is empty).

Every formula (rays, pocket windows, ghost ball, cut, clear paths, the collision, the cue ball's path) is
:mod:`billiards_env.physics.aim`'s and the motion law :mod:`billiards_env.physics.motion`'s; the players' choices
(which shots to consider, how hard to hit them, how to score them) are compiled in :mod:`.geometry`, one call per
table; this module gives them as :class:`ShotCandidate` objects.

All angles are radians (0 = +x, counter-clockwise), speeds m/s, distances m.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from billiards_env.physics import Balls, Physics, Table
from billiards_env.physics.aim import aim_angle, pocket_window, segment_blocked  # noqa: F401 (re-exported)
from billiards_env.physics.motion import launch_speed, stop_distance

from .geometry import (COL_ANGLE, COL_CLEAR, COL_CUT, COL_D_CUE, COL_D_OBJ, COL_NEED, COL_OBJ_ANGLE, COL_POCKET,
                       COL_REACH, COL_RISK, COL_SCORE, COL_SPEED, COL_TARGET, COL_TOL, COL_WINDOW, MAX_CUT,
                       ghost_shots, table_model)


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

    One compiled call for the whole table (:func:`billiards_env.players.geometry.ghost_shots`); this wraps its rows
    as :class:`ShotCandidate` objects.
    """
    on = balls.on_table
    if targets is None:
        targets = [i for i in range(len(balls)) if i != cue and on[i]]
    rows = ghost_shots(np.ascontiguousarray(balls.pos, dtype=np.float64), np.ascontiguousarray(on, dtype=np.bool_),
                       np.ascontiguousarray(balls.radius, dtype=np.float64),
                       np.ascontiguousarray(balls.mass, dtype=np.float64), int(cue),
                       np.asarray(targets, dtype=np.int64).reshape(-1), *table_model(table, physics),
                       float(speed_range[0]), float(speed_range[1]), float(max_cut), float(arrive_speed),
                       np.asarray(speed_factors, dtype=np.float64).reshape(-1), bool(check_scratch))
    return [candidate_of(r) for r in rows]


def candidate_of(row: np.ndarray) -> ShotCandidate:
    """The :class:`ShotCandidate` of a shot row of :mod:`billiards_env.players.geometry`."""
    r = row.tolist()
    return ShotCandidate(int(r[COL_TARGET]), int(r[COL_POCKET]), r[COL_ANGLE], r[COL_SPEED], r[COL_NEED],
                         r[COL_OBJ_ANGLE], r[COL_CUT], r[COL_D_CUE], r[COL_D_OBJ], r[COL_WINDOW], r[COL_TOL],
                         r[COL_CLEAR] != 0.0, r[COL_REACH] != 0.0, r[COL_RISK] != 0.0, r[COL_SCORE])


def direct_hit(balls: Balls, cue: int = 0, targets: list[int] | None = None) -> tuple[float, int]:
    """Angle of a full-ball hit on the nearest target (the fallback when no pocket shot exists). Compiled twin (the
    native vector env's ``candidates`` type): ``billiards_env.envs._action_kernels.direct_hit_xy``."""
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
