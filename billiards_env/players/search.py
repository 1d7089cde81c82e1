"""The search player: simulate candidate shots with the exact solver, value each by what the rules call plus the
position it leaves (the ease of the next shot), averaged under the shot noise, and play the best (:func:`search_shot`).

Position play, as pool programs do it (CueCard, PickPocket): a shot is worth more than its immediate result.
Keeping the table with the cue ball where the next ball is an easy pot is worth more than keeping it with no shot
left, and a miss that leaves the opponent nothing is worth more than one that leaves him a straight-in. So every
candidate (the ghost-ball shots at several speeds and, under the spin model, with stun, draw, follow and left or
right english; plus a sweep of directions for kicks and safeties) is simulated in one batch
(:func:`billiards_env.physics.batch.run_shots`), judged by the rules, and its final layout scored by
:func:`next_shot_ease`: the probability of potting the best next shot under the shot noise (its cue-angle tolerance
against the noise's spread). The best few are then re-simulated under the env's shot noise (angle, speed and tip
offsets) and ranked by their mean value: robust shots, not lucky ones. With the cue ball in hand the search runs
from the few best places for the next shot and keeps the best.

Its own work is arrays and compiled code (:mod:`.geometry`): the candidates come from one call for every ghost-ball
shot, the position terms of all final layouts from one call, the ball-in-hand places from one call; the batches run
without event logs (what the rules read comes from the batch's arrays: :func:`shot_keys`) and the rules judge each
distinct outcome once per decision (:class:`Judge`). What is left is the physics.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Sequence

import numpy as np
from numba import njit

from billiards_env.physics.batch import BatchResult, run_shots
from billiards_env.physics.plain import plain
from billiards_env.rules import EightBall, NineBall, ShotSummary, summarize_arrays
from billiards_env.rules import pool_judge as pj

from .context import BasePlayer, ShotContext, shot_context, to_action
from .geometric import break_shot, context_model
from .geometry import (COL_ANGLE, COL_POCKET, COL_SPEED, COL_TARGET, ARRIVE_SPEED, SPEED_FACTORS, ghost_shots,
                       layouts_ease, places_ease, search_places, table_model)
from .shots import MAX_CUT, direct_hit

#: Tip offsets ``(side, top)`` (fractions of R) tried with every ghost-ball shot under the spin model: stun, draw,
#: follow, left and right english.
SPIN_VARIANTS: tuple[tuple[float, float], ...] = ((0.0, 0.0), (0.0, -0.35), (0.0, 0.35), (-0.3, 0.0), (0.3, 0.0))

#: Rules values of a candidate in a game (before position): won, lost, a foul, the turn kept (+ per ball).
WIN_VALUE = 10.0
FOUL_VALUE = -3.0
KEEP_VALUE = 1.0
BALL_VALUE = 0.1


@dataclass
class Outcome:
    """A candidate shot and what the search made of it."""

    angle: float
    speed: float
    pots: int
    scratch: bool
    hit: bool
    value: float  #: the outcome's value: in a game the rules' verdict (:func:`_judge`), else pots - 3 scratch - ...
    robust: float = math.nan  #: mean total (value + position term) over the unperturbed and the noisy shots
    position: float = 0.0  #: pot probability of the next shot (the opponent's after a miss) from the final layout
    side: float = 0.0
    top: float = 0.0
    source: str = ""
    total: float = math.nan  #: value + the position term, unperturbed


@dataclass
class SearchSettings:
    n_geometric: int = 6  #: ghost-ball candidates refined
    angle_offsets: tuple[float, ...] = (0.0, 0.0015, -0.0015, 0.004, -0.004, 0.01, -0.01)
    speed_factors: tuple[float, ...] = (0.6, 1.0, 1.6, 2.5, 4.0)  #: times the ghost-ball speed
    spins: tuple[tuple[float, float], ...] = SPIN_VARIANTS  #: tip offsets tried under the spin model
    sweep_angles: int = 72  #: coarse sweep over all directions...
    sweep_speeds: tuple[float, ...] = (0.25, 0.6, 1.0)  #: ...at these fractions of the speed range
    top_k: int = 6  #: best candidates re-simulated under noise
    robust_samples: int = 10
    robust_angle: float = 0.002  #: perturbation (rad) when the env has no angle noise
    robust_speed: float = 0.05  #: relative perturbation when the env has no speed noise
    robust_tip: float = 0.02  #: tip perturbation (fraction of R) under the spin model when the env has no tip noise
    position_weight: float = 2.0  #: value of a sure next shot (pot probability 1) on top of keeping the turn (1)
    safety_weight: float = 1.0  #: cost of leaving the opponent a sure shot after a miss
    ease_noise: float = 0.002  #: angle spread (rad) the next shot's pot probability assumes without angle noise
    placements: int = 3  #: ball in hand: places searched from


# --- simulation and judgement ---------------------------------------------------------------------------------

@njit(cache=True)
def shot_keys(first_contact: np.ndarray, rail_after_contact: np.ndarray, pocket: np.ndarray,
              pocketed_at: np.ndarray, numbers: np.ndarray, cue: int, rail_detail: bool) -> tuple:
    """What the rules read of each shot of a batch, from the batch's arrays (no event log): rows ``(N, 4 + 2B)``
    of ``first contact's number (-1: none), the cue ball's pocket (-1), the balls that reached a cushion after the
    first contact, how many object balls dropped``, then their numbers in the order they dropped and their pockets
    (each padded with -1). The cushion column is the bit mask of those balls' numbers with ``rail_detail``, else
    only whether there is one (after the break the rules ask no more: ``ruleset.contact_fouls``). Also returns the
    bit masks ``(N,)``, and per shot whether two object balls dropped at the same instant (their order then needs
    the event log). The fields of :class:`~billiards_env.rules.ShotSummary`, as
    :func:`~billiards_env.rules.summarize_arrays` finds them in the log."""
    n, b = pocket.shape
    keys = np.full((n, 4 + 2 * b), -1, np.int64)
    masks = np.zeros(n, np.int64)
    ties = np.zeros(n, np.bool_)
    rows = np.empty(b, np.int64)
    for k in range(n):
        f = first_contact[k]
        keys[k, 0] = numbers[f] if f >= 0 else -1
        keys[k, 1] = pocket[k, cue]
        mask = 0
        for r in range(b):
            if rail_after_contact[k, r]:
                mask |= 1 << numbers[r]
        masks[k] = mask
        keys[k, 2] = mask if rail_detail else (1 if mask != 0 else 0)
        m = 0
        for r in range(b):
            if r != cue and pocket[k, r] >= 0:
                # insertion by drop time (stable in row order)
                i = m
                while i > 0 and pocketed_at[k, rows[i - 1]] > pocketed_at[k, r]:
                    rows[i] = rows[i - 1]
                    i -= 1
                rows[i] = r
                m += 1
        keys[k, 3] = m
        for i in range(m):
            keys[k, 4 + i] = numbers[rows[i]]
            keys[k, 4 + b + i] = pocket[k, rows[i]]
            if i > 0 and not pocketed_at[k, rows[i]] > pocketed_at[k, rows[i - 1]]:
                ties[k] = True
    return keys, masks, ties


def _key_from_log(events: np.ndarray, pocket: np.ndarray, numbers: np.ndarray, cue: int,
                  rail_detail: bool) -> tuple[np.ndarray, int]:
    """:func:`shot_keys`'s row and bit mask for one shot from its event log ``(M, 3)`` (kind, ball, other)."""
    b = len(numbers)
    s = summarize_arrays(events, pocket, numbers)
    pocketed, pockets = s.pocketed, s.pockets
    mask = int(sum(1 << int(n) for n in s.rail_balls))
    key = np.full(4 + 2 * b, -1, np.int64)
    key[0] = -1 if s.first_contact is None else s.first_contact
    key[1] = s.cue_pocket
    key[2] = mask if rail_detail else int(mask != 0)
    key[3] = len(pocketed)
    key[4:4 + len(pocketed)] = pocketed
    key[4 + b:4 + b + len(pocketed)] = pockets
    return key, mask


