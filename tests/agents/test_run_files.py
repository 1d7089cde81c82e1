"""The model a run folder loads: the best if the run wrote one, else the final one (a short run), saying which."""
from __future__ import annotations

from pathlib import Path

import pytest

from agents.run_files import model_file


def test_best_if_there_else_final_and_it_says_which(tmp_path, capsys):
    (tmp_path / "final_model.zip").write_bytes(b"final")
    assert model_file(tmp_path) == tmp_path / "final_model.zip"
    err = capsys.readouterr().err
    assert "final_model.zip" in err and "no best_model.zip" in err and "before its first evaluation" in err
    (tmp_path / "best_model.zip").write_bytes(b"best")
    assert model_file(tmp_path) == tmp_path / "best_model.zip"
    assert "best evaluation" in capsys.readouterr().err
    assert model_file(tmp_path, quiet=True) == tmp_path / "best_model.zip" and capsys.readouterr().err == ""


def test_a_folder_without_a_model_says_what_it_holds(tmp_path):
    (tmp_path / "config.yaml").write_text("x: 1\n")
    with pytest.raises(FileNotFoundError, match=r"no best_model.zip or final_model.zip \(it holds config.yaml\)"):
        model_file(tmp_path)
    with pytest.raises(FileNotFoundError, match="no such run folder"):
        model_file(tmp_path / "missing")


def test_a_run_that_ended_before_its_first_evaluation_loads_its_final_model(tmp_path):
    """The README's three lines on a short run: no best_model.zip was written, the final model loads."""
    import json

    import gymnasium as gym
    from stable_baselines3 import SAC

    import billiards_env  # noqa: F401
    from agents.config import load_train_config
    from agents.train import train

    hyper = {"n_timesteps": 120, "policy": "MlpPolicy", "n_envs": 2, "policy_kwargs": "dict(net_arch=[16])",
             "learning_starts": 50, "batch_size": 32, "buffer_size": 1000,
             "env_kwargs": {"action_type": "ghost", "observation_type": "features"}}
    s = {"algo": "sac", "seed": 1, "name": "short", "run_root": str(tmp_path), "eval_freq": 100_000,
         "n_eval_episodes": 2, "n_eval_envs": 1, "checkpoint_seconds": 0, "progress_bar": False}
    run = Path(train(load_train_config({"BilliardsOneBall-v0": hyper, "billiards": s}), quiet=True)["run_dir"])
    assert not (run / "best_model.zip").exists()
    spec = json.loads((run / "env.json").read_text())
    env = gym.make(spec["id"], **spec["kwargs"])
    model = SAC.load(model_file(run), env=env)
    obs, _ = env.reset(seed=0)
    assert env.action_space.contains(model.predict(obs, deterministic=True)[0])
