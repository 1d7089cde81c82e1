"""Marks drawn over the table: the cue-ball diagram of the tip offset (spin), the kitchen line when the cue ball
is in hand behind the head string, rings around the legal target balls and the called pocket, and the pocket
numbers when a pocket must be called. Plain geometry in pixels; the renderer says where."""
from __future__ import annotations

import math

import numpy as np
import pygame

from . import colors as C
from .paint import aa_disc, aa_ring, mix, surface_from_rgba, text

#: The largest tip offset that is not a miscue (fraction of R): a faint ring on the diagram.
MISCUE_LIMIT = 0.5
TIP_DOT: C.RGB = (214, 34, 40)  #: the tip's mark on the diagram
KITCHEN_LINE: C.RGB = (255, 232, 130)  #: the head string, highlighted when the cue ball is in hand behind it
RING: C.RGB = (255, 226, 96)  #: rings around legal targets and the called pocket
LABEL: C.RGB = (250, 244, 220)  #: pocket numbers


def draw_tip_diagram(surface: pygame.Surface, centre: tuple[float, float], radius_px: float, side: float,
                     top: float, limit: float = MISCUE_LIMIT) -> None:
    """A cue ball seen by the shooter (a white disc of ``radius_px``) with a red dot where the tip strikes it:
    ``side`` to the right, ``top`` up, both fractions of the ball's radius; a faint ring at ``limit`` (the miscue
    limit) and a faint cross through the centre."""
    c = np.asarray(centre, dtype=float)
    aa_disc(surface, (8, 8, 8), c, radius_px + max(1.0, 0.08 * radius_px))
    aa_disc(surface, C.CUE_BALL, c, radius_px)
    faint = mix(C.CUE_BALL, (90, 90, 90), 0.45)
    aa_ring(surface, faint, c, limit * radius_px, max(1.0, 0.05 * radius_px))
    w = max(1, int(round(0.04 * radius_px)))
    pygame.draw.line(surface, faint, (c[0] - radius_px * 0.85, c[1]), (c[0] + radius_px * 0.85, c[1]), w)
    pygame.draw.line(surface, faint, (c[0], c[1] - radius_px * 0.85), (c[0], c[1] + radius_px * 0.85), w)
    aa_disc(surface, TIP_DOT, tip_point(c, radius_px, side, top), max(1.6, 0.17 * radius_px))


def tip_point(centre: tuple[float, float] | np.ndarray, radius_px: float, side: float, top: float) -> np.ndarray:
    """Pixel of tip offset ``(side, top)`` on a diagram at ``centre`` of ``radius_px`` (screen y points down)."""
    return np.array([centre[0] + side * radius_px, centre[1] - top * radius_px], dtype=float)


def tip_from_point(point: tuple[float, float], centre: tuple[float, float], radius_px: float,
                   max_offset: float) -> tuple[float, float]:
    """The tip offset ``(side, top)`` of a pixel on a diagram (inverse of :func:`tip_point`), moved onto the disc of
    radius ``max_offset`` if it lies outside."""
    side = (point[0] - centre[0]) / radius_px
    top = (centre[1] - point[1]) / radius_px
    r = math.hypot(side, top)
    if r > max_offset:
        side, top = side * max_offset / r, top * max_offset / r
    return float(side), float(top)


def draw_kitchen(surface: pygame.Surface, playing_rect: pygame.Rect, x_px: float) -> None:
    """The kitchen (left of the head string at column ``x_px``) lightly tinted and the head string drawn bright."""
    left = playing_rect.left
    width = int(round(x_px)) - left
    if width <= 0:
        return
    tint = pygame.Surface((width, playing_rect.height), pygame.SRCALPHA)
    tint.fill((*KITCHEN_LINE, 22))
    surface.blit(tint, (left, playing_rect.top))
    line = max(2, int(round(playing_rect.height * 0.006)))
    strip = np.zeros((playing_rect.height, line, 4), np.uint8)
    strip[..., :3] = KITCHEN_LINE
    strip[..., 3] = 210
    surface.blit(surface_from_rgba(strip), (int(round(x_px - line / 2)), playing_rect.top))


def draw_ring(surface: pygame.Surface, centre: np.ndarray, radius_px: float, width_px: float,
              colour: C.RGB = RING) -> None:
    """A bright ring (a legal target ball, the called pocket)."""
    aa_ring(surface, (20, 16, 4), centre, radius_px, width_px + 1.5, alpha=120)
    aa_ring(surface, colour, centre, radius_px, width_px, alpha=235)


def draw_pocket_labels(surface: pygame.Surface, centres_px: np.ndarray, size: int) -> None:
    """Pocket numbers 1..n (the order of the table's pockets and of keys 1-6 in billiards-play) at ``centres_px``
    (n, 2), the label discs' centres."""
    for k, pos in enumerate(centres_px):
        aa_disc(surface, (12, 12, 12), pos, 0.62 * size)
        text(surface, str(k + 1), size, LABEL, (pos[0], pos[1] + 1), anchor="centre")


__all__ = ["draw_tip_diagram", "tip_point", "tip_from_point", "draw_kitchen", "draw_ring", "draw_pocket_labels",
           "MISCUE_LIMIT"]
