"""9-ball, WPA-style: the lowest ball first, the 9 on a legal shot wins.

Simplifications and choices: docs/rules.md. The "9" is the highest ball on the table (the money ball), so a
game on a subset of 1..9 ends on its highest ball; on a standard rack it is the 9.
"""
from __future__ import annotations

from dataclasses import dataclass

from .errors import RulesError, checked_keywords
from .ruleset import Ruleset, break_fouls, clean_call, contact_fouls, end_call, foul_call
from .state import LEGAL, NINE_BALL, NINE_POCKETED, PUSH_OUT, SCRATCH, THREE_FOULS, Call, GameState, ShotInfo
from .summary import ShotSummary


@checked_keywords
@dataclass(frozen=True)
class NineBallOptions:
    """Options of :class:`NineBall` (defaults: WPA).

    ``push_out``: the shot right after the break may be declared a push-out (no contact or cushion needed;
    pocketed balls stay down, the 9 is respotted; the opponent then plays or passes the shot back).
    ``three_foul_rule``: a third foul in a row (by the same player, on his successive shots) loses the game.
    ``break_rail_balls``: object balls that must reach a cushion on a break that pockets nothing.
    """

    push_out: bool = True
    three_foul_rule: bool = True
    break_rail_balls: int = 4

    def __post_init__(self) -> None:
        for name in ("push_out", "three_foul_rule"):
            if not isinstance(getattr(self, name), bool):
                raise RulesError(f"NineBallOptions.{name}: must be True or False, got {getattr(self, name)!r}")
        n = self.break_rail_balls
        if isinstance(n, bool) or not isinstance(n, int) or not 0 <= n <= 9:
            raise RulesError(f"NineBallOptions.break_rail_balls: must be an integer in 0..9, got {n!r}")


def nine_ball_targets(state: GameState) -> tuple[int, ...]:
    """The ball the shooter must hit first: the lowest on the table."""
    return (state.on_table[0],) if state.on_table else ()


class NineBall(Ruleset):
    """WPA 9-ball. ``NineBall(NineBallOptions(...))``; see :class:`~.ruleset.Ruleset` for the methods. Compiled twin
    (:meth:`call` and :meth:`~.ruleset.Ruleset.next_state` on integers): :func:`~.pool_judge.play`."""

    game = NINE_BALL
    targets = staticmethod(nine_ball_targets)
    full_rack = tuple(range(1, 10))

    def __init__(self, options: NineBallOptions | None = None) -> None:
        super().__init__(options if options is not None else NineBallOptions())
        if not isinstance(self.options, NineBallOptions):
            raise RulesError(f"NineBall options: expected NineBallOptions, got {type(self.options).__name__}")

    def legal_targets(self, state: GameState) -> tuple[int, ...]:
        return nine_ball_targets(state)

    def call(self, state: GameState, summary: ShotSummary, shot_info: ShotInfo | None = None) -> Call:
        info = self._check_shot(state, summary, shot_info)
        targets = nine_ball_targets(state)
        if state.break_shot:
            fouls = break_fouls(summary, targets, self.options.break_rail_balls)
        elif info.push_out:
            fouls = [SCRATCH] if summary.cue_pocketed else []
        else:
            fouls = contact_fouls(summary, targets)
        if fouls and self._three_fouls(state):
            return end_call(state, summary, THREE_FOULS, state.opponent, fouls)
        money = state.on_table[-1]
        money_down = money in summary.pocketed
        if money_down and not fouls and not info.push_out:
            return end_call(state, summary, NINE_POCKETED, state.shooter, legal=True)
        respot = (money,) if money_down else ()
        if fouls:
            return foul_call(state, summary, fouls, respot=respot)
        if info.push_out:
            return clean_call(state, summary, PUSH_OUT, keep_turn=False, respot=respot, push_out=True)
        return clean_call(state, summary, LEGAL, keep_turn=bool(summary.pocketed))

    def _push_out_next(self, state: GameState, call: Call) -> bool:
        return state.break_shot and self.options.push_out and not call.game_over

    def pass_back(self, state: GameState) -> GameState:
        """After the opponent's legal push-out, the shooter declines to play: the pusher shoots again from where
        the balls lie."""
        self._check_state(state)
        if not state.push_out_pending:
            raise RulesError("pass_back: the last shot was not a legal push-out (state.push_out_pending is False)")
        return GameState(state.game, state.on_table, shooter=state.opponent, ball_in_hand=False,
                         fouls_in_a_row=state.fouls_in_a_row, break_shot=False, shot_number=state.shot_number)


__all__ = ["NineBall", "NineBallOptions", "nine_ball_targets"]
