"""Compiled games of the native vector env: 9-ball and 8-ball tables reset and stepped whole, opponents included.

A step of a game env is the agent's shot, its call, and, when the turn passes, the built-in opponent's shots until
the turn comes back or the game ends. :func:`play_tables` does all of it for every table in one call (slices of the
tables on several threads: the result does not depend on their number), and the reset
(the layout, the rack order, who breaks, the opening, the opponent's break). This module is the driver; each part it
drives is the single env's own compiled code or a compiled twin living beside what it mirrors, with the same
floating-point operations in the same order, so that table ``k`` equals a single env with the same seed and actions,
bit for bit (``tests/envs/test_vector_env.py``):

- the action types: their arithmetic is one implementation (:func:`.actions.aim_to_angle`,
  :func:`.actions.angle_to_aim`, :func:`.actions.power_to_speed`, :func:`.actions.square_to_disc`, compiled and
  called by both paths), the reading of an action and of a shot (``ActionType.shot``/``action``,
  ``CandidateShots.shot``) twinned in :mod:`._action_kernels`;
- the view (``PoolSession.view``: :func:`billiards_env.games.pool.pool_targets_row`, ``pool_target_row``,
  ``pool_place_area_row``), the rack (``rack_rows``) and the game features (``PoolSession.features`` calls the same
  compiled :func:`billiards_env.games.pool.pool_features`), beside the session in :mod:`billiards_env.games.pool`;
- the rules (:mod:`billiards_env.rules.pool_judge`: ``play``, ``initial_row``, held equal to the Python rules by
  its tests), the respots (:func:`~billiards_env.physics.layout.spot_object_row`,
  :func:`~billiards_env.physics.layout.spot_cue_row`);
- the ``candidates`` observation and the kick cache (:func:`billiards_env.envs.candidates.candidates_features_row`,
  ``kick_cached``, beside ``slot_features`` and ``kick_of``), the ``position_reward`` shaping
  (:func:`billiards_env.players.slots.next_shot_ease`), the positions observation (:func:`._kernels.observation`);
- here, as the driver's own steps: the shot path (:func:`_play`: ``shot_path.play_shot`` with
  :func:`billiards_env.shot_path.noisy_shot`, the exact kernels, :func:`billiards_env.physics.outcome.scan_shot`),
  the call applied to the table (:func:`_judge`: ``PoolSession._call``/``_apply``), the geometric opponent's turn
  (:func:`_opponent_turn`: ``GameTask._opponent_turn`` with
  :func:`billiards_env.players.geometry.geometric_choice_cached`, its action in the acting type read back), the
  reward and its shaping (:func:`_step_table`: ``GameTask._judge``/``_shaping``).

The packed configuration (``cfg``, ``icfg``) is two records declared in :mod:`._game_config`, read by field name. Random numbers come from each
table's ``numpy.random.Generator`` in the single env's order. What is not compiled (the ``features`` observation type
and reset options per table, the infos as arrays) is done in Python by :mod:`._vector_games`, from the records these
functions write (:data:`SHOT_RECORD` per shot, :data:`STEP_OUTCOME` per table).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from billiards_env.games.pool import pool_features, pool_targets_row, pool_place_area_row, rack_rows
from billiards_env.physics.exact import simulate_exact
from billiards_env.physics.exact_spin import simulate_exact_spin
from billiards_env.physics.layout import PLACE_BATCH, PLACE_TRIES, place_random_rows, spot_cue_row, spot_object_row
from billiards_env.physics.outcome import scan_shot
from billiards_env.physics.plain import plain
from billiards_env.physics.spin_collide import strike_ball
from billiards_env.players.geometry import COL_POCKET, geometric_choice_cached
from billiards_env.players.slots import next_shot_ease
from billiards_env.rules.pool_judge import (BIH_ANYWHERE, BIH_NO, CALL_ROW, GAME_STATE_ROW, copy_state, initial_row,
                                            legal_mask, needs_called_pocket, play)
from billiards_env.shot_path import noisy_shot

from ._action_kernels import action_of_shot, candidates_shot, shot_of_action
from ._game_config import AIM_CANDIDATES
from ._kernels import observation
from .candidates import candidates_features_row

#: ``icfg["opponent"]``: none (play alone) or the geometric player.
OPP_NONE, OPP_GEOMETRIC = 0, 1
#: ``icfg["first"]``, ``icfg["opening"]``, ``icfg["rack"]`` codes.
FIRST_AGENT, FIRST_OPPONENT, FIRST_RANDOM = 0, 1, 2
OPEN_BREAK, OPEN_BALL_IN_HAND, OPEN_EITHER = 0, 1, 2
#: ``icfg["rack"]``: no ordering (``RACK_NINE``, ``RACK_EIGHT``: :func:`billiards_env.games.pool.rack_rows`).
RACK_NONE = 0
#: A shot's record: who shot, the call, what the shot did, the shot as played, the state after it.
SHOT_RECORD = np.dtype([(name, np.float64) for name in (
    "shooter", "foul", "reason", "turn_over", "pocketed", "scratch", "first", "angle", "speed", "side", "top", "bih",
    "groups", "over", "n_events", "time", "status", "start_x", "start_y", "scored")])
#: A table's step outcome: terminated, truncated, error, error detail, the opponent's shots, the last shot's index.
STEP_OUTCOME = np.dtype([(name, np.int64) for name in (
    "terminated", "truncated", "error", "detail", "n_opp", "last")])
#: Errors (``STEP_OUTCOME["error"]``): none, a ball in hand with no legal point, a ball that could not be respotted, the cue
#: ball that could not be respotted, the random placement failed, the opponent took too many shots, the opponent won
#: every rack at the reset.
E_NONE, E_NO_PLACE, E_RESPOT, E_CUE_RESPOT, E_PLACEMENT, E_TURN_CAP, E_RERACKS = range(7)


# --- one shot: played, judged, applied --------------------------------------------------------------------------------

@njit(cache=True)
def _play(k, angle, speed, side, top, placed, px, py, pos, vel, ang, on, radius, mass, gens, cfg, icfg, pocket_xy,
          pocket_r, params, rec):
    """Compiled twin of :func:`billiards_env.shot_path.play_shot` on table ``k``: the cue ball placed, the noise
    drawn from the table's generator, the strike, the exact kernel, the balls stopped. Records the shot as played;
    returns the kernel's result."""
    p = pos[k]
    if placed:
        p[0, 0] = px
        p[0, 1] = py
    an = cfg["angle_noise"]
    sn = cfg["speed_noise"]
    tn = cfg["tip_noise"]
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
                                         tn > 0.0, icfg["speed_noise_abs"] != 0)
    rec["start_x"] = p[0, 0]
    rec["start_y"] = p[0, 1]
    rec["angle"] = angle
    rec["speed"] = speed
    rec["side"] = side
    rec["top"] = top
    if icfg["spin_model"]:  # the tip offsets' spin, and the squirt of the physics (as the shot path strikes)
        vx, vy, wx, wy, wz = strike_ball(angle, speed, side, top, radius[0], mass[0], cfg["squirt"],
                                         cfg["cue_end_mass"])
        vel[k, 0, 0] = vx
        vel[k, 0, 1] = vy
        ang[k, 0, 0] = wx
        ang[k, 0, 1] = wy
        ang[k, 0, 2] = wz
        res = simulate_exact_spin(p, vel[k], ang[k], radius, mass, on[k], pocket_xy, pocket_r, params,
                                  icfg["max_events"], plain(False))
        ang[k] = 0.0
    else:
        vel[k, 0, 0] = speed * math.cos(angle)
        vel[k, 0, 1] = speed * math.sin(angle)
        res = simulate_exact(p, vel[k], ang[k], radius, mass, on[k], pocket_xy, pocket_r, params,
                             icfg["max_events"], plain(False))
    vel[k] = 0.0
    rec["n_events"] = res.n_events
    rec["time"] = res.time
    rec["status"] = res.status
    return res.pocket, res.ev_int


