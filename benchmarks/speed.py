"""Speed: time per shot of the ``exact`` solver, ``env.step`` throughput, first-call latency, pooltool.

Sections (each can run alone; ``speed.json`` keeps the sections of earlier runs that this run did not redo,
each with its own time stamp, and ``speed.md`` is rendered from it):

- ``speed`` (``ours`` in ``speed.json``): a fixed single-ball shot, seeded random single-ball shots and a
  15-ball break with the ``exact`` solver (rolling friction, mu 0.01), timed through ``Simulator.run(balls)``
  (the default, which validates the balls) and ``run(balls, validate=False)``, plus where the time of one shot
  goes (validation, the numba kernel, the Python around it).
- ``env`` (``env_steps`` in ``speed.json``): ``env.step`` per second for each registered env id, made with
  ``gymnasium.make(id)`` (and the unwrapped env for reference), random actions, resets outside the timed calls
  (:func:`time_env`, the one env-timing function of the repository).
- ``latency``: a fresh process doing import + first shot, with the numba cache warm and cold.
- ``pooltool``: the same kinds of shot in pooltool 0.6.0 (its own venv, a subprocess), and our times for the
  very same shots measured in the same run, as ratios.
"""
from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

from billiards_env.physics import Physics, Simulator, Table, validate_balls
from billiards_env.registration import ENV_IDS

from .common import (Shot, break_shots, fmt_num, fmt_rate, fmt_time, load_now, log, machine_info, machine_markdown,
                     one_ball_shots, repeat_median, straight_shot, time_call, write_json)

FIRST_CALL = Path(__file__).with_name("first_call.py")

#: Targets: (key, description).
TARGET_SINGLE_X = 100.0
TARGET_BREAK_X = 50.0
TARGET_ENV_STEPS = 20_000.0
TARGET_COLD_S = 5.0
TARGET_WARM_S = 0.5


def _sizes(quick: bool) -> dict[str, int]:
    if quick:
        return {"fixed_reps": 200, "random_n": 30, "break_reps": 10, "pt_random_n": 8, "pt_fixed_reps": 5,
                "pt_break_reps": 2, "pt_rounds": 2, "latency_warm": 1, "latency_cold": 1}
    return {"fixed_reps": 1000, "random_n": 100, "break_reps": 40, "pt_random_n": 30, "pt_fixed_reps": 10,
            "pt_break_reps": 3, "pt_rounds": 4, "latency_warm": 3, "latency_cold": 2}


# ------------------------------------------------------------------------------------------------- our shots

def _kernel_call(sim: Simulator, balls) -> Any:
    """A callable running only the numba kernel on fresh copies of the arrays (what ``run`` wraps)."""
    from billiards_env.physics.kernel_io import kernel_params
    from billiards_env.physics.kernels import kernels_for

    prm = kernel_params(sim.table, sim.physics, sim.max_time)
    pxy = np.ascontiguousarray(sim.table.pocket_xy, dtype=float)
    pr = np.ascontiguousarray(sim.table.pocket_radius, dtype=float)
    pos, vel = np.ascontiguousarray(balls.pos, float), np.ascontiguousarray(balls.vel, float)
    rad, mass = np.ascontiguousarray(balls.radius, float), np.ascontiguousarray(balls.mass, float)
    on = np.ascontiguousarray(balls.on_table, np.bool_)
    ang = np.ascontiguousarray(balls.ang, float)
    exact = kernels_for(sim.physics).exact

    def call():
        return exact(pos.copy(), vel.copy(), ang.copy(), rad, mass, on.copy(), pxy, pr, prm, sim.max_events, False)
    return call


def breakdown(sim: Simulator, balls, reps: int) -> dict[str, Any]:
    """Where one shot's time goes: ``run()``, ``run(validate=False)``, ``validate_balls`` alone, the kernel alone."""
    out: dict[str, Any] = {
        "run_s": repeat_median(lambda: sim.run(balls), reps, warmup=3),
        "run_novalidate_s": repeat_median(lambda: sim.run(balls, validate=False), reps, warmup=3),
        "validate_s": repeat_median(lambda: validate_balls(balls, sim.table), reps, warmup=3),
    }
    if hasattr(sim, "run_in_place"):  # the engine's no-copy, no-validation hot path (used by the envs)
        copies = iter([balls.copy() for _ in range(reps + 3)])
        try:
            out["run_in_place_s"] = repeat_median(lambda: sim.run_in_place(next(copies)), reps, warmup=3)
        except Exception as exc:
            out["run_in_place_note"] = f"run_in_place not timed: {type(exc).__name__}: {exc}"
    try:
        out["kernel_s"] = repeat_median(_kernel_call(sim, balls), reps, warmup=3)
        out["wrapper_s"] = out["run_novalidate_s"] - out["kernel_s"]
    except Exception as exc:  # the engine's internals changed: report without the split
        out["kernel_s"] = None
        out["kernel_note"] = f"kernel not timed alone: {type(exc).__name__}: {exc}"
    return out


