"""9-ball and 8-ball: their session (:class:`PoolSession`; the rules themselves are :mod:`billiards_env.rules`).

Both are pool games on a pool table: the cue ball in hand behind the head string (the kitchen) or anywhere, the
same eleven game features, the rack ordered as the rules say (9-ball: the 1 at the apex, the 9 in the middle;
8-ball: the 8 in the middle of the third row, a solid and a stripe in the back corners), and the ``ball_in_hand``
opening (run-out practice: a break played for nobody, then the cue ball in hand anywhere).
"""
from __future__ import annotations

from typing import Any, ClassVar

import numpy as np
from numba import njit
from numba.np.random.random_methods import random_interval

from billiards_env.physics.layout import (DIAMOND_ORDER, RACK_ORDER, head_string_x, spot_cue_ball,
                                          spot_object_ball)
from billiards_env.physics.outcome import ShotOutcome
from billiards_env.physics.table import Table
from billiards_env.rules import (ANYWHERE, KITCHEN, SOLIDS, STRIPES, EightBall, EightBallOptions,
                                 GameState, NineBall, NineBallOptions, RulesError, ShotInfo, ShotSummary,
                                 summarize_outcome)
from billiards_env.rules.pool_judge import (BIH_KITCHEN, BIH_NO, GAME_EIGHT, GROUPS_OPEN, GROUPS_SOLIDS, REASONS,
                                            legal_mask, legal_mask_for, state_row)
from billiards_env.rules.state import Call
from billiards_env.table_state import Area, RectArea, ShotView, TableState

from .declarations import CALLED_POCKET, PUSH_OUT, Declaration
from .hud import base_hud
from .infos import InfoSpec, code
from .session import GameSession, Verdict, flag_option

_NO_DECLARATION = ShotInfo()
#: The game features every pool game observes (see :meth:`PoolSession.features`).
N_POOL_FEATURES = 11
#: ``info["ball_in_hand"]``: the code of the state's value (0 none, 1 anywhere, 2 in the kitchen).
BALL_IN_HAND_NAMES = ("none", ANYWHERE, KITCHEN)
_BIH_CODE = {False: 0, ANYWHERE: 1, KITCHEN: 2}
#: ``info["groups"]``: 0 open table, 1 player 0 has the solids (player 1 the stripes), 2 player 0 the stripes.
GROUPS_NAMES = ("open", SOLIDS, STRIPES)
_GROUPS_CODE = {None: 0, (SOLIDS, STRIPES): 1, (STRIPES, SOLIDS): 2}


def pool_place_area(state: GameState, table: Table, radius: float) -> Area | None:
    """Where the shooter may place the cue ball: behind the head string (kitchen) or anywhere on the table (compiled
    twin: :func:`pool_place_area_row`)."""
    bih = state.ball_in_hand
    if not bih or state.game_over:
        return None
    x1 = head_string_x(table) if bih == KITCHEN else table.length - radius
    return RectArea(radius, x1, radius, table.width - radius)


@njit(cache=True)
def pool_features(st: np.void, me: int, out: np.ndarray) -> None:
    """:meth:`PoolSession.features` of the game state ``st`` (a ``GAME_STATE_ROW`` record of
    :mod:`billiards_env.rules.pool_judge`) seen by
    player ``me``, into ``out`` (eleven float32 values). The one implementation: the session calls it, and so does
    the native vector env's compiled observation (:mod:`billiards_env.envs._game_kernels`)."""
    over = st["over"] != 0
    mine = st["shooter"] == me and not over
    bih = st["bih"]
    out[0] = 1.0 if (mine and bih != BIH_NO) else 0.0
    out[1] = 1.0 if (mine and bih == BIH_KITCHEN) else 0.0
    out[2] = 1.0 if st["break_shot"] else 0.0
    # The viewer's own targets (8-ball: its group) also when it is not its turn (the two-player env).
    targets = 0 if over else legal_mask_for(st, me)
    low = -1
    for j in range(64):
        if (targets >> j) & 1:
            low = j
            break
    out[3] = low / 15.0 if low >= 0 else 0.0
    out[4] = 0.0
    out[5] = 0.0
    if st["groups"] != GROUPS_OPEN:
        solids = (st["groups"] == GROUPS_SOLIDS) == (me == 0)
        out[4] = 1.0 if solids else 0.0
        out[5] = 0.0 if solids else 1.0
    out[6] = 1.0 if (st["game"] == GAME_EIGHT and targets == 1 << 8) else 0.0
    mine_f = st["fouls0"] if me == 0 else st["fouls1"]
    theirs_f = st["fouls1"] if me == 0 else st["fouls0"]
    out[7] = min(mine_f / 2.0, 1.0)
    out[8] = min(theirs_f / 2.0, 1.0)
    out[9] = 1.0 if st["push_available"] else 0.0
    out[10] = 1.0 if mine else 0.0


