"""``scripts/setup.sh`` says what it is doing (it used to be silent for minutes, ~90 s of it compiling)."""
from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def test_setup_says_each_step():
    """On a set-up machine (CI runs it first) the script checks the venv and compiles the kernels: both said."""
    if not (ROOT / ".venv" / "bin" / "python").exists():
        pytest.skip("no .venv in this checkout (scripts/setup.sh makes it; CI has one)")
    proc = subprocess.run(["bash", "scripts/setup.sh"], cwd=ROOT, capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr[-2000:]
    lines = proc.stdout.splitlines()
    assert any(line.startswith("setup: .venv is up to date") or line.startswith("setup: installing billiards_env")
               for line in lines), lines
    assert any(line.startswith("setup: compiling the physics kernels") for line in lines), lines
