"""The rules of 9-ball and 8-ball compiled: :func:`play` is :meth:`~billiards_env.rules.Ruleset.play` of
:class:`~billiards_env.rules.NineBall` and :class:`~billiards_env.rules.EightBall` on integers, for code that
judges many shots in compiled loops (the native vector env plays whole games per table in one call).

The game state is an int64 row (columns ``S_*``): the balls on the table as a bit mask of their numbers, the shooter,
ball in hand (:data:`BIH_NO`, :data:`BIH_ANYWHERE`, :data:`BIH_KITCHEN`), the 8-ball groups (:data:`GROUPS_OPEN`, or
which group player 0 has), the fouls in a row, the break, the push-out flags, game over, the winner (-1: none) and
the shot number. The options are an int64 row too (columns ``O_*``; :func:`options_row`). A call is an int64 row
(columns ``C_*``): the reason is an index into :data:`REASONS`, the fouls a bit mask in the order of
:data:`~billiards_env.rules.state.FOULS`, the respotted balls a bit mask. A shot's facts are the
:class:`~billiards_env.rules.ShotSummary`'s: the first ball hit (its number, -1: none), the balls (cue included, as
0) that reached a cushion after it as a bit mask, the object balls pocketed in the order they dropped with their
pockets, the scratch; and the declarations (a push-out, the called pocket, -1: none).

The Python rules stay the definition: :func:`state_row`, :func:`game_state` and :func:`call_of` convert, and
``tests/rules/test_pool_judge.py`` holds the two equal, call for call and state for state, on many random shots
from random states. No input checks here (the Python rules raise on impossible input; the callers give none).
"""
from __future__ import annotations

from typing import Any

import numpy as np
from numba import njit

from billiards_env.physics.plain import plain

from .eight_ball import EightBall, EightBallOptions
from .nine_ball import NineBall, NineBallOptions
from .state import (ANYWHERE, EIGHT_BALL, EIGHT_EARLY, EIGHT_NOT_CALLED, EIGHT_ON_BREAK, EIGHT_ON_FOUL,
                    EIGHT_POCKETED, EIGHT_WRONG_POCKET, FOULS, ILLEGAL_BREAK, KITCHEN, LEGAL, NINE_BALL, NINE_POCKETED,
                    NO_CONTACT, NO_RAIL, PUSH_OUT, SCRATCH, SOLIDS, STRIPES, THREE_FOULS, WRONG_BALL_FIRST, Call,
                    BallInHand, GameState)

#: Columns of a game state row.
S_GAME, S_ON, S_SHOOTER, S_BIH, S_GROUPS, S_FOULS0, S_FOULS1, S_BREAK, S_PUSH_AVAILABLE, S_PUSH_PENDING, S_OVER, \
    S_WINNER, S_SHOT = range(13)
N_STATE = 13
#: Games, ball in hand, groups (the group of player 0; player 1 has the other).
GAME_NINE, GAME_EIGHT = 0, 1
BIH_NO, BIH_ANYWHERE, BIH_KITCHEN = 0, 1, 2
GROUPS_OPEN, GROUPS_SOLIDS, GROUPS_STRIPES = 0, 1, 2
#: Columns of an options row.
O_GAME, O_PUSH_OUT, O_THREE_FOULS, O_BREAK_RAILS, O_CALL_EIGHT, O_EIGHT_BREAK_WINS, O_BREAK_SCRATCH_BIH, \
    O_ILLEGAL_BREAK_BIH = range(8)
N_OPTIONS = 8
#: Columns of a call row.
C_LEGAL, C_FOUL, C_REASON, C_FOULS, C_SHOOTER, C_TURN_OVER, C_NEXT, C_BIH, C_RESPOT, C_CUE_POCKETED, C_OVER, \
    C_WINNER, C_GROUPS, C_PUSH = range(14)
N_CALL = 14
#: The calls' reasons (``Call.reason``), by index.
REASONS = (LEGAL, PUSH_OUT, SCRATCH, NO_CONTACT, WRONG_BALL_FIRST, NO_RAIL, ILLEGAL_BREAK, NINE_POCKETED,
           EIGHT_POCKETED, EIGHT_ON_BREAK, EIGHT_EARLY, EIGHT_ON_FOUL, EIGHT_WRONG_POCKET, EIGHT_NOT_CALLED,
           THREE_FOULS)
