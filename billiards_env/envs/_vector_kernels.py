"""Compiled array code of the native vector env (:mod:`.vector`): N tables reset, struck and scored per call.

Each function does for every sub-env what the single env does in Python, with the same floating-point operations
in the same order, so that sub-env ``k`` of a vector env equals a single env with the same seed bit for bit (the
test ``tests/envs/test_vector_env.py`` checks it):

- :func:`place_tables` runs :func:`billiards_env.physics.layout.place_random_rows` (the single env's placement)
  per table;
- :func:`prepare_shots` maps the actions with the single env's compiled shot arithmetic (:mod:`.actions`:
  ``aim_to_angle``, ``power_to_speed``, ``square_to_disc``; :func:`billiards_env.shot_path.noisy_shot`) and
  strikes;
- :func:`finish_shots` is the rest of :func:`~billiards_env.shot_path.play_shot` and ``PotTask.on_shot`` (re-spotting a pocketed cue ball
  with :func:`~billiards_env.physics.layout.spot_cue_row`, the single env's code), and :func:`observe_positions`
  the positions observation;
- :func:`pot_step_rows` (:func:`pot_step_rows_spin`) does a step's shots on a list of tables in one compiled call:
  strike, physics, score, observation. :func:`pot_step` runs it for the native vector env, serially or on slices of
  the tables from several threads; the single env calls it on its one table for its fast path.

The packed configuration is two numpy records read by field name (``cfg["speed_lo"]``, ``icfg["aim"]``; numba
compiles a record's field to a load at its offset): :data:`POT_FLOATS` and :data:`POT_INTS`, one-record arrays made by
:func:`pack_config`. Each table's results are one record of :data:`POT_SHOT` (``fout[k]``: the reward, the shot as
played) and one of :data:`POT_OUTCOME` (``iout[k]``: the flags, the pocketed rows), in the record arrays of
:func:`new_step_outputs`. Random numbers come from each sub-env's own ``numpy.random.Generator`` (numba draws from
the same bit generator state, with numpy's algorithms), in the single env's order.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np
from numba import njit

from billiards_env.physics.batch import store_row
from billiards_env.physics.exact import exact_scratch, simulate_exact_in
from billiards_env.physics.exact_spin import simulate_exact_spin
from billiards_env.physics.kernel_logs import leaf
from billiards_env.physics.layout import place_random_rows, spot_cue_row
from billiards_env.physics.plain import plain
from billiards_env.physics.spin_collide import strike_ball
from billiards_env.physics.threads import on_slices

from ._game_config import put_shot_fields
from ._kernels import write_observation
from billiards_env.shot_path import noisy_shot

from .actions import AIM_ABSOLUTE, AIM_GHOST, AIM_RELATIVE, aim_to_angle, power_to_speed, square_to_disc
from .tasks import pot_score

#: ``place_tables`` status: every table placed.
PLACED = -1


@njit(cache=True)
def place_tables(rows, gens, pos, vel, ang, on, fixed_rows, fixed_xy, rand_rows, regions, pockets, pocket_margin,
                 min_dist, batch, tries):
    """Reset tables ``rows``: balls at rest on the table, the fixed rows at ``fixed_xy``, each random row drawn
    by :func:`~billiards_env.physics.layout.place_random_rows` (the single env's placement). Returns
    :data:`PLACED`, or the first table that could not be placed."""
    nf = fixed_rows.shape[0]
    nr = rand_rows.shape[0]
    placed = np.empty((nf + nr, 2))
    for q in range(rows.shape[0]):
        k = rows[q]
        vel[k] = 0.0
        ang[k] = 0.0
        on[k] = True
        for f in range(nf):
            pos[k, fixed_rows[f], 0] = fixed_xy[f, 0]
            pos[k, fixed_rows[f], 1] = fixed_xy[f, 1]
            placed[f, 0] = fixed_xy[f, 0]
            placed[f, 1] = fixed_xy[f, 1]
        if place_random_rows(gens[k], pos[k], rand_rows, regions, placed, nf, pockets, pocket_margin, min_dist,
                             batch, tries) >= 0:
            return k
    return PLACED


@njit(cache=True)
def _target(on):
    """Row of the lowest-numbered object ball on the table (the pot task's target), -1 if none."""
    for i in range(1, on.shape[0]):
        if on[i]:
            return i
    return -1


#: The floats of a pot env's shot (``cfg``, a record made by :func:`pack_config`): the action type's speed range and
#: tip scale, the noise, the ghost-ball aim's largest angle, the ball radius, the head spot and the table's width (the
#: cue ball's re-spot), the rewards and penalties, the observation's scales, the ball mass and the cue's squirt (the
#: spin model's strike).
POT_FLOATS = np.dtype([(name, np.float64) for name in (
    "speed_lo", "speed_span", "max_tip", "angle_noise", "speed_noise", "tip_noise", "ghost", "radius", "head_x",
    "head_y", "width", "pot_reward", "scratch_penalty", "miss_penalty", "step_penalty", "sx", "sy", "ball_mass",
    "squirt", "cue_end_mass")])
#: The ints of a pot env's shot (``icfg``): the aim type (``AIM_*``), spin in the action, the spin model, one shot per
#: episode, the shot cap, the positions observation made by the kernels, the absolute speed noise (flags are 0/1).
POT_INTS = np.dtype([(name, np.int64) for name in (
    "aim", "spin_action", "spin_model", "single_shot", "max_shots", "positions_obs", "speed_noise_abs")])
#: A table's shot as played (``fout``, one record per table): the reward, the angle, speed and tip offsets after the
#: noise, and the cue ball's start.
POT_SHOT = np.dtype([(name, np.float64) for name in (
    "reward", "angle", "speed", "side", "top", "start_x", "start_y")])
#: A table's step outcome (``iout``, one record per table): terminated, truncated, success, scratch (0/1) and the
#: bit mask of the rows pocketed.
POT_OUTCOME = np.dtype([(name, np.int64) for name in (
    "terminated", "truncated", "success", "scratch", "pocketed")])


def pack_config(c: Any, a: Any, observation_type: Any) -> tuple[np.ndarray, np.ndarray]:
    """The constants a pot env's shot needs, as two one-record arrays ``(cfgs, icfgs)`` (:data:`POT_FLOATS`,
    :data:`POT_INTS`), from its config ``c``, its action type ``a`` and its observation type. Arrays, not record
    scalars: numba types an array argument from a cache, a record scalar anew at every call (about 1 us each, a
    tenth of the single env's step)."""
    from billiards_env.physics.layout import head_spot

    table = c.table
    hx, hy = head_spot(table)
    cfgs = np.zeros(1, POT_FLOATS)
    cfg = cfgs[0]  # the record (a view of the array): the floats by name
    put_shot_fields(cfg, a, c)
    cfg["ghost"] = float(getattr(a, "max_angle", 0.0))
    cfg["radius"] = c.ball_radius
    cfg["head_x"] = hx
    cfg["head_y"] = hy
    cfg["width"] = table.width
    cfg["pot_reward"] = c.pot_reward
    cfg["scratch_penalty"] = c.scratch_penalty
    cfg["miss_penalty"] = c.miss_penalty
    cfg["step_penalty"] = c.step_penalty
    cfg["sx"] = 1.0 / table.length
    cfg["sy"] = 1.0 / table.width
    cfg["ball_mass"] = c.ball_mass
    cfg["squirt"] = c.physics.squirt
    cfg["cue_end_mass"] = c.physics.cue_end_mass
    icfgs = np.zeros(1, POT_INTS)
    icfg = icfgs[0]
    icfg["aim"] = {"absolute": AIM_ABSOLUTE, "relative": AIM_RELATIVE, "ghost": AIM_GHOST}[a.name]
    icfg["spin_action"] = int(a.spin)
    icfg["spin_model"] = int(c.physics.has_spin)
    icfg["single_shot"] = int(c.single_shot)
    icfg["max_shots"] = int(c.max_shots)
    icfg["positions_obs"] = int(observation_type.name == "positions" and observation_type.n_game == 0)
    icfg["speed_noise_abs"] = int(c.speed_noise_mode == "absolute")
    return cfgs, icfgs


def new_step_outputs(n: int) -> tuple[np.ndarray, np.ndarray]:
    """The per-table outputs of a step of ``n`` tables, zeroed: ``(fout, iout)``, record arrays of
    :data:`POT_SHOT` and :data:`POT_OUTCOME`."""
    return np.zeros(n, POT_SHOT), np.zeros(n, POT_OUTCOME)


@njit(cache=True)
def draw_noise(active, gens, cfgs, noise):
    """The shot noise of every active table from its generator, in the single env's order: the angle's, the
    speed's, then the two tip offsets' (each only when that noise is on): ``noise[k] = (da, ds, dside, dtop)``."""
    cfg = cfgs[0]
    an = cfg["angle_noise"]
    sn = cfg["speed_noise"]
    tn = cfg["tip_noise"]
    for k in range(noise.shape[0]):
        if not active[k]:
            continue
        g = gens[k]
        if an > 0.0:
            noise[k, 0] = g.normal(0.0, an)
        if sn > 0.0:
            noise[k, 1] = g.normal(0.0, sn)
        if tn > 0.0:
            noise[k, 2] = g.normal(0.0, tn)
            noise[k, 3] = g.normal(0.0, tn)


@leaf
def _prepare_row(k, act, pos, on, radius, cfg, icfg, noise, vel, ang, fout):
    """Table ``k``'s action (clipped float64) as the cue ball's velocity (and spin), as the single env does: the
    aim type's angle, the power's speed, the tip offsets, then the shot noise (``noise[k]``, drawn beforehand:
    :func:`draw_noise`). Writes the shot as played and the cue ball's start into ``fout[k]`` (:data:`POT_SHOT`)."""
    a0 = act[k, 0]
    speed = power_to_speed(act[k, 1], cfg["speed_lo"], cfg["speed_span"])
    side = 0.0
    top = 0.0
    if icfg["spin_action"]:
        u, v = square_to_disc(act[k, 2], act[k, 3])
        side = cfg["max_tip"] * u
        top = cfg["max_tip"] * v
    p = pos[k]
    aim = icfg["aim"]
    t = _target(on[k]) if aim != AIM_ABSOLUTE else -1
    if t >= 0:
        angle = aim_to_angle(aim, a0, p[0, 0], p[0, 1], p[t, 0], p[t, 1], plain(True), radius[0] + radius[t],
                             cfg["ghost"])
    else:
        angle = aim_to_angle(aim, a0, p[0, 0], p[0, 1], 0.0, 0.0, plain(False), 0.0, cfg["ghost"])
    angle, speed, side, top = noisy_shot(angle, speed, side, top, noise[k, 0], noise[k, 1], noise[k, 2],
                                         noise[k, 3], cfg["angle_noise"] > 0.0, cfg["speed_noise"] > 0.0,
                                         cfg["tip_noise"] > 0.0, icfg["speed_noise_abs"] != 0)
    f = fout[k]  # the table's record (a view)
    f["start_x"] = p[0, 0]
    f["start_y"] = p[0, 1]
    vel[k, 0, 0] = speed * math.cos(angle)
    vel[k, 0, 1] = speed * math.sin(angle)
    if icfg["spin_model"]:  # the tip offsets' spin, and the squirt of the physics
        vx, vy, wx, wy, wz = strike_ball(angle, speed, side, top, radius[0], cfg["ball_mass"], cfg["squirt"],
                                         cfg["cue_end_mass"])
        vel[k, 0, 0] = vx
        vel[k, 0, 1] = vy
        ang[k, 0, 0] = wx
        ang[k, 0, 1] = wy
        ang[k, 0, 2] = wz
    f["angle"] = angle
    f["speed"] = speed
    f["side"] = side
    f["top"] = top


@njit(cache=True)
def prepare_shots(act, active, pos, on, radius, cfgs, icfgs, noise, vel, ang, fout):
    """:func:`_prepare_row` for every active table (``cfgs``, ``icfgs``: :func:`pack_config`'s arrays)."""
    cfg, icfg = cfgs[0], icfgs[0]
    for k in range(act.shape[0]):
        if active[k]:
            _prepare_row(k, act, pos, on, radius, cfg, icfg, noise, vel, ang, fout)


@leaf
def _finish_row(k, pocket, first, pos, on, vel, ang, shots, cfg, icfg, fout, iout):
    """Score table ``k``'s shot as ``PotTask.on_shot``: balls at rest, a pocketed cue ball re-spotted, reward,
    termination, truncation, success, scratch and the bit mask of the rows pocketed (``fout[k]["reward"]``, the
    record ``iout[k]``: :data:`POT_OUTCOME`).
    Returns False if the cue ball could not be re-spotted."""
    vel[k] = 0.0
    ang[k] = 0.0
    shots[k] += 1
    n_pocketed = 0
    mask = 0
    for i in range(pos.shape[1]):
        if pocket[k, i] >= 0:
            n_pocketed += 1
            mask |= 1 << i
    sc = pocket[k, 0] >= 0
    ok = True
    if sc:
        ok = spot_cue_row(pos[k], on[k], cfg["radius"], plain(0), cfg["head_x"], cfg["head_y"], cfg["width"])
    n_potted = n_pocketed - (1 if sc else 0)
    cleared = True
    for i in range(1, pos.shape[1]):
        if on[k, i]:
            cleared = False
            break
    r, term, trunc, success = pot_score(n_potted, sc, first[k] < 0, cleared, shots[k], cfg["pot_reward"],
                                        cfg["step_penalty"], cfg["scratch_penalty"], cfg["miss_penalty"],
                                        icfg["single_shot"] != 0, icfg["max_shots"])
    fout[k]["reward"] = r
    o = iout[k]  # the table's record (a view)
    o["terminated"] = term
    o["truncated"] = trunc
    o["success"] = success
    o["scratch"] = sc
    o["pocketed"] = mask
    return ok


@njit(cache=True)
def finish_shots(active, pocket, first, pos, on, vel, ang, shots, cfgs, icfgs, fout, iout):
    """:func:`_finish_row` for every active table; False if a cue ball could not be re-spotted."""
    cfg, icfg = cfgs[0], icfgs[0]
    ok = True
    for k in range(pos.shape[0]):
        if active[k]:
            ok = _finish_row(k, pocket, first, pos, on, vel, ang, shots, cfg, icfg, fout, iout) and ok
    return ok


@njit(cache=True)
def observe_positions(rows, pos, on, sx, sy, out):
    """The positions observation of tables ``rows`` into ``out[rows]`` (``envs._kernels.observation``)."""
    for q in range(rows.shape[0]):
        k = rows[q]
        write_observation(pos[k], on[k], sx, sy, out[k])


@leaf
def _after_shot(k, res, pos, vel, ang, on, shots, cfg, icfg, out, fout, iout, obs):
    """Table ``k`` after its shot: the kernel result into ``out`` (as the batch stores it), the score
    (:func:`_finish_row`) and the positions observation (when that is the observation type)."""
    store_row(k, res, plain(0), out)
    ok = _finish_row(k, out[3], out[5], pos, on, vel, ang, shots, cfg, icfg, fout, iout)
    if icfg["positions_obs"]:
        write_observation(pos[k], on[k], cfg["sx"], cfg["sy"], obs[k])
    return ok


@njit(cache=True, nogil=True)
def pot_step_rows(rows, act, active, pos, vel, ang, on, shots, radius, mass, pocket_xy, pocket_r, params, max_events,
                  cfgs, icfgs, noise, out, fout, iout, obs):
    """One shot on each active table of ``rows`` (int64), one after the other, without the GIL (``noise`` from
    :func:`draw_noise`): :func:`_prepare_row`, the exact kernel (``out``: the batch's result arrays, see
    :func:`billiards_env.physics.batch.new_outputs`) and :func:`_after_shot`. Returns False if a cue ball could not
    be re-spotted. :func:`pot_step` calls it on the active tables, or on slices of them from several threads."""
    cfg, icfg = cfgs[0], icfgs[0]
    ok = True
    scratch = exact_scratch(pos.shape[1])  # the kernel's arrays, made once for the tables of this call
    for q in range(rows.shape[0]):
        k = rows[q]
        if active[k]:
            _prepare_row(k, act, pos, on, radius[0], cfg, icfg, noise, vel, ang, fout)
            res = simulate_exact_in(scratch, pos[k], vel[k], ang[k], radius[0], mass[0], on[k], pocket_xy, pocket_r,
                                    params, max_events, plain(False))
            ok = _after_shot(k, res, pos, vel, ang, on, shots, cfg, icfg, out, fout, iout, obs) and ok
    return ok


@njit(cache=True, nogil=True)
def pot_step_rows_spin(rows, act, active, pos, vel, ang, on, shots, radius, mass, pocket_xy, pocket_r, params,
                       max_events, cfgs, icfgs, noise, out, fout, iout, obs):
    """:func:`pot_step_rows` for the spin model."""
    cfg, icfg = cfgs[0], icfgs[0]
    ok = True
    for q in range(rows.shape[0]):
        k = rows[q]
        if active[k]:
            _prepare_row(k, act, pos, on, radius[0], cfg, icfg, noise, vel, ang, fout)
            res = simulate_exact_spin(pos[k], vel[k], ang[k], radius[0], mass[0], on[k], pocket_xy, pocket_r, params,
                                      max_events, plain(False))
            ok = _after_shot(k, res, pos, vel, ang, on, shots, cfg, icfg, out, fout, iout, obs) and ok
    return ok


def pot_step(spin: bool, threads: int, act: np.ndarray, active: np.ndarray, *args: Any) -> bool:
    """One shot on every active table: :func:`pot_step_rows` (:func:`pot_step_rows_spin` when ``spin``) on the
    active tables, in one call or, with ``threads`` > 1, in that many contiguous slices on Python threads (the
    kernel releases the GIL; threads rather than numba's ``prange``, as the games' vector kernel runs). ``args``:
    :func:`pot_step_rows`' arguments after ``active``. Every table is struck, simulated and scored by the same code
    whatever ``threads``, so the results do not depend on it. Returns False if a cue ball could not be re-spotted."""
    kernel = pot_step_rows_spin if spin else pot_step_rows
    rows = np.flatnonzero(active).astype(np.int64)
    return all(on_slices(lambda s: bool(kernel(rows[s], act, active, *args)), rows.size, threads))


__all__ = ["AIM_ABSOLUTE", "AIM_RELATIVE", "AIM_GHOST", "PLACED", "POT_FLOATS", "POT_INTS", "POT_SHOT", "POT_OUTCOME",
           "pack_config", "new_step_outputs", "place_tables", "prepare_shots",
           "finish_shots", "observe_positions", "pot_step", "draw_noise",
           "pot_step_rows", "pot_step_rows_spin"]
