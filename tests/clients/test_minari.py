"""Minari: ``DataCollector(record_infos=True)`` -> ``create_dataset`` -> ``load_dataset`` -> ``recover_environment``
(Minari's basic usage), with the infos kept: their keys and shapes must be the same at reset and every step."""
from __future__ import annotations

import numpy as np
import pytest

from clients import ENV_IDS, require


@pytest.mark.parametrize("env_id", ENV_IDS)
def test_record_infos_dataset_round_trip(env_id, tmp_path, monkeypatch):
    require("minari")
    require("jax")  # DataCollector's episode buffers: minari's "create" extra
    import gymnasium as gym
    import minari
    from minari import DataCollector

    import billiards_env  # noqa: F401

    monkeypatch.setenv("MINARI_DATASETS_PATH", str(tmp_path))
    env = DataCollector(gym.make(env_id), record_infos=True)
    env.action_space.seed(0)
    n_episodes = 3
    for k in range(n_episodes):
        env.reset(seed=k)
        for _ in range(4):
            _, _, terminated, truncated, _ = env.step(env.action_space.sample())
            if terminated or truncated:
                break
    name = f"billiards/{env_id.lower().replace('-', '_')}/test-v0"
    dataset = env.create_dataset(dataset_id=name, algorithm_name="random")
    env.close()
    loaded = minari.load_dataset(name)
    assert loaded.total_episodes == n_episodes == dataset.total_episodes
    episode = next(loaded.iterate_episodes())
    assert episode.observations.shape[0] == len(episode.actions) + 1
    assert "is_success" in episode.infos
    assert len(np.asarray(episode.infos["is_success"])) == len(episode.actions) + 1  # reset's info + each step's
    recovered = loaded.recover_environment()
    assert recovered.spec.id == env_id
    obs, _ = recovered.reset(seed=0)
    assert recovered.observation_space.contains(obs)
