"""RL Zoo run folders: read safely (no unsafe YAML loader), loaded with the README's three lines after
``python -m agents.zoo``, played by ``agents.evaluate``; and (slow) the README's zoo commands for real."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from collections import OrderedDict
from pathlib import Path

import numpy as np
import pytest
import yaml

from agents.evaluate import model_player, run_player
from agents.zoo import is_zoo_run, main as zoo_main, read_yaml, read_zoo_run

ROOT = Path(__file__).resolve().parents[2]
ENV_ID = "BilliardsOneBall-v0"
KWARGS = {"action_type": "ghost", "observation_type": "features", "speed_max": 1.8}


def _fake_zoo_run(tmp_path: Path) -> Path:
    """A run folder laid out as rl_zoo3.train writes it, with a tiny SAC model trained here."""
    import gymnasium as gym
    from stable_baselines3 import SAC

    import billiards_env  # noqa: F401

    run = tmp_path / "logs" / "sac" / f"{ENV_ID}_1"
    (run / ENV_ID).mkdir(parents=True)
    model = SAC("MlpPolicy", gym.make(ENV_ID, **KWARGS), learning_starts=10, batch_size=8,
                policy_kwargs={"net_arch": [8]}, seed=0)
    model.learn(20)
    model.save(run / "best_model.zip")
    model.save(run / f"{ENV_ID}.zip")
    hyper = OrderedDict([("env_kwargs", KWARGS), ("learning_rate", 0.003), ("n_envs", 8), ("policy", "MlpPolicy")])
    (run / ENV_ID / "config.yml").write_text(yaml.dump(hyper))  # the zoo's own dump: python/object tags
    args = OrderedDict([("algo", "sac"), ("env", ENV_ID), ("env_kwargs", KWARGS)])
    (run / ENV_ID / "args.yml").write_text(yaml.dump(args))
    return run


def test_zoo_run_reads_safely_and_loads_with_the_three_lines(tmp_path, capsys):
    run = _fake_zoo_run(tmp_path)
    assert "python/object/apply:collections.OrderedDict" in (run / ENV_ID / "config.yml").read_text()
    assert is_zoo_run(run) and is_zoo_run(run / "best_model.zip")
    z = read_zoo_run(run)
    assert (z.env_id, z.algo, z.env_kwargs, z.model_zip.name) == (ENV_ID, "sac", KWARGS, "best_model.zip")
    assert zoo_main([str(run)]) == 0 and "wrote" in capsys.readouterr().out
    # The README's three lines, on the zoo folder.
    import gymnasium as gym
    from stable_baselines3 import SAC

    spec = json.loads((run / "env.json").read_text())
    env = gym.make(spec["id"], **spec["kwargs"])
    model = SAC.load(run / "best_model.zip", env=env)
    obs, _ = env.reset(seed=0)
    obs, reward, terminated, truncated, info = env.step(model.predict(obs, deterministic=True)[0])
    assert terminated and np.isfinite(reward)
    # And as a player of agents.evaluate.
    res, rows = run_player(model_player(run), 4, seed=5)
    assert res.episodes == 4 and all(r["shots"] == 1 for r in rows)


def test_other_python_tags_stay_refused(tmp_path):
    bad = tmp_path / "config.yml"
    bad.write_text("!!python/object/apply:os.system ['echo hacked']\n")
    with pytest.raises(yaml.constructor.ConstructorError):
        read_yaml(bad)


def test_not_a_zoo_run_is_one_line(tmp_path, capsys):
    assert zoo_main([str(tmp_path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("agents.zoo: error:") and "not an RL Zoo run folder" in err and len(err.splitlines()) == 1


@pytest.mark.slow
def test_readme_zoo_command_trains_evaluates_and_loads(tmp_path):
    """The README's zoo command (a few thousand steps): it trains with evaluations (the evaluation env needs the
    env kwargs of the command line), and agents.zoo + agents.evaluate read what it wrote."""
    pytest.importorskip("rl_zoo3", reason="the zoo extra: pip install -e '.[zoo]'")
    env = {**os.environ, "PYTHONPATH": str(ROOT), "SDL_VIDEODRIVER": "dummy"}
    (tmp_path / "configs").symlink_to(ROOT / "configs")
    cmd = [sys.executable, "-m", "rl_zoo3.train", "--algo", "sac", "--env", ENV_ID, "--gym-packages", "billiards_env",
           "--conf-file", "configs/train/one_ball_sac.yaml", "--num-threads",
           "1", "--env-kwargs", "action_type:'ghost'", "observation_type:'features'", "speed_max:1.8",
           "--log-interval", "2000", "-f", "logs", "-n", "3000", "--eval-freq", "1000", "--eval-episodes", "5"]
    proc = subprocess.run(cmd, cwd=tmp_path, env=env, capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr[-3000:]
    run = tmp_path / "logs" / "sac" / f"{ENV_ID}_1"
    assert (run / "best_model.zip").exists()
    z = read_zoo_run(run)
    assert z.env_kwargs == KWARGS
    res, _ = run_player(model_player(run), 5, seed=0)
    assert res.episodes == 5