@njit(cache=True)
def _judge(k, pocket, ev_int, shot_pocket, shot_push, st, opts, pos, on, cfg, call, after, buf, rec):
    """Compiled twin of ``GameSession.judge`` (``PoolSession._call`` and ``_apply``) of table ``k``'s shot
    (``pocket``, ``ev_int``: the kernel's): the summary, the rules' call and the next state (``st``, the table's
    game state record, updated), the respots; records the call. ``call`` and ``after``: one-record scratch arrays
    (``CALL_ROW``, ``GAME_STATE_ROW``) the rules write into. Returns an error code."""
    first, rail, order, n_order = scan_shot(ev_int, pocket, plain(0))
    nb = pocket.shape[0]
    rails = plain(0)  # (plain: the rules compiled for an int64 rails mask only)
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
    push = shot_push and st["push_available"] != 0
    called = shot_pocket if needs_called_pocket(st, opts) else -1
    c = call[0]
    nxt = after[0]
    play(st, opts, first, rails, pocketed, pockets, n_order, pocket[0] >= 0, push, called, c, nxt)
    copy_state(st, nxt)
    err = E_NONE
    kept = 0
    for i in range(n_order):
        n = pocketed[i]
        if (c["respot"] >> n) & 1:
            if not spot_object_row(pos[k], on[k], cfg["radius"], n, cfg["foot_x"], cfg["foot_y"], cfg["length"]):
                err = E_RESPOT
        else:
            kept += 1
    if not on[k, 0]:
        if not spot_cue_row(pos[k], on[k], cfg["radius"], plain(0), cfg["head_x"], cfg["head_y"], cfg["width"]):
            err = E_CUE_RESPOT
    rec["shooter"] = c["shooter"]
    rec["foul"] = c["foul"]
    rec["reason"] = c["reason"]
    rec["turn_over"] = c["turn_over"]
    rec["pocketed"] = pocketed_rows
    rec["scratch"] = pocket[0] >= 0
    rec["first"] = first
    rec["bih"] = BIH_NO if st["over"] else st["bih"]
    rec["groups"] = st["groups"]
    rec["over"] = st["over"]
    rec["scored"] = kept
    return err


