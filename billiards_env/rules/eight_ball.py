"""8-ball, WPA-style: open table after the break, groups (solids 1-7, stripes 9-15) by the first legal pot, the 8
last and in the called pocket.

Simplifications and choices: docs/rules.md.
"""
from __future__ import annotations

from dataclasses import dataclass

from .errors import RulesError, checked_keywords
from .ruleset import Ruleset, break_fouls, clean_call, contact_fouls, end_call, foul_call
from .state import (ANYWHERE, EIGHT_BALL, EIGHT_EARLY, EIGHT_NOT_CALLED, EIGHT_ON_BREAK, EIGHT_ON_FOUL,
                    EIGHT_POCKETED, EIGHT_WRONG_POCKET, KITCHEN, LEGAL, SCRATCH, SOLIDS, STRIPES, THREE_FOULS, Call,
                    GameState, ShotInfo)
from .summary import ShotSummary

EIGHT = 8
EIGHT_ON_BREAK_CHOICES = ("respot", "win")


def group_of(number: int) -> str | None:
    """The group of an object ball: solids 1-7, stripes 9-15, None for the 8."""
    if number == EIGHT:
        return None
    return SOLIDS if number < EIGHT else STRIPES


@checked_keywords
@dataclass(frozen=True)
class EightBallOptions:
    """Options of :class:`EightBall` (defaults: WPA where the WPA leaves no choice to the players).

    ``call_eight``: the 8 must drop in the pocket called in ``ShotInfo.called_pocket`` (False: any pocket, as
    pooltool relaxed it). ``eight_on_break``: ``"respot"`` (the 8 pocketed on the break is respotted and the
    breaker continues unless he fouled) or ``"win"`` (it wins a break without a foul; with a foul it is
    respotted). ``break_scratch_ball_in_hand``: where the opponent places the cue ball after a scratch on the break,
    ``"kitchen"`` (WPA: behind the head string) or ``"anywhere"``. ``illegal_break_ball_in_hand``: the same after
    an illegal break without a scratch (WPA lets the opponent re-rack; simplified to a foul, default
    ``"anywhere"``). ``break_rail_balls``: object balls that must reach a cushion on a break that pockets
    nothing. ``three_foul_rule``: a third foul in a row loses (not a WPA 8-ball rule; off by default).
    """

    call_eight: bool = True
    eight_on_break: str = "respot"
    break_scratch_ball_in_hand: str = KITCHEN
    illegal_break_ball_in_hand: str = ANYWHERE
    break_rail_balls: int = 4
    three_foul_rule: bool = False

    def __post_init__(self) -> None:
        for name in ("call_eight", "three_foul_rule"):
            if not isinstance(getattr(self, name), bool):
                raise RulesError(f"EightBallOptions.{name}: must be True or False, got {getattr(self, name)!r}")
        if self.eight_on_break not in EIGHT_ON_BREAK_CHOICES:
            raise RulesError(f"EightBallOptions.eight_on_break: {self.eight_on_break!r}; use 'respot' or 'win'")
        for name in ("break_scratch_ball_in_hand", "illegal_break_ball_in_hand"):
            if getattr(self, name) not in (KITCHEN, ANYWHERE):
                raise RulesError(f"EightBallOptions.{name}: {getattr(self, name)!r}; use 'kitchen' or 'anywhere'")
        n = self.break_rail_balls
        if isinstance(n, bool) or not isinstance(n, int) or not 0 <= n <= 15:
            raise RulesError(f"EightBallOptions.break_rail_balls: must be an integer in 0..15, got {n!r}")


def eight_ball_targets(state: GameState) -> tuple[int, ...]:
    """The balls the shooter may hit first: any ball on the break; any ball but the 8 on an open table; the
    shooter's group while it has balls on the table, then the 8."""
    on = state.on_table
    if state.break_shot:
        return on
    if state.groups is None:
        others = tuple(n for n in on if n != EIGHT)
    else:
        mine = state.groups[state.shooter]
        others = tuple(n for n in on if group_of(n) == mine)
    return others if others else tuple(n for n in on if n == EIGHT)


