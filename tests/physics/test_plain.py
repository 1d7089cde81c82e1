"""``plain`` (:mod:`billiards_env.physics.plain`): a constant passed from compiled code reaches the callee as its plain
type, so the callee is compiled once; and, after the warm-up's tasks in one process, the kernels called both from
Python and from compiled code (or with different constants) have exactly one compiled signature."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
import numpy as np
from numba import njit, prange, types

from billiards_env.physics.plain import plain

REPO = Path(__file__).resolve().parents[2]


def test_plain_is_the_identity_in_python():
    assert plain(False) is False and plain(3) == 3 and plain(-1.5) == -1.5


def test_a_constant_through_plain_reaches_the_callee_as_its_plain_type():
    @njit
    def callee(x, flag):
        return x + 1.0 if flag else x

    @njit
    def literal_caller(x):
        return callee(x, False)

    @njit
    def plain_caller(x):
        return callee(x, plain(False)) + callee(x, plain(True))

    assert plain_caller(1.0) == 3.0 and callee(1.0, True) == 2.0
    assert callee.signatures == [(types.float64, types.boolean)]  # Python's call and both plain ones: one compile
    assert literal_caller(1.0) == 1.0
    # without plain, numba compiles the callee once more, for the literal (what plain is there to avoid)
    assert len(callee.signatures) == 2 and isinstance(callee.signatures[1][1], types.Literal)


def test_plain_holds_in_a_prange_loop():
    """numba types a parallel loop's body again when it outlines it: the constant must stay plain there too."""
    @njit
    def callee(x, flag):
        return x + 1.0 if flag else x

    @njit(parallel=True)
    def rows(a):
        out = np.empty_like(a)
        for k in prange(a.shape[0]):
            out[k] = callee(a[k], plain(False))
        return out

    assert rows(np.ones(4)).tolist() == [1.0] * 4 and callee(1.0, True) == 2.0
    assert callee.signatures == [(types.float64, types.boolean)]


#: Kernels that Python and compiled callers (or call sites passing different constants) share: one signature each.
#: (Not ``simulate_exact``/``simulate_exact_spin``: the batch drivers keep a literal ``record=False`` on purpose, see
#: :mod:`billiards_env.physics.batch_rows`.)
ONE_SIGNATURE = (
    "billiards_env.physics.collide.resolve_ball_ball",
    "billiards_env.physics.kernel_logs.put_event",
    "billiards_env.physics.kernel_logs.snapshot",
    "billiards_env.physics.kernel_logs.reserve_states",
    "billiards_env.physics.batch_rows.store_row",
    "billiards_env.physics.layout.place_rows",
    "billiards_env.physics.layout.place_random_rows",
    "billiards_env.physics.layout.nearest_free_xy",
    "billiards_env.physics.layout.spot_cue_row",
    "billiards_env.physics.outcome.scan_shot",
    "billiards_env.physics.spin_collide.ball_hit",
    "billiards_env.physics.stronge._first_root",
    "billiards_env.physics.aim._window_sample",
    "billiards_env.physics.aim._window_result",
    "billiards_env.physics.aim._track_run",
    "billiards_env.physics.aim.segment_blocked_by",
    "billiards_env.players.geometry.ghost_shots_from",
    "billiards_env.players.geometry.shot_row",
    "billiards_env.players.geometry.object_path_clear",
    "billiards_env.envs.actions.aim_to_angle",
    "billiards_env.envs._game_kernels._play",
    "billiards_env.envs._action_kernels.shot_of_action",
    "billiards_env.rules.pool_judge.play",
    "billiards_env.rules.pool_judge._call",
    "billiards_env.rules.pool_judge._end",
    "billiards_env.rules.pool_judge._foul",
    "billiards_env.rules.pool_judge._clean",
    "billiards_env.rules.three_cushion._scan",
)

_SCRIPT = """
import gc, json
from numba.core.registry import CPUDispatcher
from billiards_env import warmup
for phase in warmup.PHASES:
    for name in phase:
        warmup.TASKS[name]()
print(json.dumps({f"{o.py_func.__module__}.{o.py_func.__qualname__}": [str(s) for s in o.signatures]
                  for o in gc.get_objects() if isinstance(o, CPUDispatcher)}))
"""


@pytest.mark.slow
def test_after_the_warm_up_the_shared_kernels_have_one_signature(tmp_path):
    """Every warm-up task in one process on an empty cache (minutes: it compiles everything)."""
    env = {"NUMBA_CACHE_DIR": str(tmp_path), "PATH": "/usr/bin:/bin", "PYTHONPATH": str(REPO),
           "SDL_VIDEODRIVER": "dummy", "BILLIARDS_COMPILE_NOTICE": "0", "BILLIARDS_PREBUILT": "0"}
    out = subprocess.run([sys.executable, "-c", _SCRIPT], env=env, cwd=REPO, capture_output=True, text=True,
                         timeout=3600)
    assert out.returncode == 0, out.stderr[-3000:]
    sigs = json.loads(out.stdout.strip().splitlines()[-1])
    missing = [name for name in ONE_SIGNATURE if name not in sigs]
    assert not missing, f"not compiled by the warm-up (renamed?): {missing}"
    several = {name: sigs[name] for name in ONE_SIGNATURE if len(sigs[name]) != 1}
    assert not several, json.dumps(several, indent=1)
