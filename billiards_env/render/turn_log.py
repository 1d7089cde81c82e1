"""The play window's turn log: one short line per shot of a game, newest last, from plain data; it scrolls.

A shot is a dict in words (``pocketed``: ids or numbers, ``foul``, ``foul_reason`` and ``call``: the referee's
reasons, ``scratch``, ``shooter``; optional ``turn_over``, ``game_over``, ``winner``, ``push_out``) and the game's
own keys: snooker's ``points`` and ``foul_points``, three-cushion's ``point`` and ``cushions``. The play window makes
it from the referee's calls or from the env's info (``env.unwrapped.info_words``), the same for the human's own
shots. Each game's line says what matters in it: pool the balls pocketed ("you: pocketed 3 - shoot again"), snooker
the balls potted and their points ("geometric: potted red (1) - shoots again"), three-cushion the point and the
cushions ("you: no point (2 cushions) - turn over"); every line says why a turn ended. No rules here: the words
come from the referee's call.

The balls potted are read by one small function, :func:`potted_names` (ids such as ``"red11"``, ``"blue"``, ``"3"``
or ball numbers).
"""
from __future__ import annotations

import re
from typing import Any, Iterable, Mapping, Sequence

import pygame

from .paint import text

FOUL_COLOUR = (235, 110, 100)
WIN_COLOUR = (240, 200, 80)
LINE_COLOUR = (200, 200, 194)
HINT_COLOUR = (140, 140, 150)
#: Lines the log keeps (older ones are dropped); the window shows the last few and scrolls back through these.
MAX_LINES = 500


def potted_names(pocketed: Iterable[Any]) -> list[str]:
    """The object balls of ``pocketed`` in words, the cue ball left out: pool numbers as they are (``3``, ``"3"``),
    snooker's reds as ``"red"`` (``"red11"``), colours by name (``"blue"``)."""
    out = []
    for b in pocketed or ():
        name = str(b)
        if name in ("cue", "0"):  # the cue ball (its id in every pocket game, or its number); snooker's yellow is
            continue              # a colour, and three-cushion, whose white and yellow are cue balls, pockets nothing
        out.append(re.sub(r"^([a-z]+)\d+$", r"\1", name))  # red11 -> red
    return out


def _counted(names: Sequence[str]) -> str:
    """``["red", "red", "blue"]`` -> ``"red x2, blue"``."""
    seen: dict[str, int] = {}
    for n in names:
        seen[n] = seen.get(n, 0) + 1
    return ", ".join(n if k == 1 else f"{n} x{k}" for n, k in seen.items())


def _says(name: str, third: str, second: str) -> str:
    """``name`` and the verb that agrees with it ("you have", "geometric has")."""
    return f"{name} {second if name == 'you' else third}"


def _what(turn: Mapping[str, Any]) -> str:
    """What the shot did, in the game's terms (empty for a pool shot that pocketed nothing)."""
    if "cushions" in turn:  # three-cushion
        n = int(turn.get("cushions") or 0)
        return f"{'point' if turn.get('point') else 'no point'} ({n} cushion{'' if n == 1 else 's'})"
    potted = potted_names(turn.get("pocketed", ()))
    if "points" in turn:  # snooker
        pts = int(turn.get("points") or 0)
        if potted and not turn.get("foul"):
            return f"potted {_counted(potted)} ({pts})"
        return f"potted {_counted(potted)}" if potted else "no pot"
    return f"pocketed {', '.join(potted)}" if potted else ""


def turn_line(turn: Mapping[str, Any], names: Sequence[str], last_of_turn: bool = False) -> tuple[str, str]:
    """One shot in words, and its kind (``foul``, ``win``, ``shot``): who shot, what the shot did in its game,
    what the referee called, and, for the shot that ended a turn (``last_of_turn``, or ``turn_over`` in the dict),
    why the turn passed."""
    shooter = int(turn.get("shooter", 0) or 0)
    who = names[shooter] if 0 <= shooter < len(names) else f"player {shooter}"
    other = names[1 - shooter] if len(names) == 2 and shooter in (0, 1) else "the other player"
    call = str(turn.get("call") or "")
    what = _what(turn)
    pool = "cushions" not in turn and "points" not in turn
    if turn.get("game_over"):
        winner = turn.get("winner")
        won = names[winner] if isinstance(winner, int) and 0 <= winner < len(names) else "nobody"
        said = call if (pool or not what) else (f"{what}, {call}" if call and call not in what else what)
        return f"{who}: {said or 'game over'} - {_says(won, 'wins', 'win')}", "win"
    if turn.get("foul"):
        reason = turn.get("foul_reason") or call or "foul"
        if "cushions" in turn:
            return f"{who}: FOUL {reason} - turn over", "foul"
        if "points" in turn:
            pts = int(turn.get("foul_points") or 0)
            return f"{who}: FOUL {reason} - {other} {'get' if other == 'you' else 'gets'} {pts} points", "foul"
        extra = ", scratch" if turn.get("scratch") and reason != "scratch" else ""
        return f"{who}: FOUL {reason}{extra} - {_says(other, 'has', 'have')} ball in hand", "foul"
    if turn.get("push_out") or call == "push-out":
        return f"{who}: push-out - {other} to play or pass", "shot"
    scored = bool(turn.get("point")) if "cushions" in turn else bool(potted_names(turn.get("pocketed", ())))
    line = f"{who}: {what or 'no ball pocketed'}"
    over = turn.get("turn_over")
    if over is None:
        over = last_of_turn and not scored
    if over:
        line += " - turn over"
    elif scored:
        line += " - shoot again" if who == "you" else " - shoots again"
    return line, "shot"


