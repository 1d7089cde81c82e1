"""Smoke test of ``python -m benchmarks.decision_time`` (no timed assertion): two players decide at every position
of one game, and each gets its figures."""
from __future__ import annotations

from benchmarks import decision_time


def test_every_player_decides_at_every_position(tmp_path):
    from agents.option_policies import Scorer, make_net

    Scorer([make_net(8)]).save(tmp_path / "s.pt")
    out = decision_time.measure(["position_rule", f"scorer:{tmp_path / 's.pt'}"], games=1)
    assert len(out) == 2
    counts = {r["decisions"] for r in out.values()}
    assert len(counts) == 1 and counts.pop() > 0
    for r in out.values():
        assert r["median_ms"] > 0 and r["obs_median_ms"] > 0
