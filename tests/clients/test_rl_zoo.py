"""RL Baselines3 Zoo: the shipped configs parse as the zoo reads them, and the README's command trains, as written
(no --hyperparams), a few thousand steps."""
from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from clients import require

ROOT = Path(__file__).resolve().parents[2]
CONFIGS = sorted(p for p in (ROOT / "configs" / "train").glob("*.yaml") if not p.name.startswith("rllib_"))


@pytest.mark.parametrize("path", CONFIGS, ids=[p.name for p in CONFIGS])
def test_every_config_entry_parses_as_the_zoo_reads_it(path):
    require("rl_zoo3")
    from rl_zoo3.exp_manager import ExperimentManager

    data = yaml.safe_load(path.read_text())  # the zoo's loader
    entries = {k: v for k, v in data.items() if k.startswith("Billiards")}
    assert entries, f"{path.name}: no env entry"
    for env_id, hyper in entries.items():
        parsed = ExperimentManager._preprocess_schedules(dict(hyper))  # raises on what the zoo cannot read
        lr = parsed.get("learning_rate")
        assert lr is None or callable(lr), (env_id, lr)


def readme_zoo_command() -> list[str]:
    """The docs' ``python -m rl_zoo3.train`` command (docs/training.md, the page the README sends zoo users to), as a
    user copies it."""
    text = (ROOT / "docs" / "training.md").read_text()
    block = re.search(r"(python -m rl_zoo3\.train .*?)\n(?!\s)", text.replace("\\\n", " "), re.S)
    assert block, "docs/training.md: no rl_zoo3.train command"
    import shlex

    return shlex.split(block.group(1))


def test_readme_command_trains_as_written(tmp_path):
    require("rl_zoo3")
    cmd = readme_zoo_command()
    assert "--hyperparams" not in cmd and "--gym-packages" in cmd and "--conf-file" in cmd
    (tmp_path / "configs").symlink_to(ROOT / "configs")
    env = {**os.environ, "PYTHONPATH": str(ROOT), "SDL_VIDEODRIVER": "dummy"}
    # 2,400 steps: past the file's learning_starts (2,000), so a few hundred SAC updates run.
    proc = subprocess.run([sys.executable, *cmd[1:], "-n", "2400", "--eval-freq", "-1", "--save-freq", "-1"],
                          cwd=tmp_path, env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    run = tmp_path / "logs" / "sac" / "BilliardsOneBall-v0_1"
    assert (run / "BilliardsOneBall-v0.zip").exists()
    config = (run / "BilliardsOneBall-v0" / "config.yml").read_text()
    assert "learning_rate" in config and "0.003" in config