@njit(cache=True)
def pool_targets_row(st: np.void, on: np.ndarray) -> np.ndarray:
    """Compiled twin of :meth:`PoolSession.view`'s ``targets`` on the game state record ``st``
    (:mod:`billiards_env.rules.pool_judge`): the legal balls on the table (rows; a pool ball's row is its number),
    ascending. The native vector env's kernels use it (``tests/envs/test_vector_env.py`` holds them equal)."""
    legal = legal_mask(st)
    n = 0
    out = np.empty(on.shape[0], np.int64)
    for j in range(1, on.shape[0]):
        if (legal >> j) & 1 and on[j]:
            out[n] = j
            n += 1
    return out[:n]


@njit(cache=True)
def pool_target_row(st: np.void) -> int:
    """Compiled twin of :meth:`PoolSession.view`'s ``target`` on the game state record ``st``: the lowest legal ball
    (-1: none)."""
    legal = legal_mask(st)
    for j in range(64):
        if (legal >> j) & 1:
            return j
    return -1


@njit(cache=True)
def pool_place_area_row(st: np.void, radius: float, kitchen_x: float, length: float, width: float,
                        area: np.ndarray) -> bool:
    """Compiled twin of :func:`pool_place_area` on the game state record ``st`` (``kitchen_x``: the head string's x),
    into ``area`` ``(x0, x1, y0, y1)``; False: no ball in hand."""
    if st["bih"] == BIH_NO or st["over"]:
        return False
    area[0] = radius
    area[1] = kitchen_x if st["bih"] == BIH_KITCHEN else length - radius
    area[2] = radius
    area[3] = width - radius
    return True


#: :func:`rack_rows`' codes: 9-ball's diamond, 8-ball's triangle (0: no ordering, the vector env's ``RACK_NONE``).
RACK_NINE, RACK_EIGHT = 1, 2


@njit(cache=True)
def permutation_of(g: np.random.Generator, n: int) -> np.ndarray:
    """``g.permutation(n)`` with numpy's draws: Fisher-Yates from the last slot down, each swap partner drawn by
    the bounded masked draw numpy's ``shuffle`` uses (``random_interval``). Written out rather than numba's
    ``Generator.permutation``, whose generic n-dimensional shuffle costs seconds of compile for the same values."""
    perm = np.arange(n)
    for i in range(n - 1, 0, -1):
        j = np.int64(random_interval(g.bit_generator, i))
        if j != i:
            t = perm[i]
            perm[i] = perm[j]
            perm[j] = t
    return perm


@njit(cache=True)
def rack_rows(k: int, g: np.random.Generator, pos: np.ndarray, rack_slots: np.ndarray, mode: int) -> None:
    """Compiled twin of :meth:`PoolSession.order_rack` (with :meth:`NineBallSession.rack_order` for
    :data:`RACK_NINE`, :meth:`EightBallSession.rack_order` for :data:`RACK_EIGHT`) on table ``k`` of ``pos``: the
    rack's numbers slot by slot, drawn from ``g`` as the rules say (9-ball: the 1 at the apex, the 9 in the middle;
    8-ball: the 8 in the middle, a solid and a stripe in the back corners), the same draws in the same order."""
    n_slots = rack_slots.shape[0]
    number = np.zeros(n_slots, np.int64)
    if mode == RACK_NINE:
        free = np.arange(2, 9)
        number[0] = 1
        number[4] = 9
    else:
        corner_solid = g.integers(0, 2)
        solid = 1 + g.integers(0, 7)
        stripe = 9 + g.integers(0, 7)
        number[4] = 8
        number[10] = solid if corner_solid else stripe
        number[14] = stripe if corner_solid else solid
        free = np.empty(12, np.int64)
        m = 0
        for n in range(1, 16):
            if n != 8 and n != solid and n != stripe:
                free[m] = n
                m += 1
    perm = permutation_of(g, free.shape[0])
    m = 0
    for slot in range(n_slots):
        if number[slot] == 0:
            number[slot] = free[perm[m]]
            m += 1
        pos[k, number[slot], 0] = rack_slots[slot, 0]
        pos[k, number[slot], 1] = rack_slots[slot, 1]