R_LEGAL, R_PUSH_OUT, R_SCRATCH, R_NO_CONTACT, R_WRONG_BALL_FIRST, R_NO_RAIL, R_ILLEGAL_BREAK, R_NINE_POCKETED, \
    R_EIGHT_POCKETED, R_EIGHT_ON_BREAK, R_EIGHT_EARLY, R_EIGHT_ON_FOUL, R_EIGHT_WRONG_POCKET, R_EIGHT_NOT_CALLED, \
    R_THREE_FOULS = range(15)
#: Foul bits, in the order of ``FOULS`` (scratch, no contact, wrong ball first, no rail, illegal break).
F_SCRATCH, F_NO_CONTACT, F_WRONG_BALL, F_NO_RAIL, F_ILLEGAL_BREAK = 1, 2, 4, 8, 16
#: Ball numbers' bit masks: solids 1-7, stripes 9-15, the 8.
SOLIDS_MASK = sum(1 << n for n in range(1, 8))
STRIPES_MASK = sum(1 << n for n in range(9, 16))
EIGHT_BIT = 1 << 8

_BIH_CODE = {False: BIH_NO, ANYWHERE: BIH_ANYWHERE, KITCHEN: BIH_KITCHEN}
_BIH_VALUE: tuple[BallInHand, ...] = (False, ANYWHERE, KITCHEN)
_GROUPS_VALUE = (None, (SOLIDS, STRIPES), (STRIPES, SOLIDS))


# --- the rules on integers -----------------------------------------------------------------------------------------

@njit(cache=True)
def _lowest(mask: int) -> int:
    """The lowest ball number in a mask of ball bits, -1 if none."""
    for n in range(64):
        if mask & (1 << n):
            return n
    return -1


@njit(cache=True)
def _highest(mask: int) -> int:
    """The highest ball number in a mask of ball bits, -1 if none."""
    for n in range(63, -1, -1):
        if mask & (1 << n):
            return n
    return -1


@njit(cache=True)
def _group_mask(groups: int, player: int) -> int:
    """The balls of ``player``'s group under ``groups`` (:data:`GROUPS_SOLIDS`: player 0 has the solids)."""
    solids = (groups == GROUPS_SOLIDS) == (player == 0)
    return SOLIDS_MASK if solids else STRIPES_MASK


@njit(cache=True)
def legal_mask_for(state: np.ndarray, player: int) -> int:
    """The balls ``player`` may hit first if it were to shoot (a mask of their numbers): 9-ball the lowest on the
    table; 8-ball any on the break, any but the 8 on an open table, the player's group while it has balls on the
    table, then the 8 (:func:`~billiards_env.rules.legal_targets` of the state with ``shooter=player``)."""
    on = state[S_ON]
    if state[S_GAME] == GAME_NINE:
        low = _lowest(on)
        return 0 if low < 0 else 1 << low
    if state[S_BREAK]:
        return on
    if state[S_GROUPS] == GROUPS_OPEN:
        others = on & ~EIGHT_BIT
    else:
        others = on & _group_mask(state[S_GROUPS], player)
    return others if others != 0 else on & EIGHT_BIT


@njit(cache=True)
def legal_mask(state: np.ndarray) -> int:
    """The balls the shooter may hit first (a mask of their numbers; :func:`legal_mask_for` the shooter)."""
    return legal_mask_for(state, state[S_SHOOTER])


@njit(cache=True)
def needs_called_pocket(state: np.ndarray, options: np.ndarray) -> bool:
    """8-ball with called 8s: the shooter is on the 8 (``EightBall.needs_called_pocket``); 9-ball: never."""
    return state[S_GAME] == GAME_EIGHT and options[O_CALL_EIGHT] != 0 and not state[S_BREAK] and \
        legal_mask(state) == EIGHT_BIT


@njit(cache=True)
def _contact_fouls(first: int, rails: int, n_pocketed: int, cue_pocketed: bool, targets: int) -> int:
    fouls = 0
    if cue_pocketed:
        fouls |= F_SCRATCH
    if first < 0:
        fouls |= F_NO_CONTACT
    else:
        if not (targets >> first) & 1:
            fouls |= F_WRONG_BALL
        if n_pocketed == 0 and rails == 0:
            fouls |= F_NO_RAIL
    return fouls


