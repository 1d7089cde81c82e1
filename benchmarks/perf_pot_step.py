"""The one-ball native vector env's compiled step under Linux ``perf``, with the compiled functions named.

``perf record -o /tmp/perf.data python -m benchmarks.perf_pot_step`` then ``perf report -i /tmp/perf.data
--no-children --sort sym`` lists where the step's time goes by function: the exact kernel and its helpers that
numba did not inline, numba's reference counting (``NRT_incref``, ``NRT_decref``), allocation (``malloc``,
``NRT_MemInfo_alloc_aligned``), libm (``hypot``). numba's JIT code has no symbols ``perf`` can read, so this compiles
the step afresh (not from the cache: the cached code keeps no symbol table) and writes ``/tmp/perf-<pid>.map``, the
file ``perf`` reads for JIT code, with every function of the compiled module at its address.
"""
from __future__ import annotations

import argparse
import os
import time
from typing import Any

import numpy as np


def write_perf_map(dispatcher: Any) -> int:
    """``/tmp/perf-<pid>.map`` for every function defined in ``dispatcher``'s compiled modules (address, size up to
    the next function, name); returns how many."""
    entries = []
    for cres in dispatcher.overloads.values():
        lib = cres.library
        engine = lib._codegen._engine  # numba's JIT engine: the functions' addresses
        for fn in lib._final_module.functions:
            if not fn.is_declaration:
                address = engine.get_function_address(fn.name)
                if address:
                    entries.append((address, fn.name))
    entries.sort()
    with open(f"/tmp/perf-{os.getpid()}.map", "w") as f:
        for i, (address, name) in enumerate(entries):
            size = entries[i + 1][0] - address if i + 1 < len(entries) else 0x10000
            f.write(f"{address:x} {size:x} {name}\n")
    return len(entries)


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks.perf_pot_step", description=__doc__.split("\n")[0])
    p.add_argument("--steps", type=int, default=2000, help="steps of 1024 tables (default 2000)")
    args = p.parse_args(argv)
    import gymnasium as gym
    from numba import njit

    import billiards_env  # noqa: F401  (registers the ids)
    from billiards_env.envs import _vector_kernels

    kernel = njit(nogil=True)(_vector_kernels.pot_step_rows.py_func)  # compiled here: its module has symbols
    n = 1024
    env = gym.make_vec("BilliardsOneBall-v0", n, autoreset_mode="same_step", threads=1)
    env.reset(seed=0)
    u: Any = env.unwrapped
    sim = u.template.simulator
    act = np.random.default_rng(0).uniform(-1.0, 1.0, (n, 2))
    start = (u.pos.copy(), u.on_table.copy(), u.shots.copy())
    active, rows = np.ones(n, np.bool_), np.arange(n, dtype=np.int64)
    state = (u.pos, u.vel, u.ang, u.on_table, u.shots, u._radius, u._mass, sim.pocket_xy, sim.pocket_r, sim.params,
             int(sim.max_events), u._cfg, u._icfg, u._noise, u._out, u._fout, u._iout, u._obs)
    kernel(rows, act, active, *state)
    print(f"[perf_pot_step] {write_perf_map(kernel)} functions in /tmp/perf-{os.getpid()}.map")
    t0 = time.perf_counter()
    for _ in range(args.steps):  # the same shots each time: the tables put back before each step
        u.pos[:], u.on_table[:], u.shots[:] = start
        u.vel[:] = 0.0
        u.ang[:] = 0.0
        kernel(rows, act, active, *state)
    print(f"[perf_pot_step] {(time.perf_counter() - t0) / args.steps / n * 1e6:.2f} us per table")
    env.close()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