def _order(fixed: dict[int, int], free: list[int], n_slots: int, rng: np.random.Generator) -> tuple[int, ...]:
    free = [free[k] for k in rng.permutation(len(free))]
    it = iter(free)
    return tuple(fixed[slot] if slot in fixed else next(it) for slot in range(n_slots))


class PoolSession(GameSession):
    """A pool game (9-ball, 8-ball; see the module docstring). Balls are numbered as their ids (``"cue"`` 0)."""

    n_features = N_POOL_FEATURES
    option_keys = ("ball_in_hand", "groups", "break_shot")
    openings = ("break", "ball_in_hand", "either")
    players = {"random": "billiards_env.players.random:RandomPlayer",
               "geometric": "billiards_env.players.geometric:GeometricPlayer",
               "search": "billiards_env.players.search:SearchPlayer"}
    reasons = REASONS
    #: The ball the ``ball_in_hand`` opening respots if the break dropped it (the game's last ball).
    opening_respot: ClassVar[int]

    def __init__(self, spec: Any, rules: Any, table: TableState) -> None:
        self.numbers = np.asarray(table.numbers, dtype=np.int64)
        self.row_of = {int(n): i for i, n in enumerate(self.numbers.tolist())}
        self._rack_slots: np.ndarray | None = None
        self._row_state: GameState | None = None  # the state whose record (pool_judge's) _row holds
        self._row: np.void | None = None
        super().__init__(spec, rules, table)

    # --- the state ---------------------------------------------------------------------------------------------------
    def numbers_on(self) -> tuple[int, ...]:
        """Numbers of the object balls on the table (ascending rows)."""
        on = self.table.balls.on_table
        return tuple(int(n) for i, n in enumerate(self.numbers.tolist()) if on[i] and n)

    def legal_rows(self) -> list[int]:
        """Rows of the balls the shooter may hit first (the rules' legal targets)."""
        return [self.row_of[n] for n in self.rules.legal_targets(self.game_state)]

    def needs_called_pocket(self) -> bool:
        """The shooter must call a pocket for the next shot (8-ball, on the 8)."""
        return bool(self.rules.needs_called_pocket(self.game_state))

    def needs_calls(self) -> bool:
        return self.needs_called_pocket()

    def calls_for(self, pocket: np.ndarray) -> dict[str, Any]:
        """On the 8 with calls on: the pocket the shot sends the 8 into (none if it stays up)."""
        if not self.needs_called_pocket():
            return {}
        k = int(pocket[self.row_of[8]])
        return {"pocket": k if k >= 0 else None}

    def declared_for(self, summary: ShotSummary) -> ShotInfo:
        """The declarations a shooter would have made for the outcome ``summary`` (the search player judges
        outcomes so): on the 8 with calls on, the pocket the 8 dropped into."""
        if self.needs_called_pocket() and 8 in summary.pocketed:
            return ShotInfo(called_pocket=summary.pockets[summary.pocketed.index(8)])
        return _NO_DECLARATION

    def new_game(self, rng: np.random.Generator, placement: str) -> None:
        self.order_rack(rng, placement)

    def start(self, first: int) -> None:
        self.set_state(self.rules.initial_state(first_shooter=first))

    def setup(self, options: dict[str, Any], shooter: int) -> None:
        try:
            state = GameState(self.spec.name, self.numbers_on(), shooter=shooter,
                              ball_in_hand=options.get("ball_in_hand", False), groups=options.get("groups"),
                              break_shot=flag_option(options, "break_shot"))
        except RulesError as exc:
            raise ValueError(f"reset options: {exc}") from None
        self.set_state(state)

    def open_with_ball_in_hand(self, first: int) -> None:
        """After the ``ball_in_hand`` opening's break (played by the env): the game's last ball back on its spot if
        it dropped, the others left down, the cue ball on the table, and ``first`` to shoot with the cue ball in
        hand anywhere on an open table."""
        t = self.table
        b = t.balls
        r = float(b.radius[0])
        last = self.row_of[self.opening_respot]
        if not b.on_table[last]:
            spot_object_ball(b.pos, b.on_table, r, t.table, last)
        if not b.on_table[0]:
            spot_cue_ball(b.pos, b.on_table, r, t.table)
        self.set_state(GameState(self.spec.name, self.numbers_on(), shooter=first, ball_in_hand=ANYWHERE, groups=None,
                                 break_shot=False))

    def order_rack(self, rng: np.random.Generator, placement: str) -> None:
        """Order a racked layout (``placement`` ``"rack"`` or ``"diamond"``) as the rules say, drawing from ``rng``
        (compiled twin: :func:`rack_rows`)."""
        if placement not in ("rack", "diamond"):
            return
        pos = self.table.balls.pos
        if self._rack_slots is None:
            order = DIAMOND_ORDER if placement == "diamond" else RACK_ORDER
            self._rack_slots = np.array([pos[self.row_of[n]] for n in order])
        slots = self._rack_slots
        for slot, number in enumerate(self.rack_order(len(slots), rng)):
            pos[self.row_of[number]] = slots[slot]
        self.table.changed()

    def rack_order(self, n_slots: int, rng: np.random.Generator) -> tuple[int, ...]:
        """The ball number of each rack slot, drawn as the rules say."""
        raise NotImplementedError

    # --- the view ----------------------------------------------------------------------------------------------------
    def view(self, table: TableState) -> ShotView:
        """Who shoots and what they may do (the rules' targets on the table, ball in hand, the break, the call).
        Compiled twins on a game state record: :func:`pool_targets_row`, :func:`pool_target_row`,
        :func:`pool_place_area_row`."""
        s = self.game_state
        rows = self.legal_rows()
        on = table.balls.on_table
        area = pool_place_area(s, table.table, float(table.balls.radius[0]))
        return ShotView(tuple(int(i) for i in rows if on[i] and i != 0), min(rows) if rows else None, area,
                        bool(s.break_shot and not s.game_over), self.needs_called_pocket(), bool(s.push_out_available),
                        s.shooter)

    def features(self, player: int | None = None) -> np.ndarray:
        """The game seen by the player: ball in hand (anywhere / kitchen), break shot, its lowest legal target / 15,
        its group (solids, stripes), on the 8, its own and its opponent's fouls in a row / 2, push-out available,
        and whether it is its turn (eleven values in [0, 1]): :func:`pool_features` of the state's record."""
        s = self.game_state
        if self._row_state is not s:  # the state's record, made once per state
            self._row = state_row(s)
            self._row_state = s
        out = np.zeros(N_POOL_FEATURES, np.float32)
        pool_features(self._row, self.viewer(player), out)
        return out

    # --- shots -------------------------------------------------------------------------------------------------------
    def _call(self, outcome: ShotOutcome, shot: Any) -> tuple[Call, GameState]:
        """The rules' call on the shot (compiled twin, with :meth:`_apply`: ``billiards_env.envs._game_kernels._judge``
        on :func:`~billiards_env.rules.pool_judge.play`)."""
        s = self.game_state
        summary = summarize_outcome(outcome, self.numbers)
        push = bool(shot is not None and shot.call("push", False) and s.push_out_available)
        pocket = shot.call("pocket") if (shot is not None and self.needs_called_pocket()) else None
        return self.rules.play(s, summary, ShotInfo(push_out=push, called_pocket=pocket))

    def _apply(self, call: Call, outcome: ShotOutcome) -> None:
        """The respots and the cue ball in hand (compiled twin, with :meth:`_call`:
        ``billiards_env.envs._game_kernels._judge``)."""
        t = self.table
        b = t.balls
        r = float(b.radius[0])
        for n in call.respot:
            spot_object_ball(b.pos, b.on_table, r, t.table, self.row_of[n])
        if not b.on_table[0]:
            spot_cue_ball(b.pos, b.on_table, r, t.table)  # in hand for the next shooter

    def _kept(self, call: Call) -> tuple[int, ...]:
        return tuple(n for n in call.pocketed if n not in call.respot)

    def _verdict(self, call: Call) -> Verdict:
        return Verdict(call.shooter, bool(call.foul), call.reason, bool(call.turn_over), bool(call.game_over),
                       call.winner, float(len(self._kept(call))), call)

    @classmethod
    def info_keys(cls, n_balls: int) -> dict[str, InfoSpec]:
        return {"ball_in_hand": code("the cue ball in hand for the next shot: 0 no, 1 anywhere, 2 in the kitchen "
                                     "(behind the head string)", BALL_IN_HAND_NAMES, 0),
                "groups": code("the groups (8-ball): 0 open table, 1 player 0 (the agent) has the solids, 2 the "
                               "stripes", GROUPS_NAMES, 0)}

    def call_info(self, verdict: Verdict | None) -> dict[str, Any]:
        s = self.game_state
        return {"ball_in_hand": _BIH_CODE[s.ball_in_hand] if not s.game_over else 0,
                "groups": _GROUPS_CODE[None if s.groups is None else tuple(s.groups)]}

    def _what(self) -> str | None:
        call = self.last_call
        if call is None:
            return None
        if call.push_out:
            return "push-out"
        kept = self._kept(call)
        return f"pocketed {', '.join(map(str, kept))}" if kept else "no ball pocketed"

    def hud(self, names: tuple[str, str]) -> dict[str, Any]:
        """The HUD: the common keys, the groups, ball in hand (the kitchen's line), the ringed targets (9-ball the
        lowest ball, 8-ball the 8 once it is the target), and the called pocket. While a shot is under way (the
        frames of its animation) the cue ball is no longer in hand and the called pocket is ringed."""
        s = self.game_state
        over = s.game_over
        targets = () if over else tuple(self.rules.legal_targets(s))
        shot = self.shot_under_way
        in_hand = False if (over or shot is not None) else s.ball_in_hand
        calling = bool(not over and self.needs_called_pocket())
        return {
            **base_hud(self, names, self._what()),
            "groups": s.groups,
            "ball_in_hand": in_hand,
            "kitchen_x": head_string_x(self.table.table) if in_hand == KITCHEN else None,
            "targets": self.hud_targets(targets),
            "call_pocket": calling and shot is None,
            "called_pocket": shot.call("pocket") if (calling and shot is not None) else None,
        }

    def hud_targets(self, targets: tuple[int, ...]) -> tuple[int, ...]:
        """The balls the HUD rings."""
        return ()