def _random_times(sim: Simulator, shots: list[Shot], validate: bool) -> list[float]:
    times = []
    for s in shots:
        b = s.struck()
        el, _ = time_call(lambda: sim.run(b, validate=validate), min_total=0.002, max_reps=20)
        times.append(el)
    return times


def run_ours(quick: bool, table: Table | None = None) -> dict[str, Any]:
    table = table or Table()
    n = _sizes(quick)
    sim = Simulator(table, Physics())
    fixed = straight_shot(table).struck()
    brk = break_shots(1, table)[0].struck()
    t0 = time.perf_counter()
    sim.run(fixed)  # compile / load the kernel
    first_in_process = time.perf_counter() - t0
    out: dict[str, Any] = {"time": time.strftime("%Y-%m-%d %H:%M:%S"), "physics": "rolling, mu_roll 0.01",
                           "first_call_in_process_s": first_in_process}
    res = sim.run(fixed)
    out["fixed"] = {"what": "cue ball at the head spot, object ball at the centre, struck straight at it, 2 m/s",
                    "n_events": res.n_events, "sim_time_s": res.time, "reps": n["fixed_reps"],
                    **breakdown(sim, fixed, n["fixed_reps"])}
    log(f"[speed] fixed single-ball shot: run {fmt_time(out['fixed']['run_s'])}, "
        f"validate=False {fmt_time(out['fixed']['run_novalidate_s'])}, kernel {fmt_time(out['fixed']['kernel_s'])}")
    shots = one_ball_shots(n["random_n"], seed=11, table=table)
    t_run = _random_times(sim, shots, True)
    t_nv = _random_times(sim, shots, False)
    out["random"] = {"what": "seeded random single-ball shots (cue + 1 object ball, random cut, 0.5-3 m/s)",
                     "n_shots": len(shots), "median_s": statistics.median(t_run),
                     "median_novalidate_s": statistics.median(t_nv), "shots_per_s": len(t_run) / sum(t_run),
                     "shots_per_s_novalidate": len(t_nv) / sum(t_nv), "per_shot_s": t_run,
                     "median_events": statistics.median(sim.run(s.struck()).n_events for s in shots)}
    log(f"[speed] random single-ball shots: median {fmt_time(out['random']['median_s'])}")
    res = sim.run(brk)
    out["break"] = {"what": "15-ball break: touching rack, cue ball at the head spot aimed at the apex, 8 m/s",
                    "n_events": res.n_events, "sim_time_s": res.time, "reps": n["break_reps"],
                    "pocketed": int((res.pocket >= 0).sum()), **breakdown(sim, brk, n["break_reps"])}
    log(f"[speed] 15-ball break: run {fmt_time(out['break']['run_s'])}")
    return out


# ------------------------------------------------------------------------------------------------ env.step

#: The fields of a :func:`time_env` measurement that ``speed.json`` keeps per id and wrapping.
ENV_REPORT_KEYS = ("steps", "resets", "steps_per_s", "steps_per_s_with_resets", "mean_episode_steps")


