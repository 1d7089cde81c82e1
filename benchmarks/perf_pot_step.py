"""The one-ball native vector env's step under Linux ``perf``, with its compiled functions named.

``perf record -k CLOCK_MONOTONIC -o /tmp/perf.data python -m benchmarks.perf_pot_step`` then the ``perf report``
command it prints (``--time`` the window of the steps, past the imports and the compile) lists where the step's time
goes by function: the exact kernel and its helpers that
numba did not inline, numba's reference counting (``NRT_incref``, ``NRT_decref``), allocation (``malloc``,
``NRT_MemInfo_alloc_aligned``), libm (``hypot``), the Python of the env's step. numba's JIT code has no symbols
``perf`` can read, so this compiles the pot step afresh (``recompile``: code loaded from the cache keeps no function
list; the recompiled code goes back into the cache) and writes ``/tmp/perf-<pid>.map``, the file ``perf`` reads for
JIT code, with every function of the compiled module at its address. Random actions; 1,024 tables on one thread.
"""
from __future__ import annotations

import argparse
import os
import time
from typing import Any

import numpy as np


def write_perf_map(dispatcher: Any) -> int:
    """``/tmp/perf-<pid>.map`` for every function defined in ``dispatcher``'s compiled modules (address, size up to
    the next function, name), from numba's public library API; returns how many. The dispatcher must have been
    compiled in this process (``recompile()``): code loaded from the cache keeps no function list."""
    entries = []
    for cres in dispatcher.overloads.values():
        library = cres.library
        for fn in library.get_defined_functions():
            address = library.get_pointer_to_function(fn.name)
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
    p.add_argument("--steps", type=int, default=1000, help="steps of 1024 tables (default 1000)")
    args = p.parse_args(argv)
    import gymnasium as gym

    import billiards_env  # noqa: F401  (registers the ids)
    from billiards_env.envs import _vector_kernels

    n = 1024
    env = gym.make_vec("BilliardsOneBall-v0", n, autoreset_mode="same_step", threads=1)
    env.reset(seed=0)
    actions = np.random.default_rng(0).uniform(-1.0, 1.0, (64, n, 2)).astype(np.float32)
    env.step(actions[0])  # the step's kernels loaded (from the cache) ...
    _vector_kernels.pot_step_rows.recompile()  # ... and the pot step compiled again here: its module lists its functions
    print(f"[perf_pot_step] {write_perf_map(_vector_kernels.pot_step_rows)} functions in /tmp/perf-{os.getpid()}.map")
    start, t0, c0 = time.clock_gettime(time.CLOCK_MONOTONIC), time.perf_counter(), time.thread_time()
    block, blocks = max(args.steps // 7, 1), []  # the CPU time of blocks of steps: the fastest is the least disturbed
    for k in range(args.steps):
        env.step(actions[k % 64])
        if (k + 1) % block == 0:
            blocks.append(time.thread_time())
    end = time.clock_gettime(time.CLOCK_MONOTONIC)
    wall = (time.perf_counter() - t0) / args.steps / n * 1e6
    fastest = min(b - a for a, b in zip([c0] + blocks, blocks)) / block / n * 1e6
    print(f"[perf_pot_step] {wall:.2f} us per table and step (CPU time, fastest block of {block} steps: "
          f"{fastest:.2f} us)")
    print(f"[perf_pot_step] the steps alone: perf report -i /tmp/perf.data --no-children --sort sym "
          f"--time {start:.6f},{end:.6f}")
    env.close()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
