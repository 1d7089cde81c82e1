"""Rendering through the envs: frames, ball colours, shot animations, human window, GIF recording."""
from __future__ import annotations

import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from billiards_env.render import colors, frame_times  # noqa: E402
from env_helpers import FAST_RENDER, IDS, L, corner_pot_scene, scratch_scene  # noqa: E402


@pytest.mark.parametrize("env_id", IDS)
def test_rgb_array_frame(env_id):
    env = gym.make(env_id, render_mode="rgb_array", render_width=240)
    env.reset(seed=0)
    frame = env.render()
    assert isinstance(frame, np.ndarray) and frame.dtype == np.uint8 and frame.ndim == 3
    assert frame.shape[1] == 240 and frame.shape[2] == 3
    assert frame.shape == env.render().shape
    env.close()


def test_pixel_at_each_ball_centre_has_its_colour():
    env = gym.make("BilliardsThreeBalls-v0", render_mode="rgb_array", render_width=800).unwrapped
    pos = np.array([[0.5, 0.4], [1.2, 0.9], [1.9, 0.3], [2.1, 1.0]])
    env.reset(seed=0, options={"positions": pos})
    frame = env.render()
    pixels = env.renderer.to_pixels(pos)
    for number, (col, row) in zip(env.ball_numbers, pixels):
        assert tuple(frame[row, col]) == colors.ball_colour(number), f"ball {number}"
    # a pocketed ball is no longer drawn on the cloth
    env.reset(seed=0, options={"positions": pos, "pocketed": [False, True, False, False]})
    frame = env.render()
    col, row = pixels[1]
    assert tuple(frame[row, col]) != colors.ball_colour(1)


def test_shot_animation_frames_and_final_state():
    pos, angle, speed = corner_pot_scene()
    kw = {"render_width": 200, "render_fps": 10}
    anim = gym.make("BilliardsOneBall-v0", render_mode="rgb_array_list", **kw)
    still = gym.make("BilliardsOneBall-v0", render_mode="rgb_array", **kw)
    for env in (anim, still):
        env.reset(seed=0, options={"positions": pos})
    first = anim.render()
    assert len(first) == 1 and np.array_equal(first[0], still.render())  # the reset frame
    assert anim.render() == []  # popped
    action = anim.unwrapped.action_from_shot(angle, speed)
    info = anim.step(action)[4]
    still.step(action)
    frames = anim.render()
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert w["pocketed"] == ("1",)
    assert len(frames) == len(frame_times(info["sim_time"], 10)) > 2
    assert np.array_equal(frames[-1], still.render())  # the animation ends on the state after the shot
    assert not np.array_equal(frames[0], frames[-1])  # and the balls moved in between
    anim.close()
    still.close()


def test_render_speedup_reduces_frames():
    env = gym.make("BilliardsOneBall-v0", render_mode="rgb_array_list", render_width=64, render_fps=10,
                   render_speedup=4.0)
    pos, angle, speed = corner_pot_scene()
    env.reset(seed=0, options={"positions": pos})
    env.render()
    info = env.step(env.unwrapped.action_from_shot(angle, speed))[4]
    assert len(env.render()) == len(frame_times(info["sim_time"] / 4.0, 10))


def test_cue_of_last_shot_is_drawn():
    env = gym.make("BilliardsOneBall-v0", render_mode="rgb_array", render_width=200)
    pos = np.array([[0.6, 0.6], [2.0, 0.3]])
    env.reset(seed=0, options={"positions": pos})
    empty = env.render()
    env.step(env.unwrapped.action_from_shot(np.pi / 2, 0.6))
    after = env.render()
    assert env.unwrapped.last_shot[:3] == (0.6, 0.6, pytest.approx(np.pi / 2))
    # the stick lies behind the shot's start point (below it: the shot went up)
    col, row = env.unwrapped.renderer.to_pixels(np.array([0.6, 0.6 - 0.3]))[0]
    assert not np.array_equal(after[row, col], empty[row, col])


