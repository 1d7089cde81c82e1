"""What a player reads: a :class:`~billiards_env.table_state.TableState` (the table, the balls, who is to shoot and
what they may do), seen as a :class:`ShotContext` of plain physics objects; the turn of a chosen shot into an
action of an action type (the ``codec``: an env's action type, whose ``action`` and ``shot`` map shots to actions
and back); and :class:`BasePlayer`, the two forms of every player's one decision.

Players take the state, never the env: ``player.shot(state, obs, codec)`` is the
:class:`~billiards_env.shot_path.CueShot` they play, ``player.act(state, obs, codec)`` the action of ``codec`` that
plays it. The shot is the codec's reading of that very action (float32, quantized as the action type says), so a
player plays the same shot whichever form it is asked in. Given an env instead (``player.act(env, obs)``, the
Gymnasium habit of a user's loop), they read ``env.unwrapped.table_state`` and act in ``env.unwrapped.action_type``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from billiards_env.physics import Balls, Physics, Simulator, Table
from billiards_env.shot_path import CueShot
from billiards_env.table_state import TableState, state_of


@dataclass(frozen=True)
class ShotContext:
    """What a player needs to know about the current shot.

    ``targets``: rows of the balls the shooter may hit first (every object ball on the table, or in a game the
    legal targets of the rules). ``game``: the game's session (its ``rules``, ``state``, ``needs_called_pocket()``,
    ``numbers``, ``row_of``) in a game, else None. ``place_area``: ``(x0, x1, y0, y1)`` where the shooter may put
    the cue ball now (ball in hand), else None. ``table_state``: the state it was read from (placement and aiming
    from a place: ``legal_cue_position``, ``cue_moved_to``)."""

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
    table_state: TableState | None = None


def shot_context(source: Any, codec: Any = None) -> ShotContext:
    """The :class:`ShotContext` of a table state, or of an env's (``codec``: the action type the player acts in,
    default an env's own; its spin dims say whether tip offsets are set)."""
    state = state_of(source)
    if codec is None:
        codec = getattr(getattr(source, "unwrapped", source), "action_type", None)
    s = state.settings
    view = state.view
    spin_dims = bool(getattr(codec, "spin", s.tip_offsets))
    return ShotContext(state.balls, state.table, state.physics, state.simulator, 0, list(view.targets),
                       s.speed_range, s.angle_noise, s.speed_noise, state.game, view.place_area, s.tip_noise,
                       state.physics.has_spin and spin_dims, state)


def player_inputs(source: Any, codec: Any = None) -> tuple[TableState, Any]:
    """The table state and the action type (``codec``) a player acts on: ``source`` is a table state (then
    ``codec`` is needed) or a billiards env, wrapped or not (``codec`` defaults to its action type)."""
    state = state_of(source)
    if codec is None:
        codec = getattr(getattr(source, "unwrapped", source), "action_type", None)
        if codec is None:
            raise TypeError("player.act(state, obs, codec) / player.shot(state, obs, codec): give the action type "
                            "to act in (an env's action_type) with a table state")
    return state, codec


def to_action(codec: Any, state: TableState, angle: float, speed: float, place: tuple[float, float] | None = None,
              side: float = 0.0, top: float = 0.0, **calls: Any) -> np.ndarray:
    """The action of ``codec`` (an action type) for a shot ``(angle, speed)`` (from ``place`` with ball in hand; tip
    offsets ``side``, ``top`` when the action has spin dims, else dropped), with the player's whole call ``calls``
    (e.g. ``pocket=``, ``ball=``: the codec keeps the declarations its game makes), inside its space."""
    tip = {"side": side, "top": top} if codec.spin else {}
    a = np.asarray(codec.action(state, angle, speed, place=place, **tip, **calls), dtype=np.float32)
    return np.clip(a, codec.space.low, codec.space.high)


class BasePlayer:
    """The base of the players: one decision (:meth:`choose`), asked for in two forms.

    :meth:`shot` gives the :class:`~billiards_env.shot_path.CueShot` the player plays (what the env's opponent
    plays); :meth:`act` the action of ``codec`` that plays it (SB3-style loops, teachers). Both come from one
    :meth:`choose`, which a player writes: its decision as an action of ``codec``, so the shot is always one the
    action type can express (its float32 quantization included; the search values exactly such shots) and never
    differs between the two forms. ``source``: a table state (then ``codec`` is needed) or a billiards env
    (``codec`` defaults to its action type)."""

    name = "player"
    #: Whether :meth:`choose` reads the observation (False: the env's opponent is not observed for).
    reads_observation = False

    def reset(self, seed: int | None = None) -> None:
        """A new episode (``seed``: a fresh generator for players that draw)."""

    def choose(self, state: TableState, obs: Any, codec: Any) -> np.ndarray:
        """The player's decision on ``state``: the action of ``codec`` (an action type) that plays its shot."""
        raise NotImplementedError(f"{type(self).__name__}.choose: a player writes its decision here")

    def act(self, source: Any, obs: Any = None, codec: Any = None) -> np.ndarray:
        """The action (in ``codec``; default an env's own action type) of the player's shot on ``source``."""
        state, codec = player_inputs(source, codec)
        return self.choose(state, obs, codec)

    def shot(self, source: Any, obs: Any = None, codec: Any = None) -> CueShot:
        """The shot the player plays on ``source``: ``codec``'s reading of the action it chooses (no noise)."""
        state, codec = player_inputs(source, codec)
        return codec.shot(state, self.choose(state, obs, codec))


__all__ = ["ShotContext", "shot_context", "player_inputs", "to_action", "BasePlayer"]
