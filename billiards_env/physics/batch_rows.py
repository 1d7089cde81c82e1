"""The batch API's compiled row drivers (:mod:`.batch`): every row through one model's exact kernel (with the event
logs on request), and each row's summary (:func:`store_row`).

One driver per model, so that a process compiles only the kernels of the models it runs; :data:`.kernels.KERNELS`
says which model uses which. The drivers release the GIL: :func:`.batch.simulate_into` spreads a batch over threads
by calling them on slices of the rows (:mod:`.threads`). ``out`` is the tuple of result arrays filled row by row (see
:func:`store_row`); ``radius`` and ``mass`` have one row per table or one row for all; ``ang`` has one row per table
under the spin model, one (unused) row for all otherwise.

The drivers pass ``record`` as the constant ``False`` (a literal to numba), not :func:`.plain.plain`: the kernels
compiled for it, with the state log's branches gone, run a batch about 8% faster (measured 2026-12-05), which is
worth one more compile of each kernel in the processes that run batches.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from .codes import EV_COLLISION, EV_CUSHION
from .exact import exact_scratch, simulate_exact_in
from .exact_spin import simulate_exact_spin
from .kernel_logs import leaf_public


@leaf_public
def store_row(k, res, struck, out):
    """Row ``k`` of the result arrays ``out`` from kernel result ``res`` (``struck``: the ball whose first contact
    counts): status, time, event count, pockets, first contact, cushion hits (and after the first contact), and
    events by kind."""
    status, time, n_events, pocket, pocketed_at, first, cushions, rail, counts = out
    status[k] = res.status
    time[k] = res.time
    n_events[k] = res.n_events
    for i in range(pocket.shape[1]):
        pocket[k, i] = res.pocket[i]
        pocketed_at[k, i] = res.pocketed_at[i]
        cushions[k, i] = 0
        rail[k, i] = False
    for c in range(counts.shape[1]):
        counts[k, c] = 0
    hit = -1
    ev = res.ev_int
    for e in range(res.n_events):
        kind = ev[e, 0]
        b = ev[e, 1]
        counts[k, kind] += 1
        if kind == EV_COLLISION:
            if hit < 0 and (b == struck or ev[e, 2] == struck):
                hit = ev[e, 2] if b == struck else b
        elif kind == EV_CUSHION:
            cushions[k, b] += 1
            if hit >= 0:
                rail[k, b] = True
    first[k] = hit


@njit(cache=True)
def _append_log(k, res, log):
    """Append kernel result ``res``'s events as row ``k`` of the concatenated log ``(offsets, time, kind, ball,
    other, speed)``, growing its arrays when full; returns the log."""
    offsets, ev_t, ev_k, ev_b, ev_o, ev_s = log
    m = offsets[k]
    ne = res.n_events
    if m + ne > ev_t.shape[0]:
        cap = max(m + ne, 2 * ev_t.shape[0])
        grown_t = np.empty(cap)
        grown_s = np.empty(cap)
        grown_i = np.empty((3, cap), np.int64)
        for e in range(m):  # (element by element: no shape check and its message compiled)
            grown_t[e] = ev_t[e]
            grown_s[e] = ev_s[e]
            grown_i[0, e] = ev_k[e]
            grown_i[1, e] = ev_b[e]
            grown_i[2, e] = ev_o[e]
        ev_t, ev_k, ev_b, ev_o, ev_s = grown_t, grown_i[0], grown_i[1], grown_i[2], grown_s
    for e in range(ne):
        ev_t[m + e] = res.ev_time[e]
        ev_k[m + e] = res.ev_int[e, 0]
        ev_b[m + e] = res.ev_int[e, 1]
        ev_o[m + e] = res.ev_int[e, 2]
        ev_s[m + e] = res.ev_speed[e]
    offsets[k + 1] = m + ne
    return offsets, ev_t, ev_k, ev_b, ev_o, ev_s


@njit(cache=True, nogil=True)
def rows_linear(pos, vel, ang, on, radius, mass, pocket_xy, pocket_r, params, max_events, struck, out, keep, log):
    """Rows one after the other through the rolling/drag kernel (``keep``: append each row's events to ``log``,
    returned)."""
    shared = radius.shape[0] == 1
    scratch = exact_scratch(pos.shape[1])  # one for every row: the kernel's arrays made once, not each shot
    for k in range(pos.shape[0]):
        r = 0 if shared else k
        res = simulate_exact_in(scratch, pos[k], vel[k], ang[0], radius[r], mass[r], on[k], pocket_xy, pocket_r,
                                params, max_events, False)
        store_row(k, res, struck[k], out)
        if keep:
            log = _append_log(k, res, log)
    return log


@njit(cache=True, nogil=True)
def rows_spin(pos, vel, ang, on, radius, mass, pocket_xy, pocket_r, params, max_events, struck, out, keep, log):
    """:func:`rows_linear` for the spin model (angular velocities ``ang`` updated in place too)."""
    shared = radius.shape[0] == 1
    for k in range(pos.shape[0]):
        r = 0 if shared else k
        res = simulate_exact_spin(pos[k], vel[k], ang[k], radius[r], mass[r], on[k], pocket_xy, pocket_r, params,
                                  max_events, False)
        store_row(k, res, struck[k], out)
        if keep:
            log = _append_log(k, res, log)
    return log