class EightBall(Ruleset):
    """WPA 8-ball. ``EightBall(EightBallOptions(...))``; see :class:`~.ruleset.Ruleset` for the methods. Compiled
    twin (:meth:`call` and :meth:`~.ruleset.Ruleset.next_state` on integers): :func:`~.pool_judge.play`."""

    game = EIGHT_BALL
    targets = staticmethod(eight_ball_targets)
    full_rack = tuple(range(1, 16))

    def __init__(self, options: EightBallOptions | None = None) -> None:
        super().__init__(options if options is not None else EightBallOptions())
        if not isinstance(self.options, EightBallOptions):
            raise RulesError(f"EightBall options: expected EightBallOptions, got {type(self.options).__name__}")

    def _check_balls(self, balls: tuple[int, ...]) -> None:
        super()._check_balls(balls)
        if EIGHT not in balls:
            raise RulesError(f"on_table: {balls} has no 8; an 8-ball game needs the 8")

    def legal_targets(self, state: GameState) -> tuple[int, ...]:
        return eight_ball_targets(state)

    def needs_called_pocket(self, state: GameState) -> bool:
        """The next shot needs ``ShotInfo.called_pocket``: the shooter is on the 8 and calls are on."""
        return self.options.call_eight and not state.break_shot and eight_ball_targets(state) == (EIGHT,)

    def call(self, state: GameState, summary: ShotSummary, shot_info: ShotInfo | None = None) -> Call:
        info = self._check_shot(state, summary, shot_info)
        if state.break_shot:
            return self._call_break(state, summary)
        targets = eight_ball_targets(state)
        fouls = contact_fouls(summary, targets)
        if EIGHT in summary.pocketed:
            return self._eight_down(state, summary, info, targets, fouls)
        if fouls:
            if self._three_fouls(state):
                return end_call(state, summary, THREE_FOULS, state.opponent, fouls, groups=state.groups)
            return foul_call(state, summary, fouls, groups=state.groups)
        groups = state.groups
        if groups is None:
            if not summary.pocketed:
                return clean_call(state, summary, LEGAL, keep_turn=False)
            mine = group_of(summary.pocketed[0])
            assert mine is not None  # not the 8: a shot that pots it returned above
            theirs = STRIPES if mine == SOLIDS else SOLIDS
            groups = (mine, theirs) if state.shooter == 0 else (theirs, mine)
            return clean_call(state, summary, LEGAL, keep_turn=True, groups=groups)
        mine = groups[state.shooter]
        scored = any(group_of(n) == mine for n in summary.pocketed)
        return clean_call(state, summary, LEGAL, keep_turn=scored, groups=groups)

    def _eight_down(self, state: GameState, summary: ShotSummary, info: ShotInfo, targets: tuple[int, ...],
                    fouls: list[str]) -> Call:
        """The 8 dropped on a shot after the break: the game ends, won only on a clean, called shot at the 8."""
        me, opp = state.shooter, state.opponent
        if targets != (EIGHT,):
            return end_call(state, summary, EIGHT_EARLY, opp, fouls, groups=state.groups)
        if fouls:
            return end_call(state, summary, EIGHT_ON_FOUL, opp, fouls, groups=state.groups)
        if self.options.call_eight:
            if info.called_pocket is None:
                return end_call(state, summary, EIGHT_NOT_CALLED, opp, groups=state.groups)
            if summary.pocket_of(EIGHT) != info.called_pocket:
                return end_call(state, summary, EIGHT_WRONG_POCKET, opp, groups=state.groups)
        return end_call(state, summary, EIGHT_POCKETED, me, legal=True, groups=state.groups)

    def _call_break(self, state: GameState, summary: ShotSummary) -> Call:
        """The opening break: legal with a ball pocketed or enough object balls to a cushion; the table stays
        open whatever drops; the 8 is respotted (or wins, by option)."""
        opts = self.options
        fouls = break_fouls(summary, None, opts.break_rail_balls)
        eight_down = EIGHT in summary.pocketed
        if eight_down and not fouls and opts.eight_on_break == "win":
            return end_call(state, summary, EIGHT_ON_BREAK, state.shooter, legal=True)
        respot = (EIGHT,) if eight_down else ()
        if fouls:
            bih = opts.break_scratch_ball_in_hand if fouls[0] == SCRATCH else opts.illegal_break_ball_in_hand
            return foul_call(state, summary, fouls, respot=respot, ball_in_hand=bih)
        return clean_call(state, summary, LEGAL, keep_turn=bool(summary.pocketed), respot=respot)


__all__ = ["EightBall", "EightBallOptions", "eight_ball_targets", "group_of", "EIGHT"]
