"""Many shots in one compiled call: candidate shots from one table, or one shot on each of many tables.

Two shapes, one engine:

- :func:`run_shots`: ``N`` candidate shots (angle, speed, and under the spin model tip offsets) of one ball from
  one table state, for search players (flat search, Monte-Carlo over noisy shots);
- :func:`run_tables`: ``N`` independent tables (ball arrays ``(N, B, ...)``), each simulated from its own state
  in place, for vector environments.

Each row runs the very kernel :meth:`.Simulator.run` runs (the model's exact kernel, from the table of
:mod:`.kernels`), on the same inputs, so row ``k`` is bit-identical to the
single shot. Rows are independent, so the result does not depend on how many threads run them. The results are
arrays (:class:`BatchResult`): final state, status, pockets and when, the first ball the struck ball hit, cushion
hits (and which balls reached a cushion after that first contact, as the rules of pool ask), event counts by
kind, and on request the full event log of every row (:class:`EventBatch`).

    sim = Simulator(Table(), Physics())
    res = run_shots(sim, balls, angles, speeds)     # N shots of the cue ball from ``balls``
    potted = (res.pocket[:, 1:] >= 0).sum(axis=1)   # object balls pocketed by each shot
"""
from __future__ import annotations

import math
import os
from typing import NamedTuple

import numpy as np
from numba import njit

from .balls import MAX_BALL_SPEED, Balls, check_speed, validate_balls
from .batch_rows import store_row
from .codes import EVENT_KINDS
from .errors import SceneError
from .result import EventLog
from .simulate import Simulator
from .spin_collide import MAX_TIP_OFFSET, strike_ball
from .threads import default_threads, on_slices

#: Event kinds counted per row (the columns of :attr:`BatchResult.event_counts`, see :data:`.codes.EVENT_KINDS`).
N_KINDS = len(EVENT_KINDS)
#: Below this many rows a batch runs on one thread (starting the thread pool costs more than it saves).
PARALLEL_MIN_ROWS = int(os.environ.get("BILLIARDS_PARALLEL_MIN_ROWS", "16"))


class EventBatch(NamedTuple):
    """The event logs of all rows, concatenated: row ``k``'s events are ``offsets[k]:offsets[k + 1]``."""

    offsets: np.ndarray  #: (N + 1,) int64
    time: np.ndarray  #: (M,) event times (s)
    kind: np.ndarray  #: (M,) :data:`.codes.EVENT_KINDS` code
    ball: np.ndarray  #: (M,) ball row
    other: np.ndarray  #: (M,) other ball, cushion, pocket or cluster size (see :class:`.result.EventLog`)
    speed: np.ndarray  #: (M,) impact speed

    def row(self, k: int) -> EventLog:
        """Row ``k``'s events as the :class:`~.result.EventLog` that :meth:`.Simulator.run` returns."""
        a, b = int(self.offsets[k]), int(self.offsets[k + 1])
        return EventLog(self.time[a:b], self.kind[a:b], self.ball[a:b], self.other[a:b], self.speed[a:b])


class BatchResult(NamedTuple):
    """What :func:`run_shots` and :func:`run_tables` return: one row per shot (``N`` rows, ``B`` balls)."""

    status: np.ndarray  #: (N,) int64 :data:`.codes.STATUS_NAMES` code (0 rest, 1 time cap, 2 event cap)
    time: np.ndarray  #: (N,) simulated time at the end (s)
    n_events: np.ndarray  #: (N,) int64
    pos: np.ndarray  #: (N, B, 2) final positions (a pocketed ball: where it dropped)
    vel: np.ndarray  #: (N, B, 2) final velocities (non-zero only on a capped shot)
    on_table: np.ndarray  #: (N, B) bool
    pocket: np.ndarray  #: (N, B) int64 pocket index of each ball pocketed by the shot, -1 otherwise
    pocketed_at: np.ndarray  #: (N, B) when each ball dropped (NaN if it did not)
    first_contact: np.ndarray  #: (N,) int64 row of the first ball the struck ball hit, -1 if none
    cushions: np.ndarray  #: (N, B) int64 cushion hits of each ball
    rail_after_contact: np.ndarray  #: (N, B) bool: the ball hit a cushion after the first contact
    event_counts: np.ndarray  #: (N, len(EVENT_KINDS)) int64 events of each kind
    ang: np.ndarray | None = None  #: (N, B, 3) final angular velocities (spin model; None otherwise)
    events: EventBatch | None = None  #: every row's event log (``events=True``)

    @property
    def pocketed(self) -> np.ndarray:
        """(N, B) bool: the ball was pocketed by the shot."""
        return self.pocket >= 0


# ------------------------------------------------------------------------------------------------ kernels
# The row drivers are compiled per model (:mod:`.batch_rows`); :mod:`.kernels` says which model runs which.

