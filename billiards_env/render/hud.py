"""The game panel (HUD) below the table: whose turn it is, the groups, ball in hand, the last call and the score.

The env hands the renderer plain data, a mapping (``Task.hud(env)``; None for tasks without one). Keys read here
(any may be missing):

- ``game``: the game's name (``"9-ball"``); ``players``: the two names; ``shooter``: whose turn (0, 1, or None
  when the game is over);
- ``groups``: None (open table, or no groups) or the group of player 0 and of player 1 (``"solids"``,
  ``"stripes"``);
- ``ball_in_hand``: False, ``"anywhere"`` or ``"kitchen"`` (the shooter's); ``kitchen_x``: the head string's x
  (metres) when in hand behind it (the renderer then highlights the kitchen);
- ``call``: the last call in words (``"FOUL: scratch"``); ``foul``: it was a foul; ``winner``: 0, 1 or None;
- ``wins``: games won by each player; ``pocketed``: the balls each player pocketed in this game;
- ``targets``: ball numbers ringed on the table (the legal target); ``call_pocket``: a pocket must be called now
  (the pockets are numbered on the rail); ``called_pocket``: the pocket called (ringed), or None;
- ``scores``: each player's points as text, shown where 8-ball shows the groups (snooker, three-cushion);
  ``note``: a word on the game now (``"on red, break 12"``), after the status.
"""
from __future__ import annotations

from typing import Any, Callable, Mapping

import numpy as np
import pygame

from .paint import mix, text

PANEL: tuple[int, int, int] = (20, 21, 24)  #: panel background
EDGE: tuple[int, int, int] = (58, 58, 64)  #: separator line above the panel
NAME: tuple[int, int, int] = (238, 236, 228)  #: the shooter's name
IDLE: tuple[int, int, int] = (136, 136, 140)  #: the other player's name
TURN: tuple[int, int, int] = (255, 210, 64)  #: whose-turn marker
FOUL: tuple[int, int, int] = (242, 92, 78)  #: a foul call
WIN: tuple[int, int, int] = (250, 212, 92)  #: a game-ending call
NOTE: tuple[int, int, int] = (196, 196, 192)  #: other calls and the status line
#: Panel height as a fraction of the frame width (at least :data:`MIN_HEIGHT` px).
HEIGHT_FRACTION = 0.085
MIN_HEIGHT = 30

BallIcon = Callable[[int, float], tuple[pygame.Surface, int]]


def panel_height(width_px: int) -> int:
    """Height (px) of the panel in a frame ``width_px`` wide."""
    return max(MIN_HEIGHT, int(round(HEIGHT_FRACTION * width_px)))


def turn_marker(rect: pygame.Rect, player: int) -> tuple[float, float, float]:
    """Centre ``(x, y)`` and radius (px) of ``player``'s turn marker in a panel at ``rect`` (filled for the player
    to shoot)."""
    mark = max(2.5, 0.10 * rect.height)
    pad = max(4, int(round(0.012 * rect.width)))
    return rect.left + pad + mark, rect.top + rect.height * (0.27 + 0.48 * player), mark


def draw_panel(surface: pygame.Surface, rect: pygame.Rect, hud: Mapping[str, Any], ball_icon: BallIcon) -> None:
    """Paint the panel for ``hud`` into ``rect``: one row per player on the left (turn marker, name, games won,
    group, the balls pocketed in this game as small balls), the game and its status and the last call on the
    right. ``ball_icon(number, radius_px)`` gives a ball sprite and its centre offset."""
    pygame.draw.rect(surface, PANEL, rect)
    pygame.draw.line(surface, EDGE, rect.topleft, (rect.right - 1, rect.top))
    w, h = rect.width, rect.height
    pad = max(4, int(round(0.012 * w)))
    size = max(9, int(round(0.36 * h)))
    names = tuple(hud.get("players") or ("player 0", "player 1"))
    shooter = hud.get("shooter")
    groups = hud.get("groups")
    wins = tuple(hud.get("wins") or (0, 0))
    pocketed = tuple(hud.get("pocketed") or ((), ()))
    left_w = int(0.56 * w)
    winner = hud.get("winner")
    for p in (0, 1):
        x, y, mark = turn_marker(rect, p)
        turn = shooter == p
        if turn or winner == p:
            pygame.draw.circle(surface, WIN if winner == p else TURN, (int(round(x)), int(round(y))),
                               int(round(mark)))
        else:
            pygame.draw.circle(surface, mix(PANEL, IDLE, 0.5), (int(round(x)), int(round(y))), int(round(mark)), 1)
        x += 2 * mark
        colour = WIN if winner == p else (NAME if turn else IDLE)
        text(surface, str(names[p]), size, colour, (x, y), max_width=0.17 * w - x + rect.left)
        text(surface, f"won {int(wins[p])}", size, colour, (rect.left + 0.18 * w, y), max_width=0.075 * w)
        labels = hud.get("scores") or groups  # a game's points (snooker, carom), else 8-ball's groups
        if labels is not None:
            text(surface, str(labels[p]), size, colour, (rect.left + 0.26 * w, y), max_width=0.08 * w)
        _draw_balls(surface, pocketed[p], rect.left + 0.345 * w, rect.left + left_w, y, 0.19 * h, ball_icon)
    right = rect.left + left_w + pad
    room = rect.right - pad - right
    status = _status(hud, names, shooter)
    text(surface, status, size, NOTE, (right, rect.top + h * 0.27), max_width=room)
    call = hud.get("call")
    if call:
        colour = WIN if hud.get("winner") is not None else (FOUL if hud.get("foul") else NOTE)
        text(surface, str(call), size, colour, (right, rect.top + h * 0.75), max_width=room)


def _status(hud: Mapping[str, Any], names: tuple[str, ...], shooter: int | None) -> str:
    """``"9-ball: agent to shoot, in hand (kitchen)"`` or ``"9-ball: game over"``."""
    game = str(hud.get("game", "game"))
    if shooter is None:
        return f"{game}: game over"
    out = f"{game}: {names[shooter]} to shoot"
    bih = hud.get("ball_in_hand")
    if bih:
        out += ", in hand" + (" (kitchen)" if bih == "kitchen" else "")
    if hud.get("call_pocket"):
        out += ", call a pocket"
    if hud.get("note"):
        out += f"; {hud['note']}"
    return out


def _draw_balls(surface: pygame.Surface, numbers: Any, x0: float, x1: float, y: float, radius: float,
                ball_icon: BallIcon) -> None:
    """Small balls in a row from ``x0``, closer together if they would pass ``x1``."""
    nums = [int(n) for n in numbers]
    if not nums:
        return
    step = min(2.2 * radius, (x1 - x0 - 2 * radius) / max(len(nums) - 1, 1))
    for i, n in enumerate(nums):
        sprite, half = ball_icon(n, radius)
        c = np.array([x0 + radius + i * step, y])
        surface.blit(sprite, (int(round(c[0])) - half, int(round(c[1])) - half))


__all__ = ["draw_panel", "panel_height", "turn_marker", "HEIGHT_FRACTION"]
