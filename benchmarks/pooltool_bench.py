"""Time pooltool on the benchmark's shots. Run with the pooltool venv's Python, as a script:

    .venv-pooltool/bin/python benchmarks/pooltool_bench.py

It never imports billiards_env (that venv does not have it) and billiards_env never imports pooltool:
``benchmarks.pooltool_runner`` starts this script and talks to it through JSON lines, so that the caller can
interleave rounds of pooltool timing with rounds of its own timing of the same shots (a shared, loaded machine
then slows both alike).

Protocol (one JSON document per line):

- in: the spec: table size and, per kind of shot, its shots: the balls' centres (metres, in billiards_env's
  frame: x along the table's length), the struck ball's row, the cue angle (rad, 0 = +x) and speed (m/s), and
  optionally the tip offsets ``side`` and ``top`` (fractions of R; pooltool's ``a = side`` in its mirrored frame,
  ``b = top``, and the cue speed that gives the ball ``speed``; without them the cue speed is ``speed`` and the tip
  pooltool's default, ``a = 0``, ``b = 0.25``).
  pooltool's table has its length along y, so a point ``(x, y)`` becomes ``(y, x)`` and an angle ``a``
  becomes ``90 - degrees(a)`` degrees.
- out: ``{"ready": true, "import_s", "first_shot_s", "first_call_s": {kind: s}, versions}`` after importing
  pooltool and running each kind's first shot once (the JIT / cache-load call, not counted later).
- in: ``{"kind": name, "repeats": r}``; out: ``{"times": [[s, ...] per shot], "events": [...], "pocketed": [...]}``.
- in: ``{"quit": true}`` (or end of input): exit.

Timing: ``time.perf_counter`` around ``pooltool.simulate(system, inplace=True)`` on a fresh system built for
each call outside the timed region.
"""
from __future__ import annotations

import json
import math
import os
import sys
import time


def main() -> int:
    spec = json.loads(sys.stdin.readline())
    # Run as a script, this file's folder heads sys.path: keep its modules from shadowing the real pooltool.
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != here]
    t0 = time.perf_counter()
    import numpy as np
    import pooltool as pt
    from pooltool.objects import PocketTableSpecs
    import_s = time.perf_counter() - t0

    table = pt.Table.from_table_specs(PocketTableSpecs(l=spec["table_length"], w=spec["table_width"]))

    def system(shot: dict) -> "pt.System":
        ids = shot["ids"]
        balls = {bid: pt.Ball.create(bid, xy=(y, x)) for bid, (x, y) in zip(ids, shot["pos"])}
        s = pt.System(cue=pt.Cue(cue_ball_id=ids[shot["ball"]]), table=table, balls=balls)
        s.strike(V0=shot["speed"], phi=(90.0 - math.degrees(shot["angle"])) % 360.0)
        if "side" in shot:
            # Spin shots: pooltool's frame is ours mirrored (x <-> y), so our right english is its left (a > 0),
            # and the cue speed is the one that gives the ball our speed (TP A-30: v = 2 V0 / (1 + m/M + 5/2 (a^2 +
            # b^2)), with pooltool's ball and cue masses).
            a, b = shot["side"], shot["top"]
            ball = next(iter(s.balls.values()))
            v0 = shot["speed"] * (1.0 + ball.params.m / s.cue.specs.M + 2.5 * (a * a + b * b)) / 2.0
            s.strike(V0=v0, a=a, b=b)
        return s

    def run(shot: dict) -> tuple[float, int, int]:
        s = system(shot)
        t = time.perf_counter()
        pt.simulate(s, inplace=True)
        el = time.perf_counter() - t
        pocketed = sum(1 for b in s.balls.values() if b.state.s == pt.constants.pocketed)
        return el, len(s.events), pocketed

    kinds = {k["name"]: k["shots"] for k in spec["kinds"]}
    first_name = spec["kinds"][0]["name"]
    first_shot_s, _, _ = run(kinds[first_name][0])
    first_call = {name: run(shots[0])[0] for name, shots in kinds.items()}
    ready = {"ready": True, "import_s": import_s, "first_shot_s": first_shot_s, "first_shot_kind": first_name,
             "first_call_s": first_call, "version": pt.__version__, "numpy": np.__version__}
    try:
        import numba
        ready["numba"] = numba.__version__
        ready["numba_cache_dir"] = numba.config.CACHE_DIR or "(package __pycache__)"
    except Exception:  # pragma: no cover - numba is a pooltool dependency
        pass
    print(json.dumps(ready), flush=True)

    for line in sys.stdin:
        req = json.loads(line)
        if req.get("quit"):
            break
        times, events, pocketed = [], [], []
        for shot in kinds[req["kind"]]:
            ts = []
            for _ in range(int(req.get("repeats", 1))):
                el, n_ev, n_pk = run(shot)
                ts.append(el)
            times.append(ts)
            events.append(n_ev)
            pocketed.append(n_pk)
        print(json.dumps({"times": times, "events": events, "pocketed": pocketed}), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
