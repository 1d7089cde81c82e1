"""Stable-Baselines3 and Gymnasium: both env checkers, ``gym.make_vec``, and a few hundred steps of SAC and PPO."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

from clients import ENV_IDS, require


@pytest.mark.parametrize("env_id", ENV_IDS)
def test_checkers_pass(env_id):
    require("stable_baselines3")
    import gymnasium as gym
    from gymnasium.utils.env_checker import check_env as gym_check
    from stable_baselines3.common.env_checker import check_env as sb3_check

    import billiards_env  # noqa: F401

    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a checker's warning is a failure here
        gym_check(gym.make(env_id).unwrapped)
        sb3_check(gym.make(env_id))


@pytest.mark.parametrize("env_id", ENV_IDS)
@pytest.mark.parametrize("mode", ["sync", "async"])
def test_make_vec(env_id, mode):
    import gymnasium as gym

    import billiards_env  # noqa: F401

    envs = gym.make_vec(env_id, num_envs=2, vectorization_mode=mode)
    obs, _ = envs.reset(seed=0)
    assert obs.shape == (2, *envs.single_observation_space.shape)
    for _ in range(3):
        obs, reward, terminated, truncated, _ = envs.step(envs.action_space.sample())
        assert np.isfinite(reward).all() and envs.observation_space.contains(obs)
    envs.close()


@pytest.mark.parametrize("env_id, algo", [("BilliardsOneBall-v0", "SAC"), ("Billiards9Ball-v0", "PPO")])
def test_sb3_learns_a_few_hundred_steps(env_id, algo):
    sb3 = require("stable_baselines3")
    from stable_baselines3.common.env_util import make_vec_env

    import billiards_env  # noqa: F401

    venv = make_vec_env(env_id, n_envs=2, seed=0)
    cls = getattr(sb3, algo)
    kwargs = {"learning_starts": 50, "batch_size": 32} if algo == "SAC" else {"n_steps": 64, "batch_size": 32}
    model = cls("MlpPolicy", venv, policy_kwargs={"net_arch": [16]}, seed=0, **kwargs)
    before = [p.detach().clone() for p in model.policy.parameters()]
    model.learn(200)
    assert model.num_timesteps >= 200
    assert any(not np.array_equal(a.numpy(), b.detach().numpy()) for a, b in zip(before, model.policy.parameters()))
    action, _ = model.predict(venv.reset(), deterministic=True)
    assert venv.action_space.contains(action[0])
