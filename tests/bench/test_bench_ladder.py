"""Smoke test of the model ladder of ``benchmarks`` (``benchmarks/ladder.py``) in a tiny configuration (no timed
assertions): every rung plays every scene, the preset agrees with itself, and without english (no squirt) the
preset less squirt is the preset, shot for shot."""
from __future__ import annotations

import json

import pytest

from benchmarks import ladder

TINY = {"shots": 3, "breaks": 2, "rounds": 1}


@pytest.fixture(scope="module")
def doc():
    return ladder.run(sizes=TINY)


def test_every_rung_plays_every_scene(doc):
    rows = doc["rows"]
    assert {r["model"] for r in rows} == set(ladder.rungs())
    assert {r["family"] for r in rows} == {"one ball", "9-ball break", "9-ball run-out", "off cushions"}
    assert {r["tip"] for r in rows} == {"centre ball", "english"}
    for r in rows:
        assert 0.0 <= r["same_outcome"] <= r["same_pocketed"] <= 1.0
        assert r["time_per_shot_s"] > 0.0
        assert r["shots"] == (TINY["breaks"] if r["family"] == "9-ball break" else TINY["shots"])


def test_reference_and_squirt_free_rung(doc):
    for r in doc["rows"]:
        if r["model"] == ladder.REFERENCE:
            assert r["same_outcome"] == 1.0 and r["median_pos_diff_mm"] == 0.0
        if r["model"] == "spin + throw + cushion" and r["tip"] == "centre ball":
            assert r["same_outcome"] == 1.0  # squirt needs side english: centre-ball shots are the preset's


def test_report_renders(doc, tmp_path):
    md = ladder.render_markdown(doc)
    assert "| one ball, centre ball | 3 |" in md and "`spin + throw + cushion`" in md
    (tmp_path / "ladder.json").write_text(json.dumps(doc))
    ladder.render(tmp_path)
    assert (tmp_path / "ladder.md").read_text() == md
