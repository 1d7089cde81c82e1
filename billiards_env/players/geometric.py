"""The geometric player: ghost-ball aiming at the easiest pocket (:func:`billiards_env.players.shots.ghost_ball_shots`)."""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from .context import ShotContext, shot_context, to_action
from .shots import MAX_CUT, ShotCandidate, direct_hit, ghost_ball_shots


def geometric_shot(ctx: ShotContext, max_cut: float = MAX_CUT) -> tuple[float, float, ShotCandidate | None]:
    """The easiest ghost-ball shot ``(angle, speed, candidate)``; falls back to thinner cuts (up to 88 deg) and
    then to a firm full-ball hit on the nearest ball (candidate None)."""
    for cut in (max_cut, math.radians(88.0)):
        shots = ghost_ball_shots(ctx.balls, ctx.table, ctx.physics, ctx.cue, ctx.targets, ctx.speed_range, cut)
        if shots:
            s = shots[0]
            return s.angle, s.speed, s
    angle, _ = direct_hit(ctx.balls, ctx.cue, ctx.targets)
    lo, hi = ctx.speed_range
    return angle, float(min(max(2.0, lo), hi)), None



class GeometricPlayer:
    """Ghost-ball aiming at the easiest pocket (see :func:`.shots.ghost_ball_shots`)."""

    name = "geometric"

    def __init__(self, seed: int | None = 0, max_cut: float = MAX_CUT):
        self.max_cut = max_cut
        self.last: ShotCandidate | None = None

    def reset(self, seed: int | None = None) -> None:
        self.last = None

    def act(self, env: Any, obs: Any) -> np.ndarray:
        angle, speed, self.last = geometric_shot(shot_context(env), self.max_cut)
        return to_action(env, angle, speed)



__all__ = ["geometric_shot", "GeometricPlayer"]
