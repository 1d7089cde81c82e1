"""Small drawing helpers shared by the table, the ball sprites and the HUD (pygame surfaces and numpy arrays;
no display needed)."""
from __future__ import annotations

import math
import os
from functools import lru_cache

import numpy as np

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
import pygame  # noqa: E402

RGB = tuple[int, int, int]


def aa_disc(surface: pygame.Surface, colour: RGB, centre: np.ndarray, radius: float) -> None:
    """An anti-aliased filled circle at a sub-pixel centre (coverage computed by supersampling; the image of a
    disc drawn again at the same place, as on every frame of an overlay, is reused)."""
    if radius <= 0:
        return
    image, x0, y0 = _disc_image(tuple(int(c) for c in colour), float(centre[0]), float(centre[1]), float(radius))
    surface.blit(image, (x0, y0))


@lru_cache(maxsize=512)
def _disc_image(colour: RGB, cx: float, cy: float, radius: float) -> tuple[pygame.Surface, int, int]:
    centre = (cx, cy)
    x0, y0 = int(math.floor(centre[0] - radius)) - 1, int(math.floor(centre[1] - radius)) - 1
    n_x, n_y = int(math.ceil(radius * 2)) + 3, int(math.ceil(radius * 2)) + 3
    ss = 4
    ys = y0 + (np.arange(n_y * ss) + 0.5) / ss - 0.5 - centre[1]
    xs = x0 + (np.arange(n_x * ss) + 0.5) / ss - 0.5 - centre[0]
    inside = (ys[:, None] ** 2 + xs[None, :] ** 2) <= radius * radius
    cover = inside.reshape(n_y, ss, n_x, ss).mean(axis=(1, 3))
    rgba = np.zeros((n_y, n_x, 4), np.uint8)
    rgba[..., :3] = colour
    rgba[..., 3] = np.rint(cover * 255).astype(np.uint8)
    return surface_from_rgba(rgba), x0, y0


def aa_ring(surface: pygame.Surface, colour: RGB, centre: np.ndarray, radius: float, width: float,
            alpha: int = 255) -> None:
    """An anti-aliased ring (circle outline) of ``width`` px centred on ``radius``, at a sub-pixel centre."""
    if radius <= 0 or width <= 0:
        return
    image, x0, y0 = _ring_image(tuple(int(c) for c in colour), float(centre[0]), float(centre[1]), float(radius),
                                float(width), int(alpha))
    surface.blit(image, (x0, y0))


@lru_cache(maxsize=256)
def _ring_image(colour: RGB, cx: float, cy: float, radius: float, width: float,
                alpha: int) -> tuple[pygame.Surface, int, int]:
    centre = (cx, cy)
    outer = radius + 0.5 * width
    x0, y0 = int(math.floor(centre[0] - outer)) - 1, int(math.floor(centre[1] - outer)) - 1
    n = int(math.ceil(outer * 2)) + 3
    ss = 4
    ys = y0 + (np.arange(n * ss) + 0.5) / ss - 0.5 - centre[1]
    xs = x0 + (np.arange(n * ss) + 0.5) / ss - 0.5 - centre[0]
    d = np.sqrt(ys[:, None] ** 2 + xs[None, :] ** 2)
    cover = (np.abs(d - radius) <= 0.5 * width).reshape(n, ss, n, ss).mean(axis=(1, 3))
    rgba = np.zeros((n, n, 4), np.uint8)
    rgba[..., :3] = colour
    rgba[..., 3] = np.rint(cover * alpha).astype(np.uint8)
    return surface_from_rgba(rgba), x0, y0


def smoothstep(edge0: float, edge1: float, x: np.ndarray) -> np.ndarray:
    t = np.clip((x - edge0) / (edge1 - edge0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def mix(a: RGB, b: RGB, t: float) -> RGB:
    """Colour ``a`` moved a fraction ``t`` toward ``b``."""
    return tuple(int(round(x + (y - x) * t)) for x, y in zip(a, b))  # type: ignore[return-value]


def scale_colour(colour: RGB, gain: float) -> RGB:
    """Colour brightened (gain > 1) or darkened (gain < 1), clipped to 0-255."""
    return tuple(int(min(255, max(0, round(c * gain)))) for c in colour)  # type: ignore[return-value]


def radius_key(radius_px: float) -> int:
    """Cache key of a pixel radius: tenths of a pixel."""
    return max(1, int(round(radius_px * 10)))


def surface_from_rgba(rgba: np.ndarray) -> pygame.Surface:
    """A per-pixel-alpha surface from an ``(H, W, 4) uint8`` array (no display needed)."""
    h, w = rgba.shape[:2]
    return pygame.image.frombuffer(np.ascontiguousarray(rgba).tobytes(), (w, h), "RGBA").copy()


def surface_to_array(surface: pygame.Surface) -> np.ndarray:
    """A surface's pixels as a contiguous ``(H, W, 3) uint8`` array.

    Same values as ``surfarray.array3d(surface).transpose(1, 0, 2)``, but read row-major in one copy,
    which is several times faster for full frames.
    """
    w, h = surface.get_size()
    return np.frombuffer(pygame.image.tobytes(surface, "RGB"), dtype=np.uint8).reshape(h, w, 3).copy()


_FONTS: dict[int, pygame.font.Font] = {}


def font(size: int) -> pygame.font.Font:
    """pygame's default font at ``size`` px (cached; initialises pygame.font, which needs no display)."""
    size = max(6, int(size))
    if size not in _FONTS:
        if not pygame.font.get_init():
            pygame.font.init()
        _FONTS[size] = pygame.font.Font(None, size)
    return _FONTS[size]


def text(surface: pygame.Surface, message: str, size: int, colour: RGB, pos: tuple[float, float],
         max_width: float | None = None, anchor: str = "left") -> pygame.Rect:
    """Draw ``message`` at ``pos`` (the left or right end of its vertical middle, by ``anchor``), shrunk to
    ``max_width`` px if it is wider. Returns the rectangle drawn."""
    img = font(size).render(message, True, colour)
    if max_width is not None and img.get_width() > max_width > 4:
        h = max(1, int(round(img.get_height() * max_width / img.get_width())))
        img = pygame.transform.smoothscale(img, (int(max_width), h))
    rect = img.get_rect()
    rect.centery = int(round(pos[1]))
    if anchor == "right":
        rect.right = int(round(pos[0]))
    elif anchor == "centre":
        rect.centerx = int(round(pos[0]))
    else:
        rect.left = int(round(pos[0]))
    surface.blit(img, rect)
    return rect
