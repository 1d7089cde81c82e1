"""The rules of 9-ball and 8-ball compiled: :func:`play` is :meth:`~billiards_env.rules.Ruleset.play` of
:class:`~billiards_env.rules.NineBall` and :class:`~billiards_env.rules.EightBall` on integers, for code that
judges many shots in compiled loops (the native vector env plays whole games per table in one call).

The game state is a record (:data:`GAME_STATE_ROW`, int64 fields read by name: ``state["shooter"]``): the balls on
the table as a bit mask of their numbers, the shooter, ball in hand (:data:`BIH_NO`, :data:`BIH_ANYWHERE`,
:data:`BIH_KITCHEN`), the 8-ball groups (:data:`GROUPS_OPEN`, or which group player 0 has), each player's fouls in a
row, the break, the push-out flags, game over, the winner (-1: none) and the shot number. The options are a record
too (:data:`RULE_OPTIONS`; :func:`options_row`). A call is a record (:data:`CALL_ROW`): the reason is an index into
:data:`REASONS`, the fouls a bit mask in the order of :data:`~billiards_env.rules.state.FOULS`, the respotted balls a
bit mask. A shot's facts are the :class:`~billiards_env.rules.ShotSummary`'s: the first ball hit (its number, -1:
none), the balls (cue included, as 0) that reached a cushion after it as a bit mask, the object balls pocketed in the
order they dropped with their pockets, the scratch; and the declarations (a push-out, the called pocket, -1: none).

The native vector env keeps its tables' states as one array of :data:`GAME_STATE_ROW` records; numba compiles a
record's field to a load at its offset, as it does the packed game config (:mod:`billiards_env.envs._game_config`).
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
from billiards_env.physics.kernel_logs import leaf_public

#: A game state: the game, the balls on the table (a mask of their numbers), the shooter, ball in hand, the groups,
#: each player's fouls in a row, the break, a push-out available, a push-out pending, game over, the winner, the shot.
GAME_STATE_ROW = np.dtype([(name, np.int64) for name in (
    "game", "on", "shooter", "bih", "groups", "fouls0", "fouls1", "break_shot", "push_available", "push_pending",
    "over", "winner", "shot")])
#: A ruleset's options: the game, 9-ball's push-out, the three-foul rule, the balls that must reach a cushion on the
#: break, 8-ball's called 8, the 8 on the break wins, ball in hand after a break scratch and after an illegal break.
RULE_OPTIONS = np.dtype([(name, np.int64) for name in (
    "game", "push_out", "three_fouls", "break_rails", "call_eight", "eight_break_wins", "break_scratch_bih",
    "illegal_break_bih")])
#: A call: legal, a foul, the reason, the fouls, the shooter, the turn over, the next shooter, ball in hand, the
#: respotted balls, the cue ball pocketed, game over, the winner, the groups after the shot, a push-out.
CALL_ROW = np.dtype([(name, np.int64) for name in (
    "legal", "foul", "reason", "fouls", "shooter", "turn_over", "next", "bih", "respot", "cue_pocketed", "over",
    "winner", "groups", "push")])
#: Games, ball in hand, groups (the group of player 0; player 1 has the other).
GAME_NINE, GAME_EIGHT = 0, 1
BIH_NO, BIH_ANYWHERE, BIH_KITCHEN = 0, 1, 2
GROUPS_OPEN, GROUPS_SOLIDS, GROUPS_STRIPES = 0, 1, 2
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
def legal_mask_for(state: np.void, player: int) -> int:
    """The balls ``player`` may hit first if it were to shoot (a mask of their numbers): 9-ball the lowest on the
    table; 8-ball any on the break, any but the 8 on an open table, the player's group while it has balls on the
    table, then the 8 (:func:`~billiards_env.rules.legal_targets` of the state with ``shooter=player``)."""
    on = state["on"]
    if state["game"] == GAME_NINE:
        low = _lowest(on)
        return 0 if low < 0 else 1 << low
    if state["break_shot"]:
        return on
    if state["groups"] == GROUPS_OPEN:
        others = on & ~EIGHT_BIT
    else:
        others = on & _group_mask(state["groups"], player)
    return others if others != 0 else on & EIGHT_BIT


@njit(cache=True)
def legal_mask(state: np.void) -> int:
    """The balls the shooter may hit first (a mask of their numbers; :func:`legal_mask_for` the shooter)."""
    return legal_mask_for(state, state["shooter"])


@njit(cache=True)
def needs_called_pocket(state: np.void, options: np.void) -> bool:
    """8-ball with called 8s: the shooter is on the 8 (``EightBall.needs_called_pocket``); 9-ball: never."""
    return state["game"] == GAME_EIGHT and options["call_eight"] != 0 and not state["break_shot"] and \
        legal_mask(state) == EIGHT_BIT


@njit(cache=True)
def _fouls_in_a_row(state: np.void, player: int) -> int:
    """``player``'s fouls in a row."""
    return state["fouls0"] if player == 0 else state["fouls1"]


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
def _call(out: np.void, legal: bool, foul: bool, reason: int, fouls: int, shooter: int, turn_over: bool,
          nxt: int, bih: int, respot: int, cue_pocketed: bool, over: bool, winner: int, groups: int,
          push: bool) -> None:
    out["legal"] = legal
    out["foul"] = foul
    out["reason"] = reason
    out["fouls"] = fouls
    out["shooter"] = shooter
    out["turn_over"] = turn_over
    out["next"] = nxt
    out["bih"] = bih
    out["respot"] = respot
    out["cue_pocketed"] = cue_pocketed
    out["over"] = over
    out["winner"] = winner
    out["groups"] = groups
    out["push"] = push


