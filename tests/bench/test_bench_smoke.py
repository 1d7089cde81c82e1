"""Smoke tests of the accuracy suite of ``benchmarks`` in a tiny configuration (no timed assertions)."""
from __future__ import annotations

import json

import pytest

from benchmarks import accuracy
from benchmarks.common import break_shots, one_ball_shots, three_ball_shots, write_json

DTS = (1 / 30, 1e-3)


@pytest.fixture(scope="module")
def doc():
    cfg = accuracy.AccuracyConfig(n_shots={"one_ball": 2, "three_ball": 0, "break": 0}, dts=DTS,
                                  nudges=(1e-9, 1e-4), cell_budget_s=30.0)
    return accuracy.run_accuracy(cfg, progress=False)


def test_structure(doc):
    assert {r["law"] for r in doc["exact"]} == {"rolling", "drag"}
    assert {r["category"] for r in doc["exact"]} == {"one_ball"}
    # laws x contacts x dts cells, each with every field filled.
    assert len(doc["cells"]) == 2 * 2 * len(DTS)
    assert {c["solver"] for c in doc["cells"]} == {"step-lecture", "step-rewind"}
    for c in doc["cells"]:
        assert c["n_shots"] == 2 and c["skipped"] is None
        assert c["median_time_s"] > 0 and c["shots_per_s"] > 0 and c["exact_median_time_s"] > 0
        assert 0.0 <= c["pos_err_mean_mm"] <= c["pos_err_max_mm"]
        assert 0.0 <= c["outcome_diff_rate"] <= 1.0
        assert isinstance(c["n_tunnelled"], int) and c["n_tunnelled"] >= 0
        assert len(c["per_shot_time_s"]) == 2
    assert len(doc["chaos"]) == 2 * 2  # laws x nudges
    json.dumps(doc, allow_nan=True)


def test_exact_against_itself_is_zero(doc):
    for r in doc["exact"]:
        assert r["self_error_max_mm"] == 0.0


def test_errors_are_sane(doc):
    cells = {(c["law"], c["solver"], c["dt"]): c for c in doc["cells"]}
    for law in ("rolling", "drag"):
        for solver in ("step-lecture", "step-rewind"):
            coarse = cells[(law, solver, DTS[0])]["pos_err_mean_mm"]
            fine = cells[(law, solver, DTS[1])]["pos_err_mean_mm"]
            # Errors are bounded by the table; a finer dt must not be much worse than 1/30 s.
            assert coarse < 3000.0 and fine < 3000.0
            assert fine <= 5.0 * coarse + 1.0, (law, solver, coarse, fine)
        # The rewind contact converges: at 1e-3 s it is close to exact on these shots.
        assert cells[(law, "step-rewind", DTS[1])]["pos_err_mean_mm"] < 20.0
    for r in doc["chaos"]:
        assert 0.0 <= r["outcome_change_rate"] <= 1.0
        assert r["pos_div_mean_mm"] is None or r["pos_div_mean_mm"] >= 0.0


def test_reports(doc, tmp_path):
    from benchmarks.common import machine_info

    doc["machine"] = machine_info()
    doc["target_exact_faster"] = accuracy.exact_faster_check(doc)
    assert doc["target_exact_faster"]["pass"] in (True, False, None)
    md = accuracy.render_markdown(doc, doc["machine"], "speed_vs_error.png")
    assert "| solver | dt |" in md and "Chaos floor" in md
    write_json(tmp_path / "a.json", doc)
    assert json.loads((tmp_path / "a.json").read_text())["cells"]
    pytest.importorskip("matplotlib")
    accuracy.plot(doc, tmp_path / "a.png")
    assert (tmp_path / "a.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_shot_sets_are_seeded_and_valid():
    from billiards_env.physics import Table, validate_balls

    table = Table()
    a, b = one_ball_shots(5, seed=3), one_ball_shots(5, seed=3)
    assert [s.angle for s in a] == [s.angle for s in b]
    for s in a + three_ball_shots(3) + break_shots(3):
        validate_balls(s.struck(), table)
    assert len({s.balls.pos[0, 1] for s in break_shots(3)}) == 3
