"""What a game shows on screen, as plain data: the score, the players' names, the referee's call in words, the HUD
dict the renderer draws (:mod:`billiards_env.render.hud`). Names, numbers and words; no drawing."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from billiards_env.physics.layout import head_string_x
from billiards_env.rules import KITCHEN
from billiards_env.rules.state import Call

if TYPE_CHECKING:  # pragma: no cover
    from .session import GameSession


class Score:
    """Games won by each player over the session's life, and the object balls each player pocketed in the current
    game (balls that stay down: a respotted ball does not count)."""

    def __init__(self) -> None:
        self.wins = [0, 0]
        self.pocketed: tuple[list[int], list[int]] = ([], [])

    def new_game(self) -> None:
        self.pocketed = ([], [])

    def record(self, call: Call) -> None:
        """Count a judged shot: the balls it pocketed for its shooter, the game for its winner."""
        self.pocketed[call.shooter].extend(n for n in call.pocketed if n not in call.respot)
        if call.game_over and call.winner is not None:
            self.wins[call.winner] += 1


def call_text(call: Call, names: tuple[str, str]) -> str:
    """The referee's call in words: ``"FOUL: scratch (geometric)"``, ``"9 pocketed: agent wins"``,
    ``"agent: pocketed 3, 5"``, ``"agent: no ball pocketed"``, ``"geometric: push-out"``."""
    who = names[call.shooter]
    if call.game_over:
        return f"{call.reason}: {names[call.winner] if call.winner is not None else 'nobody'} wins"
    if call.foul:
        return f"FOUL: {call.reason} ({who})"
    if call.push_out:
        return f"{who}: push-out"
    kept = [n for n in call.pocketed if n not in call.respot]
    return f"{who}: pocketed {', '.join(map(str, kept))}" if kept else f"{who}: no ball pocketed"


def game_hud(session: "GameSession", names: tuple[str, str]) -> dict[str, Any]:
    """The HUD of a game now (keys: :mod:`billiards_env.render.hud`). The ringed targets are the game's
    (``logic.hud_targets``: 9-ball the lowest ball, 8-ball the 8 once it is the target). While a shot is under way
    (the frames of its animation) the cue ball is no longer in hand and the called pocket is ringed."""
    s = session.state
    over = s.game_over
    targets = () if over else tuple(session.rules.legal_targets(s))
    shot = session.shot_under_way
    in_hand = False if (over or shot is not None) else s.ball_in_hand
    calling = bool(not over and session.needs_called_pocket())
    call = session.last_call
    score = session.score
    return {
        "game": session.spec.title,
        "players": names,
        "shooter": None if over else s.shooter,
        "groups": s.groups,
        "ball_in_hand": in_hand,
        "kitchen_x": head_string_x(session.table.table) if in_hand == KITCHEN else None,
        "call": call_text(call, names) if call is not None else None,
        "foul": bool(call is not None and call.foul),
        "winner": s.winner,
        "wins": (score.wins[0], score.wins[1]),
        "pocketed": (tuple(score.pocketed[0]), tuple(score.pocketed[1])),
        "targets": session.logic.hud_targets(s, targets),
        "call_pocket": calling and shot is None,
        "called_pocket": shot.pocket if (calling and shot is not None) else None,
    }


__all__ = ["Score", "call_text", "game_hud"]
