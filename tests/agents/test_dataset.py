"""``python -m agents.dataset`` writes expert episodes as a Minari dataset that ``minari.load_dataset`` reads, with
the env spec (kwargs included); the same seeds give the same dataset whatever the number of workers."""
from __future__ import annotations

import numpy as np
import pytest

minari = pytest.importorskip("minari")

from agents.dataset import collect, default_dataset_id, main  # noqa: E402


def test_dataset_loads_with_minari_and_recovers_the_env(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("MINARI_DATASETS_PATH", str(tmp_path))
    assert main(["--env", "BilliardsOneBall-v0", "--expert", "geometric", "--episodes", "12", "--workers", "2",
                 "--env-kwargs", '{"angle_noise": 0.001}']) == 0
    dataset_id = default_dataset_id("BilliardsOneBall-v0", "geometric")
    assert "success" in capsys.readouterr().out
    ds = minari.load_dataset(dataset_id)
    assert ds.total_episodes == 12 and ds.total_steps == 12  # one shot per episode
    env = ds.recover_environment()
    assert env.spec.id == "BilliardsOneBall-v0" and env.unwrapped.config.angle_noise == 0.001
    ep = next(iter(ds.iterate_episodes()))
    assert ep.observations.shape == (2, 6) and ep.actions.shape == (1, 2)
    obs, _ = env.reset(seed=int(ep.id))  # episode k is seed k: the first observation repeats
    assert np.allclose(obs, ep.observations[0])
    with pytest.raises(SystemExit):  # the same id again needs --overwrite
        main(["--env", "BilliardsOneBall-v0", "--expert", "geometric", "--episodes", "2"])


def test_episodes_do_not_depend_on_the_workers():
    one = collect("Billiards9Ball-v0", {"opponent": "random"}, "geometric", 3, seed=5, workers=1)
    two = collect("Billiards9Ball-v0", {"opponent": "random"}, "geometric", 3, seed=5, workers=2)
    assert [e["seed"] for e in one] == [5, 6, 7]
    for a, b in zip(one, two):
        assert np.array_equal(a["observations"], b["observations"]) and np.array_equal(a["actions"], b["actions"])
        assert len(a["actions"]) >= 1 and a["terminations"][-1] or a["truncations"][-1]