@njit(cache=True)
def _break_fouls(first: int, rails: int, n_pocketed: int, cue_pocketed: bool, targets: int, check_first: bool,
                 min_rail_balls: int) -> int:
    fouls = 0
    if cue_pocketed:
        fouls |= F_SCRATCH
    if first < 0:
        fouls |= F_NO_CONTACT
    elif check_first and not (targets >> first) & 1:
        fouls |= F_WRONG_BALL
    n_rail = 0
    for n in range(1, 64):
        if (rails >> n) & 1:
            n_rail += 1
    if n_pocketed == 0 and n_rail < min_rail_balls:
        fouls |= F_ILLEGAL_BREAK
    return fouls


@njit(cache=True)
def _first_foul(fouls: int) -> int:
    """The reason of a foul mask: its first foul in ``FOULS`` order."""
    for k, reason in enumerate((R_SCRATCH, R_NO_CONTACT, R_WRONG_BALL_FIRST, R_NO_RAIL, R_ILLEGAL_BREAK)):
        if fouls & (1 << k):
            return reason
    return R_LEGAL


@njit(cache=True)
def _call(out: np.ndarray, legal: bool, foul: bool, reason: int, fouls: int, shooter: int, turn_over: bool,
          nxt: int, bih: int, respot: int, cue_pocketed: bool, over: bool, winner: int, groups: int,
          push: bool) -> None:
    out[C_LEGAL] = legal
    out[C_FOUL] = foul
    out[C_REASON] = reason
    out[C_FOULS] = fouls
    out[C_SHOOTER] = shooter
    out[C_TURN_OVER] = turn_over
    out[C_NEXT] = nxt
    out[C_BIH] = bih
    out[C_RESPOT] = respot
    out[C_CUE_POCKETED] = cue_pocketed
    out[C_OVER] = over
    out[C_WINNER] = winner
    out[C_GROUPS] = groups
    out[C_PUSH] = push


# The helpers below are called with constants wrapped in ``plain`` (:mod:`billiards_env.physics.plain`): each is
# compiled once, for int64 and bool, instead of once per combination of literal constants.
@njit(cache=True)
def _end(out: np.ndarray, state: np.ndarray, reason: int, winner: int, fouls: int, legal: bool, groups: int,
         cue_pocketed: bool) -> None:
    s = state[S_SHOOTER]
    _call(out, legal, fouls != 0, reason, fouls, s, plain(True), 1 - s, plain(BIH_NO), plain(0), cue_pocketed,
          plain(True), winner, groups, plain(False))


@njit(cache=True)
def _foul(out: np.ndarray, state: np.ndarray, fouls: int, respot: int, bih: int, groups: int,
          cue_pocketed: bool) -> None:
    s = state[S_SHOOTER]
    _call(out, plain(False), plain(True), _first_foul(fouls), fouls, s, plain(True), 1 - s, bih, respot, cue_pocketed,
          plain(False), plain(-1), groups, plain(False))


@njit(cache=True)
def _clean(out: np.ndarray, state: np.ndarray, reason: int, keep: bool, respot: int, groups: int, push: bool) -> None:
    s = state[S_SHOOTER]
    _call(out, plain(True), plain(False), reason, plain(0), s, not keep, s if keep else 1 - s, plain(BIH_NO), respot,
          plain(False), plain(False), plain(-1), groups, push)


@njit(cache=True)
def _call_nine(out: np.ndarray, state: np.ndarray, options: np.ndarray, first: int, rails: int, pocketed: np.ndarray,
               n_pocketed: int, cue_pocketed: bool, push: bool) -> None:
    targets = legal_mask(state)
    if state[S_BREAK]:
        fouls = _break_fouls(first, rails, n_pocketed, cue_pocketed, targets, plain(True), options[O_BREAK_RAILS])
    elif push:
        fouls = F_SCRATCH if cue_pocketed else 0
    else:
        fouls = _contact_fouls(first, rails, n_pocketed, cue_pocketed, targets)
    me = state[S_SHOOTER]
    if fouls and options[O_THREE_FOULS] and state[S_FOULS0 + me] >= 2:
        _end(out, state, plain(R_THREE_FOULS), 1 - me, fouls, plain(False), plain(GROUPS_OPEN), cue_pocketed)
        return
    money = _highest(state[S_ON])
    money_down = False
    for i in range(n_pocketed):
        if pocketed[i] == money:
            money_down = True
    if money_down and not fouls and not push:
        _end(out, state, plain(R_NINE_POCKETED), me, plain(0), plain(True), plain(GROUPS_OPEN), cue_pocketed)
        return
    respot = (1 << money) if money_down else 0
    if fouls:
        _foul(out, state, fouls, respot, plain(BIH_ANYWHERE), plain(GROUPS_OPEN), cue_pocketed)
    elif push:
        _clean(out, state, plain(R_PUSH_OUT), plain(False), respot, plain(GROUPS_OPEN), plain(True))
    else:
        _clean(out, state, plain(R_LEGAL), n_pocketed > 0, respot, plain(GROUPS_OPEN), plain(False))


