"""Snooker, after the WPBSA rules: pure data in, data out.

15 reds (1 point each) and six colours (yellow 2, green 3, brown 4, blue 5, pink 6, black 7). While reds remain
the striker is on a red, then (after potting one) on a colour of his choice, which is re-spotted when potted; when
the reds are gone the colours are on in ascending order and stay down. A foul gives the opponent the higher of 4
and the values of the ball on, the ball hit first and any ball potted wrongly. The frame goes to the higher score
(a re-spotted black decides a tie).

The hot part is compiled: :func:`judge` turns one shot (the ball hit first, the balls potted, the cue ball in or
not) into the fouls, the penalty, the points, the balls to re-spot and the next ball on, and :func:`judge_batch`
does it for a search player's batch of candidate shots. :class:`Snooker` wraps it with named, checked data.
:func:`snookered` is the referee's look at the table: whether the striker can hit both edges of a ball on.

Example::

    from billiards_env.games.snooker_layout import snooker_balls
    from billiards_env.physics import Physics, Simulator
    from billiards_env.physics.table import snooker_table
    from billiards_env.rules.snooker import Snooker, SnookerShotInfo, snooker_values, summarize_snooker

    table = snooker_table()
    sim = Simulator(table, Physics())
    rules = Snooker()
    state = rules.initial_state(first_shooter=0)   # on a red, the cue ball in hand in the D
    balls = snooker_balls(table).strike("cue", angle=0.1, speed=5.0)
    values = snooker_values(balls.ids)             # row -> 0 cue, 1 red, 2..7 the colours; once per scene
    status, t, n, pocket, events = sim.run_in_place(balls)
    call = rules.call(state, summarize_snooker(events, pocket, values), SnookerShotInfo())
    state = rules.next_state(state, call)   # the env re-spots call.respot and, after an in-off, places the cue
    call.points, call.foul, call.foul_points, call.score, call.on
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any, Final, Literal, Sequence, Union

import numpy as np
from numba import njit

from ..physics.codes import EV_POCKET
from ..physics.outcome import first_contact_row
from .errors import RulesError, checked_keywords

SNOOKER = "snooker"
#: The colours in ascending value (yellow 2 ... black 7): their ids in a snooker scene.
SNOOKER_COLOURS = ("yellow", "green", "brown", "blue", "pink", "black")
#: Ids of the 15 reds.
SNOOKER_REDS = tuple(f"red{k}" for k in range(1, 16))
#: Ball ids of a snooker scene, in row order: the cue ball, the reds, the colours in ascending value.
SNOOKER_IDS = ("cue",) + SNOOKER_REDS + SNOOKER_COLOURS
#: Ball values: the cue ball 0, a red 1, the colours 2..7 in the order of :data:`SNOOKER_COLOURS`.
RED_VALUE = 1
COLOUR_VALUES = {name: k + 2 for k, name in enumerate(SNOOKER_COLOURS)}
VALUE_NAMES = {1: "red", **{v: k for k, v in COLOUR_VALUES.items()}}
#: What the striker is on: ``"red"``, ``"colour"`` (any colour, after potting a red) or a named colour.
ON_RED = "red"
ON_COLOUR = "colour"
#: The ``on`` codes of the compiled judge: 1 red, 0 any colour, 2..7 that colour.
_ON_CODE = {ON_RED: 1, ON_COLOUR: 0, **COLOUR_VALUES}
_ON_NAME = {v: k for k, v in _ON_CODE.items()}
#: Ball in hand: the cue ball is placed on or within the lines of the D.
IN_D: Final = "d"
BallInHand = Union[Literal[False], Literal["d"]]
#: The smallest penalty.
MIN_PENALTY = 4

# Fouls (``SnookerCall.fouls``), in this order; the first is the call's reason.
IN_OFF = "in-off"  #: the cue ball was pocketed
NO_BALL_HIT = "no ball hit"  #: the cue ball hit no ball
BALL_NOT_ON_FIRST = "ball not on hit first"
BALL_NOT_ON_POTTED = "ball not on potted"
FOULS = (IN_OFF, NO_BALL_HIT, BALL_NOT_ON_FIRST, BALL_NOT_ON_POTTED)
_F_IN_OFF, _F_NO_HIT, _F_FIRST, _F_POT = 1, 2, 4, 8
# Other reasons.
POT = "pot"  #: a legal shot that scored
NO_POT = "no pot"  #: a legal shot that scored nothing: the turn passes
MISS = "foul and a miss"  #: (option ``miss_rule``) a foul that failed to hit a ball on when not snookered
THREE_MISSES = "three misses"  #: (option ``miss_rule``) the frame is lost on the ``miss_limit``-th miss in a row
FRAME_OVER = "frame over"  #: the last ball went down, or a foul on the last black
RESPOTTED_BLACK = "re-spotted black"  #: a tie after the last black: the black is re-spotted to decide the frame
#: Every reason a call gives (``SnookerCall.reason``).
REASONS = FOULS + (POT, NO_POT, MISS, THREE_MISSES, FRAME_OVER, RESPOTTED_BLACK)
#: What the striker is on, by the compiled judge's ``on`` code: ``ON_NAMES[code]``.
ON_NAMES = tuple(_ON_NAME[k] for k in range(len(_ON_NAME)))


def snooker_values(ids: Sequence[str]) -> np.ndarray:
    """The value of each ball row of a snooker scene: ``"cue"`` 0, ``"red1"``..``"red15"`` 1, the colours
    (:data:`SNOOKER_COLOURS`) 2..7. Raises :class:`RulesError` for another id, a repeated colour, or not exactly
    one cue ball."""
    out = np.empty(len(ids), dtype=np.int64)
    for row, bid in enumerate(ids):
        if bid == "cue":
            out[row] = 0
        elif bid in COLOUR_VALUES:
            out[row] = COLOUR_VALUES[bid]
        elif isinstance(bid, str) and bid.startswith("red") and bid[3:].isdigit():
            out[row] = RED_VALUE
        else:
            raise RulesError(f"ball id {bid!r} (row {row}): snooker needs the ids 'cue', 'red1'..'red15' and "
                             f"{', '.join(SNOOKER_COLOURS)}; rename the ball")
    if int(np.count_nonzero(out == 0)) != 1:
        raise RulesError(f"ball ids {list(ids)}: a frame needs exactly one ball with id 'cue'")
    colours = out[out >= 2].tolist()
    if len(set(colours)) != len(colours):
        raise RulesError(f"ball ids {list(ids)}: a colour appears twice")
    if len(set(ids)) != len(ids):
        raise RulesError(f"ball ids {list(ids)}: repeated ids; every ball needs its own")
    return out


# --- the compiled judge --------------------------------------------------------------------------------------------

@njit(cache=True)
def _lowest(mask):
    """The lowest colour value in a mask of colour bits (bit v for value v), 0 if none."""
    for v in range(2, 8):
        if mask & (1 << v):
            return v
    return 0


@njit(cache=True)
def judge(on, nominated, free_ball, reds, colours, first, reds_potted, potted, cue_potted):
    """One shot under the rules, on integers.

    In: ``on`` (1 red, 0 any colour, 2..7 that colour), ``nominated`` (the colour nominated when on a colour, 0:
    none, then the first colour hit counts), ``free_ball`` (the colour nominated as a free ball, 0: none; it must
    be hit first, then counts as the ball on),
    ``reds`` (reds on the table before the shot), ``colours`` (bit mask, bit v set for colour value v on the
    table), ``first`` (value of the ball hit first, -1 none), ``reds_potted``, ``potted`` (bit mask of the
    colours potted), ``cue_potted``.

    Out: ``(fouls, penalty, points, nominated, respot, next_on, reds_after, colours_after, frame_end)``: the foul
    bits (1 in-off, 2 no ball hit, 4 ball not on first, 8 ball not on potted), the penalty (0 without a foul), the
    points scored, the effective nomination (0: none), the mask of colours to re-spot, the ball on for the next
    shot (the same code as ``on``, for whoever plays it), the reds and colours on the table after the shot, and
    whether the frame ends (the last ball potted, or a foul with only the black left).
    """
    nom = nominated
    if on == 0 and nom == 0 and first >= 2:
        nom = first
    # what may be hit first, and potted
    if on == 1:
        ok_first = first == free_ball if free_ball > 0 else first == 1  # a nominated free ball must be hit first
        allowed = (1 << free_ball) if free_ball > 0 else 0
        on_value = 1
    elif on == 0:
        ok_first = first >= 2 and first == nom
        allowed = (1 << nom) if nom > 0 else 0
        on_value = nom if nom > 0 else 7  # a foul before nominating a colour costs 7
    else:
        ok_first = first == free_ball if free_ball > 0 else first == on
        allowed = (1 << on) | ((1 << free_ball) if free_ball > 0 else 0)
        on_value = on
    bad = potted & ~allowed
    bad_reds = reds_potted > 0 and on != 1
    fouls = 0
    penalty = 0
    if cue_potted:
        fouls |= 1
    if first < 0:
        fouls |= 2
    elif not ok_first:
        fouls |= 4
    if bad != 0 or bad_reds:
        fouls |= 8
    if fouls:
        penalty = max(4, on_value)
        if fouls & 4:
            penalty = max(penalty, first)
        for v in range(2, 8):
            if bad & (1 << v):
                penalty = max(penalty, v)
    points = 0
    if not fouls:
        if on == 1:
            points = reds_potted + (1 if free_ball > 0 and potted & (1 << free_ball) else 0)
        elif on == 0:
            points = nom if nom > 0 and potted & (1 << nom) else 0
        elif potted & allowed:
            points = on
    # colours back on their spots: all but the colour on, potted legally once the reds are gone
    respot = potted
    if on >= 2 and not fouls and potted & (1 << on):
        respot = potted & ~(1 << on)
    reds_after = reds - reds_potted
    colours_after = (colours & ~potted) | respot
    if points > 0:
        if on == 1:
            nxt = 0
        elif on == 0:
            nxt = 1 if reds_after > 0 else _lowest(colours_after)
        else:
            nxt = _lowest(colours_after)
    else:
        nxt = 1 if reds_after > 0 else _lowest(colours_after)
    only_black = reds == 0 and colours == (1 << 7)
    frame_end = (reds_after == 0 and colours_after == 0) or (fouls != 0 and only_black)
    return fouls, penalty, points, nom, respot, nxt, reds_after, colours_after, frame_end


@njit(cache=True)
def judge_batch(first_row, pocket, values, cue, on, nominated, free_ball, reds, colours):
    """:func:`judge` for ``N`` candidate shots of one table: ``first_row`` (N,) the row the cue ball hit first
    (-1: none; :attr:`BatchResult.first_contact`), ``pocket`` (N, B) each ball's pocket (-1: not pocketed;
    :attr:`BatchResult.pocket`), ``values`` (B,) from :func:`snooker_values`. Returns arrays ``fouls, penalty,
    points, nominated, respot, next_on, reds_after, colours_after, frame_end`` (N,)."""
    n = first_row.shape[0]
    out_i = np.zeros((8, n), np.int64)
    frame_end = np.zeros(n, np.bool_)
    for k in range(n):
        f = first_row[k]
        first = values[f] if f >= 0 else -1
        reds_potted = 0
        potted = 0
        cue_potted = False
        for b in range(values.shape[0]):
            if pocket[k, b] >= 0:
                if b == cue:
                    cue_potted = True
                elif values[b] == 1:
                    reds_potted += 1
                else:
                    potted |= 1 << values[b]
        f_, pen, pts, nom, rsp, nxt, ra, ca, end = judge(on, nominated, free_ball, reds, colours, first,
                                                         reds_potted, potted, cue_potted)
        out_i[0, k] = f_
        out_i[1, k] = pen
        out_i[2, k] = pts
        out_i[3, k] = nom
        out_i[4, k] = rsp
        out_i[5, k] = nxt
        out_i[6, k] = ra
        out_i[7, k] = ca
        frame_end[k] = end
    return (out_i[0], out_i[1], out_i[2], out_i[3], out_i[4], out_i[5], out_i[6], out_i[7], frame_end)


# --- the referee's look at the table ---------------------------------------------------------------------------------

@njit(cache=True)
def _edge_clear(pos, on_table, radius, not_on, cue, j, sign):
    """Whether the cue ball can travel in a straight line to graze ball ``j``'s edge on side ``sign`` (+1 left,
    -1 right) without touching a ball of ``not_on`` on the way."""
    cx = pos[cue, 0]
    cy = pos[cue, 1]
    dx = pos[j, 0] - cx
    dy = pos[j, 1] - cy
    d = math.hypot(dx, dy)
    contact = (radius[cue] + radius[j]) * (1.0 - 1e-9)
    if d <= contact:
        return True
    alpha = sign * math.asin(contact / d)
    t = math.sqrt(d * d - contact * contact)
    ux = (dx * math.cos(alpha) - dy * math.sin(alpha)) / d
    uy = (dx * math.sin(alpha) + dy * math.cos(alpha)) / d
    for k in range(pos.shape[0]):
        if k == cue or k == j or not on_table[k] or not not_on[k]:
            continue
        qx = pos[k, 0] - cx
        qy = pos[k, 1] - cy
        s = min(max(qx * ux + qy * uy, 0.0), t)
        ex = qx - s * ux
        ey = qy - s * uy
        need = radius[cue] + radius[k]
        if ex * ex + ey * ey < need * need * (1.0 - 1e-12):
            return False
    return True


@njit(cache=True)
def _snookered(pos, on_table, radius, cue, is_on):
    any_on = False
    not_on = ~is_on
    for j in range(pos.shape[0]):
        if j == cue or not on_table[j] or not is_on[j]:
            continue
        any_on = True
        if _edge_clear(pos, on_table, radius, not_on, cue, j, 1.0) and \
                _edge_clear(pos, on_table, radius, not_on, cue, j, -1.0):
            return False
    return any_on


def ball_on_mask(values: np.ndarray, on: str) -> np.ndarray:
    """(B,) bool: the balls on for ``on`` (``"red"``: the reds, ``"colour"``: every colour, else that colour)."""
    code = _on_code(on)
    v = np.asarray(values)
    if code == 1:
        return v == 1
    if code == 0:
        return v >= 2
    return v == code


def snookered(pos: np.ndarray, on_table: np.ndarray, radius: np.ndarray, values: np.ndarray, on: str,
              cue: int | None = None) -> bool:
    """The WPBSA's "snookered": no ball on (for ``on``) can be hit at both extreme edges by the cue ball in a
    straight line, the way obstructed by balls not on. Balls on do not obstruct; cushions do not either (the table
    has no pocket jaws to be angled by). False when no ball on is on the table."""
    vals = np.asarray(values, dtype=np.int64)
    c = int(np.flatnonzero(vals == 0)[0]) if cue is None else int(cue)
    return bool(_snookered(np.ascontiguousarray(pos, dtype=float), np.ascontiguousarray(on_table, dtype=np.bool_),
                           np.ascontiguousarray(np.broadcast_to(radius, vals.shape), dtype=float), c,
                           ball_on_mask(vals, on)))


# --- data ----------------------------------------------------------------------------------------------------------

def _on_code(on: str) -> int:
    try:
        return _ON_CODE[on]
    except (KeyError, TypeError):
        raise RulesError(f"on: {on!r}; use 'red', 'colour' or one of {', '.join(SNOOKER_COLOURS)}") from None


def _colour_value(name: str, field: str) -> int:
    try:
        return COLOUR_VALUES[name]
    except (KeyError, TypeError):
        raise RulesError(f"{field}: {name!r} is not a colour; use one of {', '.join(SNOOKER_COLOURS)}") from None


def _mask(names: Sequence[str]) -> int:
    m = 0
    for n in names:
        m |= 1 << COLOUR_VALUES[n]
    return m


def _names(mask: int) -> tuple[str, ...]:
    return tuple(VALUE_NAMES[v] for v in range(2, 8) if mask & (1 << v))


def _check_player(name: str, value: object) -> None:
    if isinstance(value, bool) or value not in (0, 1):
        raise RulesError(f"{name}: must be player 0 or 1, got {value!r}")


def _check_pair(name: str, value: object) -> tuple[int, int]:
    v = tuple(value) if isinstance(value, (tuple, list)) else ()
    if len(v) != 2 or any(isinstance(x, bool) or not isinstance(x, (int, np.integer)) or x < 0 for x in v):
        raise RulesError(f"{name}: {value!r}; give two integers >= 0")
    return int(v[0]), int(v[1])


@checked_keywords
@dataclass(frozen=True)
class SnookerOptions:
    """Options of :class:`Snooker`.

    ``free_ball``: after a foul that leaves the incoming striker snookered (:func:`snookered`, told to the rules
    in ``SnookerShotInfo.snookered``), he may nominate any colour as the ball on (WPBSA). ``auto_free_ball``:
    when a free ball is allowed and none was nominated, the first ball hit, if it is not a ball on, counts as
    nominated (so an action needs no nomination). ``miss_rule``: a foul that fails to hit a ball on first while
    the striker was not snookered is also a miss: the balls are put back where they were and the offender plays
    again (the WPBSA lets the opponent choose; here always); ``miss_limit`` misses in a row lose the frame (WPBSA:
    3, when a ball on could be hit full).
    """

    free_ball: bool = True
    auto_free_ball: bool = True
    miss_rule: bool = False
    miss_limit: int = 3

    def __post_init__(self) -> None:
        for name in ("free_ball", "auto_free_ball", "miss_rule"):
            if not isinstance(getattr(self, name), bool):
                raise RulesError(f"SnookerOptions.{name}: must be True or False, got {getattr(self, name)!r}")
        n = self.miss_limit
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            raise RulesError(f"SnookerOptions.miss_limit: must be an integer >= 1, got {n!r}")


@dataclass(frozen=True, slots=True)
class SnookerState:
    """Where a frame stands before a shot.

    ``shooter``: the striker (0 or 1). ``score``: both players' points. ``on``: the ball on (``"red"``,
    ``"colour"`` after a red is potted, or a named colour once the reds are gone). ``reds``: reds on the table;
    ``colours``: the colours on the table (ascending value). ``break_points``: the striker's points in this visit.
    ``ball_in_hand``: ``"d"`` (place the cue ball in the D) or False. ``after_foul``: the opponent fouled on the
    last shot (a free ball may be allowed). ``misses``: each player's misses in a row (option ``miss_rule``).
    ``respotted_black``: the frame is being decided on the re-spotted black. ``best_break``: each player's
    highest break so far. ``frame_over`` / ``winner``. ``shot_number``: shots played so far.
    """

    shooter: int = 0
    score: tuple[int, int] = (0, 0)
    on: str = ON_RED
    reds: int = 15
    colours: tuple[str, ...] = SNOOKER_COLOURS
    break_points: int = 0
    ball_in_hand: BallInHand = IN_D
    after_foul: bool = False
    misses: tuple[int, int] = (0, 0)
    respotted_black: bool = False
    best_break: tuple[int, int] = (0, 0)
    frame_over: bool = False
    winner: int | None = None
    shot_number: int = 0

    def __post_init__(self) -> None:
        _check_player("SnookerState.shooter", self.shooter)
        object.__setattr__(self, "score", _check_pair("SnookerState.score", self.score))
        object.__setattr__(self, "misses", _check_pair("SnookerState.misses", self.misses))
        object.__setattr__(self, "best_break", _check_pair("SnookerState.best_break", self.best_break))
        code = _on_code(self.on)
        r = self.reds
        if isinstance(r, bool) or not isinstance(r, (int, np.integer)) or not 0 <= r <= 15:
            raise RulesError(f"SnookerState.reds: {r!r}; give the number of reds on the table, 0..15")
        object.__setattr__(self, "reds", int(r))
        cols = tuple(self.colours)
        for c in cols:
            _colour_value(c, "SnookerState.colours")
        if len(set(cols)) != len(cols):
            raise RulesError(f"SnookerState.colours: {cols!r} lists a colour twice")
        object.__setattr__(self, "colours", tuple(sorted(cols, key=SNOOKER_COLOURS.index)))
        if self.ball_in_hand not in (False, IN_D) or self.ball_in_hand is True:
            raise RulesError(f"SnookerState.ball_in_hand: {self.ball_in_hand!r}; use 'd' or False")
        if not self.frame_over:
            if code == 1 and not self.reds:
                raise RulesError("SnookerState.on: 'red' but no red is on the table")
            if self.reds and code >= 2:
                raise RulesError(f"SnookerState.on: {self.on!r} while reds remain; use 'red' or 'colour'")
            if code >= 2 and self.on not in self.colours:
                raise RulesError(f"SnookerState.on: {self.on!r} is not on the table {self.colours}")
            if code >= 2 and self.colours[0] != self.on:
                raise RulesError(f"SnookerState.on: {self.on!r}, but the lowest colour {self.colours[0]!r} comes "
                                 "first once the reds are gone")
            if (self.reds or code == 0) and self.colours != SNOOKER_COLOURS:
                raise RulesError("SnookerState.colours: every colour is on the table while reds remain (and on the "
                                 "colour after the last red); they are re-spotted")
        if self.winner is not None:
            _check_player("SnookerState.winner", self.winner)
            if not self.frame_over:
                raise RulesError("SnookerState.winner: set only when frame_over is True")

    @property
    def opponent(self) -> int:
        return 1 - self.shooter

    @property
    def on_value(self) -> int:
        """The ``on`` code of :func:`judge`: 1 red, 0 any colour, 2..7 that colour."""
        return _ON_CODE[self.on]

    @property
    def colour_mask(self) -> int:
        """The colours on the table as the bit mask of :func:`judge`."""
        return _mask(self.colours)

    @property
    def points_left(self) -> int:
        """Points still on the table: 8 a red (with a black), and the colours."""
        return 8 * self.reds + sum(COLOUR_VALUES[c] for c in self.colours)


@dataclass(frozen=True, slots=True)
class SnookerShotInfo:
    """What the striker declares before a shot, and the referee's look at the table.

    ``nominated``: the colour nominated when on a colour (after a red); None: the first colour the cue ball hits
    counts as nominated. ``free_ball``: the colour nominated as a free ball (allowed by
    :meth:`Snooker.free_ball_available`); None: none, or with the option ``auto_free_ball`` the first ball hit if
    it is not on. ``snookered``: the striker is snookered in this layout (:func:`snookered` for ``state.on``), for
    the free ball and the miss rule.
    """

    nominated: str | None = None
    free_ball: str | None = None
    snookered: bool = False

    def __post_init__(self) -> None:
        if self.nominated is not None:
            _colour_value(self.nominated, "SnookerShotInfo.nominated")
        if self.free_ball is not None:
            _colour_value(self.free_ball, "SnookerShotInfo.free_ball")
        if not isinstance(self.snookered, bool):
            raise RulesError(f"SnookerShotInfo.snookered: must be True or False, got {self.snookered!r}")


@dataclass(frozen=True, slots=True)
class SnookerSummary:
    """What a shot did: ``first`` the ball the cue ball hit first (``"red"``, a colour, None: nothing),
    ``reds_potted``, ``colours_potted`` (in the order they dropped), ``cue_pocketed``."""

    first: str | None = None
    reds_potted: int = 0
    colours_potted: tuple[str, ...] = ()
    cue_pocketed: bool = False

    def __post_init__(self) -> None:
        if self.first is not None and self.first != "red":
            _colour_value(self.first, "SnookerSummary.first")
        r = self.reds_potted
        if isinstance(r, bool) or not isinstance(r, (int, np.integer)) or not 0 <= r <= 15:
            raise RulesError(f"SnookerSummary.reds_potted: {r!r}; give a count 0..15")
        for c in self.colours_potted:
            _colour_value(c, "SnookerSummary.colours_potted")
        if len(set(self.colours_potted)) != len(self.colours_potted):
            raise RulesError(f"SnookerSummary.colours_potted: {self.colours_potted!r} lists a colour twice")


def summarize_snooker(events: np.ndarray, pocket: np.ndarray, values: np.ndarray) -> SnookerSummary:
    """The :class:`SnookerSummary` of a shot from ``Simulator.run_in_place``'s ``events`` ``(M, 3)`` (kind, ball,
    other) and ``pocket`` ``(B,)`` (pocket index per row, -1: not pocketed by this shot), with ``values`` from
    :func:`snooker_values`."""
    ev = np.ascontiguousarray(events, dtype=np.int64)
    if ev.ndim != 2 or ev.shape[1] != 3:
        raise RulesError(f"events: expected an (M, 3) array of kind, ball, other; got shape {ev.shape}")
    vals = np.asarray(values, dtype=np.int64)
    pk = np.asarray(pocket)
    if pk.shape != vals.shape:
        raise RulesError(f"pocket: shape {pk.shape} but values has shape {vals.shape}; one per ball row")
    cues = np.flatnonzero(vals == 0)
    if len(cues) != 1:
        raise RulesError("values: exactly one row must be the cue ball (value 0)")
    cue = int(cues[0])
    f = int(first_contact_row(ev, cue))
    down = [int(b) for b in np.flatnonzero(pk >= 0)]
    order = {int(b): k for k, b in enumerate(ev[ev[:, 0] == EV_POCKET, 1].tolist())}  # pocket events in time order
    down.sort(key=lambda b: order.get(b, len(order) + b))
    return SnookerSummary(None if f < 0 else VALUE_NAMES[int(vals[f])],
                          sum(1 for b in down if vals[b] == RED_VALUE),
                          tuple(VALUE_NAMES[int(vals[b])] for b in down if vals[b] >= 2), cue in down)


@dataclass(frozen=True, slots=True)
class SnookerCall:
    """The call on one shot.

    ``points``: scored by the striker. ``foul`` / ``fouls`` / ``foul_points``: the fouls and the penalty the
    opponent receives. ``score``: both players' points after the shot. ``on``: the ball on for the next shot
    (whoever plays it). ``reason``: :data:`POT`, :data:`NO_POT`, the first foul, :data:`MISS`, or what ended the
    frame. ``nominated`` / ``free_ball``: the colour nominated and the free ball, as judged (the first ball hit
    when not declared). ``respot``: colours the env puts back on their spots
    (:func:`~billiards_env.games.snooker_layout.spot_snooker_colours`); the other potted balls stay down.
    ``reds_potted`` / ``colours_potted``. ``break_points``: the striker's break after the shot (its total when
    the turn passes). ``turn_over``, ``next_shooter``, ``ball_in_hand`` (``"d"`` after an in-off; with
    ``replace`` whatever it was before the shot). ``miss`` / ``replace``: a miss was called and the env puts every
    ball back where it was before the shot. ``frame_over`` / ``winner``; ``respotted_black``: the frame was tied
    and goes on with the black re-spotted.
    """

    points: int
    foul: bool
    foul_points: int
    score: tuple[int, int]
    on: str
    fouls: tuple[str, ...]
    reason: str
    shooter: int
    turn_over: bool
    next_shooter: int
    ball_in_hand: BallInHand
    respot: tuple[str, ...] = ()
    reds_potted: int = 0
    colours_potted: tuple[str, ...] = ()
    nominated: str | None = None
    free_ball: str | None = None
    break_points: int = 0
    miss: bool = False
    replace: bool = False
    frame_over: bool = False
    winner: int | None = None
    respotted_black: bool = False

    @property
    def legal(self) -> bool:
        return not self.foul


class Snooker:
    """WPBSA snooker. ``Snooker(SnookerOptions(...))``: :meth:`initial_state`, :meth:`call`, :meth:`next_state`,
    :meth:`legal_targets`, :meth:`free_ball_available`. Stateless apart from its frozen options."""

    game = SNOOKER

    def __init__(self, options: SnookerOptions | None = None) -> None:
        self.options = options if options is not None else SnookerOptions()
        if not isinstance(self.options, SnookerOptions):
            raise RulesError(f"Snooker options: expected SnookerOptions, got {type(self.options).__name__}")

    def __repr__(self) -> str:
        return f"Snooker({self.options!r})"

    def initial_state(self, first_shooter: int = 0, reds: int = 15) -> SnookerState:
        """The state before the break-off: ``first_shooter`` on a red with the cue ball in hand in the D; ``reds``
        reds racked (fewer for short frames)."""
        _check_player("first_shooter", first_shooter)
        return SnookerState(shooter=first_shooter, reds=reds, on=ON_RED if reds else "yellow")

    def legal_targets(self, state: SnookerState) -> tuple[str, ...]:
        """The balls the striker may hit first (without a free ball): ``("red",)``, every colour when on a colour,
        or the named colour."""
        if state.on == ON_RED:
            return ("red",)
        if state.on == ON_COLOUR:
            return state.colours
        return (state.on,)

    def free_ball_available(self, state: SnookerState, snookered: bool) -> bool:
        """Whether the striker may nominate a free ball: the option is on, the opponent fouled on the last shot,
        the cue ball is not in hand, the striker is ``snookered`` (:func:`snookered`), and a colour that is not on
        is on the table."""
        return bool(self.options.free_ball and state.after_foul and not state.ball_in_hand and snookered
                    and not state.frame_over and any(c != state.on for c in state.colours))

    def call(self, state: SnookerState, summary: SnookerSummary,
             shot_info: SnookerShotInfo | None = None) -> SnookerCall:
        """The call on the shot ``summary`` played from ``state`` with the declarations ``shot_info``."""
        info = SnookerShotInfo() if shot_info is None else shot_info
        self._check(state, summary, info)
        opts = self.options
        code = state.on_value
        free_ok = self.free_ball_available(state, info.snookered)
        free = _colour_value(info.free_ball, "shot_info.free_ball") if info.free_ball is not None else 0
        first = -1 if summary.first is None else (RED_VALUE if summary.first == "red"
                                                  else COLOUR_VALUES[summary.first])
        if not free and free_ok and opts.auto_free_ball and first >= 2 and first != code:
            free = first  # the first ball hit, not on, counts as the nominated free ball
        nominated = COLOUR_VALUES[info.nominated] if info.nominated is not None else 0
        potted = _mask(summary.colours_potted)
        fouls_b, penalty, points, nom, respot, nxt, _, _, frame_end = judge(
            code, nominated, free, state.reds, state.colour_mask, first, summary.reds_potted, potted,
            summary.cue_pocketed)
        fouls = tuple(f for f, bit in zip(FOULS, (_F_IN_OFF, _F_NO_HIT, _F_FIRST, _F_POT)) if fouls_b & bit)
        me, opp = state.shooter, state.opponent
        score = [state.score[0], state.score[1]]
        score[me] += points
        score[opp] += penalty
        foul = bool(fouls)
        brk = state.break_points + points
        common: dict[str, Any] = dict(points=int(points), foul=foul, foul_points=int(penalty), fouls=fouls, shooter=me,
                      reds_potted=summary.reds_potted, colours_potted=summary.colours_potted,
                      nominated=VALUE_NAMES[nom] if nom else None, free_ball=VALUE_NAMES[free] if free else None,
                      break_points=int(brk), respot=_names(respot))
        if frame_end:  # the last ball went down, or a foul with only the black left
            if score[0] == score[1]:  # a tie: the black is re-spotted; the other player plays it from the D
                return SnookerCall(score=(score[0], score[1]), on="black", reason=RESPOTTED_BLACK, turn_over=True,
                                   next_shooter=opp, ball_in_hand=IN_D, respotted_black=True,
                                   **{**common, "respot": ("black",)})
            return SnookerCall(score=(score[0], score[1]), on=state.on, reason=FRAME_OVER, turn_over=True,
                               next_shooter=opp, ball_in_hand=False, frame_over=True,
                               winner=0 if score[0] > score[1] else 1, **common)
        if foul and opts.miss_rule and fouls_b & (_F_NO_HIT | _F_FIRST) and not info.snookered and not free:
            misses = state.misses[me] + 1
            if misses >= opts.miss_limit:
                return SnookerCall(score=(score[0], score[1]), on=state.on, reason=THREE_MISSES, turn_over=True,
                                   next_shooter=opp, ball_in_hand=False, miss=True, frame_over=True, winner=opp,
                                   **common)
            return SnookerCall(score=(score[0], score[1]), on=state.on, reason=MISS, turn_over=False,
                               next_shooter=me, ball_in_hand=state.ball_in_hand, miss=True, replace=True,
                               **common)
        return self._continue(state, common, score, nxt, foul)

    def _continue(self, state: SnookerState, common: dict[str, Any], score: list[int], nxt: int,
                  foul: bool) -> SnookerCall:
        """The frame goes on: the striker continues after scoring, else the opponent plays (from the D after an
        in-off)."""
        keep = common["points"] > 0
        reason = common["fouls"][0] if foul else (POT if keep else NO_POT)
        bih: BallInHand = IN_D if foul and IN_OFF in common["fouls"] else False
        return SnookerCall(score=(score[0], score[1]), on=_ON_NAME[nxt], reason=reason, turn_over=not keep,
                           next_shooter=state.shooter if keep else state.opponent, ball_in_hand=bih, **common)

    def next_state(self, state: SnookerState, call: SnookerCall) -> SnookerState:
        """The state after ``call`` (made on a shot from ``state``): pocketed balls leave the table except the
        re-spotted colours; with ``call.replace`` the table is as before the shot."""
        if call.shooter != state.shooter:
            raise RulesError(f"call: made for player {call.shooter}'s shot but state.shooter is {state.shooter}; "
                             "pass the state the call was made from")
        me = state.shooter
        best = list(state.best_break)
        best[me] = max(best[me], call.break_points)
        misses = list(state.misses)
        misses[me] = misses[me] + 1 if call.miss else 0
        common: dict[str, Any] = dict(score=call.score, best_break=(best[0], best[1]), misses=(misses[0], misses[1]),
                      shot_number=state.shot_number + 1)
        if call.frame_over:
            return replace(state, frame_over=True, winner=call.winner, break_points=0, ball_in_hand=False,
                           **common)
        if call.replace:  # the same table, the same ball on, the offender again
            return replace(state, break_points=0, **common)
        if call.respotted_black:
            return SnookerState(shooter=call.next_shooter, on="black", reds=0, colours=("black",),
                                ball_in_hand=IN_D, respotted_black=True, **common)
        reds = state.reds - call.reds_potted
        colours = tuple(c for c in state.colours if c not in call.colours_potted or c in call.respot)
        return SnookerState(shooter=call.next_shooter, on=call.on, reds=reds, colours=colours,
                            break_points=0 if call.turn_over else call.break_points,
                            ball_in_hand=call.ball_in_hand, after_foul=call.foul,
                            respotted_black=state.respotted_black, **common)

    def play(self, state: SnookerState, summary: SnookerSummary,
             shot_info: SnookerShotInfo | None = None) -> tuple[SnookerCall, SnookerState]:
        """:meth:`call` and :meth:`next_state` in one."""
        c = self.call(state, summary, shot_info)
        return c, self.next_state(state, c)

    def _check(self, state: SnookerState, summary: SnookerSummary, info: SnookerShotInfo) -> None:
        if state.frame_over:
            raise RulesError("state: the frame is over (state.frame_over); start a new one with initial_state()")
        if summary.reds_potted > state.reds:
            raise RulesError(f"summary.reds_potted: {summary.reds_potted} but only {state.reds} reds are on the "
                             "table; keep SnookerState.reds in step with the balls (use next_state)")
        if summary.first == "red" and not state.reds:
            raise RulesError("summary.first: a red, but no red is on the table; keep the state in step")
        for c in summary.colours_potted + ((summary.first,) if summary.first not in (None, "red") else ()):
            if c not in state.colours:
                raise RulesError(f"summary: the {c} is not on the table {state.colours}; keep the state in step")
        if info.nominated is not None:
            if state.on != ON_COLOUR:
                raise RulesError(f"shot_info.nominated: nothing to nominate, the ball on is {state.on!r} (a colour "
                                 "is nominated only after a red is potted)")
            if info.nominated not in state.colours:
                raise RulesError(f"shot_info.nominated: the {info.nominated} is not on the table")
        if info.free_ball is not None:
            if not self.free_ball_available(state, info.snookered):
                raise RulesError("shot_info.free_ball: no free ball now (only after the opponent's foul, with the "
                                 "cue ball not in hand and the striker snookered: check free_ball_available)")
            if info.free_ball not in state.colours or info.free_ball == state.on:
                raise RulesError(f"shot_info.free_ball: {info.free_ball!r} must be a colour on the table that is "
                                 f"not the ball on ({state.on!r})")


__all__ = [
    "SNOOKER", "SNOOKER_COLOURS", "SNOOKER_REDS", "SNOOKER_IDS", "RED_VALUE", "COLOUR_VALUES", "VALUE_NAMES",
    "ON_RED", "ON_COLOUR", "IN_D", "MIN_PENALTY", "IN_OFF",
    "NO_BALL_HIT", "BALL_NOT_ON_FIRST", "BALL_NOT_ON_POTTED", "FOULS", "POT", "NO_POT", "MISS", "THREE_MISSES",
    "FRAME_OVER", "RESPOTTED_BLACK", "REASONS", "ON_NAMES", "snooker_values", "judge", "judge_batch", "ball_on_mask",
    "snookered",
    "SnookerOptions", "SnookerState", "SnookerShotInfo", "SnookerSummary", "summarize_snooker", "SnookerCall",
    "Snooker",
]
