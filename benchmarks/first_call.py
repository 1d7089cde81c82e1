"""First-call latency probe, run in a fresh process by :mod:`.speed` as a script (not with ``-m``, which would
import the ``billiards_env`` package before the clock starts):

    python benchmarks/first_call.py [--env ID]

Prints one JSON line: ``import_s`` (importing the physics package, numpy and numba included), ``first_s``
(building a table, balls and a simulator and running the first shot: numba loads the kernel from its cache or
compiles it), and their sum ``total_s``. With ``--env ID``: ``import billiards_env`` + ``gymnasium.make(ID)`` +
``reset`` + the first ``step`` instead. ``NUMBA_CACHE_DIR`` (set by the caller) chooses a warm or a cold cache.

Imports nothing at module level beyond the standard library, so that every import of the package is timed
here (the caller also times the whole process, interpreter start-up included).
"""
from __future__ import annotations

import json
import sys
import time


def _shot() -> dict:
    t0 = time.perf_counter()
    from billiards_env.physics import Balls, Physics, Simulator, Table
    t1 = time.perf_counter()
    table = Table()
    balls = Balls.from_positions([(0.25 * table.length, 0.5 * table.width),
                                  (0.5 * table.length, 0.5 * table.width)]).strike(0, 0.0, 2.0)
    res = Simulator(table, Physics()).run(balls)
    t2 = time.perf_counter()
    return {"import_s": t1 - t0, "first_s": t2 - t1, "total_s": t2 - t0, "n_events": res.n_events}


def _env(env_id: str) -> dict:
    t0 = time.perf_counter()
    import gymnasium as gym

    import billiards_env  # noqa: F401  (registers the ids)
    t1 = time.perf_counter()
    env = gym.make(env_id)
    env.reset(seed=0)
    env.step(env.action_space.sample())
    t2 = time.perf_counter()
    return {"import_s": t1 - t0, "first_s": t2 - t1, "total_s": t2 - t0}


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    out = _env(argv[1]) if len(argv) >= 2 and argv[0] == "--env" else _shot()
    print(json.dumps(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
