"""An on-screen window for ``render_mode="human"``: the only module that opens a display.

Without a display (no ``DISPLAY``/``WAYLAND_DISPLAY`` on Linux) pygame quietly falls back to its ``offscreen``
video driver: a "window" then opens without error, shows nothing and the program waits on it invisibly.
:func:`require_display` turns that into a clear :class:`HeadlessDisplayError`. A headless driver the user chose
(``SDL_VIDEODRIVER=dummy`` or ``offscreen``, how pygame programs run in CI) is a different case: the env's human
mode then draws into the invisible window, as Gymnasium's own pygame envs do, so ``gymnasium``'s ``check_env``
runs headless with no project variable. ``billiards-play`` (an interactive window) refuses every invisible
display; ``BILLIARDS_ALLOW_HEADLESS=1`` (or ``allow_headless=True``) accepts one anyway (its tests).
"""
from __future__ import annotations

import os
import sys

import numpy as np

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
import pygame  # noqa: E402

#: SDL video drivers that draw into memory and show nothing.
HEADLESS_DRIVERS = ("offscreen", "dummy")
#: Environment variable that allows an invisible window (``1``/``true``/``yes``) where there is no display.
ALLOW_HEADLESS_ENV = "BILLIARDS_ALLOW_HEADLESS"


class HeadlessDisplayError(RuntimeError):
    """A window was asked for where none can be shown (no display); the message says what to do instead."""


def headless_allowed() -> bool:
    """True if ``BILLIARDS_ALLOW_HEADLESS`` is set to 1/true/yes (an invisible window is then accepted)."""
    return os.environ.get(ALLOW_HEADLESS_ENV, "").strip().lower() in ("1", "true", "yes")


def chosen_driver() -> str:
    """The video driver the user chose with ``SDL_VIDEODRIVER`` (lower case), or ``""`` if none."""
    return os.environ.get("SDL_VIDEODRIVER", "").strip().lower()


def _x11_only() -> bool:
    """Linux with an X display, no Wayland display and no driver chosen: SDL would still probe Wayland first,
    which prints ``error: XDG_RUNTIME_DIR is invalid or not set`` where that variable is missing (ssh -X, a
    container): a stray line on every start of a window."""
    return (sys.platform.startswith("linux") and not chosen_driver() and bool(os.environ.get("DISPLAY"))
            and not os.environ.get("WAYLAND_DISPLAY"))


def init_display() -> bool:
    """``pygame.display.init()``, asking SDL for X11 straight away on an X11-only Linux session (no stray Wayland
    message; the variable is set for the call only, so it does not count as the user's choice). False if that X
    server does not answer (nothing initialised: SDL would fall back to an invisible ``offscreen`` window)."""
    if pygame.display.get_init():
        return True
    if not _x11_only():
        pygame.display.init()
        return True
    os.environ["SDL_VIDEODRIVER"] = "x11"
    try:
        pygame.display.init()
    except pygame.error:
        return False
    finally:
        os.environ.pop("SDL_VIDEODRIVER", None)
    return True


