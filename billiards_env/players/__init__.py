"""billiards_env.players: baseline players for every env, and a library for pool AI (no Gymnasium imports).

- ``random``: uniformly random actions;
- ``geometric``: ghost-ball aiming at the easiest pocket (:mod:`.shots`, on :mod:`billiards_env.physics.aim`);
- ``search``: simulates candidate shots with the exact solver and plays the best (:mod:`.search`).

A player reads a table state (:class:`~billiards_env.table_state.TableState`: the balls, the table, the physics,
who is to shoot and what they may do), chooses a shot ``(angle, speed)`` in physical units as an action type
(``codec``) expresses it, and returns it: ``player.shot(state, obs, codec)`` is the
:class:`~billiards_env.shot_path.CueShot` it plays, ``player.act(state, obs, codec)`` the action of ``codec`` that
plays it (one decision, :meth:`BasePlayer.choose`, in both forms), so the same player works with every action
type. Given an env, it reads ``env.unwrapped.table_state`` and acts in the env's own action type. The decision functions
(:func:`geometric_shot`, :func:`search_shot`) take plain physics objects (a :class:`ShotContext`), so they can be
used without an environment::

    player = make_player("search", seed=0)
    obs, info = env.reset(seed=1)
    u = env.unwrapped
    shot = player.shot(u.table_state, obs, u.action_type)    # the CueShot it plays
    action = player.act(u.table_state, obs, u.action_type)   # the action that plays it

The players' geometry is compiled array code (:mod:`.geometry`, numba): every ghost-ball shot of a table, the
ball-in-hand placement and the geometric player's whole decision are one call each on arrays (the balls, a
:class:`TableModel` of the table and the motion law, the legal targets), no env needed::

    d = geometric_decision(balls.pos, balls.on_table, balls.radius, balls.mass, targets,
                           table_model(table, physics), (0.5, 5.0), place_area=None, is_break=False)
    d.angle, d.speed, d.place, d.pocket

:mod:`.slots` gives the ``candidates`` types' slot lists the same way.
"""
from __future__ import annotations

from typing import Any, Callable, Protocol

import numpy as np

from billiards_env.shot_path import CueShot

from .context import BasePlayer, ShotContext, shot_context, to_action
from .context import player_inputs as player_inputs  # importable from here (geometric, search), not in __all__
from .geometric import GeometricPlayer, geometric_shot
from .geometry import Decision, TableModel, geometric_decision, table_model
from .random import RandomPlayer
from .search import Outcome, SearchPlayer, SearchSettings, search_shot
from .shots import MAX_CUT, ShotCandidate, direct_hit, ghost_ball_shots, position_score

BASELINES = ("random", "geometric", "search")


class Player(Protocol):
    """What a player offers (:class:`BasePlayer` gives both forms from one decision): ``shot`` the
    :class:`~billiards_env.shot_path.CueShot` it plays on a table state, in what the action type ``codec`` can
    express; ``act`` the action of ``codec`` that plays it."""

    name: str

    def reset(self, seed: int | None = None) -> None: ...

    def shot(self, source: Any, obs: Any = None, codec: Any = None) -> CueShot: ...

    def act(self, source: Any, obs: Any = None, codec: Any = None) -> np.ndarray: ...


PLAYERS: dict[str, Callable[..., Any]] = {
    "random": RandomPlayer,
    "geometric": GeometricPlayer,
    "search": SearchPlayer,
}


def make_player(name: str, seed: int | None = 0, game: str | None = None, **kwargs: Any) -> Any:
    """A baseline player by name: ``random``, ``geometric`` or ``search``; of ``game`` (a registered game's name,
    e.g. ``"snooker"``: that game's players, :attr:`GameSession.players <billiards_env.games.session.GameSession>`)
    or of pool (the default: the players of the pot scenes, 9-ball and 8-ball)."""
    if game is not None:
        import importlib

        from billiards_env.games import game_spec

        players = game_spec(game).session_class.players
        if name not in players:
            raise ValueError(f"unknown player {name!r} for {game}; use one of {', '.join(players)}")
        module, _, attr = players[name].partition(":")
        return getattr(importlib.import_module(module), attr)(seed=seed, **kwargs)
    try:
        cls = PLAYERS[name]
    except KeyError:
        raise ValueError(f"unknown baseline {name!r}; use one of {', '.join(PLAYERS)}") from None
    return cls(seed=seed, **kwargs)


__all__ = ["BASELINES", "Player", "BasePlayer", "ShotContext", "shot_context", "to_action", "geometric_shot", "search_shot",
           "SearchSettings", "Outcome", "RandomPlayer", "GeometricPlayer", "SearchPlayer", "make_player", "PLAYERS",
           "ShotCandidate", "ghost_ball_shots", "direct_hit", "position_score", "MAX_CUT", "geometric_decision",
           "Decision", "TableModel", "table_model"]