class NineBallSession(PoolSession):
    """9-ball: the lowest ball first, the 9 on a legal shot wins (push-outs off by default in the envs)."""

    ruleset = NineBall
    options_type = NineBallOptions
    env_option_defaults = {"push_out": False}
    opening_respot = 9

    @classmethod
    def declared(cls, rules: Any) -> tuple[Declaration, ...]:
        return (PUSH_OUT,) if rules.options.push_out else ()

    def rack_order(self, n_slots: int, rng: np.random.Generator) -> tuple[int, ...]:
        """The diamond's numbers slot by slot: the 1 at the apex, the 9 in the middle, the others drawn."""
        return _order({0: 1, 4: 9}, list(range(2, 9)), n_slots, rng)

    def hud_targets(self, targets: tuple[int, ...]) -> tuple[int, ...]:
        return targets[:1]


class EightBallSession(PoolSession):
    """8-ball: groups, the 8 last and in the called pocket."""

    ruleset = EightBall
    options_type = EightBallOptions
    opening_respot = 8

    @classmethod
    def declared(cls, rules: Any) -> tuple[Declaration, ...]:
        return (CALLED_POCKET,) if rules.options.call_eight else ()

    def rack_order(self, n_slots: int, rng: np.random.Generator) -> tuple[int, ...]:
        """The triangle's numbers slot by slot: the 8 in the middle of the third row, a solid and a stripe in the
        back corners (which corner drawn), the others drawn."""
        corner_solid = int(rng.integers(2))
        solid = int(rng.choice(np.arange(1, 8)))
        stripe = int(rng.choice(np.arange(9, 16)))
        fixed = {4: 8, 10: solid if corner_solid else stripe, 14: stripe if corner_solid else solid}
        return _order(fixed, [n for n in range(1, 16) if n not in fixed.values()], n_slots, rng)

    def hud_targets(self, targets: tuple[int, ...]) -> tuple[int, ...]:
        return targets if targets == (8,) else ()


__all__ = ["PoolSession", "NineBallSession", "EightBallSession", "N_POOL_FEATURES", "pool_place_area", "pool_features",
           "pool_targets_row", "pool_target_row", "pool_place_area_row", "rack_rows", "RACK_NINE", "RACK_EIGHT",
           "BALL_IN_HAND_NAMES", "GROUPS_NAMES"]
