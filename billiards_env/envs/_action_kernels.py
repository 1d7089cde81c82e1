"""The action types compiled: twins of :meth:`ActionType.shot <billiards_env.envs.actions.ActionType.shot>` and
:meth:`~billiards_env.envs.actions.ActionType.action` (the absolute, relative and ghost aims) and of
:meth:`CandidateShots.shot <billiards_env.envs.actions.CandidateShots.shot>`, on a pool game's state record
(:mod:`billiards_env.rules.pool_judge`) and a packed config (:mod:`._game_config`), for the native vector env's
games (:mod:`._game_kernels`). The arithmetic of an action is one implementation: :func:`~.actions.aim_to_angle`,
:func:`~.actions.angle_to_aim`, :func:`~.actions.power_to_speed`, :func:`~.actions.square_to_disc` and
:func:`~.actions.disc_to_square` are compiled in :mod:`.actions` and called by both paths; what is twinned here is
the reading of the vector around it (the view, the placement, the declarations). ``tests/envs/test_vector_env.py``
holds the two paths equal, bit for bit.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from billiards_env.games.pool import pool_place_area_row, pool_target_row
from billiards_env.physics.layout import nearest_free_xy
from billiards_env.physics.plain import plain
from billiards_env.players.geometry import (ARRIVE_SPEED, COL_ANGLE, COL_CLEAR, COL_POCKET, COL_SPEED, SPEED_FACTORS,
                                            ghost_shots)
from billiards_env.players.slots import HAND_OBJ_ANGLE, HAND_POCKET, HAND_TARGET, in_hand_slots, shot_slots

from .actions import (AIM_ABSOLUTE, FALLBACK_SPEED, PLACE_BACK, PLACE_MAX_CUT, PLACED_MAX_CUT, aim_to_angle,
                      angle_to_aim, disc_to_square, power_to_speed, square_to_disc)
from .candidates import kick_cached, pool_targets_row
from billiards_env.physics.kernel_logs import leaf_public

_SPEED_FACTORS = np.array(SPEED_FACTORS)


@njit(cache=True)
def angle_of_action(code: int, a: float, cx: float, cy: float, t: int, pos: np.ndarray, radius: np.ndarray,
                    max_ghost: float) -> float:
    """Compiled twin of :meth:`ActionType.angle <billiards_env.envs.actions.ActionType.angle>` with the cue ball at
    ``(cx, cy)`` and the view's target ``t`` (-1: none): :func:`~.actions.aim_to_angle`, as there."""
    if code == AIM_ABSOLUTE or t < 0:
        return aim_to_angle(code, a, cx, cy, 0.0, 0.0, plain(False), 0.0, max_ghost)
    return aim_to_angle(code, a, cx, cy, pos[t, 0], pos[t, 1], plain(True), radius[0] + radius[t], max_ghost)


@njit(cache=True)
def aim_of_angle(code: int, angle: float, cx: float, cy: float, t: int, pos: np.ndarray, radius: np.ndarray,
                 max_ghost: float) -> float:
    """Compiled twin of :meth:`ActionType.aim <billiards_env.envs.actions.ActionType.aim>` (the aim component of a
    cue direction) with the cue ball at ``(cx, cy)`` and the view's target ``t`` (-1: none):
    :func:`~.actions.angle_to_aim`, as there."""
    if code == AIM_ABSOLUTE or t < 0:
        return angle_to_aim(code, angle, cx, cy, 0.0, 0.0, plain(False), 0.0, max_ghost)
    return angle_to_aim(code, angle, cx, cy, pos[t, 0], pos[t, 1], plain(True), radius[0] + radius[t], max_ghost)


@leaf_public
def legal_place(x: float, y: float, pos: np.ndarray, on: np.ndarray, radius: np.ndarray, area: np.ndarray,
                holes: np.ndarray) -> tuple:
    """Compiled twin of :meth:`TableState.legal_cue_position <billiards_env.table_state.TableState.legal_cue_position>`
    in the view's area: ``(x, y, found)``."""
    return nearest_free_xy(x, y, pos, on, radius, plain(0), area[0], area[1], area[2], area[3], 1e-6, holes)