@njit(cache=True)
def _opponent_turn(k, pos, vel, ang, on, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy, pocket_r, params,
                   tm_xy, tm_r, tm_params, holes, recs, call, after, buf, act, area, dec_area, wc):
    """Compiled twin of ``GameTask._opponent_turn`` (:mod:`billiards_env.envs.games`) of table ``k`` with the
    geometric opponent: its decision, its action in the acting type read back, the shot played and judged, until the
    agent's turn or the end of the game. Returns ``(shots, error)``."""
    st = gst[k]
    n = 0
    cap = icfg["turn_cap"]
    while not st["over"] and st["shooter"] != 0 and n < cap:
        targets = pool_targets_row(st, on[k])
        in_hand = pool_place_area_row(st, cfg["radius"], cfg["kitchen_x"], cfg["length"], cfg["width"], dec_area)
        if not in_hand:
            dec_area[:] = 0.0
        px, py, placed, angle, speed, kr, rows, status = geometric_choice_cached(
            pos[k], on[k], radius, mass, plain(0), targets, tm_xy, tm_r, tm_params, cfg["speed_min"], cfg["speed_max"],
            dec_area, in_hand, st["break_shot"] != 0, cfg["max_cut"], wc[0][k], wc[1][k], wc[2][k])
        if status == 1:
            return n, E_NO_PLACE
        pocket = int(rows[kr, COL_POCKET]) if kr >= 0 else -1
        code = icfg["act_aim"]
        if not action_of_shot(code, cfg["act_ghost"], angle, speed, placed, px, py, pocket, st, pos[k], on[k],
                               radius, cfg, icfg, holes, area, act):
            return n, E_NO_PLACE
        found, angle, speed, side, top, placed, px, py, pocket, push = shot_of_action(
            act, code, cfg["act_ghost"], st, pos[k], on[k], radius, cfg, icfg, holes, area)
        if not found:
            return n, E_NO_PLACE
        rec = recs[n]
        pk, ev = _play(k, angle, speed, side, top, placed, px, py, pos, vel, ang, on, radius, mass, gens, cfg, icfg,
                       pocket_xy, pocket_r, params, rec)
        err = _judge(k, pk, ev, pocket, push, st, opts, pos, on, cfg, call, after, buf, rec)
        n += 1
        if err != E_NONE:
            return n, err
    if not st["over"] and st["shooter"] != 0:
        return n, E_TURN_CAP
    return n, E_NONE


