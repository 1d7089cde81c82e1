"""The batch and vector-env benchmark: ``python -m benchmarks --only batch --write``
writes ``docs/bench/batch.md`` and ``batch.json``.

Every target of the issue, measured in one run on this machine, with pooltool 0.6.0 timed in the same run:

- one-ball episodes per second through the native vector env (256 tables, random actions, same-step autoreset),
  and that rate against pooltool's rate of random one-ball shots (:mod:`.pooltool_runner`);
- rack steps per second through the native vector env (256 tables);
- 1000 candidate one-ball shots from one table in one :func:`~billiards_env.physics.batch.run_shots` call;
- the search player's decision time, and its choices checked against one-by-one simulation on many tables;
- the single env (``gymnasium.make``, seeded reset + step, one ball): episodes per second;
- the first call in a fresh process (import + first shot), with numba's cache cold (compiling) and warm.

Throughputs are wall-clock rates over a few seconds (best of three windows); the batch figures are given for
one thread, two threads, and the default choice (``threads=None``: two threads when a core is idle).
"""
from __future__ import annotations

import math
import statistics
import tempfile
import time
from pathlib import Path
from typing import Any, Callable

import numpy as np

from .common import (fmt_rate, fmt_time, load_now, log, machine_info, machine_markdown, one_ball_shots, rerender,
                     write_json)

TARGETS = {
    "vector_one_ball": 200_000.0,  # episodes/s
    "vector_vs_pooltool": 1000.0,  # x pooltool's random one-ball shot rate
    "vector_rack": 30_000.0,  # steps/s
    "candidates_1000": 5e-3,  # s
    "search_decision": 1e-3,  # s
    "single_env": 30_000.0,  # episodes/s
    "first_call_cold": 5.0,  # s
    "first_call_warm": 0.3,  # s
}
THREADS = (None, 1, 2)
COMMAND = "python -m benchmarks --only batch"


def _sizes(quick: bool) -> dict[str, Any]:
    if quick:
        return {"seconds": 0.5, "windows": 2, "n_tables": 256, "reps": 5, "search_tables": 8, "check_tables": 6,
                "pt_shots": 6, "pt_rounds": 1, "cold": 0, "warm": 1}
    return {"seconds": 2.0, "windows": 3, "n_tables": 256, "reps": 15, "search_tables": 40, "check_tables": 200,
            "pt_shots": 30, "pt_rounds": 2, "cold": 1, "warm": 3}


#: Per CPU-second rates of the last :func:`_rate` call (this process's CPU time, all its threads): steadier than
#: wall-clock rates when other work shares the cores, and an estimate of the rate on idle cores for serial runs.
CPU_RATES: dict[str, float] = {}


def _rate(step: Callable[[int], int], seconds: float, windows: int, name: str = "") -> float:
    """Best wall-clock rate over ``windows`` windows of ``seconds`` (``step(k)`` returns how many units call ``k``
    did); the best per-CPU-second rate goes to ``CPU_RATES[name]``."""
    best = best_cpu = 0.0
    k = 0
    for _ in range(windows):
        done = calls = 0
        t0, c0 = time.perf_counter(), time.process_time()
        while calls == 0 or time.perf_counter() - t0 < seconds:  # one call at least, however busy the machine
            done += step(k)
            k += 1
            calls += 1
        best = max(best, done / (time.perf_counter() - t0))
        best_cpu = max(best_cpu, done / max(time.process_time() - c0, 1e-9))
    CPU_RATES[name] = best_cpu
    return best


def run_vector(env_id: str, n_tables: int, threads: int | None, seconds: float, windows: int,
               count: str) -> float:
    """Episodes (``count="episodes"``) or env steps per second of ``make_vec(env_id, n_tables)``, random actions."""
    import gymnasium as gym

    import billiards_env  # noqa: F401

    env = gym.make_vec(env_id, n_tables, autoreset_mode="same_step", threads=threads)
    env.reset(seed=0)
    rng = np.random.default_rng(0)
    actions = rng.uniform(-1.0, 1.0, (64,) + env.action_space.shape).astype(np.float32)
    for a in actions[:3]:
        env.step(a)

    def step(k: int) -> int:
        _, _, term, trunc, _ = env.step(actions[k % 64])
        return int((term | trunc).sum()) if count == "episodes" else n_tables

    rate = _rate(step, seconds, windows, f"{env_id}:{threads}")
    env.close()
    return rate


