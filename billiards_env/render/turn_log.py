"""The play window's turn log: one short line per shot of a game, newest last, from plain data.

A shot is a dict in words (``pocketed``: numbers or ids, ``foul``, ``foul_reason`` and ``call``: the referee's
reasons, ``scratch``, ``shooter``; optional ``turn_over``, ``game_over``, ``winner``, ``push_out``), which the play
window makes from the referee's calls or from the env's info (``env.unwrapped.info_words``), the same for the
human's own shots, so the window shows why each turn ended ("you: no ball pocketed - turn over", "geometric: FOUL
wrong ball first - you have ball in hand"). No rules here: the words come from the referee's call.
"""
from __future__ import annotations

from typing import Any, Iterable, Mapping, Sequence

import pygame

from .paint import text

FOUL_COLOUR = (235, 110, 100)
WIN_COLOUR = (240, 200, 80)
LINE_COLOUR = (200, 200, 194)
#: Lines the log keeps (older ones scroll away).
MAX_LINES = 50


def _numbers(pocketed: Iterable[Any]) -> list[int]:
    """Object-ball numbers from ``pocketed`` (numbers or ball ids; the cue ball left out)."""
    out = []
    for b in pocketed or ():
        if str(b) in ("cue", "0"):
            continue
        try:
            out.append(int(b))
        except (TypeError, ValueError):
            continue
    return out


def _says(name: str, third: str, second: str) -> str:
    """``name`` and the verb that agrees with it ("you have", "geometric has")."""
    return f"{name} {second if name == 'you' else third}"


def turn_line(turn: Mapping[str, Any], names: Sequence[str], last_of_turn: bool = False) -> tuple[str, str]:
    """One shot in words, and its kind (``foul``, ``win``, ``shot``): who shot, what the referee called, and, for
    the shot that ended a turn (``last_of_turn``, or ``turn_over`` in the dict), why the turn passed."""
    shooter = int(turn.get("shooter", 0) or 0)
    who = names[shooter] if 0 <= shooter < len(names) else f"player {shooter}"
    other = names[1 - shooter] if len(names) == 2 and shooter in (0, 1) else "the other player"
    potted = _numbers(turn.get("pocketed", ()))
    call = str(turn.get("call") or "")
    if turn.get("game_over"):
        winner = turn.get("winner")
        won = names[winner] if isinstance(winner, int) and 0 <= winner < len(names) else "nobody"
        return f"{who}: {call or 'game over'} - {_says(won, 'wins', 'win')}", "win"
    if turn.get("foul"):
        reason = turn.get("foul_reason") or call or "foul"
        extra = ", scratch" if turn.get("scratch") and reason != "scratch" else ""
        return f"{who}: FOUL {reason}{extra} - {_says(other, 'has', 'have')} ball in hand", "foul"
    if turn.get("push_out") or call == "push-out":
        return f"{who}: push-out - {other} to play or pass", "shot"
    line = f"{who}: pocketed {', '.join(map(str, potted))}" if potted else f"{who}: no ball pocketed"
    over = turn.get("turn_over")
    if over is None:
        over = last_of_turn and not potted
    if over:
        line += " - turn over"
    elif potted:
        line += " - shoot again" if who == "you" else " - shoots again"
    return line, "shot"


class TurnLog:
    """The lines of the current game's shots (:meth:`add` a turn's shots, :meth:`draw` the last few)."""

    def __init__(self) -> None:
        self.lines: list[tuple[str, str]] = []

    def clear(self) -> None:
        self.lines = []

    def add(self, turns: Sequence[Mapping[str, Any]], names: Sequence[str]) -> None:
        """Log the shots of one step: each line in words; the last one of the run of shots says why it ended."""
        for k, turn in enumerate(turns):
            nxt = turns[k + 1] if k + 1 < len(turns) else None
            last = nxt is None or int(nxt.get("shooter", 0) or 0) != int(turn.get("shooter", 0) or 0)
            self.lines.append(turn_line(turn, names, last_of_turn=last))
        del self.lines[:-MAX_LINES]

    def draw(self, surface: pygame.Surface, rect: pygame.Rect, line_height: int = 18, size: int = 19) -> None:
        """The newest lines that fit in ``rect``, oldest at the top."""
        n = max(rect.height // line_height, 0)
        shown = self.lines[-n:] if n else []
        for k, (line, kind) in enumerate(shown):
            colour = FOUL_COLOUR if kind == "foul" else WIN_COLOUR if kind == "win" else LINE_COLOUR
            y = rect.top + line_height * k + line_height / 2
            text(surface, line, size, colour, (rect.left, y), max_width=rect.width)


__all__ = ["TurnLog", "turn_line", "MAX_LINES"]
