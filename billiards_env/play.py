"""``billiards-play``: play a billiards scene with the mouse.

Aim: move the mouse; the cue and its aim line follow from the cue ball towards the pointer.
Shoot: press the left button, drag away from the press point to set the power (the bar below the table),
release to shoot; the shot animates. Right click (or Esc) while dragging cancels the shot.
Keys: R starts a new episode, Esc / Q (or closing the window) quits.

``--demo`` plays one scripted shot (aim at the target ball, drag, release) from synthetic pygame events and
quits, so the program can be smoke-tested headless (``SDL_VIDEODRIVER=dummy billiards-play --demo``).
Without a display (no DISPLAY/WAYLAND_DISPLAY, pygame's offscreen or dummy video driver) anything but ``--demo``
stops at once with exit status 2 and a hint, instead of playing in a window nobody can see.
"""
from __future__ import annotations

import argparse
import math
import os
import sys
from typing import Any, Iterable, Iterator

import numpy as np

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

#: Drag distance for full power, as a fraction of the table image width.
POWER_DRAG = 0.35
#: Power below which a release cancels the shot instead of playing it.
MIN_POWER = 0.02
PANEL_HEIGHT = 56
PANEL_BG = (28, 28, 32)
TEXT = (226, 226, 220)
BAR_BG = (60, 60, 66)