def run_candidates(reps: int) -> dict[str, Any]:
    """1000 random one-ball shots from one table in one ``run_shots`` call (median time)."""
    from billiards_env.physics import Balls, Physics, Simulator, Table
    from billiards_env.physics.batch import run_shots

    sim = Simulator(Table(), Physics())
    balls = Balls.from_positions([[0.62, 0.58], [1.9, 0.95]])
    rng = np.random.default_rng(3)
    angles, speeds = rng.uniform(-math.pi, math.pi, 1000), rng.uniform(0.5, 5.0, 1000)
    out: dict[str, Any] = {"n": 1000}
    for threads in THREADS:
        run_shots(sim, balls, angles, speeds, threads=threads)
        times = []
        for _ in range(reps):
            t0 = time.perf_counter()
            run_shots(sim, balls, angles, speeds, threads=threads)
            times.append(time.perf_counter() - t0)
        out[str(threads)] = statistics.median(times)
    sim.run(balls.strike(0, angles[0], speeds[0]), validate=False)  # load the compiled kernel first
    one = time.perf_counter()
    for k in range(200):
        sim.run(balls.strike(0, angles[k], speeds[k]), validate=False)
    out["one_by_one_per_shot_s"] = (time.perf_counter() - one) / 200
    return out


def _one_row_at_a_time(sim: Any, balls: Any, angles: Any, speeds: Any, **kw: Any) -> Any:
    """``run_shots`` called once per shot (batches of one row), the rows stacked: the reference the batched search
    must match (a row does not depend on the batch it runs in; each row equals its own ``Simulator.run``, which
    ``tests/players/test_search_batch.py`` checks)."""
    from billiards_env.physics.batch import BatchResult, run_shots

    def row(v: Any, k: int) -> Any:
        return v[k:k + 1] if isinstance(v, np.ndarray) and v.ndim else v

    rows = [run_shots(sim, balls, np.asarray(angles)[k:k + 1], np.asarray(speeds)[k:k + 1],
                      **{key: row(v, k) for key, v in kw.items()}) for k in range(len(angles))]
    return BatchResult(*[None if getattr(rows[0], f) is None else np.concatenate([getattr(r, f) for r in rows])
                         for f in BatchResult._fields])


def run_search(n_tables: int, n_check: int) -> dict[str, Any]:
    """Decision time of the search player (median over tables), and its choices against the one-by-one
    reference on ``n_check`` tables (first shot of three-ball and one-ball tables)."""
    import gymnasium as gym

    import billiards_env  # noqa: F401
    from billiards_env.players import search
    from billiards_env.players.context import shot_context

    out: dict[str, Any] = {}
    for env_id in ("BilliardsOneBall-v0", "BilliardsThreeBalls-v0"):
        env = gym.make(env_id)
        times = []
        for seed in range(n_tables + 1):
            env.reset(seed=seed)
            ctx = shot_context(env)
            t0 = time.perf_counter()
            search.search_shot(ctx, None, np.random.default_rng(seed))
            if seed:  # the first one loads the compiled code
                times.append(time.perf_counter() - t0)
        out[env_id] = {"median_s": statistics.median(times), "min_s": min(times), "n": len(times)}
    same = checked = 0
    batched = search.run_shots
    for k in range(n_check):
        env = gym.make("BilliardsThreeBalls-v0" if k % 2 else "BilliardsOneBall-v0")
        env.reset(seed=1000 + k)
        ctx = shot_context(env)
        a = search.search_shot(ctx, None, np.random.default_rng(k))
        search.run_shots = _one_row_at_a_time  # the search's batch simulation, one row per call
        try:
            b = search.search_shot(ctx, None, np.random.default_rng(k))
        finally:
            search.run_shots = batched
        checked += 1
        same += (a[0], a[1], a[2].value, a[2].robust, a[2].position) == (b[0], b[1], b[2].value, b[2].robust,
                                                                         b[2].position)
    out["same_choices"] = same
    out["checked"] = checked
    return out


