"""billiards_env.rules: the rules of 9-ball and 8-ball as pure data in, data out (no Gymnasium, no pygame).

A shot's event log becomes a :class:`ShotSummary` (:func:`summarize_arrays` on the arrays of
``Simulator.run_in_place``, or :func:`summarize_result` on a ``ShotResult``); a ruleset (:class:`NineBall`,
:class:`EightBall`) turns a :class:`GameState`, the summary and the shooter's declarations (:class:`ShotInfo`)
into a :class:`Call` (legal or foul and why, who shoots next, ball in hand, balls to respot, game over and the
winner), and :meth:`Ruleset.next_state` applies it. Where respotted balls and the cue ball in hand go is the
env's job. The rules, and every simplification of the WPA rules: docs/rules.md.

Example::

    from billiards_env.physics import Physics, Simulator, Table
    from billiards_env.physics.layout import rack_balls
    from billiards_env.rules import EightBall, ShotInfo, ball_numbers, summarize_arrays

    table = Table()
    sim = Simulator(table, Physics())
    rules = EightBall()
    state = rules.initial_state(first_shooter=0)
    balls = rack_balls(table).strike("cue", angle=0.0, speed=8.0)
    numbers = ball_numbers(balls.ids)                       # once per scene
    status, t, n, pocket, events = sim.run_in_place(balls)  # one shot
    call = rules.call(state, summarize_arrays(events, pocket, numbers), ShotInfo())
    state = rules.next_state(state, call)  # the env respots call.respot and places the cue ball
"""
from __future__ import annotations

from .eight_ball import EightBall, EightBallOptions, eight_ball_targets, group_of
from .errors import RulesError
from .nine_ball import NineBall, NineBallOptions, nine_ball_targets
from .ruleset import Ruleset
from .state import (ANYWHERE, EIGHT_BALL, FOULS, GAMES, KITCHEN, NINE_BALL, SOLIDS, STRIPES, TARGETS, BallInHand, Call,
                    GameState, ShotInfo)
from .summary import CUE, ShotSummary, ball_numbers, summarize_arrays, summarize_outcome, summarize_result

#: Every game's ruleset by the game's name (each :class:`Ruleset` subclass adds itself: :data:`.state.GAMES`).
RULESETS = GAMES


def ruleset_for(game: str, options: object | None = None) -> Ruleset:
    """The ruleset of ``game`` (``"nine_ball"`` or ``"eight_ball"``) with ``options`` (None: the defaults)."""
    try:
        cls = RULESETS[game]
    except KeyError:
        raise RulesError(f"game: unknown game {game!r}; use one of {', '.join(RULESETS)}") from None
    return cls(options)



def legal_targets(state: GameState) -> tuple[int, ...]:
    """The balls the shooter may hit first from ``state`` (9-ball: the lowest; 8-ball: any on the break, any but
    the 8 on an open table, the own group, then the 8). An unknown game raises :class:`RulesError`."""
    try:
        targets = TARGETS[state.game]
    except KeyError:
        raise RulesError(f"state.game: unknown game {state.game!r}; use one of {', '.join(TARGETS)}") from None
    return targets(state)


__all__ = [
    "NineBall", "NineBallOptions", "EightBall", "EightBallOptions", "Ruleset", "RulesError", "GameState",
    "ShotInfo", "Call", "ShotSummary", "BallInHand", "summarize_arrays", "summarize_outcome", "summarize_result",
    "ball_numbers", "legal_targets", "nine_ball_targets", "eight_ball_targets", "group_of", "ruleset_for",
    "RULESETS", "TARGETS", "CUE", "NINE_BALL", "EIGHT_BALL", "ANYWHERE", "KITCHEN", "SOLIDS", "STRIPES", "FOULS",
]
