"""Snooker as a session (the rules themselves are :mod:`billiards_env.rules.snooker`; docs/rules.md).

The table is the 12 ft snooker table (scene ``table: {preset: snooker}``), the balls the cue ball, 15 reds and the
six colours (ids :data:`~billiards_env.rules.snooker.SNOOKER_IDS`). The cue ball in hand goes in the D (the action's
placement dims map the square onto the half-disc: :class:`~billiards_env.table_state.HalfDiscArea`). After each call
the session re-spots the colours the rules name, puts every ball back after a miss (option ``miss_rule``), and
after an in-off puts the cue ball in the D (where the next striker's placement moves it). The colour nominated
after a red is the first colour hit (the rules' default), a free ball is taken as the rules' ``auto_free_ball``
option says: an action needs no nomination.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from billiards_env.physics.outcome import ShotOutcome
from billiards_env.rules.errors import RulesError
from billiards_env.rules.snooker import (COLOUR_VALUES, IN_D, ON_COLOUR, ON_NAMES, ON_RED, REASONS, RED_VALUE,
                                         VALUE_NAMES, Snooker,
                                         SnookerCall, SnookerOptions, SnookerShotInfo, SnookerState, SnookerSummary,
                                         ball_on_mask, snooker_values, snookered)
from billiards_env.table_state import ShotView, TableState

from .hud import base_hud
from .infos import InfoSpec, code, code_of, integer
from .session import GameSession, Verdict, pair_option
from .snooker_layout import (SNOOKER_COLOURS, SNOOKER_IDS, DArea, d_geometry, nearest_point_in_d, snooker_balls,
                             spot_snooker_colours)

#: The most points of a frame without fouls (15 reds with blacks, then the colours): the features' scale.
MAX_BREAK = 147.0
#: Drawing numbers of the balls (the renderer's plain balls): the cue ball 0, the reds, then the colours in order.
RED_NUMBER = 16
COLOUR_NUMBERS = {c: 17 + k for k, c in enumerate(SNOOKER_COLOURS)}
N_SNOOKER_FEATURES = 10


class SnookerSession(GameSession):
    """A frame of snooker (see the module docstring)."""

    ruleset = Snooker
    options_type = SnookerOptions
    n_features = N_SNOOKER_FEATURES
    option_keys = ("ball_in_hand", "on", "score")  # the reds: those on the table (positions, pocketed)
    reasons = REASONS
    scored_unit = "points"
    players = {"random": "billiards_env.players.random:RandomPlayer",
               "geometric": "billiards_env.players.snooker:SnookerGeometricPlayer",
               "search": "billiards_env.players.snooker:SnookerSearchPlayer"}

    placements = ("snooker",)
    palette = {RED_NUMBER: (196, 22, 28), COLOUR_NUMBERS["yellow"]: (250, 204, 20),
               COLOUR_NUMBERS["green"]: (0, 120, 64), COLOUR_NUMBERS["brown"]: (120, 70, 30),
               COLOUR_NUMBERS["blue"]: (22, 70, 180), COLOUR_NUMBERS["pink"]: (244, 140, 170),
               COLOUR_NUMBERS["black"]: (18, 18, 20)}

    def __init__(self, spec: Any, rules: Any, table: TableState) -> None:
        self.values = np.asarray(snooker_values(table.ids), dtype=np.int64)
        self.row_of = {bid: i for i, bid in enumerate(table.ids)}
        self._before: Any = None  # the balls before the shot under way (a miss puts them back)
        self._snookered = False
        super().__init__(spec, rules, table)

    @classmethod
    def start_layout(cls, placement: str, table: Any, radius: float) -> np.ndarray:
        """``"snooker"``: the reds' triangle, the colours on their spots, the cue ball in the D."""
        if placement != "snooker":
            return super().start_layout(placement, table, radius)
        return snooker_balls(table, radius=radius).pos

    @classmethod
    def ball_set(cls, n_object_balls: int) -> tuple[tuple[str, ...], tuple[int, ...]]:
        """The cue ball, 15 reds and the six colours (:data:`SNOOKER_IDS`), drawn as plain balls."""
        numbers = (0,) + (RED_NUMBER,) * 15 + tuple(COLOUR_NUMBERS[c] for c in SNOOKER_COLOURS)
        return SNOOKER_IDS, numbers

    # --- the state ---------------------------------------------------------------------------------------------------
    @property
    def game_over(self) -> bool:
        return bool(self.game_state.frame_over)

    def new_game(self, rng: np.random.Generator, placement: str) -> None:
        """The frame's opening layout is the env's (``placement: snooker``): nothing is drawn."""

    def start(self, first: int) -> None:
        self.set_state(self.rules.initial_state(first_shooter=first))

    def setup(self, options: dict[str, Any], shooter: int) -> None:
        """A table set up by hand: the reds and colours on it; ``on`` (default: red while reds remain, else the
        lowest colour), ``score`` (default 0-0), ``ball_in_hand`` (False or ``"d"``)."""
        on_table = self.table.balls.on_table
        reds = int(sum(on_table[i] for i in range(len(self.values)) if self.values[i] == RED_VALUE))
        colours = tuple(c for c in SNOOKER_COLOURS if on_table[self.row_of[c]])
        on = options.get("on", ON_RED if reds else (colours[0] if colours else ON_RED))
        try:
            state = SnookerState(shooter=shooter, score=pair_option(options, "score"), on=on, reds=reds,
                                 colours=colours, ball_in_hand=options.get("ball_in_hand", False))
        except RulesError as exc:
            raise ValueError(f"reset options: {exc}") from None
        self.set_state(state)

    def legal_rows(self) -> list[int]:
        """Rows of the balls on (the balls the striker may hit first, without a free ball)."""
        mask = ball_on_mask(self.values, self.game_state.on) & self.table.balls.on_table
        return [int(i) for i in np.flatnonzero(mask)]

    def legal_names(self) -> tuple[Any, ...]:
        return () if self.game_over else tuple(self.rules.legal_targets(self.game_state))

    # --- what the shooter sees ---------------------------------------------------------------------------------------
    def place_area(self) -> DArea:
        """The D."""
        return DArea.of(self.table.table)

    def view(self, table: TableState) -> ShotView:
        s = self.game_state
        rows = tuple(self.legal_rows()) if not s.frame_over else ()
        area = self.place_area() if (s.ball_in_hand and not s.frame_over) else None
        return ShotView(rows, rows[0] if rows else None, area, False, False, False, s.shooter)

    def features(self, player: int | None = None) -> np.ndarray:
        """The frame seen by the player: its ball in hand, on a red, on any colour, the named colour's value / 7,
        its score and its opponent's / 147, the points left / 147, its break / 147, a free ball possible (the
        opponent fouled), its turn (values in [0, 1])."""
        s = self.game_state
        me = self.viewer(player)
        mine = s.shooter == me and not s.frame_over
        out = np.zeros(N_SNOOKER_FEATURES, np.float32)
        out[0] = 1.0 if (mine and s.ball_in_hand) else 0.0
        out[1] = 1.0 if s.on == ON_RED else 0.0
        out[2] = 1.0 if s.on == ON_COLOUR else 0.0
        out[3] = COLOUR_VALUES[s.on] / 7.0 if s.on in COLOUR_VALUES else 0.0
        out[4] = min(s.score[me] / MAX_BREAK, 1.0)
        out[5] = min(s.score[1 - me] / MAX_BREAK, 1.0)
        out[6] = min(s.points_left / MAX_BREAK, 1.0)
        out[7] = min(s.break_points / MAX_BREAK, 1.0) if mine else 0.0
        out[8] = 1.0 if (mine and s.after_foul) else 0.0
        out[9] = 1.0 if mine else 0.0
        return out

    # --- shots -------------------------------------------------------------------------------------------------------
    def begin_shot(self, shot: Any) -> None:
        """Note the table before the shot (a miss puts it back) and whether the striker is snookered (the free ball
        and the miss rule)."""
        super().begin_shot(shot)
        b = self.table.balls
        self._before = (b.pos.copy(), b.on_table.copy())
        s = self.game_state
        self._snookered = bool(not s.frame_over and not s.ball_in_hand and b.on_table[0]
                               and snookered(b.pos, b.on_table, b.radius, self.values, s.on, 0))

    def _summary(self, outcome: ShotOutcome) -> SnookerSummary:
        """The rules' summary from the shot's outcome (read once: first contact, the balls that dropped in order)."""
        v = self.values
        first = outcome.first_contact
        down = outcome.drop_order
        return SnookerSummary(None if first < 0 else VALUE_NAMES[int(v[first])],
                              sum(1 for r in down if v[r] == RED_VALUE),
                              tuple(VALUE_NAMES[int(v[r])] for r in down if v[r] >= 2), bool(outcome.scratch))

    def _call(self, outcome: ShotOutcome, shot: Any) -> tuple[SnookerCall, SnookerState]:
        s = self.game_state
        info = SnookerShotInfo(snookered=self._snookered)
        return self.rules.play(s, self._summary(outcome), info)

    def _apply(self, call: SnookerCall, outcome: ShotOutcome) -> None:
        t = self.table
        b = t.balls
        if call.replace and self._before is not None:  # a miss: every ball back where it was
            b.pos[...] = self._before[0]
            b.on_table[...] = self._before[1]
        elif call.respot:
            spot_snooker_colours(b.pos, b.on_table, b.radius, t.table, {c: self.row_of[c] for c in call.respot})
        if not b.on_table[0]:  # in hand in the D for the next striker (who places it)
            cx, cy, r = d_geometry(t.table)
            b.on_table[0] = False
            b.pos[0] = nearest_point_in_d(cx - 0.5 * r, cy, b.pos, b.on_table, b.radius, 0, t.table)
            b.on_table[0] = True
        self._before = None

    def _kept(self, call: SnookerCall) -> tuple[int, ...]:
        """The balls the striker potted that stay down (drawing numbers), for the HUD."""
        if call.foul:
            return ()
        out = [RED_NUMBER] * call.reds_potted
        out += [COLOUR_NUMBERS[c] for c in call.colours_potted if c not in call.respot]
        return tuple(out)

    def _verdict(self, call: SnookerCall) -> Verdict:
        return Verdict(call.shooter, bool(call.foul), call.reason, bool(call.turn_over), bool(call.frame_over),
                       call.winner, float(call.points), call)

    def call_info(self, verdict: Verdict | None) -> dict[str, Any]:
        """``points`` (scored by the shot), ``foul_points`` (the penalty it gave away), ``score`` (both players),
        ``on`` (the ball on now, a code), ``break`` (the striker's break), ``ball_in_hand`` (1: in the D)."""
        s = self.game_state
        call = verdict.call if verdict is not None else None
        return {"points": int(call.points) if call is not None else 0,
                "foul_points": int(call.foul_points) if call is not None else 0,
                "score": np.array(s.score, np.int64), "on": code_of(ON_NAMES, s.on), "break": int(s.break_points),
                "ball_in_hand": int(bool(s.ball_in_hand) and not s.frame_over)}

    @classmethod
    def info_keys(cls, n_balls: int) -> dict[str, InfoSpec]:
        return {"points": integer("points the shot scored for its striker"),
                "foul_points": integer("the penalty the shot gave away (0 without a foul)"),
                "score": InfoSpec(np.int64, (2,), "both players' points (player 0 is the agent)", 0),
                "on": code("the ball on now: 0 any colour, 1 a red, 2-7 that colour (yellow, green, brown, blue, "
                           "pink, black)", ON_NAMES, 1),
                "break": integer("the striker's break so far"),
                "ball_in_hand": code("the cue ball in hand (in the D) for the next shot: 0 no, 1 yes",
                                     ("none", IN_D), 0)}

    def markings(self) -> dict[str, Any]:
        """The baulk line and the D."""
        cx, cy, r = d_geometry(self.table.table)
        return {"lines": [((cx, 0.0), (cx, self.table.table.width))],
                "arcs": [(cx, cy, r, 0.5 * np.pi, 1.5 * np.pi)]}

    def hud(self, names: tuple[str, str]) -> dict[str, Any]:
        """The HUD: the common keys, each player's points, the ball on and the break, the D when in hand, the colour
        on ringed."""
        s = self.game_state
        call = self.last_call
        what = None
        if call is not None:
            what = f"{call.points} point{'s' if call.points != 1 else ''}" if call.points else "no score"
        ring = (COLOUR_NUMBERS[s.on],) if (s.on in COLOUR_NUMBERS and not s.frame_over) else ()
        return {
            **base_hud(self, names, what),
            "scores": (f"{s.score[0]} pts", f"{s.score[1]} pts"),
            "note": None if s.frame_over else f"on {s.on}, break {s.break_points}",
            "ball_in_hand": IN_D if (s.ball_in_hand and not s.frame_over and self.shot_under_way is None) else False,
            "targets": ring,
        }


__all__ = ["SnookerSession", "RED_NUMBER", "COLOUR_NUMBERS", "N_SNOOKER_FEATURES"]
