"""The two-player game env: a PettingZoo AEC env on the single-agent game env (:class:`BilliardsGameAEC`).

It is not a second copy of the game. It holds one single-agent game env (``game_env``: a
:class:`~billiards_env.envs.nine_ball.NineBallEnv` or :class:`~billiards_env.envs.eight_ball.EightBallEnv` made
with ``opponent=None``) whose task (:class:`~billiards_env.envs.games.GameTask`) judges every shot with the rules,
places the ball-in-hand cue ball, respots balls and keeps the :class:`~billiards_env.rules.GameState`. Its
seat's ``auto`` is off (``task.seat``), so nobody plays automatically: one AEC ``step`` is one shot of the agent to shoot
(``game_env.step``), and the turn passes as the rules say (``task.game_state.shooter``). Each agent observes the table
from its own point of view (``game_env.observe(player)``), and each gets its own reward for the shot
(``task.reward_of(verdict, player)``).
"""
from __future__ import annotations

import copy
import warnings
from typing import Any, Callable, ClassVar

import gymnasium as gym
import numpy as np
from gymnasium.utils import EzPickle
from pettingzoo import AECEnv, ParallelEnv
from pettingzoo.utils import wrappers

from billiards_env.envs.base import RENDER_MODES, BilliardsEnv
from billiards_env.envs.config import ConfigError
from billiards_env.envs.games import GameTask
from billiards_env.games import GAMES
from billiards_env.games.infos import single

#: The two agents; ``player_k`` is player ``k`` of the rules (``GameState.shooter``, ``Call.winner``).
AGENTS = ("player_0", "player_1")
#: Keys of the single-agent env's info that mean nothing with two agents (replaced per agent).
_SINGLE_AGENT_KEYS = ("is_success", "opponent_shots", "opponent_pocketed", "opponent_fouls")


