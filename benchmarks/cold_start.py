"""Cold start: ``python -m benchmarks --only cold_start``.

What a new user waits for before the first step, measured in fresh processes (interpreter start-up included):

- the set-up's compile step, ``python -m billiards_env.warmup`` (what ``scripts/setup.sh`` runs after installing),
  on an empty numba cache, with its default worker processes (one per core) and with one;
- the first ``gymnasium.make`` + ``reset`` + ``step`` of ``BilliardsOneBall-v0`` and ``Billiards9Ball-v0`` after
  that set-up (the cache it built), and on an empty cache (every kernel the step needs compiled there and then).

Each figure is the median of fresh processes (``benchmarks/first_call.py``); ``NUMBA_CACHE_DIR`` points at a
temporary directory, so the repository's own cache is neither read nor changed.
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

from .common import load_now, log, machine_info, machine_markdown, publish, rerender

COMMAND = "python -m benchmarks --only cold_start"
ENV_IDS = ("BilliardsOneBall-v0", "Billiards9Ball-v0")
#: The issue's targets (seconds): the first step on an empty cache, and the set-up's compile step.
TARGETS = {"BilliardsOneBall-v0": 3.0, "Billiards9Ball-v0": 6.0, "setup": 60.0}
_ROOT = Path(__file__).resolve().parents[1]


def _sizes(quick: bool) -> dict[str, Any]:
    return ({"cold": 1, "warm": 2, "setup_workers": (None,)} if quick
            else {"cold": 3, "warm": 5, "setup_workers": (None, 1)})


def _env(cache: str) -> dict[str, str]:
    return {**os.environ, "NUMBA_CACHE_DIR": cache, "SDL_VIDEODRIVER": "dummy", "BILLIARDS_COMPILE_NOTICE": "0",
            "PYTHONPATH": str(_ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")}


def _first_step(env_id: str, cache: str) -> dict[str, float]:
    """One fresh process: import, make, reset and step ``env_id`` with numba's cache at ``cache``."""
    t0 = time.perf_counter()
    out = subprocess.run([sys.executable, str(_ROOT / "benchmarks" / "first_call.py"), "--env", env_id],
                         env=_env(cache), cwd=_ROOT, capture_output=True, text=True, check=True)
    wall = time.perf_counter() - t0
    return {**json.loads(out.stdout.strip().splitlines()[-1]), "process_s": wall}


def _setup(cache: str, workers: int | None) -> float:
    """The set-up's compile step into ``cache``: wall seconds of ``python -m billiards_env.warmup``."""
    cmd = [sys.executable, "-m", "billiards_env.warmup"] + ([] if workers is None else ["--workers", str(workers)])
    t0 = time.perf_counter()
    subprocess.run(cmd, env=_env(cache), cwd=_ROOT, capture_output=True, text=True, check=True)
    return time.perf_counter() - t0


def _median(rows: list[dict[str, float]]) -> dict[str, float]:
    return {k: statistics.median(r[k] for r in rows) for k in rows[0]}


def run(quick: bool = False) -> dict[str, Any]:
    """Measure everything above; returns the report's data."""
    n = _sizes(quick)
    doc: dict[str, Any] = {"command": COMMAND + (" --quick" if quick else ""), "quick": quick,
                           "time": time.strftime("%Y-%m-%d %H:%M:%S"), "targets": TARGETS,
                           "workers_default": len(os.sched_getaffinity(0)), "setup": {}, "warm": {}, "cold": {}}
    with tempfile.TemporaryDirectory(prefix="numba-setup-") as built:
        for workers in n["setup_workers"]:  # the default's cache (``built``) serves the steps after the set-up
            key = "default" if workers is None else str(workers)
            if workers is None:
                doc["setup"][key] = _setup(built, workers)
            else:
                with tempfile.TemporaryDirectory(prefix="numba-setup-") as d:
                    doc["setup"][key] = _setup(d, workers)
            log(f"[cold_start] set-up compile, workers {key}: {doc['setup'][key]:.1f} s")
        for env_id in ENV_IDS:
            doc["warm"][env_id] = _median([_first_step(env_id, built) for _ in range(n["warm"])])
            log(f"[cold_start] {env_id} first step after the set-up: {doc['warm'][env_id]['first_s']:.2f} s")
    for env_id in ENV_IDS:
        rows = []
        for _ in range(n["cold"]):
            with tempfile.TemporaryDirectory(prefix="numba-cold-") as d:
                rows.append(_first_step(env_id, d))
        doc["cold"][env_id] = _median(rows)
        log(f"[cold_start] {env_id} first step on an empty cache: {doc['cold'][env_id]['first_s']:.2f} s")
    doc["repeats"] = {"cold": n["cold"], "warm": n["warm"]}
    return doc


def render_markdown(doc: dict[str, Any]) -> str:
    t = doc["targets"]
    lines = ["# Cold start", "",
             f"Command: `{doc['command']}` ({doc['time']}). Fresh processes; numba's cache in a temporary directory. "
             "\"First step\": `import billiards_env`, `gymnasium.make`, `reset(seed=0)` and one `step` (the "
             "interpreter's own start-up not included; `process` includes it). Medians of "
             f"{doc['repeats']['warm']} processes after the set-up and {doc['repeats']['cold']} on an empty cache.",
             "", "| env | first step after the set-up | on an empty cache | target (empty cache) |",
             "|---|---:|---:|---:|"]
    for env_id in doc["cold"]:
        w, c = doc["warm"][env_id], doc["cold"][env_id]
        lines.append(f"| `{env_id}` | {w['first_s']:.2f} s (process {w['process_s']:.2f} s) | {c['first_s']:.1f} s "
                     f"(process {c['process_s']:.1f} s) | {t[env_id]:.0f} s |")
    lines += ["", "The set-up's compile step, `python -m billiards_env.warmup` on an empty cache (target "
              f"{t['setup']:.0f} s):", ""]
    for key, s in doc["setup"].items():
        who = (f"default: one worker process per core ({doc['workers_default']})" if key == "default"
               else f"`--workers {key}`")
        lines.append(f"- {who}: {s:.0f} s")
    if "machine" in doc:
        lines += ["", machine_markdown(doc["machine"], doc.get("end_load"))]
    return "\n".join(lines) + "\n"


def render(out: Path) -> None:
    """Re-write ``cold_start.md`` from ``cold_start.json``, without measuring."""
    rerender(out, "cold_start", render_markdown)


def main(out: Path | None, quick: bool = False) -> dict[str, Any]:
    """Measure, print, and write ``cold_start.json`` and ``cold_start.md`` into ``out`` if given."""
    doc = {"machine": machine_info(), **run(quick)}
    doc["end_load"] = load_now()
    publish(doc, render_markdown(doc), out, "cold_start")
    return doc
