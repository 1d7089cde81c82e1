"""Ball sprites: shaded, anti-aliased images of pool balls, at rest (cached per number and size) or turned to any
orientation (the spin model's animations, where the number disc, the stripe and the cue ball's dots roll and spin
with the ball).

Pure numpy on supersampled grids. A sprite is the ball seen from above: each sample has a screen normal
``(u right, v down, z toward the viewer)``; the ball's markings are defined on its body, so a turned ball is the
same picture with each normal first taken into the body frame (``m = Rs^T n``). The markings of all balls of a frame
are computed in one batch (:func:`ball_albedo` on ``(B, P, 3)`` normals), and the orientation-independent shading
of a size is computed once (:class:`OrientedSprites`), so turning a ball costs a few array operations.
"""
from __future__ import annotations

import math
from functools import lru_cache
from typing import Sequence

import numpy as np

from . import colors as C
from .paint import smoothstep, surface_from_rgba

# --- ball sprite look (angles in radians, lengths in ball radii) ------------------------------------------
SUPERSAMPLE = 5  #: sub-samples per pixel side for sprites at rest (anti-aliasing)
ORIENTED_SUPERSAMPLE = 3  #: sub-samples per pixel side for turned sprites (drawn every frame: cheaper)
DISC_ANGLE = math.radians(27.0)  #: angular radius of the number disc on the sphere
DISC_TILT = math.radians(41.0)  #: how far the number disc is turned away from the viewer (keeps the centre free)
STRIPE_HALF_ANGLE = math.radians(33.0)  #: half-width of a stripe band, as an angle
FLAT_CORE = 0.42  #: radius (in ball radii) inside which shading leaves the main colour untouched
HIGHLIGHT_AT = (-0.36, -0.40)  #: specular highlight centre (screen x right, y down): light from the top left
HIGHLIGHT_SIGMA = 0.10
GOLDEN_ANGLE = math.radians(137.50776)  #: spreads the ball orientations so the rack looks natural
#: The cue ball's markers under the spin model: six red dots on the ends of three perpendicular axes (a
#: "measles" training ball), angular radius and colour. The axes are tilted so none faces the viewer at rest.
DOT_ANGLE = math.radians(13.0)
DOT_COLOUR: C.RGB = (196, 30, 36)
_DOT_TILT = (math.radians(35.0), math.radians(25.0))

#: Table frame (x right, y up, z up toward the viewer) to sprite frame (u right, v down, z toward the viewer).
_FLIP = np.array([1.0, -1.0, 1.0])


def ball_rgba(number: int, radius_px: float, supersample: int = SUPERSAMPLE,
              palette: tuple[tuple[int, C.RGB], ...] = ()) -> np.ndarray:
    """A shaded, anti-aliased ``(S, S, 4) uint8`` sprite of ball ``number`` at rest; the centre is pixel ``S//2``.
    ``palette``: the game's plain balls as ``(number, colour)`` pairs.

    Shading (rim darkening, a highlight to the top left) and the number disc stay outside a central core,
    so the centre pixel is the ball's main colour exactly (also enforced for tiny radii).
    """
    half = int(math.ceil(radius_px)) + 1
    size = 2 * half + 1
    coords = (np.arange(size * supersample) + 0.5) / supersample - (half + 0.5)
    v, u = np.meshgrid(coords / radius_px, coords / radius_px, indexing="ij")  # u right, v down, in radii
    r2 = u * u + v * v
    inside = r2 <= 1.0
    nz = np.sqrt(np.clip(1.0 - r2, 0.0, 1.0))
    normal = np.stack([u, v, nz], axis=-1)
    colour = ball_albedo([number], normal.reshape(-1, 3), palette=palette)[0].reshape(normal.shape)
    colour = _shade(colour, u, v, np.sqrt(r2))
    w = inside.astype(float)
    block = (size, supersample, size, supersample)
    cover = w.reshape(block).mean(axis=(1, 3))
    summed = (colour * w[..., None]).reshape(block + (3,)).sum(axis=(1, 3))
    rgb = summed / np.maximum(cover * supersample * supersample, 1e-9)[..., None]
    rgba = np.dstack([np.clip(np.rint(rgb), 0, 255), np.rint(cover * 255)]).astype(np.uint8)
    rgba[half, half] = (*C.ball_colour(number, dict(palette)), 255)
    return rgba


