"""Straight pool (14.1 continuous), WPA-style: call the ball and the pocket, a point a ball, first to the target.

Pure data in, data out (no Gymnasium, no pygame), as the other games' rules: a :class:`StraightPoolState` (between
shots), a :class:`ShotSummary` (what the shot did) and a :class:`CalledShot` (the ball and pocket called) give a
:class:`StraightPoolCall`; :meth:`StraightPool.next_state` applies it. Where spotted balls, a re-rack, the 15th ball
and the cue ball go on the table is the session's job; which of the rules' cases applies after a re-rack is
:func:`rerack_placement` (pure data too).

The rules (WPA 14.1 continuous; the choices and simplifications are listed in docs/games.md):

- Any ball may be hit first. A shot scores when the called ball drops in the called pocket without a foul: one
  point for it and one for each other ball pocketed on the stroke; the shooter continues. Otherwise balls pocketed
  are illegally pocketed: they are spotted, and the inning ends.
- Fouls (-1 point each, the opponent plays the cue ball where it lies): no ball hit, no ball pocketed and no ball
  (cue or object) to a cushion after the first contact; a scratch gives the opponent the cue ball in hand behind
  the head string.
- Three fouls in a row by the same player (fouls separated by his legal shots do not count): -1 for the foul and
  -15 more (option ``three_foul_penalty``), his count back to 0, and all 15 balls re-racked for him to break again
  under the opening-break requirement.
- The opening break: the called ball in the called pocket, or the cue ball and at least two object balls
  (option ``break_rail_balls``) to a cushion after the first contact. Failing both is a breaking violation:
  -2 points (option ``break_violation_points``); the WPA lets the opponent choose between the table as it lies and
  a re-break by the offender: simplified, the opponent always accepts the table (and a scratch on the break gives
  the cue ball in hand behind the head string). A breaking violation does not count in the three fouls.
- When one object ball is left (14 pocketed) the 14 are re-racked with the apex spot empty and play continues
  (after the last two balls dropped on one stroke, all 15 are re-racked); the 15th ball and the cue ball go where
  :func:`rerack_placement` says.
- The game ends when a player reaches ``target`` points (100, 150...).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, Union

from .errors import RulesError, checked_keywords
from .state import ANYWHERE, FOULS, KITCHEN, LEGAL, NO_CONTACT, NO_RAIL, SCRATCH
from .summary import CUE, ShotSummary

STRAIGHT_POOL = "straight_pool"
#: Reasons of a :class:`StraightPoolCall` (``reason``), in the order of the info's codes.
CALLED_POCKETED = "called ball pocketed"  #: the called ball in the called pocket: points
NOT_CALLED = "called ball missed"  #: no foul, but the called ball did not drop in the called pocket
BREAK_VIOLATION = "breaking violation"  #: the opening break met neither requirement
THIRD_FOUL = "third consecutive foul"  #: the third foul in a row: -15 more, a re-rack and a re-break
TARGET_REACHED = "target reached"  #: the shooter reached the target: the game is won
REASONS = (LEGAL, CALLED_POCKETED, NOT_CALLED, SCRATCH, NO_CONTACT, NO_RAIL, BREAK_VIOLATION, THIRD_FOUL,
           TARGET_REACHED)
#: Where the 15th ball goes after a re-rack (:func:`rerack_placement`).
STAYS, HEAD_SPOT, CENTER_SPOT, RACKED = "stays", "head spot", "center spot", "racked"
BallInHand = Union[Literal[False], str]  #: False, "kitchen" (behind the head string) or "anywhere"


@checked_keywords
@dataclass(frozen=True)
class StraightPoolOptions:
    """Options of :class:`StraightPool` (defaults: WPA). ``target``: the points that win (WPA: agreed; 100, 125 and
    150 are usual). ``break_rail_balls``: object balls an opening break must drive to a cushion when no called
    ball drops. ``break_violation_points``: the penalty of a breaking violation. ``three_foul_penalty``: the points
    taken on a third consecutive foul besides that foul's point."""

    target: int = 150
    break_rail_balls: int = 2
    break_violation_points: int = 2
    three_foul_penalty: int = 15

    def __post_init__(self) -> None:
        for name, lo in (("target", 1), ("break_rail_balls", 0), ("break_violation_points", 0),
                         ("three_foul_penalty", 0)):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, int) or v < lo:
                raise RulesError(f"StraightPoolOptions.{name}: must be a whole number >= {lo}, got {v!r}")
        if self.break_rail_balls > 15:
            raise RulesError(f"StraightPoolOptions.break_rail_balls: at most 15, got {self.break_rail_balls}")