# The helpers below are called with constants wrapped in ``plain`` (:mod:`billiards_env.physics.plain`): each is
# compiled once, for int64 and bool, instead of once per combination of literal constants.
@njit(cache=True)
def _end(out: np.void, state: np.void, reason: int, winner: int, fouls: int, legal: bool, groups: int,
         cue_pocketed: bool) -> None:
    s = state["shooter"]
    _call(out, legal, fouls != 0, reason, fouls, s, plain(True), 1 - s, plain(BIH_NO), plain(0), cue_pocketed,
          plain(True), winner, groups, plain(False))


@njit(cache=True)
def _foul(out: np.void, state: np.void, fouls: int, respot: int, bih: int, groups: int,
          cue_pocketed: bool) -> None:
    s = state["shooter"]
    _call(out, plain(False), plain(True), _first_foul(fouls), fouls, s, plain(True), 1 - s, bih, respot, cue_pocketed,
          plain(False), plain(-1), groups, plain(False))


@njit(cache=True)
def _clean(out: np.void, state: np.void, reason: int, keep: bool, respot: int, groups: int, push: bool) -> None:
    s = state["shooter"]
    _call(out, plain(True), plain(False), reason, plain(0), s, not keep, s if keep else 1 - s, plain(BIH_NO), respot,
          plain(False), plain(False), plain(-1), groups, push)


@leaf_public
def _call_nine(out: np.void, state: np.void, options: np.void, first: int, rails: int, pocketed: np.ndarray,
               n_pocketed: int, cue_pocketed: bool, push: bool) -> None:
    targets = legal_mask(state)
    if state["break_shot"]:
        fouls = _break_fouls(first, rails, n_pocketed, cue_pocketed, targets, plain(True), options["break_rails"])
    elif push:
        fouls = F_SCRATCH if cue_pocketed else 0
    else:
        fouls = _contact_fouls(first, rails, n_pocketed, cue_pocketed, targets)
    me = state["shooter"]
    if fouls and options["three_fouls"] and _fouls_in_a_row(state, me) >= 2:
        _end(out, state, plain(R_THREE_FOULS), 1 - me, fouls, plain(False), plain(GROUPS_OPEN), cue_pocketed)
        return
    money = _highest(state["on"])
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


