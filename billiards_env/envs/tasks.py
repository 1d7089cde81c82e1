"""Tasks: what an episode asks of the agent: reward, termination, success and the task's part of ``info``
(panda-gym's Task; the env joins a table state, an action type, an observation type and a task).

A task reads the :class:`~billiards_env.table_state.TableState`, never the env: the env plays a shot through the one
shot path (:func:`billiards_env.shot_path.play_shot`) and hands the task the :class:`PlayedShot`; the task scores
it. A task that needs more shots played within a step (a game's opponent, the ``ball_in_hand`` opening's break)
plays them through the shot path the env lends it (:class:`Driver`); a game's opponent chooses its shots itself
(:class:`~billiards_env.envs.opponent.Opponent`, given to the game's task). :class:`PotTask` is the three scenes without rules (pot one ball, three
balls, a rack); games are tasks with rules (:mod:`billiards_env.envs.games`).
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, NamedTuple

import numpy as np
from numba import njit

from billiards_env.physics.layout import spot_cue_ball
from billiards_env.physics.outcome import ShotOutcome, first_contact_row
from billiards_env.shot_path import CueShot, PlayedShot
from billiards_env.table_state import TableState

if TYPE_CHECKING:  # pragma: no cover
    from .config import EnvConfig


class Driver(NamedTuple):
    """What the env lends a task for the shots it plays within a step: ``play(shot, by)`` plays a shot through the
    env's shot path (its noise, its recording; ``by``: ``"opponent"``, animated after the agent's shot, or
    ``"table"``, nobody's shot, not drawn)."""

    play: Callable[[CueShot, str], PlayedShot]


def first_contact(events: np.ndarray, ball: int = 0) -> int:
    """Row of the first ball that ``ball`` collided with in an ``(M, 3)`` event log, or -1."""
    return int(first_contact_row(np.ascontiguousarray(events, dtype=np.int64).reshape(-1, 3), ball))


class Task:
    """The part of an env that gives a shot its meaning. Subclasses override the hooks they need."""

    name = "task"
    #: Whether the shooter can get ball in hand (the action then has the placement dims).
    has_ball_in_hand = False
    #: Extra keys of ``reset(options=...)`` the task reads (besides ``positions`` and ``pocketed``).
    option_keys: tuple[str, ...] = ()
    #: Declarations the action carries (:class:`~billiards_env.games.declarations.Declaration`: e.g. the 8's called
    #: pocket, a 9-ball push-out; a game's session names them).
    declarations: tuple[Any, ...] = ()
    #: Game features appended to every observation (values in [0, 1]).
    n_features = 0

    def __init__(self, config: "EnvConfig", state: TableState) -> None:
        self.config = config

    def reset(self, state: TableState, rng: np.random.Generator, options: dict[str, Any] | None,
              driver: Driver) -> dict[str, Any]:
        """Called after the balls are placed; returns extra ``info`` for ``reset``."""
        return {}

    def before_shot(self, shot: CueShot) -> None:
        """Called with the shot about to be played (a game reads its declarations and shows it in the HUD)."""

    def on_shot(self, state: TableState, played: PlayedShot, shots: int, driver: Driver
                ) -> tuple[float, bool, bool, dict[str, Any]]:
        """Score a shot (``shots``: the shots of the episode so far, this one included): ``(reward, terminated,
        truncated, info)``."""
        raise NotImplementedError

    def hud(self) -> dict[str, Any] | None:
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

    def on_shot(self, state: TableState, played: PlayedShot, shots: int, driver: Driver
                ) -> tuple[float, bool, bool, dict[str, Any]]:
        c = self.config
        b = state.balls
        outcome: ShotOutcome = played.outcome
        if outcome.scratch:
            spot_cue_ball(b.pos, b.on_table, c.ball_radius, state.table)
            state.changed()
        n_potted = len(outcome.pocketed) - (1 if outcome.scratch else 0)
        reward, terminated, truncated, success = pot_score(
            n_potted, outcome.scratch, outcome.first_contact < 0, not b.on_table[1:].any(), shots, c.pot_reward,
            c.step_penalty, c.scratch_penalty, c.miss_penalty, c.single_shot, c.max_shots)
        return float(reward), bool(terminated), bool(truncated), {"is_success": bool(success)}


__all__ = ["Driver", "first_contact", "Task", "PotTask", "pot_score"]
