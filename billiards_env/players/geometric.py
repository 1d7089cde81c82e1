"""The geometric player: ghost-ball aiming at the easiest pocket (:func:`billiards_env.players.shots.ghost_ball_shots`)."""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from billiards_env.physics.aim import aim_angle, direction_vector, ghost_ball_position, pocket_window
from billiards_env.physics.layout import head_spot

from .context import ShotContext, player_inputs, shot_context, to_action
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



def break_shot(ctx: ShotContext) -> tuple[tuple[float, float] | None, float, float]:
    """The opening break: the cue ball on the head string (where the shooter may place it), struck at full speed
    into the middle of the lowest legal ball (the apex). Returns ``(place, angle, speed)``."""
    b = ctx.balls
    place = None
    if ctx.place_area is not None:
        x0, x1, y0, y1 = ctx.place_area
        place = (min(max(head_spot(ctx.table)[0], x0), x1), min(max(0.5 * ctx.table.width, y0), y1))
    cue = b.pos[ctx.cue] if place is None else np.asarray(place)
    target = min(ctx.targets, key=lambda j: float(np.hypot(*(b.pos[j] - cue)))) if ctx.targets else ctx.cue
    return place, aim_angle(cue, b.pos[target]), float(ctx.speed_range[1])


def choose_placement(ctx: ShotContext, max_cut: float = MAX_CUT,
                     backs: tuple[float, ...] = (0.25, 0.5)) -> tuple[float, float]:
    """Ball in hand: the legal cue position (in ``ctx.place_area``, off the other balls) that leaves the easiest
    ghost-ball shot. Candidates are the straight-in positions ``backs`` metres behind the ghost ball of every
    legal target and pocket (moved to the nearest legal point); each is scored by :func:`ghost_ball_shots`."""
    u = ctx.table_state
    b = ctx.balls
    r = float(b.radius[ctx.cue])
    x0, x1, y0, y1 = ctx.place_area
    best, best_score = None, -1.0
    for j in ctx.targets:
        obj = b.pos[j]
        contact = r + float(b.radius[j])
        for p in range(ctx.table.n_pockets):
            win = pocket_window(obj, float(b.radius[j]), ctx.table, p)
            if win is None:
                continue
            ghost = ghost_ball_position(obj, win[0], contact)
            for back in backs:
                x, y = ghost - back * direction_vector(win[0])
                place = u.legal_cue_position(min(max(x, x0), x1), min(max(y, y0), y1))
                with u.cue_moved_to(place):
                    shots = ghost_ball_shots(b, ctx.table, ctx.physics, ctx.cue, [j], ctx.speed_range, max_cut)
                score = shots[0].score if shots else 0.0
                if score > best_score:
                    best, best_score = place, score
    if best is None:  # nothing makeable from anywhere: the middle of the area
        best = u.legal_cue_position(0.5 * (x0 + x1), 0.5 * (y0 + y1))
    return best


class GeometricPlayer:
    """Ghost-ball aiming at the easiest pocket (see :func:`.shots.ghost_ball_shots`)."""

    name = "geometric"

    def __init__(self, seed: int | None = 0, max_cut: float = MAX_CUT):
        self.max_cut = max_cut
        self.last: ShotCandidate | None = None

    def reset(self, seed: int | None = None) -> None:
        self.last = None

    def act(self, source: Any, obs: Any = None, codec: Any = None) -> np.ndarray:
        """The action (in ``codec``, an action type; default the env's) of the shot chosen on ``source`` (a table
        state or an env). In a game it follows the rules: the legal balls only, a full-power break, ball in hand
        placed for the easiest shot (:func:`choose_placement`), and the pocket of its shot called when on the 8."""
        state, codec = player_inputs(source, codec)
        ctx = shot_context(state, codec)
        if ctx.game is not None and ctx.game.state.break_shot:
            place, angle, speed = break_shot(ctx)
            self.last = None
            return to_action(codec, state, angle, speed, place=place)
        place = choose_placement(ctx, self.max_cut) if ctx.place_area is not None else None
        with state.cue_moved_to(place):
            angle, speed, self.last = geometric_shot(ctx, self.max_cut)
        pocket = self.last.pocket if self.last is not None else None
        return to_action(codec, state, angle, speed, place=place, pocket=pocket)



__all__ = ["geometric_shot", "break_shot", "choose_placement", "GeometricPlayer"]
