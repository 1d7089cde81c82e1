"""Games as tasks: a registered game (:data:`billiards_env.games.GAMES`: 9-ball, 8-ball) against an opponent or
alone.

A :class:`GameTask` runs a :class:`~billiards_env.games.session.GameSession` on the env's table state (the rules'
state, the calls, the respots, the score), and when the turn passes it lets the opponent shoot until it is the
agent's turn again or the game is over (the :class:`~billiards_env.envs.opponent.Opponent` its env gives it plays the
opponent's shots on the table state; :class:`~billiards_env.envs.opponent.Seat` says who sits where): one ``env.step`` is one shot of the agent plus the opponent's reply
(``info["opponent_shots"]``, ``opponent_pocketed`` and ``opponent_fouls`` sum it up; with ``opponent_infos=True``
``info["opponent_turns"]`` describes each of its shots). With ``opponent=None`` the agent plays alone and the
episode ends at its first foul or miss (run-out practice). In two-player mode (:mod:`billiards_env.multi`) nobody
plays automatically.

Reward (the agent's): ``+win_reward`` for a won game, ``-loss_penalty`` for a lost one; shaping (off by default):
``+pot_reward`` per ball the agent pockets on a legal shot that counts for it, ``-foul_penalty`` per foul, and
``+position_reward`` times the chance of potting the next shot after a shot that keeps the turn (position play:
:func:`billiards_env.envs.candidates.next_shot_ease`).
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable

import numpy as np

from billiards_env.games import GameSpec, game_spec
from billiards_env.games.infos import code_of, mask_of
from billiards_env.games.session import GameSession, Verdict
from billiards_env.physics.aim import aim_angle
from billiards_env.shot_path import CueShot, PlayedShot
from billiards_env.table_state import TableState

from .candidates import next_shot_ease
from .info import OPPONENT_TURNS
from .opponent import Opponent, Seat, policy_form
from .tasks import Driver, PotTask, Task

if TYPE_CHECKING:  # pragma: no cover
    from .config import EnvConfig

#: Shots one turn of the opponent may take (at least; max_shots if larger) before the env raises (a run-out of 15 balls
#: needs 16).
MAX_TURN_SHOTS = 60
#: Racks drawn at most at reset when the opponent breaks and wins before the agent shoots.
MAX_RERACKS = 20


class GameTask(Task):
    """A game under its rules (see the module docstring). The agent is player 0."""

    has_ball_in_hand = True

    def __init__(self, config: "EnvConfig", state: TableState, spec: GameSpec) -> None:
        super().__init__(config, state)
        self.spec = spec
        self.name = spec.name
        self.session: GameSession = spec.session_class(spec, config.rules, state)
        state.attach_game(self.session, self.session.view)
        self.declarations = self.session.declarations
        self.has_ball_in_hand = self.session.ball_in_hand
        self.n_features = self.session.n_features
        self.option_keys = self.session.option_keys
        #: Who sits where: the agent's player, and whether the opponent's turns are played inside ``step``.
        self.seat = Seat()
        #: What plays the opponent's shots (given by the env once its action and observation types are made).
        self.opponent_player: Opponent | None = None
        #: The players' names in the HUD (None: "agent" and the opponent's name).
        self.player_names: tuple[str, str] | None = None
        self._ease = 0.0  # the next shot's ease after the last call (position_reward)

    # --- the game, for readers ------------------------------------------------------------------------------------
    @property
    def game_state(self) -> Any:
        """The rules' state (shooter, game over, winner, and the game's own fields); setting it continues the game
        from there (a situation set up by hand)."""
        return self.session.game_state

    @game_state.setter
    def game_state(self, value: Any) -> None:
        self.session.set_state(value)

    @property
    def rules(self) -> Any:
        return self.session.rules

    @property
    def last_call(self) -> Any:
        """The ruleset's call on the last shot (its own fields; :attr:`verdict` sums it up alike for every game)."""
        return self.session.last_call

    @property
    def verdict(self) -> Verdict | None:
        return self.session.verdict

    @property
    def score(self) -> Any:
        return self.session.score

    @property
    def agent(self) -> int:
        """The player the agent plays (the seat's)."""
        return self.seat.agent

    @property
    def auto_opponent(self) -> bool:
        """Whether the opponent's turns are played inside ``step`` (the seat's; off in two-player mode)."""
        return self.seat.auto

    @auto_opponent.setter
    def auto_opponent(self, value: bool) -> None:
        self.seat.auto = bool(value)

    # --- configuration -------------------------------------------------------------------------------------------
    def take_opponent(self, opponent: Opponent) -> None:
        """Play against ``opponent`` (:class:`~billiards_env.envs.opponent.Opponent`: its policy plays the
        opponent's shots on the table state it is given)."""
        self.opponent_player = opponent

    @property
    def opponent(self) -> Any:
        """The opponent's policy, or None (the agent plays alone)."""
        return None if self.opponent_player is None else self.opponent_player.policy

    def set_opponent(self, policy: Any) -> None:
        """The opponent's policy: a player (``shot(state, obs, codec) -> CueShot`` on a table state and the action
        type to play in, as the players of :mod:`billiards_env.players`), a policy on the table state
        (``act(state, obs, codec)``), an SB3-style model (``predict``), a callable ``obs -> action``, or None (play
        alone). A name (``"geometric"``, ``"search"``, ``"random"``) makes that player of this game. Anything else,
        and the old form ``act(env, obs)``, raises ``TypeError`` now, not at the next step
        (:meth:`~billiards_env.envs.opponent.Opponent.set_policy`)."""
        if self.opponent_player is None:
            raise RuntimeError("set_opponent: this task has no opponent seat yet; its env gives it one when made")
        self.opponent_player.set_policy(policy)

    # --- episode ---------------------------------------------------------------------------------------------
    def reset(self, state: TableState, rng: np.random.Generator, options: dict[str, Any] | None,
              driver: Driver) -> dict[str, Any]:
        if self.opponent_player is not None:
            self.opponent_player.reset(rng)
        s = self.session
        opts = options or {}
        given = [k for k in self.option_keys if k in opts]
        if given and "positions" not in opts:
            raise ValueError(f"reset options: {', '.join(map(repr, given))} set up a table by hand and need "
                             "'positions' ((N, 2) metres) too; without positions the game racks as usual")
        s.last_call = None
        s.verdict = None
        s.score.new_game()
        if "positions" in opts:
            s.setup(opts, self.agent)
            return self._info(None, [])
        for _ in range(MAX_RERACKS):
            s.new_game(rng, self.config.placement)
            first = {"agent": self.agent, "opponent": 1 - self.agent}.get(self.config.first_shooter)
            if first is None:
                first = int(rng.integers(2))
            if first != self.agent and self.opponent is None and self.auto_opponent:
                first = self.agent  # alone: the agent breaks
            s.start(first)
            opening = self.config.opening
            if opening == "either":
                opening = "ball_in_hand" if rng.integers(2) else "break"
            if opening == "ball_in_hand":
                self._open_with_ball_in_hand(state, first, driver)
            if first == self.agent or not self.auto_opponent or self.opponent is None:
                return self._info(None, [])
            turns = self._opponent_turn(driver)
            if not s.game_over:
                return self._info(None, turns)
            state.balls.on_table.fill(True)  # the opponent won from the break: rack again
            state.balls.vel.fill(0.0)
            state.changed()
            s.score.new_game()
        raise RuntimeError("the opponent won every game before the agent's first shot")  # pragma: no cover

    def _open_with_ball_in_hand(self, state: TableState, first: int, driver: Driver) -> None:
        """The ``ball_in_hand`` opening (pool games): a break played by the env (full speed from where the cue ball
        stands, the head spot, at the nearest legal ball, with the env's shot noise), then the session's opening
        (the game's last ball respotted, ``first`` to shoot with the cue ball in hand anywhere)."""
        s = self.session
        b = state.balls
        rows = s.legal_rows()
        cue = b.pos[0]
        target = min(rows, key=lambda j: float(np.hypot(*(b.pos[j] - cue))))
        driver.play(CueShot(aim_angle(cue, b.pos[target]), float(self.config.speed_max)), "table")
        s.open_with_ball_in_hand(first)

    # --- shots ----------------------------------------------------------------------------------------------------
    def before_shot(self, shot: CueShot) -> None:
        self.session.begin_shot(shot)

    def _judge(self, state: TableState, played: PlayedShot) -> Verdict:
        """Call a shot just played and apply the call (the session); note the next shot's ease for shaping.
        Compiled twin (with :meth:`_shaping`, the native vector env's pool tables): ``_game_kernels._step_table``."""
        v = self.session.judge(played.outcome)
        self._ease = 0.0
        if self.config.position_reward and not v.game_over and not v.turn_over and \
                (v.shooter == self.agent or not self.auto_opponent):
            self._ease = next_shot_ease(state, self.config.candidate_slots)
        return v

    def on_shot(self, state: TableState, played: PlayedShot, shots: int, driver: Driver
                ) -> tuple[float, bool, bool, dict[str, Any]]:
        c = self.config
        v = self._judge(state, played)
        reward = self._shaping(v, self.agent)
        turns: list[dict[str, Any]] = []
        practice_over = False
        s = self.session
        if not s.game_over and s.shooter != self.agent and self.auto_opponent:
            if self.opponent is None:
                practice_over = True
            else:
                turns = self._opponent_turn(driver)
        if s.game_over:
            reward += self._result_reward(s.winner, self.agent)
        terminated = bool(s.game_over or practice_over)
        truncated = bool(not terminated and shots >= c.max_shots)
        return float(reward), terminated, truncated, self._info(v, turns)

    def reward_of(self, verdict: Verdict, player: int) -> float:
        """``player``'s reward for the one shot judged ``verdict`` (whoever shot it): the shaping of its own shot,
        plus the win/loss reward if the shot ended the game. The two-player env gives each player its own."""
        r = self._shaping(verdict, player)
        if verdict.game_over:
            r += self._result_reward(verdict.winner, player)
        return float(r)

    def _result_reward(self, winner: int | None, player: int) -> float:
        c = self.config
        return c.win_reward if winner == player else -c.loss_penalty

    def _shaping(self, v: Verdict, player: int) -> float:
        c = self.config
        r = 0.0
        if v.shooter != player:
            return r
        if v.foul:
            r -= c.foul_penalty
        elif c.pot_reward:
            r += c.pot_reward * v.scored
        if c.position_reward and v is self.session.verdict:
            r += c.position_reward * self._ease
        return r

    def _opponent_turn(self, driver: Driver) -> list[dict[str, Any]]:
        """Let the opponent shoot until the agent's turn or the end of the game; one dict per shot. Compiled twin
        (the geometric opponent on the native vector env's pool tables): ``_game_kernels._opponent_turn``."""
        s = self.session
        turns: list[dict[str, Any]] = []
        cap = max(MAX_TURN_SHOTS, self.config.max_shots)
        while not s.game_over and s.shooter != self.agent and len(turns) < cap:
            shot = self.opponent_player.shot(s.table)
            self.before_shot(shot)
            played = driver.play(shot, "opponent")
            turns.append(self._turn_info(self._judge(s.table, played), played))
        if not s.game_over and s.shooter != self.agent:  # pragma: no cover - a stuck opponent
            raise RuntimeError(f"the opponent took {cap} shots in one turn without the game ending or the turn "
                               "passing; raise max_shots if its game allows longer turns")
        return turns

    def _turn_info(self, v: Verdict, played: PlayedShot) -> dict[str, Any]:
        """What one opponent shot did (an entry of the opponent's turns, in the info's forms: ``pocketed`` a mask
        over the rows and ``first_contact`` a row as the shot saw them, the reasons as codes)."""
        o = played.outcome
        reasons = self.session.reasons
        return {
            "shooter": int(v.shooter),
            "pocketed": mask_of(o.pocketed, self.session.table.n_balls),
            "scratch": bool(o.scratch),
            "first_contact": int(o.first_contact),
            "foul": bool(v.foul),
            "foul_reason": code_of(reasons, v.reason) if v.foul else -1,
            "call": code_of(reasons, v.reason),
            "turn_over": bool(v.turn_over),
            "angle": float(played.shot.angle),
            "speed": float(played.shot.speed),
            **self.session.call_info(v),
        }

    def _info(self, v: Verdict | None, turns: list[dict[str, Any]]) -> dict[str, Any]:
        """The game's keys of the info (in the schema's order, :func:`~.info.game_keys`) after the agent's shot
        judged ``v`` (None: at reset) and the opponent's ``turns``."""
        s = self.session
        reasons = s.reasons
        n = s.table.n_balls
        info: dict[str, Any] = {
            "is_success": bool(s.game_over and s.winner == self.agent),
            "foul": bool(v.foul) if v is not None else False,
            "foul_reason": code_of(reasons, v.reason) if (v is not None and v.foul) else -1,
            "call": code_of(reasons, v.reason) if v is not None else -1,
            "turn_over": bool(v.turn_over) if v is not None else False,
            "winner": -1 if s.winner is None else int(s.winner),
            "shooter": int(s.shooter),
            "legal_targets": s.legal_mask(),
            "opponent_shots": len(turns),
            "opponent_pocketed": np.logical_or.reduce([t["pocketed"] for t in turns]) if turns
            else np.zeros(n, np.bool_),
            "opponent_fouls": sum(t["foul"] for t in turns),
            **s.call_info(v),
        }
        if self.config.opponent_infos:
            info[OPPONENT_TURNS] = turns
        return info

    # --- what is drawn --------------------------------------------------------------------------------------------
    def names(self) -> tuple[str, str]:
        """The two players' names: ``player_names`` if set; else ``"agent"`` and the opponent policy's ``name``
        (its class name without one; ``"nobody"`` when the agent plays alone), or ``"player 0"``/``"player 1"``
        when nobody plays automatically (two players)."""
        if self.player_names:
            return str(self.player_names[0]), str(self.player_names[1])
        if not self.auto_opponent:
            return "player 0", "player 1"
        return "agent", "nobody" if self.opponent_player is None else self.opponent_player.name()

    def hud(self) -> dict[str, Any]:
        """What the game shows on screen (its session's HUD)."""
        return self.session.hud(self.names())