# --- a step of one table ----------------------------------------------------------------------------------------------

@njit(cache=True, inline="always")
def _step_table(k, act, kc, pos, vel, ang, on, shots, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy, pocket_r,
                params, tm_xy, tm_r, tm_params, holes, rec_agent, rec_opp, reward, tout, obs, wc):
    """One ``env.step`` of table ``k`` (see :func:`play_tables`)."""
    call = np.zeros(1, CALL_ROW)
    after = np.zeros(1, GAME_STATE_ROW)
    buf = np.zeros((2, pos.shape[1]), np.int64)
    area = np.zeros(4)
    dec_area = np.zeros(4)
    a = np.empty(icfg["n_act"])
    st = gst[k]
    tout[k]["error"] = E_NONE
    tout[k]["n_opp"] = 0
    # The agent's shot: its action read by the env's type.
    for i in range(a.shape[0]):
        a[i] = act[k, i]
    if icfg["aim"] == AIM_CANDIDATES:
        found, angle, speed, side, top, placed, px, py, pocket, push = candidates_shot(
            k, a, st, pos[k], on[k], radius, mass, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params,
            holes, area, kc)
    else:
        found, angle, speed, side, top, placed, px, py, pocket, push = shot_of_action(
            a, icfg["aim"], cfg["ghost"], st, pos[k], on[k], radius, cfg, icfg, holes, area)
    kc[k]["valid"] = 0.0  # the table moves on
    if not found:
        tout[k]["error"] = E_NO_PLACE
        return
    rec = rec_agent[k]
    pk, ev = _play(k, angle, speed, side, top, placed, px, py, pos, vel, ang, on, radius, mass, gens, cfg, icfg,
                   pocket_xy, pocket_r, params, rec)
    shots[k] += 1
    err = _judge(k, pk, ev, pocket, push, st, opts, pos, on, cfg, call, after, buf, rec)
    if err != E_NONE:
        tout[k]["error"] = err
        return
    # GameTask._judge's ease and _shaping (the agent's own shot).
    ease = 0.0
    if cfg["position_reward"] != 0.0 and not st["over"] and not rec["turn_over"] and rec["shooter"] == 0:
        targets = pool_targets_row(st, on[k])
        if st["break_shot"] == 0 and (st["bih"] == BIH_NO or st["over"]) and icfg["slots"] >= 1:
            ease = next_shot_ease(pos[k], on[k], radius, mass, targets, tm_xy, tm_r, tm_params, cfg["speed_min"],
                                  cfg["speed_max"], cfg["ease_sigma"])
    r = 0.0
    if rec["shooter"] == 0:
        if rec["foul"]:
            r -= cfg["foul_penalty"]
        elif cfg["pot_reward"] != 0.0:
            r += cfg["pot_reward"] * rec["scored"]
        if cfg["position_reward"] != 0.0:
            r += cfg["position_reward"] * ease
    practice_over = False
    if not st["over"] and st["shooter"] != 0:
        if icfg["opponent"] == OPP_NONE:
            practice_over = True
        else:
            n_opp, err = _opponent_turn(k, pos, vel, ang, on, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy,
                                        pocket_r, params, tm_xy, tm_r, tm_params, holes, rec_opp[k], call, after, buf,
                                        a, area, dec_area, wc)
            tout[k]["n_opp"] = n_opp
            if err != E_NONE:
                tout[k]["error"] = err
                return
    if st["over"]:
        r += cfg["win"] if st["winner"] == 0 else -cfg["loss"]
    terminated = st["over"] != 0 or practice_over
    reward[k] = r
    tout[k]["terminated"] = terminated
    tout[k]["truncated"] = not terminated and shots[k] >= icfg["max_shots"]
    tout[k]["last"] = tout[k]["n_opp"]  # the last shot: the agent's (0) or the opponent's n-th
    _observe(k, pos, on, radius, mass, gst, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params, kc, obs)


