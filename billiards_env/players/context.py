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
    tip_noise: float = 0.0
    #: Whether the shooter sets tip offsets (the spin model and an action with the side/top dims).
    tip_offsets: bool = False


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
                       float(getattr(cfg, "angle_noise", 0.0)), float(getattr(cfg, "speed_noise", 0.0)), game, area,
                       float(getattr(cfg, "tip_noise", 0.0)),
                       u.physics.friction == "spin" and bool(getattr(getattr(u, "action_type", None), "spin", False)))


def to_action(env: Any, angle: float, speed: float, place: tuple[float, float] | None = None,
              pocket: int | None = None, side: float = 0.0, top: float = 0.0) -> np.ndarray:
    """The env's action for a shot ``(angle, speed)`` (in its action type; from ``place`` with ball in hand,
    calling ``pocket`` for the 8; tip offsets ``side``, ``top`` when the action has spin dims, else dropped),
    inside its action space."""
    u = env.unwrapped
    spin = getattr(getattr(u, "action_type", None), "spin", False)
    tip = {"side": side, "top": top} if spin else {}
    a = np.asarray(u.action_from_shot(angle, speed, place=place, pocket=pocket, **tip), dtype=np.float32)
    return np.clip(a, env.action_space.low, env.action_space.high)


__all__ = ["ShotContext", "shot_context", "to_action"]