class PlayApp:
    """The interactive game: an env in ``render_mode="human"`` drawing into this app's pygame window, its
    renderer, a power bar and a status line.

    Drawing of the table and cue comes from :mod:`billiards_env.render` (through ``env.unwrapped.renderer``).
    Shots are animated by the env's own human mode, frame by frame as they are drawn, through a
    :class:`PlayWindow` that adds the panel; between shots the app draws the table with the aiming cue.
    ``run(events)`` takes the events from pygame, or from ``events`` (an iterable of per-frame event lists) for
    scripted, headless runs.

    Without a display the constructor raises :class:`~billiards_env.render.window.HeadlessDisplayError` unless
    ``allow_headless`` (default: the ``BILLIARDS_ALLOW_HEADLESS`` environment variable) is true.
    """

    def __init__(self, env_id: str = "BilliardsOneBall-v0", seed: int | None = None, width: int = 800,
                 speedup: float = 1.0, realtime: bool = True, allow_headless: bool | None = None,
                 **env_kwargs: Any) -> None:
        import gymnasium as gym
        import pygame

        import billiards_env  # noqa: F401  (registers the ids)
        from billiards_env.render.window import require_display

        require_display("billiards-play", "Try `billiards-play --demo` (one scripted shot, no window needed)",
                        allow_headless)
        self.pg = pygame
        self.env_id = env_id
        try:
            self.env = gym.make(env_id, render_mode="human", render_width=width, render_speedup=speedup,
                                **env_kwargs)
        except BaseException:
            pygame.display.quit()
            raise
        self.core = self.env.unwrapped
        self.renderer = self.core.renderer
        self.fps = self.core.config.render_fps
        self.realtime = realtime
        w, h = self.renderer.size
        self.table_size = (w, h)
        pygame.font.init()
        self.screen = pygame.display.set_mode((w, h + PANEL_HEIGHT))
        pygame.display.set_caption(f"billiards-play: {env_id}")
        self.font = pygame.font.Font(None, 22)
        self.clock = pygame.time.Clock()
        # pixel <-> metre mapping from the renderer's own forward map (affine per axis, y flipped)
        p0, p1 = self.renderer.to_pixels_float(np.array([[0.0, 0.0], [1.0, 1.0]]))
        self._px0, self._pscale = p0, p1 - p0
        self.aim = 0.0
        self.dragging = False
        self.press: tuple[int, int] | None = None
        self.power = 0.0
        self.running = True
        self.frames_shown = 0
        self.shots = 0
        self.total = 0.0
        self.done = False
        self.success = False
        self.status = ""
        self.last_info: dict[str, Any] | None = None
        self.core._window = PlayWindow(self)  # the env's human mode shows its frames here (see BilliardsEnv._show)
        self.reset(seed)

    # --- coordinates ------------------------------------------------------------------------------------
    def to_table(self, pixel: tuple[float, float]) -> tuple[float, float]:
        """Window pixel (column, row) to table metres."""
        x = (pixel[0] - self._px0[0]) / self._pscale[0]
        y = (pixel[1] - self._px0[1]) / self._pscale[1]
        return float(x), float(y)

    def ball_pixel(self, row: int) -> tuple[int, int]:
        """Window pixel of ball ``row`` (0 = cue ball)."""
        c, r = self.renderer.to_pixels(self.core.balls.pos[row])[0]
        return int(c), int(r)

    # --- game -------------------------------------------------------------------------------------------
    def reset(self, seed: int | None = None) -> None:
        self.env.reset(seed=seed)
        self.shots, self.total, self.done, self.success = 0, 0.0, False, False
        self.dragging, self.press, self.power = False, None, 0.0
        t = self.core.target_ball()
        if t is not None:
            p = self.core.balls.pos
            self.aim = math.atan2(p[t, 1] - p[0, 1], p[t, 0] - p[0, 0])
        self.status = "aim with the mouse; press, drag and release to shoot"

    def speed(self) -> float:
        c = self.core.config
        return c.speed_min + self.power * (c.speed_max - c.speed_min)

    def shoot(self) -> dict[str, Any]:
        """Play the shot set by ``aim`` and ``power``; the env animates it in the window as it is drawn, with the
        power bar already gone (the click shows at once)."""
        action = self.core.action_from_shot(self.aim, self.speed())
        self.status = f"shot {self.shots + 1}: {self.speed():.2f} m/s ..."
        self.dragging, self.power = False, 0.0  # released: the bar goes, the balls move
        _, reward, terminated, truncated, info = self.env.step(action)
        self.last_info = info
        self.shots += 1
        self.total += float(reward)
        potted = ", ".join(b for b in info["pocketed"] if b != "cue") or "nothing"
        self.status = f"shot {self.shots}: {info['speed']:.2f} m/s, potted {potted}" + (
            ", SCRATCH (cue ball re-spotted)" if info["scratch"] else "") + f", reward {float(reward):+.2f}"
        if terminated or truncated:
            self.done = True
            self.success = bool(info["is_success"])
            self.status += (" - table cleared!" if self.success else " - episode over") + " (R or click: new)"
        return info

    # --- input ------------------------------------------------------------------------------------------
    def handle(self, e: Any) -> None:
        pg = self.pg
        if e.type == pg.QUIT:
            self.running = False
        elif e.type == pg.KEYDOWN:
            if e.key == pg.K_ESCAPE and self.dragging:
                self.dragging, self.power = False, 0.0
            elif e.key in (pg.K_ESCAPE, pg.K_q):
                self.running = False
            elif e.key == pg.K_r:
                self.reset()
        elif e.type == pg.MOUSEBUTTONDOWN:
            if self.done:
                self.reset()
            elif e.button == 1:
                self.set_aim(e.pos)
                self.dragging, self.press, self.power = True, tuple(e.pos), 0.0
            elif e.button == 3 and self.dragging:
                self.dragging, self.power = False, 0.0
        elif e.type == pg.MOUSEMOTION:
            if self.dragging and self.press is not None:
                d = math.hypot(e.pos[0] - self.press[0], e.pos[1] - self.press[1])
                self.power = min(1.0, d / (POWER_DRAG * self.table_size[0]))
            elif not self.done:
                self.set_aim(e.pos)
        elif e.type == pg.MOUSEBUTTONUP and e.button == 1 and self.dragging:
            if self.power >= MIN_POWER:
                self.shoot()
            self.dragging, self.power = False, 0.0

    def set_aim(self, pixel: tuple[int, int]) -> None:
        """Aim from the cue ball towards ``pixel`` (unchanged if the pointer is on the cue ball's centre)."""
        x, y = self.to_table(pixel)
        cx, cy = self.core.balls.pos[0]
        if math.hypot(x - cx, y - cy) > 1e-3:
            self.aim = math.atan2(y - cy, x - cx)

    # --- drawing ----------------------------------------------------------------------------------------
    def draw(self) -> None:
        b = self.core.balls
        cue = None if self.done else (float(b.pos[0, 0]), float(b.pos[0, 1]), self.aim)
        surf = self.renderer.draw(b.pos, b.on_table, self.core.ball_numbers, cue=cue)
        self.screen.blit(surf, (0, 0))
        self.draw_panel()
        self.pg.display.flip()
        self.frames_shown += 1

    def draw_panel(self) -> None:
        pg = self.pg
        w, h = self.table_size
        pg.draw.rect(self.screen, PANEL_BG, pg.Rect(0, h, w, PANEL_HEIGHT))
        bar = pg.Rect(10, h + 8, max(60, w // 3), 16)
        pg.draw.rect(self.screen, BAR_BG, bar, border_radius=4)
        if self.power > 0:
            fill = bar.copy()
            fill.width = max(1, int(bar.width * self.power))
            colour = (int(60 + 195 * self.power), int(200 - 140 * self.power), 60)
            pg.draw.rect(self.screen, colour, fill, border_radius=4)
        label = f"power {self.speed():.2f} m/s" if self.dragging else \
            f"shots {self.shots}/{self.core.config.max_shots}   return {self.total:+.2f}"
        self.screen.blit(self.font.render(label, True, TEXT), (bar.right + 10, bar.top))
        self.screen.blit(self.font.render(self.status, True, TEXT), (10, h + 32))

    # --- loop -------------------------------------------------------------------------------------------
    def run(self, events: Iterable[list[Any]] | None = None, max_frames: int | None = None) -> dict[str, Any]:
        """Run until quit (or until ``events`` is exhausted, or after ``max_frames`` frames). Returns a summary."""
        pg = self.pg
        source: Iterator[list[Any]] | None = iter(events) if events is not None else None
        try:
            while self.running:
                if source is None:
                    batch = pg.event.get()
                else:
                    batch = next(source, None)
                    if batch is None:
                        break
                for e in batch:
                    self.handle(e)
                    if not self.running:
                        break
                if not self.running:
                    break
                self.draw()
                if max_frames is not None and self.frames_shown >= max_frames:
                    break
                if self.realtime:
                    self.clock.tick(self.fps)
        finally:
            self.close()
        return {"shots": self.shots, "return": self.total, "done": self.done, "is_success": self.success,
                "frames_shown": self.frames_shown}

    def close(self) -> None:
        self.env.close()
        self.pg.display.quit()


class PlayWindow:
    """The window of :class:`PlayApp` as the env's human-mode window (``closed``, ``show``, ``close``): each frame
    the env draws is shown at once, with the panel below it, at the env's ``render_fps`` when playing in real
    time. Mouse clicks made while the balls roll are dropped (they would otherwise start a drag or a new episode
    afterwards); closing the window, Esc or Q quits."""

    def __init__(self, app: PlayApp) -> None:
        self.app = app

    @property
    def closed(self) -> bool:
        app = self.app
        pg = app.pg
        if pg.display.get_init():
            for e in pg.event.get((pg.QUIT, pg.KEYDOWN, pg.MOUSEBUTTONDOWN, pg.MOUSEBUTTONUP)):
                if e.type == pg.QUIT or (e.type == pg.KEYDOWN and e.key in (pg.K_ESCAPE, pg.K_q)):
                    app.running = False
        return not app.running

    def show(self, surface: Any, fps: float | None = None) -> None:
        app = self.app
        app.screen.blit(surface, (0, 0))
        app.draw_panel()
        app.pg.display.flip()
        app.frames_shown += 1
        if fps and app.realtime:
            app.clock.tick(fps)

    def close(self) -> None:
        """The app closes the display itself (:meth:`PlayApp.close`)."""


def demo_events(app: PlayApp, power: float = 0.5) -> Iterator[list[Any]]:
    """A scripted shot: point at the target ball, press there, drag ``power`` of full power, release, quit.
    A generator: each step reads the live state, so it works for any scene and seed."""
    pg = app.pg
    t = app.core.target_ball() or 1
    bx, by = app.ball_pixel(t)
    cx, cy = app.ball_pixel(0)
    yield [pg.event.Event(pg.MOUSEMOTION, pos=(bx, by), rel=(0, 0), buttons=(0, 0, 0))]
    yield [pg.event.Event(pg.MOUSEBUTTONDOWN, pos=(bx, by), button=1)]
    n = math.hypot(bx - cx, by - cy) or 1.0
    drag = power * POWER_DRAG * app.table_size[0]
    end = (int(round(bx - (bx - cx) / n * drag)), int(round(by - (by - cy) / n * drag)))
    yield [pg.event.Event(pg.MOUSEMOTION, pos=end, rel=(0, 0), buttons=(1, 0, 0))]
    yield [pg.event.Event(pg.MOUSEBUTTONUP, pos=end, button=1)]
    yield [pg.event.Event(pg.QUIT)]


def build_parser() -> argparse.ArgumentParser:
    from billiards_env.registration import ENV_IDS

    p = argparse.ArgumentParser(prog="billiards-play", description=__doc__.split("\n\n")[0].split(": ", 1)[1],
                                epilog=__doc__.split("\n\n", 1)[1],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--env", default="BilliardsOneBall-v0", choices=list(ENV_IDS), help="scene to play")
    p.add_argument("--seed", type=int, default=None, help="seed of the first episode (default: random)")
    p.add_argument("--width", type=int, default=1000, help="window width in pixels")
    p.add_argument("--speedup", type=float, default=2.0,
                   help="animation playback speed (simulated seconds per second; 1 = real time)")
    p.add_argument("--config", default=None, help="a YAML file of env config keys layered over the scene's")
    p.add_argument("--demo", action="store_true",
                   help="play one scripted shot from synthetic events, print a summary and quit (headless test)")
    return p


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    kwargs = {"config": args.config} if args.config else {}
    from billiards_env.render.window import HeadlessDisplayError

    try:
        app = PlayApp(args.env, seed=args.seed, width=args.width, speedup=args.speedup,
                      realtime=not args.demo, allow_headless=True if args.demo else None, **kwargs)
    except (ValueError, HeadlessDisplayError) as exc:  # bad config (the message names the key), or no display
        print(f"billiards-play: error: {exc}", file=sys.stderr)
        return 2
    if args.demo:
        summary = app.run(demo_events(app))
        print(f"billiards-play demo: {summary}")
        return 0 if summary["shots"] == 1 else 1
    app.run()
    return 0


if __name__ == "__main__":
    sys.exit(main())