def _check_player(name: str, value: object) -> None:
    if isinstance(value, bool) or value not in (0, 1):
        raise RulesError(f"{name}: must be player 0 or 1, got {value!r}")


@dataclass(frozen=True, slots=True)
class StraightPoolState:
    """Where a game stands before a shot. ``on_table``: object balls on the table (ascending); ``shooter``;
    ``ball_in_hand`` (False, ``"kitchen"``: behind the head string, ``"anywhere"``); ``score``: both players'
    points (they may go below 0); ``fouls_in_a_row``: each player's consecutive fouls; ``break_shot``: the next
    shot is an opening break (the game's first, or the re-break after three fouls); ``target``: the points that
    win; ``game_over`` / ``winner``; ``shot_number``; ``racks``: re-racks so far."""

    on_table: tuple[int, ...]
    shooter: int = 0
    ball_in_hand: BallInHand = KITCHEN
    score: tuple[int, int] = (0, 0)
    fouls_in_a_row: tuple[int, int] = (0, 0)
    break_shot: bool = True
    target: int = 150
    game_over: bool = False
    winner: int | None = None
    shot_number: int = 0
    racks: int = 0

    def __post_init__(self) -> None:
        _check_player("StraightPoolState.shooter", self.shooter)
        if self.ball_in_hand not in (False, KITCHEN, ANYWHERE) or self.ball_in_hand is True:
            raise RulesError(f"StraightPoolState.ball_in_hand: must be False, 'kitchen' or 'anywhere', got "
                             f"{self.ball_in_hand!r}")
        balls = tuple(sorted(int(n) for n in self.on_table))
        if len(set(balls)) != len(balls) or any(not 1 <= n <= 15 for n in balls):
            raise RulesError(f"StraightPoolState.on_table: {self.on_table!r} must list distinct ball numbers 1..15")
        object.__setattr__(self, "on_table", balls)
        for name in ("score", "fouls_in_a_row"):
            pair = tuple(getattr(self, name))
            if len(pair) != 2 or any(isinstance(x, bool) or not isinstance(x, int) for x in pair):
                raise RulesError(f"StraightPoolState.{name}: give two whole numbers, got {getattr(self, name)!r}")
            object.__setattr__(self, name, pair)
        if any(f < 0 for f in self.fouls_in_a_row):
            raise RulesError(f"StraightPoolState.fouls_in_a_row: counts must be >= 0, got {self.fouls_in_a_row}")
        if isinstance(self.target, bool) or not isinstance(self.target, int) or self.target < 1:
            raise RulesError(f"StraightPoolState.target: a whole number >= 1, got {self.target!r}")
        if self.winner is not None:
            _check_player("StraightPoolState.winner", self.winner)
            if not self.game_over:
                raise RulesError("StraightPoolState.winner: set only when game_over is True")

    @property
    def opponent(self) -> int:
        return 1 - self.shooter