class _Markings:
    """The markings of the 16 pool balls and a game's plain balls (``palette``: ``(number, colour)`` pairs) as
    arrays indexed by ball number (built once per palette)."""

    def __init__(self, palette: tuple[tuple[int, C.RGB], ...] = ()) -> None:
        colours = dict(palette)
        n = max([C.MAX_BALL_NUMBER, *colours]) + 1  # the plain balls (16..) keep a zero disc axis: no disc, number
        known = [k for k in range(n) if k <= C.MAX_BALL_NUMBER or k in colours]
        self.main = np.zeros((n, 3))
        self.main[known] = [C.ball_colour(k, colours) for k in known]
        self.stripe = np.array([9 <= k <= C.MAX_BALL_NUMBER for k in range(n)])
        self.disc_dir = np.zeros((n, 3))
        self.band_axis = np.zeros((n, 3))
        self.e1 = np.zeros((n, 3))
        self.e2 = np.zeros((n, 3))
        self.scale = np.ones(n)
        self.gh = np.zeros(n, dtype=int)
        self.gw = np.zeros(n, dtype=int)
        numbered = range(1, C.MAX_BALL_NUMBER + 1)
        glyphs = {k: _glyph(str(k)) for k in numbered}
        gh_max = max(g.shape[0] for g in glyphs.values())
        gw_max = max(g.shape[1] for g in glyphs.values())
        self.atlas = np.zeros((n, gh_max, gw_max))
        disc_r = math.sin(DISC_ANGLE)
        for k in numbered:
            phi = k * GOLDEN_ANGLE + 0.35
            toward = np.array([math.cos(phi), math.sin(phi), 0.0])  # screen direction the disc is turned to
            disc = np.array([toward[0] * math.sin(DISC_TILT), toward[1] * math.sin(DISC_TILT), math.cos(DISC_TILT)])
            self.disc_dir[k] = disc
            self.band_axis[k] = np.array([-toward[1], toward[0], 0.0])  # the band runs through the disc
            e1 = np.array([1.0, 0.0, 0.0]) - disc[0] * disc  # screen-right projected onto the disc plane
            e1 /= np.linalg.norm(e1)
            self.e1[k] = e1
            self.e2[k] = np.cross(disc, e1)  # points screen-down, like glyph rows
            g = glyphs[k]
            gh, gw = g.shape
            self.gh[k], self.gw[k] = gh, gw
            self.scale[k] = min(1.10 * disc_r / gh, 1.45 * disc_r / gw)  # sphere units per glyph pixel
            self.atlas[k, :gh, :gw] = g
        #: per ball, the columns band axis, disc axis, glyph right, glyph down: ``normal @ frames`` (B, P, 4)
        self.frames = np.stack([self.band_axis, self.disc_dir, self.e1, self.e2], axis=-1)
        tx, tz = _DOT_TILT
        rx = np.array([[1.0, 0.0, 0.0], [0.0, math.cos(tx), -math.sin(tx)], [0.0, math.sin(tx), math.cos(tx)]])
        rz = np.array([[math.cos(tz), -math.sin(tz), 0.0], [math.sin(tz), math.cos(tz), 0.0], [0.0, 0.0, 1.0]])
        axes = (rz @ rx).T  # rows: three perpendicular unit axes
        self.dots = np.concatenate([axes, -axes])  # (6, 3)


@lru_cache(maxsize=8)
def _markings(palette: tuple[tuple[int, C.RGB], ...] = ()) -> _Markings:
    return _Markings(palette)


