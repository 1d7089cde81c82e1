"""What every game shares: the foul checks common to pool games and the :class:`Ruleset` base (input checks,
turning a call into the next state)."""
from __future__ import annotations

from abc import ABC, abstractmethod
from typing import Any, ClassVar, Iterable

from .errors import RulesError
from .state import (ANYWHERE, ILLEGAL_BREAK, NO_CONTACT, NO_RAIL, SCRATCH, WRONG_BALL_FIRST, BallInHand, Call,
                    GameState, ShotInfo, register_rules)
from .summary import ShotSummary

_NO_DECLARATION = ShotInfo()


def contact_fouls(summary: ShotSummary, targets: Iterable[int]) -> list[str]:
    """The fouls of a shot after the break: a scratch, no ball hit, a first contact outside ``targets``, or no
    ball pocketed and no ball (cue or object) to a cushion after the first contact. In :data:`~.state.FOULS`
    order."""
    fouls = []
    if summary.cue_pocketed:
        fouls.append(SCRATCH)
    if summary.first_contact is None:
        fouls.append(NO_CONTACT)
    else:
        if summary.first_contact not in targets:
            fouls.append(WRONG_BALL_FIRST)
        if not summary.pocketed and not summary.rail_balls:
            fouls.append(NO_RAIL)
    return fouls


def break_fouls(summary: ShotSummary, targets: Iterable[int] | None, min_rail_balls: int) -> list[str]:
    """The fouls of a break: a scratch, no ball hit, a first contact outside ``targets`` (None: any ball may be
    hit first), or an illegal break: no object ball pocketed and fewer than ``min_rail_balls`` object balls to
    a cushion."""
    fouls = []
    if summary.cue_pocketed:
        fouls.append(SCRATCH)
    if summary.first_contact is None:
        fouls.append(NO_CONTACT)
    elif targets is not None and summary.first_contact not in targets:
        fouls.append(WRONG_BALL_FIRST)
    if not summary.pocketed and summary.object_balls_to_rail < min_rail_balls:
        fouls.append(ILLEGAL_BREAK)
    return fouls


class Ruleset(ABC):
    """A game's rules: :meth:`call` judges a shot, :meth:`next_state` applies the call, :meth:`legal_targets`
    says which balls the shooter may hit first. Stateless apart from its frozen ``options``."""

    game: ClassVar[str]
    full_rack: ClassVar[tuple[int, ...]]  #: object balls of a full game
    #: The game's legal-target function (``state -> balls``), registered with the game: a staticmethod (a
    #: ``Callable`` class variable would read to a type checker as a method bound to the ruleset).
    targets: ClassVar[staticmethod]

    def __init_subclass__(cls, **kwargs: Any) -> None:
        """A subclass that names its ``game`` registers it (:func:`~.state.register_rules`): the game's states are
        then valid :class:`~.state.GameState` objects and ``ruleset_for`` / ``legal_targets`` know it."""
        super().__init_subclass__(**kwargs)
        if "game" in cls.__dict__:
            targets = cls.__dict__.get("targets")
            if not isinstance(targets, staticmethod):
                raise RulesError(f"{cls.__name__}: a ruleset that names its game also names its legal-target function, "
                                 "targets = staticmethod(f) with f(state) -> the balls the shooter may hit first")
            register_rules(cls.game, cls, targets.__func__)

    def __init__(self, options: Any) -> None:
        self.options = options

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.options!r})"

    def initial_state(self, first_shooter: int = 0, on_table: Iterable[int] | None = None) -> GameState:
        """The state before the opening break: ``first_shooter`` breaks with the cue ball in hand behind the head
        string; ``on_table`` defaults to the full rack. Compiled twin for 9-ball and 8-ball (a state record):
        :func:`~billiards_env.rules.pool_judge.initial_row`."""
        balls = self.full_rack if on_table is None else tuple(on_table)
        self._check_balls(tuple(sorted(balls)))
        return GameState(self.game, tuple(balls), shooter=first_shooter)

    def _check_balls(self, balls: tuple[int, ...]) -> None:
        """Raise if ``balls`` cannot start a game of this kind."""
        if not balls:
            raise RulesError("on_table: a game needs at least one object ball")
        extra = sorted(set(balls) - set(self.full_rack))
        if extra:
            raise RulesError(f"on_table: balls {extra} are not part of {self.game}; use numbers from "
                             f"{self.full_rack[0]}..{self.full_rack[-1]}")

    @abstractmethod
    def legal_targets(self, state: GameState) -> tuple[int, ...]:
        """The balls the shooter may contact first on the next shot, ascending."""

    def needs_called_pocket(self, state: GameState) -> bool:
        """Whether the next shot needs ``ShotInfo.called_pocket`` (8-ball: the shooter is on the 8); games without
        called pockets: never."""
        return False

    def reads_pockets(self, state: GameState) -> bool:
        """Whether the call on a shot from ``state`` may depend on which pocket a ball (or the cue ball) dropped
        into, not only on which balls dropped: here only with a called pocket. A game whose rules read pockets
        otherwise (one-pocket, bank pool) says so; the search player judges outcomes that differ only in their
        pockets once when this is False."""
        return self.needs_called_pocket(state)

    @abstractmethod
    def call(self, state: GameState, summary: ShotSummary, shot_info: ShotInfo | None = None) -> Call:
        """The call on the shot ``summary`` played from ``state`` with the declarations ``shot_info``."""

    def play(self, state: GameState, summary: ShotSummary,
             shot_info: ShotInfo | None = None) -> tuple[Call, GameState]:
        """:meth:`call` and :meth:`next_state` in one: the call and the state after it."""
        c = self.call(state, summary, shot_info)
        return c, self.next_state(state, c)

    def next_state(self, state: GameState, call: Call) -> GameState:
        """The state after ``call`` (made on a shot from ``state``): pocketed balls leave the table except the
        respotted ones, the shooter's foul count grows on a foul and resets on a clean shot."""
        self._check_state(state)
        if call.shooter != state.shooter:
            raise RulesError(f"call: made for player {call.shooter}'s shot but state.shooter is {state.shooter}; "
                             "pass the state the call was made from")
        on = (set(state.on_table) - set(call.pocketed)) | set(call.respot)
        fouls = list(state.fouls_in_a_row)
        fouls[call.shooter] = fouls[call.shooter] + 1 if call.foul else 0
        return GameState.trusted(
            self.game, tuple(sorted(on)), call.next_shooter, call.ball_in_hand, call.groups, (fouls[0], fouls[1]),
            False, self._push_out_next(state, call), call.push_out and not call.foul and not call.game_over,
            call.game_over, call.winner, state.shot_number + 1)

    def _push_out_next(self, state: GameState, call: Call) -> bool:
        """Whether the shot after ``call`` may be a push-out (games without push-outs: never)."""
        return False

    def _check_state(self, state: GameState) -> None:
        if state.game != self.game:
            raise RulesError(f"state.game is {state.game!r} but this ruleset plays {self.game!r}; "
                             "use the ruleset of the state's game")
        if state.game_over:
            raise RulesError("state: the game is over (state.game_over); start a new one with initial_state()")

    def _check_shot(self, state: GameState, summary: ShotSummary, info: ShotInfo | None) -> ShotInfo:
        """Raise if ``summary`` or ``info`` do not fit ``state``; return the declarations (defaults if None)."""
        self._check_state(state)
        on = state.on_table
        if summary.first_contact is not None and summary.first_contact not in on:
            raise RulesError(f"summary.first_contact: ball {summary.first_contact} is not on the table "
                             f"{on}; keep GameState.on_table in step with the balls (use next_state)")
        for n in summary.pocketed:
            if n not in on:
                raise RulesError(f"summary.pocketed: ball {n} was not on the table {on}; keep "
                                 "GameState.on_table in step with the balls (use next_state)")
        info = _NO_DECLARATION if info is None else info
        if info.push_out and not state.push_out_available:
            raise RulesError("shot_info.push_out: no push-out is allowed now (only on the shot right after the "
                             "break, with the option push_out on); check state.push_out_available")
        return info

    def _three_fouls(self, state: GameState) -> bool:
        """A foul now would be the shooter's third in a row and the three-foul rule is on."""
        return bool(self.options.three_foul_rule) and state.fouls_in_a_row[state.shooter] >= 2


