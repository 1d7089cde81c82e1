"""Compiled games of the native vector env: 9-ball and 8-ball tables reset and stepped whole, opponents included.

A step of a game env is the agent's shot, its call, and, when the turn passes, the built-in opponent's shots until
the turn comes back or the game ends. :func:`play_tables` does all of it for every table in one call (slices of the
tables on several threads: the result does not depend on their number), and the reset
(the layout, the rack order, who breaks, the opening, the opponent's break). Each part is the single env's own
code or its compiled twin, with the same floating-point operations in the same order, so that table ``k`` equals a
single env with the same seed and actions, bit for bit (``tests/envs/test_vector_env.py``):

- the action types' arithmetic (:mod:`.actions`: ``aim_to_angle``, ``power_to_speed``, ``square_to_disc``), the
  placement of a ball in hand (:func:`billiards_env.physics.layout.nearest_free_xy`) and the shot path
  (:func:`billiards_env.shot_path.noisy_shot`, the exact kernels, :func:`billiards_env.physics.outcome.scan_shot`);
- the rules (:mod:`billiards_env.rules.pool_judge`, held equal to the Python rules by its tests), the respots
  (:func:`~billiards_env.physics.layout.spot_object_row`, :func:`~billiards_env.physics.layout.spot_cue_row`);
- the geometric opponent (:func:`billiards_env.players.geometry.geometric_decision_arrays`), its action in the
  acting action type and that action read back (``Opponent.action`` then ``ActionType.shot``);
- the ``candidates`` action and observation types (``CandidateShots.shot``, ``CandidateFeatures``: the slot lists
  of :mod:`billiards_env.players.slots`, the kick verified by simulating its fan of aims on a copy of the table, kept
  per table between the observation and the next action), the ``position_reward`` shaping
  (:func:`billiards_env.players.slots.next_shot_ease`), the positions observation and the game features
  (``PoolSession.features``).

Random numbers come from each table's ``numpy.random.Generator`` in the single env's order. What is not compiled
(the ``features`` observation type and reset options per table, the infos as arrays) is done in Python by
:mod:`._vector_games`, from the records these functions write (``R_*`` columns per shot).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from billiards_env.games.pool import pool_features
from billiards_env.physics.exact import simulate_exact
from billiards_env.physics.exact_spin import simulate_exact_spin
from billiards_env.physics.layout import (PLACE_BATCH, PLACE_TRIES, nearest_free_xy, place_random_rows,
                                          spot_cue_row, spot_object_row)
from billiards_env.physics.outcome import scan_shot
from billiards_env.physics.spin_collide import strike_ball
from billiards_env.players.geometry import (ARRIVE_SPEED, COL_ANGLE, COL_CLEAR, COL_POCKET, COL_SPEED, SPEED_FACTORS,
                                            geometric_decision_cached, ghost_shots)
from billiards_env.players.slots import (HAND_OBJ_ANGLE, HAND_POCKET, HAND_TARGET, in_hand_slots, next_shot_ease,
                                         shot_slots)
from billiards_env.rules.pool_judge import (BIH_ANYWHERE, BIH_KITCHEN, BIH_NO, C_FOUL, C_REASON, C_RESPOT, C_SHOOTER,
                                            C_TURN_OVER, GROUPS_OPEN, N_CALL, N_STATE,
                                            S_BIH, S_BREAK, S_GAME, S_GROUPS, S_ON, S_OVER,
                                            S_PUSH_AVAILABLE, S_SHOOTER, S_WINNER, legal_mask, needs_called_pocket,
                                            play)
from billiards_env.shot_path import noisy_shot

from ._kernels import observation
from .actions import (AIM_ABSOLUTE, FALLBACK_SPEED, PLACE_BACK, PLACE_MAX_CUT, PLACED_MAX_CUT,
                      aim_to_angle, angle_to_aim, disc_to_square, power_to_speed, square_to_disc)
from .candidates import _slot_features, kick_of

#: The ``candidates`` action type (``J_AIM``).
AIM_CANDIDATES = 4
# Floats of a game env (``cfg``) and ints (``icfg``): see :func:`billiards_env.envs._vector_games.pack_game`.
K_SPEED_LO, K_SPEED_SPAN, K_MAX_TIP, K_ANGLE_NOISE, K_SPEED_NOISE, K_TIP_NOISE, K_GHOST, K_ACT_GHOST, K_RADIUS, \
    K_LENGTH, K_WIDTH, K_KITCHEN_X, K_HEAD_X, K_HEAD_Y, K_FOOT_X, K_FOOT_Y, K_SPEED_MIN, K_SPEED_MAX, K_WIN, \
    K_LOSS, K_FOUL_PENALTY, K_POT_REWARD, K_POSITION_REWARD, K_EASE_SIGMA, K_SX, K_SY, K_POCKET_MARGIN, \
    K_MIN_DIST, K_BREAK_SPEED, K_MAX_CUT, K_CAND_LO, K_CAND_HI, K_LOG_FACTOR, K_OBS_LO, K_OBS_HI, K_SQUIRT, \
    K_CUE_END_MASS = range(37)
N_K = 37
J_AIM, J_ACT_AIM, J_SPIN_DIMS, J_SPIN_MODEL, J_N_ACT, J_PLACE_AT, J_POCKET_AT, J_PUSH_AT, J_N_POCKETS, J_OPPONENT, \
    J_FIRST, J_OPENING, J_MAX_SHOTS, J_TURN_CAP, J_RACK, J_POSITIONS_OBS, J_SPEED_NOISE_ABS, J_SLOTS, J_MAX_EVENTS, \
    J_OPENING_RESPOT, J_MAX_RERACKS, J_GAME, J_CANDIDATES_OBS = range(23)
N_J = 23
#: The kick cache of a table (``kc`` rows): valid, a kick found, its target, angle, speed, path length, and the speed
#: range it was worked out for.
KC_VALID, KC_FOUND, KC_TARGET, KC_ANGLE, KC_SPEED, KC_LENGTH, KC_LO, KC_HI = range(8)
N_KC = 8
#: ``J_OPPONENT``: none (play alone) or the geometric player.
OPP_NONE, OPP_GEOMETRIC = 0, 1
#: ``J_FIRST``, ``J_OPENING``, ``J_RACK`` codes.
FIRST_AGENT, FIRST_OPPONENT, FIRST_RANDOM = 0, 1, 2
OPEN_BREAK, OPEN_BALL_IN_HAND, OPEN_EITHER = 0, 1, 2
RACK_NONE, RACK_NINE, RACK_EIGHT = 0, 1, 2
# Columns of a shot's record: who shot, the call, what the shot did, the shot as played, the state after it.
R_SHOOTER, R_FOUL, R_REASON, R_TURN_OVER, R_POCKETED, R_SCRATCH, R_FIRST, R_ANGLE, R_SPEED, R_SIDE, R_TOP, R_BIH, \
    R_GROUPS, R_OVER, R_N_EVENTS, R_TIME, R_STATUS, R_START_X, R_START_Y, R_SCORED = range(20)
N_R = 20
# Per-table step outputs (``out`` int columns): terminated, truncated, error, error detail, opponent shots.
T_TERMINATED, T_TRUNCATED, T_ERROR, T_DETAIL, T_N_OPP, T_LAST = range(6)
N_T = 6
#: Errors (``T_ERROR``): none, a ball in hand with no legal point, a ball that could not be respotted, the cue
#: ball that could not be respotted, the random placement failed, the opponent took too many shots, the opponent won
#: every rack at the reset.
E_NONE, E_NO_PLACE, E_RESPOT, E_CUE_RESPOT, E_PLACEMENT, E_TURN_CAP, E_RERACKS = range(7)


# --- the view: who is to shoot and what they may do ---------------------------------------------------------------

@njit(cache=True)
def _targets(st: np.ndarray, on: np.ndarray) -> np.ndarray:
    """``ShotView.targets``: the legal balls on the table (rows; a ball's row is its number), ascending."""
    legal = legal_mask(st)
    n = 0
    out = np.empty(on.shape[0], np.int64)
    for j in range(1, on.shape[0]):
        if (legal >> j) & 1 and on[j]:
            out[n] = j
            n += 1
    return out[:n]


@njit(cache=True)
def _target(st: np.ndarray) -> int:
    """``ShotView.target``: the lowest legal ball (-1: none)."""
    legal = legal_mask(st)
    for j in range(64):
        if (legal >> j) & 1:
            return j
    return -1


@njit(cache=True)
def _area(st: np.ndarray, cfg: np.ndarray, area: np.ndarray) -> bool:
    """``ShotView.place_area`` (``pool_place_area``) into ``area`` ``(x0, x1, y0, y1)``; False: no ball in hand."""
    if st[S_BIH] == BIH_NO or st[S_OVER]:
        return False
    r = cfg[K_RADIUS]
    area[0] = r
    area[1] = cfg[K_KITCHEN_X] if st[S_BIH] == BIH_KITCHEN else cfg[K_LENGTH] - r
    area[2] = r
    area[3] = cfg[K_WIDTH] - r
    return True


# --- the action types ----------------------------------------------------------------------------------------------

@njit(cache=True)
def _angle(code: int, a: float, cx: float, cy: float, t: int, pos: np.ndarray, radius: np.ndarray,
           max_ghost: float) -> float:
    """``ActionType.angle`` with the cue ball at ``(cx, cy)`` and the view's target ``t`` (-1: none)."""
    if code == AIM_ABSOLUTE or t < 0:
        return aim_to_angle(code, a, cx, cy, 0.0, 0.0, False, 0.0, max_ghost)
    return aim_to_angle(code, a, cx, cy, pos[t, 0], pos[t, 1], True, radius[0] + radius[t], max_ghost)


@njit(cache=True)
def _aim(code: int, angle: float, cx: float, cy: float, t: int, pos: np.ndarray, radius: np.ndarray,
         max_ghost: float) -> float:
    """``ActionType.aim`` (the aim component of a cue direction) with the cue ball at ``(cx, cy)`` and the view's
    target ``t`` (-1: none)."""
    if code == AIM_ABSOLUTE or t < 0:
        return angle_to_aim(code, angle, cx, cy, 0.0, 0.0, False, 0.0, max_ghost)
    return angle_to_aim(code, angle, cx, cy, pos[t, 0], pos[t, 1], True, radius[0] + radius[t], max_ghost)


@njit(cache=True)
def _legal_place(x: float, y: float, pos: np.ndarray, on: np.ndarray, radius: np.ndarray, area: np.ndarray,
                 holes: np.ndarray) -> tuple:
    """``TableState.legal_cue_position`` in the view's area: ``(x, y, found)``."""
    return nearest_free_xy(x, y, pos, on, radius, 0, area[0], area[1], area[2], area[3], 1e-6, holes)


@njit(cache=True)
def _shot_of_action(a: np.ndarray, code: int, max_ghost: float, st: np.ndarray, pos: np.ndarray, on: np.ndarray,
                    radius: np.ndarray, cfg: np.ndarray, icfg: np.ndarray, holes: np.ndarray,
                    area: np.ndarray) -> tuple:
    """``ActionType.shot``: the shot an action (float64, clipped) means now. Returns ``(found, angle, speed, side,
    top, placed, x, y, pocket, push)`` (``pocket`` -1: none; found False: no legal point for a ball in hand)."""
    speed = power_to_speed(a[1], cfg[K_SPEED_LO], cfg[K_SPEED_SPAN])
    side = 0.0
    top = 0.0
    if icfg[J_SPIN_DIMS]:
        u, v = square_to_disc(a[2], a[3])
        side = cfg[K_MAX_TIP] * u
        top = cfg[K_MAX_TIP] * v
    pocket = -1
    if icfg[J_POCKET_AT] >= 0:
        n = icfg[J_N_POCKETS]
        pocket = min(int(0.5 * (a[icfg[J_POCKET_AT]] + 1.0) * n), n - 1)
    push = icfg[J_PUSH_AT] >= 0 and a[icfg[J_PUSH_AT]] > 0.0
    t = _target(st)
    if not _area(st, cfg, area):
        angle = _angle(code, a[0], pos[0, 0], pos[0, 1], t, pos, radius, max_ghost)
        return True, angle, speed, side, top, False, 0.0, 0.0, pocket, push
    k = icfg[J_PLACE_AT]
    x = area[0] + 0.5 * (a[k] + 1.0) * (area[1] - area[0])
    y = area[2] + 0.5 * (a[k + 1] + 1.0) * (area[3] - area[2])
    px, py, found = _legal_place(x, y, pos, on, radius, area, holes)
    angle = _angle(code, a[0], px, py, t, pos, radius, max_ghost)
    return found, angle, speed, side, top, True, px, py, pocket, push


@njit(cache=True)
def _action_of_shot(code: int, max_ghost: float, angle: float, speed: float, placed: bool, px: float, py: float,
                    pocket: int, st: np.ndarray, pos: np.ndarray, on: np.ndarray, radius: np.ndarray,
                    cfg: np.ndarray, icfg: np.ndarray, holes: np.ndarray, area: np.ndarray, out: np.ndarray) -> bool:
    """``ActionType.action`` of a shot without tip offsets nor push-out (the geometric player's), as the float32
    action read back as float64 into ``out``. False: no legal point for a ball in hand."""
    out[:] = 0.0
    t = _target(st)
    found = True
    if placed and _area(st, cfg, area):
        k = icfg[J_PLACE_AT]
        out[k] = 2.0 * (px - area[0]) / max(area[1] - area[0], 1e-12) - 1.0
        out[k + 1] = 2.0 * (py - area[2]) / max(area[3] - area[2], 1e-12) - 1.0
        lx, ly, found = _legal_place(px, py, pos, on, radius, area, holes)
        out[0] = _aim(code, angle, lx, ly, t, pos, radius, max_ghost)
    else:
        out[0] = _aim(code, angle, pos[0, 0], pos[0, 1], t, pos, radius, max_ghost)
    out[1] = 2.0 * (speed - cfg[K_SPEED_LO]) / cfg[K_SPEED_SPAN] - 1.0
    if icfg[J_SPIN_DIMS]:
        out[2], out[3] = disc_to_square(0.0 / cfg[K_MAX_TIP], 0.0 / cfg[K_MAX_TIP])
    if icfg[J_POCKET_AT] >= 0:
        n = icfg[J_N_POCKETS]
        k = 0 if pocket < 0 else min(max(pocket, 0), n - 1)
        out[icfg[J_POCKET_AT]] = (2.0 * k + 1.0) / n - 1.0
    if icfg[J_PUSH_AT] >= 0:
        out[icfg[J_PUSH_AT]] = -1.0
    for i in range(out.shape[0]):
        out[i] = np.float64(np.float32(min(max(out[i], -1.0), 1.0)))
    return found


# --- the ``candidates`` action and observation types -----------------------------------------------------------------

_SPEED_FACTORS = np.array(SPEED_FACTORS)


@njit(cache=True)
def _direct_hit(targets: np.ndarray, pos: np.ndarray, on: np.ndarray, cx: float, cy: float) -> float:
    """``players.shots.direct_hit`` with the cue ball at ``(cx, cy)``: the direction of the nearest legal ball."""
    best = math.inf
    j = -1
    for t in range(targets.shape[0]):
        b = targets[t]
        if on[b] and b != 0:
            d = math.hypot(pos[b, 0] - cx, pos[b, 1] - cy)
            if d < best:
                best = d
                j = b
    if j < 0:
        return 0.0
    return math.atan2(pos[j, 1] - cy, pos[j, 0] - cx)


@njit(cache=True)
def _kick(k, targets, pos, on, radius, mass, lo, hi, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params,
          kc):
    """The kick of ``envs/candidates.py`` (:func:`~billiards_env.envs.candidates.kick_of`) for table ``k`` with
    speeds in ``[lo, hi]``, from the table's kick cache ``kc[k]`` when it holds it. Returns ``(found, target, angle,
    speed, length)``."""
    c = kc[k]
    if c[KC_VALID] != 0.0 and c[KC_LO] == lo and c[KC_HI] == hi:
        return c[KC_FOUND] != 0.0, int(c[KC_TARGET]), c[KC_ANGLE], c[KC_SPEED], c[KC_LENGTH]
    found, j, angle, speed, length = kick_of(pos, on, radius, mass, targets, tm_xy, tm_r, tm_params, lo, hi, pocket_xy,
                                             pocket_r, params, icfg[J_SPIN_MODEL] != 0, icfg[J_MAX_EVENTS])
    c[KC_VALID] = 1.0
    c[KC_FOUND] = found
    c[KC_TARGET] = j
    c[KC_ANGLE] = angle
    c[KC_SPEED] = speed
    c[KC_LENGTH] = length
    c[KC_LO] = lo
    c[KC_HI] = hi
    return found, j, angle, speed, length


@njit(cache=True)
def _cand_speed(base: float, a: float, cfg: np.ndarray) -> float:
    """``CandidateShots._speed``: ``base`` times the speed factor to the power ``a``, within the type's range."""
    return min(max(base * math.exp(a * cfg[K_LOG_FACTOR]), cfg[K_CAND_LO]), cfg[K_CAND_HI])


@njit(cache=True)
def _candidates_shot(k, a, st, pos, on, radius, mass, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r,
                     params, holes, area, kc):
    """``CandidateShots.shot`` of table ``k``'s action ``a``: the chosen slot (a pot, the kick, the break, or the
    direct hit when there is no pot), its speed scaled, the cue ball placed for it with ball in hand. Returns
    ``_shot_of_action``'s tuple."""
    found, angle, speed, side, top, placed, px, py, pocket, push = _shot_of_action(
        a, AIM_ABSOLUTE, 0.0, st, pos, on, radius, cfg, icfg, holes, area)  # side, top, declarations, placement
    if not found:
        return found, angle, speed, side, top, placed, px, py, pocket, push
    n_slots = icfg[J_SLOTS]
    lo = cfg[K_CAND_LO]
    hi = cfg[K_CAND_HI]
    keep = max(n_slots - 1, 1)
    targets = _targets(st, on)
    in_hand = _area(st, cfg, area)
    if st[S_BREAK] and not st[S_OVER]:
        cx, cy = (px, py) if placed else (pos[0, 0], pos[0, 1])
        if in_hand:
            kp = icfg[J_PLACE_AT]
            cx, cy, ok = _legal_place(area[1] - abs(a[kp]) * (area[1] - area[0]),
                                      area[2] + 0.5 * (a[kp + 1] + 1.0) * (area[3] - area[2]), pos, on, radius, area,
                                      holes)
            if not ok:
                return False, angle, speed, side, top, placed, px, py, pocket, push
            placed, px, py = True, cx, cy
        angle = _direct_hit(targets, pos, on, cx, cy)
        sp = hi * math.exp(min(a[1], 0.0) * cfg[K_LOG_FACTOR])
        return True, angle, max(sp, lo), side, top, placed, px, py, pocket, push
    kicks = n_slots > 1 and int(abs(a[0]) * n_slots) >= n_slots - 1
    cx, cy = (px, py) if placed else (pos[0, 0], pos[0, 1])
    if not in_hand:
        rows = shot_slots(pos, on, radius, mass, targets, tm_xy, tm_r, tm_params, lo, hi)[:keep]
        if kicks:
            clear = False
            for i in range(rows.shape[0]):
                if rows[i, COL_CLEAR] != 0.0:
                    clear = True
            if not clear:
                got, _, k_angle, k_speed, _ = _kick(k, targets, pos, on, radius, mass, lo, hi, cfg, icfg, tm_xy,
                                                    tm_r, tm_params, pocket_xy, pocket_r, params, kc)
                if got:
                    return True, k_angle, k_speed, 0.0, 0.0, placed, px, py, pocket, push
        n = rows.shape[0]
        if n == 0:
            return True, _direct_hit(targets, pos, on, cx, cy), _cand_speed(FALLBACK_SPEED, a[1], cfg), side, top, \
                placed, px, py, pocket, push
        row = rows[0 if kicks else min(int(abs(a[0]) * n_slots), n_slots - 1, n - 1)]
        if icfg[J_POCKET_AT] >= 0:
            pocket = int(row[COL_POCKET])
        return True, row[COL_ANGLE], _cand_speed(row[COL_SPEED], a[1], cfg), side, top, placed, px, py, pocket, push
    rows = in_hand_slots(pos, on, radius, targets, tm_xy, tm_r, tm_params)[:keep]
    n = rows.shape[0]
    if n == 0:
        return True, _direct_hit(targets, pos, on, cx, cy), _cand_speed(FALLBACK_SPEED, a[1], cfg), side, top, \
            placed, px, py, pocket, push
    row = rows[0 if kicks else min(int(abs(a[0]) * n_slots), n_slots - 1, n - 1)]
    j = int(row[HAND_TARGET])
    p = int(row[HAND_POCKET])
    oa = row[HAND_OBJ_ANGLE]
    if icfg[J_POCKET_AT] >= 0:
        pocket = p
    # CandidateShots._place_for: behind the ghost ball, at the cut of place_y.
    kp = icfg[J_PLACE_AT]
    contact = radius[0] + radius[j]
    gx = pos[j, 0] - contact * math.cos(oa)
    gy = pos[j, 1] - contact * math.sin(oa)
    back = PLACE_BACK[0] + 0.5 * (a[kp] + 1.0) * (PLACE_BACK[1] - PLACE_BACK[0])
    d = oa + a[kp + 1] * PLACE_MAX_CUT
    x = gx - back * math.cos(d)
    y = gy - back * math.sin(d)
    qx, qy, ok = _legal_place(min(max(x, area[0]), area[1]), min(max(y, area[2]), area[3]), pos, on, radius, area,
                              holes)
    if not ok:
        return False, angle, speed, side, top, placed, px, py, pocket, push
    # CandidateShots._placed_shot: the ghost-ball shot at that pocket from there, else a hit at the ghost ball.
    p2 = pos.copy()
    o2 = on.copy()
    p2[0, 0] = qx
    p2[0, 1] = qy
    o2[0] = True
    shots = ghost_shots(p2, o2, radius, mass, 0, np.array([j]), tm_xy, tm_r, tm_params, lo, hi, PLACED_MAX_CUT,
                        ARRIVE_SPEED, _SPEED_FACTORS, True)
    base_angle = math.atan2(gy - qy, gx - qx)
    base_speed = FALLBACK_SPEED
    for i in range(shots.shape[0]):
        if int(shots[i, COL_POCKET]) == p:
            base_angle = shots[i, COL_ANGLE]
            base_speed = shots[i, COL_SPEED]
            break
    return True, base_angle, _cand_speed(base_speed, a[1], cfg), side, top, True, qx, qy, pocket, push


@njit(cache=True)
def _candidates_features(k, st, pos, on, radius, mass, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r,
                         params, area, kc, out):
    """The ``candidates`` observation's slot values of table ``k`` (``envs/candidates.py`` ``slot_features`` of
    ``candidate_slots`` at the observation's speed range) into ``out``."""
    n_slots = icfg[J_SLOTS]
    lo = cfg[K_OBS_LO]
    hi = cfg[K_OBS_HI]
    keep = max(n_slots - 1, 1)
    targets = _targets(st, on)
    in_hand = _area(st, cfg, area)
    kick_target, kick_length, kick_speed = -1, 0.0, 0.0
    if st[S_BREAK] and not st[S_OVER]:
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
            got, j, _, sp, d = _kick(k, targets, pos, on, radius, mass, lo, hi, cfg, icfg, tm_xy, tm_r, tm_params,
                                     pocket_xy, pocket_r, params, kc)
            if got:
                kick_target, kick_length, kick_speed = j, d, sp
    numbers = np.arange(pos.shape[0])
    f = _slot_features(rows, in_hand, kick_target, kick_length, kick_speed, numbers, tm_xy, tm_params[0],
                       tm_params[1], hi, n_slots)
    for i in range(f.shape[0]):
        out[i] = f[i]


# --- one shot: played, judged, applied --------------------------------------------------------------------------------

@njit(cache=True)
def _play(k, angle, speed, side, top, placed, px, py, pos, vel, ang, on, radius, mass, gens, cfg, icfg, pocket_xy,
          pocket_r, params, rec):
    """``shot_path.play_shot`` on table ``k``: the cue ball placed, the noise drawn from the table's generator, the
    strike, the exact kernel, the balls stopped. Records the shot as played; returns the kernel's result."""
    p = pos[k]
    if placed:
        p[0, 0] = px
        p[0, 1] = py
    an = cfg[K_ANGLE_NOISE]
    sn = cfg[K_SPEED_NOISE]
    tn = cfg[K_TIP_NOISE]
    n_a = 0.0
    n_s = 0.0
    n_sd = 0.0
    n_tp = 0.0
    if an > 0.0 or sn > 0.0 or tn > 0.0:
        g = gens[k]
        if an > 0.0:
            n_a = g.normal(0.0, an)
        if sn > 0.0:
            n_s = g.normal(0.0, sn)
        if tn > 0.0:
            n_sd = g.normal(0.0, tn)
            n_tp = g.normal(0.0, tn)
    angle, speed, side, top = noisy_shot(angle, speed, side, top, n_a, n_s, n_sd, n_tp, an > 0.0, sn > 0.0,
                                         tn > 0.0, icfg[J_SPEED_NOISE_ABS] != 0)
    rec[R_START_X] = p[0, 0]
    rec[R_START_Y] = p[0, 1]
    rec[R_ANGLE] = angle
    rec[R_SPEED] = speed
    rec[R_SIDE] = side
    rec[R_TOP] = top
    if icfg[J_SPIN_MODEL]:  # the tip offsets' spin, and the squirt of the physics (as the shot path strikes)
        vx, vy, wx, wy, wz = strike_ball(angle, speed, side, top, radius[0], mass[0], cfg[K_SQUIRT],
                                         cfg[K_CUE_END_MASS])
        vel[k, 0, 0] = vx
        vel[k, 0, 1] = vy
        ang[k, 0, 0] = wx
        ang[k, 0, 1] = wy
        ang[k, 0, 2] = wz
        res = simulate_exact_spin(p, vel[k], ang[k], radius, mass, on[k], pocket_xy, pocket_r, params,
                                  icfg[J_MAX_EVENTS], False)
        ang[k] = 0.0
    else:
        vel[k, 0, 0] = speed * math.cos(angle)
        vel[k, 0, 1] = speed * math.sin(angle)
        res = simulate_exact(p, vel[k], ang[k], radius, mass, on[k], pocket_xy, pocket_r, params,
                             icfg[J_MAX_EVENTS], False)
    vel[k] = 0.0
    rec[R_N_EVENTS] = res.n_events
    rec[R_TIME] = res.time
    rec[R_STATUS] = res.status
    return res.pocket, res.ev_int


@njit(cache=True)
def _judge(k, pocket, ev_int, shot_pocket, shot_push, st, opts, pos, on, cfg, call, after, buf, rec):
    """``GameSession.judge`` of table ``k``'s shot (``pocket``, ``ev_int``: the kernel's): the summary, the rules'
    call and the next state (``st`` updated), the respots; records the call. Returns an error code."""
    first, rail, order, n_order = scan_shot(ev_int, pocket, 0)
    nb = pocket.shape[0]
    rails = 0
    pocketed_rows = 0
    for r in range(nb):
        if rail[r]:
            rails |= 1 << r
        if pocket[r] >= 0:
            pocketed_rows |= 1 << r
    pocketed = buf[0]
    pockets = buf[1]
    for i in range(n_order):
        pocketed[i] = order[i]
        pockets[i] = pocket[order[i]]
    push = shot_push and st[S_PUSH_AVAILABLE] != 0
    called = shot_pocket if needs_called_pocket(st, opts) else -1
    play(st, opts, first, rails, pocketed, pockets, n_order, pocket[0] >= 0, push, called, call, after)
    st[:] = after
    err = E_NONE
    kept = 0
    for i in range(n_order):
        n = pocketed[i]
        if (call[C_RESPOT] >> n) & 1:
            if not spot_object_row(pos[k], on[k], cfg[K_RADIUS], n, cfg[K_FOOT_X], cfg[K_FOOT_Y], cfg[K_LENGTH]):
                err = E_RESPOT
        else:
            kept += 1
    if not on[k, 0]:
        if not spot_cue_row(pos[k], on[k], cfg[K_RADIUS], 0, cfg[K_HEAD_X], cfg[K_HEAD_Y], cfg[K_WIDTH]):
            err = E_CUE_RESPOT
    rec[R_SHOOTER] = call[C_SHOOTER]
    rec[R_FOUL] = call[C_FOUL]
    rec[R_REASON] = call[C_REASON]
    rec[R_TURN_OVER] = call[C_TURN_OVER]
    rec[R_POCKETED] = pocketed_rows
    rec[R_SCRATCH] = pocket[0] >= 0
    rec[R_FIRST] = first
    rec[R_BIH] = BIH_NO if st[S_OVER] else st[S_BIH]
    rec[R_GROUPS] = st[S_GROUPS]
    rec[R_OVER] = st[S_OVER]
    rec[R_SCORED] = kept
    return err


@njit(cache=True)
def _opponent_turn(k, pos, vel, ang, on, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy, pocket_r, params,
                   tm_xy, tm_r, tm_params, holes, recs, call, after, buf, act, area, dec_area, wc):
    """``GameTask._opponent_turn`` of table ``k`` with the geometric opponent: its decision, its action in the
    acting type read back, the shot played and judged, until the agent's turn or the end of the game. Returns
    ``(shots, error)``."""
    st = gst[k]
    n = 0
    cap = icfg[J_TURN_CAP]
    while not st[S_OVER] and st[S_SHOOTER] != 0 and n < cap:
        targets = _targets(st, on[k])
        in_hand = _area(st, cfg, dec_area)
        if not in_hand:
            dec_area[:] = 0.0
        px, py, placed, angle, speed, kr, rows, status = geometric_decision_cached(
            pos[k], on[k], radius, mass, 0, targets, tm_xy, tm_r, tm_params, cfg[K_SPEED_MIN], cfg[K_SPEED_MAX],
            dec_area, in_hand, st[S_BREAK] != 0, cfg[K_MAX_CUT], wc[0][k], wc[1][k], wc[2][k])
        if status == 1:
            return n, E_NO_PLACE
        pocket = int(rows[kr, COL_POCKET]) if kr >= 0 else -1
        code = icfg[J_ACT_AIM]
        if not _action_of_shot(code, cfg[K_ACT_GHOST], angle, speed, placed, px, py, pocket, st, pos[k], on[k],
                               radius, cfg, icfg, holes, area, act):
            return n, E_NO_PLACE
        found, angle, speed, side, top, placed, px, py, pocket, push = _shot_of_action(
            act, code, cfg[K_ACT_GHOST], st, pos[k], on[k], radius, cfg, icfg, holes, area)
        if not found:
            return n, E_NO_PLACE
        rec = recs[n]
        pk, ev = _play(k, angle, speed, side, top, placed, px, py, pos, vel, ang, on, radius, mass, gens, cfg, icfg,
                       pocket_xy, pocket_r, params, rec)
        err = _judge(k, pk, ev, pocket, push, st, opts, pos, on, cfg, call, after, buf, rec)
        n += 1
        if err != E_NONE:
            return n, err
    if not st[S_OVER] and st[S_SHOOTER] != 0:
        return n, E_TURN_CAP
    return n, E_NONE


# --- a step of one table ----------------------------------------------------------------------------------------------

@njit(cache=True)
def _step_table(k, act, kc, pos, vel, ang, on, shots, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy, pocket_r,
                params, tm_xy, tm_r, tm_params, holes, rec_agent, rec_opp, reward, tout, obs, wc):
    """One ``env.step`` of table ``k`` (see :func:`play_tables`)."""
    call = np.zeros(N_CALL, np.int64)
    after = np.zeros(N_STATE, np.int64)
    buf = np.zeros((2, pos.shape[1]), np.int64)
    area = np.zeros(4)
    dec_area = np.zeros(4)
    a = np.empty(icfg[J_N_ACT])
    st = gst[k]
    tout[k, T_ERROR] = E_NONE
    tout[k, T_N_OPP] = 0
    # The agent's shot: its action read by the env's type.
    for i in range(a.shape[0]):
        a[i] = act[k, i]
    if icfg[J_AIM] == AIM_CANDIDATES:
        found, angle, speed, side, top, placed, px, py, pocket, push = _candidates_shot(
            k, a, st, pos[k], on[k], radius, mass, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params,
            holes, area, kc)
    else:
        found, angle, speed, side, top, placed, px, py, pocket, push = _shot_of_action(
            a, icfg[J_AIM], cfg[K_GHOST], st, pos[k], on[k], radius, cfg, icfg, holes, area)
    kc[k, KC_VALID] = 0.0  # the table moves on
    if not found:
        tout[k, T_ERROR] = E_NO_PLACE
        return
    rec = rec_agent[k]
    pk, ev = _play(k, angle, speed, side, top, placed, px, py, pos, vel, ang, on, radius, mass, gens, cfg, icfg,
                   pocket_xy, pocket_r, params, rec)
    shots[k] += 1
    err = _judge(k, pk, ev, pocket, push, st, opts, pos, on, cfg, call, after, buf, rec)
    if err != E_NONE:
        tout[k, T_ERROR] = err
        return
    # GameTask._judge's ease and _shaping (the agent's own shot).
    ease = 0.0
    if cfg[K_POSITION_REWARD] != 0.0 and not st[S_OVER] and not rec[R_TURN_OVER] and rec[R_SHOOTER] == 0:
        targets = _targets(st, on[k])
        if st[S_BREAK] == 0 and (st[S_BIH] == BIH_NO or st[S_OVER]) and icfg[J_SLOTS] >= 1:
            ease = next_shot_ease(pos[k], on[k], radius, mass, targets, tm_xy, tm_r, tm_params, cfg[K_SPEED_MIN],
                                  cfg[K_SPEED_MAX], cfg[K_EASE_SIGMA])
    r = 0.0
    if rec[R_SHOOTER] == 0:
        if rec[R_FOUL]:
            r -= cfg[K_FOUL_PENALTY]
        elif cfg[K_POT_REWARD] != 0.0:
            r += cfg[K_POT_REWARD] * rec[R_SCORED]
        if cfg[K_POSITION_REWARD] != 0.0:
            r += cfg[K_POSITION_REWARD] * ease
    practice_over = False
    if not st[S_OVER] and st[S_SHOOTER] != 0:
        if icfg[J_OPPONENT] == OPP_NONE:
            practice_over = True
        else:
            n_opp, err = _opponent_turn(k, pos, vel, ang, on, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy,
                                        pocket_r, params, tm_xy, tm_r, tm_params, holes, rec_opp[k], call, after, buf,
                                        a, area, dec_area, wc)
            tout[k, T_N_OPP] = n_opp
            if err != E_NONE:
                tout[k, T_ERROR] = err
                return
    if st[S_OVER]:
        r += cfg[K_WIN] if st[S_WINNER] == 0 else -cfg[K_LOSS]
    terminated = st[S_OVER] != 0 or practice_over
    reward[k] = r
    tout[k, T_TERMINATED] = terminated
    tout[k, T_TRUNCATED] = not terminated and shots[k] >= icfg[J_MAX_SHOTS]
    tout[k, T_LAST] = tout[k, T_N_OPP]  # the last shot: the agent's (0) or the opponent's n-th
    _observe(k, pos, on, radius, mass, gst, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params, kc, obs)


# --- a reset of one table --------------------------------------------------------------------------------------------

@njit(cache=True)
def _initial(st: np.ndarray, game: int, full: int, first: int) -> None:
    """``Ruleset.initial_state(first_shooter=first)``: the full rack on, ball in hand in the kitchen, the break."""
    st[:] = 0
    st[S_GAME] = game
    st[S_ON] = full
    st[S_SHOOTER] = first
    st[S_BIH] = BIH_KITCHEN
    st[S_GROUPS] = GROUPS_OPEN
    st[S_BREAK] = 1
    st[S_WINNER] = -1


@njit(cache=True)
def _order_rack(k, g, pos, rack_slots, mode):
    """``PoolSession.order_rack``: the rack's numbers slot by slot, drawn as the rules say (9-ball: the 1 at the apex,
    the 9 in the middle; 8-ball: the 8 in the middle, a solid and a stripe in the back corners)."""
    n_slots = rack_slots.shape[0]
    number = np.zeros(n_slots, np.int64)
    if mode == RACK_NINE:
        free = np.arange(2, 9)
        number[0] = 1
        number[4] = 9
    else:
        corner_solid = g.integers(0, 2)
        solid = 1 + g.integers(0, 7)
        stripe = 9 + g.integers(0, 7)
        number[4] = 8
        number[10] = solid if corner_solid else stripe
        number[14] = stripe if corner_solid else solid
        free = np.empty(12, np.int64)
        m = 0
        for n in range(1, 16):
            if n != 8 and n != solid and n != stripe:
                free[m] = n
                m += 1
    perm = g.permutation(free.shape[0])
    m = 0
    for slot in range(n_slots):
        if number[slot] == 0:
            number[slot] = free[perm[m]]
            m += 1
        pos[k, number[slot], 0] = rack_slots[slot, 0]
        pos[k, number[slot], 1] = rack_slots[slot, 1]


@njit(cache=True)
def _reset_table(k, pos, vel, ang, on, shots, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy, pocket_r, params,
                 tm_xy, tm_r, tm_params, holes, fixed_rows, fixed_xy, rand_rows, regions, pockets, rack_slots, full,
                 rec_agent, rec_opp, tout, kc, obs, wc):
    """One ``env.reset()`` of table ``k`` (no options; see :func:`reset_tables`)."""
    call = np.zeros(N_CALL, np.int64)
    after = np.zeros(N_STATE, np.int64)
    buf = np.zeros((2, pos.shape[1]), np.int64)
    area = np.zeros(4)
    dec_area = np.zeros(4)
    a = np.empty(icfg[J_N_ACT])
    g = gens[k]
    st = gst[k]
    tout[k, T_ERROR] = E_NONE
    tout[k, T_N_OPP] = 0
    tout[k, T_LAST] = -1
    kc[k, KC_VALID] = 0.0
    vel[k] = 0.0
    ang[k] = 0.0
    on[k] = True
    nf = fixed_rows.shape[0]
    placed = np.empty((nf + rand_rows.shape[0], 2))
    for f in range(nf):
        pos[k, fixed_rows[f], 0] = fixed_xy[f, 0]
        pos[k, fixed_rows[f], 1] = fixed_xy[f, 1]
        placed[f, 0] = fixed_xy[f, 0]
        placed[f, 1] = fixed_xy[f, 1]
    if place_random_rows(g, pos[k], rand_rows, regions, placed, nf, pockets, cfg[K_POCKET_MARGIN], cfg[K_MIN_DIST],
                         PLACE_BATCH, PLACE_TRIES) >= 0:
        tout[k, T_ERROR] = E_PLACEMENT
        return
    shots[k] = 0
    if icfg[J_OPPONENT] != OPP_NONE:
        g.integers(0, 2 ** 31)  # the opponent's reset(seed) draw (the geometric player ignores the seed)
    game = icfg[J_GAME]
    for attempt in range(icfg[J_MAX_RERACKS]):
        tout[k, T_N_OPP] = 0  # the turns of this attempt only
        tout[k, T_LAST] = -1
        if icfg[J_RACK] != RACK_NONE:
            _order_rack(k, g, pos, rack_slots, icfg[J_RACK])
        first = icfg[J_FIRST]
        if first == FIRST_RANDOM:
            first = g.integers(0, 2)
        if first != 0 and icfg[J_OPPONENT] == OPP_NONE:
            first = 0
        _initial(st, game, full, first)
        opening = icfg[J_OPENING]
        if opening == OPEN_EITHER:
            opening = OPEN_BALL_IN_HAND if g.integers(0, 2) else OPEN_BREAK
        if opening == OPEN_BALL_IN_HAND:
            # GameTask._open_with_ball_in_hand: the env's break at the nearest legal ball, then ball in hand.
            legal = legal_mask(st)
            cx = pos[k, 0, 0]
            cy = pos[k, 0, 1]
            target = -1
            best = math.inf
            for j in range(pos.shape[1]):
                if (legal >> j) & 1:
                    d = math.hypot(pos[k, j, 0] - cx, pos[k, j, 1] - cy)
                    if d < best:
                        best = d
                        target = j
            rec = rec_agent[k]
            _play(k, math.atan2(pos[k, target, 1] - cy, pos[k, target, 0] - cx), cfg[K_BREAK_SPEED], 0.0, 0.0, False,
                  0.0, 0.0, pos, vel, ang, on, radius, mass, gens, cfg, icfg, pocket_xy, pocket_r, params, rec)
            last = icfg[J_OPENING_RESPOT]
            if not on[k, last]:
                if not spot_object_row(pos[k], on[k], cfg[K_RADIUS], last, cfg[K_FOOT_X], cfg[K_FOOT_Y],
                                       cfg[K_LENGTH]):
                    tout[k, T_ERROR] = E_RESPOT
                    return
            if not on[k, 0]:
                if not spot_cue_row(pos[k], on[k], cfg[K_RADIUS], 0, cfg[K_HEAD_X], cfg[K_HEAD_Y], cfg[K_WIDTH]):
                    tout[k, T_ERROR] = E_CUE_RESPOT
                    return
            on_mask = 0
            for j in range(1, pos.shape[1]):
                if on[k, j]:
                    on_mask |= 1 << j
            st[:] = 0
            st[S_GAME] = game
            st[S_ON] = on_mask
            st[S_SHOOTER] = first
            st[S_BIH] = BIH_ANYWHERE
            st[S_GROUPS] = GROUPS_OPEN
            st[S_WINNER] = -1
        if first == 0 or icfg[J_OPPONENT] == OPP_NONE:
            break
        n_opp, err = _opponent_turn(k, pos, vel, ang, on, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy,
                                    pocket_r, params, tm_xy, tm_r, tm_params, holes, rec_opp[k], call, after, buf, a,
                                    area, dec_area, wc)
        tout[k, T_N_OPP] = n_opp
        tout[k, T_LAST] = n_opp if n_opp > 0 else -1
        if err != E_NONE:
            tout[k, T_ERROR] = err
            return
        if not st[S_OVER]:
            break
        on[k] = True  # the opponent won from the break: rack again
        vel[k] = 0.0
        if attempt == icfg[J_MAX_RERACKS] - 1:
            tout[k, T_ERROR] = E_RERACKS
            return
    _observe(k, pos, on, radius, mass, gst, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params, kc, obs)


# --- the observation -----------------------------------------------------------------------------------------------

@njit(cache=True)
def _observe(k, pos, on, radius, mass, gst, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params, kc, obs):
    """Table ``k``'s observation into ``obs[k]`` when its type is compiled: the positions, the ``candidates`` slot
    values for that type, the game features."""
    if not (icfg[J_POSITIONS_OBS] or icfg[J_CANDIDATES_OBS]):
        return
    p = observation(pos[k], on[k], cfg[K_SX], cfg[K_SY])
    n = p.shape[0]
    for i in range(n):
        obs[k, i] = p[i]
    if icfg[J_CANDIDATES_OBS]:
        m = 12 * icfg[J_SLOTS]
        _candidates_features(k, gst[k], pos[k], on[k], radius, mass, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy,
                             pocket_r, params, np.zeros(4), kc, obs[k, n:n + m])
        n += m
    pool_features(gst[k], gst[k, S_SHOOTER], obs[k, n:])


@njit(cache=True)
def observe_tables(rows, pos, on, radius, mass, gst, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params,
                   kc, obs):
    """:func:`_observe` for tables ``rows``."""
    for q in range(rows.shape[0]):
        _observe(rows[q], pos, on, radius, mass, gst, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params,
                 kc, obs)


@njit(cache=True)
def legal_masks(gst: np.ndarray, out: np.ndarray) -> None:
    """The legal balls (a mask of their numbers) of every table's game state into ``out``."""
    for k in range(gst.shape[0]):
        out[k] = legal_mask(gst[k])


# --- N tables --------------------------------------------------------------------------------------------------------

@njit(cache=True, nogil=True)
def play_tables(rows, resets, act, kc, pos, vel, ang, on, shots, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy,
                pocket_r, params, tm_xy, tm_r, tm_params, holes, layout, rack_slots, full, rec_agent, rec_opp, reward,
                tout, obs, wc):
    """A step of tables ``rows``, or a reset of those whose ``resets`` is set, one after the other. It releases the
    GIL: the vector env runs slices of ``rows`` on several Python threads at once (a table's result does not depend
    on the slice it is in). Threads instead of numba's ``prange``: the parallel pipeline took about 20 s more to
    compile this function, on every cold cache.

    A step: the agent's shot (``act``: the actions, float64 clipped; ``kc``: the tables' kick caches, ``KC_*``, for
    the ``candidates`` types), its call and reward, the opponent's turn, the termination and truncation (``tout``).
    A reset: the layout (``layout``: the fixed rows and their points, the random rows and their regions, the pocket
    centres; ``rack_slots``, ``full``: the rack's slots and balls), the game's reset, the opponent's break when it
    breaks. Both record every shot (``rec_agent``, ``rec_opp``) and, for the positions and candidates observation
    types, write the observation (``obs``). ``wc``: each table's cache of its balls' pocket windows for the
    geometric opponent (``(pos (N, B, 2), windows (N, B, K, 4), have (N, B))``, see
    :func:`~billiards_env.players.geometry.windows_cached`), kept from call to call: the same decisions, the windows
    of the balls that did not move since the table's last decision not worked out again."""
    fixed_rows, fixed_xy, rand_rows, regions, pockets = layout
    for q in range(rows.shape[0]):
        if resets[q]:
            _reset_table(rows[q], pos, vel, ang, on, shots, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy,
                         pocket_r, params, tm_xy, tm_r, tm_params, holes, fixed_rows, fixed_xy, rand_rows, regions,
                         pockets, rack_slots, full, rec_agent, rec_opp, tout, kc, obs, wc)
        else:
            _step_table(rows[q], act, kc, pos, vel, ang, on, shots, radius, mass, gens, gst, opts, cfg, icfg,
                        pocket_xy, pocket_r, params, tm_xy, tm_r, tm_params, holes, rec_agent, rec_opp, reward, tout,
                        obs, wc)


__all__ = ["play_tables", "observe_tables", "legal_masks", "AIM_CANDIDATES", "N_K", "N_J", "N_R", "N_T",
           "N_KC"]
