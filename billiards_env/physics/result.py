"""What a simulated shot returns: status, final balls, pockets, the event log and the trajectory."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Sequence

import numpy as np

from .balls import Balls
from .codes import (CUSHION_NAMES, EV_COLLISION, EV_CUSHION, EV_JAM, EV_POCKET, EV_ROLL, EV_SPIN, EV_STOP,
                    EVENT_KINDS, MOTION_STATES)
from .trajectory import Trajectory


@dataclass(frozen=True)
class EventLog:
    """Events in time order, as columns: ``time`` (s), ``kind`` (0 collision, 1 cushion, 2 pocket, 3 stop,
    4 jam; spin model: 5 roll, 6 spin), ``ball`` (row), ``other`` (other ball's row, cushion 0-3 left/right/bottom/top, pocket index, the
    number of balls in a jammed cluster, or -1),
    ``speed`` (normal impact speed, or the ball's speed when pocketed)."""

    time: np.ndarray
    kind: np.ndarray
    ball: np.ndarray
    other: np.ndarray
    speed: np.ndarray

    def __len__(self) -> int:
        return len(self.time)

    def as_dicts(self, ids: tuple[str, ...], cushion_names: Sequence[str] = CUSHION_NAMES) -> list[dict[str, Any]]:
        """The events as JSON-ready dicts naming balls by id and cushions by ``cushion_names`` (a jaw table's:
        :data:`.pocket_specs.WALL_NAMES`)."""
        out = []
        for t, k, b, o, s in zip(self.time.tolist(), self.kind.tolist(), self.ball.tolist(),
                                 self.other.tolist(), self.speed.tolist()):
            ev: dict[str, Any] = {"time": t, "kind": EVENT_KINDS[k], "ball": ids[b]}
            if k == EV_COLLISION:
                ev["other"] = ids[o]
            elif k == EV_CUSHION:
                ev["cushion"] = cushion_names[o]
            elif k == EV_POCKET:
                ev["pocket"] = o
            elif k == EV_JAM:
                ev["cluster_size"] = o
            if k not in (EV_STOP, EV_JAM, EV_ROLL, EV_SPIN):
                ev["speed"] = s
            out.append(ev)
        return out


@dataclass(frozen=True)
class ShotResult:
    """The outcome of one shot. ``status``: ``"rest"`` (every ball stopped or pocketed), ``"time_cap"``
    (balls still moving at ``max_time``) or ``"event_cap"`` (``max_events`` reached)."""

    status: str
    time: float
    n_events: int
    balls: Balls  #: final state
    pocket: np.ndarray  #: pocket index per ball, -1 if on the table
    pocketed_at: np.ndarray  #: time each ball was pocketed (NaN if not)
    events: EventLog
    solver: str
    trajectory: Trajectory | None = None
    n_steps: int = 0  #: time steps taken (``step`` solver)
    n_tunnelled: int = 0  #: ball pairs that passed through each other within a step (``step`` solver)
    extra: dict[str, Any] = field(default_factory=dict)
    #: spin model: each ball's final motion state (:data:`.codes.MOTION_STATES` codes); None for the other laws
    motion_state: np.ndarray | None = None

    @property
    def newly_pocketed(self) -> np.ndarray:
        """Rows of the balls pocketed during this shot."""
        return np.flatnonzero(self.pocket >= 0)

    def first_contact(self, ball: int = 0) -> int:
        """Row of the first ball that ``ball`` collided with, or -1 if it hit no ball."""
        ev = self.events
        for k, b, o in zip(ev.kind.tolist(), ev.ball.tolist(), ev.other.tolist()):
            if k == EV_COLLISION and (b == ball or o == ball):
                return o if b == ball else b
        return -1

    def to_dict(self, include_events: bool = False, cushion_names: Sequence[str] = CUSHION_NAMES) -> dict[str, Any]:
        """The result as the JSON document ``billiards-sim`` prints (``cushion_names``: see
        :meth:`EventLog.as_dicts`)."""
        b = self.balls
        balls = []
        spin = self.motion_state is not None
        for i, bid in enumerate(b.ids):
            pocketed = bool(self.pocket[i] >= 0) or not bool(b.on_table[i])
            ball: dict[str, Any] = {
                "id": bid,
                "x": float(b.pos[i, 0]),
                "y": float(b.pos[i, 1]),
                "vx": float(b.vel[i, 0]),
                "vy": float(b.vel[i, 1]),
            }
            if self.motion_state is not None:  # spin
                ball.update(wx=float(b.ang[i, 0]), wy=float(b.ang[i, 1]), wz=float(b.ang[i, 2]),
                            state=MOTION_STATES[int(self.motion_state[i])])
            ball.update(pocketed=pocketed, pocket=int(self.pocket[i]) if self.pocket[i] >= 0 else None,
                        pocketed_at=None if math.isnan(self.pocketed_at[i]) else float(self.pocketed_at[i]))
            balls.append(ball)
        out: dict[str, Any] = {"status": self.status, "time": float(self.time), "n_events": int(self.n_events),
                               "solver": self.solver}
        if self.solver.startswith("step"):
            out["n_steps"] = int(self.n_steps)
            out["n_tunnelled"] = int(self.n_tunnelled)
        out["balls"] = balls
        if include_events:
            out["events"] = self.events.as_dicts(b.ids, cushion_names)
            if spin:
                self._add_event_states(out["events"])
        return out

    def _add_event_states(self, events: list[dict[str, Any]]) -> None:
        """Spin model: the motion state of each ball an event leaves behind (``state``, and ``other_state`` for
        the other ball of a collision), read from the exact solver's state log (one row per involved ball after
        each event, after one row per ball at the start). Nothing is added without that log."""
        tr = self.trajectory
        if tr is None or tr.interpolate or tr.state.shape[1] < 9:
            return
        row = tr.n_balls
        codes = tr.state[:, 8]
        for ev, k, o in zip(events, self.events.kind.tolist(), self.events.other.tolist()):
            n_rows = 2 if k == EV_COLLISION else (o if k == EV_JAM else 1)
            ev["state"] = MOTION_STATES[int(codes[row])]
            if k == EV_COLLISION:
                ev["other_state"] = MOTION_STATES[int(codes[row + 1])]
            row += n_rows
