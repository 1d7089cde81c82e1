"""Smoke test of ``python -m benchmarks.openmp_wait`` (no timed assertion): both policies run in their own process
and get their figures."""
from __future__ import annotations

from benchmarks import openmp_wait


def test_both_policies_are_measured_in_their_own_process():
    out = openmp_wait.measure(rounds=20, python_work=100, repeats=1)
    assert set(out) == {"unset", "PASSIVE"}
    for r in out.values():
        assert r["wall"] > 0 and r["cpu"] > 0 and r["cpu_per_wall"] > 0
