"""What a new user trips over: stepping after the end, batched actions, the config-key listing command."""
from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from gymnasium.error import ResetNeeded

from env_helpers import make


def test_step_after_termination_raises_until_reset():
    env = make("BilliardsOneBall-v0")
    with pytest.raises(ResetNeeded, match="reset"):  # (gym.make's OrderEnforcing says it first)
        env.step(np.zeros(2, np.float32))
    env.reset(seed=0)
    terminated = env.step(np.array([0.2, 0.0], np.float32))[2]
    assert terminated  # one shot per episode
    with pytest.raises(ResetNeeded, match="after the end of the episode.*reset\\(\\)"):
        env.step(np.array([0.2, 0.0], np.float32))
    env.reset(seed=1)
    assert env.step(np.array([0.2, 0.0], np.float32))[2]


def test_step_after_truncation_raises_until_reset():
    env = make("BilliardsThreeBalls-v0", max_shots=2)
    env.reset(seed=0)
    soft = np.array([0.0, -1.0], np.float32)
    _, _, terminated, truncated, _ = env.step(soft)
    assert not (terminated or truncated)
    _, _, terminated, truncated, _ = env.step(soft)
    assert truncated and not terminated  # two soft shots cannot clear three balls
    with pytest.raises(ResetNeeded, match="terminated or truncated"):
        env.step(soft)
    env.reset(seed=0)
    env.step(soft)


def test_a_batched_action_of_shape_1_2_is_the_same_shot():
    a, b = make("BilliardsOneBall-v0"), make("BilliardsOneBall-v0")
    a.reset(seed=4)
    b.reset(seed=4)
    flat, batched = np.array([0.3, 0.1], np.float32), np.array([[0.3, 0.1]], np.float32)
    ra, rb = a.step(flat), b.step(batched)
    np.testing.assert_array_equal(ra[0], rb[0])
    assert ra[4]["angle"] == rb[4]["angle"] and ra[4]["speed"] == rb[4]["speed"]
    b.reset(seed=4)
    with pytest.raises(ValueError, match="action"):
        b.step(np.zeros(3, np.float32))  # three numbers are not a shot


def test_config_keys_listing_runs_without_warnings():
    from billiards_env.envs.config import EnvConfig

    p = subprocess.run([sys.executable, "-W", "error", "-m", "billiards_env.envs"], capture_output=True, text=True,
                       timeout=120)
    assert p.returncode == 0 and p.stderr == "", p.stderr[-2000:]
    listed = {line.split()[0] for line in p.stdout.splitlines() if line.strip()}
    assert set(EnvConfig.keys()) <= listed
