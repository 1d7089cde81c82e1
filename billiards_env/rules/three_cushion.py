"""Three-cushion billiards (carom), after the UMB world rules: pure data in, data out.

Three balls on a pocketless table: each player's cue ball (``"white"`` for player 0, ``"yellow"`` for player 1) and
the red. A shot scores a point when the shooter's cue ball meets both other balls and has touched the cushions at
least three times before it meets the second one; the player then shoots again (the inning goes on), else the
turn passes. A game is played to ``target_points``.

The facts come from the shot's event log in one compiled pass (:func:`scan_carom`, and :func:`scan_carom_batch`
for a search player's batch of candidate shots): the shooter's cue ball's ordered ball and cushion contacts.
Every rule and simplification: docs/rules.md.

Example::

    from billiards_env.games.carom_layout import carom_balls
    from billiards_env.physics import Physics, Simulator
    from billiards_env.physics.table import carom_table
    from billiards_env.rules.three_cushion import ThreeCushion, carom_rows, summarize_carom

    table = carom_table()
    sim = Simulator(table, Physics(friction="spin"))
    rules = ThreeCushion()
    state = rules.initial_state(first_shooter=0)
    balls = carom_balls(table).strike("white", angle=0.2, speed=4.0, side=0.3)
    status, t, n, pocket, events = sim.run_in_place(balls)
    call = rules.call(state, summarize_carom(events, carom_rows(balls.ids, state.shooter)))
    state = rules.next_state(state, call)
    call.point, call.cushions, call.score, call.turn_over
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Sequence

import numpy as np
from numba import njit

from ..physics.codes import EV_COLLISION, EV_CUSHION
from ..physics.plain import plain
from .errors import RulesError, checked_keywords

THREE_CUSHION = "three_cushion"
#: Ball ids of a carom scene: player 0's cue ball, player 1's cue ball, the red.
CAROM_IDS = ("white", "yellow", "red")
#: The cushions the cue ball must touch before it meets the second ball.
CUSHIONS_NEEDED = 3

# Reasons (``ThreeCushionCall.reason``).
POINT = "point"
NO_POINT = "no point"
TARGET_REACHED = "target reached"
EQUALIZING = "equalizing inning"  #: the breaker reached the target; the other player has a last inning
INNINGS_LIMIT = "innings limit"
# Fouls (``ThreeCushionCall.fouls``), in this order.
BREAK_NOT_ON_RED = "break not on the red"  #: the opening shot did not meet the red first, directly
NO_CONTACT = "no contact"  #: the cue ball met neither ball (a foul only with the option ``miss_is_foul``)
FOULS = (BREAK_NOT_ON_RED, NO_CONTACT)
#: Every reason a call gives (``ThreeCushionCall.reason``).
REASONS = (POINT, NO_POINT, TARGET_REACHED, EQUALIZING, INNINGS_LIMIT) + FOULS

#: Roles of the balls in a summary.
RED = "red"
OPPONENT = "opponent"


# --- the event scan --------------------------------------------------------------------------------------------------

@njit(cache=True)
def _scan(kind, ball, other, lo, hi, cue, opp, red):
    """The cue ball's contacts in events ``lo:hi``: ``(first, second, cushions, total, before_first)``: the rows of
    the first and second object balls it met (-1: none), its cushion contacts before it met the second (all of them
    if it did not), in the whole shot, and before it met the first (-1 if it met none)."""
    first = -1
    second = -1
    cush = 0
    at_second = -1
    before_first = -1
    for k in range(lo, hi):
        kd = kind[k]
        b = ball[k]
        if kd == EV_COLLISION:
            o = other[k]
            if b == cue or o == cue:
                x = o if b == cue else b
                if x != opp and x != red:
                    continue
                if first < 0:
                    first = x
                    before_first = cush
                elif second < 0 and x != first:
                    second = x
                    at_second = cush
        elif kd == EV_CUSHION and b == cue:
            cush += 1
    return first, second, (at_second if second >= 0 else cush), cush, before_first


@njit(cache=True)
def scan_carom(events, cue, opp, red):
    """:func:`_scan` over an ``(M, 3)`` event array (kind, ball, other) of one shot (its columns copied contiguous,
    and the start a plain int: :func:`scan_carom_batch`'s signature of ``_scan``, compiled once)."""
    return _scan(events[:, 0].copy(), events[:, 1].copy(), events[:, 2].copy(), plain(0), events.shape[0], cue, opp,
                 red)


@njit(cache=True)
def scan_carom_batch(offsets, kind, ball, other, cue, opp, red):
    """:func:`_scan` for every row of a batch's concatenated event log (row ``k``: events
    ``offsets[k]:offsets[k+1]``, see :class:`billiards_env.physics.batch.EventBatch`). Returns arrays ``first,
    second, cushions, total, before_first`` (N,), and ``point`` (N,) bool: both balls met with at least three
    cushions before the second."""
    n = offsets.shape[0] - 1
    first = np.empty(n, np.int64)
    second = np.empty(n, np.int64)
    cush = np.empty(n, np.int64)
    total = np.empty(n, np.int64)
    before = np.empty(n, np.int64)
    point = np.empty(n, np.bool_)
    for k in range(n):
        f, s, c, t, b = _scan(kind, ball, other, offsets[k], offsets[k + 1], cue, opp, red)
        first[k] = f
        second[k] = s
        cush[k] = c
        total[k] = t
        before[k] = b
        point[k] = s >= 0 and c >= CUSHIONS_NEEDED
    return first, second, cush, total, before, point


def carom_rows(ids: Sequence[str], shooter: int) -> tuple[int, int, int]:
    """Rows ``(cue, opponent's cue ball, red)`` of a carom scene for ``shooter`` (0 shoots ``"white"``, 1
    ``"yellow"``)."""
    _check_player("shooter", shooter)
    try:
        return ids.index(CAROM_IDS[shooter]), ids.index(CAROM_IDS[1 - shooter]), ids.index("red")
    except ValueError:
        raise RulesError(f"ball ids {list(ids)}: three-cushion needs the ids {', '.join(CAROM_IDS)}") from None


@dataclass(frozen=True, slots=True)
class CaromSummary:
    """What the shooter's cue ball did on one shot.

    ``first`` / ``second``: the object ball it met first and the other one when it met it (``"red"``,
    ``"opponent"`` or None). ``cushions``: its cushion contacts before it met the second ball (all its cushion
    contacts if it did not meet both). ``cushions_total``: in the whole shot. ``cushions_before_first``: before it
    met the first ball (-1 if it met none).
    """

    first: str | None = None
    second: str | None = None
    cushions: int = 0
    cushions_total: int = 0
    cushions_before_first: int = -1

    def __post_init__(self) -> None:
        for name in ("first", "second"):
            v = getattr(self, name)
            if v not in (None, RED, OPPONENT):
                raise RulesError(f"CaromSummary.{name}: {v!r}; use 'red', 'opponent' or None")
        if self.second is not None and (self.first is None or self.second == self.first):
            raise RulesError("CaromSummary.second: needs a first ball, and must be the other object ball")
        if not 0 <= self.cushions <= self.cushions_total:
            raise RulesError(f"CaromSummary.cushions: {self.cushions} must be in 0..cushions_total "
                             f"({self.cushions_total})")
        if (self.cushions_before_first >= 0) != (self.first is not None) or self.cushions_before_first > self.cushions:
            raise RulesError("CaromSummary.cushions_before_first: -1 when no ball was met, else at most cushions")

    @property
    def point(self) -> bool:
        """Both balls met, at least three cushions before the second."""
        return self.second is not None and self.cushions >= CUSHIONS_NEEDED


def summarize_carom(events: np.ndarray, rows: tuple[int, int, int]) -> CaromSummary:
    """The :class:`CaromSummary` of a shot from its ``(M, 3)`` event array (kind, ball, other) and the rows
    ``(cue, opponent's cue ball, red)`` (:func:`carom_rows`)."""
    ev = np.ascontiguousarray(events, dtype=np.int64)
    if ev.ndim != 2 or ev.shape[1] != 3:
        raise RulesError(f"events: expected an (M, 3) array of kind, ball, other; got shape {ev.shape}")
    cue, opp, red = (int(r) for r in rows)
    if len({cue, opp, red}) != 3:
        raise RulesError(f"rows: {rows} must name three different balls (cue, opponent's cue ball, red)")
    f, s, c, t, b = scan_carom(ev, cue, opp, red)
    role = {opp: OPPONENT, red: RED, -1: None}
    return CaromSummary(role[int(f)], role[int(s)], int(c), int(t), int(b))


# --- rules -----------------------------------------------------------------------------------------------------------

def _check_player(name: str, value: object) -> None:
    if isinstance(value, bool) or value not in (0, 1):
        raise RulesError(f"{name}: must be player 0 or 1, got {value!r}")


def _check_int(name: str, value: object, lo: int) -> None:
    if isinstance(value, bool) or not isinstance(value, int) or value < lo:
        raise RulesError(f"ThreeCushionOptions.{name}: must be an integer >= {lo}, got {value!r}")


@checked_keywords
@dataclass(frozen=True)
class ThreeCushionOptions:
    """Options of :class:`ThreeCushion` (defaults: the UMB rules, with a shorter game).

    ``target_points``: the game is won by the first to this many points (UMB matches: 40 or 50). ``break_red_first``:
    the opening shot must meet the red first, before any cushion (UMB: "the starting cannon must be played by
    direct attack on the red"); otherwise a foul. ``miss_is_foul``: a shot that meets neither ball is a foul (not
    in the UMB rules, where it only ends the inning: the same outcome, but counted in ``fouls``).
    ``max_innings``: the game ends when both players have had this many innings (None: no limit); the higher
    score wins, an equal score is a draw. ``equalizing_inning``: when the player who broke reaches the target,
    the other player gets one last inning (UMB, before 2019); reaching it too makes the game a draw.
    """

    target_points: int = 10
    break_red_first: bool = True
    miss_is_foul: bool = False
    max_innings: int | None = None
    equalizing_inning: bool = False

    def __post_init__(self) -> None:
        _check_int("target_points", self.target_points, 1)
        for name in ("break_red_first", "miss_is_foul", "equalizing_inning"):
            if not isinstance(getattr(self, name), bool):
                raise RulesError(f"ThreeCushionOptions.{name}: must be True or False, got {getattr(self, name)!r}")
        if self.max_innings is not None:
            _check_int("max_innings", self.max_innings, 1)


@dataclass(frozen=True, slots=True)
class ThreeCushionState:
    """Where a three-cushion game stands before a shot.

    ``shooter``: the player at the table (0 plays ``"white"``, 1 ``"yellow"``). ``score``: each player's points.
    ``innings``: the innings each player has begun (the breaker's first is counted from the start). ``run``:
    points the shooter has made in this inning. ``breaker``: who broke. ``break_shot``: the next shot is the
    opening shot. ``last_inning``: the shooter is playing the equalizing inning. ``game_over`` / ``winner`` (None
    with ``game_over``: a draw). ``shot_number``: shots played so far.
    """

    shooter: int = 0
    score: tuple[int, int] = (0, 0)
    innings: tuple[int, int] = (1, 0)
    run: int = 0
    breaker: int = 0
    break_shot: bool = True
    last_inning: bool = False
    game_over: bool = False
    winner: int | None = None
    shot_number: int = 0

    def __post_init__(self) -> None:
        _check_player("ThreeCushionState.shooter", self.shooter)
        _check_player("ThreeCushionState.breaker", self.breaker)
        for name in ("score", "innings"):
            v = tuple(getattr(self, name))
            if len(v) != 2 or any(isinstance(x, bool) or not isinstance(x, int) or x < 0 for x in v):
                raise RulesError(f"ThreeCushionState.{name}: {getattr(self, name)!r}; give two integers >= 0")
            object.__setattr__(self, name, v)
        if self.winner is not None:
            _check_player("ThreeCushionState.winner", self.winner)
            if not self.game_over:
                raise RulesError("ThreeCushionState.winner: set only when game_over is True")

    @property
    def opponent(self) -> int:
        return 1 - self.shooter

    @property
    def cue_ball(self) -> str:
        """The id of the shooter's cue ball."""
        return CAROM_IDS[self.shooter]


@dataclass(frozen=True, slots=True)
class ThreeCushionCall:
    """The call on one shot.

    ``point``: the shot scored. ``cushions``: the cue ball's cushion contacts before it met the second ball (all of
    them if it did not meet both). ``score``: both players' points after the shot. ``turn_over``: the other player
    comes to the table. ``foul`` / ``fouls``: fouls of the shot (a foul scores nothing and ends the inning).
    ``reason``: :data:`POINT`, :data:`NO_POINT`, the first foul, or what ended the game. ``run``: the shooter's
    points in this inning after the shot. ``first`` / ``second``: the balls met (``"red"`` / ``"opponent"``).
    ``innings``: innings begun after the shot. ``next_shooter``, ``game_over``, ``winner`` (None: a draw or the
    game goes on).
    """

    point: bool
    cushions: int
    score: tuple[int, int]
    turn_over: bool
    foul: bool
    fouls: tuple[str, ...]
    reason: str
    shooter: int
    next_shooter: int
    run: int
    innings: tuple[int, int]
    first: str | None = None
    second: str | None = None
    game_over: bool = False
    winner: int | None = None


class ThreeCushion:
    """UMB three-cushion. ``ThreeCushion(ThreeCushionOptions(...))``: :meth:`initial_state`, :meth:`call`,
    :meth:`next_state`. Stateless apart from its frozen options."""

    game = THREE_CUSHION

    def __init__(self, options: ThreeCushionOptions | None = None) -> None:
        self.options = options if options is not None else ThreeCushionOptions()
        if not isinstance(self.options, ThreeCushionOptions):
            raise RulesError(f"ThreeCushion options: expected ThreeCushionOptions, got {type(self.options).__name__}")

    def __repr__(self) -> str:
        return f"ThreeCushion({self.options!r})"

    def initial_state(self, first_shooter: int = 0) -> ThreeCushionState:
        """The state before the opening shot: ``first_shooter`` breaks (from :func:`~billiards_env.games.carom_layout.
        carom_start_positions`)."""
        _check_player("first_shooter", first_shooter)
        innings = (1, 0) if first_shooter == 0 else (0, 1)
        return ThreeCushionState(shooter=first_shooter, innings=innings, breaker=first_shooter)

    def call(self, state: ThreeCushionState, summary: CaromSummary) -> ThreeCushionCall:
        """The call on the shot ``summary`` played from ``state``."""
        if state.game_over:
            raise RulesError("state: the game is over (state.game_over); start a new one with initial_state()")
        opts = self.options
        fouls = []
        if state.break_shot and opts.break_red_first and not (summary.first == RED
                                                               and summary.cushions_before_first == 0):
            fouls.append(BREAK_NOT_ON_RED)
        if opts.miss_is_foul and summary.first is None:
            fouls.append(NO_CONTACT)
        point = summary.point and not fouls
        me, opp = state.shooter, state.opponent
        score = list(state.score)
        score[me] += int(point)
        innings = list(state.innings)
        run = state.run + int(point)
        reason = POINT if point else (fouls[0] if fouls else NO_POINT)
        turn_over, game_over, winner = not point, False, None
        if point and score[me] >= opts.target_points:
            reason = TARGET_REACHED
            if state.last_inning:  # the equalizing inning reached the target too: a draw
                game_over = True
            elif opts.equalizing_inning and me == state.breaker:
                turn_over, reason = True, EQUALIZING  # the other player gets the equalizing inning
            else:
                game_over, winner = True, me
        elif not point:
            if state.last_inning:  # the equalizing inning ended short of the target
                game_over, winner, reason = True, opp, TARGET_REACHED
            elif opts.max_innings is not None and me != state.breaker and innings[me] >= opts.max_innings:
                game_over, reason = True, INNINGS_LIMIT
                winner = None if score[0] == score[1] else (0 if score[0] > score[1] else 1)
        if turn_over and not game_over:
            innings[opp] += 1
        return ThreeCushionCall(point, summary.cushions, (score[0], score[1]), turn_over or game_over, bool(fouls),
                                tuple(fouls), reason, me, opp if turn_over or game_over else me, run,
                                (innings[0], innings[1]), summary.first, summary.second, game_over, winner)

    def next_state(self, state: ThreeCushionState, call: ThreeCushionCall) -> ThreeCushionState:
        """The state after ``call`` (made on a shot from ``state``)."""
        if call.shooter != state.shooter:
            raise RulesError(f"call: made for player {call.shooter}'s shot but state.shooter is {state.shooter}; "
                             "pass the state the call was made from")
        last = state.last_inning or call.reason == EQUALIZING  # the breaker reached the target
        return replace(state, shooter=call.next_shooter, score=call.score, innings=call.innings,
                       run=0 if call.turn_over else call.run, break_shot=False, last_inning=last,
                       game_over=call.game_over, winner=call.winner, shot_number=state.shot_number + 1)

    def play(self, state: ThreeCushionState, summary: CaromSummary) -> tuple[ThreeCushionCall, ThreeCushionState]:
        """:meth:`call` and :meth:`next_state` in one."""
        c = self.call(state, summary)
        return c, self.next_state(state, c)


__all__ = ["THREE_CUSHION", "CAROM_IDS", "CUSHIONS_NEEDED", "POINT", "NO_POINT", "TARGET_REACHED", "EQUALIZING",
           "INNINGS_LIMIT", "BREAK_NOT_ON_RED", "NO_CONTACT", "FOULS", "REASONS", "RED", "OPPONENT",
           "scan_carom",
           "scan_carom_batch", "carom_rows", "CaromSummary", "summarize_carom", "ThreeCushionOptions",
           "ThreeCushionState", "ThreeCushionCall", "ThreeCushion"]
