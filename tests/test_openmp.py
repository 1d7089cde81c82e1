"""numba's OpenMP workers sleep between batches unless the user asked otherwise (billiards_env._openmp)."""
from __future__ import annotations

import os
import subprocess
import sys

import pytest

PROBE = ("import os, {first}; import torch; print(os.environ.get('OMP_WAIT_POLICY'))")


def _policy_after(first: str, env_value: str | None) -> str:
    env = {k: v for k, v in os.environ.items() if k != "OMP_WAIT_POLICY"}
    if env_value is not None:
        env["OMP_WAIT_POLICY"] = env_value
    out = subprocess.run([sys.executable, "-c", PROBE.format(first=first)], env=env, capture_output=True, text=True,
                         check=True, timeout=300)
    return out.stdout.strip().splitlines()[-1]


@pytest.mark.parametrize("first", ["billiards_env", "agents"])
def test_importing_the_package_makes_the_workers_passive(first):
    assert _policy_after(first, None) == "PASSIVE"


def test_a_policy_the_user_set_is_kept():
    assert _policy_after("billiards_env", "ACTIVE") == "ACTIVE"
