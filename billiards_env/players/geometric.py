"""The geometric player: ghost-ball aiming at the easiest pocket (:func:`billiards_env.players.shots.ghost_ball_shots`).

Its whole decision (the break, the ball-in-hand placement, the easiest shot with the 80 then 88 degree cut limits,
the direct hit when nothing pots) is one compiled call on arrays
(:func:`billiards_env.players.geometry.geometric_decision`).
The functions here take a :class:`ShotContext` (the player, a table state) and call it.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from billiards_env.table_state import TableState

from .context import BasePlayer, ShotContext, shot_context, to_action
from .geometry import (MAX_CUT, PLACE_BACKS, Decision, TableModel, choose_place, geometric_decision, state_model,
                       table_model)
from .shots import ShotCandidate, candidate_of


def context_model(ctx: ShotContext) -> TableModel:
    """The table model of a context: its table state's, made once per state (:func:`.geometry.state_model`), when the
    context was read from one; else made now."""
    st = ctx.table_state
    if st is not None and st.table is ctx.table and st.physics is ctx.physics:
        return state_model(st)
    return table_model(ctx.table, ctx.physics)


def _decide(ctx: ShotContext, max_cut: float, is_break: bool, place_area: Any = None) -> Decision:
    b = ctx.balls
    return geometric_decision(b.pos, b.on_table, b.radius, b.mass, np.asarray(ctx.targets, dtype=np.int64),
                              context_model(ctx), ctx.speed_range, place_area, is_break, max_cut, ctx.cue)


def geometric_shot(ctx: ShotContext, max_cut: float = MAX_CUT) -> tuple[float, float, ShotCandidate | None]:
    """The easiest ghost-ball shot ``(angle, speed, candidate)`` from where the cue ball lies; falls back to thinner
    cuts (up to 88 deg) and then to a firm full-ball hit on the nearest ball (candidate None)."""
    d = _decide(ctx, max_cut, False)
    return d.angle, d.speed, (candidate_of(d.rows[d.shot]) if d.shot >= 0 else None)


def break_shot(ctx: ShotContext) -> tuple[tuple[float, float] | None, float, float]:
    """The opening break: the cue ball on the head string (where the shooter may place it), struck at full speed
    into the middle of the lowest legal ball (the apex). Returns ``(place, angle, speed)``."""
    d = _decide(ctx, MAX_CUT, True, ctx.place_area)
    return d.place, d.angle, d.speed


def choose_placement(ctx: ShotContext, max_cut: float = MAX_CUT,
                     backs: tuple[float, ...] = PLACE_BACKS) -> tuple[float, float]:
    """Ball in hand: the legal cue position (in ``ctx.place_area``, off the other balls and the pockets) that
    leaves the easiest ghost-ball shot. Candidates are the straight-in positions ``backs`` metres behind the ghost
    ball of every legal target and pocket (moved to the nearest legal point); each is scored by the best ghost-ball
    shot at that target from there (:func:`billiards_env.players.geometry.choose_place`)."""
    from billiards_env.physics.errors import SceneError

    b = ctx.balls
    x, y, ok = choose_place(np.ascontiguousarray(b.pos, dtype=np.float64),
                            np.ascontiguousarray(b.on_table, dtype=np.bool_),
                            np.ascontiguousarray(b.radius, dtype=np.float64),
                            np.ascontiguousarray(b.mass, dtype=np.float64), int(ctx.cue),
                            np.asarray(ctx.targets, dtype=np.int64), *context_model(ctx),
                            float(ctx.speed_range[0]), float(ctx.speed_range[1]), float(max_cut),
                            np.asarray(ctx.place_area, dtype=np.float64), np.asarray(backs, dtype=np.float64))
    if not ok:
        raise SceneError(f"no legal point for ball row {ctx.cue} in the area {ctx.place_area}: it is covered by "
                         "other balls")
    return float(x), float(y)


class GeometricPlayer(BasePlayer):
    """Ghost-ball aiming at the easiest pocket (see :func:`.shots.ghost_ball_shots`)."""

    name = "geometric"
    #: It reads the table state, not the observation (the env need not observe for it).
    reads_observation = False

    def __init__(self, seed: int | None = 0, max_cut: float = MAX_CUT):
        self.max_cut = max_cut
        self.last: ShotCandidate | None = None

    def reset(self, seed: int | None = None) -> None:
        self.last = None

    def decide(self, ctx: ShotContext) -> Decision:
        """The decision for a table (:func:`billiards_env.players.geometry.geometric_decision`): in a game it follows
        the rules: the legal balls only, a full-power break, ball in hand placed for the easiest shot, and the
        pocket of its shot called when on the 8."""
        is_break = ctx.game is not None and ctx.game.game_state.break_shot
        d = _decide(ctx, self.max_cut, bool(is_break), ctx.place_area)
        self.last = candidate_of(d.rows[d.shot]) if d.shot >= 0 else None
        return d

    def choose(self, state: TableState, obs: Any, codec: Any) -> np.ndarray:
        """The action (in ``codec``, an action type) of :meth:`decide` on ``state``, with the ball and pocket of a
        ghost-ball shot as its call."""
        d = self.decide(shot_context(state, codec))
        aimed = d.shot >= 0  # a ghost-ball shot: its ball and pocket are the call (the game keeps what it declares)
        return to_action(codec, state, d.angle, d.speed, place=d.place, pocket=d.pocket if aimed else None,
                         ball=self.last.target if (aimed and self.last is not None) else None)


__all__ = ["geometric_shot", "break_shot", "choose_placement", "GeometricPlayer", "context_model"]
