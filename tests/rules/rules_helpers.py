"""Scripted tables for the rules tests: place balls, play one shot with the exact solver, summarize it.

Imported as a plain module (``tests/`` has no ``__init__.py``; the basename is unique on purpose).
Pockets of the default table, by index: 0 bottom-left, 1 bottom-side, 2 bottom-right, 3 top-left, 4 top-side,
5 top-right.
"""
from __future__ import annotations

import math

import numpy as np

from billiards_env.physics import BALL_RADIUS, Balls, Physics, Simulator, Table
from billiards_env.physics.layout import (DIAMOND_ORDER, RACK_ORDER, diamond_positions, foot_spot, head_spot,
                                         triangle_positions)
from billiards_env.rules import ShotSummary, summarize_result

R = BALL_RADIUS
TABLE = Table()
L, W = TABLE.length, TABLE.width
POCKETS = np.asarray(TABLE.pocket_xy)
SIM = Simulator(TABLE, Physics())
HEAD_SPOT = head_spot(TABLE)
FOOT_SPOT = foot_spot(TABLE)


def unit(a, b) -> np.ndarray:
    """Unit vector from point ``a`` to point ``b``."""
    d = np.asarray(b, float) - np.asarray(a, float)
    return d / np.linalg.norm(d)


def angle_to(a, b) -> float:
    """Direction (rad) from point ``a`` to point ``b``."""
    d = np.asarray(b, float) - np.asarray(a, float)
    return math.atan2(d[1], d[0])


def behind(ball, pocket: int, dist: float, pockets: np.ndarray = POCKETS) -> tuple[float, float]:
    """The point ``dist`` behind ``ball`` on the line from pocket ``pocket`` (of ``pockets``: the pool table's by
    default) through ``ball`` (where a ball must sit to drive ``ball`` straight into the pocket)."""
    p = np.asarray(ball, float) - dist * unit(ball, pockets[pocket])
    return float(p[0]), float(p[1])


def diamond_rack(apex, numbers=DIAMOND_ORDER) -> dict[str, tuple[float, float]]:
    """A touching 9-ball diamond at ``apex``, balls ``numbers`` row by row (default: the 1 at the apex, the 9 in
    the middle)."""
    return {str(n): tuple(p) for n, p in zip(numbers, diamond_positions(apex))}


def triangle_rack(apex) -> dict[str, tuple[float, float]]:
    """A touching 15-ball triangle at ``apex`` (the 8 in the middle of the third row)."""
    return {str(n): tuple(p) for n, p in zip(RACK_ORDER, triangle_positions(apex))}


def shoot(balls: dict[str, tuple[float, float]], angle: float, speed: float, table: Table | None = None,
          ) -> ShotSummary:
    """Place ``balls`` (id -> centre; ``"cue"`` among them), strike the cue ball at ``angle``/``speed``, run the
    exact solver to rest and summarize the shot."""
    ids = list(balls)
    b = Balls.from_positions([balls[i] for i in ids], ids=ids).strike("cue", angle, speed)
    sim = SIM if table is None else Simulator(table, Physics())
    res = sim.run(b)
    assert res.status == "rest"
    return summarize_result(res)


#: Where balls that take no part in a scene wait (the left end of the table; every scene plays at x >= 0.7).
PARK = [(0.25, 0.25), (0.25, 0.5), (0.25, 0.75), (0.25, 1.0), (0.45, 0.25), (0.45, 0.5), (0.45, 0.75),
        (0.45, 1.0), (0.15, 0.635), (0.35, 0.635), (0.55, 0.4), (0.55, 0.9), (0.35, 0.15), (0.35, 1.12)]


def parked(ids) -> dict[str, tuple[float, float]]:
    """Balls ``ids`` at the parking spots."""
    ids = [str(i) for i in ids]
    assert len(ids) <= len(PARK)
    return dict(zip(ids, PARK))


def pot(ball: str, others=(), speed: float = 1.5) -> ShotSummary:
    """The cue ball drives ``ball`` straight into the bottom-right pocket (2) from 0.4 m; the cue ball stays."""
    b = (2.2, 0.3)
    cue = behind(b, 2, 0.4)
    return shoot({"cue": cue, ball: b, **parked(others)}, angle_to(cue, b), speed)


def pot_into(ball: str, pocket: int, others=(), speed: float = 1.5) -> ShotSummary:
    """The cue ball drives ``ball`` (0.3 m from pocket ``pocket`` toward the table centre) straight into it."""
    b = tuple(POCKETS[pocket] + 0.3 * unit(POCKETS[pocket], (L / 2, W / 2)))
    cue = behind(b, pocket, 0.4)
    return shoot({"cue": cue, ball: b, **parked(others)}, angle_to(cue, b), speed)


def combo(first: str, second: str, others=(), pocket: int = 5, speed: float = 2.0) -> ShotSummary:
    """The cue ball drives ``first`` into ``second``, which drops in pocket ``pocket``; ``first`` stays up."""
    s = (2.25, 1.0) if pocket == 5 else (2.25, 0.27)
    one = behind(s, pocket, 0.2)
    cue = behind(s, pocket, 0.6)
    return shoot({"cue": cue, first: one, second: s, **parked(others)}, angle_to(cue, one), speed)


def scratch_pot(ball: str, others=()) -> ShotSummary:
    """A hard straight shot at ``ball`` just in front of pocket 2: the ball drops and the cue ball follows it."""
    b = (L - 0.09, 0.09)
    cue = behind(b, 2, 0.3)
    return shoot({"cue": cue, ball: b, **parked(others)}, angle_to(cue, b), 8.0)


def rail_miss(ball: str, others=()) -> ShotSummary:
    """The cue ball sends ``ball`` softly into the top cushion, far from any pocket: nothing drops."""
    return shoot({"cue": (0.8, 0.5), ball: (0.8, 1.0), **parked(others)}, math.pi / 2, 0.6)


def soft_touch(ball: str, others=()) -> ShotSummary:
    """The cue ball nudges ``ball`` in the middle of the table: no ball reaches a cushion."""
    return shoot({"cue": (0.75, 0.635), ball: (1.0, 0.635), **parked(others)}, 0.0, 0.3)


def miss_all(others=()) -> ShotSummary:
    """The cue ball rolls into the top cushion and back without touching a ball."""
    return shoot({"cue": (0.75, 0.635), **parked(others)}, math.pi / 2, 0.5)


def straight_scratch(others=()) -> ShotSummary:
    """The cue ball rolls straight into pocket 2 without touching a ball."""
    cue = (2.0, 0.5)
    return shoot({"cue": cue, **parked(others)}, angle_to(cue, POCKETS[2]), 1.5)
