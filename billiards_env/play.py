"""``billiards-play``: play a billiards scene, or a game (any of the game registry's), with the mouse.

Aim: move the mouse; the cue and its aim line follow from the cue ball towards the pointer.
Shoot: press the left button, drag away from the press point to set the power (the bar below the table),
release to shoot; the shot animates. Right click (or Esc) while dragging cancels the shot.
Ball in hand (games): drag the cue ball, or click (or right-click) where to put it; a spot that is not allowed
(outside the kitchen on a break, on another ball) moves to the nearest legal point.
The 8 (8-ball): when you are on the 8, call its pocket: click the pocket, or press 1-6 (the numbers on the rail).
Spin (--spin): the arrow keys move the cue tip on the cue-ball diagram (right of the power bar), or click the
diagram; C centres it.
A drag too short to shoot says so (drag further from the press point). Space (or S) skips the rest of the
animation (e.g. the opponent's reply).
Keys: R starts a new episode (a new game), Esc / Q (or closing the window) quits. The turn log under a game's
panel scrolls: mouse wheel, Page Up / Page Down, Home (the first shot) / End (the newest).

Games: --env Billiards9Ball-v0, Billiards8Ball-v0, BilliardsSnooker-v0, BilliardsThreeCushion-v0 or
BilliardsStraightPool-v0. Snooker: the cue ball starts in hand in the D (drag it there); pot a red, then a colour;
the log names the balls potted and their points, a foul the points it gives away. Three-cushion: no pockets and no
ball in hand; you play the white, the opponent the yellow; a point needs both other balls met and three cushions
before the second; the log gives the point (or not) and the cushions of every shot. Straight pool: every shot calls
a ball and a pocket: the ball is the one you aim at, the pocket the one you click (or press 1-6) before shooting.
--opponent geometric|search|random plays against a baseline player (its shots animate after yours),
--opponent human lets two people play at one window, taking turns. The break alternates between the players from
game to game (you break the first; --breaker you|opponent|random chooses otherwise). The panel under the table
shows whose turn it is, the groups, ball in hand, the last call and the score; below it, the turn log gives each
shot of the game in words (the referee's call, and why a turn passed).

``--demo`` plays a scripted turn (aim at the target ball, drag, release; in a game: place the cue ball, break,
and shoot until the opponent has replied) from synthetic pygame events and quits, so the program can be
smoke-tested headless (``SDL_VIDEODRIVER=dummy billiards-play --demo --env Billiards9Ball-v0``).
Without a display (no DISPLAY/WAYLAND_DISPLAY, pygame's offscreen or dummy video driver) anything but ``--demo``
stops at once with exit status 2 and a hint, instead of playing in a window nobody can see.
"""
from __future__ import annotations

import argparse
import dataclasses
import math
import os
import sys
from typing import Any, Iterable, Iterator

import numpy as np

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

#: Drag distance for full power, as a fraction of the table image width.
POWER_DRAG = 0.35
#: Power below which a release cancels the shot instead of playing it (with ball in hand: puts the cue ball there).
MIN_POWER = 0.02
PANEL_HEIGHT = 56
#: The window's width when none is given, narrowed to fit the screen's height (:func:`~.render.window.fitted_width`).
DEFAULT_WIDTH = 1000
PANEL_BG = (28, 28, 32)
TEXT = (226, 226, 220)
BAR_BG = (60, 60, 66)
#: Step of the arrow keys on the tip offset (fraction of the ball radius).
TIP_STEP = 0.05
#: A press within this many ball radii of the cue ball (with ball in hand) picks it up.
PICK_RADII = 1.8
#: A press within this many pocket radii of a pocket (when the 8 needs a call) calls that pocket.
POCKET_PICK = 1.6
OPPONENTS = ("geometric", "search", "random", "human")
#: Who breaks each game: alternate (you, then the opponent, ...), always you, always the opponent, or drawn.
BREAKERS = ("alternate", "you", "opponent", "random")
#: The turn log under the panel of a game: lines shown and their height (px).
LOG_LINES = 6
LOG_LINE = 18
#: Log lines one notch of the mouse wheel scrolls.
WHEEL_LINES = 2

