"""The game registry: one :class:`GameSpec` per game, the one place a game is listed.

Registration of the env ids, the config's list of tasks, the two-player envs, the league and the agents read
:data:`GAMES`; an unknown game is an error, never another game. A spec is light (names and where things are), so
reading the registry imports nothing but this module: ``import billiards_env`` registers the game ids without
loading the rules. What a game does (its ruleset, rack, features, HUD, players) is its session class (a
:class:`~.session.GameSession`), loaded on first use from ``spec.session_path``. Adding a game:
``docs/architecture.md``.
"""
from __future__ import annotations

import difflib
import importlib
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from .session import GameSession


@dataclass(frozen=True)
class GameSpec:
    """One game: ``name`` (the config's ``task`` value, e.g. ``"nine_ball"``), ``title`` (``"9-ball"``),
    ``env_id`` and ``env_class`` (the registered single-agent id and its ``module:Class``), ``scene`` (its packaged
    scene YAML, ``billiards_env/envs/scenes/<scene>.yaml``), ``aec_module`` (its PettingZoo module in
    :mod:`billiards_env.multi`), ``n_object_balls``, and ``session_path`` (``module:Class`` of its
    :class:`~.session.GameSession` subclass)."""

    name: str
    title: str
    env_id: str
    env_class: str
    scene: str
    aec_module: str
    n_object_balls: int
    session_path: str

    @property
    def session_class(self) -> "type[GameSession]":
        """The game's session class (imported on first use)."""
        module, _, attr = self.session_path.partition(":")
        return getattr(importlib.import_module(module), attr)


#: Every registered game, by name, in registration order.
GAMES: dict[str, GameSpec] = {}


def register_game(spec: GameSpec) -> GameSpec:
    """Add ``spec`` to :data:`GAMES` (a name or env id registered twice is an error)."""
    if spec.name in GAMES or any(g.env_id == spec.env_id for g in GAMES.values()):
        raise ValueError(f"game {spec.name!r} ({spec.env_id}) is registered already")
    GAMES[spec.name] = spec
    return spec


def game_spec(name: str) -> GameSpec:
    """The entry of game ``name``; an unknown name raises ``KeyError`` listing the games (with a did-you-mean)."""
    try:
        return GAMES[name]
    except KeyError:
        close = difflib.get_close_matches(str(name), list(GAMES), n=1)
        hint = f"did you mean {close[0]!r}? " if close else ""
        raise KeyError(f"unknown game {name!r}; {hint}registered games: {', '.join(GAMES)}") from None


def game_of_env(env_id: str) -> GameSpec | None:
    """The game the registered id ``env_id`` plays, or None (a scene without rules)."""
    return next((g for g in GAMES.values() if g.env_id == env_id), None)


register_game(GameSpec("nine_ball", "9-ball", "Billiards9Ball-v0", "billiards_env.envs.nine_ball:NineBallEnv",
                       "nine_ball", "nine_ball_v0", 9, "billiards_env.games.pool:NineBallSession"))
register_game(GameSpec("eight_ball", "8-ball", "Billiards8Ball-v0", "billiards_env.envs.eight_ball:EightBallEnv",
                       "eight_ball", "eight_ball_v0", 15, "billiards_env.games.pool:EightBallSession"))
register_game(GameSpec("snooker", "snooker", "BilliardsSnooker-v0", "billiards_env.envs.snooker:SnookerEnv",
                       "snooker", "snooker_v0", 21, "billiards_env.games.snooker:SnookerSession"))
register_game(GameSpec("three_cushion", "three-cushion", "BilliardsThreeCushion-v0",
                       "billiards_env.envs.three_cushion:ThreeCushionEnv", "three_cushion", "three_cushion_v0", 2,
                       "billiards_env.games.carom:CaromSession"))
register_game(GameSpec("straight_pool", "straight pool", "BilliardsStraightPool-v0",
                       "billiards_env.envs.straight_pool:StraightPoolEnv", "straight_pool", "straight_pool_v0", 15,
                       "billiards_env.games.straight_pool:StraightPoolSession"))

__all__ = ["GameSpec", "GAMES", "register_game", "game_spec", "game_of_env"]
