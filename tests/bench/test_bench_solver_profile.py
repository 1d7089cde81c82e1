"""Smoke test of the exact solvers' per-event profile (``benchmarks/solver_profile.py``) in a tiny configuration (no
timed assertions): every scene and model is profiled, the parts' calls are counted from the kernels' own Python, and
the report renders."""
from __future__ import annotations

import pytest

from benchmarks import solver_profile

TINY = {"shots": 3, "breaks": 1, "game_steps": 4, "repeats": 1}


@pytest.fixture(scope="module")
def doc():
    return solver_profile.run(sizes=TINY)


def test_every_scene_and_model(doc):
    res = doc["results"]
    assert set(res) == {f"{s}/{m}" for s in solver_profile.SCENES for m in solver_profile.MODELS}
    for r in res.values():
        assert r["events_per_shot"] > 0 and r["us_per_event"] > 0.0
        parts = r["parts"]
        # Every event selects the next one (and the last selection finds none): at least one selection per event.
        assert parts["event selection"]["calls_per_event"] >= 1.0
        assert parts["roots in pairs"]["calls_per_event"] <= parts["pair re-prediction"]["calls_per_event"]


def test_report_renders(doc):
    md = solver_profile.report(doc["results"])
    for row in ("pair re-prediction", "event selection", "allocation", "event application and bookkeeping"):
        assert row in md