def time_env(env_id: str, seconds: float, wrapped: bool = True, fast: bool = True, seed: int = 0,
             **kwargs: Any) -> dict[str, Any]:
    """``env.step`` throughput of ``env_id``: seeded random actions, ``reset`` at every episode end (timed apart).

    ``wrapped``: the env as ``gymnasium.make(env_id, **kwargs)`` returns it (passive checker and order enforcing
    wrappers), else its ``.unwrapped``. ``fast=False``: shots through ``Simulator.run(validate=False)`` instead
    of the env's in-place kernel call (what that fast path saves). Returns ``steps``, ``resets``,
    ``steps_per_s`` (time inside ``step`` only), ``steps_per_s_with_resets``, ``steps_per_cpu_s`` (per CPU second
    of this process: steadier on a busy machine), ``step_us``, ``reset_us``, ``events_per_shot`` and
    ``mean_episode_steps``."""
    import gymnasium as gym

    import billiards_env  # noqa: F401  (registers the ids)

    env = gym.make(env_id, **kwargs)
    if not fast:
        if not hasattr(env.unwrapped, "fast_step"):
            raise RuntimeError(f"{env_id} has no in-place fast path to switch off (no `fast_step` property)")
        env.unwrapped.fast_step = False
    if not wrapped:
        env = env.unwrapped
    env.action_space.seed(seed)
    actions = [env.action_space.sample() for _ in range(4096)]
    env.reset(seed=seed)
    for k in range(20):  # warm-up
        _, _, term, trunc, _ = env.step(actions[k])
        if term or trunc:
            env.reset()
    steps = resets = events = 0
    t_step = t_reset = 0.0
    start = time.perf_counter()
    cpu0 = time.process_time()
    while steps == 0 or time.perf_counter() - start < seconds:  # one round at least, however busy the machine
        for _ in range(100):
            a = actions[steps % len(actions)]
            t0 = time.perf_counter()
            _, _, term, trunc, info = env.step(a)
            t_step += time.perf_counter() - t0
            steps += 1
            events += int(info["n_events"])
            if term or trunc:
                t0 = time.perf_counter()
                env.reset()
                t_reset += time.perf_counter() - t0
                resets += 1
    cpu = time.process_time() - cpu0
    env.close()
    return {"steps": steps, "resets": resets, "steps_per_s": steps / t_step,
            "steps_per_s_with_resets": steps / (t_step + t_reset),
            "mean_episode_steps": steps / resets if resets else None,
            "steps_per_cpu_s": steps / cpu if cpu > 0 else None, "step_us": 1e6 * t_step / steps,
            "reset_us": 1e6 * t_reset / resets if resets else None, "events_per_shot": events / steps}


def run_env_steps(quick: bool, ids: tuple[str, ...] = ENV_IDS, seconds: float | None = None,
                  compare: bool = False) -> dict[str, Any]:
    """The ``env`` section: :func:`time_env` of every id through ``gymnasium.make`` and unwrapped (and with
    ``compare`` unwrapped through ``Simulator.run``); prints a table of every measurement."""
    seconds = seconds if seconds is not None else (1.0 if quick else 3.0)
    try:
        import gymnasium as gym

        import billiards_env  # noqa: F401  (registers the ids)
    except Exception as exc:  # pragma: no cover - gymnasium is a dependency
        return {"available": False, "note": f"cannot import gymnasium / billiards_env: {exc}"}
    out: dict[str, Any] = {"time": time.strftime("%Y-%m-%d %H:%M:%S"), "seconds_per_env": seconds, "envs": {}}
    missing = [i for i in ids if i not in gym.registry]
    if missing:
        out["note"] = f"not registered yet: {', '.join(missing)} (skipped)"
    table: list[tuple[str, str, str, dict[str, Any]]] = []
    for env_id in ids:
        if env_id in missing:
            continue
        row: dict[str, Any] = {}
        try:
            for label, wrapped in (("make", True), ("unwrapped", False)):
                m = time_env(env_id, seconds if wrapped else seconds / 2, wrapped=wrapped)
                row[label] = {k: m[k] for k in ENV_REPORT_KEYS}
                table.append((env_id, label, "kernel", m))
            if compare:
                table.append((env_id, "unwrapped", "Simulator.run",
                              time_env(env_id, seconds / 2, wrapped=False, fast=False)))
        except Exception as exc:
            row["error"] = f"{type(exc).__name__}: {exc}"
        out["envs"][env_id] = row
        if "make" in row:
            log(f"[speed] {env_id}: {row['make']['steps_per_s']:.0f} steps/s (gym.make), "
                f"{row.get('unwrapped', {}).get('steps_per_s', float('nan')):.0f} unwrapped")
        else:
            log(f"[speed] {env_id}: {row.get('error')}")
    out["available"] = bool(out["envs"])
    print(format_env_table(table), flush=True)
    return out