@njit(cache=True)
def judge_rows(keys: np.ndarray, masks: np.ndarray, rows: np.ndarray, states: np.ndarray, options: np.ndarray,
               row_of: np.ndarray, calls: np.ndarray, afters: np.ndarray, values: np.ndarray, nxt: np.ndarray,
               t_len: np.ndarray, t_rows: np.ndarray) -> None:
    """:meth:`Judge._judge` of the outcome keys ``keys[rows]`` (:func:`shot_keys` rows; ``masks``: their cushion
    bit masks) in one compiled call, for 9-ball and 8-ball: :func:`billiards_env.rules.pool_judge.play` (the
    Python rules' call and next state on integers, held equal to them by ``tests/rules/test_pool_judge.py``) from
    the decision's state (``states[0]``, a ``GAME_STATE_ROW`` record) with the options (``options[0]``), the
    shooter's declaration as ``PoolSession.declared_for`` makes it (on the 8 with calls on: the 8's pocket). Writes
    per row its value, who shoots next (1, 0, -1) and the rows of the balls that player may hit first
    (``t_rows[q, :t_len[q]]``, by ascending number; ``row_of``: the row of each number). ``calls``, ``afters``:
    one-record scratch arrays (records are passed in arrays: numba types an array argument once, a record at
    every call)."""
    state, opts, call, after = states[0], options[0], calls[0], afters[0]
    b = (keys.shape[1] - 4) // 2
    pocketed = np.empty(b, np.int64)
    pockets = np.empty(b, np.int64)
    on_call = pj.needs_called_pocket(state, opts)
    for q in range(rows.shape[0]):
        k = rows[q]
        n = keys[k, 3]
        called = -1
        for i in range(n):
            pocketed[i] = keys[k, 4 + i]
            pockets[i] = keys[k, 4 + b + i]
            if on_call and pocketed[i] == 8:
                called = pockets[i]
        pj.play(state, opts, keys[k, 0], masks[k], pocketed, pockets, n, keys[k, 1] >= 0, plain(False), called,
                call, after)
        t_len[q] = 0
        if call["over"]:
            values[q] = WIN_VALUE if call["winner"] == call["shooter"] else -WIN_VALUE
            nxt[q] = -1
        elif call["foul"]:
            values[q] = FOUL_VALUE
            nxt[q] = -1
        else:
            legal = pj.legal_mask(after)
            for number in range(row_of.shape[0]):
                if (legal >> number) & 1:
                    t_rows[q, t_len[q]] = row_of[number]
                    t_len[q] += 1
            if call["turn_over"]:
                values[q] = 0.0
                nxt[q] = 0
            else:
                kept = 0  # the balls pocketed and not respotted
                for i in range(n):
                    if not (call["respot"] >> pocketed[i]) & 1:
                        kept += 1
                values[q] = KEEP_VALUE + BALL_VALUE * kept
                nxt[q] = 1


def _rails(mask: int) -> tuple[int, ...]:
    """The ball numbers of a bit mask, ascending."""
    out = _RAILS.get(mask)
    if out is None:
        out = _RAILS[mask] = tuple(n for n in range(mask.bit_length()) if (mask >> n) & 1)
    return out


_RAILS: dict[int, tuple[int, ...]] = {}


