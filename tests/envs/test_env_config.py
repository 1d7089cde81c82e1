"""Scene configuration: packaged YAML defaults, overrides, config files, and clear errors for bad values."""
from __future__ import annotations

import os
from pathlib import Path

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
import yaml  # noqa: E402

from billiards_env.envs import ENV_CLASSES  # noqa: E402
from billiards_env.envs.config import SCENES_DIR, ConfigError, EnvConfig, load_config  # noqa: E402
from env_helpers import IDS  # noqa: E402

REPO = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("env_id", IDS)
def test_packaged_scene_holds_only_what_differs_from_the_defaults(env_id):
    scene = ENV_CLASSES[env_id].scene
    data = yaml.safe_load((SCENES_DIR / f"{scene}.yaml").read_text())
    defaults = EnvConfig().to_dict()
    assert data and set(data) <= set(defaults), "scene keys are config keys"
    assert all(data[k] != defaults[k] for k in data), "a key equal to its default does not belong in the scene file"
    env = gym.make(env_id)
    assert env.unwrapped.config == EnvConfig.from_mapping(data)
    env.close()


def test_user_configs_are_partial_layers_and_the_readme_points_to_the_packaged_scenes():
    readme = (REPO / "configs" / "envs" / "README.md").read_text()
    assert "billiards_env/envs/scenes" in readme
    for path in sorted((REPO / "configs" / "envs").glob("*.yaml")):
        env = gym.make("BilliardsThreeBalls-v0", config=str(path)).unwrapped
        data = yaml.safe_load(path.read_text())
        assert env.config.n_object_balls == data.get("n_object_balls", 3)
        if "table" in data:
            assert env.table.length == data["table"].get("length", env.table.length)
        env.close()


def test_one_schema_for_scene_files_and_env_configs():
    """The table/physics/solver sections of an env config are a scene file's, with the same defaults."""
    from billiards_env.physics.scene import Scene

    scene = Scene.from_dict({"balls": [{"x": 0.5, "y": 0.5}]})
    cfg = EnvConfig()
    assert cfg.table == scene.table and cfg.physics == scene.physics
    assert (cfg.solver.name, cfg.solver.dt, cfg.solver.contact) == (scene.solver, scene.dt, scene.contact)
    assert (cfg.max_time, cfg.max_events) == (scene.max_time, scene.max_events)
    sec = {"table": {"length": 2.84, "width": 1.42, "corner_pocket_radius": 0.07},
           "physics": {"friction": "drag", "drag_k": 0.2, "min_speed": 0.01}, "solver": {"name": "step", "dt": 0.002}}
    scene = Scene.from_dict({**sec, "balls": [{"x": 0.5, "y": 0.5}]})
    env = gym.make("BilliardsOneBall-v0", **sec).unwrapped
    assert env.table == scene.table and env.physics == scene.physics
    assert (env.simulator.solver, env.simulator.dt) == ("step", 0.002)
    # a physics field on its own is the physics section's
    assert gym.make("BilliardsOneBall-v0", mu_roll=0.02).unwrapped.physics.mu_roll == 0.02
    # the old flat table keys say where they went
    with pytest.raises(ConfigError, match=r"table_length.*table=\{'length'"):
        gym.make("BilliardsOneBall-v0", table_length=3.0)


@pytest.mark.parametrize("env_id", IDS)
def test_unknown_keyword_is_a_type_error_in_pythons_words(env_id):
    """gym.make(id, frameskip=4) fails as Python fails on an unexpected keyword (a TypeError: wrappers such as
    TorchRL's GymEnv try frameskip and fall back on a TypeError), still a ConfigError (a ValueError) with the
    closest key and the list of valid keys."""
    with pytest.raises(TypeError, match="unexpected keyword argument") as got:
        gym.make(env_id, frameskip=4)
    err = got.value
    assert isinstance(err, TypeError) and isinstance(err, ValueError) and isinstance(err, ConfigError)
    assert str(err).startswith("__init__() got an unexpected keyword argument 'frameskip'")
    assert "valid keys:" in str(err) and "max_shots" in str(err)
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'max_shot'; did you mean 'max_shots'\?"):
        gym.make(env_id, max_shot=3)
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'table_length': it is now table="):
        gym.make(env_id, table_length=3.0)
    with pytest.raises(TypeError, match="unexpected keyword argument 'frameskip'"):  # the native vector env too
        gym.make_vec(env_id, 2, vectorization_mode="vector_entry_point", frameskip=4)


def test_unknown_key_in_a_file_or_mapping_stays_a_config_error(tmp_path):
    """Only keyword arguments are Python's TypeError; a key in a mapping or a file is a plain ConfigError."""
    with pytest.raises(ConfigError, match=r"unknown config key 'frameskip' \(from config\)") as got:
        gym.make("BilliardsOneBall-v0", config={"frameskip": 4})
    assert not isinstance(got.value, TypeError)


def test_scene_defaults_per_id():
    one = gym.make("BilliardsOneBall-v0").unwrapped
    three = gym.make("BilliardsThreeBalls-v0").unwrapped
    rack = gym.make("BilliardsRack-v0").unwrapped
    assert (one.n_balls, one.config.single_shot) == (2, True)
    assert (three.n_balls, three.config.max_shots, three.config.single_shot) == (4, 15, False)
    assert (rack.n_balls, rack.config.placement, rack.config.max_shots) == (16, "rack", 50)


def test_keyword_overrides_change_the_env():
    env = gym.make("BilliardsOneBall-v0", speed_min=1.0, speed_max=3.0, action_type="relative", mu_roll=0.02).unwrapped
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
    ({"action_type": "sideways"}, "action_type", "'relative'"),
    ({"friction": "sticky"}, "friction", "rolling"),
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
    t = env.table
    assert np.allclose(b.pos[0], (t.length / 4, t.width / 2))  # head spot
    assert np.allclose(b.pos[1], (0.75 * t.length, t.width / 2))  # 1-ball on the foot spot (apex)
    third_row_middle = 0.75 * t.length + 2 * (2 * c.ball_radius) * np.sqrt(3) / 2
    assert np.allclose(b.pos[8], (third_row_middle, t.width / 2))  # 8-ball in the middle of row 3
    d = np.linalg.norm(b.pos[1:, None] - b.pos[None, 1:], axis=-1) + np.eye(15)
    assert d.min() == pytest.approx(2 * c.ball_radius, rel=1e-9)  # touching, no overlap


def test_config_errors_are_value_errors_and_the_table_lists_every_key():
    from billiards_env.envs.config import config_table_markdown

    assert issubclass(ConfigError, ValueError)
    table = config_table_markdown()
    assert all(f"`{key}`" in table for key in EnvConfig.keys())
