"""The RLlib path end to end: a local Ray with this machine's CPUs, env runners in separate processes (Ray has no
local mode), a few PPO iterations on a small batch of the native vector env, checkpoints, resume from one, and the
checkpoint evaluated by agents.evaluate beside a baseline; the two-player game on RLlib's multi-agent API
(self-play, one shared policy). Needs the ``rllib`` extra: scripts/test.sh runs this file in ``.venv-rllib`` with
BILLIARDS_REQUIRE_RAY=1 (a missing Ray then fails instead of skipping)."""
from __future__ import annotations

import json
import math
import os
from pathlib import Path

import numpy as np
import pytest

if os.environ.get("BILLIARDS_REQUIRE_RAY"):
    import ray
else:
    ray = pytest.importorskip("ray", reason="needs the rllib extra: bash scripts/setup.sh --rllib")

from agents.evaluate import build_players, evaluate, run_player  # noqa: E402
from agents.rllib.algorithm import build_algorithm, init_ray  # noqa: E402
from agents.rllib.config import RLlibConfigError, load_rllib_config  # noqa: E402
from agents.rllib.player import RLlibPolicy, checkpoint_config, resolve_checkpoint, rllib_player  # noqa: E402
from agents.rllib.selfplay import make_env  # noqa: E402
from agents.rllib.train import train  # noqa: E402

#: The agent design of the committed config (env options), small and fast.
AGENT_KWARGS = {"action_type": "ghost", "observation_type": "features", "speed_max": 1.8}
SMALL_PPO = {"train_batch_size_per_learner": 256, "minibatch_size": 64, "num_epochs": 2, "lr": 1e-3}
SMALL_NET = {"model_config": {"fcnet_hiddens": [32, 32]}}
CONFIGS = sorted((Path(__file__).resolve().parents[2] / "configs" / "train").glob("rllib_*.yaml"))


@pytest.fixture(scope="module")
def local_ray():
    started = init_ray(None, quiet=True)  # num_cpus = the machine's
    yield
    if started:
        ray.shutdown()


def _finite(x) -> bool:
    return x is not None and math.isfinite(float(x))


def test_ppo_on_env_runners_checkpoints_resumes_and_evaluates(local_ray, tmp_path):
    runners = 2
    cfg = load_rllib_config({
        "rllib": {"env_runners": {"num_env_runners": runners, "num_envs_per_env_runner": 4},
                  "training": {**SMALL_PPO, "gamma": 0.0}, "rl_module": SMALL_NET},
        "billiards": {"env_id": "BilliardsOneBall-v0", "env_kwargs": AGENT_KWARGS, "iterations": 2,
                      "checkpoint_every": 1, "checkpoint_seconds": 0, "eval_every": 2, "eval_episodes": 20,
                      "run_root": str(tmp_path), "name": "ppo"}})
    meta = train(cfg, quiet=True)
    run = Path(meta["run_dir"])
    # The env runners were remote actors stepping the native vector env.
    assert meta["rllib"]["num_env_runners"] == runners
    assert meta["rllib"]["gym_env_vectorize_mode"] == "vector_entry_point"
    # ... with one physics thread per runner (its one CPU), an option of the vector env only.
    assert checkpoint_config(run / "final_checkpoint")["env_config"] == {**AGENT_KWARGS, "threads": 1}
    assert meta["iterations"] == 2
    assert meta["timesteps"] >= 2 * SMALL_PPO["train_batch_size_per_learner"]
    progress = json.loads((run / "progress.json").read_text())
    rows = progress["iterations"]
    assert [r["iteration"] for r in rows] == [1, 2]
    assert 0 < rows[0]["timesteps"] < rows[1]["timesteps"] == meta["timesteps"]
    assert all(_finite(r["episode_return_mean"]) and r["episode_len_mean"] == 1.0 for r in rows)
    assert all(0.0 <= r["success_rate"] <= 1.0 for r in rows)  # the env's is_success, logged by the env runners
    (ev,) = progress["evaluations"]
    assert 0.0 <= ev["success_rate"] <= 1.0 and _finite(ev["mean_reward"])
    latest = json.loads((run / "checkpoints" / "latest.json").read_text())
    assert latest["checkpoint"] == "iter_000002" and (run / "checkpoints" / "iter_000002").is_dir()
    assert (run / "final_checkpoint" / "rllib_checkpoint.json").is_file()
    assert resolve_checkpoint(run) == (run / "best_checkpoint", run)

    # Resume: the step count and the iteration number go on from the checkpoint.
    again = train(load_rllib_config(run / "config.yaml", {"iterations": 3}), resume=run, quiet=True)
    assert again["run_dir"] == str(run) and again["resumed_from"].endswith("iter_000002")
    assert again["iterations"] == 3 and again["timesteps"] > meta["timesteps"]
    assert [r["iteration"] for r in json.loads((run / "progress.json").read_text())["iterations"]] == [1, 2, 3]

    # The checkpoint in the project's evaluation, beside a baseline, on the run's own env.
    players = build_players([os.path.relpath(run), "random"], None, None)  # a relative path, as typed
    assert players[0].env_id == "BilliardsOneBall-v0" and players[0].env_kwargs == AGENT_KWARGS
    report = evaluate(players, 20, 100_000, tmp_path / "eval", gif_episodes=0, quiet=True)
    rl, rnd = report["results"]
    assert rl["label"] == run.name and rl["episodes"] == rnd["episodes"] == 20
    assert 0.0 <= rl["success_rate"] <= 1.0 and _finite(rl["mean_return"])
    md = (tmp_path / "eval" / "report.md").read_text()
    assert f"| {run.name} |" in md and f"Training: {run.name}" in md and "PPO" in md

    # Deterministic actions inside the action space, from the restored module alone.
    policy = RLlibPolicy.from_checkpoint(run / "final_checkpoint")
    obs = np.linspace(0.0, 1.0, policy.module.observation_space.shape[0], dtype=np.float32)
    a, b = policy(obs), policy(obs)
    assert np.array_equal(a, b) and policy.action_space.contains(a.astype(np.float32))