@njit(cache=True)
def _strike_rows(pos, vel, on, ang, base_pos, base_vel, base_on, base_ang, ball, angles, speeds, side, top,
                 radius, mass, spin, squirt, end_mass):
    """Fill every row with the base state and strike ``ball``: ``vel = speed (cos a, sin a)`` as
    :meth:`.Balls.strike` does, and under the spin model the tip offsets' angular velocity (zero without) and the
    squirt (``squirt``: its throttle)."""
    for k in range(pos.shape[0]):
        pos[k] = base_pos
        vel[k] = base_vel
        on[k] = base_on
        a = angles[k]
        s = speeds[k]
        vel[k, ball, 0] = s * math.cos(a)
        vel[k, ball, 1] = s * math.sin(a)
        if spin:
            ang[k] = base_ang
            if side[k] != 0.0 or top[k] != 0.0:
                vx, vy, wx, wy, wz = strike_ball(a, s, side[k], top[k], radius[ball], mass[ball], squirt, end_mass)
                vel[k, ball, 0] = vx
                vel[k, ball, 1] = vy
                ang[k, ball, 0] = wx
                ang[k, ball, 1] = wy
                ang[k, ball, 2] = wz
            else:
                ang[k, ball, 0] = 0.0
                ang[k, ball, 1] = 0.0
                ang[k, ball, 2] = 0.0


# ------------------------------------------------------------------------------------------------ Python API

def _check_simulator(sim: Simulator) -> bool:
    """Whether the model has spin; a clear error for a solver the batch does not run."""
    if sim.solver != "exact":
        raise SceneError(f"solver.name: batches run the exact solver, got {sim.solver!r}; make the Simulator "
                         "with solver='exact' (or loop over Simulator.run for the step solver)")
    return sim.kernels.spin


def _as_rows(name: str, values, n: int | None, dtype=float) -> np.ndarray:
    arr = np.ascontiguousarray(np.asarray(values, dtype=dtype).reshape(-1))
    if n is not None and arr.shape[0] not in (1, n):
        raise SceneError(f"{name}: {arr.shape[0]} values for {n} rows; give one per row (or one for all)")
    if n is not None and arr.shape[0] == 1 and n != 1:
        arr = np.full(n, arr[0], dtype=dtype)
    return arr


def use_parallel(n: int, threads: int | None) -> bool:
    """Whether ``n`` rows run on several threads: ``threads`` > 1 asks for it, 1 forbids it; None decides: at
    least :data:`PARALLEL_MIN_ROWS` rows, more than one core for numba (:func:`.threads.default_threads`), and a
    core left idle by the rest of the machine (1-minute load average below the core count less one half). A
    parallel batch waits for its slowest slice, so on cores busy with other work it is slower than a serial one."""
    if threads is not None:
        if threads < 1:
            raise ValueError(f"threads: must be >= 1 (or None to decide by the batch and the machine), got {threads}")
        return threads > 1
    if n < PARALLEL_MIN_ROWS:
        return False
    import numba

    if numba.get_num_threads() < 2:
        return False
    try:
        load = os.getloadavg()[0]
    except OSError:  # pragma: no cover - platforms without a load average
        return True
    return load < (os.cpu_count() or 1) - 0.5


def _empty_log(n: int, cap: int) -> tuple[np.ndarray, ...]:
    ints = np.empty((3, cap), np.int64)
    return np.zeros(n + 1, np.int64), np.empty(cap), ints[0], ints[1], ints[2], np.empty(cap)


_NO_LOG = _empty_log(0, 0)


def new_outputs(n: int, b: int) -> tuple[np.ndarray, ...]:
    """Empty result arrays for ``n`` rows of ``b`` balls (status, time, n_events, pocket, pocketed_at,
    first_contact, cushions, rail_after_contact, event_counts), to fill with :func:`simulate_into`."""
    return (np.empty(n, np.int64), np.empty(n), np.empty(n, np.int64), np.empty((n, b), np.int64), np.empty((n, b)),
            np.empty(n, np.int64), np.empty((n, b), np.int64), np.empty((n, b), np.bool_),
            np.empty((n, N_KINDS), np.int64))