class BilliardsGameAEC(AECEnv, EzPickle):
    """A pool game for two players (PettingZoo AEC API). Each game's module (``nine_ball_v0``, ``eight_ball_v0``,
    ``snooker_v0``, ``three_cushion_v0``) names its game with a ``raw_env`` subclass (:func:`game_module`); this is
    the manual of all of them.

    ## Description

    The game of the single-agent env (``Billiards9Ball-v0`` / ``Billiards8Ball-v0``: rules, rack, ball in hand,
    respots, docs/rules.md), with both players agents. ``agent_selection`` is the player to shoot; one ``step`` is
    one shot. A player keeps the table while he pockets legally (the same agent is selected again), and the turn
    passes on a miss or a foul (after a foul the next player has the cue ball in hand). The AEC env is built on the
    single-agent env, ``env.unwrapped.game_env``: players of :mod:`billiards_env.players` act on its table state
    in its action type (``g = env.unwrapped.game_env; player.act(g.state, obs, g.action_type)``).

    ## Agents

    ``possible_agents = ["player_0", "player_1"]``; ``player_0`` breaks (config ``first_shooter``: ``"agent"``
    is player_0, ``"opponent"`` player_1, ``"random"`` drawn at every reset).

    ## Action Space

    The single-agent env's, for the same config: ``Box(-1, 1, (n,), float32)`` laid out ``[aim, power]`` (+
    ``[side, top]`` with ``spin_action``) + ``[place_x, place_y]`` (read only with ball in hand) (+ ``[pocket]``
    for the called 8 / ``[push]`` for a 9-ball push-out); see :mod:`billiards_env.envs.actions`. Finite values
    outside the box are clipped; NaN/inf or a wrong number of values raise ``ValueError``. ``None`` is the only
    action of an agent whose game is over (PettingZoo's dead step). There is no action mask: the action is
    continuous and every action is legal (a placement that overlaps a ball moves to the nearest legal point;
    hitting the wrong ball is a foul, not an illegal move).

    ## Observation Space

    The single-agent env's, for the same config (``Box(0, 1)``: positions, pocketed flags, [shot features,] then
    the 11 game features), so a policy trained single-agent plays here and the reverse. ``observe(agent)`` takes
    that agent's point of view: ball in hand only if it is to shoot with it, its own group (8-ball), its own and
    its opponent's fouls in a row, whether it is its turn. Ball positions are the table's, unmirrored.

    ## Rewards

    Per shot, for each agent (``task.reward_of``): ``+win_reward`` (1.0) to the winner and ``-loss_penalty``
    (1.0) to the loser on the shot that ends the game (zero-sum with the defaults); the shooter's shaping if set
    (``pot_reward`` per ball it pockets on a legal shot, ``-foul_penalty`` per foul), which breaks zero-sum.
    ``last()`` returns what the agent accumulated since it last acted (PettingZoo's ``_cumulative_rewards``).

    ## Starting State

    As the single-agent env: the rack, the breaker with the cue ball in hand in the kitchen.
    ``reset(seed, options={"positions": (N, 2), "pocketed": (N,), "ball_in_hand": False | "anywhere" |
    "kitchen", "groups": (player_0's, player_1's), "break_shot": bool})`` sets up a table with player_0 to shoot.
    Unknown option keys are ignored with a warning (PettingZoo's api_test passes ``{"options": 1}``).

    ## Episode End

    ``terminations`` (both agents) when the game is over; ``truncations`` (both) after ``max_cycles`` shots of
    both players together (the config's ``max_shots``: 9-ball 100, 8-ball 150), without a winner. Each agent then
    gets one ``last()`` and steps ``None``.

    ## Info

    ``infos[agent]``: the single-agent env's keys in the same forms (``docs/infos.md``: masks over the ball rows,
    rows and codes), the same keys after reset and after every shot: the last shot's call (``foul``,
    ``foul_reason``, ``turn_over``, ``call``, ``pocketed``, ``scratch``, ``first_contact``, ``n_events``,
    ``sim_time``, ``status``, ``shots``, ``angle``, ``speed``, ``side``, ``top``), the state after it
    (``shooter``: the player to shoot next, 0 or 1; ``ball_in_hand``: his; ``legal_targets``, ``winner``: 0, 1 or
    -1 while the game goes on; the game's own keys), and per agent ``player`` (its index), ``shot_by`` (who played
    the shot, -1 after reset) and ``is_success`` (it won the game). The opponent's keys of the single-agent env
    (``opponent_shots``, ``opponent_pocketed``, ``opponent_fouls``) are left out: every shot is an agent's.

    ## Arguments

    ``raw_env(render_mode=None, config=None, max_cycles=None, **overrides)``: ``max_cycles`` is PettingZoo's name
    for the shot limit ``max_shots`` (one cycle is one shot, by whichever player is to shoot: the same count as
    the steps of ``parallel_env``), every other keyword a key of
    :class:`billiards_env.envs.config.EnvConfig` (``friction="spin"``, ``spin_action=True``, ``angle_noise``,
    ``rules={...}``...), as for ``gym.make``. ``opponent`` is ignored (both players are agents). Render modes:
    ``rgb_array``, ``rgb_array_list`` (both players' shots animated) and ``human``, as the single-agent env.
    ``env(**same)`` wraps it in PettingZoo's ``OrderEnforcingWrapper``; ``parallel_env(**same)`` is the
    parallel API on it (:class:`billiards_env.multi.parallel.BilliardsParallelEnv`: both agents give an action
    every step, the one not to shoot has it ignored).
    """

    metadata: ClassVar[dict[str, Any]] = {"render_modes": RENDER_MODES, "name": "billiards_game_v0",
                                          "is_parallelizable": False, "render_fps": 30}
    #: The single-agent game env class (set by the subclass).
    game_class: ClassVar[type[BilliardsEnv]]

    def __init__(self, render_mode: str | None = None, config: Any = None, max_cycles: int | None = None,
                 **overrides: Any) -> None:
        EzPickle.__init__(self, render_mode=render_mode, config=config, max_cycles=max_cycles, **overrides)
        super().__init__()
        if max_cycles is not None:
            overrides = {**overrides, "max_shots": _max_cycles(max_cycles, overrides.get("max_shots"))}
        task = overrides.get("task")
        if task is not None and task not in GAMES:
            raise ConfigError(f"task: {task!r} is not a game; the two-player env plays one of {', '.join(GAMES)} "
                              "(leave the key out)")
        game = self.game_class(render_mode=render_mode, config=config, **{**overrides, "opponent": None})
        if not isinstance(game.task, GameTask):
            raise ConfigError(f"task: {game.config.task!r} is not a game; the two-player env plays one of "
                              f"{', '.join(GAMES)} (leave the key out)")
        game.task.seat.auto = False  # the AEC env passes the turn; nobody plays inside step
        #: The single-agent game env the shots are played on (players act on its table state and action type:
        #: ``player.act(game_env.state, obs, game_env.action_type)``).
        self.game_env: BilliardsEnv = game
        self.task: GameTask = game.task
        self.render_mode = render_mode
        self.metadata = {**type(self).metadata, "render_fps": game.metadata["render_fps"]}
        self.possible_agents: list[str] = list(AGENTS)
        self.agent_index = {a: k for k, a in enumerate(self.possible_agents)}
        # One space object per agent (api_test and seeding want the same object back every call).
        self.observation_spaces = {a: copy.deepcopy(game.observation_space) for a in self.possible_agents}
        self.action_spaces = {a: copy.deepcopy(game.action_space) for a in self.possible_agents}
        self.agents: list[str] = []
        #: Shots of both players together before the game is truncated (the config's ``max_shots``).
        self.max_cycles: int = game.config.max_shots

    # --- PettingZoo API -------------------------------------------------------------------------------------------
    def observation_space(self, agent: str) -> gym.spaces.Box:
        return self.observation_spaces[agent]

    def action_space(self, agent: str) -> gym.spaces.Box:
        return self.action_spaces[agent]

    def observe(self, agent: str) -> np.ndarray:
        """The table seen by ``agent`` (its group, its fouls, its turn; see the class docstring)."""
        return self.game_env.observe(self.agent_index[agent])

    def reset(self, seed: int | None = None, options: dict[str, Any] | None = None) -> None:
        """Rack (or set up ``options``' table) and select the breaker. ``seed`` seeds the game env's np_random
        (rack order, first shooter if random, shot noise): the same seed and actions replay bit for bit."""
        _, info = self.game_env.reset(seed=seed, options=self._known_options(options))
        self.agents = self.possible_agents[:]
        self.rewards = {a: 0.0 for a in self.agents}
        self._cumulative_rewards = {a: 0.0 for a in self.agents}
        self.terminations = {a: False for a in self.agents}
        self.truncations = {a: False for a in self.agents}
        self.infos = self._infos(info, shot_by=-1)
        self._skip_agent_selection = None
        self.agent_selection = self.possible_agents[self.task.session.shooter]

    def step(self, action: Any) -> None:
        """Play ``action`` as the shot of ``agent_selection`` (or remove it if its game is over: action None)."""
        if not self.agents:
            raise gym.error.ResetNeeded("step() after the game ended and both agents stepped None; call reset()")
        agent = self.agent_selection
        if self.terminations[agent] or self.truncations[agent]:
            self._was_dead_step(action)
            return
        if action is None:
            raise ValueError(f"action: None is only for an agent whose game is over; {agent} is to shoot: give an "
                             f"action of env.action_space({agent!r})")
        player = self.agent_index[agent]
        if self.task.session.shooter != player:  # pragma: no cover - agent_selection always follows the state
            raise RuntimeError(f"{agent} selected but player {self.task.session.shooter} is to shoot")
        self._cumulative_rewards[agent] = 0.0
        _, _, terminated, truncated, info = self.game_env.step(action)
        verdict = self.task.verdict
        assert verdict is not None
        self.rewards = {a: self.task.reward_of(verdict, k) for a, k in self.agent_index.items()}
        if terminated or truncated:
            self.terminations = {a: bool(terminated) for a in self.agents}
            self.truncations = {a: bool(truncated) for a in self.agents}
        self.infos = self._infos(info, shot_by=player)
        self.agent_selection = self.possible_agents[self.task.session.shooter]
        self._accumulate_rewards()

    def render(self) -> np.ndarray | list[np.ndarray] | None:
        """As the single-agent env's ``render`` (``rgb_array``: the table now; ``rgb_array_list``: the frames of
        both players' shots since the last call; ``human``: the window)."""
        return self.game_env.render()

    def close(self) -> None:
        self.game_env.close()

    # --- the game -------------------------------------------------------------------------------------------------
    @property
    def game_state(self) -> Any:
        """The rules' state (its shooter, and the game's own fields: 9-ball's ball in hand, snooker's score...)."""
        return self.task.game_state

    @property
    def game_over(self) -> bool:
        return self.task.session.game_over

    @property
    def winner(self) -> str | None:
        """The agent who won the game, or None (it goes on, was drawn, or was truncated)."""
        w = self.task.session.winner
        return None if w is None else self.possible_agents[w]

    # --- helpers --------------------------------------------------------------------------------------------------
    def _known_options(self, options: dict[str, Any] | None) -> dict[str, Any] | None:
        """``options`` without the keys the game does not read (each named in a warning)."""
        if not options:
            return None
        known = {"positions", "pocketed", *self.task.option_keys}
        unknown = sorted(str(k) for k in options if k not in known)
        if unknown:
            warnings.warn(f"reset options: unknown key(s) {unknown} ignored; the game reads {sorted(known)}",
                          UserWarning, stacklevel=3)
        kept = {k: v for k, v in options.items() if k in known}
        return kept or None

    def _infos(self, info: dict[str, Any], shot_by: int) -> dict[str, dict[str, Any]]:
        common = {k: v for k, v in info.items() if k not in _SINGLE_AGENT_KEYS}
        s = self.task.session
        return {a: {**{k_: v.copy() if isinstance(v, np.ndarray) else v for k_, v in common.items()},
                    "player": np.int64(k), "shot_by": np.int64(shot_by),
                    "is_success": single(np.bool_, s.game_over and s.winner == k)}
                for a, k in self.agent_index.items()}


