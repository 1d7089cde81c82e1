"""Training scaffolding: a short run writes a loadable model and its run folder, resume continues it, the
configs parse (in the RL Zoo format), and a short training on an easy scene beats random play."""
from __future__ import annotations

import inspect
import json
from pathlib import Path

import numpy as np
import pytest
import yaml

from agents.config import TrainConfigError, load_train_config, parse_hyperparams
from agents.evaluate import baseline_player, model_player, run_player
from agents.train import algo_class, main, train

REPO = Path(__file__).resolve().parents[2]
CONFIGS = sorted(p for p in (REPO / "configs" / "train").glob("*.yaml") if not p.name.startswith("rllib_"))  # SB3

#: An easy scene through env kwargs: a half-size table with wide pockets, the cue ball on the head spot.
EASY = {"table": {"length": 1.2, "width": 0.6, "corner_pocket_radius": 0.1, "side_pocket_radius": 0.09},
        "pocket_margin": 0.12, "cue_placement": "head_spot"}
#: The agent design of configs/train/one_ball_sac.yaml: env options, no wrappers.
AGENT_KWARGS = {"action_type": "ghost", "observation_type": "features"}


def _config(tmp_path: Path, algo: str = "sac", n_timesteps: int = 600, env_kwargs: dict | None = None,
            **settings) -> dict:
    hyper = {
        "n_timesteps": n_timesteps, "policy": "MlpPolicy", "n_envs": 4,
        "policy_kwargs": "dict(net_arch=[32, 32])", "env_kwargs": {**AGENT_KWARGS, **(env_kwargs or {})},
    }
    if algo in ("sac", "td3"):
        hyper.update({"learning_starts": 100, "batch_size": 64, "gamma": 0.0, "buffer_size": 10_000})
    if algo == "td3":
        hyper.update({"noise_type": "normal", "noise_std": 0.1})
    if algo == "ppo":
        hyper.update({"n_steps": 64, "batch_size": 64, "n_epochs": 2, "gamma": 0.0})
    s = {"algo": algo, "seed": 1, "name": f"t-{algo}", "run_root": str(tmp_path), "eval_freq": 200,
         "n_eval_episodes": 20, "n_eval_envs": 4, "checkpoint_freq": 200, "checkpoint_seconds": 0,
         "progress_bar": False, **settings}
    return {"BilliardsOneBall-v0": hyper, "billiards": s}


def test_short_sac_run_writes_a_loadable_model(tmp_path):
    meta = train(load_train_config(_config(tmp_path)), quiet=True)
    run = Path(meta["run_dir"])
    for name in ("config.yaml", "run.json", "progress.json", "final_model.zip", "best_model.zip",
                 "checkpoints/latest.json", "checkpoints/replay_buffer.pkl", "eval/evaluations.npz"):
        assert (run / name).exists(), name
    assert list((run / "tb").rglob("events.out.tfevents*")), "no TensorBoard log"
    assert list((run / "monitor").rglob("*.monitor.csv")), "no Monitor log"
    assert meta["timesteps"] >= 600 and meta["train_steps_per_second"] > 0
    ev = np.load(run / "eval" / "evaluations.npz")
    assert len(ev["timesteps"]) >= 2 and "successes" in ev.files
    progress = json.loads((run / "progress.json").read_text())
    assert len(progress["evaluations"]) == len(ev["timesteps"])
    # The saved config reproduces the run and the model plays through the evaluation code.
    again = load_train_config(run / "config.yaml")
    assert again.env_id == "BilliardsOneBall-v0" and again.settings.seed == 1
    spec = model_player(run)
    res, rows = run_player(spec, 10, seed=99)
    assert res.episodes == 10 and all(r["shots"] == 1 for r in rows)


def test_resume_continues_from_the_checkpoint_with_its_replay_buffer(tmp_path):
    meta = train(load_train_config(_config(tmp_path, n_timesteps=400)), quiet=True)
    run = Path(meta["run_dir"])
    latest = json.loads((run / "checkpoints" / "latest.json").read_text())
    assert latest["timesteps"] >= 400 and latest["replay_buffer"] == "replay_buffer.pkl"
    code = main(["--resume", str(run), "--timesteps", "800", "--no-progress", "--quiet"])
    assert code == 0
    meta2 = json.loads((run / "run.json").read_text())
    assert meta2["resumed_from"].endswith(".zip")
    assert meta2["timesteps"] >= 800
    model = algo_class("sac").load(run / "final_model.zip")
    assert model.num_timesteps >= 800
    # Monitor logs of both sessions are kept.
    assert len(list((run / "monitor").glob("session*"))) == 2


@pytest.mark.parametrize("algo", ["td3", "ppo"])
def test_td3_and_ppo_train(tmp_path, algo):
    meta = train(load_train_config(_config(tmp_path, algo=algo, n_timesteps=256)), quiet=True)
    assert meta["algo"] == algo and meta["timesteps"] >= 256
    assert Path(meta["final_model"]).exists()


