"""Self-play and matches: :func:`play_match` plays games between two policies in a two-player env.

A policy is a player of :mod:`billiards_env.players` or a policy on the table state (``act(state, obs, codec)``; it
is given the table state of the single-agent game env, ``env.unwrapped.game_env.state``, whose balls, table and game
it reads, and that env's action type), an SB3-style model (``predict(obs)``, deterministic) or a callable
``obs -> action`` (:func:`billiards_env.envs.games.as_policy`). Each agent's
observation is its own point of view, so a policy trained single-agent (as player 0 of ``Billiards9Ball-v0``)
plays either seat.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Sequence

import numpy as np
from pettingzoo import AECEnv

from billiards_env.envs.games import as_policy

from .aec import BilliardsGameAEC


@dataclass(frozen=True)
class GameRecord:
    """One game of a match (policies by their index in the ``policies`` given to :func:`play_match`)."""

    seed: int  #: the env's reset seed
    seats: tuple[int, int]  #: the policy playing player_0 (who breaks by default) and player_1
    winner: int  #: the winning policy, or -1 (no winner: truncated after max_shots)
    reason: str  #: the call that ended the game ("9 pocketed", "three fouls"...) or "max_shots"
    shots: tuple[int, int]  #: shots taken by policy 0 and policy 1


@dataclass(frozen=True)
class MatchResult:
    """The games of a match, in order."""

    games: tuple[GameRecord, ...]

    @property
    def winners(self) -> list[int]:
        """The winning policy of each game (-1: none)."""
        return [g.winner for g in self.games]

    @property
    def wins(self) -> tuple[int, int]:
        """Games won by policy 0 and by policy 1."""
        w = self.winners
        return w.count(0), w.count(1)

    @property
    def unfinished(self) -> int:
        """Games without a winner (truncated)."""
        return self.winners.count(-1)


def play_match(env_fn: Callable[[], AECEnv] | AECEnv, policies: Sequence[Any], n_games: int, seed: int = 0,
               swap_seats: bool = True) -> MatchResult:
    """Play ``n_games`` games between ``policies[0]`` and ``policies[1]`` and return who won each.

    ``env_fn``: a two-player env (``nine_ball_v0.env(...)``, wrapped or raw) or a function making one (called
    once; the env is reused and closed at the end only if made here). Game ``k`` is played on ``reset(seed=seed +
    k)``; policies with a ``reset(seed)`` method (the players) are reseeded before each game from ``(seed, k)``,
    so a match replays exactly. With ``swap_seats`` the policies change seats every game (policy 0 is player_0 in
    even games), so each breaks as often as the other. The same policy object may take both seats (self-play).
    """
    if len(policies) != 2:
        raise ValueError(f"policies: expected two (one per seat), got {len(policies)}")
    if n_games < 1:
        raise ValueError(f"n_games: expected at least 1, got {n_games}")
    made = not isinstance(env_fn, AECEnv)
    env = env_fn() if made else env_fn
    raw = env.unwrapped
    if not isinstance(raw, BilliardsGameAEC):
        raise TypeError(f"env_fn: expected a billiards two-player env (billiards_env.multi), got {type(raw).__name__}")
    acts = [as_policy(p) for p in policies]
    game_env = raw.game_env
    games = []
    try:
        for k in range(n_games):
            seats = (1, 0) if (swap_seats and k % 2) else (0, 1)
            for j, p in enumerate(policies):
                if hasattr(p, "reset"):
                    p.reset(int(np.random.SeedSequence([seed, k, j]).generate_state(1)[0]))
            env.reset(seed=seed + k)
            shots = [0, 0]
            for agent in env.agent_iter():
                obs, _, terminated, truncated, _ = env.last()
                if terminated or truncated:
                    env.step(None)
                    continue
                who = seats[raw.agent_index[agent]]
                env.step(acts[who](game_env.state, obs, game_env.action_type))
                shots[who] += 1
            over = raw.game_over
            w = raw.task.session.winner
            winner = -1 if (not over or w is None) else seats[w]
            verdict = raw.task.verdict
            reason = verdict.reason if over and verdict is not None else "max_shots"
            games.append(GameRecord(seed + k, seats, winner, reason, (shots[0], shots[1])))
    finally:
        if made:
            env.close()
    return MatchResult(tuple(games))


__all__ = ["GameRecord", "MatchResult", "play_match"]