class Judge:
    """The rules' verdict on shots of one decision (one game state), each distinct outcome judged once: a shot's
    value (+10 won, -10 lost, -3 a foul, +1 for keeping the turn plus 0.1 per ball that counts, 0 for a legal
    miss), who shoots next (1: the shooter again, 0: the opponent without ball in hand, -1: nobody or ball in hand)
    and the rows of the balls that player may hit first. Outcomes are :func:`shot_keys` rows: after the break only
    whether some ball reached a cushion after the first contact counts, not which (the rules ask no more; a test
    holds them to it: tests/players/test_search_fast.py), so one verdict serves all the shots that differ only
    there (the summary judged is the first such shot's); the same for the pockets the balls dropped into, unless
    the rules read them (``Ruleset.reads_pockets``: a called pocket)."""

    def __init__(self, ctx: ShotContext) -> None:
        game = ctx.game
        self.ctx = ctx
        self.numbers = np.ascontiguousarray(game.numbers, dtype=np.int64)
        #: Whether the verdict may depend on which balls reached a cushion (the break), not only on whether one did.
        self.rail_detail = bool(game.game_state.break_shot)
        #: Whether it may depend on the pockets the balls dropped into (a called pocket), not only on which dropped.
        self.pocket_detail = bool(game.rules.reads_pockets(game.game_state))
        self.verdicts: dict[bytes, int] = {}  #: outcome key -> index into the lists below
        self.values: list[float] = []
        self.next: list[int] = []
        self.targets: list[np.ndarray] = []
        self._after: dict[Any, np.ndarray] = {}  # call -> legal rows after it
        #: 9-ball and 8-ball: the compiled rules' inputs (:func:`judge_rows`): the state and options records, the
        #: row of each number, scratch call and state records; None: the Python rules judge (:meth:`_judge`).
        self._compiled: tuple | None = None
        if type(game.rules) in (NineBall, EightBall):
            row_of = np.full(int(self.numbers.max()) + 1, -1, np.int64)
            row_of[self.numbers] = np.arange(len(self.numbers))
            state, options = np.zeros(1, pj.GAME_STATE_ROW), np.zeros(1, pj.RULE_OPTIONS)
            state[0], options[0] = pj.state_row(game.game_state), pj.options_row(game.rules)
            self._compiled = (state, options, row_of, np.zeros(1, pj.CALL_ROW), np.zeros(1, pj.GAME_STATE_ROW))
        self._groups: tuple[int, np.ndarray, np.ndarray] | None = None  # (verdicts, t_flat, t_off) of groups()

    def groups(self) -> tuple[np.ndarray, np.ndarray]:
        """The legal rows after every verdict so far as ``(t_flat, t_off)``: verdict ``v``'s are
        ``t_flat[t_off[v]:t_off[v + 1]]`` (kept until a new verdict is judged)."""
        if self._groups is None or self._groups[0] != len(self.targets):
            lens = np.array([len(t) for t in self.targets], dtype=np.int64)
            t_off = np.concatenate([[0], np.cumsum(lens)]).astype(np.int64)
            t_flat = np.concatenate(self.targets).astype(np.int64) if self.targets else np.zeros(0, np.int64)
            self._groups = (len(self.targets), t_flat, t_off)
        return self._groups[1], self._groups[2]

    def ids(self, keys: np.ndarray, masks: np.ndarray) -> np.ndarray:
        """The verdict index of each outcome key (judging the new ones; ``masks``: the shots' cushion bit masks,
        :func:`shot_keys`). Unless the rules read pockets here (:attr:`pocket_detail`), keys that differ only in the
        pockets share a verdict (judged with pocket 0 for every ball that dropped)."""
        keys = np.array(keys, dtype=np.int64)  # a copy: the pockets may be blanked below
        if not self.pocket_detail and keys.ndim == 2:
            b = len(self.numbers)
            pockets = keys[:, 4 + b:]
            pockets[pockets >= 0] = 0  # the balls' pockets, as "dropped"
            keys[:, 1] = np.where(keys[:, 1] >= 0, 0, -1)  # the cue ball's: whether it dropped
        w = keys.shape[1] * keys.itemsize if keys.ndim == 2 else 0
        buf = keys.tobytes()  # the rows' bytes in one call: row k is buf[k * w:(k + 1) * w] (its tobytes())
        verdicts = self.verdicts
        out = [0] * len(keys)
        new: list[int] = []  # the first shot of each new outcome, in the order its verdict index was given
        for k in range(len(keys)):
            kb = buf[k * w:(k + 1) * w]
            v = verdicts.get(kb)
            if v is None:
                v = verdicts[kb] = len(self.values) + len(new)
                new.append(k)
            out[k] = v
        if new and self._compiled is not None:
            self._judge_compiled(keys, np.asarray(masks, dtype=np.int64), np.array(new, dtype=np.int64))
        else:
            for k in new:
                self._judge(keys[k], int(masks[k]))
        return np.array(out, dtype=np.int64)

    def _judge_compiled(self, keys: np.ndarray, masks: np.ndarray, rows: np.ndarray) -> None:
        """The verdicts of the outcomes ``keys[rows]`` appended, from one :func:`judge_rows` call."""
        state, options, row_of, call, after = self._compiled  # type: ignore[misc]
        n = len(rows)
        values, nxt, t_len = np.empty(n), np.empty(n, np.int64), np.empty(n, np.int64)
        t_rows = np.empty((n, len(self.numbers)), np.int64)
        judge_rows(keys, masks, rows, state, options, row_of, call, after, values, nxt, t_len, t_rows)
        self.values.extend(values.tolist())
        self.next.extend(nxt.tolist())
        self.targets.extend(t_rows[q, :t_len[q]].copy() for q in range(n))

    def _judge(self, key: np.ndarray, mask: int) -> int:
        game = self.ctx.game
        b = len(self.numbers)
        k = key.tolist()
        n_pot = k[3]
        rails = _rails(mask)
        pocketed = tuple(k[4:4 + n_pot])
        pockets = tuple(k[4 + b:4 + b + n_pot])
        summary = ShotSummary(None if k[0] < 0 else k[0], rails, pocketed, pockets, k[1] >= 0, k[1])
        info = game.declared_for(summary)  # what the shooter would have called for this outcome
        state = game.game_state
        call = game.rules.call(state, summary, info)
        if call.game_over:
            value, nxt, rows = (WIN_VALUE if call.winner == call.shooter else -WIN_VALUE), -1, np.zeros(0, np.int64)
        elif call.foul:
            value, nxt, rows = FOUL_VALUE, -1, np.zeros(0, np.int64)
        else:
            rows = self._after.get(call)
            if rows is None:
                nxt_state = game.rules.next_state(state, call)
                rows = self._after[call] = np.array([game.row_of[n] for n in game.rules.legal_targets(nxt_state)],
                                                    dtype=np.int64)
            if call.turn_over:
                value, nxt = 0.0, 0
            else:
                value, nxt = KEEP_VALUE + BALL_VALUE * len(set(call.pocketed) - set(call.respot)), 1
        self.values.append(value)
        self.next.append(nxt)
        self.targets.append(rows)
        return len(self.values) - 1


