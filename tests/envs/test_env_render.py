"""Rendering through the envs: frames, ball colours, shot animations, human window, GIF recording."""
from __future__ import annotations

import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from billiards_env.render import colors, frame_times  # noqa: E402
from env_helpers import FAST_RENDER, IDS, L, W, corner_pot_scene  # noqa: E402


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
    assert info["pocketed"] == ("1",)
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


def test_render_without_mode_warns_and_returns_none():
    env = gym.make("BilliardsOneBall-v0")
    env.reset(seed=0)
    with pytest.warns(UserWarning, match="render_mode"):
        assert env.unwrapped.render() is None


def test_record_episode_gif(tmp_path):
    from PIL import Image

    from billiards_env.envs.recording import record_episode_gif

    out = record_episode_gif("BilliardsOneBall-v0", lambda obs: np.array([0.3, 0.2], np.float32),
                             tmp_path / "ep.gif", seed=1, fps=10, render_width=120, render_speedup=4.0)
    assert out["shots"] == 1 and out["frames"] > 2
    with Image.open(out["path"]) as im:
        assert im.format == "GIF" and im.n_frames > 2 and im.size[0] == 120
    env = gym.make("BilliardsOneBall-v0", render_mode="rgb_array")
    with pytest.raises(ValueError, match="rgb_array_list"):
        record_episode_gif(env, None, tmp_path / "x.gif", seed=0, fps=10)