def format_env_table(rows: list[tuple[str, str, str, dict[str, Any]]]) -> str:
    """One line per :func:`time_env` measurement ``(id, wrapping, shot path, result)``."""
    lines = [f"{'id':<24} {'env':<10} {'path':<14} {'steps/s':>9} {'with resets':>12} {'per CPU-s':>10} "
             f"{'step us':>8} {'reset us':>9} {'events/shot':>12}"]
    for env_id, label, path, m in rows:
        lines.append(f"{env_id:<24} {label:<10} {path:<14} {m['steps_per_s']:>9,.0f} "
                     f"{m['steps_per_s_with_resets']:>12,.0f} {fmt_rate(m['steps_per_cpu_s']):>10} "
                     f"{m['step_us']:>8.1f} {fmt_num(m['reset_us']):>9} {m['events_per_shot']:>12.1f}")
    return "\n".join(lines)


# ------------------------------------------------------------------------------------------------- latency

def probe_first_call(env_vars: dict[str, str], extra: list[str] | None = None) -> dict[str, Any]:
    """One first-call probe in a fresh process (``FIRST_CALL`` with ``extra`` arguments, the environment updated
    with ``env_vars``): its timings and the process's wall time (batch.py measures its own first call with it)."""
    env = dict(os.environ)
    env.update(env_vars)
    t0 = time.perf_counter()
    r = subprocess.run([sys.executable, str(FIRST_CALL), *(extra or [])], capture_output=True, text=True,
                       env=env, timeout=900)
    wall = time.perf_counter() - t0
    if r.returncode != 0:
        raise RuntimeError(" ".join(r.stderr.strip().splitlines()[-3:]))
    out = json.loads(r.stdout.strip().splitlines()[-1])
    out["process_wall_s"] = wall
    return out


def median_rows(rows: list[dict[str, Any]]) -> dict[str, Any]:
    """The median of each timing over probe rows, with the rows."""
    keys = ("import_s", "first_s", "total_s", "process_wall_s")
    return {**{k: statistics.median(r[k] for r in rows) for k in keys}, "runs": rows}


def run_latency(quick: bool, env_id: str = "BilliardsOneBall-v0") -> dict[str, Any]:
    n = _sizes(quick)
    out: dict[str, Any] = {"time": time.strftime("%Y-%m-%d %H:%M:%S")}
    base_env = {k: v for k, v in os.environ.items() if k == "NUMBA_CACHE_DIR"}
    probe_first_call(base_env)  # make sure the default cache holds the current kernels
    out["warm"] = median_rows([probe_first_call(base_env) for _ in range(n["latency_warm"])])
    log(f"[latency] warm: import + first shot {fmt_time(out['warm']['total_s'])}")
    cold = []
    for _ in range(n["latency_cold"]):
        with tempfile.TemporaryDirectory(prefix="numba-cold-") as d:
            cold.append(probe_first_call({"NUMBA_CACHE_DIR": d, "BILLIARDS_PREBUILT": "0"}))
    out["cold"] = median_rows(cold)
    log(f"[latency] cold: import + first shot {fmt_time(out['cold']['total_s'])}")
    try:
        import gymnasium as gym

        import billiards_env  # noqa: F401
        registered = env_id in gym.registry
    except Exception:  # pragma: no cover
        registered = False
    if registered:
        try:
            probe_first_call(base_env, ["--env", env_id])
            out["env_warm"] = median_rows([probe_first_call(base_env, ["--env", env_id])
                                            for _ in range(n["latency_warm"])])
            out["env_warm"]["env_id"] = env_id
            log(f"[latency] warm {env_id}: import + make + reset + step {fmt_time(out['env_warm']['total_s'])}")
        except Exception as exc:
            out["env_note"] = f"{env_id} first step failed: {exc}"
    else:
        out["env_note"] = f"{env_id} not registered: env first-step latency skipped"
    return out


# ------------------------------------------------------------------------------------------------ pooltool

