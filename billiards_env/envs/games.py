"""Games as tasks: 9-ball and 8-ball under :mod:`billiards_env.rules`, against an opponent or alone.

A :class:`GameTask` keeps the :class:`~billiards_env.rules.GameState`, judges every shot with the ruleset
(:class:`~billiards_env.rules.NineBall` / :class:`~billiards_env.rules.EightBall`), puts respotted balls back
(:func:`~billiards_env.physics.layout.spot_object_ball`), and when the turn passes lets the opponent policy shoot
until it is the agent's turn again or the game is over: one ``env.step`` is one shot of the agent plus the
opponent's reply. With ``opponent=None`` the agent plays alone and the episode ends at its first foul or miss
(run-out practice). In two-player mode (:mod:`billiards_env.multi`) nobody plays automatically.

Reward (the agent's): ``+win_reward`` for a won game, ``-loss_penalty`` for a lost one; shaping (off by default):
``+pot_reward`` per ball the agent pockets on a legal shot that counts for it, ``-foul_penalty`` per foul, and
``+position_reward`` times the chance of potting the next shot after a shot that keeps the turn (position play:
:func:`billiards_env.envs.candidates.next_shot_ease`).
"""
from __future__ import annotations

import contextlib
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any, Callable, Iterator

import numpy as np

from billiards_env.physics.aim import aim_angle
from billiards_env.physics.layout import (DIAMOND_ORDER, RACK_ORDER, head_string_x, spot_cue_ball,
                                          spot_object_ball)
from billiards_env.rules import (ANYWHERE, EIGHT_BALL, KITCHEN, NINE_BALL, SOLIDS, STRIPES, EightBall,
                                 EightBallOptions, GameState, NineBall, NineBallOptions, Ruleset, ShotInfo,
                                 ball_numbers, summarize_arrays)
from billiards_env.rules.state import Call

from .actions import AbsoluteAim, CueShot
from .game_hud import Score, game_hud
from .tasks import ShotOutcome, Task

if TYPE_CHECKING:  # pragma: no cover
    from .base import BilliardsEnv

#: Shots one turn of the opponent may take before the env stops it (a run-out of 15 balls needs 16).
MAX_TURN_SHOTS = 60
#: Racks drawn at most at reset when the opponent breaks and wins before the agent shoots.
MAX_RERACKS = 20
N_FEATURES = 11


@dataclass(frozen=True)
class GameSpec:
    """What defines a game for the env: its ruleset, its options and its object balls."""

    name: str
    n_balls: int
    ruleset: type[Ruleset]
    options_type: type
    env_option_defaults: dict[str, Any]

    def options(self, overrides: dict[str, Any]) -> Any:
        """The ruleset options: the env's defaults, then ``overrides`` (checked by the options class)."""
        return self.options_type(**{**self.env_option_defaults, **dict(overrides)})


GAMES = {
    NINE_BALL: GameSpec(NINE_BALL, 9, NineBall, NineBallOptions, {"push_out": False}),
    EIGHT_BALL: GameSpec(EIGHT_BALL, 15, EightBall, EightBallOptions, {}),
}


def game_spec(name: str) -> GameSpec:
    return GAMES[name]


