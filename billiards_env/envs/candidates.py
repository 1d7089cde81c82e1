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
simulated at a fan of aims around that one (:data:`KICK_FAN`; each aim the exact kernel's run, :func:`kick_of`),
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
from numba import njit

from billiards_env.games.pool import pool_place_area_row, pool_targets_row
from billiards_env.physics.aim import ghost_ball_position
from billiards_env.physics.exact import simulate_exact
from billiards_env.physics.exact_spin import simulate_exact_spin
from billiards_env.physics.outcome import first_contact_row
from billiards_env.physics.plain import plain
from billiards_env.players.geometry import (COL_ANGLE, COL_CLEAR, COL_CLEAR_OBJ, COL_D_CUE, COL_D_OBJ, COL_OBJ_ANGLE,
                                            COL_POCKET, COL_REACH, COL_RISK, COL_SPEED, COL_TARGET, COL_TOL, N_COLS,
                                            state_model)
from billiards_env.players.shots import ShotCandidate, candidate_of
from billiards_env.players.slots import (HAND_CLEAR, HAND_D_OBJ, HAND_HALF, HAND_OBJ_ANGLE, HAND_POCKET, HAND_TARGET,
                                         in_hand_slots, kick_candidates, shot_slots)
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


class Slots:
    """The candidate list of one table state: the pots ``slots`` (best first, at most ``n - 1``), the ``kick``,
    whether the cue ball is in hand (``in_hand``), whether the shot is a break (``break_shot``), and the legal balls
    (rows, ``targets``). ``rows``: the pots as the compiled lists' rows (shot rows of
    :mod:`billiards_env.players.geometry`, or with the cue ball in hand the ``HAND_*`` rows of
    :mod:`billiards_env.players.slots`), from which the observation is made; the :class:`Slot` objects are made from
    them on first use."""

    __slots__ = ("in_hand", "break_shot", "targets", "kick", "rows", "_slots")

    def __init__(self, slots: tuple[Slot, ...] | None, in_hand: bool, break_shot: bool, targets: tuple[int, ...],
                 kick: Slot | None = None, rows: np.ndarray | None = None) -> None:
        self._slots = None if slots is None else tuple(slots)
        self.in_hand = in_hand
        self.break_shot = break_shot
        self.targets = targets
        self.kick = kick  #: the kick slot (the last of ``n``), if there is a kick
        self.rows = rows

    @property
    def slots(self) -> tuple[Slot, ...]:
        if self._slots is None:
            self._slots = tuple(self.at(i) for i in range(self.count))
        return self._slots

    @property
    def count(self) -> int:
        """How many pots (``len(slots)``, without making them)."""
        return len(self._slots) if self._slots is not None else (0 if self.rows is None else len(self.rows))

    def at(self, i: int) -> Slot:
        """Pot ``i`` (``slots[i]``, made alone when the others are not made yet)."""
        if self._slots is not None:
            return self._slots[i]
        assert self.rows is not None
        return _hand_slot(self.rows[i].tolist()) if self.in_hand else _pot_slot(self.rows[i])

    def __repr__(self) -> str:
        return (f"Slots(slots={self.slots!r}, in_hand={self.in_hand}, break_shot={self.break_shot}, "
                f"targets={self.targets}, kick={self.kick!r})")


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
    rows = None
    if area is not None and not brk:
        rows = in_hand_slots(b.pos, b.on_table, b.radius, _targets(state), *state_model(state))[:keep]
    elif not brk:
        lo, hi = float(speed_range[0]), float(speed_range[1])
        rows = shot_slots(b.pos, b.on_table, b.radius, b.mass, _targets(state), *state_model(state), lo, hi)[:keep]
        if n > 1 and not rows[:, COL_CLEAR].any():
            kick = _kick_slot(state, lo, hi)
    out = Slots(() if brk else None, area is not None, brk, targets, kick, rows)
    view.memo[key] = out
    return out


def _hand_slot(r: list[float]) -> Slot:
    """The slot of an in-hand row of :func:`billiards_env.players.slots.in_hand_slots` (as a list)."""
    return Slot(int(r[HAND_TARGET]), int(r[HAND_POCKET]), r[HAND_OBJ_ANGLE], r[HAND_HALF], r[HAND_D_OBJ],
                r[HAND_CLEAR] != 0.0)


def _pot_slot(row: np.ndarray) -> Slot:
    """The slot of a shot row of :func:`billiards_env.players.slots.shot_slots`."""
    s = candidate_of(row)
    return Slot(s.target, s.pocket, s.obj_angle, s.window, s.d_obj, bool(row[COL_CLEAR_OBJ] != 0.0), s)


def _kick_slot(state: "TableState", lo: float, hi: float) -> Slot | None:
    """The kick (see the module docstring; :func:`kick_of`); None if none hits."""
    b = state.balls
    sim = state.simulator
    found, j, a, speed, d = kick_of(b.pos, b.on_table, b.radius, b.mass, _targets(state), *state_model(state), lo, hi,
                                    sim.pocket_xy, sim.pocket_r, sim.params, sim.has_spin, int(sim.max_events))
    if not found:
        return None
    shot = ShotCandidate(j, -1, a, speed, speed, math.nan, 0.0, d, 0.0, 0.0, 0.0, True, True, False, 0.0)
    return Slot(j, -1, math.nan, 0.0, 0.0, True, shot)


@njit(cache=True)
def kick_of(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray, targets: np.ndarray,
            tm_xy: np.ndarray, tm_r: np.ndarray, tm_params: np.ndarray, lo: float, hi: float, pocket_xy: np.ndarray,
            pocket_r: np.ndarray, params: np.ndarray, spin: bool, max_events: int) -> tuple:
    """The kick in one compiled call: the candidates of :func:`billiards_env.players.slots.kick_candidates`,
    shortest first, each simulated at the fan of aims (:data:`KICK_FAN`; each aim the exact kernel's run on a copy
    of the table, as :func:`billiards_env.physics.batch.run_shots` runs it) until one hits its ball first without a
    scratch at some aim: the middle of those is played. Returns ``(found, target, angle, speed, path length)``."""
    rows = kick_candidates(pos, on, radius, targets, tm_xy, tm_r, tm_params, lo, hi, KICK_ARRIVAL, KICK_MARGIN)
    nb = pos.shape[0]
    nf = _FAN.shape[0]
    p2 = np.empty((nb, 2))
    v2 = np.empty((nb, 2))
    a2 = np.empty((nb, 3))
    o2 = np.empty(nb, np.bool_)
    hits = np.empty(nf, np.bool_)
    for r in range(rows.shape[0]):
        d, target, a0, sp = rows[r, 0], int(rows[r, 1]), rows[r, 2], rows[r, 3]
        for f in range(nf):
            # Element by element: an array-to-array assignment compiles numba's shape check and its message
            # formatting (seconds of a cold start).
            for b in range(nb):
                p2[b, 0] = pos[b, 0]
                p2[b, 1] = pos[b, 1]
                o2[b] = on[b]
            v2[:] = 0.0
            a = a0 + _FAN[f]
            v2[0, 0] = sp * math.cos(a)
            v2[0, 1] = sp * math.sin(a)
            a2[:] = 0.0
            if spin:
                res = simulate_exact_spin(p2, v2, a2, radius, mass, o2, pocket_xy, pocket_r, params, max_events,
                                          plain(False))
            else:
                res = simulate_exact(p2, v2, a2, radius, mass, o2, pocket_xy, pocket_r, params, max_events,
                                     plain(False))
            hits[f] = first_contact_row(res.ev_int, 0) == target and res.pocket[0] < 0
        n_ok = 0
        for f in range(nf):
            if hits[_FAN_ORDER[f]]:
                n_ok += 1
        if n_ok == 0:
            continue
        mid = n_ok // 2
        for f in range(nf):
            if hits[_FAN_ORDER[f]]:
                if mid == 0:
                    return True, target, a0 + _FAN_SORTED[f], sp, d  # the middle of the aims that hit it
                mid -= 1
    return False, -1, 0.0, 0.0, 0.0


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


# --- the ``candidates`` observation's values ------------------------------------------------------------------------

#: Values per slot of the ``candidates`` observation.
SLOT_FEATURES = 12
#: Tolerance (rad of cue angle) that reads 1 in the ``candidates`` observation (an easy shot).
EASY_TOLERANCE = 0.02


def slot_features(state: "TableState", cands: Slots, n_slots: int, speed_max: float) -> np.ndarray:
    """The ``candidates`` observation's slot values of ``cands`` (``n_slots`` slots of :data:`SLOT_FEATURES` values,
    float32, in [-1, 1]; see :class:`billiards_env.envs.observations.CandidateFeatures`), in one compiled call on the
    slots' rows. Compiled twin of it on :func:`candidate_slots` (the native vector env's pool tables):
    :func:`candidates_features_row`."""
    rows = cands.rows if cands.rows is not None else _NO_ROWS
    k = cands.kick
    kick = (k.target, k.shot.d_cue, k.shot.speed) if k is not None else (-1, 0.0, 0.0)
    tm = state_model(state)
    return _slot_features(rows, cands.in_hand, kick[0], kick[1], kick[2], _numbers(state), tm.pocket_xy,
                          float(tm.params[0]), float(tm.params[1]), float(speed_max), int(n_slots))


_NO_ROWS = np.zeros((0, N_COLS))


def _numbers(state: "TableState") -> np.ndarray:
    memo = state.view.memo
    got = memo.get("numbers_array")
    if got is None:
        got = memo["numbers_array"] = np.asarray(state.numbers, dtype=np.int64)
    return got


@njit(cache=True)
def _wrap(angle: float) -> float:
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


@njit(cache=True)
def _slot_features(rows: np.ndarray, in_hand: bool, kick_target: int, kick_length: float, kick_speed: float,
                   numbers: np.ndarray, pocket_xy: np.ndarray, length: float, width: float, speed_max: float,
                   n_slots: int) -> np.ndarray:
    """:func:`slot_features` on arrays: ``rows`` the pots (shot rows, or ``HAND_*`` rows with ``in_hand``), the
    kick's target (-1: none), path length and speed."""
    out = np.zeros((n_slots, SLOT_FEATURES), np.float32)
    if kick_target >= 0:
        row = out[n_slots - 1]
        row[0] = 1.0
        row[1] = numbers[kick_target] / 15.0
        row[2] = -1.0
        row[3] = -1.0  # no pocket
        row[5] = min(kick_length / length, 1.0)
        row[8] = 1.0
        row[9] = 1.0
        row[11] = kick_speed / speed_max
    for k in range(rows.shape[0]):
        r = rows[k]
        row = out[k]
        row[0] = 1.0
        if in_hand:
            p = int(r[HAND_POCKET])
            row[1] = numbers[int(r[HAND_TARGET])] / 15.0
            row[2] = pocket_xy[p, 0] / length
            row[3] = pocket_xy[p, 1] / width
            row[6] = min(r[HAND_D_OBJ] / length, 1.0)
            row[7] = min(r[HAND_HALF] / (math.pi / 8.0), 1.0)
            row[8] = 1.0 if r[HAND_CLEAR] != 0.0 else 0.0
            continue
        p = int(r[COL_POCKET])
        row[1] = numbers[int(r[COL_TARGET])] / 15.0
        row[2] = pocket_xy[p, 0] / length
        row[3] = pocket_xy[p, 1] / width
        row[6] = min(r[COL_D_OBJ] / length, 1.0)
        row[4] = _wrap(r[COL_OBJ_ANGLE] - r[COL_ANGLE]) / (math.pi / 2.0)
        row[5] = min(r[COL_D_CUE] / length, 1.0)
        row[7] = min(r[COL_TOL] / EASY_TOLERANCE, 1.0)
        row[8] = 1.0 if r[COL_CLEAR] != 0.0 else 0.0
        row[9] = 1.0 if r[COL_REACH] != 0.0 else 0.0
        row[10] = 1.0 if r[COL_RISK] != 0.0 else 0.0
        row[11] = r[COL_SPEED] / speed_max
    flat = out.reshape(-1)
    for i in range(flat.shape[0]):
        flat[i] = min(max(flat[i], np.float32(-1.0)), np.float32(1.0))
    return flat


# --- the compiled twins of the native vector env's games (a pool state record, a packed config) ---------------------

@njit(cache=True)
def kick_cached(k, targets, pos, on, radius, mass, lo, hi, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r,
                params, kc):
    """The kick of the candidate list (:func:`kick_of`, as :func:`candidate_slots` finds it) for table ``k`` with
    speeds in ``[lo, hi]``, from the table's kick cache ``kc[k]`` when it holds it. Returns ``(found, target, angle,
    speed, length)``."""
    c = kc[k]
    if c["valid"] != 0.0 and c["lo"] == lo and c["hi"] == hi:
        return c["found"] != 0.0, int(c["target"]), c["angle"], c["speed"], c["length"]
    found, j, angle, speed, length = kick_of(pos, on, radius, mass, targets, tm_xy, tm_r, tm_params, lo, hi, pocket_xy,
                                             pocket_r, params, icfg["spin_model"] != 0, icfg["max_events"])
    c["valid"] = 1.0
    c["found"] = found
    c["target"] = j
    c["angle"] = angle
    c["speed"] = speed
    c["length"] = length
    c["lo"] = lo
    c["hi"] = hi
    return found, j, angle, speed, length


@njit(cache=True, inline="always")
def candidates_features_row(k, st, pos, on, radius, mass, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r,
                         params, area, kc, out):
    """Compiled twin of :func:`slot_features` of :func:`candidate_slots` (the ``candidates`` observation's slot
    values, at the observation's speed range) for table ``k`` on its pool state record ``st``, into ``out``."""
    n_slots = icfg["slots"]
    lo = cfg["obs_lo"]
    hi = cfg["obs_hi"]
    keep = max(n_slots - 1, 1)
    targets = pool_targets_row(st, on)
    in_hand = pool_place_area_row(st, cfg["radius"], cfg["kitchen_x"], cfg["length"], cfg["width"], area)
    kick_target, kick_length, kick_speed = -1, 0.0, 0.0
    if st["break_shot"] and not st["over"]:
        rows = np.zeros((0, 16))
    elif in_hand:
        rows = in_hand_slots(pos, on, radius, targets, tm_xy, tm_r, tm_params)[:keep]
    else:
        rows = shot_slots(pos, on, radius, mass, targets, tm_xy, tm_r, tm_params, lo, hi)[:keep]
        clear = False
        for i in range(rows.shape[0]):
            if rows[i, COL_CLEAR] != 0.0:
                clear = True
        if n_slots > 1 and not clear:
            got, j, _, sp, d = kick_cached(k, targets, pos, on, radius, mass, lo, hi, cfg, icfg, tm_xy, tm_r, tm_params,
                                     pocket_xy, pocket_r, params, kc)
            if got:
                kick_target, kick_length, kick_speed = j, d, sp
    numbers = np.arange(pos.shape[0])
    f = _slot_features(rows, in_hand, kick_target, kick_length, kick_speed, numbers, tm_xy, tm_params[0],
                       tm_params[1], hi, n_slots)
    for i in range(f.shape[0]):
        out[i] = f[i]


__all__ = ["Slot", "Slots", "candidate_slots", "next_shot_ease", "slot_features", "SLOT_FEATURES", "EASY_TOLERANCE",
           "EASE_SPREAD", "FALLBACK_CUT", "KICK_ARRIVAL", "KICK_MARGIN", "KICK_FAN", "kick_of"]