def simulate_into(sim: Simulator, pos: np.ndarray, vel: np.ndarray, on: np.ndarray, radius: np.ndarray,
                  mass: np.ndarray, ang: np.ndarray, struck: np.ndarray, out: tuple[np.ndarray, ...],
                  threads: int | None = None) -> None:
    """The hot loop of :func:`run_tables` without its checks and allocations, for callers that keep their arrays
    (a vector env): simulate every row in place into ``out`` (from :func:`new_outputs`). ``radius``/``mass``:
    ``(1, B)`` or ``(N, B)``; ``ang``: ``(N, B, 3)`` (read only under the spin model); ``struck``: ``(N,)`` int64."""
    ks = sim.kernels
    consts = (sim.pocket_xy, sim.pocket_r, sim.params, int(sim.max_events))
    n = pos.shape[0]
    if not use_parallel(n, threads):
        ks.rows(pos, vel, ang, on, radius, mass, *consts, struck, out, False, _NO_LOG)
        return

    def rows(s: slice) -> None:
        """The rows of slice ``s``: per-row arrays sliced (views: the kernel writes through them), shared ones whole."""
        ks.rows(pos[s], vel[s], ang[s] if ang.shape[0] == n else ang, on[s], radius[s] if radius.shape[0] == n else radius,
                mass[s] if mass.shape[0] == n else mass, *consts, struck[s], tuple(o[s] for o in out), False, _NO_LOG)

    on_slices(rows, n, threads or default_threads())


def _simulate_rows(sim: Simulator, pos, vel, ang, on, radius, mass, struck, events: bool,
                   threads: int | None, spin: bool) -> BatchResult:
    n, b = on.shape
    out = new_outputs(n, b)
    log = None
    if events:
        common = (radius, mass, sim.pocket_xy, sim.pocket_r, sim.params, int(sim.max_events), struck, out)
        empty = _empty_log(n, 16 * n + 16)
        raw = sim.kernels.rows(pos, vel, ang, on, *common, True, empty)
        m = int(raw[0][n])
        log = EventBatch(raw[0], *(a[:m] for a in raw[1:]))
    else:
        simulate_into(sim, pos, vel, on, radius, mass, ang, struck, out, threads)
    return BatchResult(out[0], out[1], out[2], pos, vel, on, out[3], out[4], out[5], out[6], out[7], out[8],
                       ang if spin else None, log)


def run_shots(sim: Simulator, balls: Balls, angles, speeds, *, ball: str | int = 0, side=None, top=None,
              events: bool = False, validate: bool = True, threads: int | None = None) -> BatchResult:
    """Simulate ``N`` shots of ``ball`` from the table state ``balls`` (not modified): shot ``k`` strikes it at
    ``speeds[k]`` (m/s) along ``angles[k]`` (rad), with tip offsets ``side[k]``, ``top[k]`` under the spin model
    (see :meth:`.Balls.strike`). Row ``k`` equals ``sim.run(balls.strike(ball, angles[k], speeds[k]))``.

    ``events``: also return every row's event log (the rows then run on one thread). ``threads``: 1 runs the rows
    serially, more spreads slices of them over that many threads, None decides (see :func:`use_parallel`); the
    results do not depend on it. ``validate``: check ``balls`` first.
    """
    spin = _check_simulator(sim)
    if validate:
        validate_balls(balls, sim.table, allow_spin=spin)
        sim.physics.check_cushion_height(balls.radius)
    row = balls.index(ball)
    if not balls.on_table[row]:
        raise SceneError(f"ball: ball {balls.ids[row]!r} is pocketed and cannot be struck")
    ang_k = _as_rows("angles", angles, None)
    n = ang_k.shape[0]
    spd_k = _as_rows("speeds", speeds, n)
    bad = ~np.isfinite(ang_k) | ~np.isfinite(spd_k) | (spd_k < 0.0)
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise SceneError(f"shot {k}: angle {ang_k[k]} and speed {spd_k[k]} must be finite, with speed >= 0")
    fast = np.flatnonzero(spd_k > MAX_BALL_SPEED)
    if fast.size:
        check_speed(f"shot {int(fast[0])}: speed", float(spd_k[fast[0]]))
    sd = _as_rows("side", 0.0 if side is None else side, n)
    tp = _as_rows("top", 0.0 if top is None else top, n)
    if not spin and (sd.any() or tp.any()):
        raise SceneError("side, top: only the spin model has tip offsets; set physics.friction to 'spin' or leave "
                         "them 0")
    over = sd * sd + tp * tp > MAX_TIP_OFFSET ** 2
    if over.any():
        k = int(np.flatnonzero(over)[0])
        raise SceneError(f"shot {k}: the tip offset ({sd[k]}, {tp[k]}) is beyond {MAX_TIP_OFFSET} ball radii "
                         f"(side^2 + top^2 <= {MAX_TIP_OFFSET ** 2}); the cue would miscue")
    nb = len(balls)
    base_pos = np.ascontiguousarray(balls.pos, dtype=float)
    base_vel = np.ascontiguousarray(balls.vel, dtype=float)
    base_on = np.ascontiguousarray(balls.on_table, dtype=np.bool_)
    base_ang = np.ascontiguousarray(balls.ang, dtype=float)
    radius = np.ascontiguousarray(balls.radius, dtype=float).reshape(1, nb)
    mass = np.ascontiguousarray(balls.mass, dtype=float).reshape(1, nb)
    pos = np.empty((n, nb, 2))
    vel = np.empty((n, nb, 2))
    on = np.empty((n, nb), np.bool_)
    ang = np.empty((n, nb, 3)) if spin else np.empty((1, nb, 3))
    _strike_rows(pos, vel, on, ang, base_pos, base_vel, base_on, base_ang, row, ang_k, spd_k, sd, tp, radius[0],
                 mass[0], spin, float(sim.physics.squirt), float(sim.physics.cue_end_mass))
    struck = np.full(n, row, np.int64)
    return _simulate_rows(sim, pos, vel, ang, on, radius, mass, struck, events, threads, spin)


