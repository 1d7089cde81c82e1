"""Smoke test of the batch section of ``benchmarks`` (no timed assertions; pooltool not run): the search check
finds the batched player's choices equal to one-by-one simulation, the pooltool part reports its absence, and the
report lists every target with its figure."""
from __future__ import annotations

import numpy as np

from benchmarks import batch


def test_search_choices_match_one_by_one():
    out = batch.run_search(n_tables=1, n_check=4)
    assert out["checked"] == 4 and out["same_choices"] == 4
    assert out["BilliardsThreeBalls-v0"]["median_s"] > 0


def test_the_choice_check_runs_its_reference_and_can_fail(monkeypatch):
    """The second search really simulates through the one-row reference, and a wrong reference shows up as
    different choices (a reference that pockets nothing)."""
    real = batch._one_row_at_a_time
    calls = []

    def counting(*args, **kw):
        calls.append(len(args[2]))
        return real(*args, **kw)

    monkeypatch.setattr(batch, "_one_row_at_a_time", counting)
    assert batch.run_search(n_tables=1, n_check=2)["same_choices"] == 2 and sum(calls) > 0

    def blind(*args, **kw):
        res = real(*args, **kw)
        return res._replace(pocket=np.full_like(res.pocket, -1))

    monkeypatch.setattr(batch, "_one_row_at_a_time", blind)
    out = batch.run_search(n_tables=1, n_check=2)
    assert out["same_choices"] < out["checked"] == 2


def test_one_row_reference_equals_the_batch():
    import gymnasium as gym

    import billiards_env  # noqa: F401
    from billiards_env.physics.batch import run_shots

    env = gym.make("BilliardsThreeBalls-v0")
    env.reset(seed=4)
    u = env.unwrapped
    sim, balls = u.table_state.simulator, u.table_state.balls
    rng = np.random.default_rng(4)
    angles, speeds = rng.uniform(-np.pi, np.pi, 12), rng.uniform(0.5, 3.0, 12)
    whole = run_shots(sim, balls, angles, speeds, validate=False)
    rows = batch._one_row_at_a_time(sim, balls, angles, speeds, validate=False)
    for name in whole._fields:
        a, b = getattr(whole, name), getattr(rows, name)
        assert (a is None and b is None) or np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), name
    assert (whole.first_contact >= 0).any()


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