# --- a reset of one table --------------------------------------------------------------------------------------------

@njit(cache=True, inline="always")
def _reset_table(k, pos, vel, ang, on, shots, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy, pocket_r, params,
                 tm, holes, layout, rack_slots, full, rec_agent, rec_opp, tout, kc, obs, wc):
    """One ``env.reset()`` of table ``k`` (no options; see :func:`play_tables`; ``tm``: ``(tm_xy, tm_r,
    tm_params)``)."""
    tm_xy, tm_r, tm_params = tm
    fixed_rows, fixed_xy, rand_rows, regions, pockets = layout
    call = np.zeros(1, CALL_ROW)
    after = np.zeros(1, GAME_STATE_ROW)
    buf = np.zeros((2, pos.shape[1]), np.int64)
    area = np.zeros(4)
    dec_area = np.zeros(4)
    a = np.empty(icfg["n_act"])
    g = gens[k]
    st = gst[k]
    tout[k]["error"] = E_NONE
    tout[k]["n_opp"] = 0
    tout[k]["last"] = -1
    kc[k]["valid"] = 0.0
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
    if place_random_rows(g, pos[k], rand_rows, regions, placed, nf, pockets, cfg["pocket_margin"], cfg["min_dist"],
                         plain(PLACE_BATCH), plain(PLACE_TRIES)) >= 0:
        tout[k]["error"] = E_PLACEMENT
        return
    shots[k] = 0
    if icfg["opponent"] != OPP_NONE:
        g.integers(0, 2 ** 31)  # the opponent's reset(seed) draw (the geometric player ignores the seed)
    game = icfg["game"]
    for attempt in range(icfg["max_reracks"]):
        tout[k]["n_opp"] = 0  # the turns of this attempt only
        tout[k]["last"] = -1
        if icfg["rack"] != RACK_NONE:
            rack_rows(k, g, pos, rack_slots, icfg["rack"])
        first = icfg["first"]
        if first == FIRST_RANDOM:
            first = g.integers(0, 2)
        if first != 0 and icfg["opponent"] == OPP_NONE:
            first = 0
        initial_row(st, game, full, first)
        opening = icfg["opening"]
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
            _play(k, math.atan2(pos[k, target, 1] - cy, pos[k, target, 0] - cx), cfg["break_speed"], 0.0, 0.0,
                  plain(False), 0.0, 0.0, pos, vel, ang, on, radius, mass, gens, cfg, icfg, pocket_xy, pocket_r, params,
                  rec)
            last = icfg["opening_respot"]
            if not on[k, last]:
                if not spot_object_row(pos[k], on[k], cfg["radius"], last, cfg["foot_x"], cfg["foot_y"],
                                       cfg["length"]):
                    tout[k]["error"] = E_RESPOT
                    return
            if not on[k, 0]:
                if not spot_cue_row(pos[k], on[k], cfg["radius"], plain(0), cfg["head_x"], cfg["head_y"], cfg["width"]):
                    tout[k]["error"] = E_CUE_RESPOT
                    return
            on_mask = plain(0)
            for j in range(1, pos.shape[1]):
                if on[k, j]:
                    on_mask |= 1 << j
            initial_row(st, game, on_mask, first)  # then ball in hand anywhere, the break played
            st["bih"] = BIH_ANYWHERE
            st["break_shot"] = 0
        if first == 0 or icfg["opponent"] == OPP_NONE:
            break
        n_opp, err = _opponent_turn(k, pos, vel, ang, on, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy,
                                    pocket_r, params, tm_xy, tm_r, tm_params, holes, rec_opp[k], call, after, buf, a,
                                    area, dec_area, wc)
        tout[k]["n_opp"] = n_opp
        tout[k]["last"] = n_opp if n_opp > 0 else -1
        if err != E_NONE:
            tout[k]["error"] = err
            return
        if not st["over"]:
            break
        on[k] = True  # the opponent won from the break: rack again
        vel[k] = 0.0
        if attempt == icfg["max_reracks"] - 1:
            tout[k]["error"] = E_RERACKS
            return
    _observe(k, pos, on, radius, mass, gst, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params, kc, obs)


