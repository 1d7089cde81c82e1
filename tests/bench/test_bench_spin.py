"""Smoke test of the spin section of ``benchmarks`` in a tiny configuration (no timed assertions; pooltool not run)."""
from __future__ import annotations

import json

import pytest

from benchmarks import spin
from billiards_env.physics import Table

TINY = {"reps": 1, "break_reps": 1, "rounds": 1, "pt_reps": 1, "n_random": 2, "dts": 1}


@pytest.fixture(scope="module")
def doc():
    table = Table()
    return {"machine": {"cpu": "test", "cores": 1, "python": "3", "numpy": "x", "numba": "y", "platform": "p",
                        "time": "now"},
            "speed": spin.run_speed(True, table, "/nonexistent/python", allow_setup=False, sizes=TINY),
            "accuracy": spin.run_accuracy(True, table, sizes=TINY)}


def test_speed_rows(doc):
    rows = doc["speed"]["rows"]
    assert [r["shot"] for r in rows] == [s.name for s in spin.fixed_shots(Table())]
    assert not doc["speed"]["pooltool"]["available"] and "pooltool" in doc["speed"]["pooltool"]["note"]
    for r in rows:
        assert r["ours_s"] > 0 and r["ours_novalidate_s"] > 0 and r["ours_events"] >= 1
        assert r["preset_s"] > 0 and r["preset_events"] >= 1
        assert r["ours_status"] == "rest" and "speedup" not in r and "preset_speedup" not in r
    assert max(r["ours_events"] for r in rows) == next(r for r in rows if "break" in r["shot"])["ours_events"]


def test_accuracy_cells(doc):
    acc = doc["accuracy"]
    assert acc["n_shots"] == 4 + TINY["n_random"]
    assert {c["solver"] for c in acc["cells"]} == {"step-lecture", "step-rewind"}
    for c in acc["cells"]:
        assert c["dt"] == spin.DTS[0] and c["time_s"] > 0
        assert 0.0 <= c["pos_err_mean_mm"] <= c["pos_err_max_mm"] < 3000.0
        assert 0.0 <= c["outcome_diff_rate"] <= 1.0


def test_report_renders(doc, tmp_path):
    md = spin.render_markdown(doc)
    assert "pooltool not run" in md and "| draw into a ball |" in md and "step-rewind" in md
    (tmp_path / "spin.json").write_text(json.dumps(doc))
    spin.render(tmp_path)
    assert (tmp_path / "spin.md").read_text() == md
