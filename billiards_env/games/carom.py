"""Three-cushion (carom) as a session (the rules themselves are :mod:`billiards_env.rules.three_cushion`).

The table is the pocketless match table (scene ``table: {preset: carom}``), the balls the two cue balls and the red
(ids :data:`~billiards_env.rules.three_cushion.CAROM_IDS`: player 0 plays ``"white"``, player 1 ``"yellow"``). The
shooter's cue ball is always row 0 (the row every shot strikes and every observation lists first): when the turn
passes the session swaps the first two rows (positions, flags, ids and drawing numbers), so a policy always sees
its own ball first, then the opponent's, then the red. Nothing is re-spotted, there is no ball in hand. The opening
shot is played from the UMB start position of the player who breaks.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from billiards_env.physics.outcome import ShotOutcome
from billiards_env.rules.errors import RulesError
from billiards_env.rules.three_cushion import (REASONS, ThreeCushion, ThreeCushionCall, ThreeCushionOptions,
                                               ThreeCushionState, summarize_carom)
from billiards_env.table_state import ShotView, TableState

from .hud import base_hud
from .infos import InfoSpec, flag, integer
from .carom_layout import CAROM_IDS, carom_start_positions
from .session import GameSession, Verdict, flag_option, pair_option

#: Drawing numbers of the white, the yellow and the red (the renderer's plain carom balls).
CAROM_NUMBERS = {"white": 23, "yellow": 24, "red": 25}
N_CAROM_FEATURES = 6


class CaromSession(GameSession):
    """A game of three-cushion (see the module docstring)."""

    ruleset = ThreeCushion
    options_type = ThreeCushionOptions
    n_features = N_CAROM_FEATURES
    option_keys = ("score", "break_shot")
    reasons = REASONS
    scored_unit = "points"
    ball_in_hand = False
    players = {"random": "billiards_env.players.random:RandomPlayer",
               "geometric": "billiards_env.players.three_cushion:CaromGeometricPlayer",
               "search": "billiards_env.players.three_cushion:CaromSearchPlayer"}

    placements = ("carom",)
    palette = {CAROM_NUMBERS["white"]: (248, 246, 238), CAROM_NUMBERS["yellow"]: (250, 214, 40),
               CAROM_NUMBERS["red"]: (204, 26, 30)}

    @classmethod
    def start_layout(cls, placement: str, table: Any, radius: float) -> np.ndarray:
        """``"carom"``: the UMB start position (player 0 breaking), rows white, yellow, red."""
        if placement != "carom":
            return super().start_layout(placement, table, radius)
        return np.array([carom_start_positions(table)[i] for i in CAROM_IDS])

    @classmethod
    def ball_set(cls, n_object_balls: int) -> tuple[tuple[str, ...], tuple[int, ...]]:
        return CAROM_IDS, tuple(CAROM_NUMBERS[i] for i in CAROM_IDS)

    # --- rows: the shooter's ball first ------------------------------------------------------------------------------
    def arrange(self, shooter: int) -> None:
        """Order the rows ``(shooter's cue ball, opponent's cue ball, red)``, swapping the first two if needed."""
        t = self.table
        b = t.balls
        if b.ids[0] == CAROM_IDS[shooter]:
            return
        for arr in (b.pos, b.vel, b.ang, b.on_table, b.radius, b.mass):
            arr[[0, 1]] = arr[[1, 0]]
        b.ids = (b.ids[1], b.ids[0]) + tuple(b.ids[2:])
        t.numbers = (t.numbers[1], t.numbers[0]) + tuple(t.numbers[2:])
        t.changed()

    def restore_order(self) -> None:
        """The rows in the canonical order (white, yellow, red), as the env's layouts and reset options give them."""
        self.arrange(0)

    # --- the state ---------------------------------------------------------------------------------------------------
    def new_game(self, rng: np.random.Generator, placement: str) -> None:
        self.restore_order()

    def start(self, first: int) -> None:
        """The opening: the UMB start position of ``first``'s break, ``first``'s ball first."""
        self.restore_order()
        b = self.table.balls
        start = carom_start_positions(self.table.table, breaker=first, side=1)
        for row, bid in enumerate(b.ids):
            b.pos[row] = start[bid]
        self.set_state(self.rules.initial_state(first_shooter=first))
        self.arrange(first)

    def setup(self, options: dict[str, Any], shooter: int) -> None:
        """A table set up by hand (positions in the rows white, yellow, red): ``score`` (default 0-0) and
        ``break_shot`` (default False)."""
        score = pair_option(options, "score")
        goal = self.rules.options.target_points
        if max(score) >= goal:
            raise ValueError(f"reset options['score']: {score} reaches target_points={goal}, where the game is over; "
                             f"give scores below {goal}, or a higher target with rules={{'target_points': ...}}")
        try:
            state = ThreeCushionState(shooter=shooter, score=score, break_shot=flag_option(options, "break_shot"))
        except RulesError as exc:
            raise ValueError(f"reset options: {exc}") from None
        self.set_state(state)
        self.arrange(shooter)

    # --- what the shooter sees ---------------------------------------------------------------------------------------
    def view(self, table: TableState) -> ShotView:
        """Both object balls may be met first (the red first on the opening shot); the aim types' target is the
        red; no ball in hand."""
        s = self.game_state
        targets = () if s.game_over else ((2,) if s.break_shot and self.rules.options.break_red_first else (1, 2))
        return ShotView(targets, None if s.game_over else 2, None, False, False, False, s.shooter)

    def legal_names(self) -> tuple[Any, ...]:
        s = self.game_state
        if s.game_over:
            return ()
        return ("red",) if s.break_shot and self.rules.options.break_red_first else ("opponent", "red")

    def features(self, player: int | None = None) -> np.ndarray:
        """The game seen by the player: its points and its opponent's / the target, its run / the target, the
        opening shot, its turn, its innings / the innings limit (0 without one) (values in [0, 1])."""
        s = self.game_state
        me = self.viewer(player)
        opts = self.rules.options
        goal = float(opts.target_points)
        mine = s.shooter == me and not s.game_over
        out = np.zeros(N_CAROM_FEATURES, np.float32)
        out[0] = min(s.score[me] / goal, 1.0)
        out[1] = min(s.score[1 - me] / goal, 1.0)
        out[2] = min(s.run / goal, 1.0) if mine else 0.0
        out[3] = 1.0 if s.break_shot else 0.0
        out[4] = 1.0 if mine else 0.0
        out[5] = min(s.innings[me] / opts.max_innings, 1.0) if opts.max_innings else 0.0
        return out

    # --- shots -------------------------------------------------------------------------------------------------------
    def _call(self, outcome: ShotOutcome, shot: Any) -> tuple[ThreeCushionCall, ThreeCushionState]:
        return self.rules.play(self.game_state, summarize_carom(outcome.events, (0, 1, 2)))

    def _apply(self, call: ThreeCushionCall, outcome: ShotOutcome) -> None:
        if not call.game_over:
            self.arrange(call.next_shooter)

    def _verdict(self, call: ThreeCushionCall) -> Verdict:
        return Verdict(call.shooter, bool(call.foul), call.reason, bool(call.turn_over), bool(call.game_over),
                       call.winner, 1.0 if call.point else 0.0, call)

    def call_info(self, verdict: Verdict | None) -> dict[str, Any]:
        """``point`` (the shot scored), ``cushions`` (the cue ball's cushion contacts before the second ball),
        ``score`` (both players), ``run`` (the shooter's points in this inning)."""
        s = self.game_state
        call = verdict.call if verdict is not None else None
        return {"point": bool(call.point) if call is not None else False,
                "cushions": int(call.cushions) if call is not None else 0,
                "score": np.array(s.score, np.int64), "run": int(s.run)}

    @classmethod
    def info_keys(cls, n_balls: int) -> dict[str, InfoSpec]:
        return {"point": flag("the shot scored a point"),
                "cushions": integer("the cue ball's cushion contacts before it met the second ball"),
                "score": InfoSpec(np.int64, (2,), "both players' points (player 0 is the agent)", 0),
                "run": integer("the shooter's points in this inning")}

    def hud(self, names: tuple[str, str]) -> dict[str, Any]:
        s = self.game_state
        call = self.last_call
        what = None
        if call is not None:
            what = f"point ({call.cushions} cushions)" if call.point else f"no point ({call.cushions} cushions)"
        goal = self.rules.options.target_points
        return {
            **base_hud(self, names, what),
            "scores": (f"{s.score[0]}/{goal}", f"{s.score[1]}/{goal}"),
            "note": None if s.game_over else (f"run {s.run}" + (", opening shot" if s.break_shot else "")),
            "ball_in_hand": False,
            "targets": (),
        }


__all__ = ["CaromSession", "CAROM_NUMBERS", "N_CAROM_FEATURES"]
