"""The play window's turn log in every game (headless): snooker's pots by name, three-cushion's point and cushions,
the opponent's game-winning shot, and a log that scrolls back to the line that ended the player's turn."""
from __future__ import annotations

import math
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import numpy as np  # noqa: E402
import pygame  # noqa: E402

from billiards_env import play  # noqa: E402
from billiards_env.rules.snooker import SNOOKER_IDS  # noqa: E402
from billiards_env.render.turn_log import TurnLog, potted_names, scroll_hint, turn_line  # noqa: E402

E = pygame.event.Event
NAMES = ("you", "geometric")


def _app(env_id: str, **kw) -> play.PlayApp:
    return play.PlayApp(env_id, seed=0, width=400, speedup=50.0, realtime=False, allow_headless=True,
                        opponent="geometric", **kw)


def _shoot(app: play.PlayApp, angle: float, speed: float) -> dict:
    c = app.core.config
    app.aim, app.power = angle, (speed - c.speed_min) / (c.speed_max - c.speed_min)
    info = app.shoot()
    assert info is not None
    return info


# --- plain data ------------------------------------------------------------------------------------------------
def test_ball_ids_become_names():
    assert potted_names(("red11", "blue", "cue")) == ["red", "blue"]
    assert potted_names((3, "9", "cue")) == ["3", "9"]
    assert potted_names(("yellow", "red3", "white")) == ["yellow", "red", "white"]  # snooker's yellow is a colour


def test_every_snooker_colour_is_named_when_potted():
    """Each colour potted alone reads as a pot of that colour, with its points and the shooter going on."""
    base = {"foul": False, "foul_reason": None, "scratch": False, "shooter": 1, "foul_points": 0, "call": "pot",
            "turn_over": False}
    for value, colour in enumerate(("yellow", "green", "brown", "blue", "pink", "black"), start=2):
        line = turn_line({**base, "pocketed": (colour,), "points": value}, NAMES)[0]
        assert line == f"geometric: potted {colour} ({value}) - shoots again"


def test_snooker_lines_name_the_balls_and_points():
    base = {"foul": False, "foul_reason": None, "scratch": False, "shooter": 1, "points": 0, "foul_points": 0}
    red = {**base, "pocketed": ("red11",), "points": 1, "call": "pot", "turn_over": False}
    blue = {**base, "pocketed": ("blue",), "points": 5, "call": "pot", "turn_over": False}
    miss = {**base, "pocketed": (), "call": "no pot", "turn_over": True}
    foul = {**base, "pocketed": (), "foul": True, "foul_reason": "ball not on hit first", "foul_points": 6,
            "call": "ball not on hit first", "turn_over": True}
    assert turn_line(red, NAMES)[0] == "geometric: potted red (1) - shoots again"
    assert turn_line(blue, NAMES)[0] == "geometric: potted blue (5) - shoots again"
    assert turn_line(miss, NAMES)[0] == "geometric: no pot - turn over"
    assert turn_line(foul, NAMES) == ("geometric: FOUL ball not on hit first - you get 6 points", "foul")


def test_three_cushion_lines_give_the_point_and_the_cushions():
    base = {"pocketed": (), "foul": False, "foul_reason": None, "scratch": False, "shooter": 0}
    point = {**base, "point": True, "cushions": 3, "call": "point", "turn_over": False}
    miss = {**base, "point": False, "cushions": 1, "call": "no point", "turn_over": True}
    won = {**point, "call": "target reached", "game_over": True, "winner": 0}
    assert turn_line(point, NAMES)[0] == "you: point (3 cushions) - shoot again"
    assert turn_line(miss, NAMES)[0] == "you: no point (1 cushion) - turn over"
    assert turn_line(won, NAMES) == ("you: point (3 cushions), target reached - you win", "win")


def test_the_opponents_winning_shot_says_so_from_the_info_alone():
    """Without recorded calls, the env's info: the game over and the winner from ``info["winner"]``."""
    info = {"opponent_shots": 1, "winner": 1, "opponent_turns": [
        {"shooter": 1, "pocketed": ("9",), "scratch": False, "foul": False, "foul_reason": None,
         "call": "9 pocketed", "turn_over": False}]}
    log = TurnLog()
    log.add(play.PlayApp._opponent_turns(info, [], lambda turn: turn), NAMES)  # the turns in words already
    assert log.lines == [("geometric: 9 pocketed - geometric wins", "win")]