def test_two_player_game_in_rllibs_pettingzoo_wrapper_is_zero_sum():
    env = make_env("Billiards9Ball-v0", {"opponent": "random"})  # the opponent key is ignored by the AEC env
    rng = np.random.default_rng(0)
    obs, _ = env.reset(seed=3)
    totals = {"player_0": 0.0, "player_1": 0.0}
    for _ in range(500):
        (agent,) = obs  # a turn-based game: only the player to shoot observes
        assert env.observation_spaces[agent].contains(obs[agent])
        obs, rew, term, trunc, _ = env.step({agent: rng.uniform(-1, 1, 4).astype(np.float32)})
        for a, r in rew.items():
            totals[a] += r
        if term["__all__"] or trunc["__all__"]:
            break
    assert term["__all__"], "a random game ends within 500 shots (three fouls in a row lose)"
    assert sorted(totals.values()) == [-1.0, 1.0]  # one win, one loss, nothing else (no shaping by default)


def test_self_play_shared_policy_trains_and_plays_the_single_agent_game(local_ray, tmp_path):
    cfg = load_rllib_config({
        "rllib": {"env_runners": {"num_env_runners": 1, "num_envs_per_env_runner": 2},
                  "training": {**SMALL_PPO, "train_batch_size_per_learner": 128, "num_epochs": 1},
                  "rl_module": SMALL_NET},
        "billiards": {"env_id": "Billiards9Ball-v0", "self_play": "shared", "iterations": 1,
                      "env_kwargs": {"action_type": "ghost"}, "run_root": str(tmp_path), "name": "selfplay"}})
    meta = train(cfg, quiet=True)
    run = Path(meta["run_dir"])
    assert meta["self_play"] == "shared" and meta["timesteps"] >= 128
    (row,) = json.loads((run / "progress.json").read_text())["iterations"]
    assert set(row["module_returns"]) == {"shared"} and _finite(row["module_returns"]["shared"])
    assert _finite(row["episode_len_mean"]) and row["episode_len_mean"] >= 1
    # The shared module plays the single-agent game against the env's opponent: the same observation.
    spec = rllib_player(run)
    assert spec.env_id == "Billiards9Ball-v0" and spec.env_kwargs == {"action_type": "ghost"}
    result, rows = run_player(spec, 2, 0)
    assert result.episodes == 2 and all(r["shots"] >= 1 for r in rows)


def test_more_env_runners_than_cpus_is_refused_not_left_waiting(local_ray):
    cpus = int(ray.cluster_resources()["CPU"])
    cfg = load_rllib_config({"rllib": {"env_runners": {"num_env_runners": cpus + 1}}, "billiards": {"iterations": 1}})
    with pytest.raises(RLlibConfigError, match="reserve"):
        build_algorithm(cfg, local=True)


@pytest.mark.parametrize("path", CONFIGS, ids=[p.name for p in CONFIGS])
def test_committed_configs_are_valid_algorithm_configs(local_ray, path):
    from agents.rllib.algorithm import algorithm_config

    cfg = load_rllib_config(path)
    config = algorithm_config(cfg)  # every section's keys are arguments of its AlgorithmConfig method
    config.validate()  # RLlib's own checks (batch sizes, vectorize mode, multi-agent policies)
    assert config.env_config == ({**cfg.settings.env_kwargs, "threads": 1}
                                 if cfg.vectorize_mode == "vector_entry_point" else cfg.settings.env_kwargs)
    assert config.is_multi_agent == bool(cfg.settings.self_play)


def test_failed_start_leaves_no_stub_run_folder(local_ray, tmp_path):
    """A new run that fails before its first iteration removes its folder (the README's `runs/<name>-*` globs
    would otherwise match it)."""
    cpus = int(ray.cluster_resources()["CPU"])
    cfg = load_rllib_config({"rllib": {"env_runners": {"num_env_runners": cpus + 1}},
                             "billiards": {"iterations": 1, "run_root": str(tmp_path), "name": "stub"}})
    with pytest.raises(RLlibConfigError, match="reserve"):
        train(cfg, quiet=True)
    assert list(tmp_path.iterdir()) == []


def test_address_auto_without_a_cluster_is_one_clear_line(tmp_path, monkeypatch, capsys):
    """`--address auto` with no cluster: one line saying what to do, no traceback, no run folder. Ray's own
    ConnectionError is raised by a stand-in for ray.init: with `auto` a real Ray joins any instance it finds on the
    node (this module's local one, another job's), so the missing cluster cannot be had for sure here."""
    from agents.rllib.train import main

    def no_cluster(*args, **kwargs):
        raise ConnectionError("Could not find any running Ray instance. Please specify the one to connect to by "
                              "setting `--address` flag or `RAY_ADDRESS` environment variable.")

    monkeypatch.setattr(ray, "is_initialized", lambda: False)
    monkeypatch.setattr(ray, "init", no_cluster)
    code = main(["--address", "auto", "--iterations", "1", "--num-env-runners", "0", "--run-root", str(tmp_path)])
    assert code == 2
    lines = capsys.readouterr().err.strip().splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("agents.rllib: error: --address auto: no running Ray cluster") and "ray start" in lines[0]
    assert list(tmp_path.iterdir()) == []
