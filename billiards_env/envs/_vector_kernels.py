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
- :func:`pot_step` (:func:`pot_step_spin`) does all of a step's shots in one serial call: strike, physics, score,
  observation. The native vector env uses it when it runs serially, and the single env for its fast path;
  :func:`pot_step_parallel` does the same on several threads (:func:`pot_step_rows` on slices of the tables).

Random numbers come from each sub-env's own ``numpy.random.Generator`` (numba draws from the same bit generator
state, with numpy's algorithms), in the single env's order.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np
from numba import njit

from billiards_env.physics.batch import store_row
from billiards_env.physics.exact import simulate_exact
from billiards_env.physics.exact_spin import simulate_exact_spin
from billiards_env.physics.layout import place_random_rows, spot_cue_row
from billiards_env.physics.plain import plain
from billiards_env.physics.spin_collide import strike_ball

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


# Constants of a pot env, packed in one float array (``cfg``) and one int array (``icfg``) by :func:`pack_config`.
C_SPEED_LO, C_SPEED_SPAN, C_MAX_TIP, C_ANGLE_NOISE, C_SPEED_NOISE, C_TIP_NOISE, C_MAX_GHOST, C_BALL_RADIUS, \
    C_HEAD_X, C_HEAD_Y, C_WIDTH, C_POT_REWARD, C_SCRATCH_PENALTY, C_MISS_PENALTY, C_STEP_PENALTY, C_SX, C_SY, \
    C_BALL_MASS, C_SQUIRT, C_CUE_END_MASS = range(20)
I_AIM, I_SPIN_ACTION, I_SPIN_MODEL, I_SINGLE_SHOT, I_MAX_SHOTS, I_POSITIONS_OBS, I_SPEED_NOISE_ABS = range(7)
# Columns of the per-table float outputs (``fout``) and int outputs (``iout``).
F_REWARD, F_ANGLE, F_SPEED, F_SIDE, F_TOP, F_START_X, F_START_Y = range(7)
O_TERMINATED, O_TRUNCATED, O_SUCCESS, O_SCRATCH, O_POCKETED = range(5)


def pack_config(c: Any, a: Any, observation_type: Any) -> tuple[np.ndarray, np.ndarray]:
    """The constants a pot env's shot needs, as ``(cfg float64, icfg int64)`` (see the ``C_*`` / ``I_*`` indices),
    from its config ``c``, its action type ``a`` and its observation type."""
    from billiards_env.physics.layout import head_spot

    table = c.table
    hx, hy = head_spot(table)
    cfg = np.zeros(20)
    cfg[C_SPEED_LO] = a.speed_lo
    cfg[C_SPEED_SPAN] = a.speed_span
    cfg[C_MAX_TIP] = a.max_tip
    cfg[C_ANGLE_NOISE] = c.angle_noise
    cfg[C_SPEED_NOISE] = c.speed_noise
    cfg[C_TIP_NOISE] = c.tip_noise
    cfg[C_MAX_GHOST] = float(getattr(a, "max_angle", 0.0))
    cfg[C_BALL_RADIUS] = c.ball_radius
    cfg[C_HEAD_X] = hx
    cfg[C_HEAD_Y] = hy
    cfg[C_WIDTH] = table.width
    cfg[C_POT_REWARD] = c.pot_reward
    cfg[C_SCRATCH_PENALTY] = c.scratch_penalty
    cfg[C_MISS_PENALTY] = c.miss_penalty
    cfg[C_STEP_PENALTY] = c.step_penalty
    cfg[C_SX] = 1.0 / table.length
    cfg[C_SY] = 1.0 / table.width
    cfg[C_BALL_MASS] = c.ball_mass
    cfg[C_SQUIRT] = c.physics.squirt
    cfg[C_CUE_END_MASS] = c.physics.cue_end_mass
    icfg = np.zeros(7, np.int64)
    icfg[I_AIM] = {"absolute": AIM_ABSOLUTE, "relative": AIM_RELATIVE, "ghost": AIM_GHOST}[a.name]
    icfg[I_SPIN_ACTION] = int(a.spin)
    icfg[I_SPIN_MODEL] = int(c.physics.has_spin)
    icfg[I_SINGLE_SHOT] = int(c.single_shot)
    icfg[I_MAX_SHOTS] = int(c.max_shots)
    icfg[I_POSITIONS_OBS] = int(observation_type.name == "positions" and observation_type.n_game == 0)
    icfg[I_SPEED_NOISE_ABS] = int(c.speed_noise_mode == "absolute")
    return cfg, icfg


@njit(cache=True)
def draw_noise(active, gens, cfg, noise):
    """The shot noise of every active table from its generator, in the single env's order: the angle's, the
    speed's, then the two tip offsets' (each only when that noise is on): ``noise[k] = (da, ds, dside, dtop)``."""
    an = cfg[C_ANGLE_NOISE]
    sn = cfg[C_SPEED_NOISE]
    tn = cfg[C_TIP_NOISE]
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