@leaf_public
def shot_of_action(a: np.ndarray, code: int, max_ghost: float, st: np.void, pos: np.ndarray, on: np.ndarray,
                   radius: np.ndarray, cfg: np.ndarray, icfg: np.ndarray, holes: np.ndarray,
                   area: np.ndarray) -> tuple:
    """Compiled twin of :meth:`ActionType.shot <billiards_env.envs.actions.ActionType.shot>` on a pool state record:
    the shot an action (float64, clipped) means now. Returns ``(found, angle, speed, side, top, placed, x, y,
    pocket, push)`` (``pocket`` -1: none; found False: no legal point for a ball in hand)."""
    speed = power_to_speed(a[1], cfg["speed_lo"], cfg["speed_span"])
    side = 0.0
    top = 0.0
    if icfg["spin_dims"]:
        u, v = square_to_disc(a[2], a[3])
        side = cfg["max_tip"] * u
        top = cfg["max_tip"] * v
    pocket = -1
    if icfg["pocket_at"] >= 0:
        n = icfg["n_pockets"]
        pocket = min(int(0.5 * (a[icfg["pocket_at"]] + 1.0) * n), n - 1)
    push = icfg["push_at"] >= 0 and a[icfg["push_at"]] > 0.0
    t = pool_target_row(st)
    if not pool_place_area_row(st, cfg["radius"], cfg["kitchen_x"], cfg["length"], cfg["width"], area):
        angle = angle_of_action(code, a[0], pos[0, 0], pos[0, 1], t, pos, radius, max_ghost)
        return True, angle, speed, side, top, False, 0.0, 0.0, pocket, push
    k = icfg["place_at"]
    x = area[0] + 0.5 * (a[k] + 1.0) * (area[1] - area[0])
    y = area[2] + 0.5 * (a[k + 1] + 1.0) * (area[3] - area[2])
    px, py, found = legal_place(x, y, pos, on, radius, area, holes)
    angle = angle_of_action(code, a[0], px, py, t, pos, radius, max_ghost)
    return found, angle, speed, side, top, True, px, py, pocket, push


@leaf_public
def action_of_shot(code: int, max_ghost: float, angle: float, speed: float, placed: bool, px: float, py: float,
                   pocket: int, st: np.void, pos: np.ndarray, on: np.ndarray, radius: np.ndarray,
                   cfg: np.ndarray, icfg: np.ndarray, holes: np.ndarray, area: np.ndarray, out: np.ndarray) -> bool:
    """Compiled twin of :meth:`ActionType.action <billiards_env.envs.actions.ActionType.action>` on a pool state
    record, for a shot without tip offsets nor push-out (the geometric player's), as the float32 action read back as
    float64 into ``out``. False: no legal point for a ball in hand."""
    out[:] = 0.0
    t = pool_target_row(st)
    found = True
    if placed and pool_place_area_row(st, cfg["radius"], cfg["kitchen_x"], cfg["length"], cfg["width"], area):
        k = icfg["place_at"]
        out[k] = 2.0 * (px - area[0]) / max(area[1] - area[0], 1e-12) - 1.0
        out[k + 1] = 2.0 * (py - area[2]) / max(area[3] - area[2], 1e-12) - 1.0
        lx, ly, found = legal_place(px, py, pos, on, radius, area, holes)
        out[0] = aim_of_angle(code, angle, lx, ly, t, pos, radius, max_ghost)
    else:
        out[0] = aim_of_angle(code, angle, pos[0, 0], pos[0, 1], t, pos, radius, max_ghost)
    out[1] = 2.0 * (speed - cfg["speed_lo"]) / cfg["speed_span"] - 1.0
    if icfg["spin_dims"]:
        out[2], out[3] = disc_to_square(0.0 / cfg["max_tip"], 0.0 / cfg["max_tip"])
    if icfg["pocket_at"] >= 0:
        n = icfg["n_pockets"]
        k = 0 if pocket < 0 else min(max(pocket, 0), n - 1)
        out[icfg["pocket_at"]] = (2.0 * k + 1.0) / n - 1.0
    if icfg["push_at"] >= 0:
        out[icfg["push_at"]] = -1.0
    for i in range(out.shape[0]):
        out[i] = np.float64(np.float32(min(max(out[i], -1.0), 1.0)))
    return found


@njit(cache=True)
def direct_hit_xy(targets: np.ndarray, pos: np.ndarray, on: np.ndarray, cx: float, cy: float) -> float:
    """Compiled twin of :func:`billiards_env.players.shots.direct_hit` (its angle) with the cue ball at ``(cx, cy)``:
    the direction of the nearest legal ball."""
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
def candidate_speed(base: float, a: float, cfg: np.ndarray) -> float:
    """Compiled twin of ``CandidateShots._speed``: ``base`` times the speed factor to the power ``a``, within the
    type's range."""
    return min(max(base * math.exp(a * cfg["log_factor"]), cfg["cand_lo"]), cfg["cand_hi"])


