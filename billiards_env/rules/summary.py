"""What a shot did, in the terms the rules of pool need: the :class:`ShotSummary` of a simulated shot.

A summary is built from the solver's event log (columns ``kind``, ``ball``, ``other``) and its per-ball pocket
array, with ``numbers`` mapping each row to a ball number (0 = the cue ball). The env's hot path calls
:func:`summarize_arrays` on the arrays of ``Simulator.run_in_place``; :func:`summarize_result` does the same for
a :class:`~billiards_env.physics.ShotResult`. Both work on whole arrays (no per-event objects).

Only collision, cushion and pocket events matter; the other kinds (stop, the spin model's roll and spin) carry no
rule information, and a ``jam`` (a burst of contacts merged into one cluster move, see ``physics/collide.py``) only
ever follows the collision and cushion events that started the burst, which are logged as such. The scan over the
events is one compiled pass (:func:`scan_events`, numba, cached).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Sequence

import numpy as np
from numba import njit

from ..physics.codes import EV_COLLISION, EV_CUSHION, EV_POCKET
from .errors import RulesError

if TYPE_CHECKING:  # pragma: no cover
    from ..physics import ShotResult

CUE = 0  #: the cue ball's number


@dataclass(frozen=True, slots=True)
class ShotSummary:
    """The rule-relevant facts of one shot. Balls are named by number (0 = cue ball).

    ``first_contact``: the first ball the cue ball touched (None: it touched none).
    ``rail_balls``: balls (cue included, as 0) that touched a cushion after that first contact, ascending.
    ``pocketed``: object balls pocketed, in the order they dropped; ``pockets``: the pocket index of each
    (the table's pocket order). ``cue_pocketed`` / ``cue_pocket``: the scratch and its pocket (-1 if none).
    """

    first_contact: int | None = None
    rail_balls: tuple[int, ...] = ()
    pocketed: tuple[int, ...] = ()
    pockets: tuple[int, ...] = ()
    cue_pocketed: bool = False
    cue_pocket: int = -1

    def __post_init__(self) -> None:
        if len(self.pocketed) != len(self.pockets):
            raise RulesError(f"ShotSummary.pockets: {len(self.pockets)} pocket indices for {len(self.pocketed)} "
                             "pocketed balls; give one pocket per pocketed ball")
        if CUE in self.pocketed:
            raise RulesError("ShotSummary.pocketed: lists the cue ball (0); report a scratch with cue_pocketed=True")
        if len(set(self.pocketed)) != len(self.pocketed):
            raise RulesError(f"ShotSummary.pocketed: a ball appears twice in {self.pocketed}")
        if self.first_contact == CUE:
            raise RulesError("ShotSummary.first_contact: the cue ball cannot be its own first contact")

    @property
    def rail_after_contact(self) -> bool:
        """Some ball (cue or object) touched a cushion after the first contact."""
        return bool(self.rail_balls)

    @property
    def object_balls_to_rail(self) -> int:
        """How many object balls touched a cushion after the first contact (the break requirement counts these)."""
        return sum(1 for n in self.rail_balls if n != CUE)

    def pocket_of(self, number: int) -> int | None:
        """The pocket ball ``number`` dropped into on this shot, or None if it was not pocketed."""
        if number == CUE:
            return self.cue_pocket if self.cue_pocketed else None
        try:
            return self.pockets[self.pocketed.index(number)]
        except ValueError:
            return None


def ball_numbers(ids: Sequence[str]) -> np.ndarray:
    """Ball numbers of a scene's ids: ``"cue"`` is 0, ``"1"``..``"15"`` are 1..15 (the ids games use).

    Raises :class:`RulesError` for any other id, a repeated number or a scene without exactly one cue ball.
    """
    out = np.empty(len(ids), dtype=np.int64)
    for row, bid in enumerate(ids):
        if bid == "cue":
            out[row] = CUE
        elif isinstance(bid, str) and bid.isdigit() and 1 <= int(bid) <= 15:
            out[row] = int(bid)
        else:
            raise RulesError(f"ball id {bid!r} (row {row}): games need the ids 'cue' and '1'..'15'; "
                             "rename the ball")
    if len(set(out.tolist())) != len(out):
        raise RulesError(f"ball ids {list(ids)}: a ball number appears twice; every ball needs its own number")
    if int(np.count_nonzero(out == CUE)) != 1:
        raise RulesError(f"ball ids {list(ids)}: a game needs exactly one ball with id 'cue'")
    return out


@njit(cache=True)
def scan_events(events, pocket, numbers):
    """One compiled pass over the event log ``events`` ``(M, 3)``: kind, ball row, other) with the pocket index and
    ball number of each row. Returns ``(first, rails, pocketed, pockets, cue_pocket)``: the number of the first ball the
    cue ball collided with (-1: none; -2: ``numbers`` has no single 0), the numbers of the balls with a cushion
    contact after that collision (ascending), the object balls pocketed in the order of their pocket events and
    their pockets, and the cue ball's pocket (-1: none)."""
    n = numbers.shape[0]
    cue = -1
    for r in range(n):
        if numbers[r] == 0:
            if cue >= 0:
                cue = -2
                break
            cue = r
    empty = np.empty(0, np.int64)
    if cue < 0:
        return -2, empty, empty, empty, -1
    first = -1
    rail = np.zeros(n, np.bool_)
    pocketed = np.empty(n, np.int64)
    pockets = np.empty(n, np.int64)
    listed = np.zeros(n, np.bool_)
    n_pot = 0
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
                pocketed[n_pot] = numbers[b]
                pockets[n_pot] = pocket[b]
                n_pot += 1
    for r in range(n):  # a ball the pocket array reports without a pocket event (not expected): last
        if r != cue and pocket[r] >= 0 and not listed[r]:
            pocketed[n_pot] = numbers[r]
            pockets[n_pot] = pocket[r]
            n_pot += 1
    rails = np.sort(numbers[rail])
    return (numbers[first] if first >= 0 else -1), rails, pocketed[:n_pot], pockets[:n_pot], pocket[cue]