def run_pooltool_section(quick: bool, python: str | None = None, allow_setup: bool = False,
                         table: Table | None = None) -> dict[str, Any]:
    """pooltool and our solver on the same shots, in interleaved rounds of the same run."""
    from .pooltool_runner import PooltoolSession, PooltoolUnavailable

    table = table or Table()
    n = _sizes(quick)
    fixed = straight_shot(table)
    random_shots = one_ball_shots(n["random_n"], seed=11, table=table)[: n["pt_random_n"]]
    brk = break_shots(1, table)[0]
    kinds = [("straight", [fixed]), ("random", random_shots), ("break", [brk])]
    reps = {"straight": n["pt_fixed_reps"], "random": 1, "break": n["pt_break_reps"]}
    rounds = n["pt_rounds"]
    out: dict[str, Any] = {"time": time.strftime("%Y-%m-%d %H:%M:%S"), "rounds": rounds, "repeats": reps}
    log(f"[pooltool] starting pooltool ({1 + len(random_shots) + 1} shots, {rounds} interleaved rounds)")
    t0 = time.perf_counter()
    try:
        session = PooltoolSession(kinds, table.length, table.width, python=python, allow_setup=allow_setup)
    except PooltoolUnavailable as exc:
        out["pooltool"] = {"available": False, "note": str(exc)}
        log(f"[pooltool] skipped: {exc}")
        return out
    sim = Simulator(table, Physics())
    struck = {name: [s.struck() for s in shots] for name, shots in kinds}
    sim.run(struck["straight"][0])
    # samples[kind][engine] = per shot, the list of times over all rounds and repeats
    samples: dict[str, dict[str, list[list[float]]]] = {
        name: {e: [[] for _ in shots] for e in ("pooltool", "ours", "ours_novalidate")} for name, shots in kinds}
    round_ratios: dict[str, list[float]] = {name: [] for name, _ in kinds}
    pt_events: dict[str, list[int]] = {}
    try:
        with session:
            for _ in range(rounds):
                for name, _shots in kinds:
                    for validate, key in ((True, "ours"), (False, "ours_novalidate")):
                        for k, b in enumerate(struck[name]):
                            for _r in range(reps[name]):
                                t = time.perf_counter()
                                sim.run(b, validate=validate)
                                samples[name][key][k].append(time.perf_counter() - t)
                    ans = session.time(name, reps[name])
                    for k, ts in enumerate(ans["times"]):
                        samples[name]["pooltool"][k].extend(ts)
                    pt_events[name] = ans["events"]
                    this_round = {e: statistics.median(statistics.median(ts[-reps[name]:]) for ts in samples[name][e])
                                  for e in ("pooltool", "ours")}
                    round_ratios[name].append(this_round["pooltool"] / this_round["ours"])
    except PooltoolUnavailable as exc:
        out["pooltool"] = {"available": False, "note": str(exc)}
        log(f"[pooltool] failed: {exc}")
        return out
    pt_info = dict(session.ready)
    pt_info.update({"available": True, "wall_s": time.perf_counter() - t0})
    out["pooltool"] = pt_info
    ratios = {}
    for name, shots in kinds:
        med = {e: statistics.median(statistics.median(ts) for ts in samples[name][e]) for e in samples[name]}
        ours_events = [sim.run(b).n_events for b in struck[name]]
        ratios[name] = {
            "n_shots": len(shots), "samples_per_shot": len(samples[name]["pooltool"][0]),
            "pooltool_s": med["pooltool"], "ours_s": med["ours"], "ours_novalidate_s": med["ours_novalidate"],
            "speedup": med["pooltool"] / med["ours"], "speedup_novalidate": med["pooltool"] / med["ours_novalidate"],
            "speedup_per_round": round_ratios[name],
            "pooltool_min_s": min(min(ts) for ts in samples[name]["pooltool"]),
            "ours_min_s": min(min(ts) for ts in samples[name]["ours"]),
            "pooltool_events": statistics.median(pt_events[name]), "ours_events": statistics.median(ours_events),
        }
        r = ratios[name]
        log(f"[pooltool] {name}: pooltool {fmt_time(r['pooltool_s'])}, ours {fmt_time(r['ours_s'])} -> "
            f"{r['speedup']:.0f}x ({r['speedup_novalidate']:.0f}x without validation; per round "
            f"{', '.join(f'{x:.0f}' for x in round_ratios[name])})")
    out["ratios"] = ratios
    return out


# ------------------------------------------------------------------------------------------------- targets

