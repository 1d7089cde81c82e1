"""``python -m billiards_env.fuzz --check FILE`` says what it found: each violation on its own line, or that
there were none (it used to print ``violations:`` with nothing after it on a clean scene)."""
from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

from billiards_env.fuzz import cli

CASE = Path(__file__).resolve().parent / "cases" / "zeno_min_speed_wedge.json"


def test_clean_scene_says_no_violations(capsys):
    assert cli.main(["--check", str(CASE)]) == 0
    out, err = capsys.readouterr()
    assert out.strip().endswith("events; no violations") and out.startswith("status rest,")
    assert err == ""


def test_each_violation_is_printed(capsys, monkeypatch):
    report = SimpleNamespace(status="rest", n_events=3, violations={"energy": "kinetic energy rose by 1e-6 at event 2",
                                                                    "overlap": "balls 1 and 2 overlap by 3e-9 m"})
    monkeypatch.setattr(cli, "run_case", lambda scene: (report, None))
    assert cli.main(["--check", str(CASE)]) == 1
    out, err = capsys.readouterr()
    assert out == ""
    assert err.splitlines() == ["status rest, 3 events; 2 violation(s):",
                                "  energy: kinetic energy rose by 1e-6 at event 2",
                                "  overlap: balls 1 and 2 overlap by 3e-9 m"]
