"""Helpers compiled without numba's reference counting (``kernel_logs.leaf`` and ``leaf_public``, ``_nrt=False``)
are safe only if they never hand out an array: the caller keeps the arrays it passes, and an array a leaf returned
would be released by the caller once too often. numba itself refuses an allocation in a leaf and an array got from
a call (checked here, as the rule leans on it); returning an argument it allows, so the tests hold every leaf to
that, and check that the kernels calling them free what they allocate (numba's allocation counters)."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from numba import errors, njit

REPO = Path(__file__).resolve().parents[2]

#: Steps of the pot scenes (rolling and spin), the jaw tables' fuzz scenes (every law, the optional collision
#: models), the games' vector env (its geometric opponent and rules) and a search decision, in a fresh process.
#: Prints the live numba arrays after a warm-up and after more of the same, and with ``--returns`` the leaf
#: helpers compiled in this process whose compiled result holds an array.
_SCRIPT = r"""
import importlib, json, pkgutil, sys
import numpy as np
import gymnasium as gym
import billiards_env
from numba import types
from numba.core.registry import CPUDispatcher
from numba.core.runtime import rtsys
from billiards_env.fuzz.generator import NumpySource, random_scene, shot_rng
from billiards_env.physics.scene import Scene
from billiards_env.players.search import SearchPlayer

envs = [gym.make_vec(env_id, 8, **kw) for env_id, kw in (
    ("BilliardsOneBall-v0", {}),
    ("BilliardsThreeBalls-v0", {"physics": {"friction": "spin"}, "spin_action": True}),
    ("Billiards9Ball-v0", {}), ("Billiards8Ball-v0", {}))]
single = gym.make("Billiards9Ball-v0")
obs, _ = single.reset(seed=1)
rng = np.random.default_rng(0)
shot = [0]

def play(steps):
    for env in envs:
        for _ in range(steps):
            env.step(rng.uniform(-1, 1, (8,) + env.single_action_space.shape))
    for _ in range(steps):
        scene = random_scene(NumpySource(shot_rng(5, shot[0])), solver="exact", max_time=60.0, spin=0.5,
                             models=0.5, table=("jaws", "rect")[shot[0] % 2])
        Scene.from_dict(scene).run()
        shot[0] += 1
    SearchPlayer(seed=0).act(single, obs)

def live():
    s = rtsys.get_allocation_stats()
    return s.mi_alloc - s.mi_free

for env in envs:
    env.reset(seed=0)
play(5)
before = live()
play(40)
after = live()
out = {"before": before, "after": after, "allocs": rtsys.get_allocation_stats().mi_alloc}
if "--returns" in sys.argv:
    def has_array(t):
        return isinstance(t, types.Array) or (isinstance(t, types.BaseTuple) and any(has_array(x) for x in t))
    leaves, bad = set(), []
    for info in pkgutil.walk_packages(billiards_env.__path__, "billiards_env."):
        if info.name.endswith("__main__") or ".render" in info.name:
            continue
        for name, obj in vars(importlib.import_module(info.name)).items():
            if isinstance(obj, CPUDispatcher) and obj.targetoptions.get("_nrt") is False \
                    and obj.py_func.__module__ == info.name:
                leaves.add(info.name + "." + name)
                if not obj.signatures:
                    bad.append(info.name + "." + name + " (not compiled by these steps)")
                bad += [info.name + "." + name for c in obj.overloads.values() if has_array(c.signature.return_type)]
    out["leaves"], out["bad"] = sorted(leaves), bad
print(json.dumps(out))
"""


def _run(*args: str, cache_dir: str | None = None) -> dict:
    env = {**os.environ, "NUMBA_NRT_STATS": "1", "SDL_VIDEODRIVER": "dummy"}
    if cache_dir is not None:
        env["NUMBA_CACHE_DIR"] = cache_dir  # an empty cache: every function compiled in the process
        env["BILLIARDS_PREBUILT"] = "0"  # (not unpacked from the prebuilt kernels)
    out = subprocess.run([sys.executable, "-c", _SCRIPT, *args], capture_output=True, text=True, cwd=REPO, env=env,
                         timeout=1800)
    assert out.returncode == 0, out.stderr[-3000:]
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_kernels_free_what_they_allocate():
    """40 more rounds of the steps leave as many live numba arrays as before them: no array lost or released once
    too often through a leaf helper's missing count."""
    got = _run()
    assert got["allocs"] > 1000  # the steps did allocate (the counters are on)
    assert got["after"] == got["before"], got


@pytest.mark.slow
def test_no_leaf_returns_an_array(tmp_path):
    """Every leaf helper, compiled afresh by the steps, returns no array (an empty numba cache: about 4 minutes)."""
    got = _run("--returns", cache_dir=str(tmp_path))
    assert len(got["leaves"]) >= 20, got["leaves"]
    assert not got["bad"], f"leaf helpers returning an array or not exercised: {got['bad']}"


#: The leaf helpers' option (``kernel_logs.leaf``), without the cache (the helpers below are compiled per run).
uncounted = njit(_nrt=False)


def test_numba_refuses_an_allocation_in_a_leaf():
    @uncounted
    def makes_one(n):
        return np.zeros(n)[0]

    with pytest.raises(errors.TypingError, match="Only accept returning of array passed"):
        makes_one(3)


def test_numba_refuses_an_array_from_a_call_in_a_leaf():
    @njit
    def tail(a):
        return a[1:]

    @uncounted
    def gets_one(a):
        return tail(a)[0]

    with pytest.raises(errors.TypingError):
        gets_one(np.arange(3.0))