def targets(doc: dict[str, Any], accuracy: dict[str, Any] | None) -> list[dict[str, Any]]:
    rows: list[dict[str, Any]] = []

    def add(name: str, value: str, ok: bool | None, note: str = "") -> None:
        rows.append({"target": name, "measured": value, "status": "n/a" if ok is None else ("PASS" if ok else "FAIL"),
                     "note": note})

    pt = doc.get("pooltool") or {}
    ratios = pt.get("ratios")
    for kind, label, goal in (("straight", "fixed single-ball shot", TARGET_SINGLE_X),
                              ("random", "random single-ball shots (median)", TARGET_SINGLE_X),
                              ("break", "15-ball break", TARGET_BREAK_X)):
        name = f"{label} >= {goal:g}x faster than pooltool"
        if ratios and kind in ratios:
            r = ratios[kind]
            add(name, f"{r['speedup']:.0f}x ({fmt_time(r['ours_s'])} vs {fmt_time(r['pooltool_s'])})",
                r["speedup"] >= goal, f"{r['speedup_novalidate']:.0f}x with run(validate=False)")
        else:
            add(name, "not measured", None, (pt.get("pooltool") or {}).get("note", "pooltool section not run"))
    envs = (doc.get("env_steps") or {}).get("envs", {})
    one = envs.get("BilliardsOneBall-v0", {}).get("make")
    name = f"env.step on BilliardsOneBall-v0 >= {TARGET_ENV_STEPS:,.0f} steps/s"
    if one:
        unw = envs["BilliardsOneBall-v0"].get("unwrapped", {}).get("steps_per_s")
        add(name, f"{one['steps_per_s']:,.0f} steps/s", one["steps_per_s"] >= TARGET_ENV_STEPS,
            f"unwrapped env: {unw:,.0f} steps/s" if unw else "")
    else:
        add(name, "not measured", None, (doc.get("env_steps") or {}).get("note", "env section not run"))
    name = "exact faster than step at every dt with mean error < 1 mm"
    if accuracy and accuracy.get("target_exact_faster"):
        chk = accuracy["target_exact_faster"]
        if chk["pass"] is None:
            add(name, "no step cell below 1 mm", None)
        else:
            add(name, f"{len(chk['cells'])} accurate step cells; step is >= {fmt_num(chk['min_speedup'])}x slower",
                chk["pass"], "from speed_vs_error.json")
    else:
        add(name, "not measured", None, "run the accuracy suite")
    lat = doc.get("latency") or {}
    for key, goal in (("cold", TARGET_COLD_S), ("warm", TARGET_WARM_S)):
        name = f"first call (import + first shot, fresh process) <= {goal:g} s with a {key} numba cache"
        if key in lat:
            r = lat[key]
            add(name, f"{r['total_s']:.2f} s", r["total_s"] <= goal,
                f"import {r['import_s']:.2f} s + first shot {r['first_s']:.2f} s; whole process "
                f"{r['process_wall_s']:.2f} s")
        else:
            add(name, "not measured", None, "latency section not run")
    return rows


# ------------------------------------------------------------------------------------------------ markdown

