"""What OpenMP's wait policy costs a loop of short parallel batches with Python between them (the shape of a training
loop on a native vector env): ``python -m benchmarks.openmp_wait``.

Each policy runs in its own process (libgomp reads ``OMP_WAIT_POLICY`` once, when it is loaded), alternately, and
the script prints the medians of wall and CPU seconds and the CPU/wall ratio. Unset (libgomp's default: its workers
spin after a batch) the idle worker burns a core between batches (CPU about twice wall on an idle 2-core machine)
and, on busy cores, takes time from the main thread; ``PASSIVE``, what importing ``billiards_env`` sets
(:mod:`billiards_env._openmp`), costs a wake-up per batch instead (a longer wall time on idle cores when the batches
are short).
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
from typing import Sequence

_WORKER = """
import json, sys, time
import numpy as np
from numba import njit, prange

@njit(parallel=True, cache=False)
def batch(a):
    s = 0.0
    for i in prange(a.shape[0]):
        s += a[i] * a[i]
    return s

rounds, python_work = int(sys.argv[1]), int(sys.argv[2])
a = np.ones(2000)
batch(a)
w0, c0 = time.perf_counter(), time.process_time()
for _ in range(rounds):
    batch(a)
    x = 0
    for j in range(python_work):
        x += j
print(json.dumps({"wall": time.perf_counter() - w0, "cpu": time.process_time() - c0}))
"""


def run_once(policy: str, rounds: int, python_work: int) -> dict[str, float]:
    """One process with ``OMP_WAIT_POLICY=policy`` (``unset``: libgomp's default): wall and CPU seconds of the
    loop."""
    env = {k: v for k, v in os.environ.items() if k != "OMP_WAIT_POLICY"}
    env["NUMBA_THREADING_LAYER"] = "omp"
    if policy != "unset":
        env["OMP_WAIT_POLICY"] = policy
    out = subprocess.run([sys.executable, "-c", _WORKER, str(rounds), str(python_work)], env=env, check=True,
                         capture_output=True, text=True, timeout=600)
    return json.loads(out.stdout.strip().splitlines()[-1])


def measure(rounds: int = 2000, python_work: int = 20000, repeats: int = 3) -> dict[str, dict[str, float]]:
    """Median wall and CPU seconds, and their ratio, per policy (the processes alternate)."""
    runs: dict[str, list[dict[str, float]]] = {"unset": [], "PASSIVE": []}
    for _ in range(repeats):
        for policy in runs:
            runs[policy].append(run_once(policy, rounds, python_work))
    out = {}
    for policy, rs in runs.items():
        wall = statistics.median(r["wall"] for r in rs)
        cpu = statistics.median(r["cpu"] for r in rs)
        out[policy] = {"wall": wall, "cpu": cpu, "cpu_per_wall": cpu / wall if wall > 0 else float("nan")}
    return out


def main(argv: Sequence[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks.openmp_wait", description=__doc__.split("\n\n")[0])
    p.add_argument("--rounds", type=int, default=2000, help="parallel batches per process")
    p.add_argument("--python-work", type=int, default=20000, help="Python loop iterations between batches")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--quick", action="store_true", help="a short run (100 batches, one process a policy)")
    args = p.parse_args(argv)
    if args.quick:
        args.rounds, args.repeats = 100, 1
    res = measure(args.rounds, args.python_work, args.repeats)
    print(f"load average {os.getloadavg()[0]:.2f}, {os.cpu_count()} cores; medians of {args.repeats} processes each")
    for policy, r in res.items():
        print(f"OMP_WAIT_POLICY={policy:8s} wall {r['wall']:.2f} s  CPU {r['cpu']:.2f} s  CPU/wall {r['cpu_per_wall']:.2f}")
    a, b = res["unset"], res["PASSIVE"]
    print(f"unset / PASSIVE: wall {a['wall'] / b['wall']:.2f}x, CPU {a['cpu'] / b['cpu']:.2f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