@dataclass
class Judged:
    """A judged batch: per shot ``pots``, ``scratch``, ``hit``, ``values``, who shoots ``next`` (1, 0, -1) and
    the group of that player's legal balls (``group``: rows ``t_flat[t_off[g]:t_off[g + 1]]``), and the batch."""

    pots: np.ndarray
    scratch: np.ndarray
    hit: np.ndarray
    values: np.ndarray
    res: BatchResult
    next: np.ndarray
    group: np.ndarray
    t_flat: np.ndarray
    t_off: np.ndarray


def simulate_candidates(ctx: ShotContext, angles: Any, speeds: Any, sides: Any = None, tops: Any = None
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, BatchResult]:
    """Play candidate shots, all in one batch (:func:`~billiards_env.physics.batch.run_shots`; each row is the
    single ``Simulator.run`` of its shot): ``(pots, scratch, hit, value, batch result)`` per candidate. Without a
    game the value is :func:`candidate_value`; in a game it is the rules' verdict (:class:`Judge`)."""
    j = _simulate_judged(ctx, angles, speeds, sides, tops)
    return j.pots, j.scratch, j.hit, j.values, j.res


def _simulate_judged(ctx: ShotContext, angles: Any, speeds: Any, sides: Any = None, tops: Any = None,
                     judge: Judge | None = None) -> Judged:
    """:func:`simulate_candidates`, with who shoots next and his legal balls (see :class:`Judged`)."""
    game = ctx.game is not None
    spin = ctx.physics.has_spin
    res = run_shots(ctx.simulator, ctx.balls, angles, speeds, ball=ctx.cue, validate=False,
                    side=sides if spin else None, top=tops if spin else None)
    targets = np.asarray(ctx.targets, dtype=np.int64)
    pots = (res.pocket[:, targets] >= 0).sum(axis=1)
    scratch = res.pocket[:, ctx.cue] >= 0
    hit = res.first_contact >= 0
    n = len(res.time)
    if not game:
        # Without rules the shooter plays on only after a pot without a scratch: a miss earns no position (it
        # must never outrank a pot), and a cleared table has no next shot.
        left = res.on_table[:, targets].any(axis=1)
        nxt = np.where((pots > 0) & ~scratch & left, 1, -1)
        return Judged(pots, scratch, hit, candidate_value(pots, scratch, hit), res, nxt, np.zeros(n, np.int64),
                      targets, np.array([0, len(targets)], np.int64))
    judge = judge or Judge(ctx)
    keys, masks, ties = shot_keys(res.first_contact, res.rail_after_contact, res.pocket, res.pocketed_at,
                                  judge.numbers, int(ctx.cue), judge.rail_detail)
    for k in np.flatnonzero(ties):  # balls dropping at one instant: their order is the event log's
        one = run_shots(ctx.simulator, ctx.balls, np.asarray(angles)[k:k + 1], np.asarray(speeds)[k:k + 1],
                        ball=ctx.cue, validate=False, events=True,
                        side=np.asarray(sides)[k:k + 1] if spin else None,
                        top=np.asarray(tops)[k:k + 1] if spin else None)
        ev = one.events
        keys[k], masks[k] = _key_from_log(np.stack([ev.kind, ev.ball, ev.other], axis=1), one.pocket[0],
                                          judge.numbers, int(ctx.cue), judge.rail_detail)
    ids = judge.ids(keys, masks)
    values = np.asarray(judge.values)[ids]
    nxt = np.asarray(judge.next, dtype=np.int64)[ids]
    t_flat, t_off = judge.groups()
    return Judged(pots, scratch, hit, values, res, nxt, ids, t_flat, t_off)


def candidate_value(pots: Any, scratch: Any, hit: Any) -> Any:
    """``pots - 3 scratch - 0.5 (no ball hit)``, for one candidate or arrays of them."""
    return pots - 3.0 * scratch - np.where(hit, 0.0, 0.5)


# --- position: the ease of the next shot -------------------------------------------------------------------------