@njit(cache=True)
def _prepare_row(k, act, pos, on, radius, cfg, icfg, noise, vel, ang, fout):
    """Table ``k``'s action (clipped float64) as the cue ball's velocity (and spin), as the single env does: the
    aim type's angle, the power's speed, the tip offsets, then the shot noise (``noise[k]``, drawn beforehand:
    :func:`draw_noise`). Writes the shot as played and the cue ball's start into ``fout[k]``."""
    a0 = act[k, 0]
    speed = power_to_speed(act[k, 1], cfg[C_SPEED_LO], cfg[C_SPEED_SPAN])
    side = 0.0
    top = 0.0
    if icfg[I_SPIN_ACTION]:
        u, v = square_to_disc(act[k, 2], act[k, 3])
        side = cfg[C_MAX_TIP] * u
        top = cfg[C_MAX_TIP] * v
    p = pos[k]
    aim = icfg[I_AIM]
    t = _target(on[k]) if aim != AIM_ABSOLUTE else -1
    if t >= 0:
        angle = aim_to_angle(aim, a0, p[0, 0], p[0, 1], p[t, 0], p[t, 1], plain(True), radius[0] + radius[t],
                             cfg[C_MAX_GHOST])
    else:
        angle = aim_to_angle(aim, a0, p[0, 0], p[0, 1], 0.0, 0.0, plain(False), 0.0, cfg[C_MAX_GHOST])
    angle, speed, side, top = noisy_shot(angle, speed, side, top, noise[k, 0], noise[k, 1], noise[k, 2],
                                         noise[k, 3], cfg[C_ANGLE_NOISE] > 0.0, cfg[C_SPEED_NOISE] > 0.0,
                                         cfg[C_TIP_NOISE] > 0.0, icfg[I_SPEED_NOISE_ABS] != 0)
    fout[k, F_START_X] = p[0, 0]
    fout[k, F_START_Y] = p[0, 1]
    vel[k, 0, 0] = speed * math.cos(angle)
    vel[k, 0, 1] = speed * math.sin(angle)
    if icfg[I_SPIN_MODEL]:  # the tip offsets' spin, and the squirt of the physics
        vx, vy, wx, wy, wz = strike_ball(angle, speed, side, top, radius[0], cfg[C_BALL_MASS], cfg[C_SQUIRT],
                                         cfg[C_CUE_END_MASS])
        vel[k, 0, 0] = vx
        vel[k, 0, 1] = vy
        ang[k, 0, 0] = wx
        ang[k, 0, 1] = wy
        ang[k, 0, 2] = wz
    fout[k, F_ANGLE] = angle
    fout[k, F_SPEED] = speed
    fout[k, F_SIDE] = side
    fout[k, F_TOP] = top


@njit(cache=True)
def prepare_shots(act, active, pos, on, radius, cfg, icfg, noise, vel, ang, fout):
    """:func:`_prepare_row` for every active table."""
    for k in range(act.shape[0]):
        if active[k]:
            _prepare_row(k, act, pos, on, radius, cfg, icfg, noise, vel, ang, fout)


