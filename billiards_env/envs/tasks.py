"""Tasks: what an episode asks of the agent — reward, termination, success and the task's part of ``info``
(panda-gym's Task; the env joins a simulator, an action type, an observation type and a task).

The env simulates a shot and hands the task a :class:`ShotOutcome`; the task scores it. :class:`PotTask` is the
three original scenes (pot one ball, three balls, a rack). Games (9-ball, 8-ball) are tasks with rules
(:mod:`billiards_env.envs.games`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numba import njit

from billiards_env.physics.codes import EV_COLLISION
from billiards_env.physics.layout import spot_cue_ball

if TYPE_CHECKING:  # pragma: no cover
    from .base import BilliardsEnv


@dataclass(frozen=True)
class ShotOutcome:
    """What one simulated shot did (rows index the env's balls; the cue ball is row 0)."""

    status: str  #: "rest", "time_cap" or "event_cap"
    sim_time: float  #: simulated seconds
    n_events: int
    pocket: np.ndarray  #: (N,) pocket index of each ball pocketed by this shot, -1 otherwise
    events: np.ndarray  #: (M, 3) int event log: kind, ball, other
    pocketed: tuple[int, ...]  #: rows pocketed by this shot (the cue ball included)
    scratch: bool  #: the cue ball was pocketed
    first_contact: int  #: row of the first ball the cue ball hit, -1 if none

    @classmethod
    def from_arrays(cls, status: str, sim_time: float, n_events: int, pocket: np.ndarray,
                    events: np.ndarray) -> "ShotOutcome":
        pocketed = tuple(i for i, p in enumerate(pocket.tolist()) if p >= 0)
        return cls(status, float(sim_time), int(n_events), pocket, events, pocketed, bool(pocket[0] >= 0),
                   first_contact(events))


def first_contact(events: np.ndarray, ball: int = 0) -> int:
    """Row of the first ball that ``ball`` collided with in an ``(M, 3)`` event log, or -1."""
    for kind, b, other in events.tolist():
        if kind == EV_COLLISION and (b == ball or other == ball):
            return other if b == ball else b
    return -1


class Task:
    """The part of an env that gives a shot its meaning. Subclasses override the hooks they need."""

    name = "task"
    #: Whether the shooter can get ball in hand (the action then has the placement dims).
    has_ball_in_hand = False
    #: Extra keys of ``reset(options=...)`` the task reads (besides ``positions`` and ``pocketed``).
    option_keys: tuple[str, ...] = ()
    #: Declarations the action carries (``"pocket"``: the 8's called pocket; ``"push"``: a 9-ball push-out).
    declarations: tuple[str, ...] = ()

    def __init__(self, env: "BilliardsEnv") -> None:
        self.config = env.config

    def reset(self, env: "BilliardsEnv", options: dict[str, Any] | None) -> dict[str, Any]:
        """Called after the balls are placed; returns extra ``info`` for ``reset``."""
        return {}

    def target_ball(self, env: "BilliardsEnv") -> int | None:
        """Row of the ball the shooter should hit first (the relative and ghost aim's target), or None."""
        on = env.balls.on_table
        for i in range(1, env.n_balls):
            if on[i]:
                return i
        return None

    def is_break(self, env: "BilliardsEnv") -> bool:
        """Whether the shot to play is a game's opening break (the ``candidates`` action type plays it apart)."""
        return False

    def ball_in_hand_area(self, env: "BilliardsEnv") -> tuple[float, float, float, float] | None:
        """The rectangle ``(x0, x1, y0, y1)`` where the shooter may place the cue ball now, or None (no ball in
        hand)."""
        return None

    def before_shot(self, env: "BilliardsEnv", shot: Any) -> None:
        """Called with the shot (a :class:`~.actions.CueShot`) before it is played (a game reads the declarations)."""

    def feature_bounds(self, env: "BilliardsEnv") -> tuple[np.ndarray, np.ndarray]:
        """Bounds of the task's observation features (none by default)."""
        return np.zeros(0, np.float32), np.zeros(0, np.float32)

    def features(self, env: "BilliardsEnv") -> np.ndarray:
        return np.zeros(0, np.float32)

    def on_shot(self, env: "BilliardsEnv", outcome: ShotOutcome) -> tuple[float, bool, bool, dict[str, Any]]:
        """Score a shot: ``(reward, terminated, truncated, info)``."""
        raise NotImplementedError

    def hud(self, env: "BilliardsEnv") -> dict[str, Any] | None:
        """Plain data for the renderer's game panel (players, whose turn, the last call, the score:
        :mod:`billiards_env.render.hud`), or None: no panel (the frames keep their size)."""
        return None


@njit(cache=True)
def pot_score(n_potted: int, scratch: bool, missed: bool, cleared: bool, shots: int, pot_reward: float,
              step_penalty: float, scratch_penalty: float, miss_penalty: float, single_shot: bool,
              max_shots: int) -> tuple:
    """The pot task's score of a shot: ``(reward, terminated, truncated, success)`` (see :class:`PotTask`).
    Compiled once: the single env calls it, and so does the native vector env."""
    reward = pot_reward * n_potted - step_penalty
    if scratch:
        reward -= scratch_penalty
    if missed:
        reward -= miss_penalty
    terminated = cleared or single_shot
    truncated = (not terminated) and shots >= max_shots
    return reward, terminated, truncated, cleared and not scratch


class PotTask(Task):
    """Pocket the object balls: ``+pot_reward`` per object ball pocketed, ``-scratch_penalty`` for a pocketed cue
    ball (re-spotted on the head spot or the nearest free point of the head string), ``-miss_penalty`` when the
    cue ball hits nothing, ``-step_penalty`` per shot. Terminated when the table is cleared (or after every shot
    with ``single_shot``); truncated after ``max_shots``. Success: the table cleared without a scratch on the
    last shot."""

    name = "pot"

    def on_shot(self, env: "BilliardsEnv", outcome: ShotOutcome) -> tuple[float, bool, bool, dict[str, Any]]:
        c = self.config
        b = env.balls
        if outcome.scratch:
            spot_cue_ball(b.pos, b.on_table, c.ball_radius, env.table)
        n_potted = len(outcome.pocketed) - (1 if outcome.scratch else 0)
        reward, terminated, truncated, success = pot_score(
            n_potted, outcome.scratch, outcome.first_contact < 0, not b.on_table[1:].any(), env.shots, c.pot_reward,
            c.step_penalty, c.scratch_penalty, c.miss_penalty, c.single_shot, c.max_shots)
        return float(reward), bool(terminated), bool(truncated), {"is_success": bool(success)}


def task_factory(env: "BilliardsEnv") -> Task:
    """The task named by ``env.config.task`` (``pot``, or a game: ``nine_ball``, ``eight_ball``)."""
    if env.config.task == "pot":
        return PotTask(env)
    from .games import EightBallTask, NineBallTask

    return {"nine_ball": NineBallTask, "eight_ball": EightBallTask}[env.config.task](env)


__all__ = ["ShotOutcome", "first_contact", "Task", "PotTask", "pot_score", "task_factory"]
