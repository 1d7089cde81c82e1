"""Three-cushion's opening position (UMB) and its three balls.

The three-cushion game owns these (its session racks by them; its players read them); the physics keeps the pool
table's markings they stand on (:mod:`billiards_env.physics.layout`: the head and foot spots). The balls' ids are
the rules' (:data:`~billiards_env.rules.three_cushion.CAROM_IDS`).
"""
from __future__ import annotations

from billiards_env.physics.balls import Balls
from billiards_env.physics.errors import SceneError
from billiards_env.physics.layout import foot_spot, head_spot
from billiards_env.physics.table import CAROM_BALL_MASS, CAROM_BALL_RADIUS, CAROM_WIDTH, Table
from billiards_env.rules.three_cushion import CAROM_IDS

#: UMB: the starting spots on the head string, 182 mm either side of the head spot (on the 1.42 m wide table).
CAROM_START_OFFSET = 0.182


def carom_start_positions(table: Table, breaker: int = 0, side: int = 1) -> dict[str, tuple[float, float]]:
    """The UMB opening position: the red on the top spot (``3 length/4``, the foot spot), the opponent's cue ball
    on the head spot (``length/4``), and the breaker's cue ball (``"white"`` for player 0, ``"yellow"`` for
    player 1) on the head string 182 mm (scaled with the width) to one side of it: ``side`` +1 towards ``y =
    width``, -1 towards ``y = 0``."""
    if breaker not in (0, 1):
        raise SceneError(f"breaker: must be player 0 or 1, got {breaker!r}")
    if side not in (-1, 1):
        raise SceneError(f"side: must be -1 or +1, got {side!r}")
    hx, hy = head_spot(table)
    off = CAROM_START_OFFSET * table.width / CAROM_WIDTH
    mine, theirs = CAROM_IDS[breaker], CAROM_IDS[1 - breaker]
    return {mine: (hx, hy + side * off), theirs: (hx, hy), "red": foot_spot(table)}


def carom_balls(table: Table, positions: dict[str, tuple[float, float]] | None = None, breaker: int = 0,
                side: int = 1, radius: float = CAROM_BALL_RADIUS, mass: float = CAROM_BALL_MASS) -> Balls:
    """The three carom balls (ids :data:`CAROM_IDS`) at ``positions`` (default: the opening position of
    :func:`carom_start_positions`)."""
    pos = carom_start_positions(table, breaker, side) if positions is None else positions
    missing = [i for i in CAROM_IDS if i not in pos]
    if missing:
        raise SceneError(f"positions: missing {missing}; give a position for each of {', '.join(CAROM_IDS)}")
    return Balls.from_positions([pos[i] for i in CAROM_IDS], ids=CAROM_IDS, radius=radius, mass=mass)


__all__ = ["CAROM_IDS", "CAROM_START_OFFSET", "carom_start_positions", "carom_balls"]
