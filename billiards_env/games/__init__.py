"""billiards_env.games: the games played on the tables, above the rules and below the envs (no Gymnasium).

- :mod:`.registry`: :data:`GAMES`, one :class:`GameSpec` per game: the one list every other module reads;
- :mod:`.session`: :class:`GameSession`, one game in progress on a table state (judges shots, applies the calls,
  tells who is to shoot and what they may do, the features an agent observes, the HUD); each game subclasses it;
- :mod:`.pool`: 9-ball and 8-ball;
- :mod:`.hud`: the plain data of a game's HUD (the score, the call in words);
- :mod:`.infos`: the form of an info value (:class:`~.infos.InfoSpec`); each session declares its own info keys.

Importing this package loads only the registry; the rest loads on use.
"""
from .registry import GAMES, GameSpec, game_of_env, game_spec, register_game

__all__ = ["GAMES", "GameSpec", "game_spec", "game_of_env", "register_game"]
