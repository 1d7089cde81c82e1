"""billiards-play on straight pool (headless): a pocket is called by key or click, the called ball is the one the
cue is aimed at, and the shot carries both."""
from __future__ import annotations

import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import numpy as np  # noqa: E402
import pygame  # noqa: E402

from billiards_env import play  # noqa: E402


def _feed(app: play.PlayApp, batches) -> None:
    for batch in batches:
        for e in batch:
            app.handle(e)


def test_a_human_calls_the_pocket_and_the_ball_aimed_at():
    app = play.PlayApp("BilliardsStraightPool-v0", seed=0, width=400, speedup=50.0, realtime=False,
                       allow_headless=True, opponent="random")
    core = app.core
    pos = np.array(core.balls.pos)
    pocketed = np.ones(16, bool)
    pocketed[[0, 6, 11]] = False
    pos[0], pos[6], pos[11] = (0.8, 0.4), (1.6, 0.4), (2.2, 1.0)
    app.reset(seed=0, options={"positions": pos, "pocketed": pocketed})
    assert app.needs_pocket() and app.pocket is None
    _feed(app, list(play.mouse_shot(app, 0.5)))
    assert app.shots == 0 and "call" in app.status  # no shot without a pocket
    _feed(app, [[pygame.event.Event(pygame.KEYDOWN, key=pygame.K_3, mod=0, unicode="", scancode=0)]])
    assert app.pocket == 2
    _feed(app, list(play.mouse_shot(app, 0.5)))  # aimed at the target ball: row 6, the lowest on the table
    assert app.shots == 1
    shot = core.shot_from_action(app.last_action)
    assert shot.call("ball") == 6 and shot.call("pocket") == 2
    app.close()