def run_tables(sim: Simulator, pos: np.ndarray, vel: np.ndarray, on_table: np.ndarray, radius, mass, ang=None, *,
               ball=0, events: bool = False, validate: bool = False, ids: tuple[str, ...] | None = None,
               threads: int | None = None) -> BatchResult:
    """Simulate ``N`` tables, each from its own state, IN PLACE: ``pos`` ``(N, B, 2)``, ``vel`` ``(N, B, 2)``,
    ``on_table`` ``(N, B)`` (and ``ang`` ``(N, B, 3)`` under the spin model) become the final states; they must
    be C-contiguous float64 / bool arrays. ``radius``, ``mass``: ``(B,)`` shared by every table or ``(N, B)``.
    Row ``k`` equals ``sim.run`` of table ``k``. ``ball``: the struck ball (an int, or one per row) whose first
    contact is reported. ``validate``: check every table first (``ids`` name the balls in messages).
    """
    spin = _check_simulator(sim)
    for name, arr, dtype, nd in (("pos", pos, np.float64, 3), ("vel", vel, np.float64, 3),
                                 ("on_table", on_table, np.bool_, 2)):
        if not isinstance(arr, np.ndarray) or arr.dtype != dtype or arr.ndim != nd or not arr.flags.c_contiguous:
            raise SceneError(f"{name}: expected a C-contiguous {np.dtype(dtype).name} array with {nd} dimensions "
                             "(it is updated in place); build it with np.ascontiguousarray(..., dtype=...)")
    n, nb = on_table.shape
    if pos.shape != (n, nb, 2) or vel.shape != (n, nb, 2):
        raise SceneError(f"pos, vel: shapes {pos.shape}, {vel.shape}; expected ({n}, {nb}, 2) for on_table of "
                         f"shape {on_table.shape}")
    rad = np.ascontiguousarray(radius, dtype=float).reshape(-1, nb)
    ms = np.ascontiguousarray(mass, dtype=float).reshape(-1, nb)
    if rad.shape[0] not in (1, n) or ms.shape[0] not in (1, n):
        raise SceneError(f"radius, mass: expected ({nb},) or ({n}, {nb}), got {np.shape(radius)}, {np.shape(mass)}")
    if spin:
        if not isinstance(ang, np.ndarray) or ang.dtype != np.float64 or ang.shape != (n, nb, 3) \
                or not ang.flags.c_contiguous:
            raise SceneError(f"ang: the spin model needs angular velocities as a C-contiguous float64 array of shape "
                             f"({n}, {nb}, 3) (updated in place)")
        ang_k = ang
    else:
        if ang is not None and np.any(ang):
            raise SceneError("ang: only the spin model has spin; set physics.friction to 'spin' or pass ang=None")
        ang_k = np.zeros((1, nb, 3))  # unused by the kernel of this model
    struck = _as_rows("ball", ball, n, dtype=np.int64)
    if ((struck < 0) | (struck >= nb)).any():
        raise SceneError(f"ball: rows must be in [0, {nb}), got {struck[(struck < 0) | (struck >= nb)][0]}")
    if validate:
        names = ids or tuple(str(i) for i in range(nb))
        for k in range(n):
            r = rad[k if rad.shape[0] > 1 else 0]
            m = ms[k if ms.shape[0] > 1 else 0]
            a = ang_k[k] if spin else np.zeros((nb, 3))
            try:
                validate_balls(Balls(names, pos[k], vel[k], r, m, on_table[k], a), sim.table, allow_spin=spin)
            except SceneError as exc:
                raise SceneError(f"table {k}: {exc}") from None
    res = _simulate_rows(sim, pos, vel, ang_k, on_table, rad, ms, struck, events, threads, spin)
    return res if spin else res._replace(ang=None)


__all__ = ["BatchResult", "EventBatch", "N_KINDS", "PARALLEL_MIN_ROWS", "run_shots", "run_tables", "new_outputs",
           "simulate_into", "store_row", "use_parallel"]
