"""Commands the README pipes into ``head`` end quietly when the reader stops early (no BrokenPipe traceback)."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("args", [["-m", "billiards_env.envs"], ["-m", "billiards_env.envs", "--markdown"]])
def test_reader_closing_the_pipe_gives_no_traceback(args):
    read, write = os.pipe()
    os.close(read)  # the reader is gone before the first byte: every write fails with EPIPE
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    proc = subprocess.run([sys.executable, *args], stdout=write, stderr=subprocess.PIPE, text=True, cwd=ROOT,
                          env=env, timeout=120)
    os.close(write)
    assert proc.stderr == ""
    assert proc.returncode == 1
