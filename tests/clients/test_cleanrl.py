"""A CleanRL-style PPO loop (``ppo_continuous_action.py``'s structure: ``gym.vector.SyncVectorEnv`` of
``make_env`` thunks with ``RecordEpisodeStatistics`` and ``ClipAction``, rollouts into tensors, GAE, clipped
updates), a few updates on each id."""
from __future__ import annotations

import numpy as np
import pytest

from clients import ENV_IDS, require


def make_env(env_id: str):
    import gymnasium as gym

    def thunk():
        env = gym.make(env_id)
        env = gym.wrappers.FlattenObservation(env)
        env = gym.wrappers.RecordEpisodeStatistics(env)
        env = gym.wrappers.ClipAction(env)
        return env

    return thunk


@pytest.mark.parametrize("env_id", ENV_IDS)
def test_ppo_loop_updates(env_id):
    torch = require("torch")
    from torch import nn
    from torch.distributions.normal import Normal
    import gymnasium as gym

    import billiards_env  # noqa: F401

    torch.manual_seed(0)
    num_envs, num_steps, updates, gamma, lam, clip = 2, 16, 3, 0.99, 0.95, 0.2
    envs = gym.vector.SyncVectorEnv([make_env(env_id) for _ in range(num_envs)])
    assert isinstance(envs.single_action_space, gym.spaces.Box)
    n_obs, n_act = int(np.prod(envs.single_observation_space.shape)), int(np.prod(envs.single_action_space.shape))
    critic = nn.Sequential(nn.Linear(n_obs, 32), nn.Tanh(), nn.Linear(32, 1))
    actor_mean = nn.Sequential(nn.Linear(n_obs, 32), nn.Tanh(), nn.Linear(32, n_act))
    actor_logstd = nn.Parameter(torch.zeros(1, n_act))
    params = [*critic.parameters(), *actor_mean.parameters(), actor_logstd]
    optimizer = torch.optim.Adam(params, lr=3e-4, eps=1e-5)

    def act(x, action=None):
        probs = Normal(actor_mean(x), actor_logstd.expand(x.shape[0], n_act).exp())
        action = probs.sample() if action is None else action
        return action, probs.log_prob(action).sum(1), critic(x).squeeze(-1)

    obs_buf = torch.zeros((num_steps, num_envs, n_obs))
    act_buf = torch.zeros((num_steps, num_envs, n_act))
    logp_buf, rew_buf, done_buf, val_buf = (torch.zeros((num_steps, num_envs)) for _ in range(4))
    next_obs = torch.tensor(envs.reset(seed=0)[0], dtype=torch.float32)
    next_done = torch.zeros(num_envs)
    episodes = 0
    for _ in range(updates):
        for step in range(num_steps):
            obs_buf[step], done_buf[step] = next_obs, next_done
            with torch.no_grad():
                action, logp, value = act(next_obs)
            act_buf[step], logp_buf[step], val_buf[step] = action, logp, value
            next_obs_np, reward, terminations, truncations, infos = envs.step(action.numpy())
            rew_buf[step] = torch.tensor(reward, dtype=torch.float32)
            next_done = torch.tensor(np.logical_or(terminations, truncations), dtype=torch.float32)
            next_obs = torch.tensor(next_obs_np, dtype=torch.float32)
            if "episode" in infos:
                episodes += int(infos["_episode"].sum())
        with torch.no_grad():
            next_value = critic(next_obs).squeeze(-1)
            adv = torch.zeros_like(rew_buf)
            last = torch.zeros(num_envs)
            for t in reversed(range(num_steps)):
                nonterminal = 1.0 - (next_done if t == num_steps - 1 else done_buf[t + 1])
                nv = next_value if t == num_steps - 1 else val_buf[t + 1]
                delta = rew_buf[t] + gamma * nv * nonterminal - val_buf[t]
                adv[t] = last = delta + gamma * lam * nonterminal * last
            returns = adv + val_buf
        b_obs, b_act = obs_buf.reshape(-1, n_obs), act_buf.reshape(-1, n_act)
        _, new_logp, new_value = act(b_obs, b_act)
        ratio = (new_logp - logp_buf.reshape(-1)).exp()
        b_adv = adv.reshape(-1)
        pg_loss = torch.max(-b_adv * ratio, -b_adv * ratio.clamp(1 - clip, 1 + clip)).mean()
        loss = pg_loss + 0.5 * ((new_value - returns.reshape(-1)) ** 2).mean()
        before = actor_mean[0].weight.detach().clone()
        optimizer.zero_grad()
        loss.backward()
        optimizer.step()
        assert torch.isfinite(loss) and not torch.equal(before, actor_mean[0].weight)
    assert episodes > 0  # RecordEpisodeStatistics reported finished episodes through the vector env's infos
    envs.close()
