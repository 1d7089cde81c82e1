"""Distillation (agents/distill.py): labels in the env's own action type, the same whatever the number of workers;
behaviour cloning fits a policy to them; the pipeline writes a loadable model and what each stage bought."""
from __future__ import annotations

import json

import numpy as np
import pytest

from agents.config import load_train_config
from agents.distill import behaviour_clone, collect_labels, distill, label_episodes

ONE_BALL = {"action_type": "candidates", "observation_type": "candidates", "candidate_slots": 4}


def test_labels_are_the_teachers_actions_in_the_envs_type():
    data = label_episodes("BilliardsOneBall-v0", ONE_BALL, None, "geometric", [5, 6, 7])
    assert data["obs"].shape == (3, 6 + 12 * 4) and data["actions"].shape == (3, 2)
    # the geometric player's own shot is the easiest candidate: slot 0 (a[0] in [0, 1/4)), its own speed (a[1] 0)
    assert np.all((data["actions"][:, 0] >= 0) & (data["actions"][:, 0] < 0.25))
    assert np.allclose(data["actions"][:, 1], 0.0, atol=1e-5)
    assert data["success"].dtype == bool and len(data["success"]) == 3


def test_labels_do_not_depend_on_the_workers():
    one = collect_labels("Billiards9Ball-v0", {"opponent": "random", "max_shots": 6}, None, "geometric", [3, 4],
                         workers=1)
    two = collect_labels("Billiards9Ball-v0", {"opponent": "random", "max_shots": 6}, None, "geometric", [3, 4],
                         workers=2)
    for k in ("obs", "actions", "rewards", "success"):
        assert np.array_equal(one[k], two[k])
    assert len(one["obs"]) >= 2


def _sac(env_kwargs):
    import gymnasium as gym
    from stable_baselines3 import SAC

    import billiards_env  # noqa: F401

    return SAC("MlpPolicy", gym.make("BilliardsOneBall-v0", **env_kwargs), policy_kwargs={"net_arch": [32, 32]},
               seed=0, learning_starts=0)


def test_behaviour_cloning_fits_the_labels():
    rng = np.random.default_rng(0)
    obs = rng.random((600, 6 + 12 * 4)).astype(np.float32)
    actions = np.stack([0.6 * obs[:, 0] - 0.3, 0.5 - obs[:, 1]], axis=1).astype(np.float32)  # a known map
    model = _sac(ONE_BALL)
    fit = behaviour_clone(model, obs, actions, epochs=60, lr=3e-3)
    first, last = fit["epochs"][0], fit["epochs"][-1]
    assert last["train_loss"] < first["train_loss"] - 1.0 and last["holdout_nll"] < first["holdout_nll"]
    assert last["holdout_mae"] < 0.05  # the deterministic action reproduces unseen labels
    pred = model.predict(obs[:5], deterministic=True)[0]
    assert np.abs(pred - actions[:5]).max() < 0.15


def test_the_pipeline_writes_a_model_and_its_figures(tmp_path):
    cfg = load_train_config("configs/train/one_ball_sac_path.yaml", overrides={"run_root": str(tmp_path)})
    rep = distill(cfg, teacher="geometric", states=40, bc_epochs=5, workers=1, eval_episodes=20, quiet=True)
    run = tmp_path / next(p.name for p in tmp_path.iterdir())
    saved = json.loads((run / "distill.json").read_text())
    assert saved["stages"][0]["labels"] == 40 and (run / "bc_model.zip").exists()
    assert 0.0 <= saved["stages"][0]["success_rate"] <= 1.0 and rep["run_dir"] == str(run)
    from agents.evaluate import model_player

    assert model_player(run / "bc_model.zip").env_kwargs["action_type"] == "candidates_aim"  # its run's env


@pytest.mark.slow
def test_dagger_rounds_and_fine_tuning(tmp_path):
    cfg = load_train_config("configs/train/one_ball_sac_path.yaml", overrides={"run_root": str(tmp_path)},
                            hyper_overrides={"learning_starts": 100})
    rep = distill(cfg, teacher="geometric", states=60, dagger_rounds=1, bc_epochs=3, rl_seconds=6,
                  actor_delay=200, workers=1, eval_episodes=10, quiet=True)
    stages = [s["stage"] for s in rep["stages"]]
    assert stages == ["bc", "dagger round 1", "rl fine-tuning"]
    assert rep["stages"][1]["labels_total"] == 60