def test_interrupt_saves_a_checkpoint(tmp_path, monkeypatch):
    from stable_baselines3.common.callbacks import BaseCallback

    class Boom(BaseCallback):
        def _on_step(self) -> bool:
            if self.num_timesteps >= 300:
                raise KeyboardInterrupt
            return True

    import agents.train as tr

    real = tr.train

    orig_learn = algo_class("sac").learn

    def learn(self, *a, callback=None, **k):
        from stable_baselines3.common.callbacks import CallbackList

        return orig_learn(self, *a, callback=CallbackList([callback, Boom()]), **k)

    monkeypatch.setattr(algo_class("sac"), "learn", learn)
    meta = real(load_train_config(_config(tmp_path, n_timesteps=2000, checkpoint_freq=0)), quiet=True)
    assert meta["interrupted"] is True
    latest = json.loads((Path(meta["run_dir"]) / "checkpoints" / "latest.json").read_text())
    assert 300 <= latest["timesteps"] < 2000


@pytest.mark.parametrize("path", CONFIGS, ids=[p.name for p in CONFIGS])
def test_committed_configs_parse_in_zoo_format(path):
    data = yaml.safe_load(path.read_text())
    cfg = load_train_config(path)
    assert cfg.env_id in data and "billiards" in data
    zoo = data[cfg.env_id]
    assert {"n_timesteps", "policy"} <= set(zoo)  # the RL Zoo requires these
    setup = parse_hyperparams(cfg)
    params = inspect.signature(algo_class(cfg.algo).__init__).parameters
    unknown = set(setup.algo_kwargs) - set(params)
    assert not unknown, f"not constructor arguments of {cfg.algo}: {unknown}"
    assert setup.wrapper is not None or "env_wrapper" not in zoo


def test_bad_configs_are_reported(tmp_path):
    with pytest.raises(TrainConfigError, match="unknown key"):
        load_train_config({"X-v0": {"n_timesteps": 1}, "billiards": {"algoo": "sac"}})
    with pytest.raises(TrainConfigError, match="unknown algorithm"):
        load_train_config({"X-v0": {"n_timesteps": 1}, "billiards": {"algo": "dqn2"}})
    with pytest.raises(TrainConfigError, match="no entry"):
        load_train_config({"X-v0": {"n_timesteps": 1}}, env_id="Y-v0")
    assert main(["--config", str(tmp_path / "missing.yaml")]) == 2


def _easy_training(tmp_path, seconds: float, steps: int) -> tuple[float, float]:
    cfg = _config(tmp_path, n_timesteps=steps, env_kwargs=dict(EASY), max_seconds=seconds, eval_freq=0,
                  checkpoint_freq=0)
    hyper = cfg["BilliardsOneBall-v0"]  # the tuned one-ball settings (configs/train/one_ball_sac.yaml)
    hyper.update({"n_envs": 8, "batch_size": 128, "learning_rate": 3e-3, "learning_starts": 1000,
                  "target_entropy": -4.0, "policy_kwargs": "dict(net_arch=[64, 64])", "buffer_size": 100_000})
    hyper["env_kwargs"]["speed_max"] = 1.8
    meta = train(load_train_config(cfg), quiet=True)
    trained, _ = run_player(model_player(meta["run_dir"]), 200, seed=4242)
    rand, _ = run_player(baseline_player("random", "BilliardsOneBall-v0", dict(EASY)), 200, seed=4242)
    return trained.success_rate, rand.success_rate


def test_short_training_beats_random_on_an_easy_scene(tmp_path):
    trained, rand = _easy_training(tmp_path, seconds=25, steps=12_000)
    assert trained >= rand + 0.3, (trained, rand)  # measured: 0.82 vs 0.085 in 25 s on a loaded machine


@pytest.mark.slow
def test_longer_training_on_the_easy_scene(tmp_path):
    trained, rand = _easy_training(tmp_path, seconds=240, steps=200_000)
    assert trained >= rand + 0.5, (trained, rand)


def test_resume_of_a_spent_run_says_how_to_train_on(tmp_path, capsys):
    """A run whose budget is spent: one clear line with the command that trains on (it used to crash with an
    AttributeError); --seconds is the run's total, so a larger one trains on in the same folder."""
    meta = train(load_train_config(_config(tmp_path, n_timesteps=100_000, max_seconds=3, budget_clock="cpu",
                                           eval_freq=0)), quiet=True)
    run = Path(meta["run_dir"])
    assert meta["stopped_by_budget"] and meta["wall_seconds"] >= 3
    capsys.readouterr()
    assert main(["--resume", str(run), "--no-progress", "--quiet"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "has spent its time budget" in err and "CPU s" in err and "--seconds" in err
    assert main(["--resume", str(run), "--seconds", str(meta["wall_seconds"] + 2), "--no-progress", "--quiet"]) == 0
    meta2 = json.loads((run / "run.json").read_text())
    assert meta2["timesteps"] > meta["timesteps"] and meta2["wall_seconds"] >= meta["wall_seconds"] + 2


def test_progress_bar_counts_the_budget(tmp_path, capsys):
    """With a time budget the bar's end (and so its ETA) is the budget, not n_timesteps."""
    meta = train(load_train_config(_config(tmp_path, n_timesteps=2_000_000, max_seconds=2, eval_freq=0)),
                 progress_bar=True, quiet=True)
    err = capsys.readouterr().err
    assert "budget (wall clock)" in err and "/2 s" in err and "2,000,000" not in err
    assert meta["stopped_by_budget"]


def test_help_says_what_seconds_counts(capsys):
    with pytest.raises(SystemExit):
        main(["--help"])
    out = " ".join(capsys.readouterr().out.split())
    assert "CPU seconds" in out and "total" in out and "wall-clock budget" not in out
