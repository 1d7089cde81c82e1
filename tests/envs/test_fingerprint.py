"""Behaviour kept: every fingerprint case (``fingerprint_cases.py``: envs, vector envs, two-player envs and
players on every id, type, solver and law, fixed seeds) hashes as recorded in ``fingerprint.json``. A failure
means observations, rewards, infos or player choices changed; if the change is deliberate, regenerate the file with
``python tests/envs/fingerprint_cases.py --write`` and say why in the commit."""
from __future__ import annotations

import json

import pytest
from fingerprint_cases import FILE, canon, cases

RECORDED = json.loads(FILE.read_text())
CASES = dict(cases())


def test_every_case_is_recorded():
    assert sorted(CASES) == sorted(RECORDED)


@pytest.mark.parametrize("name", sorted(CASES))
def test_fingerprint(name):
    assert CASES[name]() == RECORDED[name], f"{name}: behaviour changed (see the module docstring)"


def test_canon_tells_floats_apart():
    # The hash must see a change in the last bit of a float and a change of type.
    assert canon(0.1) != canon(0.1 + 2 ** -56)
    assert canon(1) != canon(1.0)
    assert canon({"opponent_turns": [1]}) != canon({})  # every info key is hashed (none added since)
