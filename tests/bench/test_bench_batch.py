"""Smoke test of the batch section of ``benchmarks`` (no timed assertions; pooltool not run): the search check
finds the batched player's choices equal to one-by-one simulation, the pooltool part reports its absence, and the
report lists every target with its figure."""
from __future__ import annotations

from benchmarks import batch


def test_search_choices_match_one_by_one():
    out = batch.run_search(n_tables=1, n_check=4)
    assert out["checked"] == 4 and out["same_choices"] == 4
    assert out["BilliardsThreeBalls-v0"]["median_s"] > 0


def test_pooltool_absent_is_reported():
    out = batch.run_pooltool(2, 1, "/nonexistent/python", allow_setup=False)
    assert not out["available"] and "pooltool" in out["note"]


def test_report_has_every_target():
    doc = {"machine": {"cpu": "test", "cores": 2, "python": "3", "numpy": "x", "numba": "y", "platform": "p",
                       "time": "now"},
           "command": batch.COMMAND, "time": "now", "pooltool": {"available": True, "version": "0.6.0",
                                                                 "random_shot_s": 8e-3, "shots_per_s": 125.0,
                                                                 "n_shots": 30, "rounds": 2},
           "vector_one_ball": {"None": 250_000.0, "1": 150_000.0, "2": 250_000.0},
           "vector_rack": {"None": 20_000.0, "1": 12_000.0, "2": 20_000.0},
           "candidates_1000": {"None": 3e-3, "1": 4e-3, "2": 3e-3, "n": 1000, "one_by_one_per_shot_s": 2e-5},
           "search": {"BilliardsOneBall-v0": {"median_s": 2e-3, "min_s": 1e-3, "n": 40},
                      "BilliardsThreeBalls-v0": {"median_s": 4e-3, "min_s": 2e-3, "n": 40},
                      "same_choices": 200, "checked": 200},
           "single_env": 31_000.0,
           "first_call": {"warm": {"import_s": 0.3, "first_s": 0.1, "total_s": 0.4},
                          "cold": {"import_s": 0.3, "first_s": 8.0, "total_s": 8.3}}}
    rows = batch.targets(doc)
    assert len(rows) == len(batch.TARGETS)
    verdicts = {r["name"].split(",")[0]: r["ok"] for r in rows}
    assert verdicts["one-ball episodes/s"] and not verdicts["rack steps/s"]
    md = batch.render_markdown(doc)
    assert md.count("| pass |") == sum(r["ok"] for r in rows) and "**miss**" in md
    assert "2,000x (125/s)" in md and batch.COMMAND in md
