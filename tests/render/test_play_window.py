"""The play window (``billiards-play``), driven headless: the turn log, the too-soft drag, skipping an animation,
and who breaks after R."""
from __future__ import annotations

import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import numpy as np  # noqa: E402
import pygame  # noqa: E402
import pytest  # noqa: E402

from billiards_env import play  # noqa: E402
from billiards_env.render.turn_log import TurnLog, turn_line  # noqa: E402

E = pygame.event.Event
NAMES = ("you", "geometric")


def _game(**kw) -> play.PlayApp:
    return play.PlayApp("Billiards9Ball-v0", seed=0, width=400, speedup=50.0, realtime=False, allow_headless=True,
                        opponent="geometric", **kw)


# --- the turn log, from plain data --------------------------------------------------------------------------
def test_turn_lines_say_the_call_and_why_the_turn_ended():
    pot = {"pocketed": (2,), "foul": False, "foul_reason": None, "call": "legal", "scratch": False, "shooter": 0}
    miss = {"pocketed": (), "foul": False, "foul_reason": None, "call": "legal", "scratch": False, "shooter": 0}
    foul = {"pocketed": ("cue",), "foul": True, "foul_reason": "scratch", "call": "scratch", "scratch": True,
            "shooter": 1}
    wrong = {"pocketed": (), "foul": True, "foul_reason": "wrong ball first", "call": "wrong ball first",
             "scratch": True, "shooter": 1}
    assert turn_line(pot, NAMES) == ("you: pocketed 2 - shoot again", "shot")
    assert turn_line(miss, NAMES, last_of_turn=True) == ("you: no ball pocketed - turn over", "shot")
    assert turn_line(foul, NAMES) == ("geometric: FOUL scratch - you have ball in hand", "foul")
    assert turn_line(wrong, NAMES)[0] == "geometric: FOUL wrong ball first, scratch - you have ball in hand"
    end = {**pot, "pocketed": (9,), "call": "9 pocketed", "game_over": True, "winner": 0}
    assert turn_line(end, NAMES) == ("you: 9 pocketed - you win", "win")
    log = TurnLog()
    log.add([pot, miss], NAMES)  # a run of shots in words: the last of the run ended the turn
    assert [line for line, _ in log.lines] == ["you: pocketed 2 - shoot again", "you: no ball pocketed - turn over"]


# --- the window ------------------------------------------------------------------------------------------------
def test_turn_log_shows_the_humans_shot_and_each_opponent_shot():
    app = _game()
    height = app.screen.get_height()
    app.run(play.demo_events(app))  # break, then shoot until the geometric player has replied
    lines = [line for line, _ in app.log.lines]
    assert app.opponent_shots >= 1
    mine = [line for line in lines if line.startswith("you:")]
    theirs = [line for line in lines if line.startswith("geometric:")]
    assert len(mine) == app.shots and len(theirs) == app.opponent_shots
    # The human's last shot says why the turn passed; the log is drawn in the panel under the game's panel.
    assert mine[-1].endswith(("turn over", "ball in hand")) or "FOUL" in mine[-1]
    assert height == app.table_size[1] + app.panel_height > app.table_size[1] + play.PANEL_HEIGHT


def test_a_drag_below_the_minimum_power_says_so():
    app = play.PlayApp("BilliardsOneBall-v0", seed=0, width=300, realtime=False, allow_headless=True)
    cx, cy = app.ball_pixel(0)
    app.handle(E(pygame.MOUSEBUTTONDOWN, pos=(cx + 30, cy), button=1))
    app.handle(E(pygame.MOUSEMOTION, pos=(cx + 31, cy), rel=(1, 0), buttons=(1, 0, 0)))
    app.handle(E(pygame.MOUSEBUTTONUP, pos=(cx + 31, cy), button=1))
    assert app.shots == 0 and app.too_soft
    assert app.status.startswith("too soft to shoot") and "px" in app.status
    app.close()


