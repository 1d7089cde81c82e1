"""One game in progress on a table state: :class:`GameSession`.

The session holds the rules' :class:`~billiards_env.rules.GameState`, judges each shot's
:class:`~billiards_env.physics.outcome.ShotOutcome` with the ruleset, applies the call to the table (respotted
balls, the cue ball back on the table for the next shooter in hand), keeps the score, and tells the table state who
is to shoot and what they may do (its :class:`~billiards_env.table_state.ShotView`). It is the game for every
driver: the single-agent env's task, the two-player env and the players all read it through ``table_state.game``.
No Gymnasium here.
"""
from __future__ import annotations

import contextlib
from dataclasses import replace
from typing import Any, Iterator

import numpy as np

from billiards_env.physics.layout import DIAMOND_ORDER, RACK_ORDER, spot_cue_ball, spot_object_ball
from billiards_env.physics.outcome import ShotOutcome
from billiards_env.rules import Call, GameState, ShotInfo, summarize_outcome
from billiards_env.table_state import ShotView, TableState

from .hud import Score
from .registry import GameSpec


class GameSession:
    """The game ``spec`` on ``table`` with the rules options ``rules`` (layered over the game's env defaults).
    Installs itself as ``table.game`` and as the source of ``table.view``.

    ``state`` is the rules' state (shooter, ball in hand, groups, fouls, game over, winner); ``last_call`` the call
    on the last shot; ``score`` the games won and the balls each player pocketed; ``shot_under_way`` the shot being
    played (between :meth:`begin_shot` and :meth:`judge`: the HUD shows its called pocket)."""

    def __init__(self, spec: GameSpec, rules: Any, table: TableState) -> None:
        self.spec = spec
        self.logic = spec.logic
        self.rules = self.logic.make_rules(rules)
        #: What the shooter declares besides the shot (action dims): ``"pocket"``, ``"push"``.
        self.declarations: tuple[str, ...] = self.logic.declarations(self.rules)
        self.table = table
        self.numbers = np.asarray(table.numbers, dtype=np.int64)
        self.row_of = {int(n): i for i, n in enumerate(self.numbers.tolist())}
        self.state: GameState = self.rules.initial_state()
        self.last_call: Call | None = None
        self.score = Score()
        self.shot_under_way: Any = None
        self._viewer: int | None = None
        self._rack_slots: np.ndarray | None = None
        table.game = self
        table.view_source = self.view
        table.changed()

    # --- the game's state --------------------------------------------------------------------------------------------
    def set_state(self, state: GameState) -> None:
        """Continue from ``state`` (a new game, a table set up by hand)."""
        self.state = state
        self.table.changed()

    def numbers_on(self) -> tuple[int, ...]:
        """Numbers of the object balls on the table (ascending rows)."""
        on = self.table.balls.on_table
        return tuple(int(n) for i, n in enumerate(self.numbers.tolist()) if on[i] and n)

    def legal_rows(self) -> list[int]:
        """Rows of the balls the shooter may hit first (the rules' legal targets)."""
        return [self.row_of[n] for n in self.rules.legal_targets(self.state)]

    def needs_called_pocket(self) -> bool:
        """The shooter must call a pocket for the next shot (8-ball, on the 8)."""
        return bool(self.rules.needs_called_pocket(self.state))

    def view(self, table: TableState) -> ShotView:
        """Who is to shoot and what they may do (the table state's ``view``)."""
        s = self.state
        rows = self.legal_rows()
        on = table.balls.on_table
        area = self.logic.place_area(s, table.table, float(table.balls.radius[0]))
        return ShotView(tuple(int(i) for i in rows if on[i] and i != 0), min(rows) if rows else None, area,
                        bool(s.break_shot and not s.game_over), self.needs_called_pocket(), bool(s.push_out_available),
                        s.shooter)

    # --- racks -------------------------------------------------------------------------------------------------------
    def order_rack(self, rng: np.random.Generator, placement: str) -> None:
        """Order a racked layout (``placement`` ``"rack"`` or ``"diamond"``) as the rules say, drawing from ``rng``."""
        order_rack = self.logic.order_rack
        if order_rack is None or placement not in ("rack", "diamond"):
            return
        pos = self.table.balls.pos
        if self._rack_slots is None:
            order = DIAMOND_ORDER if placement == "diamond" else RACK_ORDER
            self._rack_slots = np.array([pos[self.row_of[n]] for n in order])
        slots = self._rack_slots
        for slot, number in enumerate(order_rack(len(slots), rng)):
            pos[self.row_of[number]] = slots[slot]
        self.table.changed()

    # --- the view of one player --------------------------------------------------------------------------------------
    def features(self, player: int | None = None) -> np.ndarray:
        """The game features seen by ``player`` (default: the player of :meth:`seen_by`, else the shooter)."""
        s = self.state
        me = player if player is not None else (s.shooter if self._viewer is None else self._viewer)
        return self.logic.features(self.rules, s, me)

    @contextlib.contextmanager
    def seen_by(self, player: int) -> Iterator[None]:
        """Within the block :meth:`features` takes ``player``'s point of view instead of the shooter's."""
        if player not in (0, 1):
            raise ValueError(f"player: must be 0 or 1, got {player!r}")
        saved, self._viewer = self._viewer, player
        try:
            yield
        finally:
            self._viewer = saved

    # --- shots -------------------------------------------------------------------------------------------------------
    def begin_shot(self, shot: Any) -> None:
        """A shot is under way (its declarations are read when it is judged; the HUD shows it)."""
        self.shot_under_way = shot

    def judge(self, outcome: ShotOutcome, shot: Any = None) -> Call:
        """Call the shot just played (``shot``: its :class:`~billiards_env.shot_path.CueShot`, for the
        declarations; default the one under way), apply the call to the table and the state, keep the score."""
        s = self.state
        shot = self.shot_under_way if shot is None else shot
        summary = summarize_outcome(outcome, self.numbers)
        push = bool(shot is not None and shot.push and s.push_out_available)
        pocket = shot.pocket if (shot is not None and self.needs_called_pocket()) else None
        call, self.state = self.rules.play(s, summary, ShotInfo(push_out=push, called_pocket=pocket))
        t = self.table
        b = t.balls
        r = float(b.radius[0])
        for n in call.respot:
            spot_object_ball(b.pos, b.on_table, r, t.table, self.row_of[n])
        if not b.on_table[0]:
            spot_cue_ball(b.pos, b.on_table, r, t.table)  # in hand for the next shooter
        self.last_call = call
        self.score.record(call)
        self.shot_under_way = None
        t.changed()
        return call

    def respot_opening(self) -> None:
        """After the ``ball_in_hand`` opening's break: the game's last ball back on its spot if it dropped, the cue
        ball on the table."""
        t = self.table
        b = t.balls
        r = float(b.radius[0])
        last = self.logic.opening_respot
        if last is not None and not b.on_table[self.row_of[last]]:
            spot_object_ball(b.pos, b.on_table, r, t.table, self.row_of[last])
        if not b.on_table[0]:
            spot_cue_ball(b.pos, b.on_table, r, t.table)
        t.changed()

    def viewer_state(self, player: int) -> GameState:
        """The rules' state with ``player`` to shoot (what that player's legal targets are read from)."""
        return self.state if self.state.shooter == player else replace(self.state, shooter=player)


__all__ = ["GameSession"]
