"""Cold start: ``python -m benchmarks --only cold_start``.

What a new user waits for before the first step, measured in fresh processes (interpreter start-up included):

- the set-up's compile step, ``python -m billiards_env.warmup`` (what ``scripts/setup.sh`` runs after installing),
  on an empty numba cache: with the prebuilt kernels shipped with the package (unpacked, then every kernel loaded),
  and with ``BILLIARDS_PREBUILT=0`` (every kernel compiled here, for this CPU), with its default worker processes
  (one per core) and, in a full run, with one;
- the first ``gymnasium.make`` + ``reset`` + ``step`` of ``BilliardsOneBall-v0`` and ``Billiards9Ball-v0`` after
  that set-up, and on an empty cache: with the prebuilt kernels, and compiling what the step needs there and then.

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
    """Repeats, and the set-ups measured: (key, prebuilt kernels, worker processes; None: the default)."""
    setups = [("prebuilt", True, None), ("compiled", False, None)] + ([] if quick else [("compiled_1", False, 1)])
    return {"cold": 1 if quick else 3, "warm": 2 if quick else 5, "setups": setups}


def _env(cache: str, prebuilt: bool = True) -> dict[str, str]:
    """A fresh process's environment: numba's cache at ``cache``, the prebuilt kernels on or off (and numba's CPU as
    a user's process would start with it: this process's import of the package may have set it)."""
    env = {k: v for k, v in os.environ.items() if k not in ("BILLIARDS_PREBUILT", "NUMBA_CPU_NAME", "NUMBA_CPU_FEATURES")}
    env.update({"NUMBA_CACHE_DIR": cache, "SDL_VIDEODRIVER": "dummy", "BILLIARDS_COMPILE_NOTICE": "0",
                "PYTHONPATH": str(_ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")})
    if not prebuilt:
        env["BILLIARDS_PREBUILT"] = "0"
    return env


def _first_step(env_id: str, cache: str, prebuilt: bool = True) -> dict[str, float]:
    """One fresh process: import, make, reset and step ``env_id`` with numba's cache at ``cache``."""
    t0 = time.perf_counter()
    out = subprocess.run([sys.executable, str(_ROOT / "benchmarks" / "first_call.py"), "--env", env_id],
                         env=_env(cache, prebuilt), cwd=_ROOT, capture_output=True, text=True, check=True)
    wall = time.perf_counter() - t0
    return {**json.loads(out.stdout.strip().splitlines()[-1]), "process_s": wall}


def _setup(cache: str, prebuilt: bool, workers: int | None) -> float:
    """The set-up's compile step into ``cache``: wall seconds of ``python -m billiards_env.warmup``."""
    cmd = [sys.executable, "-m", "billiards_env.warmup"] + ([] if workers is None else ["--workers", str(workers)])
    t0 = time.perf_counter()
    subprocess.run(cmd, env=_env(cache, prebuilt), cwd=_ROOT, capture_output=True, text=True, check=True)
    return time.perf_counter() - t0


def _median(rows: list[dict[str, float]]) -> dict[str, float]:
    return {k: statistics.median(r[k] for r in rows) for k in rows[0]}


def run(quick: bool = False) -> dict[str, Any]:
    """Measure everything above; returns the report's data."""
    n = _sizes(quick)
    doc: dict[str, Any] = {"command": COMMAND + (" --quick" if quick else ""), "quick": quick,
                           "time": time.strftime("%Y-%m-%d %H:%M:%S"), "targets": TARGETS,
                           "workers_default": len(os.sched_getaffinity(0)), "setup": {}, "warm": {}, "cold": {},
                           "cold_compiled": {}}
    with tempfile.TemporaryDirectory(prefix="numba-setup-") as built:
        for key, prebuilt, workers in n["setups"]:  # the first set-up's cache (``built``) serves the warm steps
            if key == "prebuilt":
                doc["setup"][key] = _setup(built, prebuilt, workers)
            else:
                with tempfile.TemporaryDirectory(prefix="numba-setup-") as d:
                    doc["setup"][key] = _setup(d, prebuilt, workers)
            log(f"[cold_start] set-up, {key}: {doc['setup'][key]:.1f} s")
        for env_id in ENV_IDS:
            doc["warm"][env_id] = _median([_first_step(env_id, built) for _ in range(n["warm"])])
            log(f"[cold_start] {env_id} first step after the set-up: {doc['warm'][env_id]['first_s']:.2f} s")
    for key, prebuilt in (("cold", True), ("cold_compiled", False)):
        for env_id in ENV_IDS:
            rows = []
            for _ in range(n["cold"]):
                with tempfile.TemporaryDirectory(prefix="numba-cold-") as d:
                    rows.append(_first_step(env_id, d, prebuilt))
            doc[key][env_id] = _median(rows)
            log(f"[cold_start] {env_id} first step on an empty cache, {'prebuilt' if prebuilt else 'compiled'}: "
                f"{doc[key][env_id]['first_s']:.2f} s")
    doc["repeats"] = {"cold": n["cold"], "warm": n["warm"]}
    return doc


def render_markdown(doc: dict[str, Any]) -> str:
    t = doc["targets"]
    lines = ["# Cold start", "",
             f"Command: `{doc['command']}` ({doc['time']}). Fresh processes; numba's cache in a temporary directory. "
             "\"First step\": `import billiards_env`, `gymnasium.make`, `reset(seed=0)` and one `step` (the "
             "interpreter's own start-up not included; `process` includes it). Medians of "
             f"{doc['repeats']['warm']} processes after the set-up and {doc['repeats']['cold']} on an empty cache. "
             "\"Prebuilt\": the kernels shipped with the package, unpacked into the empty cache at import; "
             "\"compiled here\": `BILLIARDS_PREBUILT=0`, every kernel the step needs compiled for this CPU.",
             "", "| env | first step after the set-up | empty cache, prebuilt | empty cache, compiled here | "
             "target (empty cache) |", "|---|---:|---:|---:|---:|"]
    for env_id in doc["cold"]:
        w, c = doc["warm"][env_id], doc["cold"][env_id]
        cc = doc.get("cold_compiled", {}).get(env_id)
        compiled = f"{cc['first_s']:.1f} s (process {cc['process_s']:.1f} s)" if cc else "-"
        lines.append(f"| `{env_id}` | {w['first_s']:.2f} s (process {w['process_s']:.2f} s) | {c['first_s']:.2f} s "
                     f"(process {c['process_s']:.2f} s) | {compiled} | {t[env_id]:.0f} s |")
    lines += ["", "The set-up's compile step, `python -m billiards_env.warmup` on an empty cache (target "
              f"{t['setup']:.0f} s):", ""]
    names = {"prebuilt": "with the prebuilt kernels (unpacked, then every kernel loaded)",
             "compiled": "`BILLIARDS_PREBUILT=0`: every kernel compiled here",
             "default": "every kernel compiled here"}
    for key, s in doc["setup"].items():
        workers = (f"one worker process per core ({doc['workers_default']})" if not key.endswith("_1")
                   and key != "1" else "`--workers 1`")
        lines.append(f"- {names.get(key.removesuffix('_1'), 'every kernel compiled here')}, {workers}: {s:.1f} s")
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
