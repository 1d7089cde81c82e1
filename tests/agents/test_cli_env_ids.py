"""A mistyped env id on any command line: argparse's one error line with the did-you-mean and exit 2 (never
Gymnasium's NameNotFound traceback); a config file naming an unknown id: the tool's one-line config error."""
from __future__ import annotations

import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import pytest  # noqa: E402

from billiards_env.registration import check_env_id  # noqa: E402

TYPO = "BilliardsSnoker-v0"
HINT = "unknown env id 'BilliardsSnoker-v0'; did you mean 'BilliardsSnooker-v0'?"


def _main(module: str):
    import importlib

    return importlib.import_module(module).main


@pytest.mark.parametrize("module, argv", [
    ("agents.evaluate", ["--env", TYPO, "--players", "random", "--episodes", "1"]),
    ("agents.dataset", ["--env", TYPO]),
    ("agents.rllib.train", ["--env", TYPO]),
    ("billiards_env.play", ["--env", TYPO, "--demo"]),
])
def test_a_mistyped_env_id_is_one_line_and_exit_2(module, argv, capsys):
    with pytest.raises(SystemExit) as exit_:
        _main(module)(argv)
    assert exit_.value.code == 2
    err = capsys.readouterr().err
    last = err.strip().splitlines()[-1]
    assert "error: argument --env: " + HINT in last and "Traceback" not in err and "NameNotFound" not in err


def test_check_env_id_accepts_ours_and_other_registered_ids():
    assert check_env_id("BilliardsSnooker-v0") == "BilliardsSnooker-v0"
    assert check_env_id("CartPole-v1") == "CartPole-v1"  # any registered Gymnasium id
    with pytest.raises(ValueError, match=HINT):
        check_env_id(TYPO)


def test_a_training_config_naming_an_unknown_id_is_a_config_error(tmp_path, capsys):
    from agents.train import main

    cfg = tmp_path / "typo.yaml"
    cfg.write_text(f"{TYPO}:\n  policy: MlpPolicy\n  n_timesteps: 10\nbilliards:\n  algo: sac\n")
    assert main(["--config", str(cfg), "--timesteps", "1"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("agents.train: error: ") and HINT in err and "\n" not in err
