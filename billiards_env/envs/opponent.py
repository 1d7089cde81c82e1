"""The opponent of a game env: who sits where (:class:`Seat`) and the object that plays the opponent's shots
(:class:`Opponent`).

A :class:`~billiards_env.envs.games.GameTask` is given an :class:`Opponent` by its env and asks it for the
opponent's shot on the table state now (:meth:`Opponent.shot`); it plays that shot through the shot path the env
lends it (:class:`~billiards_env.envs.tasks.Driver`). The task never calls back into the env: the opponent holds
what it acts with (the observation type, the env's action type, the action type a player acts in), given once
when the env is made.
"""
from __future__ import annotations

import inspect
from dataclasses import dataclass
from typing import Any

import numpy as np

from billiards_env.players import make_player
from billiards_env.shot_path import CueShot
from billiards_env.table_state import TableState


@dataclass
class Seat:
    """Who sits where in a game env: ``agent`` is the player the env's agent plays (0), and ``auto`` says whether
    the opponent's turns are played inside ``step`` (single-agent mode) or by someone else (the two-player env,
    two people at ``billiards-play``: nobody plays automatically)."""

    agent: int = 0
    auto: bool = True

    @property
    def opponent(self) -> int:
        """The opponent's player number."""
        return 1 - self.agent


class Opponent:
    """Plays the opponent's shots on the table state it is given.

    ``policy``: a player (``act(state, obs, codec)``, as the players of :mod:`billiards_env.players`: it acts in
    ``acting_type``, the env's action type or an exact one when the env's cannot express every shot), an object
    with ``act(env, obs)`` (handed ``handle``, the env, as the agents' policies expect), an SB3-style model
    (``predict``), a callable ``obs -> action``, a player's name (made for ``game``) or None (nobody: the agent
    plays alone). The observation is made only for a policy that reads it (``reads_observation``, True unless the
    policy says otherwise)."""

    def __init__(self, observation_type: Any, action_type: Any, acting_type: Any, game: str,
                 policy: Any = None, handle: Any = None) -> None:
        self.observation_type = observation_type
        self.action_type = action_type
        self.acting_type = acting_type
        self.game = game
        self.handle = handle
        self._policy: Any = None
        self._takes_codec = False  # the policy's act takes a table state and an action type
        self.set_policy(policy)

    @property
    def policy(self) -> Any:
        """The opponent's policy, or None (the agent plays alone)."""
        return self._policy

    def set_policy(self, policy: Any) -> None:
        """Play with ``policy`` (see the class docstring). Anything else raises ``TypeError`` now, not at the next
        step."""
        if isinstance(policy, str):
            policy = make_player(policy, seed=0, game=self.game)
        if policy is not None and not (hasattr(policy, "act") or hasattr(policy, "predict") or callable(policy)):
            raise TypeError(f"opponent: expected a player (act), a model (predict), a callable obs -> action, a "
                            f"player's name or None; got {type(policy).__name__}")
        self._policy = policy
        act = getattr(policy, "act", None)
        self._takes_codec = act is not None and "codec" in inspect.signature(act).parameters

    def reset(self, rng: np.random.Generator) -> None:
        """A new episode: a policy that keeps a generator (``reset(seed)``) is reseeded from ``rng`` (one draw; none
        for a policy without ``reset``)."""
        if self._policy is not None and hasattr(self._policy, "reset"):
            self._policy.reset(int(rng.integers(2**31)))

    def action(self, state: TableState) -> tuple[np.ndarray, Any]:
        """The policy's action on ``state`` and the action type it is in."""
        opp = self._policy
        if opp is None:
            raise RuntimeError("the opponent has no policy: the agent plays alone (set_opponent(policy) sets one)")
        obs = self.observation_type.observe(state) if getattr(opp, "reads_observation", True) else None
        if self._takes_codec:
            return opp.act(state, obs, codec=self.acting_type), self.acting_type
        if hasattr(opp, "act"):
            return opp.act(self.handle, obs), self.action_type
        if hasattr(opp, "predict"):
            return opp.predict(obs, deterministic=True)[0], self.action_type
        return opp(obs), self.action_type

    def shot(self, state: TableState) -> CueShot:
        """The opponent's shot on ``state``: its policy's action read back through the action type it acts in."""
        action, codec = self.action(state)
        return codec.shot(state, action)

    def name(self) -> str:
        """The policy's name for the HUD: its ``name``, else its class name; ``"nobody"`` without a policy."""
        opp = self._policy
        if opp is None:
            return "nobody"
        return str(getattr(opp, "name", None) or type(opp).__name__)


__all__ = ["Seat", "Opponent"]
