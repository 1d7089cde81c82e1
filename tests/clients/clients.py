"""What the client-library tests share: the env ids they run on and :func:`require`, which imports a client
library or skips (only where ``BILLIARDS_REQUIRE_CLIENTS`` is unset: in the run meant to test them, a missing
library fails)."""
from __future__ import annotations

import os
from types import ModuleType

import pytest

#: The env ids every client runs on: the one-shot scene and a game (an opponent's turns inside a step).
ENV_IDS = ["BilliardsOneBall-v0", "Billiards9Ball-v0"]


def require(module: str) -> ModuleType:
    """``module`` imported; skipped if missing, unless ``BILLIARDS_REQUIRE_CLIENTS`` is set (then it fails):
    scripts/test.sh runs these tests in .venv-clients (``scripts/setup.sh --clients``) with it set."""
    if os.environ.get("BILLIARDS_REQUIRE_CLIENTS"):
        return __import__(module, fromlist=["_"])
    return pytest.importorskip(module, reason=f"{module}: a client library of the clients extra "
                                              "(bash scripts/setup.sh --clients makes .venv-clients)")