def run_single_env(seconds: float, windows: int) -> float:
    """``gymnasium.make("BilliardsOneBall-v0")``: seeded reset + one step, episodes per second."""
    import gymnasium as gym

    import billiards_env  # noqa: F401

    env = gym.make("BilliardsOneBall-v0")
    actions = np.random.default_rng(0).uniform(-1.0, 1.0, (1024, 2)).astype(np.float32)
    for k in range(50):
        env.reset(seed=k)
        env.step(actions[k])

    def episode(k: int) -> int:
        env.reset(seed=k)
        env.step(actions[k % 1024])
        return 1

    return _rate(episode, seconds, windows, "single_env")


def run_pooltool(n_shots: int, rounds: int, python: str | None, allow_setup: bool) -> dict[str, Any]:
    """pooltool's time per random one-ball shot (the speed section's shots), median over shots and rounds."""
    from billiards_env.physics import Table

    from .pooltool_runner import PooltoolSession, PooltoolUnavailable

    table = Table()
    shots = one_ball_shots(n_shots, seed=11, table=table)
    try:
        session = PooltoolSession([("random", shots)], table.length, table.width, python=python,
                                  allow_setup=allow_setup)
    except PooltoolUnavailable as exc:
        return {"available": False, "note": str(exc)}
    per_shot: list[list[float]] = [[] for _ in shots]
    try:
        with session:
            for _ in range(rounds):
                ans = session.time("random", 1)
                for k, ts in enumerate(ans["times"]):
                    per_shot[k].extend(ts)
    except PooltoolUnavailable as exc:
        return {"available": False, "note": str(exc)}
    med = statistics.median(statistics.median(ts) for ts in per_shot)
    return {"available": True, "version": session.ready.get("version"), "random_shot_s": med,
            "shots_per_s": 1.0 / med, "n_shots": len(shots), "rounds": rounds}


def run_first_call(cold: int, warm: int) -> dict[str, Any]:
    """Import + first shot in fresh processes (``benchmarks/first_call.py``): numba's cache warm, and cold."""
    from .speed import median_rows, probe_first_call

    out: dict[str, Any] = {}
    probe_first_call({})  # the default cache holds the current kernels
    if warm:
        out["warm"] = median_rows([probe_first_call({}) for _ in range(warm)])
    rows = []
    for _ in range(cold):
        with tempfile.TemporaryDirectory(prefix="numba-cold-") as d:
            rows.append(probe_first_call({"NUMBA_CACHE_DIR": d, "BILLIARDS_PREBUILT": "0"}))
    if rows:
        out["cold"] = median_rows(rows)
    return out


def run(quick: bool = False, pooltool_python: str | None = None, allow_setup: bool = False) -> dict[str, Any]:
    n = _sizes(quick)
    doc: dict[str, Any] = {"machine": machine_info(), "quick": quick, "command": COMMAND + (" --quick" if quick else ""),
                           "time": time.strftime("%Y-%m-%d %H:%M:%S")}
    log("[batch] pooltool's random one-ball shots")
    doc["pooltool"] = run_pooltool(n["pt_shots"], n["pt_rounds"], pooltool_python, allow_setup)
    for env_id, key, count in (("BilliardsOneBall-v0", "vector_one_ball", "episodes"),
                               ("BilliardsRack-v0", "vector_rack", "steps")):
        doc[key] = {}
        for threads in THREADS:
            r = run_vector(env_id, n["n_tables"], threads, n["seconds"], n["windows"], count)
            doc[key][str(threads)] = r
            log(f"[batch] {env_id} x{n['n_tables']} threads={threads}: {fmt_rate(r)} {count}/s")
    doc["candidates_1000"] = run_candidates(n["reps"])
    log(f"[batch] 1000 candidate shots: {fmt_time(doc['candidates_1000']['None'])}")
    doc["search"] = run_search(n["search_tables"], n["check_tables"])
    log(f"[batch] search decision (three balls): {fmt_time(doc['search']['BilliardsThreeBalls-v0']['median_s'])}; "
        f"same choices {doc['search']['same_choices']}/{doc['search']['checked']}")
    doc["single_env"] = run_single_env(n["seconds"], n["windows"])
    log(f"[batch] single env: {fmt_rate(doc['single_env'])} episodes/s")
    doc["first_call"] = run_first_call(n["cold"], n["warm"])
    doc["per_cpu_s"] = dict(CPU_RATES)
    doc["end_load"] = load_now()
    return doc


