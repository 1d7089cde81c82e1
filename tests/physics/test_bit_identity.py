"""Scenes that use none of the optional collision models (Alciatore throw, compliant cushions, a raised cushion nose,
squirt) give bit-identical results to the engine before those models existed: the fingerprints of
``bit_identity.py`` (rolling, drag and spin laws; exact, recorded and both step treatments; the batch API) against
the committed ``data/bit_identity.json``. Regenerate it only for an intended change of those results:
``python tests/physics/bit_identity.py --write``."""
from __future__ import annotations

import json

import pytest

from bit_identity import DATA, fingerprints


def test_fingerprints_unchanged():
    expected = json.loads(DATA.read_text())
    got = fingerprints()
    assert set(got) == set(expected)
    changed_scenes = [k for k in got if got[k]["scenes"] != expected[k]["scenes"]]
    assert not changed_scenes, f"the fuzz generator draws other scenes for {changed_scenes}: keep its draws"
    changed = [k for k in got if got[k]["physics"] != expected[k]["physics"]]
    if changed:
        pytest.fail(f"results changed (not bit-identical) for {changed}")