def ball_albedo(numbers: Sequence[int], normal: np.ndarray, turn: np.ndarray | None = None,
                cue_dots: bool = False, palette: tuple[tuple[int, C.RGB], ...] = ()) -> np.ndarray:
    """Surface colours ``(B, P, 3)`` (0-255 floats) of balls ``numbers`` (B,) seen at screen normals ``(P, 3)``
    (unit vectors, sprite frame), each ball turned by ``turn`` (``(B, 3, 3)`` rotations in the sprite frame, body
    to screen; None: as at rest): the body colour, the stripe band (9-15), the number disc and its printed number
    (mapped onto the tilted disc so it foreshortens with it), and with ``cue_dots`` the cue ball's six red dots.

    A body-frame direction ``a`` is seen along ``R a``, so each sample's coordinate along it is ``n . (R a)``:
    the few axes are turned, not the many normals. ``palette``: the game's plain balls, ``(number, colour)``
    pairs."""
    mk = _markings(palette)
    nums = np.asarray(numbers, dtype=int).reshape(-1)
    axes = mk.frames[nums] if turn is None else np.matmul(turn, mk.frames[nums])  # (B, 3, 4)
    # each sample's coordinates along the band axis, the disc axis and the glyph's two axes
    dots = np.matmul(normal[None], axes)  # (B, P, 4)
    kind = (np.abs(dots[..., 0]) >= math.sin(STRIPE_HALF_ANGLE)) & mk.stripe[nums][:, None]  # 1: stripe white
    in_disc = dots[..., 1] > math.cos(DISC_ANGLE)  # the cue ball's disc axis is 0: never
    kind = np.where(in_disc, 2, kind.astype(np.int8))  # 2: number disc
    if cue_dots and np.any(nums == 0):
        cues = np.flatnonzero(nums == 0)
        dot_axes = mk.dots.T[None] if turn is None else np.matmul(turn[cues], mk.dots.T[None])
        near = np.matmul(normal[None], dot_axes).max(axis=-1) > math.cos(DOT_ANGLE)
        kind[cues] = np.where(near, 3, kind[cues])  # 3: a red dot
    palette = np.empty((len(nums), 4, 3))
    palette[:, 0] = mk.main[nums]
    palette[:, 1] = C.STRIPE_WHITE
    palette[:, 2] = C.NUMBER_DISC
    palette[:, 3] = DOT_COLOUR
    colour = palette[np.arange(len(nums))[:, None], kind]
    # the printed number: ink coverage from the ball's glyph, on the disc samples only
    b, p = np.nonzero(in_disc)
    k = nums[b]
    col = np.floor(dots[b, p, 2] / mk.scale[k] + mk.gw[k] / 2.0).astype(int)
    row = np.floor(dots[b, p, 3] / mk.scale[k] + mk.gh[k] / 2.0).astype(int)
    ok = (col >= 0) & (col < mk.gw[k]) & (row >= 0) & (row < mk.gh[k])
    b, p = b[ok], p[ok]
    ink = mk.atlas[k[ok], row[ok], col[ok]][:, None]
    colour[b, p] = colour[b, p] * (1.0 - ink) + np.array(C.NUMBER_INK, dtype=float) * ink
    return colour


def _glyph(text: str) -> np.ndarray:
    """High-resolution ink mask (rows, cols) in 0..1 of ``text`` in pygame's default bold font, cropped."""
    import pygame

    if not pygame.font.get_init():
        pygame.font.init()
    surf = pygame.font.Font(None, 120).render(text, True, (255, 255, 255))
    alpha = pygame.surfarray.array_alpha(surf).T.astype(float) / 255.0
    rows, cols = np.flatnonzero(alpha.any(axis=1)), np.flatnonzero(alpha.any(axis=0))
    return alpha[rows[0]:rows[-1] + 1, cols[0]:cols[-1] + 1]


def _shade(colour: np.ndarray, u: np.ndarray, v: np.ndarray, r: np.ndarray) -> np.ndarray:
    """Sphere shading that leaves the core (r < FLAT_CORE) untouched: rim darkening, a darker lower-right
    side, a soft specular highlight at the top left and a faint cloth-green bounce light on the lower rim."""
    rim = smoothstep(FLAT_CORE, 1.02, r)
    away = np.clip((u + v) * 0.7071, 0.0, 1.0)  # toward the lower right, away from the light
    shade = 1.0 - 0.30 * rim**1.6 - 0.22 * rim * away
    out = colour * shade[..., None]
    bounce = (rim**3 * away * 0.10)[..., None]
    out = out * (1.0 - bounce) + np.array(C.CLOTH, dtype=float) * bounce
    hx, hy = HIGHLIGHT_AT
    spec = np.exp(-((u - hx) ** 2 + (v - hy) ** 2) / (2.0 * HIGHLIGHT_SIGMA**2))
    spec = np.where(r < FLAT_CORE * 0.6, 0.0, spec)  # the core keeps the main colour
    return out + (255.0 - out) * (0.85 * spec)[..., None]


