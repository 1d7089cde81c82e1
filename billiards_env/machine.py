"""The machine and versions a measurement ran on: what benchmark reports and the agents' reports (leagues, jobs)
print beside their figures, so that every figure says where it was measured."""
from __future__ import annotations

import os
import platform
import time
from pathlib import Path
from typing import Any

import numpy as np


def machine_info() -> dict[str, Any]:
    """CPU model, cores, load, and the versions that matter for the timings."""
    cpu = platform.processor() or "unknown"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    info: dict[str, Any] = {
        "cpu": cpu,
        "cores": os.cpu_count(),
        "python": platform.python_version(),
        "platform": platform.platform(),
        "numpy": np.__version__,
    }
    try:
        import numba
        info["numba"] = numba.__version__
    except ImportError:  # pragma: no cover
        info["numba"] = None
    try:
        info["load_avg"] = [round(x, 2) for x in os.getloadavg()]
    except OSError:  # pragma: no cover
        info["load_avg"] = None
    info["time"] = time.strftime("%Y-%m-%d %H:%M:%S %z")
    info["engine"] = engine_version()
    return info


def engine_version() -> str | None:
    """The repository's commit and whether the engine (``billiards_env/physics``) has uncommitted changes
    (read-only git queries; None outside a git checkout)."""
    import subprocess

    repo = Path(__file__).resolve().parents[1]  # the checkout holding billiards_env/
    try:
        head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=repo, capture_output=True, text=True,
                              timeout=10)
        if head.returncode != 0:
            return None
        dirty = subprocess.run(["git", "status", "--porcelain", "--", "billiards_env/physics"], cwd=repo,
                               capture_output=True, text=True, timeout=10)
    except (OSError, subprocess.TimeoutExpired):
        return None
    out = head.stdout.strip()
    if dirty.stdout.strip():
        out += " + uncommitted changes in billiards_env/physics"
    return out


def machine_markdown(info: dict[str, Any], end_load: list[float] | None = None) -> str:
    load = info.get("load_avg")
    s = (f"Machine: {info['cpu']}, {info['cores']} cores; Python {info['python']}, numpy {info['numpy']}, "
         f"numba {info['numba']}; {info['platform']}. Engine: commit {info.get('engine') or 'unknown'}. "
         f"Run at {info['time']}")
    if load:
        s += f"; load average (1/5/15 min) at start {load[0]}/{load[1]}/{load[2]}"
    if end_load:
        s += f", at end {end_load[0]}/{end_load[1]}/{end_load[2]}"
    s += "."
    if load and load[0] > 0.5 * (info["cores"] or 1):
        s += (" The machine was shared with other work during the run (load above half the cores): absolute "
              "times are noisy; ratios measured in one run are more robust.")
    return s


def load_now() -> list[float] | None:
    try:
        return [round(x, 2) for x in os.getloadavg()]
    except OSError:  # pragma: no cover
        return None


__all__ = ["machine_info", "machine_markdown", "engine_version", "load_now"]