class GameTask(Task):
    """A game under its rules (see the module docstring). The agent is player 0."""

    has_ball_in_hand = True
    option_keys = ("ball_in_hand", "groups", "break_shot")

    def __init__(self, env: "BilliardsEnv") -> None:
        super().__init__(env)
        c = env.config
        self.spec = game_spec(c.task)
        self.rules: Ruleset = self.spec.ruleset(self.spec.options(c.rules))
        opts = self.rules.options
        self.declarations = (("pocket",) if self.spec.name == EIGHT_BALL and opts.call_eight else ()) + \
            (("push",) if self.spec.name == NINE_BALL and opts.push_out else ())
        self.numbers = ball_numbers(env.ball_ids)
        self.row_of = {int(n): i for i, n in enumerate(self.numbers.tolist())}
        self.agent = 0
        #: Whether the opponent's turns are played inside ``step`` (single-agent mode).
        self.auto_opponent = True
        self.opponent: Any = None
        if c.opponent is not None:
            from billiards_env.players import make_player

            self.opponent = make_player(c.opponent, seed=0)
        self.state: GameState = self.rules.initial_state()
        self.last_call: Call | None = None
        #: Games won over the env's life and balls pocketed per player in this game (the HUD's score).
        self.score = Score()
        #: The players' names in the HUD (None: "agent" and the opponent's name).
        self.player_names: tuple[str, str] | None = None
        self._shot: Any = None
        self._viewer: int | None = None  # see seen_by()
        self._rack_slots: np.ndarray | None = None
        self._exact_type: Any = None  # see _acting_type()
        self._ease = 0.0  # the next shot's ease after the last call (position_reward)

    # --- configuration -------------------------------------------------------------------------------------------
    def set_opponent(self, policy: Any) -> None:
        """The opponent's policy: a player (``act(env, obs)``), an SB3-style model (``predict``), a callable
        ``obs -> action``, or None (play alone). Models and callables act in the env's action type; a player acts
        in it too unless it is one that cannot express every shot (``candidates``): then the player's actions are
        read in the absolute type with the same dims (:meth:`_acting_type`)."""
        self.opponent = policy

    # --- episode ---------------------------------------------------------------------------------------------
    def reset(self, env: "BilliardsEnv", options: dict[str, Any] | None) -> dict[str, Any]:
        rng = env.np_random
        if self.opponent is not None and hasattr(self.opponent, "reset"):
            self.opponent.reset(int(rng.integers(2**31)))
        opts = options or {}
        self.last_call = None
        self.score.new_game()
        if "positions" in opts:
            on = tuple(n for n in self._numbers_on(env) if n)
            self.state = GameState(self.spec.name, on, shooter=self.agent,
                                   ball_in_hand=opts.get("ball_in_hand", False), groups=opts.get("groups"),
                                   break_shot=bool(opts.get("break_shot", False)))
            return self._info(env, None, 0)
        for _ in range(MAX_RERACKS):
            self._shuffle_rack(env, rng)
            first = {"agent": self.agent, "opponent": 1 - self.agent}.get(self.config.first_shooter)
            if first is None:
                first = int(rng.integers(2))
            if first != self.agent and self.opponent is None and self.auto_opponent:
                first = self.agent  # alone: the agent breaks
            self.state = self.rules.initial_state(first_shooter=first)
            opening = self.config.opening
            if opening == "either":
                opening = "ball_in_hand" if rng.integers(2) else "break"
            if opening == "ball_in_hand":
                self._open_with_ball_in_hand(env, first)
            if first == self.agent or not self.auto_opponent or self.opponent is None:
                return self._info(env, None, 0)
            n = self._opponent_turn(env)
            if not self.state.game_over:
                return self._info(env, None, n)
            env.balls.on_table.fill(True)  # the opponent won from the break: rack again
            self.score.new_game()
            env.balls.vel.fill(0.0)
        raise RuntimeError("the opponent won every game before the agent's first shot")  # pragma: no cover

    def _open_with_ball_in_hand(self, env: "BilliardsEnv", first: int) -> None:
        """The ``ball_in_hand`` opening: a break played by the env (full speed from where the cue ball stands, the
        head spot, at the nearest legal ball, with the env's shot noise), the game's last ball (9-ball: the 9,
        8-ball: the 8) respotted if it dropped, the others left down, and ``first`` to shoot with the cue ball in
        hand anywhere on an open table."""
        b = env.balls
        rows = [self.row_of[n] for n in self.rules.legal_targets(self.state)]
        cue = b.pos[0]
        target = min(rows, key=lambda j: float(np.hypot(*(b.pos[j] - cue))))
        env.play_shot(CueShot(aim_angle(cue, b.pos[target]), float(env.config.speed_max)))
        env.last_shot, env.last_tip = None, (0.0, 0.0)  # nobody's shot: not drawn
        last = self.row_of[9 if self.spec.name == NINE_BALL else 8]
        r = env.config.ball_radius
        if not b.on_table[last]:
            spot_object_ball(b.pos, b.on_table, r, env.table, last)
        if not b.on_table[0]:
            spot_cue_ball(b.pos, b.on_table, r, env.table)
        self.state = GameState(self.spec.name, tuple(n for n in self._numbers_on(env) if n), shooter=first,
                               ball_in_hand=ANYWHERE, groups=None, break_shot=False)

    def _numbers_on(self, env: "BilliardsEnv") -> tuple[int, ...]:
        on = env.balls.on_table
        return tuple(int(n) for i, n in enumerate(self.numbers.tolist()) if on[i])

    def _shuffle_rack(self, env: "BilliardsEnv", rng: np.random.Generator) -> None:
        """Order the rack as the rules say, drawing the free slots from ``rng``: 9-ball: the 1 at the apex, the 9
        in the middle; 8-ball: the 8 in the middle of the third row, a solid and a stripe in the back corners."""
        if env.config.placement not in ("rack", "diamond"):
            return
        pos = env.balls.pos
        if self._rack_slots is None:
            order = DIAMOND_ORDER if env.config.placement == "diamond" else RACK_ORDER
            self._rack_slots = np.array([pos[self.row_of[n]] for n in order])
        slots = self._rack_slots
        if self.spec.name == NINE_BALL:
            fixed = {0: 1, 4: 9}
            free = [n for n in range(2, 9)]
        else:
            corner_solid = int(rng.integers(2))
            solid = int(rng.choice(np.arange(1, 8)))
            stripe = int(rng.choice(np.arange(9, 16)))
            fixed = {4: 8, 10: solid if corner_solid else stripe, 14: stripe if corner_solid else solid}
            free = [n for n in range(1, 16) if n not in fixed.values()]
        free = [free[k] for k in rng.permutation(len(free))]
        it = iter(free)
        for slot in range(len(slots)):
            number = fixed.get(slot)
            if number is None:
                number = next(it)
            pos[self.row_of[number]] = slots[slot]

    # --- what the shooter sees and may do --------------------------------------------------------------------
    def legal_rows(self) -> list[int]:
        """Rows of the balls the shooter may hit first."""
        return [self.row_of[n] for n in self.rules.legal_targets(self.state)]

    def target_ball(self, env: "BilliardsEnv") -> int | None:
        rows = self.legal_rows()
        return min(rows) if rows else None

    def is_break(self, env: "BilliardsEnv") -> bool:
        return bool(self.state.break_shot and not self.state.game_over)

    def ball_in_hand_area(self, env: "BilliardsEnv") -> tuple[float, float, float, float] | None:
        bih = self.state.ball_in_hand
        if not bih or self.state.game_over:
            return None
        r = env.config.ball_radius
        x1 = head_string_x(env.table) if bih == KITCHEN else env.table.length - r
        return r, x1, r, env.table.width - r

    def needs_called_pocket(self) -> bool:
        return isinstance(self.rules, EightBall) and self.rules.needs_called_pocket(self.state)

    def feature_bounds(self, env: "BilliardsEnv") -> tuple[np.ndarray, np.ndarray]:
        return np.zeros(N_FEATURES, np.float32), np.ones(N_FEATURES, np.float32)

    def features(self, env: "BilliardsEnv", player: int | None = None) -> np.ndarray:
        """The game seen by ``player`` (default: the player of :meth:`seen_by`, else the shooter): ball in hand
        (anywhere/kitchen), break shot, its lowest legal target / 15, own group (solids, stripes), on the 8, own and
        opponent's fouls in a row / 2, push-out available, and whether it is this player's turn."""
        s = self.state
        me = player if player is not None else (s.shooter if self._viewer is None else self._viewer)
        out = np.zeros(N_FEATURES, np.float32)
        mine = s.shooter == me and not s.game_over
        out[0] = 1.0 if (mine and s.ball_in_hand) else 0.0
        out[1] = 1.0 if (mine and s.ball_in_hand == KITCHEN) else 0.0
        out[2] = 1.0 if s.break_shot else 0.0
        # The viewer's own targets (8-ball: its group) also when it is not its turn (the two-player env).
        targets = self.rules.legal_targets(s if me == s.shooter else replace(s, shooter=me)) \
            if not s.game_over else ()
        out[3] = targets[0] / 15.0 if targets else 0.0
        if s.groups is not None:
            out[4] = 1.0 if s.groups[me] == SOLIDS else 0.0
            out[5] = 1.0 if s.groups[me] == STRIPES else 0.0
        out[6] = 1.0 if (s.game == EIGHT_BALL and targets == (8,)) else 0.0
        out[7] = min(s.fouls_in_a_row[me] / 2.0, 1.0)
        out[8] = min(s.fouls_in_a_row[1 - me] / 2.0, 1.0)
        out[9] = 1.0 if s.push_out_available else 0.0
        out[10] = 1.0 if mine else 0.0
        return out

    @contextlib.contextmanager
    def seen_by(self, player: int) -> Iterator[None]:
        """Within the block :meth:`features` (so the env's observation) takes ``player``'s point of view instead of
        the shooter's: how the two-player env (:mod:`billiards_env.multi`) observes each agent."""
        if player not in (0, 1):
            raise ValueError(f"player: must be 0 or 1, got {player!r}")
        saved, self._viewer = self._viewer, player
        try:
            yield
        finally:
            self._viewer = saved

    def hud(self, env: "BilliardsEnv") -> dict[str, Any]:
        """What the game shows on screen: players, whose turn, groups, ball in hand, the last call, the score, the
        target (:func:`~billiards_env.envs.game_hud.game_hud`)."""
        return game_hud(self, env)

    # --- shots ----------------------------------------------------------------------------------------------------
    def before_shot(self, env: "BilliardsEnv", shot: "CueShot") -> None:
        self._shot = shot

    def judge(self, env: "BilliardsEnv", outcome: ShotOutcome) -> Call:
        """Call the shot just played (from ``self.state``), apply the call to the table and the state."""
        s = self.state
        shot = self._shot
        summary = summarize_arrays(outcome.events, outcome.pocket, self.numbers)
        push = bool(shot is not None and shot.push and s.push_out_available)
        pocket = shot.pocket if (shot is not None and self.needs_called_pocket()) else None
        call, self.state = self.rules.play(s, summary, ShotInfo(push_out=push, called_pocket=pocket))
        b = env.balls
        r = env.config.ball_radius
        for n in call.respot:
            spot_object_ball(b.pos, b.on_table, r, env.table, self.row_of[n])
        if not b.on_table[0]:
            spot_cue_ball(b.pos, b.on_table, r, env.table)  # in hand for the next shooter
        self.last_call = call
        self.score.record(call)
        self._shot = None
        self._ease = 0.0
        if self.config.position_reward and not call.game_over and not call.turn_over and \
                (call.shooter == self.agent or not self.auto_opponent):
            from .candidates import next_shot_ease

            self._ease = next_shot_ease(env)
        return call

    def on_shot(self, env: "BilliardsEnv", outcome: ShotOutcome) -> tuple[float, bool, bool, dict[str, Any]]:
        c = self.config
        call = self.judge(env, outcome)
        reward = self._shaping(call, self.agent)
        n_opp = 0
        practice_over = False
        if not self.state.game_over and self.state.shooter != self.agent and self.auto_opponent:
            if self.opponent is None:
                practice_over = True
            else:
                n_opp = self._opponent_turn(env)
        s = self.state
        if s.game_over:
            reward += self._result_reward(s.winner, self.agent)
        terminated = bool(s.game_over or practice_over)
        truncated = bool(not terminated and env.shots >= c.max_shots)
        return float(reward), terminated, truncated, self._info(env, call, n_opp)

    def reward_of(self, call: Call, player: int) -> float:
        """``player``'s reward for the one shot judged by ``call`` (whoever shot it): the shaping of its own shot,
        plus the win/loss reward if the shot ended the game. The two-player env gives each player its own."""
        r = self._shaping(call, player)
        if call.game_over:
            r += self._result_reward(call.winner, player)
        return float(r)

    def _result_reward(self, winner: int | None, player: int) -> float:
        c = self.config
        return c.win_reward if winner == player else -c.loss_penalty

    def _shaping(self, call: Call, player: int) -> float:
        c = self.config
        r = 0.0
        if call.shooter != player:
            return r
        if call.foul:
            r -= c.foul_penalty
        elif c.pot_reward:
            counted = [n for n in call.pocketed if n not in call.respot]
            r += c.pot_reward * len(counted)
        if c.position_reward and call is self.last_call:
            r += c.position_reward * self._ease
        return r

    def _acting_type(self, env: "BilliardsEnv") -> Any:
        """The action type the opponent acts in: the env's, except that a player (``act``: it aims shots of its own
        and turns them into actions with ``action_from_shot``) facing an agent whose type cannot express every shot
        (``candidates``) acts through the absolute type with the same dims, so it plays the shots it chose."""
        at = env.action_type
        if at.exact_inverse or not hasattr(self.opponent, "act"):
            return at
        if self._exact_type is None:
            self._exact_type = AbsoluteAim(env.config, at.placement, at.declarations, at.n_pockets)
        return self._exact_type

    def _opponent_turn(self, env: "BilliardsEnv") -> int:
        """Let the opponent shoot until the agent's turn or the end of the game; the number of shots."""
        policy = as_policy(self.opponent)
        acting = self._acting_type(env)
        n = 0
        while not self.state.game_over and self.state.shooter != self.agent and n < MAX_TURN_SHOTS:
            obs = env.observation_type.observe(env)
            if acting is env.action_type:
                action = policy(env, obs)
            else:
                saved = env.action_type, env.action_space
                env.action_type, env.action_space = acting, acting.space
                try:
                    action = policy(env, obs)
                finally:
                    env.action_type, env.action_space = saved
            shot = acting.shot(env, action)
            if shot.place is not None:
                env.balls.pos[0] = shot.place
            self.before_shot(env, shot)
            outcome, trajectory, _ = env.play_shot(shot)
            env.queue_animation(trajectory)
            self.judge(env, outcome)
            n += 1
        if not self.state.game_over and self.state.shooter != self.agent:  # pragma: no cover - a stuck opponent
            self.state = GameState(self.state.game, self.state.on_table, shooter=self.agent, ball_in_hand=ANYWHERE,
                                   groups=self.state.groups, break_shot=False)
        return n

    def _info(self, env: "BilliardsEnv", call: Call | None, opponent_shots: int) -> dict[str, Any]:
        s = self.state
        agent_call = call
        info: dict[str, Any] = {
            "foul": bool(agent_call.foul) if agent_call is not None else False,
            "foul_reason": agent_call.reason if (agent_call is not None and agent_call.foul) else None,
            "turn_over": bool(agent_call.turn_over) if agent_call is not None else False,
            "ball_in_hand": s.ball_in_hand if not s.game_over else False,
            "winner": -1 if s.winner is None else s.winner,  # an int always (vector envs stack info values)
            "is_success": bool(s.game_over and s.winner == self.agent),
            "opponent_shots": opponent_shots,
            "shooter": s.shooter,
            "groups": s.groups,
            "legal_targets": self.rules.legal_targets(s) if not s.game_over else (),
        }
        if call is not None:
            info["call"] = call.reason
        return info


def as_policy(policy: Any) -> Callable[[Any, Any], np.ndarray]:
    """``(env, obs) -> action`` from a player (``act(env, obs)``), an SB3-style model (``predict``, deterministic)
    or a callable ``obs -> action``; ``env`` is the single-agent env (players read its balls, table and task)."""
    if hasattr(policy, "act"):
        return policy.act
    if hasattr(policy, "predict"):
        return lambda env, obs: policy.predict(obs, deterministic=True)[0]
    if callable(policy):
        return lambda env, obs: policy(obs)
    raise TypeError(f"opponent: expected a player (act), a model (predict) or a callable, got {type(policy).__name__}")


class NineBallTask(GameTask):
    """9-ball (see :class:`GameTask`)."""

    name = NINE_BALL


class EightBallTask(GameTask):
    """8-ball (see :class:`GameTask`)."""

    name = EIGHT_BALL


__all__ = ["GameSpec", "GAMES", "game_spec", "GameTask", "NineBallTask", "EightBallTask", "MAX_TURN_SHOTS",
           "as_policy"]