def render_markdown(doc: dict[str, Any], accuracy: dict[str, Any] | None) -> str:
    info = doc["machine"]
    L = ["# Speed", "", machine_markdown(info, doc.get("end_load")), ""]
    L.append("Produced by `python -m benchmarks` (sections: `--only speed|env|pooltool|latency`). Timing: "
             "`time.perf_counter`, median of repeats after a warm-up call; ratios only between numbers of the same "
             "run. Sections measured in different runs carry their own time stamps.")
    L.append("")
    L.append("## Targets")
    L.append("")
    L.append("| target | measured | status | note |")
    L.append("|---|---|---|---|")
    for r in targets(doc, accuracy):
        L.append(f"| {r['target']} | {r['measured']} | **{r['status']}** | {r['note']} |")
    L.append("")
    ours = doc.get("ours")
    if ours:
        L.append(f"## Exact solver, time per shot ({ours['time']})")
        L.append("")
        L.append(f"Physics: {ours['physics']}. `run()` is `Simulator.run(balls)` as called by default (it validates "
                 "the balls); `validate=False` skips that; `run_in_place` (where the engine has it) is its "
                 "no-copy, no-validation hot path used by the envs; `kernel` is the numba function alone on "
                 "prepared arrays; `wrapper` is `run(validate=False)` minus the kernel (array copies, result objects).")
        L.append("")
        L.append("| shot | events | run() | run(validate=False) | run_in_place | validate_balls | kernel | wrapper "
                 "| shots/s (run) |")
        L.append("|---|---|---|---|---|---|---|---|---|")
        for key in ("fixed", "break"):
            r = ours[key]
            L.append(f"| {r['what']} | {r['n_events']} | {fmt_time(r['run_s'])} | {fmt_time(r['run_novalidate_s'])} "
                     f"| {fmt_time(r.get('run_in_place_s'))} | {fmt_time(r['validate_s'])} "
                     f"| {fmt_time(r.get('kernel_s'))} | {fmt_time(r.get('wrapper_s'))} | {1 / r['run_s']:,.0f} |")
        r = ours["random"]
        L.append(f"| {r['what']}: {r['n_shots']} shots, median | {r['median_events']:g} | {fmt_time(r['median_s'])} | "
                 f"{fmt_time(r['median_novalidate_s'])} | | | | | {r['shots_per_s']:,.0f} |")
        L.append("")
        f = ours["fixed"]
        if f.get("kernel_s"):
            L.append(f"Single-ball shot: validation is {f['validate_s'] / f['run_s']:.0%} of `run()`, the kernel "
                     f"{f['kernel_s'] / f['run_s']:.0%}, the rest (copies, `Balls`/`EventLog`/`ShotResult`) "
                     f"{max(f['wrapper_s'], 0) / f['run_s']:.0%}. Each column is a separate median, so a small "
                     "difference of two (the wrapper) can come out negative on a noisy machine: read it as ~0.")
            L.append("")
    pts = doc.get("pooltool")
    if pts:
        p = pts["pooltool"]
        L.append(f"## Against pooltool ({pts['time']})")
        L.append("")
        if not p.get("available"):
            L.append(f"pooltool not run: {p.get('note')}")
        else:
            L.append(f"pooltool {p['version']} (numpy {p.get('numpy')}, numba {p.get('numba')}) in its own venv "
                     f"(`{p['python']}`, made by `benchmarks/pooltool_setup.sh`), in a subprocess of this run that "
                     "times on request, so that its rounds interleave with ours "
                     f"({pts['rounds']} rounds; per round and shot: {pts['repeats']['straight']} repeats of the "
                     f"straight shot, 1 of each random shot, {pts['repeats']['break']} of the break). pooltool: "
                     "`pooltool.simulate(system, inplace=True)` on a freshly built system; ours: `Simulator.run` on "
                     "the same shots (same positions, aim and speed; pooltool's table built with the same length "
                     "and width). Medians over all samples; a first call per kind of shot is made before and not "
                     "counted. The physics differ (pooltool models spin, sliding and its own cushions and "
                     "pockets), so the event counts differ too. pooltool's import took "
                     f"{p['import_s']:.2f} s and its first shot {p['first_shot_s']:.2f} s "
                     f"(numba cache: {p.get('numba_cache_dir')}).")
            L.append("")
            L.append("| shot | pooltool | ours run() | ours validate=False | speed-up | speed-up per round "
                     "| speed-up (no validation) | events pooltool / ours |")
            L.append("|---|---|---|---|---|---|---|---|")
            for kind, r in pts.get("ratios", {}).items():
                per_round = ", ".join(f"{x:.0f}" for x in r.get("speedup_per_round", []))
                L.append(f"| {kind} ({r['n_shots']} shot{'s' if r['n_shots'] > 1 else ''}) | "
                         f"{fmt_time(r['pooltool_s'])} | {fmt_time(r['ours_s'])} | {fmt_time(r['ours_novalidate_s'])} "
                         f"| {r['speedup']:.0f}x | {per_round} | {r['speedup_novalidate']:.0f}x | "
                         f"{r['pooltool_events']:g} / {r['ours_events']:g} |")
        L.append("")
    env = doc.get("env_steps")
    if env:
        L.append(f"## env.step per second ({env.get('time', '')})")
        L.append("")
        if env.get("note"):
            L.append(f"Note: {env['note']}.")
            L.append("")
        if env.get("envs"):
            L.append(f"All ids in one process, `gymnasium.make(id)` (passive checker and order enforcing wrappers) "
                     f"and `.unwrapped`; seeded random actions; ~{env['seconds_per_env']:g} s each; steps/s counts "
                     "the time inside `step` only, the next column adds the resets at episode ends.")
            L.append("")
            L.append("| env id | steps/s (make) | with resets | steps/s (unwrapped) | mean episode length |")
            L.append("|---|---|---|---|---|")
            for eid, row in env["envs"].items():
                if "error" in row:
                    L.append(f"| {eid} | error: {row['error']} | | | |")
                    continue
                m, u = row["make"], row.get("unwrapped", {})
                L.append(f"| {eid} | {m['steps_per_s']:,.0f} | {m['steps_per_s_with_resets']:,.0f} | "
                         f"{u.get('steps_per_s', float('nan')):,.0f} | {fmt_num(m['mean_episode_steps'])} |")
            L.append("")
    lat = doc.get("latency")
    if lat:
        L.append(f"## First-call latency in a fresh process ({lat['time']})")
        L.append("")
        L.append("`python benchmarks/first_call.py` in a subprocess: import the physics package (numpy, "
                 "numba, and gymnasium through `billiards_env/__init__`), build a table and a simulator, run one "
                 "shot. Warm: the default numba cache (`__pycache__`), primed by a first run. Cold: "
                 "`NUMBA_CACHE_DIR` pointed at an empty temporary directory, so every kernel compiles (runs since "
                 "2026-12-07 set `BILLIARDS_PREBUILT=0`: the prebuilt kernels not unpacked).")
        L.append("")
        L.append("| cache | runs | import | first shot | import + first shot | whole process |")
        L.append("|---|---|---|---|---|---|")
        for key, label in (("warm", "warm"), ("cold", "cold"), ("env_warm", "warm, env: make + reset + step")):
            if key in lat:
                r = lat[key]
                L.append(f"| {label} | {len(r['runs'])} | {r['import_s']:.2f} s | {r['first_s']:.2f} s | "
                         f"{r['total_s']:.2f} s | {r['process_wall_s']:.2f} s |")
        if lat.get("env_note"):
            L.append("")
            L.append(f"Note: {lat['env_note']}.")
        L.append("")
    return "\n".join(L)


