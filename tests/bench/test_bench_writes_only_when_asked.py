"""``python -m benchmarks`` writes reports only when asked (``--write`` for docs/bench, ``--out DIR``) and prints
only what the run measured (``--only env`` used to overwrite the committed reports and reprint pooltool, latency and
accuracy figures from them)."""
from __future__ import annotations

import os
from pathlib import Path

import pytest

from benchmarks import __main__ as bench_cli

REPO = Path(__file__).resolve().parents[2]
ONE = "BilliardsOneBall-v0"


def _tree(root: Path) -> dict[str, float]:
    return {str(p.relative_to(root)): p.stat().st_mtime for p in root.rglob("*") if p.is_file()}


def test_env_section_prints_and_writes_nothing(tmp_path, capsys, monkeypatch):
    committed = _tree(REPO / "docs" / "bench")
    monkeypatch.chdir(tmp_path)
    assert bench_cli.main(["--only", "env", "--env-seconds", "0.02", "--env-ids", ONE]) == 0
    assert list(tmp_path.iterdir()) == []  # no docs/bench made where it ran
    assert _tree(REPO / "docs" / "bench") == committed  # the committed reports untouched
    out, err = capsys.readouterr()
    assert [line.split()[:3] for line in out.splitlines()[1:]] == [[ONE, "make", "kernel"], [ONE, "unwrapped", "kernel"]]
    targets = [line for line in err.splitlines() if line.startswith("[target]")]
    assert len(targets) == 1 and f"env.step on {ONE}" in targets[0]  # nothing it did not measure
    for other in ("pooltool", "first call", "exact faster"):
        assert other not in err
    assert "no report written" in err


def test_write_goes_to_docs_bench_and_out_elsewhere(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert bench_cli.main(["--only", "env", "--env-seconds", "0.02", "--env-ids", ONE, "--write"]) == 0
    assert {p.name for p in (tmp_path / "docs" / "bench").iterdir()} == {"speed.json", "speed.md"}
    assert bench_cli.main(["--only", "env", "--env-seconds", "0.02", "--env-ids", ONE, "--out", "elsewhere"]) == 0
    assert {p.name for p in (tmp_path / "elsewhere").iterdir()} == {"speed.json", "speed.md"}


def test_render_only_needs_a_place(capsys):
    with pytest.raises(SystemExit) as exc:
        bench_cli.main(["--render-only"])
    assert exc.value.code == 2 and "--write" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        bench_cli.main(["--write", "--out", os.devnull])  # one or the other