@njit(cache=True)
def _call_eight(out: np.ndarray, state: np.ndarray, options: np.ndarray, first: int, rails: int,
                pocketed: np.ndarray, pockets: np.ndarray, n_pocketed: int, cue_pocketed: bool, called: int) -> None:
    me = state[S_SHOOTER]
    eight_at = -1
    for i in range(n_pocketed):
        if pocketed[i] == 8:
            eight_at = i
    if state[S_BREAK]:
        fouls = _break_fouls(first, rails, n_pocketed, cue_pocketed, plain(0), plain(False), options[O_BREAK_RAILS])
        if eight_at >= 0 and not fouls and options[O_EIGHT_BREAK_WINS]:
            _end(out, state, plain(R_EIGHT_ON_BREAK), me, plain(0), plain(True), plain(GROUPS_OPEN), cue_pocketed)
            return
        respot = EIGHT_BIT if eight_at >= 0 else 0
        if fouls:
            bih = options[O_BREAK_SCRATCH_BIH] if _first_foul(fouls) == R_SCRATCH else options[O_ILLEGAL_BREAK_BIH]
            _foul(out, state, fouls, respot, bih, plain(GROUPS_OPEN), cue_pocketed)
        else:
            _clean(out, state, plain(R_LEGAL), n_pocketed > 0, respot, plain(GROUPS_OPEN), plain(False))
        return
    targets = legal_mask(state)
    fouls = _contact_fouls(first, rails, n_pocketed, cue_pocketed, targets)
    groups = state[S_GROUPS]
    if eight_at >= 0:  # the game ends: won only on a clean, called shot at the 8
        if targets != EIGHT_BIT:
            _end(out, state, plain(R_EIGHT_EARLY), 1 - me, fouls, plain(False), groups, cue_pocketed)
        elif fouls:
            _end(out, state, plain(R_EIGHT_ON_FOUL), 1 - me, fouls, plain(False), groups, cue_pocketed)
        elif options[O_CALL_EIGHT] and called < 0:
            _end(out, state, plain(R_EIGHT_NOT_CALLED), 1 - me, plain(0), plain(False), groups, cue_pocketed)
        elif options[O_CALL_EIGHT] and pockets[eight_at] != called:
            _end(out, state, plain(R_EIGHT_WRONG_POCKET), 1 - me, plain(0), plain(False), groups, cue_pocketed)
        else:
            _end(out, state, plain(R_EIGHT_POCKETED), me, plain(0), plain(True), groups, cue_pocketed)
        return
    if fouls:
        if options[O_THREE_FOULS] and state[S_FOULS0 + me] >= 2:
            _end(out, state, plain(R_THREE_FOULS), 1 - me, fouls, plain(False), groups, cue_pocketed)
        else:
            _foul(out, state, fouls, plain(0), plain(BIH_ANYWHERE), groups, cue_pocketed)
        return
    if groups == GROUPS_OPEN:
        if n_pocketed == 0:
            _clean(out, state, plain(R_LEGAL), plain(False), plain(0), plain(GROUPS_OPEN), plain(False))
            return
        solids = pocketed[0] < 8
        chosen = GROUPS_SOLIDS if solids == (me == 0) else GROUPS_STRIPES
        _clean(out, state, plain(R_LEGAL), plain(True), plain(0), chosen, plain(False))
        return
    mine = _group_mask(groups, me)
    scored = plain(False)
    for i in range(n_pocketed):
        if (mine >> pocketed[i]) & 1:
            scored = True
    _clean(out, state, plain(R_LEGAL), scored, plain(0), groups, plain(False))


