"""Scene configuration: packaged YAML defaults, overrides, config files, and clear errors for bad values."""
from __future__ import annotations

import os
from pathlib import Path

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
import yaml  # noqa: E402

from billiards_env.envs import ENV_IDS  # noqa: E402
from billiards_env.envs.config import SCENES_DIR, ConfigError, EnvConfig, load_config  # noqa: E402
from env_helpers import IDS  # noqa: E402

REPO = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("env_id", IDS)
def test_packaged_scene_is_complete_and_mirrored(env_id):
    scene = ENV_IDS[env_id].scene
    packaged = SCENES_DIR / f"{scene}.yaml"
    data = yaml.safe_load(packaged.read_text())
    assert set(data) == set(EnvConfig.keys()), "the scene YAML lists every config key, and only those"
    user_copy = REPO / "configs" / "envs" / f"{scene}.yaml"
    assert user_copy.read_text() == packaged.read_text(), f"{user_copy} must mirror {packaged}"
    env = gym.make(env_id)
    assert env.unwrapped.config == EnvConfig(**data)
    env.close()


def test_scene_defaults_per_id():
    one = gym.make("BilliardsOneBall-v0").unwrapped
    three = gym.make("BilliardsThreeBalls-v0").unwrapped
    rack = gym.make("BilliardsRack-v0").unwrapped
    assert (one.n_balls, one.config.single_shot) == (2, True)
    assert (three.n_balls, three.config.max_shots, three.config.single_shot) == (4, 15, False)
    assert (rack.n_balls, rack.config.placement, rack.config.max_shots) == (16, "rack", 50)


def test_keyword_overrides_change_the_env():
    env = gym.make("BilliardsOneBall-v0", speed_min=1.0, speed_max=3.0, aim="relative", mu_roll=0.02).unwrapped
    assert env.config.speed_max == 3.0 and env.physics.mu_roll == 0.02
    env.reset(seed=0)
    assert env.shot_from_action([0.0, 1.0])[1] == pytest.approx(3.0)
    assert env.shot_from_action([0.0, -1.0])[1] == pytest.approx(1.0)


def test_config_file_layers_over_defaults(tmp_path):
    path = tmp_path / "two_balls.yaml"
    path.write_text("n_object_balls: 2\nmax_shots: 4\nsingle_shot: false\n")
    env = gym.make("BilliardsOneBall-v0", config=str(path), max_shots=6)
    obs, _ = env.reset(seed=1)
    assert obs.shape == (9,) and env.observation_space.shape == (9,)
    assert env.unwrapped.config.max_shots == 6  # keyword beats file
    assert env.unwrapped.config.speed_max == 5.0  # untouched default from the id's scene
    env.close()


def test_config_mapping_and_load_config():
    cfg = load_config("three_balls", {"n_object_balls": 5}, speed_max=4)
    assert cfg.n_object_balls == 5 and cfg.speed_max == 4.0 and isinstance(cfg.speed_max, float)


@pytest.mark.parametrize("kwargs, key, hint", [
    ({"speed_mx": 3.0}, "speed_mx", "speed_max"),
    ({"speed_min": -1.0}, "speed_min", ">= 0"),
    ({"speed_min": 3.0, "speed_max": 2.0}, "speed_max", "greater than speed_min"),
    ({"max_shots": 0}, "max_shots", ">= 1"),
    ({"max_shots": "ten"}, "max_shots", "integer"),
    ({"aim": "sideways"}, "aim", "'relative'"),
    ({"friction": "sticky"}, "friction", "'rolling'"),
    ({"n_object_balls": 16}, "n_object_balls", "1..15"),
    ({"angle_noise": float("nan")}, "angle_noise", "finite"),
    ({"scratch_penalty": -1.0}, "scratch_penalty", "positive value is subtracted"),
    ({"ball_restitution": 1.5}, "ball_restitution", "[0, 1]"),
    ({"single_shot": 1}, "single_shot", "true or false"),
    ({"render_width": 10}, "render_width", "64"),
])
def test_bad_config_values_raise_clear_errors(kwargs, key, hint):
    with pytest.raises(ConfigError) as exc:
        gym.make("BilliardsOneBall-v0", **kwargs)
    msg = str(exc.value)
    assert key in msg and hint in msg, msg


def test_bad_config_files(tmp_path):
    with pytest.raises(ConfigError, match="cannot read"):
        gym.make("BilliardsOneBall-v0", config=str(tmp_path / "missing.yaml"))
    bad = tmp_path / "bad.yaml"
    bad.write_text("placement: random\nballs: 3\n")
    with pytest.raises(ConfigError, match=r"unknown config key 'balls' \(from .*bad.yaml\)"):
        gym.make("BilliardsOneBall-v0", config=str(bad))
    notmap = tmp_path / "list.yaml"
    notmap.write_text("- 1\n- 2\n")
    with pytest.raises(ConfigError, match="mapping"):
        gym.make("BilliardsOneBall-v0", config=str(notmap))


def test_infeasible_layouts_fail_at_make_time():
    with pytest.raises(ConfigError, match="could not place"):
        gym.make("BilliardsThreeBalls-v0", n_object_balls=15, ball_gap=0.5)
    with pytest.raises(ConfigError, match="pocket_margin"):
        gym.make("BilliardsOneBall-v0", pocket_margin=0.01)
    with pytest.raises(ConfigError, match="rack_gap"):
        gym.make("BilliardsRack-v0", rack_gap=0.2)


def test_rack_layout_is_the_standard_triangle():
    env = gym.make("BilliardsRack-v0").unwrapped
    env.reset(seed=0)
    b = env.balls
    c = env.config
    assert np.allclose(b.pos[0], (c.table_length / 4, c.table_width / 2))  # head spot
    assert np.allclose(b.pos[1], (0.75 * c.table_length, c.table_width / 2))  # 1-ball on the foot spot (apex)
    third_row_middle = 0.75 * c.table_length + 2 * (2 * c.ball_radius) * np.sqrt(3) / 2
    assert np.allclose(b.pos[8], (third_row_middle, c.table_width / 2))  # 8-ball in the middle of row 3
    d = np.linalg.norm(b.pos[1:, None] - b.pos[None, 1:], axis=-1) + np.eye(15)
    assert d.min() == pytest.approx(2 * c.ball_radius, rel=1e-9)  # touching, no overlap


def test_config_errors_are_value_errors_and_the_table_lists_every_key():
    from billiards_env.envs.config import config_table_markdown

    assert issubclass(ConfigError, ValueError)
    table = config_table_markdown()
    assert all(f"`{key}`" in table for key in EnvConfig.keys())
