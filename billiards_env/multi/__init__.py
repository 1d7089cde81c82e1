"""billiards_env.multi: the games for two players, as PettingZoo AEC and parallel envs, and matches between policies.

::

    from billiards_env.multi import eight_ball_v0, nine_ball_v0, play_match
    from billiards_env.players import make_player

    env = nine_ball_v0.env(angle_noise=0.01)      # every config key of the single-agent envs
    env.reset(seed=0)
    for agent in env.agent_iter():                # "player_0", "player_1": whoever is to shoot
        obs, reward, terminated, truncated, info = env.last()
        action = None if terminated or truncated else env.action_space(agent).sample()
        env.step(action)

    par = nine_ball_v0.parallel_env(max_cycles=100)   # the parallel API: both agents act every step,
    observations, infos = par.reset(seed=0)           # only the action of infos[a]["active_agent"] is played
    while par.agents:
        actions = {a: par.action_space(a).sample() for a in par.agents}
        observations, rewards, terminations, truncations, infos = par.step(actions)

    result = play_match(nine_ball_v0.env, [make_player("geometric"), make_player("random")], n_games=10, seed=0)
    result.winners, result.wins                   # per game: 0 / 1 (the policy) or -1 (truncated)

- :mod:`.nine_ball_v0`, :mod:`.eight_ball_v0`, :mod:`.snooker_v0`, :mod:`.three_cushion_v0`: ``env(**config)``
  (AEC, wrapped), ``parallel_env(**config)`` (:class:`.parallel.BilliardsParallelEnv`: turn-based, the action of
  the agent not to shoot is ignored) and ``raw_env`` (made by :func:`.aec.game_module`); both take
  ``max_cycles`` (the shot limit); the manual is :class:`.aec.BilliardsGameAEC`. Built on the single-agent game
  env (``env.unwrapped.game_env``), which plays and judges every shot; the two-player env only passes the turn
  and gives each agent its view and its reward.
- :func:`play_match` (:mod:`.match`): games between two policies (players, SB3 models, callables), seats
  alternating, for self-play evaluation and leagues.

PettingZoo is a dependency; Gymnasium's registry does not list these (PettingZoo has none): import the modules.
"""
from __future__ import annotations

import importlib
from types import ModuleType

from billiards_env.games import GAMES

from .aec import AGENTS, BilliardsGameAEC
from .match import GameRecord, MatchResult, play_match
from .parallel import BilliardsParallelEnv

#: Every game's two-player module name (``nine_ball_v0``...), from the game registry: a new game's module is listed
#: by its registry entry, and imported on first use (``from billiards_env.multi import nine_ball_v0``, or
#: ``billiards_env.multi.nine_ball_v0``).
GAME_MODULES: tuple[str, ...] = tuple(g.aec_module for g in GAMES.values())


def __getattr__(name: str) -> ModuleType:
    """A registered game's two-player module, imported on first use."""
    if name in GAME_MODULES:
        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = [*GAME_MODULES, "GAME_MODULES", "BilliardsGameAEC", "BilliardsParallelEnv", "AGENTS", "play_match",
           "MatchResult", "GameRecord"]
