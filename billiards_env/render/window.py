"""An on-screen window for ``render_mode="human"``: the only module that opens a display."""
from __future__ import annotations

import os

import numpy as np

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
import pygame  # noqa: E402

#: Unread events kept for ``take_events`` (older ones are dropped so an unread queue cannot grow forever).
_MAX_KEPT_EVENTS = 256


class HumanWindow:
    """A pygame window that shows rendered frames at a steady rate and notices when the user closes it."""

    def __init__(self, size: tuple[int, int], title: str = "billiards_env") -> None:
        self.size = (int(size[0]), int(size[1]))
        if self.size[0] <= 0 or self.size[1] <= 0:
            raise ValueError(f"window size must be positive, got {size!r}")
        pygame.display.init()
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
        """Display a frame (a surface, or an ``(H, W, 3) uint8`` array), then wait to hold ``fps`` if given.

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
