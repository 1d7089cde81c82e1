"""``billiards-play`` driven headless by synthetic pygame events."""
from __future__ import annotations

import math
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import numpy as np  # noqa: E402
import pygame  # noqa: E402
import pytest  # noqa: E402

from billiards_env import play  # noqa: E402


def test_demo_plays_one_shot(capsys):
    assert play.main(["--env", "BilliardsThreeBalls-v0", "--seed", "0", "--demo", "--width", "240",
                      "--speedup", "50"]) == 0
    assert "'shots': 1" in capsys.readouterr().out


def test_mouse_aim_drag_release_plays_the_shot():
    app = play.PlayApp("BilliardsOneBall-v0", seed=3, width=400, speedup=50.0, realtime=False)
    start = app.core.balls.pos.copy()
    cx, cy = app.ball_pixel(0)
    target = (cx + 80, cy - 40)  # aim up and to the right of the cue ball
    drag_end = (target[0] - 0.5 * play.POWER_DRAG * 400, target[1])  # half of full power
    E = pygame.event.Event
    script = [
        [E(pygame.MOUSEMOTION, pos=target, rel=(0, 0), buttons=(0, 0, 0))],
        [E(pygame.MOUSEBUTTONDOWN, pos=target, button=1)],
        [E(pygame.MOUSEMOTION, pos=(int(drag_end[0]), int(drag_end[1])), rel=(0, 0), buttons=(1, 0, 0))],
        [E(pygame.MOUSEBUTTONUP, pos=(int(drag_end[0]), int(drag_end[1])), button=1)],
        [E(pygame.QUIT)],
    ]
    summary = app.run(script)
    assert summary["shots"] == 1 and summary["frames_shown"] > 4
    info = app.last_info
    tx, ty = app.to_table(target)
    expected = math.atan2(ty - start[0, 1], tx - start[0, 0])
    assert math.cos(info["angle"] - expected) == pytest.approx(1.0, abs=1e-4)  # screen y is flipped: up = +y
    assert 0 < info["angle"] < math.pi / 2
    c = app.core.config
    assert info["speed"] == pytest.approx(c.speed_min + 0.5 * (c.speed_max - c.speed_min), rel=0.02)
    assert not np.array_equal(app.core.balls.pos[0], start[0]) or info["scratch"]


def test_small_drag_cancels():
    app = play.PlayApp("BilliardsOneBall-v0", seed=0, width=300, realtime=False)
    cx, cy = app.ball_pixel(0)
    E = pygame.event.Event
    script = [[E(pygame.MOUSEBUTTONDOWN, pos=(cx + 30, cy), button=1)],
              [E(pygame.MOUSEBUTTONUP, pos=(cx + 30, cy), button=1)], [E(pygame.QUIT)]]
    assert app.run(script)["shots"] == 0