@dataclass(frozen=True, slots=True)
class CalledShot:
    """What the shooter declares: ``ball`` (the number of the ball called, None: nothing called) and ``pocket``
    (the pocket called for it, an index into the table's pockets)."""

    ball: int | None = None
    pocket: int | None = None

    def __post_init__(self) -> None:
        for name in ("ball", "pocket"):
            v = getattr(self, name)
            if v is not None and (isinstance(v, bool) or not isinstance(v, int) or v < 0):
                raise RulesError(f"CalledShot.{name}: must be None or a whole number >= 0, got {v!r}")
        if self.ball == CUE:
            raise RulesError("CalledShot.ball: the cue ball (0) cannot be called; call an object ball 1..15")


@dataclass(frozen=True, slots=True)
class StraightPoolCall:
    """The call on one shot. ``points``: the change of the shooter's score (points scored, or the penalty as a
    negative number); ``fouls``: each foul (in :data:`~.state.FOULS` order; a breaking violation is not one);
    ``respot``: balls pocketed illegally, spotted again; ``rerack``: object balls racked after the shot (0, 14 or
    15; 15 also after a third foul); ``break_next``: the next shot is a re-break (after a third foul);
    ``next_shooter``, ``ball_in_hand``, ``turn_over``, ``game_over``, ``winner`` as in the other games."""

    legal: bool
    foul: bool
    reason: str
    fouls: tuple[str, ...]
    shooter: int
    turn_over: bool
    next_shooter: int
    ball_in_hand: BallInHand
    points: int
    pocketed: tuple[int, ...] = ()
    respot: tuple[int, ...] = ()
    cue_pocketed: bool = False
    rerack: int = 0
    break_next: bool = False
    game_over: bool = False
    winner: int | None = None


def rerack_placement(fifteenth: str | None, cue_in_rack: bool, cue_in_kitchen: bool) -> tuple[str, bool]:
    """After a re-rack: where the 15th ball goes and whether the cue ball is taken in hand behind the head string
    (WPA 14.1, the positions after a re-rack). ``fifteenth``: where the ball left on the table lies: ``"rack"``
    (in the rack's area), ``"head spot"`` (on the head spot), ``"elsewhere"``, or None (it was pocketed: all 15 are
    racked). ``cue_in_rack``: the cue ball lies in the rack's area; ``cue_in_kitchen``: behind the head string.

    =======================  ===========================  ===================================
    15th ball                cue ball in the rack          cue ball elsewhere
    =======================  ===========================  ===================================
    in the rack              head spot; cue in hand        head spot (center spot if the cue
                                                           ball is behind the head string)
    pocketed                 racked; cue in hand           racked
    on the head spot         center spot; cue in hand      stays
    elsewhere                stays; cue in hand            stays
    =======================  ===========================  ===================================
    """
    if fifteenth not in ("rack", HEAD_SPOT, "elsewhere", None):
        raise RulesError(f"rerack_placement: fifteenth must be 'rack', 'head spot', 'elsewhere' or None, got "
                         f"{fifteenth!r}")
    if fifteenth is None:
        return RACKED, cue_in_rack
    if fifteenth == "rack":
        if cue_in_rack:
            return HEAD_SPOT, True
        return (CENTER_SPOT if cue_in_kitchen else HEAD_SPOT), False
    if fifteenth == HEAD_SPOT and cue_in_rack:
        return CENTER_SPOT, True
    return STAYS, cue_in_rack