def headless_reason() -> str | None:
    """Why a window would be invisible here, or None if it can be seen. Initialises pygame's display if needed.

    On Linux with neither ``DISPLAY`` nor ``WAYLAND_DISPLAY`` set (and no ``SDL_VIDEODRIVER`` chosen) there is no
    display to open: the display is not even initialised (SDL would print a stray error and fall back to
    ``offscreen``); with only ``DISPLAY`` set, an X server must answer there. Otherwise the video driver pygame
    picked decides: ``offscreen`` (its silent fallback when no display server answers) and ``dummy`` (chosen by
    hand) show nothing."""
    chosen = chosen_driver()
    if sys.platform.startswith("linux") and not chosen and not pygame.display.get_init() and not (
            os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")):
        return "there is no display: DISPLAY and WAYLAND_DISPLAY are unset"
    if not init_display():
        return f"no X server answered at DISPLAY={os.environ.get('DISPLAY')}"
    driver = pygame.display.get_driver()
    if driver not in HEADLESS_DRIVERS:
        return None
    why = f"SDL_VIDEODRIVER={driver}" if chosen == driver else "no display server answered"
    return f"pygame's video driver is {driver!r} ({why}), so a window would be invisible"


def invisible_by_choice() -> bool:
    """True if pygame's display runs on a headless driver because the user chose it (``SDL_VIDEODRIVER=dummy``
    or ``offscreen``): drawing invisibly is then what was asked for. False before the display is initialised."""
    if not pygame.display.get_init():
        return False
    driver = pygame.display.get_driver()
    return driver in HEADLESS_DRIVERS and chosen_driver() == driver


def require_display(what: str, instead: str, allow_headless: bool | None = None,
                    accept_chosen_driver: bool = False) -> None:
    """Initialise pygame's display, or raise :class:`HeadlessDisplayError` if a window could not be seen.

    ``what`` names the caller (``"render_mode='human'"``), ``instead`` says what to use without a display.
    ``allow_headless`` (default: the ``BILLIARDS_ALLOW_HEADLESS`` variable) accepts any invisible window;
    ``accept_chosen_driver`` accepts one on a headless driver the user chose with ``SDL_VIDEODRIVER`` (the env's
    human mode, as Gymnasium's pygame envs do), but still refuses the silent fallback of a machine with no display.
    """
    if allow_headless is None:
        allow_headless = headless_allowed()
    was_init = pygame.display.get_init()
    reason = None if allow_headless else headless_reason()
    if reason is None or (accept_chosen_driver and invisible_by_choice()):
        if not init_display():  # allowed headless where the X server does not answer: SDL's offscreen fallback
            pygame.display.init()
        return
    if not was_init and pygame.display.get_init():
        pygame.display.quit()
    hint = ("SDL_VIDEODRIVER=dummy draws into an invisible window on purpose (CI)" if accept_chosen_driver else
            f"{ALLOW_HEADLESS_ENV}=1 draws into an invisible window anyway (tests)")
    raise HeadlessDisplayError(
        f"{what} needs a display, but {reason}. {instead}; or run it where a display is available (a desktop "
        f"session, DISPLAY=:0, or a virtual one: xvfb-run); {hint}.")


#: Room a window leaves on the screen's height for a title bar and a task bar (px).
SCREEN_MARGIN = 80
#: The narrowest window :func:`fitted_width` gives (px).
MIN_FIT_WIDTH = 320


def screen_height() -> int | None:
    """The height of the (first) desktop in pixels, or None when no display tells it."""
    try:
        if not pygame.display.get_init():
            pygame.display.init()
        sizes = pygame.display.get_desktop_sizes()
    except pygame.error:
        return None
    return int(sizes[0][1]) if sizes and sizes[0][1] > 0 else None


def fitted_width(width: int, table_height: int, panel_height: int, screen: int | None) -> int:
    """The widest window up to ``width`` that fits a screen ``screen`` px high (less :data:`SCREEN_MARGIN`): the
    table image is ``table_height`` px high at ``width`` and scales with the width; the panel below it
    (``panel_height``) does not. ``width`` when the screen's height is unknown or the window fits; at least
    :data:`MIN_FIT_WIDTH`."""
    if screen is None:
        return width
    room = screen - SCREEN_MARGIN - panel_height
    if table_height <= room:
        return width
    return max(MIN_FIT_WIDTH, min(width, int(width * room / table_height)))


class HumanWindow:
    """A pygame window that shows rendered frames at a steady rate and notices when the user closes it.

    Raises :class:`HeadlessDisplayError` where no window can be seen (see :func:`require_display`): no display and
    no video driver chosen, or pygame's silent ``offscreen`` fallback. A headless driver chosen with
    ``SDL_VIDEODRIVER`` (``dummy``, ``offscreen``) draws invisibly, as asked; so does ``allow_headless`` (default:
    the ``BILLIARDS_ALLOW_HEADLESS`` environment variable).
    """

    def __init__(self, size: tuple[int, int], title: str = "billiards_env", allow_headless: bool | None = None
                 ) -> None:
        self.size = (int(size[0]), int(size[1]))
        if self.size[0] <= 0 or self.size[1] <= 0:
            raise ValueError(f"window size must be positive, got {size!r}")
        require_display("render_mode='human'", "Use render_mode='rgb_array' or 'rgb_array_list' to get frames "
                        "without a display (billiards_env.envs.recording.record_gif writes an episode as a GIF)",
                        allow_headless, accept_chosen_driver=True)
        self._screen = pygame.display.set_mode(self.size)
        pygame.display.set_caption(title)
        self._clock = pygame.time.Clock()
        #: Whether frames are paced at ``fps``: not in an invisible window, where nobody watches the animation.
        self.paced = pygame.display.get_driver() not in HEADLESS_DRIVERS
        self._closed = False

    @property
    def closed(self) -> bool:
        """True once the user has closed the window (or ``close`` was called)."""
        if not self._closed:
            self._pump()
        return self._closed

    def show(self, surface: pygame.Surface | np.ndarray, fps: float | None = None) -> None:
        """Display a frame (a surface, or an ``(H, W, 3) uint8`` array) now, then wait to hold ``fps`` if given
        (not in an invisible window: there the frames go through at once).

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
        if fps and self.paced:
            self._clock.tick(fps)

    def close(self) -> None:
        """Close the window and shut the display down; safe to call more than once."""
        if not self._closed:
            self._closed = True
            pygame.display.quit()

    def _pump(self) -> bool:
        """Drain window events; False (and closes) if the user closed the window."""
        events = pygame.event.get()
        if any(e.type == pygame.QUIT for e in events):
            self.close()
            return False
        return True

    def __enter__(self) -> "HumanWindow":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
