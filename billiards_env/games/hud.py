"""What a game shows on screen, as plain data: the score, the referee's call in words, and the pieces of the HUD
dict the renderer draws (:mod:`billiards_env.render.hud`). Names, numbers and words; no drawing."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Sequence

if TYPE_CHECKING:  # pragma: no cover
    from .session import Verdict


class Score:
    """Games won by each player over the session's life, and the balls each player pocketed in the current game
    (balls that stay down: a respotted ball does not count)."""

    def __init__(self) -> None:
        self.wins = [0, 0]
        self.pocketed: tuple[list[Any], list[Any]] = ([], [])

    def new_game(self) -> None:
        self.pocketed = ([], [])

    def record(self, verdict: "Verdict", kept: Sequence[Any] = ()) -> None:
        """Count a judged shot: the balls ``kept`` down for its shooter, the game for its winner."""
        self.pocketed[verdict.shooter].extend(kept)
        if verdict.game_over and verdict.winner is not None:
            self.wins[verdict.winner] += 1


def call_text(verdict: "Verdict", names: tuple[str, str], what: str) -> str:
    """The referee's call in words: ``"FOUL: scratch (geometric)"``, ``"9 pocketed: agent wins"`` (``"you win"`` in the
    play window), or
    ``"<shooter>: <what>"`` (``what`` the game's own words for a clean shot: ``"pocketed 3, 5"``, ``"point"``...)."""
    who = names[verdict.shooter]
    if verdict.game_over:
        winner = names[verdict.winner] if verdict.winner is not None else "nobody"
        return f"{verdict.reason}: {winner} {'win' if winner == 'you' else 'wins'}"
    if verdict.foul:
        return f"FOUL: {verdict.reason} ({who})"
    return f"{who}: {what}"


def base_hud(session: Any, names: tuple[str, str], what: str | None) -> dict[str, Any]:
    """The HUD keys every game fills: the game's title, the players, whose turn, the last call in words, a foul,
    the winner, the games won, the balls pocketed."""
    over = session.game_over
    v = session.verdict
    score = session.score
    return {
        "game": session.spec.title,
        "players": names,
        "shooter": None if over else session.shooter,
        "call": call_text(v, names, what or "") if v is not None else None,
        "foul": bool(v is not None and v.foul),
        "winner": session.winner,
        "wins": (score.wins[0], score.wins[1]),
        "pocketed": (tuple(score.pocketed[0]), tuple(score.pocketed[1])),
    }


__all__ = ["Score", "call_text", "base_hud"]