@njit(cache=True)
def _finish_row(k, pocket, first, pos, on, vel, ang, shots, cfg, icfg, fout, iout):
    """Score table ``k``'s shot as ``PotTask.on_shot``: balls at rest, a pocketed cue ball re-spotted, reward,
    termination, truncation, success, scratch and the bit mask of the rows pocketed (``iout[k]``, ``fout[k]``).
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
        ok = spot_cue_row(pos[k], on[k], cfg[C_BALL_RADIUS], plain(0), cfg[C_HEAD_X], cfg[C_HEAD_Y], cfg[C_WIDTH])
    n_potted = n_pocketed - (1 if sc else 0)
    cleared = True
    for i in range(1, pos.shape[1]):
        if on[k, i]:
            cleared = False
            break
    r, term, trunc, success = pot_score(n_potted, sc, first[k] < 0, cleared, shots[k], cfg[C_POT_REWARD],
                                        cfg[C_STEP_PENALTY], cfg[C_SCRATCH_PENALTY], cfg[C_MISS_PENALTY],
                                        icfg[I_SINGLE_SHOT] != 0, icfg[I_MAX_SHOTS])
    fout[k, F_REWARD] = r
    iout[k, O_TERMINATED] = term
    iout[k, O_TRUNCATED] = trunc
    iout[k, O_SUCCESS] = success
    iout[k, O_SCRATCH] = sc
    iout[k, O_POCKETED] = mask
    return ok


@njit(cache=True)
def finish_shots(active, pocket, first, pos, on, vel, ang, shots, cfg, icfg, fout, iout):
    """:func:`_finish_row` for every active table; False if a cue ball could not be re-spotted."""
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


@njit(cache=True)
def _after_shot(k, res, pos, vel, ang, on, shots, cfg, icfg, out, fout, iout, obs):
    """Table ``k`` after its shot: the kernel result into ``out`` (as the batch stores it), the score
    (:func:`_finish_row`) and the positions observation (when that is the observation type)."""
    store_row(k, res, plain(0), out)
    ok = _finish_row(k, out[3], out[5], pos, on, vel, ang, shots, cfg, icfg, fout, iout)
    if icfg[I_POSITIONS_OBS]:
        write_observation(pos[k], on[k], cfg[C_SX], cfg[C_SY], obs[k])
    return ok


@njit(cache=True)
def pot_step(act, active, pos, vel, ang, on, shots, radius, mass, pocket_xy, pocket_r, params, max_events, cfg,
             icfg, noise, out, fout, iout, obs):
    """One shot on every active table in one call, serially (``noise`` from :func:`draw_noise`):
    :func:`_prepare_row`, the exact kernel (``out``: the
    batch's result arrays, see :func:`billiards_env.physics.batch.new_outputs`) and :func:`_after_shot`. Returns
    False if a cue ball could not be re-spotted."""
    ok = True
    for k in range(pos.shape[0]):
        if active[k]:
            _prepare_row(k, act, pos, on, radius[0], cfg, icfg, noise, vel, ang, fout)
            res = simulate_exact(pos[k], vel[k], ang[k], radius[0], mass[0], on[k], pocket_xy, pocket_r, params,
                                 max_events, plain(False))
            ok = _after_shot(k, res, pos, vel, ang, on, shots, cfg, icfg, out, fout, iout, obs) and ok
    return ok


@njit(cache=True)
def pot_step_spin(act, active, pos, vel, ang, on, shots, radius, mass, pocket_xy, pocket_r, params, max_events, cfg,
                  icfg, noise, out, fout, iout, obs):
    """:func:`pot_step` for the spin model (its own kernel: each model compiles only when used)."""
    ok = True
    for k in range(pos.shape[0]):
        if active[k]:
            _prepare_row(k, act, pos, on, radius[0], cfg, icfg, noise, vel, ang, fout)
            res = simulate_exact_spin(pos[k], vel[k], ang[k], radius[0], mass[0], on[k], pocket_xy, pocket_r, params,
                                      max_events, plain(False))
            ok = _after_shot(k, res, pos, vel, ang, on, shots, cfg, icfg, out, fout, iout, obs) and ok
    return ok


@njit(cache=True, nogil=True)
def pot_step_rows(rows, act, active, pos, vel, ang, on, shots, radius, mass, pocket_xy, pocket_r, params, max_events,
                  cfg, icfg, noise, out, fout, iout, obs):
    """:func:`pot_step` on tables ``rows`` only (int64), without the GIL: :func:`pot_step_parallel` runs slices of
    the tables on several Python threads at once (a table's result does not depend on the slice it is in)."""
    ok = True
    for q in range(rows.shape[0]):
        k = rows[q]
        if active[k]:
            _prepare_row(k, act, pos, on, radius[0], cfg, icfg, noise, vel, ang, fout)
            res = simulate_exact(pos[k], vel[k], ang[k], radius[0], mass[0], on[k], pocket_xy, pocket_r, params,
                                 max_events, plain(False))
            ok = _after_shot(k, res, pos, vel, ang, on, shots, cfg, icfg, out, fout, iout, obs) and ok
    return ok


@njit(cache=True, nogil=True)
def pot_step_rows_spin(rows, act, active, pos, vel, ang, on, shots, radius, mass, pocket_xy, pocket_r, params,
                       max_events, cfg, icfg, noise, out, fout, iout, obs):
    """:func:`pot_step_rows` for the spin model."""
    ok = True
    for q in range(rows.shape[0]):
        k = rows[q]
        if active[k]:
            _prepare_row(k, act, pos, on, radius[0], cfg, icfg, noise, vel, ang, fout)
            res = simulate_exact_spin(pos[k], vel[k], ang[k], radius[0], mass[0], on[k], pocket_xy, pocket_r, params,
                                      max_events, plain(False))
            ok = _after_shot(k, res, pos, vel, ang, on, shots, cfg, icfg, out, fout, iout, obs) and ok
    return ok


def pot_step_parallel(spin: bool, threads: int, act: np.ndarray, active: np.ndarray, *args: Any) -> bool:
    """:func:`pot_step` spread over ``threads`` Python threads: the active tables in ``threads`` contiguous slices,
    one compiled call (:func:`pot_step_rows`, which releases the GIL) per slice, as the games' vector kernel runs
    (threads rather than numba's ``prange``). ``args``: :func:`pot_step`'s arguments after ``active``. Every table
    is struck, simulated and scored by the same code as serially, so the results do not depend on ``threads``."""
    from ._vector_games import _pool

    kernel = pot_step_rows_spin if spin else pot_step_rows
    rows = np.flatnonzero(active).astype(np.int64)
    threads = max(1, min(threads, rows.size))
    if threads == 1:
        return bool(kernel(rows, act, active, *args))
    slices = np.array_split(rows, threads)
    return all(list(_pool(threads).map(lambda r: bool(kernel(r, act, active, *args)), slices)))


__all__ = ["AIM_ABSOLUTE", "AIM_RELATIVE", "AIM_GHOST", "PLACED", "pack_config", "place_tables", "prepare_shots",
           "finish_shots", "observe_positions", "pot_step", "draw_noise",
           "pot_step_spin", "pot_step_rows", "pot_step_rows_spin", "pot_step_parallel"]
