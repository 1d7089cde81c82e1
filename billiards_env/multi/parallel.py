"""The two-player games on PettingZoo's parallel API (:class:`BilliardsParallelEnv`), for libraries that take a
``ParallelEnv`` (TorchRL's ``PettingZooWrapper(parallel=True)``, SuperSuit, RLlib's ``ParallelPettingZooEnv``).

Pool is turn-based, so the parallel env is PettingZoo's own conversion for turn-based games
(``pettingzoo.utils.conversions.turn_based_aec_to_parallel``) on the AEC env: every ``step`` takes an action per
agent, plays the one of the agent to shoot and ignores the other's. ``aec_to_parallel`` does not fit (it needs
the agents to act in a fixed cycle; a player who pockets a ball shoots again). This module adds to the
conversion what a user needs: clear errors for a missing or unknown agent's action and a step after the game,
and ``infos[agent]["active_agent"]`` (the agent to shoot next) after ``reset`` as after every ``step``.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import gymnasium as gym
import numpy as np
from pettingzoo import AECEnv
from pettingzoo.utils.conversions import turn_based_aec_to_parallel_wrapper


class BilliardsParallelEnv(turn_based_aec_to_parallel_wrapper):
    """A pool game for two players on PettingZoo's parallel API; made by each game module's ``parallel_env``
    (``nine_ball_v0.parallel_env(max_cycles=100, **config)``).

    ## Turns

    Both agents act every step (``actions = {"player_0": a0, "player_1": a1}``); the action of the agent to shoot
    (``infos[agent]["active_agent"]``, the same for both agents) is played as one shot, and the other's is
    ignored (any value; it may be left out). One step is one shot, one step of the AEC env: a player who keeps the
    table is the active agent again.

    ## Spaces, rewards, infos, episode end

    As the AEC env (:class:`billiards_env.multi.aec.BilliardsGameAEC`): the single-agent env's spaces, each agent
    its own point of view and its own reward for the shot, ``terminations`` for both when the game is over,
    ``truncations`` for both after ``max_cycles`` steps (the config's ``max_shots``); then ``agents`` is empty
    and the next ``step`` raises ``gymnasium.error.ResetNeeded``. ``reset(seed)`` replays bit for bit.
    """

    def __init__(self, aec_env: AECEnv) -> None:
        super().__init__(aec_env)
        self.agents: list[str] = []

    def reset(self, seed: int | None = None, options: dict[str, Any] | None = None
              ) -> tuple[dict[str, np.ndarray], dict[str, dict[str, Any]]]:
        """The AEC env's reset; the infos name the agent to shoot (``active_agent``) as ``step``'s do."""
        observations, infos = super().reset(seed=seed, options=options)
        active = self.aec_env.agent_selection
        return observations, {a: {**info, "active_agent": active} for a, info in infos.items()}

    def step(self, actions: Mapping[str, Any]) -> tuple[dict[str, np.ndarray], dict[str, float], dict[str, bool],
                                                         dict[str, bool], dict[str, dict[str, Any]]]:
        """Play the action of the agent to shoot; the other agent's action is ignored."""
        if not self.agents:
            raise gym.error.ResetNeeded("step() after the game ended (env.agents is empty); call reset()")
        if not isinstance(actions, Mapping):
            raise TypeError(f"actions: expected a dict agent -> action, got {type(actions).__name__}")
        unknown = sorted(str(a) for a in actions if a not in self.possible_agents)
        if unknown:
            raise ValueError(f"actions: unknown agent(s) {unknown}; the agents are {self.possible_agents}")
        shooter = self.aec_env.agent_selection
        if actions.get(shooter) is None:
            raise ValueError(f"actions: no action for {shooter!r}, the agent to shoot (infos[agent]['active_agent']); "
                             "the other agent's action is ignored and may be left out")
        observations, rewards, terminations, truncations, infos = super().step(actions)
        active = self.aec_env.agent_selection  # also after the last shot, so the infos keep one set of keys
        return observations, rewards, terminations, truncations, {a: {**info, "active_agent": active}
                                                                  for a, info in infos.items()}


__all__ = ["BilliardsParallelEnv"]