def next_shot_ease(table: Any, radius: np.ndarray, pos: np.ndarray, on: np.ndarray, cue: int,
                   targets: Sequence[Sequence[int]], sigma: float, max_cut: float = MAX_CUT,
                   windows: dict | None = None, physics: Any = None) -> np.ndarray:
    """For ``N`` layouts (``pos`` (N, B, 2), ``on`` (N, B)), the probability of potting the easiest ghost-ball shot
    from the cue ball at one of the layout's ``targets[k]`` (rows), when the cue angle errs with spread ``sigma``
    (rad): :func:`~.shots.pot_probability` of its tolerance, the tolerance being the geometric player's (the pocket
    window seen from the ball, scaled by ``(r_c + r_o) cos(cut) / (d_cue + r_c + r_o)``, divided by 10 when the cue
    ball's or the ball's path is blocked; cuts beyond ``max_cut`` and ghost balls off the table do not count). One
    compiled call (:func:`billiards_env.players.geometry.layouts_ease`); ``windows`` is not used any more (the
    windows are exact, computed once per ball position that the layouts share with the first)."""
    from billiards_env.physics import Physics

    n = len(pos)
    if n == 0:
        return np.zeros(0)
    pos = np.ascontiguousarray(pos, dtype=np.float64)
    lens = np.array([len(t) for t in targets], dtype=np.int64)
    t_off = np.concatenate([[0], np.cumsum(lens)]).astype(np.int64)
    t_flat = np.concatenate([np.asarray(t, dtype=np.int64) for t in targets]) if n else np.zeros(0, np.int64)
    return layouts_ease(pos, np.ascontiguousarray(on, dtype=np.bool_), np.ascontiguousarray(radius, dtype=np.float64),
                        int(cue), np.arange(n, dtype=np.int64), np.arange(n, dtype=np.int64), t_flat, t_off,
                        *table_model(table, physics or Physics()), float(sigma), float(max_cut), pos[0])


def _positions(ctx: ShotContext, st: SearchSettings, j: Judged, rows: np.ndarray, tm: Any
               ) -> tuple[np.ndarray, np.ndarray]:
    """Position term and pot probability of the next shot (the shooter's when he keeps the turn, the opponent's
    after a legal miss, 0 otherwise) for batch rows ``rows`` (see :func:`search_shot`)."""
    term = np.zeros(len(j.values))
    ease = np.zeros(len(j.values))
    rows = np.asarray(rows, dtype=np.int64)
    rows = rows[j.next[rows] >= 0]
    if len(rows) == 0:
        return term, ease
    sigma = max(ctx.angle_noise, st.ease_noise)
    b = ctx.balls
    e = layouts_ease(j.res.pos, j.res.on_table, np.ascontiguousarray(b.radius, dtype=np.float64), int(ctx.cue), rows,
                     j.group, j.t_flat, j.t_off, *tm, float(sigma), MAX_CUT,
                     np.ascontiguousarray(b.pos, dtype=np.float64))
    ease[rows] = e
    term[rows] = np.where(j.next[rows] == 1, st.position_weight, -st.safety_weight) * e
    return term, ease


# --- the search -------------------------------------------------------------------------------------------------

@dataclass
class Candidates:
    """Candidate shots as arrays: ``angle``, ``speed``, ``side``, ``top``, and ``source``: the ghost-ball shot
    (``shots[source]``: target, pocket) each comes from, -1 for the sweep."""

    angle: np.ndarray
    speed: np.ndarray
    side: np.ndarray
    top: np.ndarray
    source: np.ndarray
    shots: np.ndarray  #: (G, 2) target, pocket of the ghost-ball shots used

    def name(self, k: int) -> str:
        s = int(self.source[k])
        return "sweep" if s < 0 else f"ghost:{int(self.shots[s, 0])}->{int(self.shots[s, 1])}"


def _candidates(ctx: ShotContext, st: SearchSettings, tm: Any = None) -> Candidates:
    """Every candidate: each ghost-ball shot (cut up to 85 deg, the ``n_geometric`` easiest) at the angle offsets
    (stun, its own speed), at the speed factors with every tip variant (when the shooter sets tip offsets: the spin
    model and an action with spin dims; else stun only), then the sweep of directions (from the direct hit on the
    nearest legal ball) and speeds."""
    lo, hi = ctx.speed_range
    spins = st.spins if ctx.tip_offsets else ((0.0, 0.0),)
    b = ctx.balls
    rows = ghost_shots(np.ascontiguousarray(b.pos, dtype=np.float64), np.ascontiguousarray(b.on_table, dtype=np.bool_),
                       np.ascontiguousarray(b.radius, dtype=np.float64), np.ascontiguousarray(b.mass, dtype=np.float64),
                       int(ctx.cue), np.asarray(ctx.targets, dtype=np.int64),
                       *(tm or context_model(ctx)), float(lo), float(hi), math.radians(85.0),
                       ARRIVE_SPEED, np.asarray(SPEED_FACTORS), True)[: st.n_geometric]
    offsets = np.asarray(st.angle_offsets, dtype=np.float64)
    variants = [(f, sd, tp) for f in st.speed_factors for sd, tp in spins
                if not (f == 1.0 and sd == 0.0 and tp == 0.0)]  # (1.0, stun) is already in (offset 0)
    vf = np.array([v[0] for v in variants], dtype=np.float64)
    per = len(offsets) + len(variants)
    g = len(rows)
    ang = np.empty(g * per)
    spd = np.empty(g * per)
    sd = np.zeros(g * per)
    tp = np.zeros(g * per)
    for i in range(g):
        a, v = rows[i, COL_ANGLE], rows[i, COL_SPEED]
        k = i * per
        ang[k:k + len(offsets)] = a + offsets
        spd[k:k + len(offsets)] = min(max(v, lo), hi)
        k += len(offsets)
        ang[k:k + len(variants)] = a
        spd[k:k + len(variants)] = np.minimum(np.maximum(v * vf, lo), hi)
        sd[k:k + len(variants)] = [x[1] for x in variants]
        tp[k:k + len(variants)] = [x[2] for x in variants]
    base = direct_hit(b, ctx.cue, ctx.targets)[0]
    ks = np.repeat(np.arange(st.sweep_angles, dtype=np.float64), len(st.sweep_speeds))
    fs = np.tile(np.asarray(st.sweep_speeds, dtype=np.float64), st.sweep_angles)
    sweep_a = base + 2.0 * math.pi * ks / st.sweep_angles
    sweep_v = lo + fs * (hi - lo)
    n_s = len(ks)
    return Candidates(np.concatenate([ang, sweep_a]), np.concatenate([spd, sweep_v]),
                      np.concatenate([sd, np.zeros(n_s)]), np.concatenate([tp, np.zeros(n_s)]),
                      np.concatenate([np.repeat(np.arange(g), per), np.full(n_s, -1)]).astype(np.int64),
                      rows[:, [COL_TARGET, COL_POCKET]].astype(np.int64))


