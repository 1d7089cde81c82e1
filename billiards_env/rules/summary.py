"""What a shot did, in the terms the rules of pool need: the :class:`ShotSummary` of a simulated shot.

A summary is built from the solver's event log (columns ``kind``, ``ball``, ``other``) and its per-ball pocket
array, with ``numbers`` mapping each row to a ball number (0 = the cue ball). The env's shot path reads the log
once into a :class:`~billiards_env.physics.outcome.ShotOutcome` and calls :func:`summarize_outcome`;
:func:`summarize_arrays` takes the arrays of ``Simulator.run_in_place`` and :func:`summarize_result` a
:class:`~billiards_env.physics.ShotResult`. All work on whole arrays (no per-event objects).

Only collision, cushion and pocket events matter; the other kinds (stop, the spin model's roll and spin) carry no
rule information, and a ``jam`` (a burst of contacts merged into one cluster move, see ``physics/collide.py``) only
ever follows the collision and cushion events that started the burst, which are logged as such. The scan over the
events is one compiled pass (:func:`billiards_env.physics.outcome.scan_shot`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Sequence

import numpy as np

from ..physics.outcome import scan_shot
from .errors import RulesError

if TYPE_CHECKING:  # pragma: no cover
    from ..physics import ShotResult
    from ..physics.outcome import ShotOutcome

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


def _summary(numbers: np.ndarray, pocket: np.ndarray, cue: int, first: int, rail: np.ndarray,
             order: np.ndarray) -> ShotSummary:
    """The summary of one scan (:func:`~billiards_env.physics.outcome.scan_shot`), rows named by ``numbers``."""
    pocketed = numbers[order]
    return ShotSummary(None if first < 0 else int(numbers[first]), tuple(np.sort(numbers[rail]).tolist()),
                       tuple(pocketed.tolist()), tuple(pocket[order].tolist()), bool(pocket[cue] >= 0),
                       int(pocket[cue]))


def summarize_outcome(outcome: "ShotOutcome", numbers: np.ndarray) -> ShotSummary:
    """The summary of a :class:`~billiards_env.physics.outcome.ShotOutcome` (the env's shot path reads the event log
    once, there), with ``numbers`` ``(N,)`` int64 the ball number of each row (row ``outcome.cue`` must be 0)."""
    rail = np.zeros(len(numbers), np.bool_)
    rail[list(outcome.rails)] = True
    return _summary(numbers, np.asarray(outcome.pocket, dtype=np.int64), outcome.cue, outcome.first_contact, rail,
                    np.asarray(outcome.drop_order, dtype=np.int64))


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
    cues = np.flatnonzero(numbers == CUE)
    if len(cues) != 1:
        raise RulesError(f"numbers: {len(cues)} rows have number 0; exactly one row must be the cue ball")
    cue = int(cues[0])
    first, rail, order, n_order = scan_shot(ev, pocket, cue)
    return _summary(numbers, pocket, cue, int(first), rail, order[:n_order])


def summarize_result(result: "ShotResult", numbers: np.ndarray | Sequence[int] | None = None) -> ShotSummary:
    """The summary of a :class:`~billiards_env.physics.ShotResult`; ``numbers`` default to the balls' ids
    read by :func:`ball_numbers`."""
    nums = ball_numbers(result.balls.ids) if numbers is None else numbers
    ev = result.events
    return summarize_arrays(np.stack([ev.kind, ev.ball, ev.other], axis=1), result.pocket, nums)


__all__ = ["CUE", "ShotSummary", "ball_numbers", "summarize_outcome", "summarize_arrays", "summarize_result"]
