"""Smoke test of ``python -m benchmarks.cue_rest_accuracy`` on two games: the map's rest point is the engine's
wherever the cue ball meets its target once (the closed form's claim), and the report counts every grid point."""
from __future__ import annotations

from benchmarks import cue_rest_accuracy


def test_the_map_is_the_engine_where_the_cue_ball_meets_its_target_once():
    out = cue_rest_accuracy.measure(2, seed=3)
    parts = [out[k] for k in ("one_collision_no_cushion", "one_collision_cushions", "second_collision",
                              "another_ball_first")]
    assert out["grid_points"] > 0 and sum(p["points"] for p in parts) <= out["grid_points"]
    once = [p for p in parts[:2] if p["points"]]
    assert once
    for p in once:
        assert p["within_1mm"] == 1.0
    assert 0.0 <= out["scratch_agreement"] <= 1.0 and 0.0 <= out["pot_agreement"] <= 1.0
