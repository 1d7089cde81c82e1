"""The ``golden`` records (tests/golden.py): a value the test checks must be the recorded one, in the recorded
number, and equal values share their record."""
from __future__ import annotations

import json

import numpy as np
import pytest

import golden
from golden import Golden, canonical, digest


def _recorded(tmp_path, values) -> Golden:
    path = tmp_path / "t.json"
    path.write_text(json.dumps([digest(v) for v in values]))
    return Golden(path)


def test_the_recorded_values_pass_and_another_value_fails(tmp_path):
    g = _recorded(tmp_path, [(1.0, np.float64(2.5)), np.arange(3.0)])
    g.check((1.0, 2.5))  # a numpy scalar and a float are the same number
    g.check(np.array([0.0, 1.0, 2.0]))
    g.finish()
    g = _recorded(tmp_path, [1.0])
    with pytest.raises(AssertionError, match="not the recorded value"):
        g.check(1.0 + 2.0 ** -52)  # one unit in the last place


def test_a_test_that_checks_fewer_or_more_values_fails(tmp_path):
    g = _recorded(tmp_path, [1, 2])
    g.check(1)
    with pytest.raises(AssertionError, match="1 values checked, 2 recorded"):
        g.finish()
    g = _recorded(tmp_path, [1])
    g.check(1)
    with pytest.raises(AssertionError, match="more values than the 1 recorded"):
        g.check(2)


def test_equal_values_share_a_record_and_nan_is_itself():
    assert digest(-0.0) == digest(0.0) and digest(np.array([-0.0])) == digest(np.array([0.0]))
    assert digest(float("nan")) == digest(np.float64("nan")) != digest(0.0)
    assert digest([1, 2]) == digest((1, 2)) != digest([2, 1])
    assert canonical(0.1) == (0.1).hex()
    with pytest.raises(TypeError, match="no canonical form"):
        canonical(object())


def test_recording_asserts_the_compiled_value_equals_the_reference(tmp_path, monkeypatch):
    monkeypatch.setattr(golden, "RECORD", True)
    g = Golden(tmp_path / "new.json")
    g.check(3, lambda: 3)
    with pytest.raises(AssertionError, match="differs from the reference"):
        g.check(3, lambda: 4)
    g.finish()
    assert json.loads((tmp_path / "new.json").read_text()) == [digest(3), digest(3)]
