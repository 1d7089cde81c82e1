"""The opponent of a game env: who sits where (:class:`Seat`) and the object that plays the opponent's shots
(:class:`Opponent`).

A :class:`~billiards_env.envs.games.GameTask` is given an :class:`Opponent` by its env and asks it for the
opponent's shot on the table state now (:meth:`Opponent.shot`); it plays that shot through the shot path the env
lends it (:class:`~billiards_env.envs.tasks.Driver`). The task never calls back into the env, and neither does the
opponent: it holds what it acts with (the observation type, the env's action type, the action type a player acts
in), given once when the env is made, and hands its policy the table state, never the env.
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

    ``policy``: a player (``shot(state, obs, codec) -> CueShot``, as the players of :mod:`billiards_env.players`:
    it plays in ``acting_type``, the env's action type or an exact one when the env's cannot express every shot,
    and its shot is played as it is), a policy on the table state (``act(state, obs, codec)``), an SB3-style model
    (``predict``) or a callable ``obs -> action`` (these three act in the env's ``action_type``, as an agent does;
    their action is read back through it), a player's name (made for ``game``) or None (nobody: the agent plays
    alone). The old form ``act(env, obs)`` is refused (:func:`policy_form`): no policy is handed the env. The
    observation is made only for a policy that reads it (``reads_observation``, True unless the policy says
    otherwise)."""

    def __init__(self, observation_type: Any, action_type: Any, acting_type: Any, game: str,
                 policy: Any = None) -> None:
        self.observation_type = observation_type
        self.action_type = action_type
        self.acting_type = acting_type
        self.game = game
        self._policy: Any = None
        self._form = ""  # how the policy is asked (policy_form)
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
        self._form = "" if policy is None else policy_form(policy, "opponent")
        self._policy = policy

    def reset(self, rng: np.random.Generator) -> None:
        """A new episode: a policy that keeps a generator (``reset(seed)``) is reseeded from ``rng`` (one draw; none
        for a policy without ``reset``)."""
        if self._policy is not None and hasattr(self._policy, "reset"):
            self._policy.reset(int(rng.integers(2**31)))

    def shot(self, state: TableState) -> CueShot:
        """The opponent's shot on ``state``: a player's own :class:`CueShot` (in ``acting_type``); for a policy that
        returns actions, its action read back through the env's action type, which it acts in."""
        opp = self._policy
        if opp is None:
            raise RuntimeError("the opponent has no policy: the agent plays alone (set_opponent(policy) sets one)")
        obs = self.observation_type.observe(state) if getattr(opp, "reads_observation", True) else None
        if self._form == "shot":
            return opp.shot(state, obs, codec=self.acting_type)
        if self._form == "act":
            return self.action_type.shot(state, opp.act(state, obs, codec=self.action_type))
        if self._form == "predict":
            return self.action_type.shot(state, opp.predict(obs, deterministic=True)[0])
        return self.action_type.shot(state, opp(obs))

    def name(self) -> str:
        """The policy's name for the HUD: its ``name``, else its class name; ``"nobody"`` without a policy."""
        opp = self._policy
        if opp is None:
            return "nobody"
        return str(getattr(opp, "name", None) or type(opp).__name__)


def _takes_codec(method: Any) -> bool:
    """Whether ``method`` has a ``codec`` parameter (the table-state form ``(state, obs, codec)``)."""
    try:
        return "codec" in inspect.signature(method).parameters
    except (TypeError, ValueError):  # no signature to read
        return False


def policy_form(policy: Any, what: str = "policy") -> str:
    """How ``policy`` is asked for its shot: ``"shot"`` (a player: ``shot(state, obs, codec) -> CueShot``),
    ``"act"`` (a policy on the table state: ``act(state, obs, codec)``, an action of ``codec``), ``"predict"`` (an
    SB3-style model) or ``"call"`` (a callable ``obs -> action``). Anything else raises ``TypeError``; an ``act``
    without a ``codec`` parameter is the old ``act(env, obs)`` form, refused with the form to write: policies are
    handed the :class:`~billiards_env.table_state.TableState`, never the env."""
    if callable(getattr(policy, "shot", None)) and _takes_codec(policy.shot):
        return "shot"
    act = getattr(policy, "act", None)
    if act is not None:
        if _takes_codec(act):
            return "act"
        sig = ""
        try:
            sig = str(inspect.signature(act))
        except (TypeError, ValueError):
            pass
        raise TypeError(f"{what}: {type(policy).__name__}.act{sig} is the old form act(env, obs); policies are no "
                        "longer handed the env. Write act(state, obs, codec) (read the TableState `state`, return "
                        "an action of the action type `codec`) or shot(state, obs, codec) -> CueShot, as the "
                        "players of billiards_env.players do")
    if hasattr(policy, "predict"):
        return "predict"
    if callable(policy):
        return "call"
    raise TypeError(f"{what}: expected a player (shot(state, obs, codec)), a policy (act(state, obs, codec)), a "
                    f"model (predict), a callable obs -> action, a player's name or None; got "
                    f"{type(policy).__name__}")


__all__ = ["Seat", "Opponent", "policy_form"]
