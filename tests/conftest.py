"""Shared fixtures: ``golden``, the recorded results of the Python the compiled players replaced (:mod:`golden`)."""
from __future__ import annotations

import re
from typing import Any

import pytest

from golden import GOLDEN_DIR, Golden


@pytest.fixture
def golden(request: pytest.FixtureRequest) -> Any:
    """The :class:`~golden.Golden` of this test: its records are
    ``tests/golden_records/<module>__<test>[<params>].json``."""
    name = re.sub(r"[^A-Za-z0-9_.\-\[\]]+", "_", f"{request.node.module.__name__.rsplit('.', 1)[-1]}__"
                  f"{request.node.name}")
    g = Golden(GOLDEN_DIR / f"{name}.json")
    yield g
    g.finish()
