"""What a player needs to know about the shot it is to play: :class:`ShotContext` (plain physics objects), and
the turn of a shot into an env action."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from billiards_env.physics import Balls, Physics, Simulator, Table


@dataclass(frozen=True)
class ShotContext:
    """What a player needs to know about the current shot.

    ``targets``: rows of the balls the shooter may hit first (every object ball on the table, or in a game the
    legal targets of the rules). ``game``: the env's game task in a game (its ``rules``, ``state``,
    ``needs_called_pocket()``), else None. ``place_area``: ``(x0, x1, y0, y1)`` where the shooter may put the cue
    ball now (ball in hand), else None."""

    balls: Balls
    table: Table
    physics: Physics
    simulator: Simulator
    cue: int
    targets: list[int]
    speed_range: tuple[float, float]
    angle_noise: float = 0.0
    speed_noise: float = 0.0
    game: Any = None
    place_area: tuple[float, float, float, float] | None = None


def shot_context(env: Any) -> ShotContext:
    """The :class:`ShotContext` of a billiards env (wrapped or not)."""
    u = env.unwrapped
    balls: Balls = u.balls
    cfg = u.config
    cue = balls.index("cue") if "cue" in balls.ids else 0
    task = getattr(u, "task", None)
    game = task if hasattr(task, "rules") else None
    if game is not None:
        targets = [i for i in game.legal_rows() if balls.on_table[i]]
    else:
        targets = [i for i in range(len(balls)) if i != cue and balls.on_table[i]]
    area = task.ball_in_hand_area(u) if task is not None else None
    return ShotContext(balls, u.table, u.physics, u.simulator, cue, targets,
                       (float(cfg.speed_min), float(cfg.speed_max)),
                       float(getattr(cfg, "angle_noise", 0.0)), float(getattr(cfg, "speed_noise", 0.0)), game, area)


def to_action(env: Any, angle: float, speed: float, place: tuple[float, float] | None = None,
              pocket: int | None = None) -> np.ndarray:
    """The env's action for a shot ``(angle, speed)`` (in its action type; from ``place`` with ball in hand,
    calling ``pocket`` for the 8), inside its action space."""
    a = np.asarray(env.unwrapped.action_from_shot(angle, speed, place=place, pocket=pocket), dtype=np.float32)
    return np.clip(a, env.action_space.low, env.action_space.high)


__all__ = ["ShotContext", "shot_context", "to_action"]
