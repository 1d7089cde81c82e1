"""Gymnasium/SB3 API conformance of every registered id, in every render mode, and vectorisation."""
from __future__ import annotations

import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from gymnasium.utils.env_checker import check_env as gym_check_env  # noqa: E402
from stable_baselines3.common.env_checker import check_env as sb3_check_env  # noqa: E402

from env_helpers import FAST_RENDER, GAME_IDS, IDS, RENDER_MODES  # noqa: E402


@pytest.mark.parametrize("env_id", IDS)
@pytest.mark.parametrize("render_mode", [None] + RENDER_MODES)
def test_env_checkers_pass(env_id, render_mode):
    env = gym.make(env_id, render_mode=render_mode, **FAST_RENDER)
    try:
        gym_check_env(env.unwrapped)  # also makes and renders every declared render mode from the spec
        sb3_check_env(env.unwrapped, warn=True, skip_render_check=render_mode is None)
    finally:
        env.close()


@pytest.mark.parametrize("env_id", IDS)
def test_spaces_and_types(env_id):
    env = gym.make(env_id)
    n = env.unwrapped.n_balls
    game = env_id in GAME_IDS
    # aim, power (+ side, top with spin dims) (+ place with ball in hand) (+ the game's declarations, in order)
    u = env.unwrapped
    names = ["aim", "power"] + (["side", "top"] if u.action_type.spin else []) \
        + (["place_x", "place_y"] if game and u.task.session.ball_in_hand else []) \
        + ([d.name for d in u.task.session.declarations] if game else [])
    assert u.action_type.layout() == ", ".join(names)
    # pinned for the games whose layouts the docs print (a game registered later follows its declarations)
    n_act = {"Billiards9Ball-v0": 4, "Billiards8Ball-v0": 5, "BilliardsSnooker-v0": 4,
             "BilliardsThreeCushion-v0": 4}.get(env_id, len(names) if game else 2)
    n_obs = 3 * n + (env.unwrapped.task.n_features if game else 0)  # positions, pocketed flags (+ the game's)
    assert (env.unwrapped.task.n_features > 0) == game
    assert env.action_space == gym.spaces.Box(-1, 1, (n_act,), np.float32)
    assert env.observation_space == gym.spaces.Box(0, 1, (n_obs,), np.float32)
    obs, info = env.reset(seed=3)
    assert obs.dtype == np.float32 and obs.shape == (n_obs,) and env.observation_space.contains(obs)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
    assert env.observation_space.contains(obs)
    assert type(reward) is float and type(terminated) is bool and type(truncated) is bool
    for key in ("is_success", "pocketed", "scratch", "first_contact", "n_events", "sim_time", "status"):
        assert key in info, key
    for flag in ("is_success", "scratch"):  # flags: 0-d boolean arrays (a dtype each, stacked as bool by vector envs)
        assert type(info[flag]) is np.ndarray and info[flag].dtype == np.bool_ and info[flag].shape == ()
    assert info["status"] in (0, 1, 2) and -1 <= info["first_contact"] < n
    assert info["pocketed"].dtype == np.bool_ and info["pocketed"].shape == (n,)
    assert info["sim_time"] > 0 and info["n_events"] >= 1
    env.close()


@pytest.mark.parametrize("env_id", IDS)
@pytest.mark.parametrize("mode", ["sync", "async"])
def test_make_vec(env_id, mode):
    envs = gym.make_vec(env_id, num_envs=2, vectorization_mode=mode)
    try:
        obs, _ = envs.reset(seed=[1, 2])
        n = envs.single_observation_space.shape[0]
        assert obs.shape == (2, n) and obs.dtype == np.float32
        assert not np.array_equal(obs[0], obs[1]) or env_id not in ("BilliardsOneBall-v0", "BilliardsThreeBalls-v0")
        for k in range(3):  # crosses an episode end of the one-shot env (next-step auto-reset)
            obs, rew, term, trunc, info = envs.step(envs.action_space.sample())
            assert obs.shape == (2, n) and rew.shape == (2,) and term.dtype == bool
            assert np.all((obs >= 0) & (obs <= 1))
            if k == 0:
                assert "is_success" in info and info["is_success"].shape == (2,)
    finally:
        envs.close()


def test_registered_ids_and_docstrings():
    from billiards_env.envs import ENV_CLASSES
    from billiards_env.registration import ENV_IDS

    assert set(ENV_CLASSES) == set(ENV_IDS)  # every registered id has its class, and no class is unregistered
    for env_id, cls in ENV_CLASSES.items():
        assert gym.spec(env_id).entry_point.endswith(cls.__name__)
        doc = cls.__doc__
        for section in ("## Description", "## Action Space", "## Observation Space", "## Rewards",
                        "## Starting State", "## Episode End", "## Arguments", "## Version History"):
            assert section in doc, f"{cls.__name__} docstring lacks {section}"


def test_training_path_does_not_import_pygame(monkeypatch):
    """Training needs no display: making, resetting and stepping without a render mode never imports pygame
    or the renderer (both are made unimportable here; any import would raise)."""
    import sys

    for name in ("pygame", "billiards_env.render", "billiards_env.render.table_renderer",
                 "billiards_env.render.window"):
        monkeypatch.setitem(sys.modules, name, None)
    for env_id in IDS:
        env = gym.make(env_id)
        env.reset(seed=0)
        env.step(env.action_space.sample())
        env.close()
    env = gym.make("BilliardsOneBall-v0", render_mode="rgb_array")
    env.reset(seed=0)
    with pytest.raises(ImportError):  # the guard works: rendering does need the import
        env.render()