def search_shot(ctx: ShotContext, settings: SearchSettings | None = None,
                rng: np.random.Generator | None = None, windows: dict | None = None,
                playable: Any = None, judge: Judge | None = None) -> tuple[float, float, Outcome]:
    """Simulate candidate shots with the exact solver (in batches: one compiled call for all candidates, one for
    the noisy re-runs of the best) and pick the best.

    Candidates (:func:`_candidates`): the ghost-ball shots at angle offsets, speed factors and, under the spin model,
    tip offsets (stun, draw, follow, english), plus a sweep of directions and speeds (kicks and safeties). Each
    candidate's total is its value (in a game the rules' verdict: win, loss, foul, turn kept or lost) plus a
    position term from its final layout: ``position_weight`` times the pot probability of the next shot when the
    turn is kept (:func:`next_shot_ease`), minus ``safety_weight`` times the opponent's when it is lost without a
    foul. The ``top_k`` best totals are re-simulated ``robust_samples`` times under the shot noise (the env's, or the
    small ``robust_*`` defaults), and the shot with the best mean total (the unperturbed run counted as one sample)
    is played; in an env without shot noise the unperturbed total comes first and the mean only breaks ties.
    Returns ``(angle, speed, outcome)``; the outcome holds the tip offsets. ``playable``: maps the candidates to the
    shots an action type can express (:func:`playable_shots`), so the search values what will be played.
    ``judge``: the rules' verdicts of this decision so far (:class:`Judge`, shared by the searches of one decision).
    ``windows``: not used (kept for callers that pass a cache).
    """
    st = settings or SearchSettings()
    rng = rng or np.random.default_rng(0)
    lo, hi = ctx.speed_range
    spin = ctx.physics.has_spin
    tm = context_model(ctx)  # the table state's, made once per state
    c = _candidates(ctx, st, tm)
    if playable is not None:
        c.angle, c.speed, c.side, c.top = _play(playable, c)
    if ctx.game is not None and judge is None:
        judge = Judge(ctx)
    j = _simulate_judged(ctx, c.angle, c.speed, c.side, c.top, judge)
    values = j.values
    # Position terms move a total by less than the gap between outcome classes (win 10 > kept 1-1.9 + 2 >
    # missed 0 - 1 > foul -3): only the best class's candidates need them.
    near = np.flatnonzero(values >= values.max() - 0.95)
    term, ease = _positions(ctx, st, j, near, tm)
    totals = values + term
    order = np.argsort(-totals, kind="stable")
    shortlist: list[Outcome] = []
    for k in order:
        angle, speed, side, top = float(c.angle[k]), float(c.speed[k]), float(c.side[k]), float(c.top[k])
        if all(abs(angle - q.angle) > 1e-3 or abs(speed - q.speed) > 0.05 or side != q.side or top != q.top
               for q in shortlist):
            shortlist.append(Outcome(angle, speed, int(j.pots[k]), bool(j.scratch[k]), bool(j.hit[k]),
                                     float(values[k]), position=float(ease[k]), side=side, top=top,
                                     source=c.name(k), total=float(totals[k])))
        if len(shortlist) >= st.top_k:
            break
    sa = ctx.angle_noise if ctx.angle_noise > 0 else st.robust_angle
    ss = ctx.speed_noise if ctx.speed_noise > 0 else st.robust_speed
    stn = (ctx.tip_noise if ctx.tip_noise > 0 else st.robust_tip) if spin else 0.0
    # Robustness: the noisy re-runs of the whole shortlist in one batch (drawn in the order of a loop).
    m = st.robust_samples
    if shortlist and m > 0:
        per = 4 if stn > 0.0 else 2
        z = rng.standard_normal(len(shortlist) * m * per).reshape(len(shortlist) * m, per)
        base = np.array([[o.angle, o.speed, o.side, o.top] for o in shortlist]).repeat(m, axis=0)
        n_a = base[:, 0] + (0.0 + sa * z[:, 0])
        n_v = np.minimum(np.maximum(base[:, 1] * (1.0 + (0.0 + ss * z[:, 1])), lo), hi)
        n_sd, n_tp = base[:, 2].copy(), base[:, 3].copy()
        if stn > 0.0:
            for i in range(len(base)):
                n_sd[i], n_tp[i] = _tip_inside(n_sd[i] + (0.0 + stn * z[i, 2]), n_tp[i] + (0.0 + stn * z[i, 3]))
        nj = _simulate_judged(ctx, n_a, n_v, n_sd, n_tp, judge)
        n_term, _ = _positions(ctx, st, nj, np.arange(len(n_a)), tm)
        n_totals = nj.values + n_term
        # Without shot noise in the env the unperturbed outcome is what happens: the noisy runs only break ties
        # (towards shots with margin); with noise, every run is a sample of what may happen.
        exact = ctx.angle_noise == 0.0 and ctx.speed_noise == 0.0 and (not spin or ctx.tip_noise == 0.0)
        for q, o in enumerate(shortlist):
            block = n_totals[q * m:(q + 1) * m]
            mean = float((o.total + block.sum()) / (1 + len(block)))
            o.robust = o.total + 0.5 * mean if exact else mean
    else:
        for o in shortlist:
            o.robust = o.total
    best = max(shortlist, key=lambda o: o.robust)  # the first of equals (a stable choice)
    return best.angle, best.speed, best