def targets(doc: dict[str, Any]) -> list[dict[str, Any]]:
    """One row per target: the measured figure (the default thread choice), the target, pass or miss."""
    rows: list[dict[str, Any]] = []

    def add(name: str, value: str, ok: bool | None, target: str) -> None:
        rows.append({"name": name, "value": value, "ok": ok, "target": target})

    one = doc["vector_one_ball"]["None"]
    add("one-ball episodes/s, native vector env (256 tables)", fmt_rate(one), one >= TARGETS["vector_one_ball"],
        ">= 200,000")
    pt = doc.get("pooltool", {})
    if pt.get("available"):
        ratio = one / pt["shots_per_s"]
        add("... against pooltool's random one-ball shots/s", f"{ratio:,.0f}x ({fmt_rate(pt['shots_per_s'])}/s)",
            ratio >= TARGETS["vector_vs_pooltool"], ">= 1000x")
    else:
        add("... against pooltool", "pooltool unavailable: " + str(pt.get("note", "")), None, ">= 1000x")
    rack = doc["vector_rack"]["None"]
    add("rack steps/s, native vector env (256 tables)", fmt_rate(rack), rack >= TARGETS["vector_rack"], ">= 30,000")
    c = doc["candidates_1000"]["None"]
    add("1000 candidate one-ball shots from one table", fmt_time(c), c <= TARGETS["candidates_1000"], "<= 5 ms")
    s = doc["search"]["BilliardsThreeBalls-v0"]["median_s"]
    same = f"; same choices as one-by-one on {doc['search']['same_choices']}/{doc['search']['checked']} tables"
    add("search player decision (three balls, median)", fmt_time(s) + same,
        s <= TARGETS["search_decision"] and doc["search"]["same_choices"] == doc["search"]["checked"], "<= 1 ms")
    e = doc["single_env"]
    add("single env episodes/s (gym.make, seeded reset + step, one ball)", fmt_rate(e), e >= TARGETS["single_env"],
        ">= 30,000")
    fc = doc.get("first_call", {})
    if "cold" in fc:
        add("first call, cold numba cache (import + first shot)", fmt_time(fc["cold"]["total_s"]),
            fc["cold"]["total_s"] <= TARGETS["first_call_cold"], "<= 5 s")
    if "warm" in fc:
        add("first call, warm numba cache (import + first shot)", fmt_time(fc["warm"]["total_s"]),
            fc["warm"]["total_s"] <= TARGETS["first_call_warm"], "<= 0.3 s")
    return rows


