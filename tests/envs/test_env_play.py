"""``billiards-play`` driven headless by synthetic pygame events."""
from __future__ import annotations

import math
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import numpy as np  # noqa: E402
import pygame  # noqa: E402
import pytest  # noqa: E402

from billiards_env import play  # noqa: E402
from billiards_env.render.window import ALLOW_HEADLESS_ENV  # noqa: E402

E = pygame.event.Event


def test_demo_plays_one_shot(capsys, monkeypatch):
    monkeypatch.delenv(ALLOW_HEADLESS_ENV, raising=False)  # --demo needs no display and no opt-in
    assert play.main(["--env", "BilliardsThreeBalls-v0", "--seed", "0", "--demo", "--width", "240",
                      "--speedup", "50"]) == 0
    assert "'shots': 1" in capsys.readouterr().out


@pytest.mark.parametrize("driver", ["dummy", "offscreen"])
def test_without_a_display_play_stops_with_a_hint(capsys, monkeypatch, driver):
    monkeypatch.delenv(ALLOW_HEADLESS_ENV, raising=False)
    monkeypatch.setenv("SDL_VIDEODRIVER", driver)
    assert play.main(["--env", "BilliardsOneBall-v0", "--width", "240"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and len(err.strip().splitlines()) == 1
    assert err.startswith("billiards-play: error: ") and "display" in err and "--demo" in err
    assert driver in err
    assert not pygame.display.get_init()  # nothing left open


def test_no_display_variables_on_linux_is_headless(monkeypatch):
    from billiards_env.render import window

    monkeypatch.setattr(window.sys, "platform", "linux")
    for var in ("SDL_VIDEODRIVER", "DISPLAY", "WAYLAND_DISPLAY", ALLOW_HEADLESS_ENV):
        monkeypatch.delenv(var, raising=False)
    with pytest.raises(window.HeadlessDisplayError, match="DISPLAY and WAYLAND_DISPLAY are unset"):
        play.PlayApp("BilliardsOneBall-v0", seed=0, width=200, realtime=False)
    assert not pygame.display.get_init()


def _mouse_shot(app: play.PlayApp, power: float = 0.5) -> tuple[tuple[int, int], list[list]]:
    """Aim up and to the right of the cue ball, drag ``power`` of full power, release, quit."""
    cx, cy = app.ball_pixel(0)
    target = (cx + 80, cy - 40)
    end = (int(target[0] - power * play.POWER_DRAG * app.table_size[0]), target[1])
    return target, [
        [E(pygame.MOUSEMOTION, pos=target, rel=(0, 0), buttons=(0, 0, 0))],
        [E(pygame.MOUSEBUTTONDOWN, pos=target, button=1)],
        [E(pygame.MOUSEMOTION, pos=end, rel=(0, 0), buttons=(1, 0, 0))],
        [E(pygame.MOUSEBUTTONUP, pos=end, button=1)],
        [E(pygame.QUIT)],
    ]


def test_mouse_aim_drag_release_plays_the_shot():
    app = play.PlayApp("BilliardsOneBall-v0", seed=3, width=400, speedup=50.0, realtime=False,
                       allow_headless=True)
    start = app.core.balls.pos.copy()
    target, script = _mouse_shot(app)
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


def test_shot_frames_are_shown_as_drawn_and_the_power_bar_goes():
    """After the release every frame is shown as soon as it is drawn (draw, flip, draw, flip: no batch of
    frames rendered ahead), the animation ends on the state after the shot, and the power bar is empty."""
    app = play.PlayApp("BilliardsOneBall-v0", seed=3, width=300, speedup=20.0, realtime=False,
                       allow_headless=True)
    log: list[tuple] = []
    draw, flip = app.renderer.draw, pygame.display.flip
    w, h = app.table_size
    bar_probe = (16, h + 16)  # inside the power bar, where its fill starts

    def logged_draw(pos, *a, **k):
        log.append(("draw", app.core.shots, np.array(pos)))
        return draw(pos, *a, **k)

    def logged_flip():
        log.append(("flip", app.core.shots, tuple(app.screen.get_at(bar_probe))[:3]))
        flip()

    app.renderer.draw = logged_draw
    pygame.display.flip = logged_flip
    try:
        _, script = _mouse_shot(app, power=0.6)
        app.run(script)
    finally:
        pygame.display.flip = flip
    kinds = [e[0] for e in log]
    assert all(a != b for a, b in zip(kinds, kinds[1:])), "frames drawn ahead of being shown"
    before = [e for e in log if e[1] == 0]
    during = [e for e in log if e[1] == 1]
    assert any(e[0] == "flip" and e[2] != play.BAR_BG for e in before)  # the bar was filled while dragging
    flips = [e for e in during if e[0] == "flip"]
    assert len(flips) > 3 and all(e[2] == play.BAR_BG for e in flips)  # and is empty once released
    draws = [e[2] for e in during if e[0] == "draw"]
    assert not np.array_equal(draws[0], draws[-1])  # the balls moved
    np.testing.assert_array_equal(draws[-1][app.core.balls.on_table], app.core.balls.pos[app.core.balls.on_table])


def test_small_drag_cancels():
    app = play.PlayApp("BilliardsOneBall-v0", seed=0, width=300, realtime=False, allow_headless=True)
    cx, cy = app.ball_pixel(0)
    script = [[E(pygame.MOUSEBUTTONDOWN, pos=(cx + 30, cy), button=1)],
              [E(pygame.MOUSEBUTTONUP, pos=(cx + 30, cy), button=1)], [E(pygame.QUIT)]]
    assert app.run(script)["shots"] == 0
