"""What a player needs to know about the shot it is to play: :class:`ShotContext` (plain physics objects)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from billiards_env.physics import Balls, Physics, Simulator, Table


@dataclass(frozen=True)
class ShotContext:
    """What a player needs to know about the current shot."""

    balls: Balls
    table: Table
    physics: Physics
    simulator: Simulator
    cue: int
    targets: list[int]
    speed_range: tuple[float, float]
    angle_noise: float = 0.0
    speed_noise: float = 0.0


def shot_context(env: Any) -> ShotContext:
    """The :class:`ShotContext` of a billiards env (wrapped or not)."""
    u = env.unwrapped
    balls: Balls = u.balls
    cfg = u.config
    cue = balls.index("cue") if "cue" in balls.ids else 0
    targets = [i for i in range(len(balls)) if i != cue and balls.on_table[i]]
    return ShotContext(balls, u.table, u.physics, u.simulator, cue, targets,
                       (float(cfg.speed_min), float(cfg.speed_max)),
                       float(getattr(cfg, "angle_noise", 0.0)), float(getattr(cfg, "speed_noise", 0.0)))


def to_action(env: Any, angle: float, speed: float) -> np.ndarray:
    """The env's action for a shot ``(angle, speed)`` (in its action type), inside its action space."""
    a = np.asarray(env.unwrapped.action_from_shot(angle, speed), dtype=np.float32)
    return np.clip(a, env.action_space.low, env.action_space.high)


__all__ = ["ShotContext", "shot_context", "to_action"]