def render_markdown(doc: dict[str, Any]) -> str:
    L = ["# Batch simulation and the native vector env", "",
         f"Measured by `{doc['command']}` on {doc['time']} (all figures from this one run).", "",
         machine_markdown(doc["machine"], doc.get("end_load")), "", "## Targets", "",
         "| | measured | target | |", "|---|---|---|---|"]
    for r in targets(doc):
        verdict = "pass" if r["ok"] else ("**miss**" if r["ok"] is False else "n/a")
        L.append(f"| {r['name']} | {r['value']} | {r['target']} | {verdict} |")
    L += ["", "## By thread count", "",
          "`threads=None` (the default) runs on two threads when the machine leaves a core idle, else on one; the "
          "results are the same whatever the thread count (tests/physics/test_batch.py, tests/envs/test_vector_env.py).",
          "", "| | threads=None | 1 | 2 |", "|---|---|---|---|"]
    for key, name, fmt in (("vector_one_ball", "one-ball episodes/s (256 tables)", fmt_rate),
                           ("vector_rack", "rack steps/s (256 tables)", fmt_rate),
                           ("candidates_1000", "1000 candidate shots", fmt_time)):
        d = doc[key]
        L.append(f"| {name} | {fmt(d['None'])} | {fmt(d['1'])} | {fmt(d['2'])} |")
    cpu = doc.get("per_cpu_s") or {}
    if cpu:
        L += ["", "Per CPU-second of the benchmark process (all its threads), steadier than the wall-clock rates when "
              "other work shares the cores: " + "; ".join(f"{k.replace(':', ' threads=')} {fmt_rate(v)}/CPU-s"
                                                         for k, v in cpu.items()) + "."]
    c = doc["candidates_1000"]
    L += ["", f"One by one, `Simulator.run(validate=False)` takes {fmt_time(c['one_by_one_per_shot_s'])} per "
          f"candidate shot ({fmt_time(1000 * c['one_by_one_per_shot_s'])} for 1000).", ""]
    s = doc["search"]
    L += ["## Search player", "",
          "| table | decision (median) | fastest | decisions |", "|---|---|---|---|"]
    for env_id in ("BilliardsOneBall-v0", "BilliardsThreeBalls-v0"):
        r = s[env_id]
        L.append(f"| {env_id} | {fmt_time(r['median_s'])} | {fmt_time(r['min_s'])} | {r['n']} |")
    L += ["", f"Choices identical to simulating each candidate with `Simulator.run`: {s['same_choices']} of "
          f"{s['checked']} tables.", ""]
    fc = doc.get("first_call", {})
    if fc:
        L += ["## First call", "", "`benchmarks/first_call.py` in a fresh process (import of the physics package, "
              "numpy and numba included, then a table, two balls and the first shot); cold: `NUMBA_CACHE_DIR` "
              "pointed at an empty directory, every kernel compiled (runs since 2026-12-07 set `BILLIARDS_PREBUILT=0`).", "", "| cache | import | first shot | total |", "|---|---|---|---|"]
        for k in ("warm", "cold"):
            if k in fc:
                r = fc[k]
                L.append(f"| {k} | {fmt_time(r['import_s'])} | {fmt_time(r['first_s'])} | {fmt_time(r['total_s'])} |")
        L.append("")
    pt = doc.get("pooltool", {})
    if pt.get("available"):
        L += [f"pooltool {pt.get('version')}: {fmt_time(pt['random_shot_s'])} per random one-ball shot (median of "
              f"{pt['n_shots']} shots x {pt['rounds']} rounds).", ""]
    return "\n".join(L)


def render(out: Path) -> None:
    """Re-write ``batch.md`` from ``batch.json``, without measuring."""
    rerender(out, "batch", render_markdown)


def main(out: Path | None, quick: bool = False, pooltool_python: str | None = None, allow_setup: bool = False) -> dict:
    """Measure everything and print the targets; write ``batch.json`` and ``batch.md`` into ``out`` if given."""
    doc = run(quick, pooltool_python, allow_setup)
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
        write_json(out / "batch.json", doc)
        (out / "batch.md").write_text(render_markdown(doc))
    for r in targets(doc):
        log(f"[batch] {r['name']}: {r['value']} (target {r['target']}: "
            f"{'pass' if r['ok'] else 'MISS' if r['ok'] is False else 'n/a'})")
    if out is not None:
        log(f"[batch] wrote {out / 'batch.md'}")
    return doc


__all__ = ["run", "targets", "render_markdown", "render", "main", "TARGETS"]