def _max_cycles(max_cycles: Any, max_shots: Any) -> int:
    """``max_cycles`` checked (an int >= 1, agreeing with ``max_shots`` if that is given too)."""
    if isinstance(max_cycles, bool) or not isinstance(max_cycles, (int, np.integer)) or max_cycles < 1:
        raise ConfigError(f"max_cycles: expected an int >= 1 (shots before the game is truncated), got {max_cycles!r}")
    if max_shots is not None and max_shots != max_cycles:
        raise ConfigError(f"max_cycles={max_cycles} and max_shots={max_shots}: both are the shot limit; give one")
    return int(max_cycles)


def wrap(env: BilliardsGameAEC) -> AECEnv:
    """``env`` in PettingZoo's standard wrappers that fit a continuous-action turn-based game: the
    ``OrderEnforcingWrapper`` (errors for calls before ``reset``). Not the others: there is no action mask to
    terminate illegal moves on, and out-of-box actions are already clipped by the env (``ClipOutOfBoundsWrapper``
    would also warn on float64 actions and refuse the ``(1, n)`` batches the env accepts)."""
    return wrappers.OrderEnforcingWrapper(env)


def game_module(game_class: type[BilliardsEnv], name: str, module: str, doc: str
                ) -> tuple[type[BilliardsGameAEC], Callable[..., AECEnv], Callable[..., ParallelEnv]]:
    """The three names a PettingZoo env module exports for a game: ``raw_env`` (the :class:`BilliardsGameAEC` of
    ``game_class``, its ``metadata["name"]`` = ``name``), ``env(render_mode=None, config=None, max_cycles=None,
    **overrides)`` (``raw_env`` in :func:`wrap`) and ``parallel_env(same)`` (``env`` in
    :class:`~billiards_env.multi.parallel.BilliardsParallelEnv`). ``module`` is the exporting module's
    ``__name__``, so they pickle by name."""
    from .parallel import BilliardsParallelEnv  # parallel.py builds on this module
    raw = type("raw_env", (BilliardsGameAEC,), {
        "__doc__": doc, "__module__": module, "__qualname__": "raw_env", "game_class": game_class,
        "metadata": {**BilliardsGameAEC.metadata, "name": name}})

    def env(render_mode: str | None = None, config: Any = None, max_cycles: int | None = None,
            **overrides: Any) -> AECEnv:
        return wrap(raw(render_mode=render_mode, config=config, max_cycles=max_cycles, **overrides))

    def parallel_env(render_mode: str | None = None, config: Any = None, max_cycles: int | None = None,
                     **overrides: Any) -> ParallelEnv:
        return BilliardsParallelEnv(env(render_mode=render_mode, config=config, max_cycles=max_cycles, **overrides))

    env.__module__, env.__qualname__ = module, "env"
    env.__doc__ = (f"``{name}``'s :class:`raw_env` in PettingZoo's ``OrderEnforcingWrapper`` "
                   "(see :func:`billiards_env.multi.aec.wrap`).")
    parallel_env.__module__, parallel_env.__qualname__ = module, "parallel_env"
    parallel_env.__doc__ = (f"``{name}`` on PettingZoo's parallel API: both agents act every step, the action of "
                            "the one not to shoot is ignored (see "
                            ":class:`billiards_env.multi.parallel.BilliardsParallelEnv`).")
    return raw, env, parallel_env


__all__ = ["AGENTS", "BilliardsGameAEC", "game_module", "wrap"]