def test_space_skips_the_rest_of_the_animation():
    shown = []
    for skip in (False, True):
        app = play.PlayApp("BilliardsOneBall-v0", seed=3, width=300, speedup=2.0, realtime=False,
                           allow_headless=True)
        app.power = 0.6
        start = app.frames_shown
        if skip:
            pygame.event.post(E(pygame.KEYDOWN, key=pygame.K_SPACE, mod=0, unicode=" ", scancode=0))
        info = app.shoot()
        shown.append(app.frames_shown - start)
        assert info is not None and app.shots == 1 and not app.skipping  # the shot was played in full
        app.close()
    assert shown[0] > 20 and shown[1] <= 1  # the skipped shot showed nothing before the table after it


@pytest.mark.parametrize("breaker, expected", [("alternate", [0, 1, 0]), ("opponent", [1, 1, 1]),
                                               ("you", [0, 0, 0])])
def test_who_breaks_after_r(breaker, expected):
    app = _game(breaker=breaker)
    breakers = []
    for k in range(3):
        if k:
            app.handle(E(pygame.KEYDOWN, key=pygame.K_r, mod=0, unicode="r", scancode=0))
        state = app.core.task.game_state
        # The opponent's break has been played inside reset (and logged); otherwise you break.
        breakers.append(1 if app.opponent_shots else 0)
        assert (state.break_shot and state.shooter == 0) == (breakers[-1] == 0)
        if breakers[-1] == 1:
            assert app.log.lines and app.log.lines[-1][0].startswith("geometric:")
    app.close()
    assert breakers == expected


def test_log_reads_the_envs_opponent_turns():
    """Where the env's info gives ``opponent_turns`` (``opponent_infos=True``: masks over the rows, reason codes),
    the log puts them in words with the env's ``info_words``; the human's own shot is read from the step's info."""
    import gymnasium as gym

    u = gym.make("Billiards9Ball-v0", opponent_infos=True).unwrapped
    reasons = u.task.session.reasons
    pocketed = np.zeros(u.n_balls, bool)
    pocketed[3] = True
    info = {"opponent_shots": 2, "opponent_turns": [
        {"shooter": 1, "pocketed": pocketed, "scratch": False, "foul": False, "foul_reason": -1,
         "call": reasons.index("legal"), "turn_over": False},
        {"shooter": 1, "pocketed": np.eye(u.n_balls, dtype=bool)[0], "scratch": True, "foul": True,
         "foul_reason": reasons.index("scratch"), "call": reasons.index("scratch"), "turn_over": True}]}
    log = TurnLog()
    log.add(play.PlayApp._opponent_turns(info, [], u.info_words), NAMES)
    assert [line for line, _ in log.lines] == ["geometric: pocketed 3 - shoots again",
                                               "geometric: FOUL scratch - you have ball in hand"]
    step = {"pocketed": np.eye(u.n_balls, dtype=bool)[0], "foul": True, "foul_reason": reasons.index("scratch"),
            "call": reasons.index("scratch"), "scratch": True, "turn_over": True, "winner": -1, "opponent_shots": 2}
    own = {**u.info_words(step), **play._info_turn(step, 0)}
    assert turn_line(own, NAMES)[0] == "you: FOUL scratch - geometric has ball in hand"


def test_games_the_opponent_won_from_its_break_are_logged():
    """When the opponent breaks and runs out before your first shot, the env racks again inside reset; the panel
    counts those games, so the log says so instead of leaving them unexplained."""
    for seed in range(40):
        app = play.PlayApp("Billiards9Ball-v0", seed=seed, width=400, speedup=50.0, realtime=False,
                           allow_headless=True, opponent="geometric", breaker="opponent")
        won = app.core.task.session.score.wins[1]
        lines = list(app.log.lines)
        app.close()
        if won:
            break
    else:
        pytest.fail("the geometric player never won from its break in 40 racks")
    assert lines[0] == (f"geometric broke and won {won} game{'s' if won > 1 else ''} before your first shot; "
                        "racked again", "win")
    assert all(line.startswith("geometric:") for line, _ in lines[1:])  # then the rack you face, shot by shot