# --- the observation -----------------------------------------------------------------------------------------------

@njit(cache=True)
def _observe(k, pos, on, radius, mass, gst, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params, kc, obs):
    """Table ``k``'s observation into ``obs[k]`` when its type is compiled: the positions, the ``candidates`` slot
    values for that type, the game features."""
    if not (icfg["positions_obs"] or icfg["candidates_obs"]):
        return
    p = observation(pos[k], on[k], cfg["sx"], cfg["sy"])
    n = p.shape[0]
    for i in range(n):
        obs[k, i] = p[i]
    if icfg["candidates_obs"]:
        m = 12 * icfg["slots"]
        candidates_features_row(k, gst[k], pos[k], on[k], radius, mass, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy,
                             pocket_r, params, np.zeros(4), kc, obs[k, n:n + m])
        n += m
    st = gst[k]
    pool_features(st, st["shooter"], obs[k, n:])


@njit(cache=True)
def observe_tables(rows, pos, on, radius, mass, gst, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params,
                   kc, obs):
    """:func:`_observe` for tables ``rows``."""
    for q in range(rows.shape[0]):
        _observe(rows[q], pos, on, radius, mass, gst, cfg, icfg, tm_xy, tm_r, tm_params, pocket_xy, pocket_r, params,
                 kc, obs)


@njit(cache=True)
def legal_masks(gst: np.ndarray, out: np.ndarray) -> None:
    """The legal balls (a mask of their numbers) of every table's game state (``gst``: ``GAME_STATE_ROW`` records)
    into ``out``."""
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

    A step: the agent's shot (``act``: the actions, float64 clipped; ``kc``: the tables' kick caches,
    ``KICK_CACHE`` records, for the ``candidates`` types), its call and reward (``gst``: the tables' game states,
    :data:`~billiards_env.rules.pool_judge.GAME_STATE_ROW` records; ``opts``: the rules' options, a ``RULE_OPTIONS``
    record), the opponent's turn, the termination and truncation (``tout``).
    A reset: the layout (``layout``: the fixed rows and their points, the random rows and their regions, the pocket
    centres; ``rack_slots``, ``full``: the rack's slots and balls), the game's reset, the opponent's break when it
    breaks. Both record every shot (``rec_agent``, ``rec_opp``) and, for the positions and candidates observation
    types, write the observation (``obs``). ``wc``: each table's cache of its balls' pocket windows for the
    geometric opponent (``(pos (N, B, 2), windows (N, B, K, 4), have (N, B))``, see
    :func:`~billiards_env.players.geometry.fill_window`), kept from call to call: the same decisions, the windows
    of the balls that did not move since the table's last decision not worked out again."""
    tm = (tm_xy, tm_r, tm_params)
    for q in range(rows.shape[0]):
        if resets[q]:
            _reset_table(rows[q], pos, vel, ang, on, shots, radius, mass, gens, gst, opts, cfg, icfg, pocket_xy,
                         pocket_r, params, tm, holes, layout, rack_slots, full, rec_agent, rec_opp, tout, kc, obs, wc)
        else:
            _step_table(rows[q], act, kc, pos, vel, ang, on, shots, radius, mass, gens, gst, opts, cfg, icfg,
                        pocket_xy, pocket_r, params, tm_xy, tm_r, tm_params, holes, rec_agent, rec_opp, reward, tout,
                        obs, wc)


__all__ = ["play_tables", "observe_tables", "legal_masks", "SHOT_RECORD", "STEP_OUTCOME"]