def test_the_log_scrolls_back_and_says_what_is_hidden():
    log = TurnLog()
    miss = {"pocketed": (), "foul": False, "call": "legal", "shooter": 1, "turn_over": False}
    log.add([{**miss, "shooter": 0, "turn_over": True}] + [miss] * 27, NAMES)
    surface = pygame.Surface((400, 120))
    log.draw(surface, pygame.Rect(0, 0, 400, 108), line_height=18)  # room for 6 lines
    assert log.visible(6)[-1][0] == "geometric: no ball pocketed" and log.offset == 0
    assert scroll_hint(22, 0) == "22 earlier (wheel, PgUp/PgDn)"
    log.scroll(1000)  # as far back as there are lines
    assert log.offset == 22 and log.visible(6)[0][0] == "you: no ball pocketed - turn over"
    log.scroll(-5)
    assert log.offset == 17
    log.add([miss], NAMES)  # a new shot brings the window back to the newest line
    assert log.offset == 0


# --- the window ------------------------------------------------------------------------------------------------
def test_snooker_pot_is_logged_by_name():
    app = _app("BilliardsSnooker-v0")
    u = app.core
    pos = u.balls.pos.copy()
    pocketed = np.array([bid.startswith("red") and bid != "red1" for bid in SNOOKER_IDS])
    length, width = u.table.length, u.table.width
    pos[SNOOKER_IDS.index("red1")] = (length - 0.3, width - 0.3)
    pos[0] = (length - 0.8, width - 0.8)
    app.reset(options={"positions": pos, "pocketed": pocketed})
    info = _shoot(app, math.pi / 4, 2.0)
    assert info["points"] == 1
    assert app.log.lines[-1] == ("you: potted red (1) - shoot again", "shot")
    assert "potted red (1) - shoot again" in app.status
    assert not any("pocketed" in line for line, _ in app.log.lines)
    app.close()


def test_three_cushion_shows_your_shot_and_its_cushions():
    app = _app("BilliardsThreeCushion-v0")
    u = app.core
    red = u.balls.pos[2]
    cue = u.balls.pos[0]
    _shoot(app, math.atan2(red[1] - cue[1], red[0] - cue[0]) + 0.05, 3.0)
    lines = [line for line, _ in app.log.lines]
    mine = [line for line in lines if line.startswith("you:")]
    assert mine and ("cushion" in mine[0] or "FOUL" in mine[0])
    assert not any("pocketed" in line for line in lines)
    assert ("cushion" in app.status or "FOUL" in app.status) and "pocketed" not in app.status
    app.close()


def test_the_opponents_winning_pot_ends_the_log_with_the_winner():
    """The 9 hangs over a corner pocket; you hit nothing (a foul), the geometric player pots the 9 and wins."""
    app = _app("Billiards9Ball-v0", breaker="you")
    u = app.core
    length, width = u.table.length, u.table.width
    pos = u.balls.pos.copy()
    pocketed = np.ones(len(pos), bool)
    pocketed[0] = pocketed[9] = False
    pos[9] = (length - 0.12, width - 0.12)
    pos[0] = (length / 2, width / 2)
    app.reset(options={"positions": pos, "pocketed": pocketed})
    _shoot(app, -math.pi / 2, 0.6)  # away from the 9, into the cushion: no ball hit
    assert app.done and u.task.session.winner == 1
    line, kind = app.log.lines[-1]
    assert kind == "win" and line.startswith("geometric: ") and line.endswith("geometric wins")
    assert app.log.lines[0][1] == "foul"
    app.close()


def test_wheel_and_page_keys_scroll_the_window_log():
    app = _app("Billiards9Ball-v0", breaker="you")
    miss = {"pocketed": (), "foul": False, "call": "legal", "shooter": 1, "turn_over": False}
    app.log.add([miss] * 30, NAMES)
    app.draw()
    app.handle(E(pygame.MOUSEWHEEL, x=0, y=3, flipped=False))
    assert app.log.offset == 3 * play.WHEEL_LINES
    app.handle(E(pygame.KEYDOWN, key=pygame.K_HOME, mod=0, unicode="", scancode=0))
    assert app.log.offset == len(app.log.lines) - play.LOG_LINES
    app.handle(E(pygame.KEYDOWN, key=pygame.K_END, mod=0, unicode="", scancode=0))
    assert app.log.offset == 0
    app.handle(E(pygame.KEYDOWN, key=pygame.K_PAGEUP, mod=0, unicode="", scancode=0))
    assert app.log.offset == play.LOG_LINES - 1
    app.close()


def test_the_help_names_every_game_it_offers():
    from billiards_env.games import GAMES

    text = play.build_parser().format_help()
    assert "9-ball or 8-ball" not in text
    for game in GAMES.values():
        assert game.env_id in text and game.title in text.split("\n\n")[1]  # the summary line names each game
    assert "Page Up" in text and "wheel" in text  # the log's scroll keys
