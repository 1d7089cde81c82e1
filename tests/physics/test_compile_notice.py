"""A cold numba cache: one line says the kernels compile once and how to do it ahead (``billiards_env.warmup``);
a warm cache says nothing."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from billiards_env.physics.compile_notice import NOTICE

REPO = Path(__file__).resolve().parents[2]
#: Compiles one small kernel (the balls' validation), not the whole engine.
SCRIPT = ("from billiards_env.physics import Balls, Table, validate_balls; "
          "validate_balls(Balls.from_positions([(0.5, 0.5), (1.0, 0.5)]), Table())")


def _run(cache: Path, notice: str | None) -> str:
    env = {"NUMBA_CACHE_DIR": str(cache), "PATH": "/usr/bin:/bin", "PYTHONPATH": str(REPO),
           "BILLIARDS_PREBUILT": "0"}  # compiled here: the prebuilt kernels would leave nothing to compile
    if notice is not None:
        env["BILLIARDS_COMPILE_NOTICE"] = notice
    out = subprocess.run([sys.executable, "-c", SCRIPT], env=env, cwd=REPO, capture_output=True, text=True,
                         timeout=300)
    assert out.returncode == 0, out.stderr
    return out.stderr


def test_a_cold_cache_says_so_once_and_a_warm_one_says_nothing(tmp_path):
    cold = _run(tmp_path, "1")
    assert cold.count(NOTICE) == 1 and "python -m billiards_env.warmup" in NOTICE
    assert _run(tmp_path, "1") == ""  # the same cache, now warm


def test_output_to_a_pipe_stays_quiet_unless_asked(tmp_path):
    assert NOTICE not in _run(tmp_path / "a", None)  # stderr is a pipe here, not a terminal
    assert NOTICE not in _run(tmp_path / "b", "0")
