"""skrl: ``wrap_env`` (auto-detected as Gymnasium) steps our envs with torch tensors, single and vectorized."""
from __future__ import annotations

import pytest

from clients import ENV_IDS, require


@pytest.mark.parametrize("env_id", ENV_IDS)
def test_wrap_env_steps(env_id):
    require("skrl")
    import gymnasium as gym
    import torch
    from skrl.envs.wrappers.torch import wrap_env

    import billiards_env  # noqa: F401

    for raw, n in ((gym.make(env_id), 1), (gym.make_vec(env_id, num_envs=2, vectorization_mode="sync"), 2)):
        env = wrap_env(raw)
        assert env.num_envs == n
        obs, info = env.reset()
        assert isinstance(obs, torch.Tensor) and obs.shape == (n, env.observation_space.shape[0])
        for _ in range(4):
            actions = torch.rand((n, env.action_space.shape[0])) * 2 - 1
            obs, reward, terminated, truncated, info = env.step(actions)
            assert reward.shape == (n, 1) and terminated.dtype == torch.bool
            if n == 1 and (terminated.any() or truncated.any()):
                obs, info = env.reset()
        env.close()