class StraightPool:
    """WPA straight pool. ``StraightPool(StraightPoolOptions(...))``: :meth:`call` judges a shot,
    :meth:`next_state` applies the call, :meth:`legal_targets` (any ball) and :meth:`initial_state`."""

    game = STRAIGHT_POOL
    full_rack = tuple(range(1, 16))

    def __init__(self, options: StraightPoolOptions | None = None) -> None:
        self.options = options if options is not None else StraightPoolOptions()
        if not isinstance(self.options, StraightPoolOptions):
            raise RulesError(f"StraightPool options: expected StraightPoolOptions, got {type(self.options).__name__}")

    def __repr__(self) -> str:
        return f"StraightPool({self.options!r})"

    def initial_state(self, first_shooter: int = 0, on_table: tuple[int, ...] | None = None) -> StraightPoolState:
        """The opening break: ``first_shooter`` breaks with the cue ball in hand behind the head string."""
        return StraightPoolState(self.full_rack if on_table is None else tuple(on_table), shooter=first_shooter,
                                 target=self.options.target)

    def legal_targets(self, state: StraightPoolState) -> tuple[int, ...]:
        """Any ball on the table may be hit first."""
        return state.on_table

    def needs_called_pocket(self, state: StraightPoolState) -> bool:
        """Every shot is called (ball and pocket)."""
        return not state.game_over

    def reads_pockets(self, state: StraightPoolState) -> bool:
        """Whether the call may depend on the pockets the balls dropped into: yes, every shot calls its pocket
        (``Ruleset.reads_pockets``)."""
        return True

    def call(self, state: StraightPoolState, summary: ShotSummary, called: CalledShot | None = None
             ) -> StraightPoolCall:
        """The call on the shot ``summary`` played from ``state`` with the declaration ``called``."""
        called = CalledShot() if called is None else called
        self._check(state, summary, called)
        me, opp = state.shooter, state.opponent
        made = called.ball is not None and called.pocket is not None and summary.pocket_of(called.ball) == called.pocket
        fouls = []
        if summary.cue_pocketed:
            fouls.append(SCRATCH)
        if summary.first_contact is None:
            fouls.append(NO_CONTACT)
        elif not summary.pocketed and not summary.rail_balls:
            fouls.append(NO_RAIL)
        if state.break_shot:
            fouls = [f for f in fouls if f == SCRATCH]  # the break has its own requirement
            rails = summary.object_balls_to_rail >= self.options.break_rail_balls and CUE in summary.rail_balls
            if not (made and not fouls) and not rails:
                return self._break_violation(state, summary, fouls)
        if fouls:
            return self._foul(state, summary, fouls)
        if not made:
            return StraightPoolCall(True, False, NOT_CALLED, (), me, True, opp, False, 0, summary.pocketed,
                                    summary.pocketed, False)
        points = len(summary.pocketed)
        if state.score[me] + points >= state.target:
            return StraightPoolCall(True, False, TARGET_REACHED, (), me, True, opp, False, points, summary.pocketed,
                                    (), False, game_over=True, winner=me)
        left = len(state.on_table) - len(summary.pocketed)
        rerack = 14 if left == 1 else (15 if left == 0 else 0)
        return StraightPoolCall(True, False, CALLED_POCKETED, (), me, False, me, False, points, summary.pocketed,
                                (), False, rerack)

    def _foul(self, state: StraightPoolState, summary: ShotSummary, fouls: list[str],
              extra: int = 0) -> StraightPoolCall:
        """A foul: -1 (and ``extra`` more), the balls pocketed spotted; the third in a row: -15 more, a re-rack of
        all 15 and a re-break by the offender."""
        me, opp = state.shooter, state.opponent
        bih: BallInHand = KITCHEN if SCRATCH in fouls else False
        if state.fouls_in_a_row[me] >= 2:
            return StraightPoolCall(False, True, THIRD_FOUL, tuple(fouls), me, False, me, KITCHEN,
                                    -(1 + extra + self.options.three_foul_penalty), summary.pocketed, (),
                                    summary.cue_pocketed, 15, True)
        return StraightPoolCall(False, True, fouls[0], tuple(fouls), me, True, opp, bih, -(1 + extra),
                                summary.pocketed, summary.pocketed, summary.cue_pocketed)

    def _break_violation(self, state: StraightPoolState, summary: ShotSummary, fouls: list[str]) -> StraightPoolCall:
        """An opening break that met neither requirement: -2, the opponent takes the table as it lies (a scratch:
        the cue ball in hand behind the head string); the balls pocketed are spotted. With a scratch it is also a
        foul (-1 more, counted)."""
        me, opp = state.shooter, state.opponent
        penalty = self.options.break_violation_points
        if fouls:
            c = self._foul(state, summary, fouls, extra=penalty)
            return c if c.reason == THIRD_FOUL else \
                StraightPoolCall(False, True, BREAK_VIOLATION, c.fouls, me, True, opp, KITCHEN, c.points, c.pocketed,
                                 c.respot, True)
        return StraightPoolCall(False, False, BREAK_VIOLATION, (), me, True, opp, False, -penalty, summary.pocketed,
                                summary.pocketed, False)

    def _check(self, state: StraightPoolState, summary: ShotSummary, called: CalledShot) -> None:
        if not isinstance(state, StraightPoolState):
            raise RulesError(f"state: expected a StraightPoolState, got {type(state).__name__}")
        if state.game_over:
            raise RulesError("state: the game is over (state.game_over); start a new one with initial_state()")
        if not isinstance(called, CalledShot):
            raise RulesError(f"called: expected a CalledShot (ball, pocket), got {type(called).__name__}")
        if called.ball is not None and called.ball not in state.on_table:
            raise RulesError(f"called.ball: ball {called.ball} is not on the table {state.on_table}; call a ball on it")
        on = set(state.on_table)
        if summary.first_contact is not None and summary.first_contact not in on:
            raise RulesError(f"summary.first_contact: ball {summary.first_contact} is not on the table {state.on_table}"
                             "; keep the state in step with the balls (use next_state)")
        for n in summary.pocketed:
            if n not in on:
                raise RulesError(f"summary.pocketed: ball {n} was not on the table {state.on_table}; keep the state "
                                 "in step with the balls (use next_state)")

    def next_state(self, state: StraightPoolState, call: StraightPoolCall) -> StraightPoolState:
        """The state after ``call`` (made on a shot from ``state``): the score, the foul counts (a foul adds one, a
        legal shot clears the shooter's, as a third foul does; a breaking violation without a foul leaves it), the
        balls (pocketed leave, spotted and re-racked come back) and who shoots how."""
        if call.shooter != state.shooter:
            raise RulesError(f"call: made for player {call.shooter}'s shot but state.shooter is {state.shooter}; "
                             "pass the state the call was made from")
        me = call.shooter
        score = list(state.score)
        score[me] += call.points
        fouls = list(state.fouls_in_a_row)
        if call.reason == THIRD_FOUL or call.legal:
            fouls[me] = 0
        elif call.foul:
            fouls[me] += 1  # (a breaking violation without a foul leaves the count as it was)
        on = (set(state.on_table) - set(call.pocketed)) | set(call.respot)
        racks = state.racks
        if call.rerack:
            on = set(self.full_rack) if call.rerack == 15 else on | (set(self.full_rack) - on)
            racks += 1
        return StraightPoolState(tuple(sorted(on)), call.next_shooter, call.ball_in_hand, (score[0], score[1]),
                                 (fouls[0], fouls[1]), call.break_next, state.target, call.game_over, call.winner,
                                 state.shot_number + 1, racks)

    def play(self, state: StraightPoolState, summary: ShotSummary, called: CalledShot | None = None
             ) -> tuple[StraightPoolCall, StraightPoolState]:
        """:meth:`call` and :meth:`next_state` in one."""
        c = self.call(state, summary, called)
        return c, self.next_state(state, c)


__all__ = ["StraightPool", "StraightPoolOptions", "StraightPoolState", "StraightPoolCall", "CalledShot",
           "rerack_placement", "STRAIGHT_POOL", "REASONS", "CALLED_POCKETED", "NOT_CALLED", "BREAK_VIOLATION",
           "THIRD_FOUL", "TARGET_REACHED", "STAYS", "HEAD_SPOT", "CENTER_SPOT", "RACKED", "FOULS"]
