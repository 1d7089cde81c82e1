"""Draw a pool table and its balls from a given state (positions, on-table flags, ball numbers).

The renderer holds no physics: it turns metres into pixels and paints. Everything is drawn on plain
``pygame.Surface`` objects with only ``pygame.font`` initialised, so ``rgb_array`` rendering needs no display
or video driver. The static table (rails, cloth, cushions, pockets) is painted once and cached; balls are
pre-rendered shaded sprites (supersampled, so their edges and numbers are anti-aliased) cached per number
and pixel radius, so a frame is one background copy plus a few blits.

Given the balls' orientations (the spin model's animations), each ball is drawn turned (:mod:`.sprites`): its
number disc and stripe, and the cue ball's red dots, roll and spin with it; a ball is redrawn only when its
orientation changed. Given a tip offset, a small cue-ball diagram in the tray shows where the last shot struck
the cue ball. Given a HUD (a game's plain data, :mod:`.hud`), a panel below the tray shows the players, whose turn
it is, the score and the last call, and the table shows the legal target, the kitchen when the cue ball is in
hand behind the head string, and the pockets to call.

Conventions: table origin at a corner, x along the length, y along the width, angles counter-clockwise from
+x. The image shows table y = 0 at the BOTTOM (screen y is flipped).
"""
from __future__ import annotations

import math
import os
from typing import TYPE_CHECKING, Any, Mapping, Sequence

import numpy as np

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
import pygame  # noqa: E402  (after the banner switch)

from billiards_env.physics.aim import ray_cushion_distance  # noqa: E402

from . import colors as C  # noqa: E402
from .paint import (aa_disc, mix, radius_key, scale_colour, smoothstep, surface_from_rgba,  # noqa: E402
                    surface_to_array)
from .hud import draw_panel, panel_height  # noqa: E402
from .overlays import draw_kitchen, draw_pocket_labels, draw_ring, draw_tip_diagram  # noqa: E402
from .sprites import SUPERSAMPLE, OrientedSprites, ball_rgba, shadow_sprite  # noqa: E402,F401

if TYPE_CHECKING:
    from billiards_env.physics.table import Table

# --- geometry of the furniture around the playing area (metres) -------------------------------------------
CUSHION_WIDTH = 0.045  #: cushion nose to the wooden rail
RAIL_WIDTH = 0.115  #: wooden rail, cushion back to outer edge
BORDER = CUSHION_WIDTH + RAIL_WIDTH  #: playing-area edge to image edge
RAIL_CORNER_RADIUS = 0.05  #: rounding of the rail's outer corners
DIAMOND_HALF = (0.010, 0.0055)  #: half-diagonals of a rail sight (along, across the rail)
SPOT_RADIUS = 0.005  #: head and foot spots
#: Cushion shading strips (fraction of the way from nose to rail, brightness): the rubber's rounded top.
CUSHION_PROFILE = ((0.0, 0.10, 0.86), (0.10, 0.22, 1.06), (0.22, 0.40, 1.12), (0.40, 0.65, 1.04),
                   (0.65, 0.88, 0.96), (0.88, 1.0, 0.86))

# --- ball look ------------------------------------------------------------------------------------------
SHADOW_OFFSET = (0.20, 0.26)  #: ball shadow offset on the cloth (ball radii, down-right)
CUE_SHADOW_OFFSET = (0.012, 0.016)  #: cue stick shadow offset (metres, down-right: the cue is higher)

#: Cue stick from the tip backwards: (length m, half-width at start m, half-width at end m, colour).
CUE_SEGMENTS: tuple[tuple[float, float, float, tuple[int, int, int]], ...] = (
    (0.010, 0.0064, 0.0064, (62, 104, 168)),  # chalked tip
    (0.020, 0.0065, 0.0066, (238, 234, 220)),  # ferrule
    (0.700, 0.0066, 0.0100, (226, 198, 150)),  # maple shaft
    (0.012, 0.0104, 0.0104, (200, 200, 206)),  # joint ring
    (0.020, 0.0104, 0.0106, (34, 30, 30)),  # joint collar
    (0.360, 0.0106, 0.0130, (92, 40, 22)),  # forearm
    (0.008, 0.0130, 0.0130, (214, 200, 160)),  # inlay ring
    (0.250, 0.0131, 0.0142, (30, 30, 34)),  # wrap
    (0.008, 0.0142, 0.0142, (214, 200, 160)),  # inlay ring
    (0.100, 0.0142, 0.0148, (104, 46, 24)),  # butt sleeve
    (0.012, 0.0148, 0.0146, (14, 14, 14)),  # bumper
)
CUE_TIP_GAP = 0.030  #: gap between the cue ball's surface and the cue tip (metres)


