"""Scripted three-cushion tables: shots built on the engine so that the cue ball meets the balls where and when
the test says.

A shot is built in stages, each a real simulation: the cue ball rolls alone (the other balls parked out of its
way) and the ball to meet is placed where the cue ball will be after its ``k``-th cushion, touching the cue ball's
centre at that instant (at a cut, so the cue ball carries on); then the next ball the same way on the path the
cue ball takes after that contact. The final scene is played once more with every ball in place.
"""
from __future__ import annotations

import math

import numpy as np

from billiards_env.physics import Balls, Physics, Simulator
from billiards_env.physics.codes import EV_COLLISION, EV_CUSHION
from billiards_env.rules.three_cushion import CAROM_IDS
from billiards_env.physics.table import CAROM_BALL_MASS, CAROM_BALL_RADIUS, carom_table

TABLE = carom_table()
L, W = TABLE.length, TABLE.width
R = CAROM_BALL_RADIUS
SIM = Simulator(TABLE, Physics())
#: Where a ball waits while the cue ball's path is traced (corners far from every path used).
PARK = {"white": (R + 0.001, R + 0.001), "yellow": (L - R - 0.001, W - R - 0.001), "red": (L - R - 0.001, R + 0.001)}


def carom(pos: dict[str, tuple[float, float]]) -> Balls:
    """The three carom balls at ``pos`` (missing ones parked)."""
    p = {**PARK, **pos}
    return Balls.from_positions([p[i] for i in CAROM_IDS], ids=CAROM_IDS, radius=R, mass=CAROM_BALL_MASS)


def run(pos: dict[str, tuple[float, float]], cue: str, angle: float, speed: float, record: bool = False):
    res = SIM.run(carom(pos).strike(cue, angle, speed), record=record)
    assert res.status == "rest"
    return res


def _cue_events(res, row: int, kind: int) -> np.ndarray:
    ev = res.events
    mask = (ev.kind == kind) & ((ev.ball == row) | ((ev.other == row) & (kind == EV_COLLISION)))
    return ev.time[mask]


def place_on_path(pos: dict[str, tuple[float, float]], cue: str, angle: float, speed: float, after: str,
                  index: int, ball: str, cut: float = 0.8, frac: float = 0.5) -> dict[str, tuple[float, float]]:
    """``pos`` plus ``ball`` placed where the cue ball, played from ``pos``, meets it ``frac`` of the way between
    its ``index``-th event of kind ``after`` (``"cushion"`` or ``"collision"``, 1-based; 0: the strike) and its next
    cushion (or its stop), at the cut angle ``cut`` (rad) to the cue ball's direction there."""
    res = run(pos, cue, angle, speed, record=True)
    row = CAROM_IDS.index(cue)
    kind = EV_CUSHION if after == "cushion" else EV_COLLISION
    t0 = _cue_events(res, row, kind)[index - 1] if index else 0.0
    later = _cue_events(res, row, EV_CUSHION)
    later = later[later > t0 + 1e-9]
    stop = res.time if not len(later) else later[0]
    t = t0 + frac * (stop - t0)
    states, _, _ = res.trajectory.sample_states(np.array([t - 1e-6, t]))
    p = states[1, row, :2]
    v = states[1, row, 2:4]
    d = v / np.linalg.norm(v)
    u = np.array([math.cos(cut) * d[0] - math.sin(cut) * d[1], math.sin(cut) * d[0] + math.cos(cut) * d[1]])
    centre = p + 2.0 * R * u
    assert R < centre[0] < L - R and R < centre[1] < W - R, "placed off the table: change the shot"
    out = {**pos, ball: (float(centre[0]), float(centre[1]))}
    check = run(out, cue, angle, speed)  # the construction holds: the cue ball meets the ball first at time t
    met = _cue_events(check, row, EV_COLLISION)
    ev = check.events
    first = ev.time[(ev.kind == EV_COLLISION) & (((ev.ball == row) & (ev.other == CAROM_IDS.index(ball)))
                                                 | ((ev.other == row) & (ev.ball == CAROM_IDS.index(ball))))]
    assert len(met) and len(first) and abs(first[0] - t) < 1e-3, "the ball is met elsewhere: change the shot"
    return out