def _tip_inside(side: float, top: float, limit: float = 0.5 * (1.0 - 1e-12)) -> tuple[float, float]:
    """A tip offset moved onto the miscue limit if beyond it (as the env keeps noisy tips legal)."""
    r = math.hypot(side, top)
    if r > limit:
        return side * limit / r, top * limit / r
    return side, top


# --- ball in hand ------------------------------------------------------------------------------------------------

def placement_candidates(ctx: ShotContext, n: int, backs: tuple[float, ...] = (0.25, 0.5),
                         cuts: tuple[float, ...] = (0.0, math.radians(25.0), -math.radians(25.0)),
                         sigma: float = 0.002) -> list[tuple[float, float]]:
    """Ball in hand: up to ``n`` legal places (at least a ball apart) that leave the easiest shot, best first. The
    places tried: ``backs`` metres behind the ghost ball of every legal ball and pocket, straight in and at the
    ``cuts`` (for position after the pot), moved to the nearest legal point (off the balls and the pockets' capture
    circles, in ``ctx.place_area``); each scored by :func:`next_shot_ease`. Two compiled calls
    (:func:`billiards_env.players.geometry.search_places`, :func:`~billiards_env.players.geometry.places_ease`)."""
    from billiards_env.physics.errors import SceneError

    b = ctx.balls
    r = float(b.radius[ctx.cue])
    tm = context_model(ctx)  # the table state's, made once per state
    pos = np.ascontiguousarray(b.pos, dtype=np.float64)
    on = np.ascontiguousarray(b.on_table, dtype=np.bool_)
    radius = np.ascontiguousarray(b.radius, dtype=np.float64)
    targets = np.asarray(ctx.targets, dtype=np.int64)
    places, status = search_places(pos, on, radius, int(ctx.cue), targets, *tm,
                                   np.asarray(ctx.place_area, dtype=np.float64), np.asarray(backs, dtype=np.float64),
                                   np.asarray(cuts, dtype=np.float64))
    if status == 2:
        raise SceneError(f"no legal point for ball row {ctx.cue} in the area {ctx.place_area}: it is covered by "
                         "other balls")
    if status == 1:  # no window anywhere: the middle of the area
        return [(float(places[0, 0]), float(places[0, 1]))]
    ease = places_ease(places, pos, on, radius, int(ctx.cue), targets, *tm, float(sigma), MAX_CUT)
    out: list[tuple[float, float]] = []
    for k in np.argsort(-ease, kind="stable"):
        p = (float(places[k, 0]), float(places[k, 1]))
        if all(math.hypot(p[0] - q[0], p[1] - q[1]) > 2.0 * r for q in out):
            out.append(p)
        if len(out) >= n:
            break
    return out


# --- what an action type can play ----------------------------------------------------------------------------------