@njit(cache=True)
def next_state(state: np.ndarray, options: np.ndarray, call: np.ndarray, pocketed: np.ndarray, n_pocketed: int,
               out: np.ndarray) -> None:
    """The state after ``call`` made on a shot from ``state`` into ``out`` (``Ruleset.next_state``): the pocketed
    balls off the table but the respotted ones, the shooter's fouls in a row counted (or reset), the push-out
    flags, the shot number."""
    on = state[S_ON]
    for i in range(n_pocketed):
        on &= ~(1 << pocketed[i])
    on |= call[C_RESPOT]
    s = call[C_SHOOTER]
    fouls0 = state[S_FOULS0]
    fouls1 = state[S_FOULS1]
    if s == 0:
        fouls0 = fouls0 + 1 if call[C_FOUL] else 0
    else:
        fouls1 = fouls1 + 1 if call[C_FOUL] else 0
    push_next = state[S_GAME] == GAME_NINE and state[S_BREAK] != 0 and options[O_PUSH_OUT] != 0 and \
        not call[C_OVER]
    out[S_GAME] = state[S_GAME]
    out[S_ON] = on
    out[S_SHOOTER] = call[C_NEXT]
    out[S_BIH] = call[C_BIH]
    out[S_GROUPS] = call[C_GROUPS]
    out[S_FOULS0] = fouls0
    out[S_FOULS1] = fouls1
    out[S_BREAK] = 0
    out[S_PUSH_AVAILABLE] = push_next
    out[S_PUSH_PENDING] = call[C_PUSH] != 0 and not call[C_FOUL] and not call[C_OVER]
    out[S_OVER] = call[C_OVER]
    out[S_WINNER] = call[C_WINNER]
    out[S_SHOT] = state[S_SHOT] + 1


@njit(cache=True)
def play(state: np.ndarray, options: np.ndarray, first: int, rails: int, pocketed: np.ndarray,
         pockets: np.ndarray, n_pocketed: int, cue_pocketed: bool, push: bool, called: int, call: np.ndarray,
         after: np.ndarray) -> None:
    """The call on a shot (``Ruleset.call``) into ``call`` and the state after it (``Ruleset.next_state``) into
    ``after``. The shot: ``first`` (the number of the first ball hit, -1: none), ``rails`` (bit mask of the numbers
    that reached a cushion after it, the cue ball as 0), the ``n_pocketed`` object balls ``pocketed`` in the order
    they dropped and their ``pockets``, ``cue_pocketed``; the declarations: ``push`` (a push-out, allowed only when
    the state says so: the caller checks), ``called`` (the pocket called for the 8, -1: none)."""
    if state[S_GAME] == GAME_NINE:
        _call_nine(call, state, options, first, rails, pocketed, n_pocketed, cue_pocketed, push)
    else:
        _call_eight(call, state, options, first, rails, pocketed, pockets, n_pocketed, cue_pocketed, called)
    next_state(state, options, call, pocketed, n_pocketed, after)


@njit(cache=True)
def initial_row(st: np.ndarray, game: int, full: int, first: int) -> None:
    """Compiled twin of :meth:`~billiards_env.rules.Ruleset.initial_state` ``(first_shooter=first)`` into the state
    row ``st``: the balls of ``full`` (a mask) on, ball in hand in the kitchen, the break."""
    st[:] = 0
    st[S_GAME] = game
    st[S_ON] = full
    st[S_SHOOTER] = first
    st[S_BIH] = BIH_KITCHEN
    st[S_GROUPS] = GROUPS_OPEN
    st[S_BREAK] = 1
    st[S_WINNER] = -1


# --- the Python rules' values --------------------------------------------------------------------------------------

def options_row(rules: Any) -> np.ndarray:
    """The options row of a ruleset (:class:`NineBall` or :class:`EightBall`)."""
    out = np.zeros(N_OPTIONS, np.int64)
    o = rules.options
    if isinstance(rules, NineBall):
        assert isinstance(o, NineBallOptions)
        out[O_GAME] = GAME_NINE
        out[O_PUSH_OUT] = o.push_out
        out[O_THREE_FOULS] = o.three_foul_rule
        out[O_BREAK_RAILS] = o.break_rail_balls
    elif isinstance(rules, EightBall):
        assert isinstance(o, EightBallOptions)
        out[O_GAME] = GAME_EIGHT
        out[O_THREE_FOULS] = o.three_foul_rule
        out[O_BREAK_RAILS] = o.break_rail_balls
        out[O_CALL_EIGHT] = o.call_eight
        out[O_EIGHT_BREAK_WINS] = o.eight_on_break == "win"
        out[O_BREAK_SCRATCH_BIH] = _BIH_CODE[o.break_scratch_ball_in_hand]
        out[O_ILLEGAL_BREAK_BIH] = _BIH_CODE[o.illegal_break_ball_in_hand]
    else:
        raise TypeError(f"options_row: 9-ball or 8-ball rules expected, got {type(rules).__name__}")
    return out


