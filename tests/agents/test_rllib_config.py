"""RLlib configs without Ray: the committed files parse, bad files and flags get clear errors, a non-RLlib path is
not mistaken for a checkpoint (the SB3 evaluation path imports no Ray). Runs in the default venv."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from agents.rllib.config import (ALGOS, CONFIG_SECTIONS, RLlibConfigError, load_rllib_config, normalize_algo,
                                 parse_assignments)
from agents.rllib.player import env_of, is_rllib_path
from billiards_env.registration import ENV_IDS

REPO = Path(__file__).resolve().parents[2]
CONFIGS = sorted((REPO / "configs" / "train").glob("rllib_*.yaml"))


@pytest.mark.parametrize("path", CONFIGS, ids=[p.name for p in CONFIGS])
def test_committed_rllib_configs_parse(path):
    cfg = load_rllib_config(path)
    assert cfg.settings.algo in ALGOS
    assert cfg.env_id in ENV_IDS
    assert set(cfg.sections) <= set(CONFIG_SECTIONS)
    assert cfg.settings.name == path.stem
    assert cfg.settings.timesteps or cfg.settings.iterations or cfg.settings.max_seconds
    assert cfg.vectorize_mode == ("sync" if cfg.settings.self_play else "vector_entry_point")


def test_committed_configs_cover_one_env_and_self_play():
    cfgs = [load_rllib_config(p) for p in CONFIGS]
    assert any(c.settings.self_play is None for c in cfgs)
    assert any(c.settings.self_play == "shared" for c in cfgs)


def test_overrides_merge_and_numbers_in_exponent_form_are_numbers():
    cfg = load_rllib_config({"rllib": {"training": {"lr": "1e-3", "gamma": 0.5}},
                             "billiards": {"env_kwargs": {"speed_max": 2.0}}},
                            overrides={"algo": "ppo", "timesteps": "2e5"},
                            section_overrides=parse_assignments(["training.lr=3e-4", "env_runners.num_env_runners=4"],
                                                                "--set"))
    assert cfg.settings.algo == "PPO" and cfg.settings.timesteps == 2e5
    assert cfg.sections["training"] == {"lr": 3e-4, "gamma": 0.5}
    assert cfg.sections["env_runners"] == {"num_env_runners": 4}
    assert cfg.settings.env_kwargs == {"speed_max": 2.0}
    assert load_rllib_config(None).to_yaml_dict()["billiards"]["algo"] == "PPO"


@pytest.mark.parametrize("data, match", [
    ({"rllib": {"trainig": {"lr": 0.1}}}, "not a section"),
    ({"billiards": {"algoo": "PPO"}}, "unknown key"),
    ({"billiards": {"algo": "DQN"}}, "discrete"),
    ({"billiards": {"self_play": "both"}}, "self_play"),
    ({"billiards": {"timesteps": -1}}, "timesteps"),
    ({"rllib": {"environment": {"env": "CartPole-v1"}}}, "env_id"),
    ({"rllib": {"env_runners": {"gym_env_vectorize_mode": "threads"}}}, "gym_env_vectorize_mode"),
    ({"billiards": {"self_play": "shared"}, "rllib": {"env_runners": {"gym_env_vectorize_mode": "vector_entry_point"}}},
     "no native vector env"),
    ({"billiards": {"self_play": "shared"}, "rllib": {"multi_agent": {"policies": ["a"]}}}, "policies are set"),
    ({"ppo": {}}, "top-level"),
    ([1, 2], "mapping"),
])
def test_bad_configs_name_the_key(data, match):
    with pytest.raises(RLlibConfigError, match=match):
        load_rllib_config(data)


def test_bad_flags_and_files(tmp_path):
    with pytest.raises(RLlibConfigError, match="section.key=value"):
        parse_assignments(["lr=3e-4"], "--set")
    with pytest.raises(RLlibConfigError, match="cannot read"):
        load_rllib_config(tmp_path / "missing.yaml")
    (tmp_path / "bad.yaml").write_text("rllib: [\n")
    with pytest.raises(RLlibConfigError, match="not valid YAML"):
        load_rllib_config(tmp_path / "bad.yaml")
    assert normalize_algo("sac") == "SAC"


def test_paths_and_checkpoint_envs_are_recognised(tmp_path):
    assert not is_rllib_path(tmp_path)  # an empty folder, an SB3 run: not RLlib
    (tmp_path / "run.json").write_text(json.dumps({"algo": "sac"}))
    assert not is_rllib_path(tmp_path)
    (tmp_path / "run.json").write_text(json.dumps({"framework": "rllib"}))
    assert is_rllib_path(tmp_path)
    ckpt = tmp_path / "ckpt"
    ckpt.mkdir()
    (ckpt / "rllib_checkpoint.json").write_text("{}")
    assert is_rllib_path(ckpt)
    assert env_of({"env": "billiards_env:BilliardsRack-v0", "env_config": {"speed_max": 3}}) == \
        ("BilliardsRack-v0", {"speed_max": 3}, False)
    assert env_of({"env": "billiards_selfplay:Billiards9Ball-v0"}) == ("Billiards9Ball-v0", {}, True)
    # The native vector env's own options (set for the env runners) are not single-env options.
    assert env_of({"env": "billiards_env:BilliardsOneBall-v0", "env_config": {"threads": 1, "speed_max": 2}}) == \
        ("BilliardsOneBall-v0", {"speed_max": 2}, False)


def test_the_cli_reports_bad_input_with_exit_status_2(capsys):
    from agents.rllib.train import main

    assert main(["--config", "/nonexistent/rllib.yaml"]) == 2
    assert "cannot read" in capsys.readouterr().err
    assert main(["--env", "BilliardsOneBall-v0", "--set", "lr=1"]) == 2
    assert "section.key=value" in capsys.readouterr().err