def as_policy(policy: Any) -> Callable[[TableState, Any, Any], np.ndarray]:
    """``(state, obs, codec) -> action`` (an action of the action type ``codec``) from a player or a policy on the
    table state (``act(state, obs, codec)``; a player with ``shot`` only: its shot in ``codec``), an SB3-style model
    (``predict``, deterministic) or a callable ``obs -> action`` (both acting in ``codec``, the env's type). The
    old form ``act(env, obs)`` raises ``TypeError`` (:func:`~billiards_env.envs.opponent.policy_form`)."""
    form = policy_form(policy)
    if form == "act" or (form == "shot" and hasattr(policy, "act")):
        return lambda state, obs, codec: policy.act(state, obs, codec=codec)
    if form == "shot":
        def from_shot(state: TableState, obs: Any, codec: Any) -> np.ndarray:
            s = policy.shot(state, obs, codec=codec)
            return np.asarray(codec.action(state, s.angle, s.speed, s.side, s.top, s.place, **dict(s.calls)),
                              dtype=np.float32)
        return from_shot
    if form == "predict":
        return lambda state, obs, codec: policy.predict(obs, deterministic=True)[0]
    return lambda state, obs, codec: policy(obs)


def task_factory(config: "EnvConfig", state: TableState) -> Task:
    """The task named by ``config.task``: ``pot`` (:class:`~.tasks.PotTask`), or a registered game
    (:data:`billiards_env.games.GAMES`; :class:`GameTask`)."""
    if config.task == "pot":
        return PotTask(config, state)
    return GameTask(config, state, game_spec(config.task))


__all__ = ["GameTask", "MAX_TURN_SHOTS", "MAX_RERACKS", "as_policy", "task_factory"]