def summarize_arrays(events: np.ndarray, pocket: np.ndarray, numbers: np.ndarray | Sequence[int]) -> ShotSummary:
    """The summary of a shot from ``Simulator.run_in_place``'s ``events`` ``(M, 3)`` int array (kind, ball,
    other) and ``pocket`` ``(N,)`` array (pocket index per ball row, -1: not pocketed on this shot), with
    ``numbers`` ``(N,)`` the ball number of each row (0 = cue ball; :func:`ball_numbers` makes them from ids)."""
    ev = np.ascontiguousarray(events, dtype=np.int64)
    if ev.ndim != 2 or ev.shape[1] != 3:
        raise RulesError(f"events: expected an (M, 3) array of kind, ball, other; got shape {ev.shape}")
    numbers = np.ascontiguousarray(numbers, dtype=np.int64)
    pocket = np.ascontiguousarray(pocket, dtype=np.int64)
    if pocket.shape != numbers.shape or numbers.ndim != 1:
        raise RulesError(f"pocket: shape {pocket.shape} but numbers has shape {numbers.shape}; give one pocket "
                         "index and one ball number per ball row")
    first, rails, pocketed, pockets, cue_pocket = scan_events(ev, pocket, numbers)
    if first == -2:
        raise RulesError(f"numbers: {int(np.count_nonzero(numbers == CUE))} rows have number 0; exactly one row "
                         "must be the cue ball")
    return ShotSummary(None if first < 0 else int(first), tuple(rails.tolist()), tuple(pocketed.tolist()),
                       tuple(pockets.tolist()), cue_pocket >= 0, int(cue_pocket))


def summarize_result(result: "ShotResult", numbers: np.ndarray | Sequence[int] | None = None) -> ShotSummary:
    """The summary of a :class:`~billiards_env.physics.ShotResult`; ``numbers`` default to the balls' ids
    read by :func:`ball_numbers`."""
    nums = ball_numbers(result.balls.ids) if numbers is None else numbers
    ev = result.events
    return summarize_arrays(np.stack([ev.kind, ev.ball, ev.other], axis=1), result.pocket, nums)


__all__ = ["CUE", "ShotSummary", "ball_numbers", "scan_events", "summarize_arrays", "summarize_result"]