class PlayApp:
    """The interactive game: an env in ``render_mode="human"`` drawing into this app's pygame window, its
    renderer, a power bar, a status line and (with spin) the tip diagram.

    Drawing of the table, the cue and a game's panel comes from :mod:`billiards_env.render` (through
    ``env.unwrapped.renderer`` and ``env.unwrapped.render_data()``). Shots are animated by the env's own human
    mode, frame by frame as they are drawn, through a :class:`PlayWindow` that adds the app's panel; between shots
    the app draws the table with the aiming cue. ``run(events)`` takes the events from pygame, or from ``events``
    (an iterable of per-frame event lists) for scripted, headless runs.

    Games: ``opponent`` is a baseline player's name (the env plays its turns inside ``step``; default the env's
    own, ``geometric``) or ``"human"`` (nobody plays automatically: two people take turns). ``spin`` plays with
    the spin model and tip offsets (``friction="spin"``, ``spin_action=True``).

    ``width``: the window's width in pixels; None (the default) is :data:`DEFAULT_WIDTH`, narrowed until the window
    fits the screen's height (a 1366 x 768 laptop gets the whole table and the turn log).

    Without a display the constructor raises :class:`~billiards_env.render.window.HeadlessDisplayError` unless
    ``allow_headless`` (default: the ``BILLIARDS_ALLOW_HEADLESS`` environment variable) is true.
    """

    def __init__(self, env_id: str = "BilliardsOneBall-v0", seed: int | None = None, width: int | None = None,
                 speedup: float = 1.0, realtime: bool = True, allow_headless: bool | None = None,
                 opponent: str | None = None, spin: bool = False, breaker: str = "alternate",
                 **env_kwargs: Any) -> None:
        import gymnasium as gym
        import pygame

        import billiards_env  # noqa: F401  (registers the ids)
        from billiards_env.render.window import fitted_width, require_display, screen_height

        if opponent is not None and opponent not in OPPONENTS:
            raise ValueError(f"opponent: unknown {opponent!r}; use one of {', '.join(OPPONENTS)}")
        if breaker not in BREAKERS:
            raise ValueError(f"breaker: unknown {breaker!r}; use one of {', '.join(BREAKERS)}")
        if spin:
            env_kwargs = {**env_kwargs, "friction": "spin", "spin_action": True}
        if opponent is not None:
            env_kwargs = {**env_kwargs, "opponent": None if opponent == "human" else opponent}
        require_display("billiards-play", "Try `billiards-play --demo` (a scripted turn, no window needed)",
                        allow_headless)
        self.pg = pygame
        self.env_id = env_id
        try:
            self.env = gym.make(env_id, render_mode="human", render_width=width or DEFAULT_WIDTH,
                                render_speedup=speedup, **env_kwargs)
            self.core = self.env.unwrapped
            self.is_game = hasattr(self.core.task, "game_state")
            screen = screen_height() if width is None else None
            for _ in range(3):  # the default width, narrowed until the window fits the screen's height
                w, h = self.core.renderer.size  # (the image's height rounds: a second pass settles it)
                fit = fitted_width(w, h, self._panel_height(), screen)
                if fit >= w:
                    break
                self.env.close()
                self.env = gym.make(env_id, render_mode="human", render_width=fit, render_speedup=speedup,
                                    **env_kwargs)
                self.core = self.env.unwrapped
            if opponent is not None and not self.is_game:
                from billiards_env.games import GAMES

                raise ValueError(f"opponent: {env_id} is not a game; --opponent applies to the games: "
                                 f"{', '.join(g.env_id for g in GAMES.values())}")
        except BaseException:
            pygame.display.quit()
            raise
        self.two_people = opponent == "human"
        from billiards_env.render.turn_log import TurnLog

        self.breaker = breaker
        self.games = 0  # games started (the break alternates with it)
        self.log = TurnLog()
        self._calls: list[Any] = []  # the referee's calls of the shots of the step under way
        self.skipping = False  # Space: the rest of the animation is not shown
        self.too_soft = False
        if self.is_game:
            self._record_calls()
            task = self.core.task
            if self.two_people:
                task.seat.auto = False  # nobody plays inside step: the players take turns at the window
                task.player_names = ("player 1", "player 2")
            else:
                task.player_names = ("you", task.names()[1])
        self.renderer = self.core.renderer
        self.fps = self.core.config.render_fps
        self.realtime = realtime
        w, h = self.renderer.size
        self.table_size = (w, h)
        self.panel_height = self._panel_height()
        pygame.font.init()
        self.screen = pygame.display.set_mode((w, h + self.panel_height))
        pygame.display.set_caption(f"billiards-play: {env_id}")
        self.font = pygame.font.Font(None, 22)
        self.clock = pygame.time.Clock()
        self.spin = bool(self.core.action_type.spin)
        self.max_tip = float(self.core.config.max_tip_offset)
        self.tip = (0.0, 0.0)
        self.aim = 0.0
        self.dragging = False
        self.press: tuple[int, int] | None = None
        self.power = 0.0
        self.place: tuple[float, float] | None = None  # the cue ball's spot while in hand
        self.placing = False  # dragging the cue ball
        self.tip_drag = False
        self.pocket: int | None = None  # the pocket called for the 8
        self.running = True
        self.frames_shown = 0
        self.shots = 0
        self.opponent_shots = 0
        self.total = 0.0
        self.done = False
        self.success = False
        self.status = ""
        self.last_info: dict[str, Any] | None = None
        self.last_action: np.ndarray | None = None
        self.core.attach_window(PlayWindow(self))  # the env's human mode shows its frames here
        self.reset(seed)

    # --- coordinates ------------------------------------------------------------------------------------
    def to_table(self, pixel: tuple[float, float]) -> tuple[float, float]:
        """Window pixel (column, row) to table metres."""
        x, y = self.renderer.to_table(pixel)
        return float(x), float(y)

    def ball_pixel(self, row: int) -> tuple[int, int]:
        """Window pixel of ball ``row`` (0 = cue ball; while in hand, where it is being placed)."""
        xy = self.cue_xy() if row == 0 else self.core.balls.pos[row]
        c, r = self.renderer.to_pixels(np.asarray(xy))[0]
        return int(c), int(r)

    def pocket_pixel(self, k: int) -> tuple[int, int]:
        c, r = self.renderer.to_pixels(self.core.table.pocket_xy[k])[0]
        return int(c), int(r)

    @property
    def tip_diagram(self) -> tuple[tuple[float, float], float]:
        """Centre and radius (px) of the app's tip diagram, at the right end of its panel."""
        w, h = self.table_size
        r = 0.4 * PANEL_HEIGHT
        return (w - r - 10.0, h + PANEL_HEIGHT / 2.0), r

    # --- game -------------------------------------------------------------------------------------------
    def reset(self, seed: int | None = None, options: dict[str, Any] | None = None) -> None:
        """A new episode (a new game): ``env.reset(seed=seed, options=options)``. In a game the breaker follows
        ``breaker`` (alternate: you the first game, the opponent the next...); an opponent's break animates and is
        logged."""
        if self.is_game:
            self._choose_breaker()
            self._calls = []
            self.log.clear()
        won_before = self._opponent_wins()
        _, info = self.env.reset(seed=seed, options=options)
        self.games += 1
        self.shots, self.total, self.done, self.success = 0, 0.0, False, False
        self.opponent_shots = int(info.get("opponent_shots", 0)) if self.is_game else 0
        self.dragging, self.press, self.power = False, None, 0.0
        self.skipping = self.too_soft = False
        if self.is_game:
            names = self._names()
            won = self._opponent_wins() - won_before
            if won > 0:  # the env racks again when the opponent wins from its break, before your first shot
                self.log.note(f"{names[1]} broke and won {won} game{'s' if won > 1 else ''} before your first "
                              "shot; racked again", "win")
            turns = self._opponent_turns(info, self._calls, self._words)
            self.log.add(turns, names)
        self._new_turn()
        base = "aim with the mouse; press, drag and release to shoot"
        if self.is_game and self.opponent_shots:
            names = self._names()
            base = f"{names[1]} broke; {names[self.core.task.game_state.shooter]} to shoot"
        self.status = self._hint(base)

    def _opponent_wins(self) -> int:
        """Games the opponent has won this session (0 outside a game)."""
        score = getattr(getattr(self.core.task, "session", None), "score", None)
        return int(score.wins[1]) if score is not None else 0

    def _choose_breaker(self) -> None:
        """Set who breaks the next game (the env's ``first_shooter``, read at reset) from ``breaker``."""
        who = {"you": "agent", "opponent": "opponent", "random": "random"}.get(self.breaker)
        if who is None:  # alternate: the first game (games == 0) you, then the opponent...
            who = "agent" if self.games % 2 == 0 else "opponent"
        task = self.core.task
        if task.config.first_shooter != who:
            task.config = dataclasses.replace(task.config, first_shooter=who)

    def _record_calls(self) -> None:
        """Keep the referee's call of every shot played inside ``env.step``/``reset`` (the human's and the
        opponent's), for the turn log; the env's ``info["opponent_turns"]`` is used instead where it exists."""
        task = self.core.task
        owner = task if hasattr(task, "judge") else getattr(task, "session", None)  # who judges the shots
        if owner is None or not hasattr(owner, "judge"):
            return  # the env's info alone then (opponent_turns; the human's shot from its own keys)
        judge = owner.judge

        def judge_and_record(*args: Any, **kwargs: Any) -> Any:
            call = judge(*args, **kwargs)
            self._calls.append(call)
            return call

        owner.judge = judge_and_record

    def _names(self) -> tuple[str, str]:
        """The players' names in the log and the panel: the game's (``GameTask.names``), else you and opponent."""
        task = self.core.task
        if hasattr(task, "names"):
            return tuple(task.names())  # type: ignore[return-value]
        return ("you", "opponent")

    @staticmethod
    def _opponent_turns(info: dict[str, Any], calls: list[Any], words: Any) -> list[dict[str, Any]]:
        """The opponent's shots of a step or reset: the referee's calls recorded for them (the last
        ``info["opponent_shots"]`` calls: their game over and winner included), else ``info["opponent_turns"]``
        (with ``opponent_infos``; put in words by ``words``, the env's ``info_words``) with the game's end taken
        from ``info["winner"]``."""
        n = int(info.get("opponent_shots", 0) or 0)
        if n and len(calls) >= n:
            return [call_turn(c) for c in calls[len(calls) - n:]]
        turns = [words(t) for t in info.get("opponent_turns") or ()]
        winner = info.get("winner", -1)
        if turns and winner in (0, 1):  # the game ended on the opponent's last shot
            turns[-1].update(game_over=True, winner=winner)
        return turns

    def _words(self, turn: dict[str, Any]) -> dict[str, Any]:
        """A shot of the env's info (masks over the rows, reason codes) as a turn-log entry (ids, reasons)."""
        return self.core.info_words(turn)

    def _new_turn(self) -> None:
        """Before a shot: pick up the cue ball if in hand, forget the called pocket, aim at the target."""
        self.placing = self.tip_drag = False
        self.pocket = None
        self.place = None
        if self.in_hand():
            x, y = self.core.balls.pos[0]
            self.place = self.core.legal_cue_position(float(x), float(y))
        t = self.core.target_ball()
        if t is not None and not self.done:
            cx, cy = self.cue_xy()
            p = self.core.balls.pos[t]
            self.aim = math.atan2(p[1] - cy, p[0] - cx)

    def in_hand(self) -> bool:
        """The shooter has the cue ball in hand (games)."""
        return not self.done and self.core.table_state.view.place_area is not None

    def needs_pocket(self) -> bool:
        """The shooter must call a pocket (8-ball on the 8; every shot of straight pool, whose called ball is the
        one aimed at)."""
        return not self.done and self.is_game and self.core.table_state.view.call_pocket

    def aimed_ball(self) -> int | None:
        """Row of the first object ball on the cue's line from where the cue ball is (or will be placed), or None:
        the ball a game that calls balls (straight pool) takes as called."""
        from billiards_env.physics.aim import ray_circle_entry

        b = self.core.balls
        cx, cy = self.cue_xy()
        ux, uy = math.cos(self.aim), math.sin(self.aim)
        best, row = math.inf, None
        for k in range(1, len(b.pos)):
            if b.on_table[k]:
                d = ray_circle_entry(cx, cy, ux, uy, float(b.pos[k, 0]), float(b.pos[k, 1]),
                                     float(b.radius[0] + b.radius[k]))
                if math.isfinite(d) and d < best:
                    best, row = d, k
        return row

    def cue_xy(self) -> tuple[float, float]:
        if self.place is not None:
            return self.place
        x, y = self.core.balls.pos[0]
        return float(x), float(y)

    def put_cue_ball(self, pixel: tuple[float, float]) -> None:
        """Ball in hand: put the cue ball at ``pixel`` (the env's nearest legal point)."""
        self.place = self.core.legal_cue_position(*self.to_table(pixel))

    def speed(self) -> float:
        c = self.core.config
        return c.speed_min + self.power * (c.speed_max - c.speed_min)

    def shoot(self) -> dict[str, Any] | None:
        """Play the shot set by ``aim``, ``power``, the tip, the placement and the called pocket; the env animates
        it (and a game's opponent's reply) in the window as it is drawn, with the power bar already gone."""
        if self.needs_pocket() and self.pocket is None:
            self.status = "call the pocket first: click a pocket or press 1-6"
            self.dragging, self.power = False, 0.0
            return None
        side, top = self.tip if self.spin else (0.0, 0.0)
        calls: dict[str, Any] = {"pocket": self.pocket}
        if any(d.name == "ball" for d in self.core.action_type.declarations):  # a called ball: the one aimed at
            calls["ball"] = self.aimed_ball()
        action = self.core.action_from_shot(self.aim, self.speed(), side, top, place=self.place, **calls)
        self.last_action = action
        self.status = f"shot {self.shots + 1}: {self.speed():.2f} m/s ... (Space skips the animation)"
        self.dragging, self.power = False, 0.0  # released: the bar goes, the balls move
        self.place = None
        shooter = int(self.core.task.game_state.shooter) if self.is_game else 0
        self._calls = []
        self.skipping = self.too_soft = False
        try:
            _, reward, terminated, truncated, info = self.env.step(action)
        finally:
            self.skipping = False
        self.last_info = info
        own_line = ""
        if self.is_game:
            from billiards_env.render.turn_log import turn_line

            own = call_turn(self._calls[0]) if self._calls else {**self._words(info), **_info_turn(info, shooter)}
            self.log.add([own] + self._opponent_turns(info, self._calls, self._words), self._names())
            own_line = turn_line(own, self._names())[0].split(": ", 1)[-1]
        self.shots += 1
        self.total += float(reward)
        self.opponent_shots += int(info.get("opponent_shots", 0))
        if terminated or truncated:
            self.done = True
            self.success = bool(info["is_success"])
        self.status = self._game_status(info, own_line) if self.is_game else self._scene_status(info, float(reward))
        self._new_turn()
        return info

    def _scene_status(self, info: dict[str, Any], reward: float) -> str:
        ids = self.core.ball_ids
        potted = ", ".join(ids[i] for i in np.flatnonzero(info["pocketed"]) if i != 0) or "nothing"
        out = f"shot {self.shots}: {info['speed']:.2f} m/s, potted {potted}" + (
            ", SCRATCH (cue ball re-spotted)" if info["scratch"] else "") + f", reward {reward:+.2f}"
        if self.done:
            out += (" - table cleared!" if self.success else " - episode over") + " (R or click: new)"
        return out

    def _game_status(self, info: dict[str, Any], own: str = "") -> str:
        """The status after a shot: its speed and what it did (``own``: its turn-log words, e.g. "no point (2
        cushions) - turn over"), the opponent's reply, who is to shoot or who won."""
        hud = self.core.task.hud()
        names = hud["players"]
        out = f"shot {self.shots}: {info['speed']:.2f} m/s" + (f", {own}" if own else "")
        if self.opponent_shots and info.get("opponent_shots"):
            n = info["opponent_shots"]
            out += f"; {names[1]} played {n} shot{'s' if n > 1 else ''}"
        if self.done:
            winner = hud["winner"]
            result = "no winner" if winner is None else f"{names[winner]} won{'!' if winner == 0 else ''}"
            return f"{out}; {result} (R or click: new game)"
        return self._hint(out + f"; {names[hud['shooter']]} to shoot")

    def _hint(self, base: str) -> str:
        """``base`` with what the shooter must do next: place the cue ball, call the 8's pocket."""
        if self.in_hand():
            base += "; ball in hand: drag it, or click where to put it"
        if self.needs_pocket():
            base += "; call the pocket (click it or press 1-6)"
        return base

    # --- input ------------------------------------------------------------------------------------------
    def handle(self, e: Any) -> None:
        pg = self.pg
        if e.type == pg.QUIT:
            self.running = False
        elif e.type == pg.KEYDOWN:
            self._key(e)
        elif e.type == pg.MOUSEWHEEL:
            self.log.scroll(WHEEL_LINES * int(e.y))  # wheel up: older lines
        elif e.type == pg.MOUSEBUTTONDOWN:
            if e.button in (4, 5):  # the wheel as buttons (older SDL): MOUSEWHEEL scrolls
                return
            if self.done:
                self.reset()
            elif e.button == 1:
                self._press(e.pos)
            elif e.button == 3:
                if self.dragging:
                    self.dragging, self.power = False, 0.0
                elif self.in_hand():
                    self.put_cue_ball(e.pos)
        elif e.type == pg.MOUSEMOTION:
            if self.placing:
                self.put_cue_ball(e.pos)
            elif self.tip_drag:
                self.set_tip_at(e.pos)
            elif self.dragging and self.press is not None:
                d = math.hypot(e.pos[0] - self.press[0], e.pos[1] - self.press[1])
                self.power = min(1.0, d / (POWER_DRAG * self.table_size[0]))
            elif not self.done:
                self.set_aim(e.pos)
        elif e.type == pg.MOUSEBUTTONUP and e.button == 1:
            if self.placing or self.tip_drag:
                self.placing = self.tip_drag = False
            elif self.dragging:
                if self.power >= MIN_POWER:
                    self.shoot()
                elif self.in_hand():  # a click, not a drag: put the cue ball there
                    self.put_cue_ball(e.pos)
                    self.status = self._hint("cue ball placed; press and drag away to shoot")
                else:
                    px = int(math.ceil(MIN_POWER * POWER_DRAG * self.table_size[0]))
                    self.too_soft = True
                    self.status = (f"too soft to shoot: press, then drag at least {px} px away from where you "
                                   "pressed before releasing (the further, the harder)")
                self.dragging, self.power = False, 0.0

    def _press(self, pos: tuple[int, int]) -> None:
        """Left button down: on the tip diagram, a pocket to call, the cue ball in hand, or the start of a shot."""
        (cx, cy), r = self.tip_diagram
        if self.spin and math.hypot(pos[0] - cx, pos[1] - cy) <= r * 1.15:
            self.tip_drag = True
            self.set_tip_at(pos)
            return
        if self.needs_pocket():
            k = self._pocket_at(pos)
            if k is not None:
                self.pocket = k
                self.status = f"pocket {k + 1} called"
                return
        if self.in_hand():
            bx, by = self.ball_pixel(0)
            pick = PICK_RADII * float(self.core.balls.radius[0]) * self.renderer.pixels_per_metre
            if math.hypot(pos[0] - bx, pos[1] - by) <= max(pick, 6.0):
                self.placing = True
                return
        self.set_aim(pos)
        self.dragging, self.press, self.power = True, tuple(pos), 0.0

    def _pocket_at(self, pos: tuple[int, int]) -> int | None:
        t = self.core.table
        ppm = self.renderer.pixels_per_metre
        for k in range(t.n_pockets):
            px, py = self.pocket_pixel(k)
            if math.hypot(pos[0] - px, pos[1] - py) <= POCKET_PICK * float(t.pocket_radius[k]) * ppm:
                return k
        return None

    def _key(self, e: Any) -> None:
        pg = self.pg
        scroll = {pg.K_PAGEUP: self.log.page(), pg.K_PAGEDOWN: -self.log.page(), pg.K_HOME: len(self.log.lines),
                  pg.K_END: -len(self.log.lines)}
        if e.key in scroll:
            self.log.scroll(scroll[e.key])
        elif e.key == pg.K_ESCAPE and self.dragging:
            self.dragging, self.power = False, 0.0
        elif e.key in (pg.K_ESCAPE, pg.K_q):
            self.running = False
        elif e.key == pg.K_r:
            self.reset()
        elif self.spin and e.key in (pg.K_LEFT, pg.K_RIGHT, pg.K_UP, pg.K_DOWN):
            ds = {pg.K_LEFT: -TIP_STEP, pg.K_RIGHT: TIP_STEP}.get(e.key, 0.0)
            dt = {pg.K_DOWN: -TIP_STEP, pg.K_UP: TIP_STEP}.get(e.key, 0.0)
            self.set_tip(self.tip[0] + ds, self.tip[1] + dt)
        elif self.spin and e.key == pg.K_c:
            self.set_tip(0.0, 0.0)
        elif self.needs_pocket() and pg.K_1 <= e.key <= pg.K_9 and e.key - pg.K_1 < self.core.table.n_pockets:
            self.pocket = e.key - pg.K_1
            self.status = f"pocket {self.pocket + 1} called"

    def set_tip(self, side: float, top: float) -> None:
        """Tip offsets (fractions of R), moved onto the disc of radius ``max_tip_offset`` if outside."""
        r = math.hypot(side, top)
        if r > self.max_tip:
            side, top = side * self.max_tip / r, top * self.max_tip / r
        self.tip = (round(side, 6), round(top, 6))

    def set_tip_at(self, pixel: tuple[int, int]) -> None:
        from billiards_env.render.overlays import tip_from_point

        centre, r = self.tip_diagram
        self.tip = tip_from_point(pixel, centre, r, self.max_tip)

    def set_aim(self, pixel: tuple[int, int]) -> None:
        """Aim from the cue ball towards ``pixel`` (unchanged if the pointer is on the cue ball's centre)."""
        x, y = self.to_table(pixel)
        cx, cy = self.cue_xy()
        if math.hypot(x - cx, y - cy) > 1e-3:
            self.aim = math.atan2(y - cy, x - cx)

    # --- drawing ----------------------------------------------------------------------------------------
    def draw(self) -> None:
        b = self.core.balls
        pos, on = b.pos, b.on_table
        if self.place is not None:
            pos, on = pos.copy(), on.copy()
            pos[0], on[0] = self.place, True
        data = self.core.render_data()
        cx, cy = self.cue_xy()
        data["cue"] = None if self.done else (cx, cy, self.aim)
        if self.spin:
            data["tip"] = self.tip  # the shot being prepared
        if "hud" in data and self.needs_pocket():
            data["hud"] = {**data["hud"], "called_pocket": self.pocket}
        surf = self.renderer.draw(pos, on, self.core.ball_numbers, **data)
        self.screen.blit(surf, (0, 0))
        self.draw_panel()
        self.pg.display.flip()
        self.frames_shown += 1

    def draw_panel(self) -> None:
        from billiards_env.render.overlays import draw_tip_diagram
        from billiards_env.render.paint import text

        pg = self.pg
        w, h = self.table_size
        pg.draw.rect(self.screen, PANEL_BG, pg.Rect(0, h, w, self.panel_height))
        bar = pg.Rect(10, h + 8, max(60, w // 3), 16)
        pg.draw.rect(self.screen, BAR_BG, bar, border_radius=4)
        if self.power > 0:
            fill = bar.copy()
            fill.width = max(1, int(bar.width * self.power))
            colour = (int(60 + 195 * self.power), int(200 - 140 * self.power), 60)
            pg.draw.rect(self.screen, colour, fill, border_radius=4)
        label = f"power {self.speed():.2f} m/s" if self.dragging else \
            f"shots {self.shots}/{self.core.config.max_shots}" + ("" if self.is_game else f"   return {self.total:+.2f}")
        room = w - 20
        if self.spin:
            (cx, cy), r = self.tip_diagram
            draw_tip_diagram(self.screen, (cx, cy), r, *self.tip)
            label += f"   tip: side {self.tip[0]:+.2f} R, top {self.tip[1]:+.2f} R"
            room = int(cx - r) - 20
        text(self.screen, label, 22, TEXT, (bar.right + 10, bar.centery), max_width=room - bar.right)
        text(self.screen, self.status, 22, TEXT, (10, h + 40), max_width=room)
        if self.is_game:
            self.log.draw(self.screen, pg.Rect(10, h + PANEL_HEIGHT + 4, w - 20, LOG_LINES * LOG_LINE),
                          line_height=LOG_LINE)

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
        return {"shots": self.shots, "opponent_shots": self.opponent_shots, "return": self.total, "done": self.done,
                "is_success": self.success, "frames_shown": self.frames_shown}

    def _panel_height(self) -> int:
        """The panel's height below the table (px): the status lines, and the turn log in a game."""
        return PANEL_HEIGHT + (LOG_LINES * LOG_LINE + 8 if self.is_game else 0)

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
                elif e.type == pg.KEYDOWN and e.key in SKIP_KEYS(pg):
                    app.skipping = True  # the rest of this step's animation is not shown
        return not app.running

    def show(self, surface: Any, fps: float | None = None) -> None:
        app = self.app
        if app.skipping:  # Space: nothing drawn or waited for until the step returns
            return
        app.screen.blit(surface, (0, 0))
        app.draw_panel()
        app.pg.display.flip()
        app.frames_shown += 1
        if fps and app.realtime:
            app.clock.tick(fps)

    def close(self) -> None:
        """The app closes the display itself (:meth:`PlayApp.close`)."""


def SKIP_KEYS(pg: Any) -> tuple[int, ...]:  # noqa: N802 - a constant that needs pygame imported
    """Keys that skip the rest of an animation."""
    return (pg.K_SPACE, pg.K_s)


def call_turn(verdict: Any) -> dict[str, Any]:
    """A session's :class:`~billiards_env.games.session.Verdict` (or a ruleset's call) as a turn-log entry in words
    (``pocketed``, ``foul``, ``foul_reason``, ``call``, ``scratch``, ``shooter``, with the game's own: snooker's
    ``points``, ``foul_points``; three-cushion's ``point``, ``cushions``), plus ``turn_over``, ``game_over``,
    ``winner`` and ``push_out``. The balls potted: pool's kept down (not re-spotted), snooker's every ball that
    dropped (its points count)."""
    call = getattr(verdict, "call", verdict)
    game: dict[str, Any] = {}
    if hasattr(call, "reds_potted"):  # snooker
        pocketed: tuple[Any, ...] = ("red",) * int(call.reds_potted) + tuple(call.colours_potted)
        game = {"points": int(call.points), "foul_points": int(call.foul_points)}
    elif hasattr(call, "cushions"):  # three-cushion
        pocketed = ()
        game = {"point": bool(call.point), "cushions": int(call.cushions)}
    else:
        respot = getattr(call, "respot", ())
        pocketed = tuple(n for n in getattr(call, "pocketed", ()) if n not in respot)
    over = getattr(verdict, "game_over", getattr(call, "game_over", False))
    return {
        "pocketed": pocketed,
        "foul": bool(call.foul), "foul_reason": call.reason if call.foul else None, "call": call.reason,
        "scratch": bool(getattr(call, "cue_pocketed", False)), "shooter": int(call.shooter),
        "turn_over": bool(call.turn_over), "game_over": bool(over), "winner": getattr(verdict, "winner", None),
        "push_out": bool(getattr(call, "push_out", False)), **game,
    }


def _info_turn(info: dict[str, Any], shooter: int) -> dict[str, Any]:
    """What a game step's info says of the human's own shot besides its words (``env.info_words``; when no call
    was recorded): its shooter and whether it ended the game."""
    winner = info.get("winner", -1)
    return {"shooter": shooter, "game_over": winner in (0, 1) and not info.get("opponent_shots"), "winner": winner}


# --- scripted play (--demo, tests) ------------------------------------------------------------------------------
def mouse_shot(app: PlayApp, power: float, target: tuple[int, int] | None = None) -> Iterator[list[Any]]:
    """Events of one shot: point at ``target`` (default: the target ball), press there, drag ``power`` of full
    power straight back towards the cue ball, release. Reads the live state when it starts."""
    pg = app.pg
    if target is None:
        t = app.core.target_ball() or 1
        target = app.ball_pixel(t)
    bx, by = target
    cx, cy = app.ball_pixel(0)
    yield [pg.event.Event(pg.MOUSEMOTION, pos=(bx, by), rel=(0, 0), buttons=(0, 0, 0))]
    yield [pg.event.Event(pg.MOUSEBUTTONDOWN, pos=(bx, by), button=1)]
    n = math.hypot(bx - cx, by - cy) or 1.0
    drag = power * POWER_DRAG * app.table_size[0]
    end = (int(round(bx - (bx - cx) / n * drag)), int(round(by - (by - cy) / n * drag)))
    yield [pg.event.Event(pg.MOUSEMOTION, pos=end, rel=(0, 0), buttons=(1, 0, 0))]
    yield [pg.event.Event(pg.MOUSEBUTTONUP, pos=end, button=1)]


def mouse_drag(app: PlayApp, start: tuple[int, int], end: tuple[int, int]) -> Iterator[list[Any]]:
    """Events of a left-button drag from ``start`` to ``end`` (e.g. the cue ball in hand to a new spot)."""
    pg = app.pg
    yield [pg.event.Event(pg.MOUSEMOTION, pos=start, rel=(0, 0), buttons=(0, 0, 0))]
    yield [pg.event.Event(pg.MOUSEBUTTONDOWN, pos=start, button=1)]
    mid = ((start[0] + end[0]) // 2, (start[1] + end[1]) // 2)
    yield [pg.event.Event(pg.MOUSEMOTION, pos=mid, rel=(0, 0), buttons=(1, 0, 0))]
    yield [pg.event.Event(pg.MOUSEMOTION, pos=end, rel=(0, 0), buttons=(1, 0, 0))]
    yield [pg.event.Event(pg.MOUSEBUTTONUP, pos=end, button=1)]


def demo_events(app: PlayApp, power: float = 0.5, max_shots: int = 4) -> Iterator[list[Any]]:
    """A scripted turn, then quit. A scene: one shot at the target ball with ``power``. A game: with ball in hand
    drag the cue ball a little towards the side rail, call pocket 1 if on the 8, shoot at the target ball (the
    break at full power), and go on until the opponent has replied, the game is over or ``max_shots`` were played.
    A generator: each step reads the live state, so it works for any scene and seed."""
    pg = app.pg
    if not app.is_game:
        yield from mouse_shot(app, power)
    else:
        for k in range(max_shots):
            if app.in_hand():
                cx, cy = app.ball_pixel(0)
                yield from mouse_drag(app, (cx, cy), (cx - 12, cy - 20))
            if app.needs_pocket():
                yield [pg.event.Event(pg.KEYDOWN, key=pg.K_1, mod=0, unicode="1", scancode=0)]
            yield from mouse_shot(app, 1.0 if k == 0 else power)
            if app.done or app.opponent_shots or app.two_people:
                break
    yield [pg.event.Event(pg.QUIT)]


def build_parser() -> argparse.ArgumentParser:
    from billiards_env.games import GAMES
    from billiards_env.registration import ENV_IDS, env_id_arg

    games = ", ".join(g.title for g in GAMES.values())  # the registry's games, by title
    summary = __doc__.split("\n\n")[0].split(": ", 1)[1].replace("any of the game registry's", games)
    p = argparse.ArgumentParser(prog="billiards-play", description=summary,
                                epilog=__doc__.split("\n\n", 1)[1],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--env", default="BilliardsOneBall-v0", type=env_id_arg, choices=list(ENV_IDS),
                   help="scene or game to play")
    p.add_argument("--opponent", default=None, choices=list(OPPONENTS),
                   help="games: the opponent, a baseline player or 'human' (two people take turns); default: the "
                        "env's (geometric)")
    p.add_argument("--breaker", default="alternate", choices=list(BREAKERS),
                   help="games: who breaks each game; alternate (default): you the first, then the opponent, ...")
    p.add_argument("--spin", action="store_true",
                   help="the spin model with tip offsets (friction='spin', spin_action=True): draw, follow, english")
    p.add_argument("--seed", type=int, default=None, help="seed of the first episode (default: random)")
    p.add_argument("--width", type=int, default=None,
                   help=f"window width in pixels (default: {DEFAULT_WIDTH}, narrower if the window would not fit "
                        "the screen's height)")
    p.add_argument("--speedup", type=float, default=2.0,
                   help="animation playback speed (simulated seconds per second; 1 = real time)")
    p.add_argument("--config", default=None, help="a YAML file of env config keys layered over the scene's")
    p.add_argument("--demo", action="store_true",
                   help="play a scripted turn from synthetic events, print a summary and quit (headless test)")
    return p


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    kwargs = {"config": args.config} if args.config else {}
    from billiards_env.render.window import HeadlessDisplayError

    try:
        app = PlayApp(args.env, seed=args.seed, width=args.width, speedup=args.speedup,
                      realtime=not args.demo, allow_headless=True if args.demo else None, opponent=args.opponent,
                      spin=args.spin, breaker=args.breaker, **kwargs)
    except (ValueError, HeadlessDisplayError) as exc:  # bad config (the message names the key), or no display
        print(f"billiards-play: error: {exc}", file=sys.stderr)
        return 2
    if args.demo:
        summary = app.run(demo_events(app))
        print(f"billiards-play demo: {summary}")
        replied = not app.is_game or app.two_people or summary["done"] or summary["opponent_shots"] > 0
        return 0 if summary["shots"] >= 1 and replied else 1
    app.run()
    return 0


if __name__ == "__main__":
    sys.exit(main())
