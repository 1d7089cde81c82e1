"""Tianshou: ``DummyVectorEnv`` + ``Collector`` into a ``VectorReplayBuffer`` and a few SAC updates (Tianshou's
SAC example, small)."""
from __future__ import annotations

import numpy as np
import pytest

from clients import ENV_IDS, require


@pytest.mark.parametrize("env_id", ENV_IDS)
def test_collector_and_sac_updates(env_id):
    require("tianshou")
    import gymnasium as gym
    import torch
    from tianshou.algorithm.modelfree.sac import SAC, SACPolicy
    from tianshou.algorithm.optim import AdamOptimizerFactory
    from tianshou.data import Collector, VectorReplayBuffer
    from tianshou.env import DummyVectorEnv
    from tianshou.utils.net.common import Net
    from tianshou.utils.net.continuous import ContinuousActorProbabilistic, ContinuousCritic
    from tianshou.utils.torch_utils import policy_within_training_step

    import billiards_env  # noqa: F401

    torch.manual_seed(0)
    envs = DummyVectorEnv([lambda: gym.make(env_id) for _ in range(2)])
    envs.seed(0)
    obs_space, act_space = envs.observation_space[0], envs.action_space[0]
    obs_dim, act_dim = obs_space.shape[0], act_space.shape[0]
    actor = ContinuousActorProbabilistic(preprocess_net=Net(state_shape=obs_dim, hidden_sizes=[32]),
                                         action_shape=act_dim, unbounded=True, conditioned_sigma=True)
    critics = [ContinuousCritic(preprocess_net=Net(state_shape=obs_dim, action_shape=act_dim, hidden_sizes=[32],
                                                   concat=True)) for _ in range(2)]
    policy = SACPolicy(actor=actor, action_space=act_space, observation_space=obs_space)
    algo = SAC(policy=policy, policy_optim=AdamOptimizerFactory(lr=1e-3), critic=critics[0],
               critic_optim=AdamOptimizerFactory(lr=1e-3), critic2=critics[1],
               critic2_optim=AdamOptimizerFactory(lr=1e-3))
    buffer = VectorReplayBuffer(1000, len(envs))
    collector = Collector(algo, envs, buffer, exploration_noise=True)
    stats = collector.collect(n_step=64, reset_before_collect=True)
    assert stats.n_collected_steps >= 64 and len(buffer) >= 64
    assert np.all((buffer.obs[: len(buffer)] >= 0) & (buffer.obs[: len(buffer)] <= 1))
    before = [p.detach().clone() for p in critics[0].parameters()]
    with policy_within_training_step(policy):  # what Tianshou's trainer does around its updates
        for _ in range(3):
            algo.update(buffer=buffer, sample_size=32)
    assert any(not torch.equal(a, b) for a, b in zip(before, critics[0].parameters()))  # the critic learned
    envs.close()
