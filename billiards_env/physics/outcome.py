"""What one shot did, read once from the solver's output: :class:`ShotOutcome`.

The event log (columns ``kind``, ``ball``, ``other``) and the per-ball pocket array of a shot hold every fact the
layers above need: the first ball the cue ball touched, the balls that met a cushion after that contact, the balls
pocketed (in the order they dropped, and where), the scratch. :func:`scan_shot` reads them in one compiled pass;
the env's task, the rules' :class:`~billiards_env.rules.ShotSummary` and the info dict all take them from the
outcome instead of scanning the log again.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from .codes import EV_COLLISION, EV_CUSHION, EV_POCKET


@njit(cache=True)
def scan_shot(events, pocket, cue):
    """One pass over ``events`` ``(M, 3)`` (kind, ball row, other) with the pocket index of each row (``pocket``,
    -1: not pocketed on this shot) for the struck ball ``cue``. Returns ``(first, rail, order, n_order)``: the row
    of the first ball ``cue`` collided with (-1: none), a bool mask of the rows with a cushion contact after that
    collision, and the rows of the other pocketed balls in the order of their pocket events (rows the pocket array
    reports without a pocket event last, in row order: not expected), ``order[:n_order]``."""
    n = pocket.shape[0]
    first = -1
    rail = np.zeros(n, np.bool_)
    order = np.empty(n, np.int64)
    listed = np.zeros(n, np.bool_)
    n_order = 0
    for k in range(events.shape[0]):
        kd = events[k, 0]
        b = events[k, 1]
        if kd == EV_COLLISION:
            o = events[k, 2]
            if first < 0 and (b == cue or o == cue):
                first = o if b == cue else b
        elif kd == EV_CUSHION:
            if first >= 0:
                rail[b] = True
        elif kd == EV_POCKET:
            if b != cue and pocket[b] >= 0 and not listed[b]:
                listed[b] = True
                order[n_order] = b
                n_order += 1
    for r in range(n):
        if r != cue and pocket[r] >= 0 and not listed[r]:
            order[n_order] = r
            n_order += 1
    return first, rail, order, n_order


@njit(cache=True)
def first_contact_row(events, ball):
    """Row of the first ball that ``ball`` collided with in an ``(M, 3)`` event log, or -1."""
    for k in range(events.shape[0]):
        if events[k, 0] == EV_COLLISION:
            b = events[k, 1]
            o = events[k, 2]
            if b == ball:
                return o
            if o == ball:
                return b
    return -1


@dataclass(frozen=True)
class ShotOutcome:
    """What one simulated shot did (rows index the balls; the struck ball is row ``cue``, 0 in every env)."""

    status: str  #: "rest", "time_cap" or "event_cap"
    sim_time: float  #: simulated seconds
    n_events: int
    pocket: np.ndarray  #: (N,) pocket index of each ball pocketed by this shot, -1 otherwise
    events: np.ndarray  #: (M, 3) int event log: kind, ball, other
    pocketed: tuple[int, ...]  #: rows pocketed by this shot, in row order (the cue ball included)
    scratch: bool  #: the struck ball was pocketed
    first_contact: int  #: row of the first ball the struck ball hit, -1 if none
    rails: tuple[int, ...]  #: rows with a cushion contact after the first contact, ascending
    drop_order: tuple[int, ...]  #: rows of the other balls pocketed, in the order they dropped
    cue: int = 0  #: the struck ball's row

    @classmethod
    def from_arrays(cls, status: str, sim_time: float, n_events: int, pocket: np.ndarray, events: np.ndarray,
                    cue: int = 0) -> "ShotOutcome":
        """The outcome of a shot from the solver's arrays (``Simulator.run_in_place``'s return values)."""
        ev = np.ascontiguousarray(events, dtype=np.int64).reshape(-1, 3)
        pk = np.ascontiguousarray(pocket, dtype=np.int64)
        first, rail, order, n_order = scan_shot(ev, pk, cue)
        pocketed = tuple(i for i, p in enumerate(pk.tolist()) if p >= 0)
        return cls(status, float(sim_time), int(n_events), pocket, ev, pocketed, bool(pk[cue] >= 0), int(first),
                   tuple(np.flatnonzero(rail).tolist()), tuple(order[:n_order].tolist()), cue)


__all__ = ["ShotOutcome", "scan_shot", "first_contact_row"]
