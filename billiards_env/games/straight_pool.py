"""Straight pool (14.1 continuous) as a session (the rules themselves: :mod:`billiards_env.rules.straight_pool`).

The 15 balls racked on the foot spot (the 1 and the 5 in the back corners, the others drawn), the cue ball in hand
behind the head string for the opening break. Every shot calls a ball and a pocket (the action's ``ball`` and
``pocket`` dims: :data:`~.declarations.CALLED_BALL`, :data:`~.declarations.CALLED_POCKET`). After each call the
session spots the balls pocketed illegally on the foot spot (behind it when taken), re-racks the 14 (or 15) balls
with the 15th ball and the cue ball placed as the rules' table says
(:func:`~billiards_env.rules.straight_pool.rerack_placement`), and racks all 15 for the re-break after a third foul.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from billiards_env.physics.layout import (RACK_ORDER, foot_spot, head_spot, head_string_x, nearest_free_point,
                                          spot_cue_ball, spot_object_ball, triangle_positions)
from billiards_env.physics.outcome import ShotOutcome
from billiards_env.rules.errors import RulesError
from billiards_env.rules.state import ANYWHERE, KITCHEN
from billiards_env.rules.straight_pool import (CENTER_SPOT, HEAD_SPOT, RACKED, REASONS, CalledShot, StraightPool,
                                               StraightPoolCall, StraightPoolOptions, StraightPoolState,
                                               rerack_placement)
from billiards_env.rules.summary import ShotSummary, summarize_outcome
from billiards_env.table_state import ShotView, TableState

from .declarations import CALLED_BALL, CALLED_POCKET, Declaration
from .hud import base_hud
from .infos import InfoSpec, code, integer
from .pool import BALL_IN_HAND_NAMES, pool_place_area
from .session import GameSession, Verdict, flag_option

#: Game features of the observation (see :meth:`StraightPoolSession.features`).
N_STRAIGHT_FEATURES = 8
_BIH_CODE = {False: 0, ANYWHERE: 1, KITCHEN: 2}
#: The rack's slots (:data:`~billiards_env.physics.layout.RACK_ORDER`'s triangle) of the two back corners.
BACK_CORNERS = (10, 14)


def _score_option(options: dict[str, Any]) -> tuple[int, int]:
    """Reset option ``score``: two whole numbers (a straight pool score may be below zero), default 0-0."""
    value = options.get("score", (0, 0))
    pair = tuple(value) if isinstance(value, (tuple, list, np.ndarray)) else ()
    if len(pair) != 2 or not all(isinstance(x, (int, np.integer)) and not isinstance(x, (bool, np.bool_))
                                 for x in pair):
        raise ValueError(f"reset options['score']: expected two whole numbers (player 0's, player 1's; below zero "
                         f"allowed), got {value!r}")
    return int(pair[0]), int(pair[1])


class StraightPoolSession(GameSession):
    """A game of straight pool (see the module docstring). Balls are numbered as their ids (``"cue"`` 0)."""

    ruleset = StraightPool
    options_type = StraightPoolOptions
    n_features = N_STRAIGHT_FEATURES
    option_keys = ("ball_in_hand", "score", "break_shot")
    openings = ("break",)
    reasons = REASONS
    scored_unit = "points"
    players = {"random": "billiards_env.players.random:RandomPlayer",
               "geometric": "billiards_env.players.geometric:GeometricPlayer",
               "search": "billiards_env.players.search:SearchPlayer"}

    def __init__(self, spec: Any, rules: Any, table: TableState) -> None:
        #: The ball number of each row (the players' and the search's judge read it) and the row of each number.
        self.numbers = np.asarray(table.numbers, dtype=np.int64)
        self.row_of = {int(n): i for i, n in enumerate(self.numbers.tolist())}
        self._rack_slots: np.ndarray | None = None
        super().__init__(spec, rules, table)

    @classmethod
    def declared(cls, rules: Any) -> tuple[Declaration, ...]:
        """Every shot calls a ball and a pocket."""
        return (CALLED_BALL, CALLED_POCKET)

    # --- the state ---------------------------------------------------------------------------------------------------
    def numbers_on(self) -> tuple[int, ...]:
        """Numbers of the object balls on the table (ascending rows)."""
        on = self.table.balls.on_table
        return tuple(int(n) for i, n in enumerate(self.numbers.tolist()) if on[i] and n)

    def legal_rows(self) -> list[int]:
        """Rows of the balls the shooter may hit first (any ball on the table)."""
        return [self.row_of[n] for n in self.rules.legal_targets(self.game_state)]

    def needs_called_pocket(self) -> bool:
        """Every shot calls a pocket (and a ball)."""
        return bool(self.rules.needs_called_pocket(self.game_state))

    def new_game(self, rng: np.random.Generator, placement: str) -> None:
        """The env's triangle (``placement`` ``"rack"``) ordered as :meth:`rack_order` says; other placements as
        placed."""
        if placement != "rack":
            return
        pos = self.table.balls.pos
        if self._rack_slots is None:  # the env's triangle, slot by slot, read once
            self._rack_slots = np.array([pos[self.row_of[n]] for n in RACK_ORDER])
        for slot, number in enumerate(self.rack_order(len(self._rack_slots), rng)):
            pos[self.row_of[number]] = self._rack_slots[slot]
        self.table.changed()

    def start(self, first: int) -> None:
        self.set_state(self.rules.initial_state(first_shooter=first))

    def setup(self, options: dict[str, Any], shooter: int) -> None:
        """A table set up by hand: the balls on it, ``score`` (default 0-0), ``ball_in_hand`` (False, ``"kitchen"``
        or ``"anywhere"``), ``break_shot`` (default False)."""
        try:
            state = StraightPoolState(self.numbers_on(), shooter=shooter,
                                      ball_in_hand=options.get("ball_in_hand", False),
                                      score=_score_option(options),
                                      break_shot=flag_option(options, "break_shot"), target=self.rules.options.target)
        except RulesError as exc:
            raise ValueError(f"reset options: {exc}") from None
        self.set_state(state)

    def rack_order(self, n_slots: int, rng: np.random.Generator) -> tuple[int, ...]:
        """The triangle's numbers slot by slot: the 1 and the 5 in the back corners, the others drawn."""
        fixed = {BACK_CORNERS[0]: 1, BACK_CORNERS[1]: 5}
        free = [n for n in range(1, 16) if n not in fixed.values()]
        free = [free[k] for k in rng.permutation(len(free))]
        it = iter(free)
        return tuple(fixed[slot] if slot in fixed else next(it) for slot in range(n_slots))

    # --- the view ----------------------------------------------------------------------------------------------------
    def view(self, table: TableState) -> ShotView:
        s = self.game_state
        on = table.balls.on_table
        rows = [r for r in self.legal_rows() if on[r] and r != 0] if not s.game_over else []
        area = pool_place_area(s, table.table, float(table.balls.radius[0]))
        return ShotView(tuple(rows), min(rows) if rows else None, area, bool(s.break_shot and not s.game_over),
                        not s.game_over, False, s.shooter)

    def features(self, player: int | None = None) -> np.ndarray:
        """The game seen by the player: its ball in hand (kitchen), the break shot, its score and its opponent's /
        target (clipped to [0, 1]), its own and its opponent's fouls in a row / 2, the object balls on the table /
        15, and whether it is its turn (eight values in [0, 1])."""
        s = self.game_state
        me = self.viewer(player)
        mine = s.shooter == me and not s.game_over
        out = np.zeros(N_STRAIGHT_FEATURES, np.float32)
        out[0] = 1.0 if (mine and s.ball_in_hand) else 0.0
        out[1] = 1.0 if s.break_shot else 0.0
        out[2] = min(max(s.score[me] / s.target, 0.0), 1.0)
        out[3] = min(max(s.score[1 - me] / s.target, 0.0), 1.0)
        out[4] = min(s.fouls_in_a_row[me] / 2.0, 1.0)
        out[5] = min(s.fouls_in_a_row[1 - me] / 2.0, 1.0)
        out[6] = len(s.on_table) / 15.0
        out[7] = 1.0 if mine else 0.0
        return out

    # --- declarations ------------------------------------------------------------------------------------------------
    def needs_calls(self) -> bool:
        return not self.game_state.game_over

    def calls_for(self, pocket: np.ndarray) -> dict[str, Any]:
        """The ball a simulated shot pockets (the lowest row of those it pockets) and its pocket; none if it pockets
        none."""
        rows = [int(r) for r in np.flatnonzero(np.asarray(pocket)[1:] >= 0) + 1]
        if not rows:
            return {}
        return {"ball": rows[0], "pocket": int(pocket[rows[0]])}

    def declared_for(self, summary: ShotSummary) -> CalledShot:
        """The call a shooter would have made for the outcome ``summary``: its first ball pocketed and that pocket."""
        if not summary.pocketed:
            return CalledShot()
        return CalledShot(summary.pocketed[0], summary.pockets[0])

    def called(self, shot: Any) -> CalledShot:
        """The call a shot declares, as the rules read it: a called ball that is not on the table (an action may name
        any row) or no pocket is no call."""
        if shot is None:
            return CalledShot()
        row, pocket = shot.call("ball"), shot.call("pocket")
        if row is None or pocket is None or not 0 < int(row) < len(self.numbers):
            return CalledShot()
        number = int(self.numbers[int(row)])
        return CalledShot(number, int(pocket)) if number in self.game_state.on_table else CalledShot()

    # --- shots -------------------------------------------------------------------------------------------------------
    def _call(self, outcome: ShotOutcome, shot: Any) -> tuple[StraightPoolCall, StraightPoolState]:
        summary = summarize_outcome(outcome, self.numbers)
        return self.rules.play(self.game_state, summary, self.called(shot))

    def _apply(self, call: StraightPoolCall, outcome: ShotOutcome) -> None:
        """Spot the balls pocketed illegally; re-rack (the 14, the 15, or all 15 for a re-break), placing the 15th
        ball and the cue ball as the rules say; the cue ball back on the table after a scratch (in hand)."""
        t = self.table
        b = t.balls
        r = float(b.radius[0])
        for n in call.respot:
            spot_object_ball(b.pos, b.on_table, r, t.table, self.row_of[n])
        if call.rerack:
            in_hand = self._rerack(call)
            if in_hand and not self.game_state.game_over and self.game_state.ball_in_hand is False:
                self.game_state = replace(self.game_state, ball_in_hand=KITCHEN)
        if not b.on_table[0]:
            spot_cue_ball(b.pos, b.on_table, r, t.table)  # in hand for the next shooter

    def _slots(self) -> np.ndarray:
        """The rack's 15 slots (the env's racked layout, else a touching triangle on the foot spot)."""
        if self._rack_slots is not None:
            return self._rack_slots
        t = self.table
        return triangle_positions(foot_spot(t.table), float(t.balls.radius[1]), rows=5)

    def _rerack(self, call: StraightPoolCall) -> bool:
        """Rack the balls of ``call.rerack``; returns whether the cue ball goes in hand behind the head string."""
        t = self.table
        b = t.balls
        r = float(b.radius[0])
        slots = self._slots()
        near = 2.0 * r + 1e-9

        def in_rack(row: int) -> bool:
            return bool(b.on_table[row]) and bool(np.any(np.hypot(*(slots - b.pos[row]).T) < near))

        cue_in_rack = in_rack(0)
        cue_in_kitchen = bool(b.on_table[0]) and float(b.pos[0, 0]) <= head_string_x(t.table)
        left = [row for row in range(1, len(self.numbers)) if b.on_table[row]]
        fifteenth = None
        if call.rerack == 14 and len(left) == 1:
            row = left[0]
            hx, hy = head_spot(t.table)
            fifteenth = "rack" if in_rack(row) else \
                (HEAD_SPOT if np.hypot(b.pos[row, 0] - hx, b.pos[row, 1] - hy) < near else "elsewhere")
        if call.break_next:  # all 15 for the re-break, the cue ball in hand behind the head string
            where, in_hand = RACKED, True
        else:
            where, in_hand = rerack_placement(fifteenth, cue_in_rack, cue_in_kitchen)
        rackable = [row for row in range(1, len(self.numbers)) if not b.on_table[row] or where == RACKED]
        if in_hand or not b.on_table[0]:
            b.on_table[0] = False
        for row in rackable:
            b.on_table[row] = False
        if where in (HEAD_SPOT, CENTER_SPOT) and fifteenth is not None:
            row = left[0]
            x, y = head_spot(t.table) if where == HEAD_SPOT else (0.5 * t.table.length, 0.5 * t.table.width)
            area = (r, t.table.length - r, r, t.table.width - r)
            b.pos[row] = nearest_free_point(x, y, b.pos, b.on_table, b.radius, row, area)
        numbers = sorted(int(self.numbers[row]) for row in rackable)
        first = 0 if len(numbers) == 15 else 1  # 14: the apex spot stays empty
        order = self.rack_order(15, np.random.default_rng(self.game_state.racks)) if len(numbers) == 15 else numbers
        for slot, number in zip(range(first, first + len(order)), order, strict=True):
            row = self.row_of[number]
            b.pos[row] = slots[slot]
            b.on_table[row] = True
        if not b.on_table[0]:
            spot_cue_ball(b.pos, b.on_table, r, t.table)
        t.changed()
        return in_hand

    def _kept(self, call: StraightPoolCall) -> tuple[int, ...]:
        return ()

    def _verdict(self, call: StraightPoolCall) -> Verdict:
        return Verdict(call.shooter, bool(call.foul), call.reason, bool(call.turn_over), bool(call.game_over),
                       call.winner, float(max(call.points, 0)), call)

    @classmethod
    def info_keys(cls, n_balls: int) -> dict[str, InfoSpec]:
        return {"points": integer("the change of the shooter's score on the shot (points, or a penalty below 0)"),
                "score": InfoSpec(np.int64, (2,), "both players' points (player 0 is the agent)", 0),
                "ball_in_hand": code("the cue ball in hand for the next shot: 0 no, 1 anywhere, 2 in the kitchen "
                                     "(behind the head string)", BALL_IN_HAND_NAMES, 0),
                "rerack": integer("object balls racked after the shot (0, 14 or 15)")}

    def call_info(self, verdict: Verdict | None) -> dict[str, Any]:
        s = self.game_state
        call = verdict.call if verdict is not None else None
        return {"points": int(call.points) if call is not None else 0,
                "score": np.array(s.score, dtype=np.int64),
                "ball_in_hand": _BIH_CODE[s.ball_in_hand] if not s.game_over else 0,
                "rerack": int(call.rerack) if call is not None else 0}

    def _what(self) -> str | None:
        call = self.last_call
        if call is None:
            return None
        if call.points > 0:
            return f"+{call.points} ({call.reason})"
        return call.reason

    def hud(self, names: tuple[str, str]) -> dict[str, Any]:
        """The HUD: the common keys, each player's points out of the target, ball in hand (the kitchen's line), and
        while a shot is under way its called ball ringed and its called pocket."""
        s = self.game_state
        over = s.game_over
        shot = self.shot_under_way
        in_hand = False if (over or shot is not None) else s.ball_in_hand
        called = self.called(shot) if shot is not None else CalledShot()
        return {
            **base_hud(self, names, self._what()),
            "scores": tuple(f"{p} / {s.target}" for p in s.score),
            "ball_in_hand": in_hand,
            "kitchen_x": head_string_x(self.table.table) if in_hand == KITCHEN else None,
            "targets": (called.ball,) if called.ball is not None else (),
            "call_pocket": not over and shot is None,
            "called_pocket": called.pocket,
        }


__all__ = ["StraightPoolSession", "N_STRAIGHT_FEATURES"]
