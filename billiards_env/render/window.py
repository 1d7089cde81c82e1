"""An on-screen window for ``render_mode="human"``: the only module that opens a display.

Without a display (no ``DISPLAY``/``WAYLAND_DISPLAY`` on Linux) pygame quietly falls back to its ``offscreen``
video driver (``dummy`` when asked for by ``SDL_VIDEODRIVER``): a "window" then opens without error, shows nothing
and the program waits on it invisibly. :func:`require_display` turns that into a clear :class:`HeadlessDisplayError`;
set ``BILLIARDS_ALLOW_HEADLESS=1`` (or pass ``allow_headless=True``) to draw into an invisible window anyway, as
the tests do to exercise the human-mode code path.
"""
from __future__ import annotations

import os
import sys

import numpy as np

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
import pygame  # noqa: E402

#: Unread events kept for ``take_events`` (older ones are dropped so an unread queue cannot grow forever).
_MAX_KEPT_EVENTS = 256
#: SDL video drivers that draw into memory and show nothing.
HEADLESS_DRIVERS = ("offscreen", "dummy")
#: Environment variable that allows an invisible window (``1``/``true``/``yes``) where there is no display.
ALLOW_HEADLESS_ENV = "BILLIARDS_ALLOW_HEADLESS"


class HeadlessDisplayError(RuntimeError):
    """A window was asked for where none can be shown (no display); the message says what to do instead."""


def headless_allowed() -> bool:
    """True if ``BILLIARDS_ALLOW_HEADLESS`` is set to 1/true/yes (an invisible window is then accepted)."""
    return os.environ.get(ALLOW_HEADLESS_ENV, "").strip().lower() in ("1", "true", "yes")


def headless_reason() -> str | None:
    """Why a window would be invisible here, or None if it can be seen. Initialises pygame's display if needed.

    On Linux with neither ``DISPLAY`` nor ``WAYLAND_DISPLAY`` set (and no ``SDL_VIDEODRIVER`` chosen) there is no
    display to open: the display is not even initialised (SDL would print a stray error and fall back to
    ``offscreen``). Otherwise the video driver pygame picked decides: ``offscreen`` (its silent fallback when no
    display server answers) and ``dummy`` (chosen by hand) show nothing."""
    chosen = os.environ.get("SDL_VIDEODRIVER", "").strip().lower()
    if sys.platform.startswith("linux") and not chosen and not pygame.display.get_init() and not (
            os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")):
        return "there is no display: DISPLAY and WAYLAND_DISPLAY are unset"
    pygame.display.init()
    driver = pygame.display.get_driver()
    if driver not in HEADLESS_DRIVERS:
        return None
    why = f"SDL_VIDEODRIVER={driver}" if chosen == driver else "no display server answered"
    return f"pygame's video driver is {driver!r} ({why}), so a window would be invisible"


def require_display(what: str, instead: str, allow_headless: bool | None = None) -> None:
    """Initialise pygame's display, or raise :class:`HeadlessDisplayError` if a window could not be seen.

    ``what`` names the caller (``"render_mode='human'"``), ``instead`` says what to use without a display.
    ``allow_headless`` (default: the ``BILLIARDS_ALLOW_HEADLESS`` variable) accepts an invisible window.
    """
    if allow_headless is None:
        allow_headless = headless_allowed()
    was_init = pygame.display.get_init()
    reason = None if allow_headless else headless_reason()
    if reason is None:
        pygame.display.init()
        return
    if not was_init and pygame.display.get_init():
        pygame.display.quit()
    raise HeadlessDisplayError(
        f"{what} needs a display, but {reason}. {instead}; or run it where a display is available (a desktop "
        f"session, DISPLAY=:0, or a virtual one: xvfb-run). {ALLOW_HEADLESS_ENV}=1 draws into an invisible "
        "window anyway (tests).")


class HumanWindow:
    """A pygame window that shows rendered frames at a steady rate and notices when the user closes it.

    Raises :class:`HeadlessDisplayError` where no window can be seen (see :func:`require_display`) unless
    ``allow_headless`` (default: the ``BILLIARDS_ALLOW_HEADLESS`` environment variable) is true.
    """

    def __init__(self, size: tuple[int, int], title: str = "billiards_env", allow_headless: bool | None = None
                 ) -> None:
        self.size = (int(size[0]), int(size[1]))
        if self.size[0] <= 0 or self.size[1] <= 0:
            raise ValueError(f"window size must be positive, got {size!r}")
        require_display("render_mode='human'", "Use render_mode='rgb_array' or 'rgb_array_list' to get frames "
                        "without a display (billiards_env.envs.recording.record_gif writes an episode as a GIF)",
                        allow_headless)
        self._screen = pygame.display.set_mode(self.size)
        pygame.display.set_caption(title)
        self._clock = pygame.time.Clock()
        self._closed = False
        self._events: list[pygame.event.Event] = []

    @property
    def closed(self) -> bool:
        """True once the user has closed the window (or ``close`` was called)."""
        if not self._closed:
            self._pump()
        return self._closed

    def show(self, surface: pygame.Surface | np.ndarray, fps: float | None = None) -> None:
        """Display a frame (a surface, or an ``(H, W, 3) uint8`` array) now, then wait to hold ``fps`` if given.

        Frames of another size are scaled to the window. Does nothing once the window is closed.
        """
        if self._closed or not self._pump():
            return
        if isinstance(surface, np.ndarray):
            surface = pygame.surfarray.make_surface(np.ascontiguousarray(surface.transpose(1, 0, 2)))
        if surface.get_size() != self.size:
            surface = pygame.transform.smoothscale(surface.convert(self._screen), self.size)
        self._screen.blit(surface, (0, 0))
        pygame.display.flip()
        if fps:
            self._clock.tick(fps)

    def take_events(self) -> list[pygame.event.Event]:
        """Window events (keys, mouse; not QUIT) received since the last call, for interactive callers."""
        events, self._events = self._events, []
        return events

    def close(self) -> None:
        """Close the window and shut the display down; safe to call more than once."""
        if not self._closed:
            self._closed = True
            pygame.display.quit()

    def _pump(self) -> bool:
        """Drain window events (kept for ``take_events``); False (and closes) if the user closed the window."""
        events = pygame.event.get()
        kept = [e for e in events if e.type != pygame.QUIT]
        self._events = (self._events + kept)[-_MAX_KEPT_EVENTS:]
        if len(kept) != len(events):
            self.close()
            return False
        return True

    def __enter__(self) -> "HumanWindow":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
