"""The warm-up (``python -m billiards_env.warmup``): every task in one phase, every env among them, the worker
processes' report, and bad input refused."""
from __future__ import annotations

import pytest

from billiards_env import warmup
from billiards_env.registration import ENV_IDS


def test_every_task_runs_once_and_every_env_has_one():
    flat = [name for phase in warmup.PHASES for name in phase]
    assert sorted(flat) == sorted(warmup.TASKS) and len(flat) == len(set(flat))
    assert {f"env:{env_id}" for env_id in ENV_IDS} <= set(flat)
    # The physics kernels first: everything else calls them.
    assert set(warmup.PHASES[0]) == {"exact", "exact_spin", "step", "step_spin"}


def test_worker_processes_run_every_task_and_report_it():
    """On the cache the set-up built this is seconds: each task loads its kernels in a fresh process."""
    heard: list[str] = []
    seconds = warmup.warm_up(workers=2, report=lambda name, s: heard.append(name))
    assert sorted(heard) == sorted(warmup.TASKS) and seconds > 0.0


@pytest.mark.parametrize("argv", [["--workers", "0"], ["--workers", "-3"], ["--workers", "two"]])
def test_bad_worker_counts_are_refused(argv, capsys):
    with pytest.raises(SystemExit) as exc:
        warmup.main(argv)
    assert exc.value.code == 2 and "--workers" in capsys.readouterr().err
    with pytest.raises(ValueError, match="workers: must be >= 1"):
        warmup.warm_up(workers=0)