@leaf_public
def _call_eight(out: np.void, state: np.void, options: np.void, first: int, rails: int,
                pocketed: np.ndarray, pockets: np.ndarray, n_pocketed: int, cue_pocketed: bool, called: int) -> None:
    me = state["shooter"]
    eight_at = -1
    for i in range(n_pocketed):
        if pocketed[i] == 8:
            eight_at = i
    if state["break_shot"]:
        fouls = _break_fouls(first, rails, n_pocketed, cue_pocketed, plain(0), plain(False), options["break_rails"])
        if eight_at >= 0 and not fouls and options["eight_break_wins"]:
            _end(out, state, plain(R_EIGHT_ON_BREAK), me, plain(0), plain(True), plain(GROUPS_OPEN), cue_pocketed)
            return
        respot = EIGHT_BIT if eight_at >= 0 else 0
        if fouls:
            bih = options["break_scratch_bih"] if _first_foul(fouls) == R_SCRATCH else options["illegal_break_bih"]
            _foul(out, state, fouls, respot, bih, plain(GROUPS_OPEN), cue_pocketed)
        else:
            _clean(out, state, plain(R_LEGAL), n_pocketed > 0, respot, plain(GROUPS_OPEN), plain(False))
        return
    targets = legal_mask(state)
    fouls = _contact_fouls(first, rails, n_pocketed, cue_pocketed, targets)
    groups = state["groups"]
    if eight_at >= 0:  # the game ends: won only on a clean, called shot at the 8
        if targets != EIGHT_BIT:
            _end(out, state, plain(R_EIGHT_EARLY), 1 - me, fouls, plain(False), groups, cue_pocketed)
        elif fouls:
            _end(out, state, plain(R_EIGHT_ON_FOUL), 1 - me, fouls, plain(False), groups, cue_pocketed)
        elif options["call_eight"] and called < 0:
            _end(out, state, plain(R_EIGHT_NOT_CALLED), 1 - me, plain(0), plain(False), groups, cue_pocketed)
        elif options["call_eight"] and pockets[eight_at] != called:
            _end(out, state, plain(R_EIGHT_WRONG_POCKET), 1 - me, plain(0), plain(False), groups, cue_pocketed)
        else:
            _end(out, state, plain(R_EIGHT_POCKETED), me, plain(0), plain(True), groups, cue_pocketed)
        return
    if fouls:
        if options["three_fouls"] and _fouls_in_a_row(state, me) >= 2:
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
def next_state(state: np.void, options: np.void, call: np.void, pocketed: np.ndarray, n_pocketed: int,
               out: np.void) -> None:
    """The state after ``call`` made on a shot from ``state`` into ``out`` (``Ruleset.next_state``): the pocketed
    balls off the table but the respotted ones, the shooter's fouls in a row counted (or reset), the push-out
    flags, the shot number."""
    on = state["on"]
    for i in range(n_pocketed):
        on &= ~(1 << pocketed[i])
    on |= call["respot"]
    s = call["shooter"]
    fouls0 = state["fouls0"]
    fouls1 = state["fouls1"]
    if s == 0:
        fouls0 = fouls0 + 1 if call["foul"] else 0
    else:
        fouls1 = fouls1 + 1 if call["foul"] else 0
    push_next = state["game"] == GAME_NINE and state["break_shot"] != 0 and options["push_out"] != 0 and \
        not call["over"]
    out["game"] = state["game"]
    out["on"] = on
    out["shooter"] = call["next"]
    out["bih"] = call["bih"]
    out["groups"] = call["groups"]
    out["fouls0"] = fouls0
    out["fouls1"] = fouls1
    out["break_shot"] = 0
    out["push_available"] = push_next
    out["push_pending"] = call["push"] != 0 and not call["foul"] and not call["over"]
    out["over"] = call["over"]
    out["winner"] = call["winner"]
    out["shot"] = state["shot"] + 1