class TableRenderer:
    """Paints a table and balls into a ``pygame.Surface`` / ``(H, W, 3) uint8`` array.

    ``ball_radius`` is in metres: one value for all balls or one per ball (``(N,)``, matching ``draw``).
    The image is ``width_px`` wide; its height follows the table's aspect ratio plus the rail border, plus a
    tray strip below the table for pocketed balls when ``tray`` is true, plus the game panel when ``hud`` is true
    (frames then need a ``hud`` mapping). ``palette``: the game's plain balls (drawing numbers above 15 mapped to
    ``(r, g, b)``, as its session declares them: snooker's reds and colours, the carom set); balls 0-15 are the
    pool set.
    """

    def __init__(
        self, table: "Table", ball_radius: float | np.ndarray, width_px: int = 800, tray: bool = True,
        hud: bool = False, markings: dict[str, Any] | None = None, palette: C.Palette | None = None,
    ) -> None:
        if int(width_px) < 64:
            raise ValueError(f"width_px must be at least 64, got {width_px!r}")
        radius = np.asarray(ball_radius, dtype=float)
        if radius.ndim > 1 or radius.size == 0 or not np.all(np.isfinite(radius)) or np.any(radius <= 0):
            raise ValueError(f"ball_radius must be a positive number or a 1-D array of them, got {ball_radius!r}")
        if not pygame.font.get_init():
            pygame.font.init()
        self.table = table
        self.ball_radius = radius
        #: The game's plain balls (drawing number -> colour; :mod:`.colors`), as given.
        self.palette = C.check_palette(palette)
        self._palette_items = tuple(sorted(self.palette.items()))
        self.length = float(table.length)
        self.width = float(table.width)
        self.width_px = int(width_px)
        self.pixels_per_metre = self.width_px / (self.length + 2.0 * BORDER)
        self.table_height_px = int(round((self.width + 2.0 * BORDER) * self.pixels_per_metre))
        self._origin = BORDER * self.pixels_per_metre  # pixel coordinate of the playing area's edge
        max_r = float(radius.max()) * self.pixels_per_metre
        self.tray_height_px = int(math.ceil(2.0 * max_r + max(8.0, 1.2 * max_r))) if tray else 0
        self.hud_height_px = panel_height(self.width_px) if hud else 0
        self.height_px = self.table_height_px + self.tray_height_px + self.hud_height_px
        self._sprites: dict[tuple[int, int], tuple[pygame.Surface, int]] = {}
        self._oriented: dict[int, OrientedSprites] = {}
        self._turned: dict[int, tuple[tuple[int, int, bytes], pygame.Surface, int]] = {}  # per ball row
        self._panel_cache: tuple[str, pygame.Surface] | None = None
        self._shadows: dict[int, tuple[pygame.Surface, int]] = {}
        self._overlay: pygame.Surface | None = None
        #: Lines drawn on the cloth, as plain data in metres: ``{"lines": [((x0, y0), (x1, y1)), ...], "arcs":
        #: [(cx, cy, r, start_rad, end_rad), ...]}`` (a snooker table's baulk line and D).
        self.markings = dict(markings or {})
        self._background = self._paint_background()

    # --- coordinates ------------------------------------------------------------------------------------
    @property
    def size(self) -> tuple[int, int]:
        """Image size ``(width, height)`` in pixels."""
        return self.width_px, self.height_px

    @property
    def playing_rect(self) -> pygame.Rect:
        """Pixel rectangle of the playing area (inside the cushion noses)."""
        o = int(round(self._origin))
        return pygame.Rect(o, o, int(round(self.length * self.pixels_per_metre)),
                           int(round(self.width * self.pixels_per_metre)))

    def to_pixels_float(self, xy: np.ndarray) -> np.ndarray:
        """Table points ``(N,2)`` in metres to sub-pixel image coordinates ``(N,2)`` (column, row)."""
        p = np.asarray(xy, dtype=float).reshape(-1, 2)
        col = self._origin + p[:, 0] * self.pixels_per_metre
        row = self._origin + (self.width - p[:, 1]) * self.pixels_per_metre
        return np.stack([col, row], axis=1)

    def to_pixels(self, xy: np.ndarray) -> np.ndarray:
        """Table points ``(N,2)`` in metres to integer pixels ``(N,2)`` as (column, row); y is flipped."""
        return np.rint(self.to_pixels_float(xy)).astype(int)

    def to_table(self, pixel: tuple[float, float] | np.ndarray) -> np.ndarray:
        """Image pixel ``(column, row)`` to the table point ``(x, y)`` in metres (inverse of
        :meth:`to_pixels_float`)."""
        col, row = (float(v) for v in pixel)
        return np.array([(col - self._origin) / self.pixels_per_metre,
                         self.width - (row - self._origin) / self.pixels_per_metre])

    @property
    def tip_diagram(self) -> tuple[tuple[float, float], float]:
        """Centre (px) and radius (px) of the tip-offset diagram: at the right end of the tray (without a tray, in
        the bottom-right corner of the frame)."""
        if self.tray_height_px:
            r = 0.40 * self.tray_height_px
            return (self.width_px - max(self.width_px * 0.03, 2.0 * r) - r,
                    self.table_height_px + 0.5 * self.tray_height_px), r
        r = 0.3 * BORDER * self.pixels_per_metre
        return (self.width_px - 1.6 * r, self.table_height_px - 1.6 * r), r

    @property
    def hud_rect(self) -> pygame.Rect:
        """Pixel rectangle of the game panel (empty without a HUD)."""
        return pygame.Rect(0, self.table_height_px + self.tray_height_px, self.width_px, self.hud_height_px)

    # --- frames -----------------------------------------------------------------------------------------
    def draw(
        self,
        positions: np.ndarray,
        on_table: np.ndarray,
        numbers: Sequence[int],
        cue: tuple[float, float, float] | None = None,
        *,
        orientations: np.ndarray | None = None,
        tip: tuple[float, float] | None = None,
        hud: Mapping[str, Any] | None = None,
    ) -> pygame.Surface:
        """A new surface with the balls on the table, pocketed balls in the tray, and the cue if given.

        ``cue = (x, y, angle)``: the cue ball position (m) and shot direction (radians, CCW from +x) of the
        last shot; an aim line runs from there to the cushion and the stick lies behind the ball.
        ``orientations`` (N, 3, 3): each ball's rotation (body to table frame; the spin model) to draw it turned,
        the cue ball with red dots; None: every ball as at rest. ``tip = (side, top)``: the tip offset of the last
        shot (fractions of R) on a cue-ball diagram in the tray. ``hud``: a game's data for the panel (needs a
        renderer made with ``hud=True``); see :mod:`.hud`.
        """
        pos, flags, nums, radii = self._check_state(positions, on_table, numbers)
        if hud is not None and not self.hud_height_px:
            raise ValueError("hud: this renderer has no panel; make it with TableRenderer(..., hud=True)")
        frame = self._background.copy()
        centres = self.to_pixels(pos)
        radii_px = radii * self.pixels_per_metre
        live = np.flatnonzero(flags)
        cue_radius = float(radii[nums == 0][0]) if np.any(nums == 0) else float(self.ball_radius.max())
        if hud is not None:
            self._draw_table_marks(frame, hud, pos, flags, nums, radii_px)
        if cue is not None:
            self._draw_aim_line(frame, cue, cue_radius)
        for k in live:
            self._blit_shadow(frame, centres[k], radii_px[k])
        if orientations is None:
            for k in live:
                self._blit_ball(frame, nums[k], centres[k], radii_px[k])
        else:
            self._blit_turned(frame, live, nums, centres, radii_px, orientations)
        if cue is not None:
            self._draw_cue_stick(frame, cue, cue_radius)
        if self.tray_height_px:
            self._draw_tray_balls(frame, nums[~flags], radii_px[~flags])
        if tip is not None:
            side, top = (float(v) for v in tip)
            if not (math.isfinite(side) and math.isfinite(top)):
                raise ValueError(f"tip must be two finite numbers (side, top), got {tip!r}")
            centre, r = self.tip_diagram
            draw_tip_diagram(frame, centre, r, side, top)
        if hud is not None:
            frame.blit(self._panel(hud), self.hud_rect.topleft)
        return frame

    def _panel(self, hud: Mapping[str, Any]) -> pygame.Surface:
        """The game panel for ``hud`` (the last one is kept: an animation draws the same panel on every frame)."""
        key = repr(sorted(hud.items()))
        if self._panel_cache is None or self._panel_cache[0] != key:
            rect = self.hud_rect
            panel = pygame.Surface(rect.size)
            draw_panel(panel, pygame.Rect(0, 0, rect.width, rect.height), hud, self._ball_sprite)
            self._panel_cache = (key, panel)
        return self._panel_cache[1]

    def render_array(
        self,
        positions: np.ndarray,
        on_table: np.ndarray,
        numbers: Sequence[int],
        cue: tuple[float, float, float] | None = None,
        **extras: Any,
    ) -> np.ndarray:
        """``draw`` as a contiguous ``(H, W, 3) uint8`` array (rows top to bottom, like an image); ``extras`` are
        ``draw``'s keywords (``orientations``, ``tip``, ``hud``)."""
        return surface_to_array(self.draw(positions, on_table, numbers, cue, **extras))

    def _check_state(
        self, positions: np.ndarray, on_table: np.ndarray, numbers: Sequence[int]
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Validated arrays: positions (N,2), flags (N,) bool, numbers (N,) int, radii (N,) metres."""
        pos = np.asarray(positions, dtype=float)
        if pos.ndim != 2 or pos.shape[1] != 2:
            raise ValueError(f"positions must have shape (N, 2), got {pos.shape}")
        n = len(pos)
        flags = np.asarray(on_table).reshape(-1).astype(bool)
        raw = list(numbers)
        for num in set(raw):
            C.ball_colour(num, self.palette)  # raises on anything but a drawing number (0-15, the palette's)
        nums = np.asarray(raw, dtype=int).reshape(-1)
        if len(flags) != n or len(nums) != n:
            raise ValueError(f"{n} positions but {len(flags)} on_table flags and {len(nums)} numbers")
        if not np.all(np.isfinite(pos[flags])):
            raise ValueError("positions of balls on the table must be finite")
        if self.ball_radius.ndim == 0:
            radii = np.full(n, float(self.ball_radius))
        elif len(self.ball_radius) == n:
            radii = self.ball_radius
        else:
            raise ValueError(f"renderer has {len(self.ball_radius)} ball radii but the state has {n} balls")
        return pos, flags, nums, radii

    # --- balls ------------------------------------------------------------------------------------------
    def _blit_ball(self, frame: pygame.Surface, number: int, centre: np.ndarray, radius_px: float) -> None:
        sprite, half = self._ball_sprite(int(number), radius_px)
        frame.blit(sprite, (int(centre[0]) - half, int(centre[1]) - half))

    def _blit_turned(self, frame: pygame.Surface, live: np.ndarray, nums: np.ndarray, centres: np.ndarray,
                     radii_px: np.ndarray, orientations: np.ndarray) -> None:
        """Balls ``live`` drawn at their orientations: the sprites of balls whose orientation (or number, size)
        changed since the last frame are made in one batch per size, the others reused."""
        rot = np.ascontiguousarray(orientations, dtype=float)
        if rot.shape != (len(nums), 3, 3) or not np.all(np.isfinite(rot[live])):
            raise ValueError(f"orientations must be finite rotation matrices, shape ({len(nums)}, 3, 3), got "
                             f"shape {rot.shape}")
        keys = {int(k): (int(nums[k]), radius_key(radii_px[k]), rot[k].tobytes()) for k in live}
        stale: dict[int, list[int]] = {}
        for k, key in keys.items():
            cached = self._turned.get(k)
            if cached is None or cached[0] != key:
                stale.setdefault(key[1], []).append(k)
        for rk, rows in stale.items():
            if rk not in self._oriented:
                self._oriented[rk] = OrientedSprites(rk / 10.0, palette=self._palette_items)
            maker = self._oriented[rk]
            for k, rgba in zip(rows, maker.rgba(nums[rows], rot[rows])):
                self._turned[k] = (keys[k], surface_from_rgba(rgba), maker.half)
        for k in live:
            _, sprite, half = self._turned[int(k)]
            frame.blit(sprite, (int(centres[k][0]) - half, int(centres[k][1]) - half))

    def _draw_table_marks(self, frame: pygame.Surface, hud: Mapping[str, Any], pos: np.ndarray, flags: np.ndarray,
                          nums: np.ndarray, radii_px: np.ndarray) -> None:
        """The HUD's marks on the table: the kitchen when the cue ball is in hand behind the head string, rings
        around the target balls, and when a pocket must be called the pocket numbers and the called pocket."""
        kitchen_x = hud.get("kitchen_x")
        if kitchen_x is not None:
            draw_kitchen(frame, self.playing_rect, float(self.to_pixels_float(np.array([kitchen_x, 0.0]))[0, 0]))
        targets = {int(n) for n in (hud.get("targets") or ())}
        for k in np.flatnonzero(flags):
            if int(nums[k]) in targets:
                r = radii_px[k]
                draw_ring(frame, self.to_pixels_float(pos[k])[0], 1.5 * r, max(1.5, 0.2 * r))
        if hud.get("call_pocket"):
            pockets = np.asarray(self.table.pocket_xy, dtype=float)
            called = hud.get("called_pocket")
            if called is not None and 0 <= int(called) < len(pockets):
                r = float(self.table.pocket_radius[int(called)]) * self.pixels_per_metre
                draw_ring(frame, self.to_pixels_float(pockets[int(called)])[0], 1.25 * r, max(2.0, 0.15 * r))
            centres, size = self.pocket_label_centres()
            draw_pocket_labels(frame, centres, size)

    def pocket_label_centres(self) -> tuple[np.ndarray, int]:
        """Where the pocket numbers go, ``(centres (n, 2) px, label size px)``: on the rail beside each pocket,
        out of its mouth (corners diagonally outwards; side pockets along the rail, whose far side is the image's
        edge), and inside the table image."""
        pockets = np.asarray(self.table.pocket_xy, dtype=float)
        centre = np.array([self.length / 2.0, self.width / 2.0])
        away = pockets - centre
        away = np.sign(away) * (np.abs(away) > 1e-9)  # corners diagonally
        side = away[:, 0] == 0.0
        away[side] = (1.0, 0.0)  # side pockets: along the rail
        away /= np.maximum(np.linalg.norm(away, axis=1), 1e-12)[:, None]
        size = max(10, int(round(0.42 * BORDER * self.pixels_per_metre)))
        reach = np.asarray(self.table.pocket_radius) * 1.32 * self.pixels_per_metre + 0.62 * size + 1.0
        centres = self.to_pixels_float(pockets) + away * reach[:, None] * np.array([1.0, -1.0])
        r = 0.62 * size + 1.0
        centres[:, 0] = np.clip(centres[:, 0], r, self.width_px - r)
        centres[:, 1] = np.clip(centres[:, 1], r, self.table_height_px - r)
        return centres, size

    def _blit_shadow(self, frame: pygame.Surface, centre: np.ndarray, radius_px: float) -> None:
        key = radius_key(radius_px)
        if key not in self._shadows:
            self._shadows[key] = shadow_sprite(key / 10.0)
        sprite, half = self._shadows[key]
        dx, dy = (round(o * radius_px) for o in SHADOW_OFFSET)
        frame.blit(sprite, (int(centre[0]) - half + dx, int(centre[1]) - half + dy))

    def _ball_sprite(self, number: int, radius_px: float) -> tuple[pygame.Surface, int]:
        """Cached shaded sprite of ball ``number`` and its centre offset (the sprite's middle pixel)."""
        key = (number, radius_key(radius_px))
        if key not in self._sprites:
            rgba = ball_rgba(number, key[1] / 10.0, palette=self._palette_items)
            self._sprites[key] = (surface_from_rgba(rgba), rgba.shape[0] // 2)
        return self._sprites[key]

    def _draw_tray_balls(self, frame: pygame.Surface, numbers: np.ndarray, radii_px: np.ndarray) -> None:
        """Pocketed balls in number order along the tray strip below the table."""
        if len(numbers) == 0:
            return
        order = np.argsort(numbers, kind="stable")
        r = float(radii_px.max())
        row = self.table_height_px + self.tray_height_px // 2
        pad = max(self.width_px * 0.03, r * 2.0)
        step = min(2.0 * r + max(3.0, 0.3 * r), (self.width_px - 2 * pad) / max(len(numbers), 1))
        for i, k in enumerate(order):
            col = int(round(pad + r + i * step))
            self._blit_ball(frame, numbers[k], np.array([col, row]), radii_px[k])

    # --- cue --------------------------------------------------------------------------------------------
    def _cue_geometry(self, cue: tuple[float, float, float]) -> tuple[np.ndarray, np.ndarray]:
        """Sub-pixel start point and unit screen direction (y down) of a cue ``(x, y, angle)``."""
        x, y, angle = (float(v) for v in cue)
        if not all(math.isfinite(v) for v in (x, y, angle)):
            raise ValueError(f"cue must be finite (x, y, angle), got {cue!r}")
        start = self.to_pixels_float(np.array([x, y]))[0]
        return start, np.array([math.cos(angle), -math.sin(angle)])

    def _draw_aim_line(self, frame: pygame.Surface, cue: tuple[float, float, float], radius: float) -> None:
        """A light line from the cue ball's edge along the shot to where its centre would meet a cushion."""
        x, y, angle = (float(v) for v in cue)
        reach = _reach_to_cushion(x, y, angle, radius, self.length, self.width)
        start, direction = self._cue_geometry(cue)
        r_px = radius * self.pixels_per_metre
        length = reach * self.pixels_per_metre
        if length <= r_px + 2:
            return
        colour = mix(C.CLOTH, C.AIM_LINE, 0.55)
        p0 = start + direction * (r_px + 1.5)
        p1 = start + direction * length
        width = max(1, int(round(self.pixels_per_metre * 0.004)))
        pygame.draw.aaline(frame, colour, p0.tolist(), p1.tolist(), width)
        aa_disc(frame, colour, p1, max(1.5, 0.3 * r_px))

    def _draw_cue_stick(self, frame: pygame.Surface, cue: tuple[float, float, float], radius: float) -> None:
        """The cue stick lying behind the cue ball along the shot line, with its shadow on the table."""
        start, direction = self._cue_geometry(cue)
        ppm = self.pixels_per_metre
        back = -direction
        normal = np.array([-back[1], back[0]])
        if normal @ np.array([-1.0, -1.0]) < 0:  # make ``normal`` point to the lit (top-left) side
            normal = -normal
        s = (radius + CUE_TIP_GAP) * ppm
        outline_near, outline_far, pieces = [], [], []
        for length, w0, w1, colour in CUE_SEGMENTS:
            s1 = s + length * ppm
            a, b = start + back * s, start + back * s1
            pieces.append((a, b, w0 * ppm, w1 * ppm, colour))
            outline_near += [a + normal * w0 * ppm, b + normal * w1 * ppm]
            outline_far += [a - normal * w0 * ppm, b - normal * w1 * ppm]
            s = s1
        frame.set_clip(pygame.Rect(0, 0, self.width_px, self.table_height_px))
        shadow = np.array(outline_near + outline_far[::-1]) + np.array(CUE_SHADOW_OFFSET) * ppm
        self._blend_polygon(frame, shadow, (0, 0, 0, 80))
        for a, b, w0, w1, colour in pieces:
            _cylinder_quad(frame, a, b, w0, w1, normal, colour)
        frame.set_clip(None)

    def _blend_polygon(self, frame: pygame.Surface, points: np.ndarray, rgba: tuple[int, int, int, int]) -> None:
        """Fill a polygon with a translucent colour (via a reusable full-frame alpha overlay)."""
        if self._overlay is None:
            self._overlay = pygame.Surface(self.size, pygame.SRCALPHA)
        self._overlay.fill((0, 0, 0, 0))
        pygame.draw.polygon(self._overlay, rgba, points.tolist())
        frame.blit(self._overlay, (0, 0))

    # --- static background ------------------------------------------------------------------------------
    def _paint_background(self) -> pygame.Surface:
        """The table without balls: rails, pocket liners, cloth, cushions, pockets, sights, spots, tray."""
        surface = pygame.Surface(self.size)
        image = np.empty((self.height_px, self.width_px, 3))
        image[:] = C.BACKGROUND
        self._paint_rails(image)
        pygame.surfarray.blit_array(surface, np.clip(np.rint(image), 0, 255).astype(np.uint8).transpose(1, 0, 2))
        self._paint_pocket_liners(surface)
        self._paint_cloth(surface)
        self._paint_markings(surface)
        if self.table.has_jaws:  # pocket circles behind the mouths, then the rails and jaws over their edges
            self._paint_pockets(surface)
            self._paint_jaw_cushions(surface)
        else:
            self._paint_cushions(surface)
            self._paint_pockets(surface)
        self._paint_sights(surface)
        if self.tray_height_px:
            self._paint_tray(surface)
        return surface

    def _paint_markings(self, surface: pygame.Surface) -> None:
        """The chalk lines of :attr:`markings` on the cloth."""
        colour = C.MARKING
        width = max(1, int(round(0.0025 * self.pixels_per_metre)))
        for a, b in self.markings.get("lines", ()):
            p = self.to_pixels_float(np.array([a, b], dtype=float))
            pygame.draw.line(surface, colour, p[0], p[1], width)
        for cx, cy, r, a0, a1 in self.markings.get("arcs", ()):
            n = 48
            t = np.linspace(a0, a1, n)
            pts = self.to_pixels_float(np.column_stack([cx + r * np.cos(t), cy + r * np.sin(t)]))
            pygame.draw.lines(surface, colour, False, [tuple(q) for q in pts], width)

    def _paint_rails(self, image: np.ndarray) -> None:
        """Wooden rails with grain along each rail, mitred corners, rounded outer corners and a soft bevel.

        Only the border ring is computed (the middle is covered by cloth and cushions anyway).
        """
        h, w, ppm = self.table_height_px, self.width_px, self.pixels_per_metre
        ring = int(math.ceil(BORDER * ppm)) + 2
        rows, cols = np.mgrid[0:h, 0:w]
        d_long = np.minimum(rows, h - 1 - rows)
        d_short = np.minimum(cols, w - 1 - cols)
        rows, cols = rows[np.minimum(d_long, d_short) < ring], cols[np.minimum(d_long, d_short) < ring]
        yy, xx = rows + 0.5, cols + 0.5
        d_long, d_short = np.minimum(yy, h - yy), np.minimum(xx, w - xx)  # distances to the outer edges
        long_rail = d_long <= d_short
        along = np.where(long_rail, xx, yy) / ppm
        across = np.where(long_rail, yy, xx) / ppm
        phase = np.where(long_rail, 0.0, 2.1)
        grain = across * 420.0 + 2.2 * np.sin(along * 9.0 + phase) + 0.9 * np.sin(along * 31.0 + across * 60.0)
        streak = (0.5 + 0.5 * np.sin(grain)) ** 4
        noise = np.random.default_rng(11).normal(0.0, 0.015, streak.shape)
        shade = 1.0 - 0.10 * streak + 0.05 * np.sin(along * 3.0 + phase) + noise
        d_out = np.minimum(d_long, d_short) / ppm
        shade *= 0.72 + 0.28 * smoothstep(0.0, 0.014, d_out)  # rounded outer edge
        shade *= 1.0 + 0.10 * np.exp(-((d_out - 0.02) / 0.008) ** 2)  # light catching the top of the rail
        wood = np.array(C.RAIL, dtype=float) * shade[:, None]
        cover = _rounded_rect_coverage(xx, yy, w, h, RAIL_CORNER_RADIUS * ppm)[:, None]
        image[rows, cols] = image[rows, cols] * (1.0 - cover) + wood * cover

    def _paint_pocket_liners(self, surface: pygame.Surface) -> None:
        """Dark leather around each pocket hole, seen on the rail."""
        centres = self.to_pixels_float(self.table.pocket_xy)
        for c, r in zip(centres, np.asarray(self.table.pocket_radius) * self.pixels_per_metre):
            aa_disc(surface, C.RAIL_DARK, c, r * 1.32)
            aa_disc(surface, C.POCKET_LINER, c, r * 1.20)

    def _paint_cloth(self, surface: pygame.Surface) -> None:
        """The cushion band (black where no cushion covers it: pocket throats) and the lit cloth."""
        ppm, o = self.pixels_per_metre, self._origin
        band = (self.table.specs.cushion_width if self.table.has_jaws else CUSHION_WIDTH) * ppm
        outer = pygame.Rect(int(round(o - band)), int(round(o - band)),
                            int(round((self.length * ppm) + 2 * band)), int(round((self.width * ppm) + 2 * band)))
        surface.fill(C.POCKET_LINER, outer)  # what no cushion covers is pocket opening
        rect = self.playing_rect
        u = ((np.arange(rect.w, dtype=np.float32) + 0.5) / rect.w - 0.5) * 2.0
        v = ((np.arange(rect.h, dtype=np.float32) + 0.5) / rect.h - 0.5) * 2.0
        light = 1.06 - 0.07 * (v[:, None] ** 2 + u[None, :] ** 2)  # overhead lamp: brightest in the middle
        light -= 0.06 * np.maximum(np.abs(v)[:, None], np.abs(u)[None, :]) ** 8  # darker toward the cushions
        light += 0.010 * np.random.default_rng(5).standard_normal(light.shape, dtype=np.float32)  # felt
        pixels = np.empty((rect.h, rect.w, 4), np.uint8)
        pixels[..., :3] = np.clip(np.array(C.CLOTH, np.float32) * light[..., None] + 0.5, 0, 255)
        pixels[..., 3] = 255
        surface.blit(surface_from_rgba(pixels), rect.topleft)

    def _paint_cushions(self, surface: pygame.Surface) -> None:
        """Cushions along the four sides, cut at the pockets with angled jaws."""
        for quad in self._cushion_quads():
            pts = self.to_pixels_float(quad)
            pygame.draw.polygon(surface, C.CUSHION, pts.tolist())
            pygame.draw.aalines(surface, C.CUSHION, True, pts.tolist())
            for t0, t1, gain in CUSHION_PROFILE:  # strips from the nose (t=0) back to the rail (t=1)
                strip = [pts[0] + (pts[3] - pts[0]) * t0, pts[1] + (pts[2] - pts[1]) * t0,
                         pts[1] + (pts[2] - pts[1]) * t1, pts[0] + (pts[3] - pts[0]) * t1]
                colour = scale_colour(C.CUSHION, gain)
                pygame.draw.polygon(surface, colour, [p.tolist() for p in strip])
            nose = pts[:2]
            pygame.draw.aaline(surface, mix(C.CUSHION, (0, 0, 0), 0.45), nose[0].tolist(), nose[1].tolist())
            back = pts[2:]
            pygame.draw.aaline(surface, C.RAIL_DARK, back[0].tolist(), back[1].tolist())

    def _paint_jaw_cushions(self, surface: pygame.Surface) -> None:
        """A jaw table's cushions as the solver sees them: each rail with the jaw faces and rounded tips at its
        ends (:meth:`jaw_cushion_polygons`)."""
        for poly in self.jaw_cushion_polygons():
            pts = self.to_pixels_float(poly).tolist()
            pygame.draw.polygon(surface, C.CUSHION, pts)
            pygame.draw.aalines(surface, mix(C.CUSHION, (0, 0, 0), 0.45), True, pts)

    def jaw_cushion_polygons(self, arc_points: int = 8) -> list[np.ndarray]:
        """One polygon (metres) per rail of a jaw table: from the deep end of the jaw face at its start, along the
        face to its tip, round the tip to the rail, along the rail, and back the same way at its other end."""
        segs, tips = self.table.walls()
        rails, jaws = segs[:6], segs[6:]
        polys = []
        for ax, ay, bx, by, nx, ny in rails:
            pts: list[np.ndarray] = []
            for end, other in ((np.array([ax, ay]), np.array([bx, by])), (np.array([bx, by]), np.array([ax, ay]))):
                k = int(np.argmin(np.hypot(tips[:, 0] - end[0], tips[:, 1] - end[1])))
                centre, rad = tips[k, :2], tips[k, 2]
                jaw = jaws[k]
                arc_from = np.arctan2(*(jaw[2:4] - centre)[::-1])
                arc_to = np.arctan2(*(end - centre)[::-1])
                sweep = (arc_to - arc_from + np.pi) % (2 * np.pi) - np.pi  # the short way round
                arc = [centre + rad * np.array([np.cos(arc_from + sweep * q), np.sin(arc_from + sweep * q)])
                       for q in np.linspace(0.0, 1.0, arc_points)]
                side = [jaw[0:2]] + arc
                pts.extend(side if not pts else side[::-1])
            polys.append(np.array(pts))
        return polys

    def _cushion_quads(self) -> list[np.ndarray]:
        """Cushion pieces as (4,2) quads in metres: nose start, nose end, back end, back start."""
        L, W, c = self.length, self.width, CUSHION_WIDTH
        sides = (  # origin of the nose line, unit along, unit outward, side length
            (np.array([0.0, 0.0]), np.array([1.0, 0.0]), np.array([0.0, -1.0]), L),
            (np.array([0.0, W]), np.array([1.0, 0.0]), np.array([0.0, 1.0]), L),
            (np.array([0.0, 0.0]), np.array([0.0, 1.0]), np.array([-1.0, 0.0]), W),
            (np.array([L, 0.0]), np.array([0.0, 1.0]), np.array([1.0, 0.0]), W),
        )
        quads = []
        for origin, along, out, side_len in sides:
            for a, b, ext_a, ext_b in self._cushion_pieces(origin, along, out, side_len):
                quads.append(np.array([
                    origin + along * a, origin + along * b,
                    origin + along * (b + ext_b) + out * c, origin + along * (a - ext_a) + out * c,
                ]))
        return quads

    def _cushion_pieces(
        self, origin: np.ndarray, along: np.ndarray, out: np.ndarray, side_len: float
    ) -> list[tuple[float, float, float, float]]:
        """Intervals ``(a, b, jaw_a, jaw_b)`` of one side's nose line not cut by a pocket.

        A pocket whose capture circle reaches the nose line cuts it; the cushion back reaches ``jaw`` further
        toward that pocket (45 degrees at corner pockets, steeper at side pockets; a mitre at bare corners).
        """
        c = CUSHION_WIDTH
        cuts: list[tuple[float, float, float]] = []
        for p, r in zip(np.asarray(self.table.pocket_xy), np.asarray(self.table.pocket_radius)):
            rel = p - origin
            dist = abs(rel @ out)
            if dist >= r:
                continue
            half = math.sqrt(r * r - dist * dist)
            centre = rel @ along
            corner = min(centre, side_len - centre) < r
            cuts.append((centre - half, centre + half, c if corner else 0.3 * c))
        pieces = []
        start, jaw_start = 0.0, c
        for lo, hi, jaw in sorted(cuts):
            if lo > start:
                pieces.append((start, min(lo, side_len), jaw_start, jaw))
            if hi > start:
                start, jaw_start = hi, jaw
        if start < side_len:
            pieces.append((start, side_len, jaw_start, c))
        return pieces

    def _paint_pockets(self, surface: pygame.Surface) -> None:
        """Pockets as black circles of their capture radius, with a faint rim for depth."""
        centres = self.to_pixels_float(self.table.pocket_xy)
        for c, r in zip(centres, np.asarray(self.table.pocket_radius) * self.pixels_per_metre):
            aa_disc(surface, (14, 14, 14), c, r)
            aa_disc(surface, C.POCKET, c, r - max(1.0, 0.08 * r))

    def _paint_sights(self, surface: pygame.Surface) -> None:
        """Diamond sights on the rails (thirds between pockets) and the head and foot spots on the cloth."""
        L, W = self.length, self.width
        mid = CUSHION_WIDTH + RAIL_WIDTH * 0.5
        ax, ac = DIAMOND_HALF
        marks = [((L * k / 8, -mid), True) for k in (1, 2, 3, 5, 6, 7)]
        marks += [((L * k / 8, W + mid), True) for k in (1, 2, 3, 5, 6, 7)]
        marks += [((-mid, W * k / 4), False) for k in (1, 2, 3)] + [((L + mid, W * k / 4), False) for k in (1, 2, 3)]
        for (x, y), horizontal in marks:
            da, dc = (np.array([ax, 0.0]), np.array([0.0, ac])) if horizontal else (np.array([0.0, ax]),
                                                                                    np.array([ac, 0.0]))
            p = np.array([x, y])
            pts = self.to_pixels_float(np.array([p + da, p + dc, p - da, p - dc])).tolist()
            pygame.draw.polygon(surface, C.DIAMOND, pts)
            pygame.draw.aalines(surface, C.DIAMOND, True, pts)
        spot = mix(C.CLOTH, (0, 0, 0), 0.25)
        for x in (L * 0.25, L * 0.75):
            aa_disc(surface, spot, self.to_pixels_float(np.array([x, W / 2]))[0], SPOT_RADIUS * self.pixels_per_metre)

    def _paint_tray(self, surface: pygame.Surface) -> None:
        """A dark channel below the table that holds pocketed balls."""
        top, h = self.table_height_px, self.tray_height_px
        inset = max(2, h // 8)
        rect = pygame.Rect(inset, top + inset, self.width_px - 2 * inset, h - 2 * inset)
        pygame.draw.rect(surface, C.TRAY, rect, border_radius=max(2, rect.h // 2))
        pygame.draw.rect(surface, mix(C.TRAY, (0, 0, 0), 0.5), rect, width=1, border_radius=max(2, rect.h // 2))


# --- small drawing helpers -------------------------------------------------------------------------------
def _cylinder_quad(
    surface: pygame.Surface, a: np.ndarray, b: np.ndarray, w0: float, w1: float, lit: np.ndarray,
    colour: tuple[int, int, int],
) -> None:
    """One cue segment from ``a`` to ``b`` (half-widths ``w0``, ``w1`` px) shaded as a lit cylinder."""
    bands = ((-1.0, 1.0, 1.0), (-1.0, -0.45, 0.72), (0.15, 0.62, 1.22), (0.28, 0.45, 1.38))
    for lo, hi, gain in bands:
        pts = [a + lit * w0 * lo, b + lit * w1 * lo, b + lit * w1 * hi, a + lit * w0 * hi]
        c = tuple(int(min(255, round(ch * gain))) for ch in colour)
        flat = [p.tolist() for p in pts]
        pygame.draw.polygon(surface, c, flat)
        if lo == -1.0 and hi == 1.0:
            pygame.draw.aalines(surface, c, True, flat)


def _reach_to_cushion(x: float, y: float, angle: float, radius: float, length: float, width: float) -> float:
    """How far a ball of ``radius`` at ``(x, y)`` travels along ``angle`` before it touches a cushion (0 if it is
    already past one): the physics' ray test, with direction components below 1e-12 taken as 0 (along a rail)."""
    dx, dy = math.cos(angle), math.sin(angle)
    reach = ray_cushion_distance(x, y, dx if abs(dx) > 1e-12 else 0.0, dy if abs(dy) > 1e-12 else 0.0,
                                 length, width, radius)
    return reach if math.isfinite(reach) else 0.0


def _rounded_rect_coverage(xx: np.ndarray, yy: np.ndarray, w: float, h: float, radius: float) -> np.ndarray:
    """Approximate pixel coverage (0..1) of a ``w`` x ``h`` rectangle with rounded corners."""
    cx = np.clip(xx, radius, w - radius)
    cy = np.clip(yy, radius, h - radius)
    dist = np.hypot(xx - cx, yy - cy)
    return np.clip(radius - dist + 0.5, 0.0, 1.0)
