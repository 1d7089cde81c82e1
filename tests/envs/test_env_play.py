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


# --- games and spin ------------------------------------------------------------------------------------------
def _press_release(pos, button=1):
    return [[E(pygame.MOUSEBUTTONDOWN, pos=pos, button=button)], [E(pygame.MOUSEBUTTONUP, pos=pos, button=button)]]


def _key(key):
    return [E(pygame.KEYDOWN, key=key, mod=0, unicode="", scancode=0)]


def _feed(app: play.PlayApp, batches) -> None:
    for batch in batches:
        for e in batch:
            app.handle(e)


def test_game_demo_places_breaks_and_the_opponent_replies(capsys, monkeypatch):
    import ast

    monkeypatch.delenv(ALLOW_HEADLESS_ENV, raising=False)
    assert play.main(["--env", "Billiards9Ball-v0", "--seed", "0", "--demo", "--width", "240",
                      "--speedup", "50", "--opponent", "random"]) == 0
    out = capsys.readouterr().out
    summary = ast.literal_eval(out.split("billiards-play demo: ", 1)[1].strip())
    assert summary["shots"] >= 1 and (summary["opponent_shots"] >= 1 or summary["done"])


def test_opponent_is_refused_for_a_scene(capsys):
    assert play.main(["--env", "BilliardsOneBall-v0", "--opponent", "random", "--demo"]) == 2
    assert "only the games" in capsys.readouterr().err


def test_ball_in_hand_drag_and_click_map_to_the_placement_dims():
    from billiards_env.physics.layout import head_string_x

    app = play.PlayApp("Billiards9Ball-v0", seed=0, width=400, speedup=50.0, realtime=False, allow_headless=True,
                       opponent="random")
    core = app.core
    assert app.in_hand() and app.place is not None
    kitchen_x = head_string_x(core.table)
    # a click (no drag) on an empty spot of the kitchen puts the cue ball there
    spot = tuple(int(v) for v in core.renderer.to_pixels(np.array([0.4, 0.3]))[0])
    _feed(app, [[E(pygame.MOUSEMOTION, pos=spot, rel=(0, 0), buttons=(0, 0, 0))]] + _press_release(spot))
    assert app.place == pytest.approx(core.legal_cue_position(*app.to_table(spot)))
    # dragging it past the head string stops it at the kitchen's edge (the nearest legal point)
    far = tuple(int(v) for v in core.renderer.to_pixels(np.array([1.5, 0.9]))[0])
    _feed(app, list(play.mouse_drag(app, app.ball_pixel(0), far)))
    r = core.config.ball_radius
    assert app.place[0] == pytest.approx(kitchen_x, abs=1e-9) and app.place[1] == pytest.approx(
        core.legal_cue_position(*app.to_table(far))[1])
    wanted = app.place
    area = core.table_state.view.place_area
    assert area == pytest.approx((r, kitchen_x, r, core.table.width - r))
    _feed(app, list(play.mouse_shot(app, 1.0)))
    assert app.shots == 1
    k = core.action_type._place_at
    a = app.last_action
    x0, x1, y0, y1 = area
    placed = (x0 + 0.5 * (a[k] + 1) * (x1 - x0), y0 + 0.5 * (a[k + 1] + 1) * (y1 - y0))
    assert placed == pytest.approx(wanted, abs=1e-6)  # the placement dims carry the spot (float32)
    app.close()


def test_calling_the_pocket_for_the_8():
    app = play.PlayApp("Billiards8Ball-v0", seed=0, width=400, speedup=50.0, realtime=False, allow_headless=True,
                       opponent="random")
    core = app.core
    pos = np.array(core.balls.pos)
    pos[0], pos[8] = (0.8, 0.4), (1.9, 0.9)
    pocketed = np.ones(16, bool)
    pocketed[[0, 8, 12]] = False  # solids cleared: the agent (solids) is on the 8; one stripe left
    pos[12] = (2.3, 0.2)
    app.reset(seed=0, options={"positions": pos, "pocketed": pocketed, "groups": ("solids", "stripes")})
    assert app.needs_pocket() and app.pocket is None
    _feed(app, list(play.mouse_shot(app, 0.5)))
    assert app.shots == 0 and "call" in app.status  # no shot without a call
    _feed(app, [_key(pygame.K_3)])
    assert app.pocket == 2
    _feed(app, _press_release(app.pocket_pixel(4)))
    assert app.pocket == 4 and app.shots == 0
    hud_frame = app.core.render_data()["hud"]
    assert hud_frame["call_pocket"]
    _feed(app, list(play.mouse_shot(app, 0.5)))
    assert app.shots == 1
    assert core.shot_from_action(app.last_action).call("pocket") == 4
    app.close()


def test_spin_keys_and_the_tip_diagram_set_the_tip():
    app = play.PlayApp("BilliardsOneBall-v0", seed=3, width=400, speedup=50.0, realtime=False, allow_headless=True,
                       spin=True)
    assert app.spin and app.core.physics.friction == "spin"
    _feed(app, [_key(pygame.K_RIGHT), _key(pygame.K_RIGHT), _key(pygame.K_UP), _key(pygame.K_DOWN),
                _key(pygame.K_DOWN)])
    assert app.tip == pytest.approx((2 * play.TIP_STEP, -play.TIP_STEP))
    (cx, cy), r = app.tip_diagram
    _feed(app, _press_release((int(cx - 0.3 * r), int(cy - 0.2 * r))))  # a click on the diagram
    assert app.tip == pytest.approx((-0.3, 0.2), abs=1.0 / r)
    assert app.shots == 0
    _feed(app, [_key(pygame.K_LEFT)] * 20)
    assert math.hypot(*app.tip) == pytest.approx(app.max_tip)  # held on the disc of legal offsets
    tip = app.tip
    _feed(app, list(play.mouse_shot(app, 0.4)))
    info = app.last_info
    assert app.shots == 1 and (info["side"], info["top"]) == pytest.approx(tip, abs=1e-6)
    app.close()


def test_two_people_take_turns():
    app = play.PlayApp("Billiards9Ball-v0", seed=0, width=300, speedup=50.0, realtime=False, allow_headless=True,
                       opponent="human")
    core = app.core
    pos = np.zeros((10, 2))
    pos[:, 0] = np.linspace(1.0, 2.3, 10)
    pos[:, 1] = 0.9
    pos[0] = (0.5, 0.3)
    app.reset(seed=0, options={"positions": pos})
    assert core.task.hud()["players"] == ("player 1", "player 2")
    cx, cy = app.ball_pixel(0)
    below = (cx, cy + 40)  # straight down into the near cushion: no contact, a foul
    _feed(app, list(play.mouse_shot(app, 0.2, target=below)))
    assert app.shots == 1 and app.opponent_shots == 0
    assert core.task.game_state.shooter == 1 and app.in_hand()  # player 2 to shoot, with the cue ball in hand
    assert "player 2 to shoot" in app.status
    app.close()