class Playable:
    """The map of candidate shots to the shots their actions play: through an action type (``codec``) and back,
    float32 as every action is (see :func:`playable_shots`). Call it on a list of ``(angle, speed, side, top,
    source)`` tuples, or :meth:`arrays` on arrays; :meth:`action_for` gives the action of a shot it returned. An
    action type that maps arrays itself (``round_trip_arrays``: the plain absolute aim) is asked once for all."""

    def __init__(self, state: Any, codec: Any, place: tuple[float, float] | None = None) -> None:
        self.state = state
        self.codec = codec
        self.place = place
        self.actions: dict[tuple[float, float, float, float], np.ndarray] = {}
        self._fast = bool(getattr(codec, "plain_absolute", False))
        self._last: tuple[np.ndarray, ...] | None = None

    def __call__(self, cands: list[tuple[float, float, float, float, str]]
                 ) -> list[tuple[float, float, float, float, str]]:
        if not cands:
            return []
        arr = np.array([c[:4] for c in cands], dtype=np.float64)
        a, v, sd, tp = self.arrays(arr[:, 0], arr[:, 1], arr[:, 2], arr[:, 3])
        return [(float(a[k]), float(v[k]), float(sd[k]), float(tp[k]), c[4]) for k, c in enumerate(cands)]

    def arrays(self, angles: np.ndarray, speeds: np.ndarray, sides: np.ndarray, tops: np.ndarray
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The played ``(angles, speeds, sides, tops)`` of candidate arrays."""
        if self._fast:
            angle, speed, side, top, dims = self.codec.round_trip_arrays(angles, speeds, sides, tops)
            self._last = (angle, speed, side, top, dims)
            return angle, speed, side, top
        codec, state = self.codec, self.state
        out = np.empty((len(angles), 4))
        for k in range(len(angles)):
            action = to_action(codec, state, float(angles[k]), float(speeds[k]), place=self.place,
                               side=float(sides[k]), top=float(tops[k]))
            s = codec.shot(state, action)
            out[k] = (s.angle, s.speed, s.side, s.top)
            self.actions[(s.angle, s.speed, s.side, s.top)] = action
        return out[:, 0], out[:, 1], out[:, 2], out[:, 3]

    def action_for(self, angle: float, speed: float, side: float, top: float) -> np.ndarray | None:
        """The action (its shot dims at least) of a shot :meth:`arrays` returned, None if it returned none such."""
        if not self._fast:
            return self.actions.get((angle, speed, side, top))
        if self._last is None:
            return None
        a, v, sd, tp, dims = self._last
        hit = np.flatnonzero((a == angle) & (v == speed) & (sd == side) & (tp == top))
        return dims[hit[-1]] if len(hit) else None


def _play(playable: Any, c: Candidates) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The played shots of candidates ``c`` through ``playable`` (a :class:`Playable`, or a function on lists of
    ``(angle, speed, side, top, source)``)."""
    if hasattr(playable, "arrays"):
        return playable.arrays(c.angle, c.speed, c.side, c.top)
    out = playable([(float(c.angle[k]), float(c.speed[k]), float(c.side[k]), float(c.top[k]), c.name(k))
                    for k in range(len(c.angle))])
    arr = np.array([o[:4] for o in out], dtype=np.float64).reshape(-1, 4)
    return arr[:, 0], arr[:, 1], arr[:, 2], arr[:, 3]


def playable_shots(state: Any, codec: Any, place: tuple[float, float] | None = None) -> Playable | None:
    """The map of candidates ``(angle, speed, side, top, source)`` to the shots their actions play: through the
    action type ``codec`` and back, float32 as every action is. The search then values exactly what the env will
    play: a break or a hard shot through a cluster is chaotic (a 1e-8 rad change of the cue angle, the float32
    rounding of an action, can drop the 8), and an action type may not express every direction (``ghost`` aim:
    only direct hits, within ``ghost_max_angle``). The plain absolute aim is mapped on arrays, every other type
    shot by shot. None without an action type."""
    if codec is None:
        return None
    return Playable(state, codec, place)


class SearchPlayer(BasePlayer):
    """Simulates candidate shots with the env's exact solver and plays the best for the position it leaves (see
    :func:`search_shot`)."""

    name = "search"
    #: It does not read the observation (the env need not observe for it).
    reads_observation = False

    def __init__(self, seed: int | None = 0, settings: SearchSettings | None = None):
        self.settings = settings or SearchSettings()
        self.rng = np.random.default_rng(seed)
        self.last: Outcome | None = None

    def reset(self, seed: int | None = None) -> None:
        if seed is not None:
            self.rng = np.random.default_rng(seed)

    def choose(self, state: Any, obs: Any, codec: Any) -> np.ndarray:
        """The action (in ``codec``, an action type) of the best shot found on ``state`` among the shots ``codec``
        can play (:func:`playable_shots`). In a game it plays by the rules (candidates valued by the rules' call and the
        position they leave), breaks at full power, and with the cue ball in hand searches from the best few places
        (:func:`placement_candidates`) and plays the best shot of all."""
        ctx = shot_context(state, codec)
        if ctx.game is not None and ctx.game.game_state.break_shot:
            place, angle, speed = break_shot(ctx)
            self.last = None
            return to_action(codec, state, angle, speed, place=place)
        places: list[Any] = [None]
        if ctx.place_area is not None:
            sigma = max(ctx.angle_noise, self.settings.ease_noise)
            places = placement_candidates(ctx, max(self.settings.placements, 1), sigma=sigma)
        judge = Judge(ctx) if ctx.game is not None else None  # one game state: the verdicts are shared
        best: tuple[Any, float, float, Outcome, Any] | None = None
        for place in places:
            play = playable_shots(state, codec, place)
            with state.cue_moved_to(place):
                angle, speed, out = search_shot(ctx, self.settings, self.rng, None, play, judge)
            if best is None or out.robust > best[3].robust:
                best = (place, angle, speed, out, play)
        assert best is not None
        place, angle, speed, self.last, play = best
        action = to_action(codec, state, angle, speed, place=place, side=self.last.side, top=self.last.top)
        searched = None if play is None else play.action_for(angle, speed, self.last.side, self.last.top)
        if searched is not None:  # the shot dims of the very action searched (the call and place stay)
            shot_dims = 4 if codec.spin else 2
            action[:shot_dims] = searched[:shot_dims]
        return codec.with_calls(action, **self.calls_of_action(ctx, codec, action))

    @staticmethod
    def calls_of_action(ctx: ShotContext, codec: Any, action: np.ndarray) -> dict[str, Any]:
        """The declarations of the shot ``action`` plays (decoded by ``codec``, from its own placement: the very
        shot the env plays without noise, so a call on a shot that scatters balls names what it pockets): the
        game's :meth:`~billiards_env.games.session.GameSession.calls_for` on where it sends the balls."""
        if ctx.game is None or not ctx.game.needs_calls():
            return {}
        state = ctx.table_state
        shot = codec.shot(state, action)
        spin = ctx.physics.has_spin
        with state.cue_moved_to(shot.place):
            struck = ctx.balls.strike(ctx.cue, shot.angle, shot.speed,
                                      **({"side": shot.side, "top": shot.top} if spin else {}), physics=ctx.physics)
            res = ctx.simulator.run(struck, validate=False)
        return ctx.game.calls_for(np.asarray(res.pocket, dtype=np.int64))

    @staticmethod
    def calls_for(ctx: ShotContext, angle: float, speed: float, out: Outcome) -> dict[str, Any]:
        """The declarations of the chosen shot (the game's :meth:`~billiards_env.games.session.GameSession.calls_for`
        on where the shot sends the balls: 8-ball on the 8, the 8's pocket; straight pool, the ball it pots and its
        pocket); none outside a game or when the game needs none now."""
        if ctx.game is None or not ctx.game.needs_calls():
            return {}
        spin = ctx.physics.has_spin
        shot = ctx.balls.strike(ctx.cue, angle, speed, **({"side": out.side, "top": out.top} if spin else {}),
                                physics=ctx.physics)
        res = ctx.simulator.run(shot, validate=False)
        return ctx.game.calls_for(np.asarray(res.pocket, dtype=np.int64))


__all__ = ["Outcome", "SearchSettings", "search_shot", "simulate_candidates", "candidate_value", "SearchPlayer",
           "playable_shots", "Playable", "next_shot_ease", "placement_candidates", "shot_keys", "Judge", "SPIN_VARIANTS"]
