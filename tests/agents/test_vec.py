"""The SB3 adapter (``agents/vec.py``): ``BilliardsVecEnv`` returns what SB3's ``DummyVecEnv`` over single envs
returns (observations, rewards, dones, infos with ``terminal_observation`` and ``TimeLimit.truncated``) with the
same seeds and actions, and SB3 trains on it."""
from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest
from stable_baselines3.common.vec_env import DummyVecEnv, VecMonitor

import billiards_env  # noqa: F401
from agents.vec import BilliardsVecEnv, native_vec_env_supported


def _same(a, b) -> None:
    assert set(a) == set(b), (sorted(a), sorted(b))
    for key in a:
        if isinstance(a[key], np.ndarray):
            assert np.array_equal(a[key], b[key]), key
        else:
            assert a[key] == b[key] and type(a[key]) is type(b[key]), (key, a[key], b[key])


@pytest.mark.parametrize("env_id,kwargs,truncates", [
    ("BilliardsOneBall-v0", {}, False),
    ("BilliardsThreeBalls-v0", {"max_shots": 2, "action_type": "relative"}, True),
    ("Billiards9Ball-v0", {"action_type": "candidates", "observation_type": "candidates", "friction": "spin",
                           "spin_action": True, "noise": "olympiad", "first_shooter": "random"}, False),
    ("Billiards8Ball-v0", {"max_shots": 3}, True),
])
def test_adapter_equals_dummy_vec_env(env_id, kwargs, truncates):
    """The same observations, rewards, dones and infos (every key, its value and its type: the games' infos mix
    ``False`` and ``"anywhere"`` under one key) as ``DummyVecEnv`` with the same seeds and actions."""
    n = 4
    native = BilliardsVecEnv(env_id, n, kwargs)
    assert native.venv.unwrapped.native  # the arrays' path, not its sub-envs one by one
    dummy = DummyVecEnv([lambda: gym.make(env_id, **kwargs) for _ in range(n)])
    native.seed(3)
    dummy.seed(3)
    assert np.array_equal(native.reset(), dummy.reset())
    rng = np.random.default_rng(0)
    ends = truncations = 0
    for _ in range(12):
        action = rng.uniform(-1, 1, (n,) + native.action_space.shape).astype(np.float32)
        obs, rew, done, infos = native.step(action)
        obs_d, rew_d, done_d, infos_d = dummy.step(action)
        assert np.array_equal(obs, obs_d) and np.array_equal(done, done_d)
        assert rew.dtype == rew_d.dtype and np.array_equal(rew, rew_d)
        for a, b in zip(infos, infos_d):
            _same(a, b)
        ends += int(done.sum())
        truncations += sum(d["TimeLimit.truncated"] for d in infos)
    assert ends > 0 and all("terminal_observation" in d for d, e in zip(infos, done) if e)
    assert (truncations > 0) == truncates


def test_sb3_trains_on_the_adapter_with_vec_monitor(tmp_path):
    from stable_baselines3 import PPO

    env = VecMonitor(BilliardsVecEnv("BilliardsOneBall-v0", 8), str(tmp_path / "vec"), info_keywords=("is_success",))
    model = PPO("MlpPolicy", env, n_steps=16, batch_size=32, n_epochs=1, seed=0, device="cpu")
    model.learn(64)
    assert model.num_timesteps >= 64
    lines = (tmp_path / "vec.monitor.csv").read_text().splitlines()
    assert lines[1].startswith("r,l,t,is_success") and len(lines) > 2 + 32  # one row per one-shot episode


def test_native_is_used_only_where_it_applies():
    assert native_vec_env_supported("BilliardsOneBall-v0", {"action_type": "ghost"}, None)
    assert not native_vec_env_supported("BilliardsOneBall-v0", {}, wrapper=lambda e: e)
    assert not native_vec_env_supported("BilliardsOneBall-v0", {"solver": "step"}, None)
    assert native_vec_env_supported("Billiards9Ball-v0", {}, None)
    assert not native_vec_env_supported("Billiards9Ball-v0", {"opponent": "random"}, None)