def mask_of(numbers: Any) -> int:
    """The bit mask of ball numbers."""
    m = 0
    for n in numbers:
        m |= 1 << int(n)
    return m


def numbers_of(mask: int) -> tuple[int, ...]:
    """The ball numbers of a bit mask, ascending."""
    return tuple(n for n in range(int(mask).bit_length()) if (int(mask) >> n) & 1)


def state_row(state: GameState) -> np.ndarray:
    """The int64 row of a :class:`GameState`."""
    out = np.zeros(N_STATE, np.int64)
    out[S_GAME] = GAME_NINE if state.game == NINE_BALL else GAME_EIGHT
    out[S_ON] = mask_of(state.on_table)
    out[S_SHOOTER] = state.shooter
    out[S_BIH] = _BIH_CODE[state.ball_in_hand]
    out[S_GROUPS] = _GROUPS_VALUE.index(state.groups)
    out[S_FOULS0], out[S_FOULS1] = state.fouls_in_a_row
    out[S_BREAK] = state.break_shot
    out[S_PUSH_AVAILABLE] = state.push_out_available
    out[S_PUSH_PENDING] = state.push_out_pending
    out[S_OVER] = state.game_over
    out[S_WINNER] = -1 if state.winner is None else state.winner
    out[S_SHOT] = state.shot_number
    return out


def game_state(row: np.ndarray) -> GameState:
    """The :class:`GameState` of a state row (the values a ruleset gives: Python ints and bools)."""
    r = [int(v) for v in row]
    return GameState.trusted(NINE_BALL if r[S_GAME] == GAME_NINE else EIGHT_BALL, numbers_of(r[S_ON]),
                              r[S_SHOOTER], _BIH_VALUE[r[S_BIH]], _GROUPS_VALUE[r[S_GROUPS]],
                              (r[S_FOULS0], r[S_FOULS1]), bool(r[S_BREAK]), bool(r[S_PUSH_AVAILABLE]),
                              bool(r[S_PUSH_PENDING]), bool(r[S_OVER]), None if r[S_WINNER] < 0 else r[S_WINNER],
                              r[S_SHOT])


def call_of(row: np.ndarray, pocketed: tuple[int, ...]) -> Call:
    """The :class:`Call` of a call row (``pocketed``: the shot's object balls in the order they dropped)."""
    r = [int(v) for v in row]
    return Call(legal=bool(r[C_LEGAL]), foul=bool(r[C_FOUL]), reason=REASONS[r[C_REASON]],
                fouls=tuple(f for k, f in enumerate(FOULS) if (r[C_FOULS] >> k) & 1), shooter=r[C_SHOOTER],
                turn_over=bool(r[C_TURN_OVER]), next_shooter=r[C_NEXT], ball_in_hand=_BIH_VALUE[r[C_BIH]],
                pocketed=tuple(pocketed), respot=tuple(n for n in pocketed if (r[C_RESPOT] >> n) & 1),
                cue_pocketed=bool(r[C_CUE_POCKETED]), game_over=bool(r[C_OVER]),
                winner=None if r[C_WINNER] < 0 else r[C_WINNER], groups=_GROUPS_VALUE[r[C_GROUPS]],
                push_out=bool(r[C_PUSH]))


def ball_in_hand_value(code: int) -> Any:
    """``GameState.ball_in_hand`` of a :data:`BIH_NO` / :data:`BIH_ANYWHERE` / :data:`BIH_KITCHEN` code."""
    return _BIH_VALUE[int(code)]


def groups_value(code: int) -> tuple[str, str] | None:
    """``GameState.groups`` of a groups code."""
    return _GROUPS_VALUE[int(code)]


__all__ = ["play", "next_state", "initial_row", "legal_mask", "legal_mask_for", "needs_called_pocket",
           "options_row", "state_row", "game_state", "call_of", "mask_of", "numbers_of", "ball_in_hand_value",
           "groups_value", "REASONS", "N_STATE", "N_CALL", "N_OPTIONS", "GAME_NINE", "GAME_EIGHT", "BIH_NO",
           "BIH_ANYWHERE", "BIH_KITCHEN", "GROUPS_OPEN", "GROUPS_SOLIDS", "GROUPS_STRIPES", "SOLIDS_MASK",
           "STRIPES_MASK", "EIGHT_BIT"]