def foul_call(state: GameState, summary: ShotSummary, fouls: list[str], *, respot: tuple[int, ...] = (),
              ball_in_hand: BallInHand = ANYWHERE, groups: tuple[str, str] | None = None) -> Call:
    """A foul that ends the turn: the opponent shoots with the cue ball in hand (``ball_in_hand``)."""
    return Call(legal=False, foul=True, reason=fouls[0], fouls=tuple(fouls), shooter=state.shooter,
                turn_over=True, next_shooter=state.opponent, ball_in_hand=ball_in_hand, pocketed=summary.pocketed,
                respot=respot, cue_pocketed=summary.cue_pocketed, groups=groups)


def end_call(state: GameState, summary: ShotSummary, reason: str, winner: int,
             fouls: list[str] | tuple[str, ...] = (), legal: bool = False,
             groups: tuple[str, str] | None = None) -> Call:
    """A shot that ends the game: ``winner`` wins for ``reason``."""
    return Call(legal=legal, foul=bool(fouls), reason=reason, fouls=tuple(fouls), shooter=state.shooter,
                turn_over=True, next_shooter=1 - state.shooter, ball_in_hand=False, pocketed=summary.pocketed,
                cue_pocketed=summary.cue_pocketed, game_over=True, winner=winner, groups=groups)


def clean_call(state: GameState, summary: ShotSummary, reason: str, keep_turn: bool, *,
               respot: tuple[int, ...] = (), groups: tuple[str, str] | None = None, push_out: bool = False) -> Call:
    """A shot without a foul: the shooter continues if ``keep_turn``, else the opponent plays from where the
    balls lie."""
    nxt = state.shooter if keep_turn else state.opponent
    return Call(legal=True, foul=False, reason=reason, fouls=(), shooter=state.shooter, turn_over=not keep_turn,
                next_shooter=nxt, ball_in_hand=False, pocketed=summary.pocketed, respot=respot,
                cue_pocketed=False, groups=groups, push_out=push_out)


__all__ = ["Ruleset", "contact_fouls", "break_fouls", "foul_call", "end_call", "clean_call"]
