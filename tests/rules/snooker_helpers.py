"""Scripted snooker tables: place balls, play one shot with the exact solver on the snooker table, summarize it.

The colours that take no part in a scene wait on their spots, the reds at the baulk end below the yellow spot
(every scene plays away from them). Pockets by index: 0 bottom-left, 1 bottom-middle, 2 bottom-right (the top end,
``x = L``), 3 top-left, 4 top-middle, 5 top-right.
"""
from __future__ import annotations

import math

import numpy as np
import rules_helpers
from rules_helpers import angle_to, unit  # noqa: F401 (the scenes use them)

from billiards_env.games.snooker_layout import snooker_spots
from billiards_env.physics import Balls, Physics, Simulator
from billiards_env.physics.table import SNOOKER_BALL_MASS, SNOOKER_BALL_RADIUS, snooker_table
from billiards_env.rules.snooker import (SNOOKER_COLOURS, SNOOKER_REDS, SnookerSummary, snooker_values,
                                         summarize_snooker)

R = SNOOKER_BALL_RADIUS
TABLE = snooker_table()
L, W = TABLE.length, TABLE.width
POCKETS = np.asarray(TABLE.pocket_xy)
SIM = Simulator(TABLE, Physics())
SPOTS = snooker_spots(TABLE)
#: Where reds that take no part wait (the baulk end, right of the yellow spot; no scene plays there).
RED_PARK = [(0.12 + 0.06 * (k % 4), 0.3 + 0.06 * (k // 4)) for k in range(15)]


def behind(ball, pocket: int, dist: float) -> tuple[float, float]:
    """The point ``dist`` behind ``ball`` on the line from the snooker pocket ``pocket`` through ``ball``."""
    return rules_helpers.behind(ball, pocket, dist, POCKETS)


def near_pocket(pocket: int, dist: float = 0.3) -> tuple[float, float]:
    """The point ``dist`` from pocket ``pocket`` towards the middle of the table."""
    p = POCKETS[pocket] + dist * unit(POCKETS[pocket], (L / 2, W / 2))
    return float(p[0]), float(p[1])


def layout(balls: dict[str, tuple[float, float]], reds: int = 15, colours=SNOOKER_COLOURS) -> Balls:
    """A table with ``balls`` (id -> centre; ``"cue"`` among them), ``reds`` reds in all (those not in ``balls``
    parked) and ``colours`` (those not in ``balls`` on their spots)."""
    pos = dict(balls)
    placed_reds = [i for i in balls if i.startswith("red")]
    spare = [r for r in SNOOKER_REDS if r not in balls][:reds - len(placed_reds)]
    for k, rid in enumerate(spare):
        pos[rid] = RED_PARK[k]
    for c in colours:
        pos.setdefault(c, SPOTS[c])
    ids = list(pos)
    return Balls.from_positions([pos[i] for i in ids], ids=ids, radius=R, mass=SNOOKER_BALL_MASS)


def shoot(balls: dict[str, tuple[float, float]], angle: float, speed: float, reds: int = 15,
          colours=SNOOKER_COLOURS) -> SnookerSummary:
    """Lay out the table (:func:`layout`), strike the cue ball, run the exact solver to rest, summarize."""
    b = layout(balls, reds, colours).strike("cue", angle, speed)
    res = SIM.run(b)
    assert res.status == "rest"
    ev = np.stack([res.events.kind, res.events.ball, res.events.other], axis=1)
    return summarize_snooker(ev, res.pocket, snooker_values(b.ids))


def pot(ball: str, pocket: int = 2, speed: float = 1.2, **kw) -> SnookerSummary:
    """The cue ball drives ``ball`` straight into ``pocket`` from 0.4 m behind it; the cue ball stays up."""
    b = near_pocket(pocket)
    cue = behind(b, pocket, 0.4)
    return shoot({"cue": cue, ball: b}, angle_to(cue, b), speed, **kw)


def pot_two(first: str, second: str, pocket: int = 2, speed: float = 1.6, **kw) -> SnookerSummary:
    """The cue ball hits ``first`` into ``second`` (a plant), which drops into ``pocket``; ``first`` stays up."""
    s = near_pocket(pocket, 0.25)
    one = behind(s, pocket, 0.2)
    cue = behind(s, pocket, 0.6)
    return shoot({"cue": cue, first: one, second: s}, angle_to(cue, one), speed, **kw)


def in_off(ball: str, pocket: int = 2, **kw) -> SnookerSummary:
    """A hard straight shot at ``ball`` just in front of ``pocket``: the ball drops and the cue ball follows."""
    b = near_pocket(pocket, 0.06)
    cue = behind(b, pocket, 0.3)
    return shoot({"cue": cue, ball: b}, angle_to(cue, b), 6.0, **kw)


def hit_and_stay(ball: str, **kw) -> SnookerSummary:
    """The cue ball sends ``ball`` softly into the bottom cushion in the middle of the top half: nothing drops."""
    return shoot({"cue": (2.4, 0.5), ball: (2.4, 0.25)}, -math.pi / 2, 0.6, **kw)


def miss_all(**kw) -> SnookerSummary:
    """The cue ball rolls into the bottom cushion and back, touching nothing."""
    return shoot({"cue": (2.2, 0.5)}, -math.pi / 2, 0.5, **kw)
