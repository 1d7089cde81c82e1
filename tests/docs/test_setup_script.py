"""``scripts/setup.sh`` says what it is doing (it used to be silent for minutes, ~90 s of it compiling)."""
from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def test_setup_says_each_step():
    """On a set-up machine (CI runs it first) the script checks the venv, says whether the prebuilt kernels are used
    and loads the kernels: all said."""
    if not (ROOT / ".venv" / "bin" / "python").exists():
        pytest.skip("no .venv in this checkout (scripts/setup.sh makes it; CI has one)")
    proc = subprocess.run(["bash", "scripts/setup.sh"], cwd=ROOT, capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr[-2000:]
    lines = proc.stdout.splitlines()
    assert any(line.startswith("setup: .venv is up to date") or line.startswith("setup: installing billiards_env")
               for line in lines), lines
    assert any(line.startswith("setup: platform ") and "prebuilt kernels: " in line for line in lines), lines
    assert any(line.startswith("setup: loading the physics kernels") for line in lines), lines
    assert any(line.startswith("setup: kernels ready in ") for line in lines), lines


def _test_sh(tmp_path: Path, rllib_venv: bool, args: list[str], env: dict[str, str], clients_venv: bool = True
             ) -> tuple[str, list[str]]:
    """``scripts/test.sh`` in a copy whose set-up script and venvs' pythons only record their calls: what it says
    first, and what it ran."""
    (tmp_path / "scripts").mkdir()
    (tmp_path / "scripts" / "test.sh").write_text((ROOT / "scripts" / "test.sh").read_text())
    calls = tmp_path / "calls"
    stub = '#!/usr/bin/env bash\necho "{venv} $*" >> {calls}\n'
    make_rllib = (f'mkdir -p .venv-rllib/bin; printf \'{stub.format(venv=".venv-rllib", calls=calls)}\' '
                  '> .venv-rllib/bin/python; chmod +x .venv-rllib/bin/python')
    make_clients = (f'mkdir -p .venv-clients/bin; printf \'{stub.format(venv=".venv-clients", calls=calls)}\' '
                    '> .venv-clients/bin/python; chmod +x .venv-clients/bin/python')
    (tmp_path / "scripts" / "setup.sh").write_text(f'echo "setup $*" >> {calls}\n'
                                                   f'if [ "${{1:-}}" = --rllib ]; then {make_rllib}; fi\n'
                                                   f'if [ "${{1:-}}" = --clients ]; then {make_clients}; fi\n')
    tools = [(".venv", "python"), (".venv-docs", "mkdocs")] + ([(".venv-clients", "python")] if clients_venv else [])
    for venv, tool in tools + ([(".venv-rllib", "python")] if rllib_venv else []):
        py = tmp_path / venv / "bin" / tool
        py.parent.mkdir(parents=True)
        py.write_text(stub.format(venv=venv, calls=calls))
        py.chmod(0o755)
    proc = subprocess.run(["bash", str(tmp_path / "scripts" / "test.sh"), *args], capture_output=True, text=True,
                          env={"PATH": "/usr/bin:/bin", **env}, timeout=60)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout, calls.read_text().splitlines()


def test_test_sh_says_it_sets_up_rllib_before_it_starts(tmp_path):
    out, calls = _test_sh(tmp_path, False, [], {})
    first = out.splitlines()[0]
    assert first.startswith("test: the RLlib tests too: this first sets up .venv-rllib") and "2.1 GB" in first
    assert "BILLIARDS_SKIP_RLLIB=1" in first
    assert calls[:2] == ["setup ", "setup --rllib"]
    assert any(c.startswith(".venv-rllib -m pytest") for c in calls)


def test_test_sh_says_it_sets_up_the_clients_venv_before_it_starts(tmp_path):
    out, calls = _test_sh(tmp_path, True, [], {}, clients_venv=False)
    said = [line for line in out.splitlines() if line.startswith("test: the client libraries' tests too")]
    assert len(said) == 1 and ".venv-clients" in said[0] and "2.4 GB" in said[0]
    assert out.splitlines().index(said[0]) < 2  # before any set-up runs
    assert "setup --clients" in calls and any(c.startswith(".venv-clients -m pytest") for c in calls)
    (tmp_path / "again").mkdir()
    again, _ = _test_sh(tmp_path / "again", True, [], {}, clients_venv=True)
    assert not any(line.startswith("test: the client libraries' tests too") for line in again.splitlines())


def test_test_sh_says_when_the_rllib_venv_is_there_already(tmp_path):
    out, calls = _test_sh(tmp_path, True, [], {})
    assert out.splitlines()[0].startswith("test: the RLlib tests too, in .venv-rllib (set up already; checked)")
    assert "setup --rllib" in calls


@pytest.mark.parametrize("args, env", [([], {"BILLIARDS_SKIP_RLLIB": "1"}), (["-q"], {})])
def test_test_sh_can_leave_rllib_out(tmp_path, args, env):
    out, calls = _test_sh(tmp_path, False, args, env)
    assert out.splitlines()[0] == "test: the default test set in .venv (the RLlib tests and .venv-rllib left out)"
    assert "setup --rllib" not in calls and not any(c.startswith(".venv-rllib") for c in calls)
    assert any(c.startswith(".venv -m pytest -n 2") for c in calls)