@njit(cache=True)
def play(state: np.void, options: np.void, first: int, rails: int, pocketed: np.ndarray,
         pockets: np.ndarray, n_pocketed: int, cue_pocketed: bool, push: bool, called: int, call: np.void,
         after: np.void) -> None:
    """The call on a shot (``Ruleset.call``) into ``call`` and the state after it (``Ruleset.next_state``) into
    ``after``. The shot: ``first`` (the number of the first ball hit, -1: none), ``rails`` (bit mask of the numbers
    that reached a cushion after it, the cue ball as 0), the ``n_pocketed`` object balls ``pocketed`` in the order
    they dropped and their ``pockets``, ``cue_pocketed``; the declarations: ``push`` (a push-out, allowed only when
    the state says so: the caller checks), ``called`` (the pocket called for the 8, -1: none)."""
    if state["game"] == GAME_NINE:
        _call_nine(call, state, options, first, rails, pocketed, n_pocketed, cue_pocketed, push)
    else:
        _call_eight(call, state, options, first, rails, pocketed, pockets, n_pocketed, cue_pocketed, called)
    next_state(state, options, call, pocketed, n_pocketed, after)


@njit(cache=True)
def copy_state(dst: np.void, src: np.void) -> None:
    """The game state ``src`` into ``dst`` (both :data:`GAME_STATE_ROW` records), field by field."""
    dst["game"] = src["game"]
    dst["on"] = src["on"]
    dst["shooter"] = src["shooter"]
    dst["bih"] = src["bih"]
    dst["groups"] = src["groups"]
    dst["fouls0"] = src["fouls0"]
    dst["fouls1"] = src["fouls1"]
    dst["break_shot"] = src["break_shot"]
    dst["push_available"] = src["push_available"]
    dst["push_pending"] = src["push_pending"]
    dst["over"] = src["over"]
    dst["winner"] = src["winner"]
    dst["shot"] = src["shot"]


@njit(cache=True)
def initial_row(st: np.void, game: int, full: int, first: int) -> None:
    """Compiled twin of :meth:`~billiards_env.rules.Ruleset.initial_state` ``(first_shooter=first)`` into the state
    record ``st``: the balls of ``full`` (a mask) on, ball in hand in the kitchen, the break."""
    st["game"] = game
    st["on"] = full
    st["shooter"] = first
    st["bih"] = BIH_KITCHEN
    st["groups"] = GROUPS_OPEN
    st["fouls0"] = 0
    st["fouls1"] = 0
    st["break_shot"] = 1
    st["push_available"] = 0
    st["push_pending"] = 0
    st["over"] = 0
    st["winner"] = -1
    st["shot"] = 0


# --- the Python rules' values --------------------------------------------------------------------------------------

def _record(dtype: np.dtype) -> np.void:
    """A zeroed record of ``dtype`` (a view of a 0-d array, which compiled code writes into in place)."""
    rec = np.zeros((), dtype)[()]
    assert isinstance(rec, np.void)
    return rec


def options_row(rules: Any) -> np.void:
    """The options of a ruleset (:class:`NineBall` or :class:`EightBall`) as a :data:`RULE_OPTIONS` record."""
    out = _record(RULE_OPTIONS)
    o = rules.options
    if isinstance(rules, NineBall):
        assert isinstance(o, NineBallOptions)
        out["game"] = GAME_NINE
        out["push_out"] = o.push_out
        out["three_fouls"] = o.three_foul_rule
        out["break_rails"] = o.break_rail_balls
    elif isinstance(rules, EightBall):
        assert isinstance(o, EightBallOptions)
        out["game"] = GAME_EIGHT
        out["three_fouls"] = o.three_foul_rule
        out["break_rails"] = o.break_rail_balls
        out["call_eight"] = o.call_eight
        out["eight_break_wins"] = o.eight_on_break == "win"
        out["break_scratch_bih"] = _BIH_CODE[o.break_scratch_ball_in_hand]
        out["illegal_break_bih"] = _BIH_CODE[o.illegal_break_ball_in_hand]
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