class TurnLog:
    """The lines of the current game's shots (:meth:`add` a turn's shots, :meth:`draw` a window of them).

    The window shows the newest lines unless scrolled back (:meth:`scroll`: the mouse wheel, Page Up / Page Down,
    Home / End in the play window); new lines bring it back to the newest. A hint in the corner says how many lines
    are hidden above or below."""

    def __init__(self) -> None:
        self.lines: list[tuple[str, str]] = []
        self.offset = 0  # lines scrolled back from the newest
        self._shown = 1  # lines the last draw had room for

    def clear(self) -> None:
        self.lines = []
        self.offset = 0

    def add(self, turns: Sequence[Mapping[str, Any]], names: Sequence[str]) -> None:
        """Log the shots of one step: each line in words; the last one of the run of shots says why it ended."""
        for k, turn in enumerate(turns):
            nxt = turns[k + 1] if k + 1 < len(turns) else None
            last = nxt is None or int(nxt.get("shooter", 0) or 0) != int(turn.get("shooter", 0) or 0)
            self.lines.append(turn_line(turn, names, last_of_turn=last))
        del self.lines[:-MAX_LINES]
        self.offset = 0

    def note(self, line: str, kind: str = "shot") -> None:
        """Log one line that is not a shot (what happened before the first shot of a game)."""
        self.lines.append((line, kind))
        del self.lines[:-MAX_LINES]
        self.offset = 0

    def scroll(self, lines: int) -> None:
        """Scroll back (``lines > 0``, towards older lines) or forward, within the lines kept."""
        self.offset = min(max(self.offset + int(lines), 0), max(len(self.lines) - self._shown, 0))

    def page(self) -> int:
        """Lines in one page of the window (what Page Up / Page Down scroll)."""
        return max(self._shown - 1, 1)

    def visible(self, n: int) -> list[tuple[str, str]]:
        """The ``n`` lines in the window, oldest at the top."""
        end = len(self.lines) - self.offset
        return self.lines[max(end - n, 0):end] if n > 0 else []

    def draw(self, surface: pygame.Surface, rect: pygame.Rect, line_height: int = 18, size: int = 19) -> None:
        """The lines in the window that fit in ``rect``, oldest at the top, and the scroll hint."""
        n = max(rect.height // line_height, 0)
        self._shown = max(n, 1)
        self.offset = min(self.offset, max(len(self.lines) - self._shown, 0))
        shown = self.visible(n)
        hint = scroll_hint(len(self.lines) - self.offset - len(shown), self.offset)
        for k, (line, kind) in enumerate(shown):
            colour = FOUL_COLOUR if kind == "foul" else WIN_COLOUR if kind == "win" else LINE_COLOUR
            y = rect.top + line_height * k + line_height / 2
            room = rect.width - (150 if hint and k == 0 else 0)
            text(surface, line, size, colour, (rect.left, y), max_width=room)
        if hint:
            text(surface, hint, size - 3, HINT_COLOUR, (rect.right - 145, rect.top + line_height / 2), max_width=145)


def scroll_hint(above: int, below: int) -> str:
    """The corner hint of a scrolled log: lines hidden above (older) and below (newer), and the keys."""
    parts = []
    if above > 0:
        parts.append(f"{above} earlier")
    if below > 0:
        parts.append(f"{below} newer")
    return f"{', '.join(parts)} (wheel, PgUp/PgDn)" if parts else ""


__all__ = ["TurnLog", "turn_line", "potted_names", "scroll_hint", "MAX_LINES"]