def render(out: Path) -> None:
    """Re-write ``speed.md`` from ``speed.json`` (and the accuracy JSON, for its target) without measuring."""
    doc = json.loads((out / "speed.json").read_text())
    acc_path = out / "speed_vs_error.json"
    acc = json.loads(acc_path.read_text()) if acc_path.exists() else None
    doc["targets"] = targets(doc, acc)
    write_json(out / "speed.json", doc)
    (out / "speed.md").write_text(render_markdown(doc, acc))


def main(out: Path | None, quick: bool = False, sections: tuple[str, ...] = ("speed", "env", "pooltool", "latency"),
         pooltool_python: str | None = None, allow_setup: bool = False, env_seconds: float | None = None,
         env_ids: tuple[str, ...] | None = None, env_compare: bool = False,
         accuracy: dict[str, Any] | None = None) -> dict[str, Any]:
    """Measure ``sections`` and print the targets they measured (``accuracy``: this run's accuracy doc, if it ran).
    With ``out``, also merge them into ``out/speed.json`` (the sections of earlier runs that this run did not redo
    stay, with their own time stamps) and re-write ``speed.md``; without, nothing is written."""
    measured: dict[str, Any] = {"machine": machine_info(), "quick": quick}
    if "speed" in sections:
        measured["ours"] = run_ours(quick)
    if "env" in sections:
        measured["env_steps"] = run_env_steps(quick, ids=env_ids or ENV_IDS, seconds=env_seconds,
                                              compare=env_compare)
    if "pooltool" in sections:
        measured["pooltool"] = run_pooltool_section(quick, python=pooltool_python, allow_setup=allow_setup)
    if "latency" in sections:
        measured["latency"] = run_latency(quick)
    measured["end_load"] = load_now()
    for r in targets(measured, accuracy):
        if r["measured"] != "not measured":  # only what this run measured
            log(f"[target] {r['status']:4s} {r['target']}: {r['measured']}")
    if out is None:
        return measured
    out.mkdir(parents=True, exist_ok=True)
    path = out / "speed.json"
    doc: dict[str, Any] = {}
    if path.exists():
        try:
            doc = json.loads(path.read_text())
        except ValueError:
            doc = {}
    doc.update(measured)
    acc = accuracy
    acc_path = out / "speed_vs_error.json"
    if acc is None and acc_path.exists():
        try:
            acc = json.loads(acc_path.read_text())
        except ValueError:
            acc = None
    doc["targets"] = targets(doc, acc)
    write_json(path, doc)
    (out / "speed.md").write_text(render_markdown(doc, acc))
    log(f"[speed] wrote {out / 'speed.md'}")
    return doc