def state_row(state: GameState) -> np.void:
    """The :data:`GAME_STATE_ROW` record of a :class:`GameState`."""
    out = _record(GAME_STATE_ROW)
    out["game"] = GAME_NINE if state.game == NINE_BALL else GAME_EIGHT
    out["on"] = mask_of(state.on_table)
    out["shooter"] = state.shooter
    out["bih"] = _BIH_CODE[state.ball_in_hand]
    out["groups"] = _GROUPS_VALUE.index(state.groups)
    out["fouls0"] = state.fouls_in_a_row[0]
    out["fouls1"] = state.fouls_in_a_row[1]
    out["break_shot"] = state.break_shot
    out["push_available"] = state.push_out_available
    out["push_pending"] = state.push_out_pending
    out["over"] = state.game_over
    out["winner"] = -1 if state.winner is None else state.winner
    out["shot"] = state.shot_number
    return out


def game_state(row: np.void) -> GameState:
    """The :class:`GameState` of a :data:`GAME_STATE_ROW` record (the values a ruleset gives: Python ints and
    bools)."""
    r = {name: int(row[name]) for name in row.dtype.names or ()}
    return GameState.trusted(NINE_BALL if r["game"] == GAME_NINE else EIGHT_BALL, numbers_of(r["on"]),
                              r["shooter"], _BIH_VALUE[r["bih"]], _GROUPS_VALUE[r["groups"]],
                              (r["fouls0"], r["fouls1"]), bool(r["break_shot"]), bool(r["push_available"]),
                              bool(r["push_pending"]), bool(r["over"]), None if r["winner"] < 0 else r["winner"],
                              r["shot"])


def call_of(row: np.void, pocketed: tuple[int, ...]) -> Call:
    """The :class:`Call` of a :data:`CALL_ROW` record (``pocketed``: the shot's object balls in the order they
    dropped)."""
    r = {name: int(row[name]) for name in row.dtype.names or ()}
    return Call(legal=bool(r["legal"]), foul=bool(r["foul"]), reason=REASONS[r["reason"]],
                fouls=tuple(f for k, f in enumerate(FOULS) if (r["fouls"] >> k) & 1), shooter=r["shooter"],
                turn_over=bool(r["turn_over"]), next_shooter=r["next"], ball_in_hand=_BIH_VALUE[r["bih"]],
                pocketed=tuple(pocketed), respot=tuple(n for n in pocketed if (r["respot"] >> n) & 1),
                cue_pocketed=bool(r["cue_pocketed"]), game_over=bool(r["over"]),
                winner=None if r["winner"] < 0 else r["winner"], groups=_GROUPS_VALUE[r["groups"]],
                push_out=bool(r["push"]))


def ball_in_hand_value(code: int) -> Any:
    """``GameState.ball_in_hand`` of a :data:`BIH_NO` / :data:`BIH_ANYWHERE` / :data:`BIH_KITCHEN` code."""
    return _BIH_VALUE[int(code)]


def groups_value(code: int) -> tuple[str, str] | None:
    """``GameState.groups`` of a groups code."""
    return _GROUPS_VALUE[int(code)]


__all__ = ["play", "next_state", "initial_row", "copy_state", "legal_mask", "legal_mask_for", "needs_called_pocket",
           "options_row", "state_row", "game_state", "call_of", "mask_of", "numbers_of", "ball_in_hand_value",
           "groups_value", "GAME_STATE_ROW", "CALL_ROW", "RULE_OPTIONS", "REASONS", "GAME_NINE", "GAME_EIGHT", "BIH_NO",
           "BIH_ANYWHERE", "BIH_KITCHEN", "GROUPS_OPEN", "GROUPS_SOLIDS", "GROUPS_STRIPES", "SOLIDS_MASK",
           "STRIPES_MASK", "EIGHT_BIT"]