def test_human_mode_opens_animates_and_closes():
    import pygame

    env = gym.make("BilliardsOneBall-v0", render_mode="human", **FAST_RENDER)
    env.reset(seed=0)
    assert pygame.display.get_init() and pygame.display.get_surface() is not None
    assert env.render() is None
    env.step(np.array([0.1, 0.0], dtype=np.float32))
    env.close()
    assert not pygame.display.get_init()
    env.close()  # twice is fine


def test_human_mode_shows_each_frame_as_it_is_drawn(monkeypatch):
    """No frames are rendered ahead: draw, show, draw, show... through the whole shot."""
    from billiards_env.render import HumanWindow

    pos, angle, speed = corner_pot_scene()
    env = gym.make("BilliardsOneBall-v0", render_mode="human", render_width=120, render_fps=1000,
                   render_speedup=20.0)
    env.reset(seed=0, options={"positions": pos})
    log: list[str] = []
    renderer = env.unwrapped.renderer
    draw, show = renderer.draw, HumanWindow.show
    renderer.draw = lambda *a, **k: (log.append("draw"), draw(*a, **k))[1]
    monkeypatch.setattr(HumanWindow, "show", lambda self, *a, **k: (log.append("show"), show(self, *a, **k))[1])
    env.step(env.unwrapped.action_from_shot(angle, speed))
    env.close()
    assert log.count("draw") > 5
    assert log == ["draw", "show"] * (len(log) // 2)


def test_human_mode_without_a_display_says_what_to_do(monkeypatch):
    from billiards_env.render.window import ALLOW_HEADLESS_ENV, HeadlessDisplayError

    monkeypatch.delenv(ALLOW_HEADLESS_ENV, raising=False)
    monkeypatch.delenv("SDL_VIDEODRIVER", raising=False)  # SDL_VIDEODRIVER=dummy would ask for an invisible window
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    monkeypatch.setenv("DISPLAY", ":97")  # no X server there: pygame would fall back to 'offscreen' silently
    env = gym.make("BilliardsOneBall-v0", render_mode="human", render_width=120)
    with pytest.raises(HeadlessDisplayError, match="render_mode='human' needs a display.*rgb_array"):
        env.reset(seed=0)
    env.close()


def test_render_without_mode_warns_and_returns_none():
    env = gym.make("BilliardsOneBall-v0")
    env.reset(seed=0)
    with pytest.warns(UserWarning, match="render_mode"):
        assert env.unwrapped.render() is None


def test_record_gif_several_seeds_into_one_gif(tmp_path):
    from PIL import Image

    from billiards_env.envs.recording import record_gif

    policy = lambda obs: np.array([0.3, 0.2], np.float32)  # noqa: E731
    out = record_gif("BilliardsOneBall-v0", policy, tmp_path / "ep.gif", seeds=[1, 2, 3], width=120, fps=10,
                     speedup=4.0, max_frames_per_shot=8, hold_frames=3)
    assert out["episodes"] == [1, 2, 3] and out["shots"] == [1, 1, 1] and out["fps"] == 10
    # per episode: the reset frame, at most 8 frames of the shot, 3 held frames
    assert 3 * (1 + 2 + 3) <= out["frames"] <= 3 * (1 + 8 + 3)
    assert out["seconds"] == pytest.approx(out["frames"] / 10)
    # the returns and successes are those of the same episodes played without recording
    plain = gym.make("BilliardsOneBall-v0")
    for seed, ret, ok in zip(out["episodes"], out["returns"], out["successes"]):
        plain.reset(seed=seed)
        _, reward, _, _, info = plain.step(policy(None))
        assert (ret, ok) == (reward, info["is_success"])
    with Image.open(out["path"]) as im:
        assert im.format == "GIF" and im.n_frames > 6 and im.size[0] == 120
        assert im.info["duration"] == 100  # 10 fps
    again = record_gif("BilliardsOneBall-v0", policy, tmp_path / "again.gif", seeds=[1, 2, 3], width=120, fps=10,
                       speedup=4.0, max_frames_per_shot=8, hold_frames=3)
    assert again["path"].read_bytes() == out["path"].read_bytes()  # deterministic


def test_record_gif_caps_frames_per_shot_and_holds_the_end(tmp_path):
    from billiards_env.envs.recording import record_gif

    pos, angle, speed = corner_pot_scene()
    env = gym.make("BilliardsOneBall-v0", render_mode="rgb_array_list", render_width=64, render_fps=20)
    action = env.unwrapped.action_from_shot(angle, speed)
    env.reset(seed=0)
    env.render()
    env.step(action)
    full = len(env.render())
    assert full > 12  # a real-time shot at 20 fps: many frames
    out = record_gif(env, lambda obs: action, tmp_path / "capped.gif", seeds=0, max_frames_per_shot=12,
                     hold_frames=5)
    assert out["frames"] == 1 + 12 + 5 and out["fps"] == 20
    uncapped = record_gif(env, lambda obs: action, tmp_path / "full.gif", seeds=0, max_frames_per_shot=None,
                          hold_frames=0)
    assert uncapped["frames"] == 1 + full
    env.close()


def test_record_gif_defaults_are_light():
    from billiards_env.envs.recording import GIF_RENDER, HOLD_FRAMES, MAX_FRAMES_PER_SHOT

    assert GIF_RENDER["render_width"] <= 400 and GIF_RENDER["render_speedup"] >= 2
    assert MAX_FRAMES_PER_SHOT / GIF_RENDER["render_fps"] <= 3.0  # at most 3 s of GIF per shot
    assert HOLD_FRAMES / GIF_RENDER["render_fps"] <= 2.0


def test_record_gif_rejects_bad_use(tmp_path):
    from billiards_env.envs.recording import record_gif

    env = gym.make("BilliardsOneBall-v0", render_mode="rgb_array")
    with pytest.raises(ValueError, match="rgb_array_list"):
        record_gif(env, None, tmp_path / "x.gif", seeds=0)
    listing = gym.make("BilliardsOneBall-v0", render_mode="rgb_array_list")
    with pytest.raises(ValueError, match="width.*when you make the env"):
        record_gif(listing, None, tmp_path / "x.gif", seeds=0, width=200)
    with pytest.raises(ValueError, match="max_frames_per_shot"):
        record_gif("BilliardsOneBall-v0", None, tmp_path / "x.gif", max_frames_per_shot=1)
    with pytest.raises(ValueError, match="seeds is empty"):
        record_gif("BilliardsOneBall-v0", None, tmp_path / "x.gif", seeds=[])


# --- spin and games: the tip diagram, turning balls, the game panel ---------------------------------------------
def _red_in(frame: np.ndarray, box: tuple[int, int, int, int]) -> np.ndarray:
    """Columns and rows of the tip's red dot inside ``box`` (x0, y0, x1, y1)."""
    from billiards_env.render.overlays import TIP_DOT

    x0, y0, x1, y1 = box
    rows, cols = np.nonzero(np.all(np.abs(frame[y0:y1, x0:x1].astype(int) - TIP_DOT) < 50, axis=-1))
    return np.stack([cols + x0, rows + y0], axis=1)


def _diagram_box(renderer) -> tuple[tuple[float, float], float, tuple[int, int, int, int]]:
    (cx, cy), r = renderer.tip_diagram
    return (cx, cy), r, (int(cx - r - 2), int(cy - r - 2), int(cx + r + 3), int(cy + r + 3))


@pytest.mark.parametrize("env_id", ["BilliardsOneBall-v0", "BilliardsRack-v0"])
def test_pot_frames_are_unchanged_by_the_game_and_spin_marks(env_id):
    """Without spin and a HUD the env draws exactly what the plain renderer draws (no panel, no diagram)."""
    from billiards_env.render import TableRenderer

    env = gym.make(env_id, render_mode="rgb_array", render_width=300).unwrapped
    env.reset(seed=2)
    env.step(np.array([0.3, 0.1], np.float32))
    plain = TableRenderer(env.table, env.config.ball_radius, width_px=300)
    b = env.balls
    expected = plain.render_array(b.pos, b.on_table, env.ball_numbers, cue=env.last_shot[:3])
    np.testing.assert_array_equal(env.render(), expected)
    assert env.task.hud() is None and env.renderer.hud_height_px == 0


def test_game_frames_have_the_panel():
    from billiards_env.render.hud import panel_height

    pot = gym.make("BilliardsRack-v0", render_mode="rgb_array", render_width=320)
    pot.reset(seed=0)
    for game in ("Billiards9Ball-v0", "Billiards8Ball-v0"):
        env = gym.make(game, render_mode="rgb_array", render_width=320)
        env.reset(seed=0)
        assert env.render().shape == (pot.render().shape[0] + panel_height(320), 320, 3)


def test_spin_env_shows_the_tip_of_the_last_shot():
    env = gym.make("BilliardsOneBall-v0", render_mode="rgb_array", render_width=600, friction="spin",
                   spin_action=True).unwrapped
    pos = np.array([[0.6, 0.4], [2.0, 1.0]])
    env.reset(seed=0, options={"positions": pos})
    centre, r, box = _diagram_box(env.renderer)
    np.testing.assert_allclose(_red_in(env.render(), box).mean(axis=0), centre, atol=1.0)  # no shot yet: centre
    env.step(env.action_from_shot(0.0, 1.0, side=0.3, top=-0.2))
    dot = _red_in(env.render(), box).mean(axis=0)
    assert dot[0] > centre[0] + 0.2 * r and dot[1] > centre[1] + 0.1 * r  # right (english) and low (draw)
    plain = gym.make("BilliardsOneBall-v0", render_mode="rgb_array", render_width=600).unwrapped
    plain.reset(seed=0, options={"positions": pos})
    assert len(_red_in(plain.render(), box)) == 0  # no spin model: no diagram


def _patches(frames, renderer, centres, radius_px):
    k = int(radius_px)
    out = []
    for frame, (col, row) in zip(frames, renderer.to_pixels(centres)):
        out.append(frame[row - k:row + k + 1, col - k:col + k + 1].astype(int))
    return out


@pytest.mark.parametrize("friction", ["spin", "rolling"])
def test_a_rolling_ball_turns_between_frames_only_under_the_spin_model(friction):
    """The cue ball rolls across the table: under the spin model its dots turn from frame to frame; without it
    (and for a ball at rest) the ball looks the same in every frame."""
    pos = np.array([[0.5, 0.45], [2.2, 1.05]])
    env = gym.make("BilliardsOneBall-v0", render_mode="rgb_array_list", render_width=800, render_fps=10,
                   render_speedup=2.0, friction=friction).unwrapped
    env.reset(seed=0, options={"positions": pos})
    env.render()
    res = env.simulator.run(env.balls.copy().strike(0, 0.0, 1.2), record=True)
    env.step(env.action_from_shot(0.0, 1.2))
    frames = env.render()[:-1]
    xy, on = res.trajectory.sample(env.animation_times(res.time)[:-1])
    assert len(frames) == len(xy) > 4 and on[:, 0].all()
    rpx = 0.7 * env.config.ball_radius * env.renderer.pixels_per_metre
    cue = _patches(frames, env.renderer, xy[:, 0], rpx)
    # frames of the ball rolling, away from the cue stick (it lies left of the start point, drawn over the balls)
    moving = [k for k in range(len(xy) - 1)
              if np.hypot(*(xy[k + 1, 0] - xy[k, 0])) > 0.01 and min(xy[k, 0, 0], xy[k + 1, 0, 0]) > 0.9]
    assert len(moving) >= 3
    changed = [np.any(cue[k] != cue[k + 1]) for k in moving]
    if friction == "spin":
        assert np.mean(changed) > 0.8
    else:
        assert not any(changed)
    still = _patches(frames, env.renderer, xy[:, 1], rpx)  # ball 1 is never touched
    assert all(np.array_equal(still[0], p) for p in still)


def test_game_hud_data_follows_the_game():
    env = gym.make("Billiards9Ball-v0", opponent=None).unwrapped
    env.reset(seed=0)
    hud = env.task.hud()
    assert hud["game"] == "9-ball" and hud["players"] == ("agent", "nobody") and hud["shooter"] == 0
    assert hud["ball_in_hand"] == "kitchen" and hud["kitchen_x"] == pytest.approx(L / 4)
    assert hud["targets"] == (1,) and hud["call"] is None and hud["wins"] == (0, 0)
    pos, angle, speed = corner_pot_scene()
    full = np.zeros((10, 2))
    full[:, 0] = np.linspace(0.3, 2.2, 10)
    full[:, 1] = 0.15
    full[0], full[9] = pos[0], pos[1]
    pocketed = np.ones(10, bool)
    pocketed[[0, 9]] = False
    env.reset(seed=0, options={"positions": full, "pocketed": pocketed})
    info = env.step(env.action_from_shot(angle, speed))[4]
    hud = env.task.hud()
    assert info["winner"] == 0 and hud["winner"] == 0 and hud["shooter"] is None
    assert hud["call"] == "9 pocketed: agent wins" and not hud["foul"]
    assert hud["wins"] == (1, 0) and hud["pocketed"] == ((9,), ())
    cue, _, _ = scratch_scene()
    full[0] = cue[0]
    env.reset(seed=0, options={"positions": full, "pocketed": pocketed})
    env.step(env.action_from_shot(-3 * np.pi / 4, 1.5))
    hud = env.task.hud()
    assert hud["call"] == "FOUL: scratch (agent)" and hud["foul"] and hud["wins"] == (1, 0)
    assert hud["pocketed"] == ((), ())  # a new game


def test_game_animation_shows_whose_shot_it_is():
    """The panel of each animated shot shows its shooter: the agent's miss, then the opponent's reply."""
    from billiards_env.render.hud import TURN, turn_marker

    env = gym.make("Billiards9Ball-v0", opponent="random", render_mode="rgb_array_list", render_width=400,
                   render_fps=10, render_speedup=8.0).unwrapped
    full = np.zeros((10, 2))
    full[:, 0] = np.linspace(1.0, 2.3, 10)
    full[:, 1] = 0.9
    full[0] = (0.5, 0.3)
    env.reset(seed=4, options={"positions": full})
    env.render()
    info = env.step(env.action_from_shot(-np.pi / 2, 0.8))[4]  # straight into the near cushion: no contact
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert w["foul_reason"] == "no contact" and info["opponent_shots"] >= 1
    frames = env.render()
    rect = env.renderer.hud_rect
    marks = []
    for frame in frames[:-1]:
        lit = []
        for p in (0, 1):
            x, y, _ = turn_marker(rect, p)
            lit.append(tuple(frame[int(round(y)), int(round(x))]) == TURN)
        marks.append(lit)
    assert marks[0] == [True, False]  # the agent's shot
    assert marks[-1] == [False, True]  # the opponent's
    changes = sum(a != b for a, b in zip(marks, marks[1:]))
    assert changes >= 1


def test_kitchen_is_marked_only_with_the_cue_ball_in_hand_behind_the_head_string():
    env = gym.make("Billiards9Ball-v0", render_mode="rgb_array", render_width=500).unwrapped
    env.reset(seed=0)
    in_kitchen = env.render()
    env.reset(seed=0, options={"positions": env.balls.pos.copy(), "ball_in_hand": "anywhere"})
    anywhere = env.render()
    col, row = env.renderer.to_pixels(np.array([L / 4, 0.3]))[0]
    assert int(in_kitchen[row, col].sum()) > int(anywhere[row, col].sum()) + 120