def _shading_terms(u: np.ndarray, v: np.ndarray, r: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """:func:`_shade` as ``albedo * gain + base`` (it is linear in the albedo): ``gain`` (...,) and ``base``
    (..., 3), so a turned sprite reuses the shading of its size."""
    rim = smoothstep(FLAT_CORE, 1.02, r)
    away = np.clip((u + v) * 0.7071, 0.0, 1.0)
    shade = 1.0 - 0.30 * rim**1.6 - 0.22 * rim * away
    bounce = rim**3 * away * 0.10
    hx, hy = HIGHLIGHT_AT
    spec = np.exp(-((u - hx) ** 2 + (v - hy) ** 2) / (2.0 * HIGHLIGHT_SIGMA**2))
    spec = 0.85 * np.where(r < FLAT_CORE * 0.6, 0.0, spec)
    gain = shade * (1.0 - bounce) * (1.0 - spec)
    base = (np.array(C.CLOTH, dtype=float) * (bounce * (1.0 - spec))[..., None]) + (255.0 * spec)[..., None]
    return gain, base


class OrientedSprites:
    """Sprites of balls of one pixel radius turned to any orientation, drawn in batches.

    The samples inside the ball (grouped by pixel), their shading and each pixel's coverage are computed once;
    :meth:`rgba` colours the samples of a batch of turned balls (:func:`ball_albedo`) and sums them per pixel.
    Orientations are rotation matrices in the table frame (x right, y up, z up toward the viewer), body to table;
    the identity is the ball as drawn at rest.
    """

    def __init__(self, radius_px: float, supersample: int = ORIENTED_SUPERSAMPLE,
                 palette: tuple[tuple[int, C.RGB], ...] = ()) -> None:
        self.palette = tuple(palette)
        self.radius_px = float(radius_px)
        self.supersample = ss = int(supersample)
        self.half = half = int(math.ceil(radius_px)) + 1
        self.size = size = 2 * half + 1
        coords = (np.arange(size * ss) + 0.5) / ss - (half + 0.5)
        v, u = np.meshgrid(coords / radius_px, coords / radius_px, indexing="ij")
        r2 = u * u + v * v
        inside = r2 <= 1.0
        pixel = (np.arange(size * ss)[:, None] // ss) * size + np.arange(size * ss)[None, :] // ss
        order = np.argsort(pixel[inside], kind="stable")  # the samples inside, grouped by pixel
        nz = np.sqrt(np.clip(1.0 - r2, 0.0, 1.0))
        self._normal = np.stack([u, v, nz], axis=-1)[inside][order]
        gain, base = _shading_terms(u, v, np.sqrt(r2))
        self._gain = gain[inside][order][:, None]
        self._base = base[inside][order]
        px = pixel[inside][order]
        self._starts = np.flatnonzero(np.r_[True, px[1:] != px[:-1]])
        self._pixels = px[self._starts]
        cover = inside.astype(float).reshape(size, ss, size, ss).mean(axis=(1, 3)).reshape(-1)
        self._norm = (cover[self._pixels] * ss * ss)[:, None]
        self._alpha = np.rint(cover * 255).astype(np.uint8)

    def rgba(self, numbers: Sequence[int], orientations: np.ndarray, cue_dots: bool = True) -> np.ndarray:
        """``(B, S, S, 4) uint8`` sprites of balls ``numbers`` (B,) at ``orientations`` (B, 3, 3)."""
        turn = np.asarray(orientations, dtype=float).reshape(-1, 3, 3) * _FLIP[None, :, None] * _FLIP[None, None, :]
        colour = ball_albedo(numbers, self._normal, turn, cue_dots, self.palette) * self._gain[None] + \
            self._base[None]
        n, s = len(turn), self.size
        rgb = np.zeros((n, s * s, 3))
        rgb[:, self._pixels] = np.add.reduceat(colour, self._starts, axis=1) / self._norm[None]
        out = np.empty((n, s * s, 4), np.uint8)
        out[..., :3] = np.clip(np.rint(rgb), 0, 255)
        out[..., 3] = self._alpha[None]
        return out.reshape(n, s, s, 4)


def shadow_sprite(radius_px: float) -> tuple["pygame.Surface", int]:  # noqa: F821
    """Soft translucent black disc (the ball's shadow on the cloth) and its centre offset."""
    half = int(math.ceil(radius_px * 1.35)) + 1
    yy, xx = np.mgrid[-half:half + 1, -half:half + 1].astype(float)
    d = np.hypot(xx, yy) / radius_px
    alpha = 105.0 * (1.0 - smoothstep(0.55, 1.25, d))
    rgba = np.zeros(d.shape + (4,), np.uint8)
    rgba[..., 3] = np.rint(alpha).astype(np.uint8)
    return surface_from_rgba(rgba), half


__all__ = ["ball_rgba", "ball_albedo", "OrientedSprites", "shadow_sprite", "SUPERSAMPLE", "ORIENTED_SUPERSAMPLE"]