@njit(cache=True, inline="always")
def candidates_shot(k, a, st, pos, on, radius, mass, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r,
                    params, holes, area, kc):
    """Compiled twin of :meth:`CandidateShots.shot <billiards_env.envs.actions.CandidateShots.shot>` for table
    ``k``'s action ``a``: the chosen slot (a pot, the kick, the break, or the direct hit when there is no pot), its
    speed scaled, the cue ball placed for it with ball in hand. Returns :func:`shot_of_action`'s tuple."""
    found, angle, speed, side, top, placed, px, py, pocket, push = shot_of_action(
        a, plain(AIM_ABSOLUTE), 0.0, st, pos, on, radius, cfg, icfg, holes, area)  # side, top, declarations, placement
    if not found:
        return found, angle, speed, side, top, placed, px, py, pocket, push
    n_slots = icfg["slots"]
    lo = cfg["cand_lo"]
    hi = cfg["cand_hi"]
    keep = max(n_slots - 1, 1)
    targets = pool_targets_row(st, on)
    in_hand = pool_place_area_row(st, cfg["radius"], cfg["kitchen_x"], cfg["length"], cfg["width"], area)
    if st["break_shot"] and not st["over"]:
        cx, cy = (px, py) if placed else (pos[0, 0], pos[0, 1])
        if in_hand:
            kp = icfg["place_at"]
            cx, cy, ok = legal_place(area[1] - abs(a[kp]) * (area[1] - area[0]),
                                      area[2] + 0.5 * (a[kp + 1] + 1.0) * (area[3] - area[2]), pos, on, radius, area,
                                      holes)
            if not ok:
                return False, angle, speed, side, top, placed, px, py, pocket, push
            placed, px, py = True, cx, cy
        angle = direct_hit_xy(targets, pos, on, cx, cy)
        sp = hi * math.exp(min(a[1], 0.0) * cfg["log_factor"])
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
                got, _, k_angle, k_speed, _ = kick_cached(k, targets, pos, on, radius, mass, lo, hi, cfg, icfg, tm_xy,
                                                    tm_r, tm_params, pocket_xy, pocket_r, params, kc)
                if got:
                    return True, k_angle, k_speed, 0.0, 0.0, placed, px, py, pocket, push
        n = rows.shape[0]
        if n == 0:
            return True, direct_hit_xy(targets, pos, on, cx, cy), candidate_speed(FALLBACK_SPEED, a[1], cfg), side, \
                top, placed, px, py, pocket, push
        row = rows[0 if kicks else min(int(abs(a[0]) * n_slots), n_slots - 1, n - 1)]
        if icfg["pocket_at"] >= 0:
            pocket = int(row[COL_POCKET])
        return True, row[COL_ANGLE], candidate_speed(row[COL_SPEED], a[1], cfg), side, top, placed, px, py, pocket, push
    rows = in_hand_slots(pos, on, radius, targets, tm_xy, tm_r, tm_params)[:keep]
    n = rows.shape[0]
    if n == 0:
        return True, direct_hit_xy(targets, pos, on, cx, cy), candidate_speed(FALLBACK_SPEED, a[1], cfg), side, top, \
            placed, px, py, pocket, push
    row = rows[0 if kicks else min(int(abs(a[0]) * n_slots), n_slots - 1, n - 1)]
    j = int(row[HAND_TARGET])
    p = int(row[HAND_POCKET])
    oa = row[HAND_OBJ_ANGLE]
    if icfg["pocket_at"] >= 0:
        pocket = p
    # CandidateShots._place_for: behind the ghost ball, at the cut of place_y.
    kp = icfg["place_at"]
    contact = radius[0] + radius[j]
    gx = pos[j, 0] - contact * math.cos(oa)
    gy = pos[j, 1] - contact * math.sin(oa)
    back = PLACE_BACK[0] + 0.5 * (a[kp] + 1.0) * (PLACE_BACK[1] - PLACE_BACK[0])
    d = oa + a[kp + 1] * PLACE_MAX_CUT
    x = gx - back * math.cos(d)
    y = gy - back * math.sin(d)
    qx, qy, ok = legal_place(min(max(x, area[0]), area[1]), min(max(y, area[2]), area[3]), pos, on, radius, area,
                              holes)
    if not ok:
        return False, angle, speed, side, top, placed, px, py, pocket, push
    # CandidateShots._placed_shot: the ghost-ball shot at that pocket from there, else a hit at the ghost ball.
    p2 = pos.copy()
    o2 = on.copy()
    p2[0, 0] = qx
    p2[0, 1] = qy
    o2[0] = True
    shots = ghost_shots(p2, o2, radius, mass, plain(0), np.array([j]), tm_xy, tm_r, tm_params, lo, hi, PLACED_MAX_CUT,
                        ARRIVE_SPEED, _SPEED_FACTORS.copy(), plain(True))  # (a writable copy, plain values: the
    # players' signature of ghost_shots, not one more compile of it)
    base_angle = math.atan2(gy - qy, gx - qx)
    base_speed = FALLBACK_SPEED
    for i in range(shots.shape[0]):
        if int(shots[i, COL_POCKET]) == p:
            base_angle = shots[i, COL_ANGLE]
            base_speed = shots[i, COL_SPEED]
            break
    return True, base_angle, candidate_speed(base_speed, a[1], cfg), side, top, True, qx, qy, pocket, push


__all__ = ["angle_of_action", "aim_of_angle", "legal_place", "shot_of_action", "action_of_shot", "direct_hit_xy",
           "candidate_speed", "candidates_shot"]
