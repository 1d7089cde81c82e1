"""Where a cold first call's compile time goes: ``python benchmarks/compile_profile.py [--env ID] [--warmup]
[--signatures] [--top N]``.

Runs the first shot (``Simulator(Table(), Physics()).run``; with ``--env ID`` also ``gymnasium.make(ID)``, a
reset and a step; with ``--warmup`` every task of ``python -m billiards_env.warmup``, one after the other) in this
process with numba's cache pointed at an empty temporary directory (unless ``NUMBA_CACHE_DIR`` is set) and the
prebuilt kernels off (``BILLIARDS_PREBUILT=0`` unless set), listening to numba's compile events. Prints how many compilations ran, of how many distinct functions (ours and numba's own
overloads of numpy functions), which functions were compiled more than once (``--signatures``: for which
signatures), the most expensive compilations (CPU seconds, including the functions each one compiled in turn) and
the functions whose own compile (without the functions it compiled in turn) costs most.

Run it as a script from the repository root (not with ``-m``: the clock and the listener start before the package
is imported), with ``PYTHONPATH=.`` to profile this checkout rather than the installed one.
"""
from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from collections import defaultdict


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python benchmarks/compile_profile.py", description=__doc__.splitlines()[0])
    ap.add_argument("--env", help="also make, reset and step this env id")
    ap.add_argument("--no-shot", action="store_true", help="skip the Simulator shot: profile the env's first step alone")
    ap.add_argument("--warmup", action="store_true",
                    help="also run every warm-up task (billiards_env.warmup's PHASES) in this process")
    ap.add_argument("--signatures", action="store_true",
                    help="list the signatures of each function compiled more than once")
    ap.add_argument("--top", type=int, default=25, help="how many compilations to list (default 25)")
    args = ap.parse_args(argv)
    tmp = None
    if "NUMBA_CACHE_DIR" not in os.environ:
        tmp = tempfile.TemporaryDirectory(prefix="numba-cold-")
        os.environ["NUMBA_CACHE_DIR"] = tmp.name
    os.environ.setdefault("BILLIARDS_PREBUILT", "0")  # compiled here, not unpacked from the prebuilt kernels
    t0, c0 = time.perf_counter(), time.process_time()
    from numba.core import event

    stack: list[list] = []  # [name, CPU clock at the start, CPU seconds of the compilations it ran in turn]
    rows: list[tuple[str, str, float, int, float]] = []  # name, signature, inclusive CPU s, depth, exclusive CPU s

    class Listener(event.Listener):
        def on_start(self, ev: event.Event) -> None:
            d = ev.data["dispatcher"]
            stack.append([f"{d.py_func.__module__}.{d.py_func.__qualname__}", time.process_time(), 0.0])

        def on_end(self, ev: event.Event) -> None:
            name, c, inner = stack.pop()
            spent = time.process_time() - c
            if stack:
                stack[-1][2] += spent
            rows.append((name, str(ev.data.get("args")), spent, len(stack), spent - inner))

    event.register("numba:compile", Listener())
    from billiards_env.physics import Balls, Physics, Simulator, Table

    t1 = time.perf_counter()
    table = Table()
    balls = Balls.from_positions([(0.25 * table.length, 0.5 * table.width), (0.5 * table.length, 0.5 * table.width)])
    if not args.no_shot:
        Simulator(table, Physics()).run(balls.strike(0, 0.0, 2.0))
    t2 = time.perf_counter()
    if args.env:
        import gymnasium as gym

        import billiards_env  # noqa: F401

        env = gym.make(args.env)
        env.reset(seed=0)
        env.step(env.action_space.sample())
    if args.warmup:
        from billiards_env import warmup

        for phase in warmup.PHASES:
            for name in phase:
                warmup.TASKS[name]()
    t3 = time.perf_counter()
    cpu = time.process_time() - c0
    ours = [r for r in rows if r[0].startswith("billiards_env")]
    per_fn: dict[str, list[str]] = defaultdict(list)
    for name, sig, *_ in ours:
        per_fn[name].append(sig)
    then = " and ".join(part for part, on in (("env", args.env), ("warm-up tasks", args.warmup)) if on)
    print(f"import {t1 - t0:.2f} s, first shot {t2 - t1:.2f} s" + (f", {then} {t3 - t2:.2f} s" if then else "")
          + f"; CPU {cpu:.2f} s; cache {os.environ['NUMBA_CACHE_DIR']}")
    print(f"compilations: {len(rows)} ({len(ours)} of {len(per_fn)} billiards_env functions, "
          f"{len(rows) - len(ours)} of numba's own overloads)")
    multi = {k: v for k, v in per_fn.items() if len(v) > 1}
    for name, sigs in sorted(multi.items()):
        print(f"  {len(sigs)} compilations, {len(set(sigs))} signatures: {name}")
        if args.signatures:
            for sig in sorted(set(sigs)):
                print(f"      {sig}")
    top = sum(r[2] for r in rows if r[3] == 0)
    print(f"top-level compilations: {top:.2f} CPU s; the most expensive (inclusive CPU s, depth):")
    for name, sig, cpu_s, depth, _ in sorted(rows, key=lambda r: -r[2])[:args.top]:
        print(f"  {cpu_s:6.2f}  d{depth}  {name} {sig[:70]}")
    own: dict[str, float] = defaultdict(float)
    for name, _, _, _, excl in rows:
        own[name] += excl
    print("the most expensive functions by their own compile (exclusive CPU s, all signatures; the rest of an "
          "inclusive figure is the functions compiled in turn):")
    for name, excl in sorted(own.items(), key=lambda kv: -kv[1])[:args.top]:
        print(f"  {excl:6.2f}  {name}")
    if tmp is not None:
        tmp.cleanup()
    return 0


if __name__ == "__main__":
    sys.exit(main())
