"""Run :mod:`.pooltool_bench` in the pooltool venv (a separate interpreter) and exchange JSON lines with it.

The venv is made by ``benchmarks/pooltool_setup.sh`` (default ``<repo>/.venv-pooltool``; override with the
``BILLIARDS_BENCH_POOLTOOL_PYTHON`` environment variable or ``--pooltool-python``). pooltool is never imported
in this process.
"""
from __future__ import annotations

import json
import os
import queue
import subprocess
import threading
from pathlib import Path
from typing import Any

from .common import Shot, log

SCRIPT = Path(__file__).with_name("pooltool_bench.py")
REPO = Path(__file__).resolve().parents[1]
SETUP = REPO / "benchmarks" / "pooltool_setup.sh"
DEFAULT_VENV = REPO / ".venv-pooltool"
#: What the setup script installs, for the messages that offer it.
SETUP_SIZE = "a venv of about 734 MB in .venv-pooltool, a few minutes"


class PooltoolUnavailable(RuntimeError):
    pass


def pooltool_python(explicit: str | None = None) -> Path:
    if explicit:
        return Path(explicit)
    env = os.environ.get("BILLIARDS_BENCH_POOLTOOL_PYTHON")
    if env:
        return Path(env)
    return DEFAULT_VENV / "bin" / "python"


def _has_pooltool(py: Path) -> str | None:
    """pooltool's version in that interpreter, or None."""
    if not py.exists():
        return None
    try:
        r = subprocess.run([str(py), "-c", "import importlib.metadata as m; print(m.version('pooltool-billiards'))"],
                           capture_output=True, text=True, timeout=120)
    except (OSError, subprocess.TimeoutExpired):
        return None
    return r.stdout.strip() if r.returncode == 0 else None


def ensure_pooltool(py: Path, allow_setup: bool = False) -> tuple[str | None, str]:
    """``(version, note)``: pooltool's version in ``py``, running the setup script if it is missing."""
    version = _has_pooltool(py)
    if version:
        return version, ""
    if not allow_setup:
        return None, (f"pooltool is not installed at {py}, so the comparison with pooltool is left out; "
                      f"`python -m benchmarks --with-pooltool` installs it ({SETUP_SIZE}) and includes it (or run "
                      "`bash benchmarks/pooltool_setup.sh` once)")
    if py != DEFAULT_VENV / "bin" / "python" or not SETUP.exists():
        return None, f"pooltool is not installed at {py} and there is no setup script to run here"
    log(f"[pooltool] {py} missing: --with-pooltool, so running {SETUP} ({SETUP_SIZE})")
    try:
        r = subprocess.run(["bash", str(SETUP), str(DEFAULT_VENV)], capture_output=True, text=True, timeout=900)
    except (OSError, subprocess.TimeoutExpired) as exc:
        return None, f"pooltool could not be installed: {exc}"
    if r.returncode != 0:
        tail = " ".join((r.stderr or r.stdout).strip().splitlines()[-3:])
        return None, f"pooltool could not be installed (benchmarks/pooltool_setup.sh exit {r.returncode}): {tail}"
    version = _has_pooltool(py)
    return version, "" if version else "pooltool setup ran but pooltool still does not import"


class PooltoolSession:
    """A pooltool process holding the shots; :meth:`time` times one kind of shot on request."""

    def __init__(self, kinds: list[tuple[str, list[Shot]]], table_length: float, table_width: float,
                 python: str | None = None, allow_setup: bool = False, timeout: float = 600.0) -> None:
        py = pooltool_python(python)
        version, note = ensure_pooltool(py, allow_setup)
        if not version:
            raise PooltoolUnavailable(note)
        self.python = str(py)
        self.timeout = timeout
        self._stderr: list[str] = []
        self.proc = subprocess.Popen([str(py), str(SCRIPT)], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE, text=True, bufsize=1)
        self._lines: queue.Queue[str | None] = queue.Queue()
        threading.Thread(target=self._pump, args=(self.proc.stdout, self._lines), daemon=True).start()
        threading.Thread(target=self._pump_err, daemon=True).start()
        spec = {"table_length": table_length, "table_width": table_width,
                "kinds": [{"name": name, "shots": [s.spec() for s in shots]} for name, shots in kinds]}
        try:
            self.ready = self._send(spec)
        except PooltoolUnavailable:
            self.close()
            raise
        self.ready["python"] = self.python

    @staticmethod
    def _pump(stream, q: "queue.Queue[str | None]") -> None:
        for line in stream:
            q.put(line)
        q.put(None)

    def _pump_err(self) -> None:
        for line in self.proc.stderr:
            self._stderr.append(line)
            del self._stderr[:-20]

    def _send(self, obj: dict[str, Any]) -> dict[str, Any]:
        try:
            self.proc.stdin.write(json.dumps(obj) + "\n")
            self.proc.stdin.flush()
        except (BrokenPipeError, OSError) as exc:
            raise PooltoolUnavailable(f"pooltool process ended: {exc}; {self._err_tail()}") from None
        while True:
            try:
                line = self._lines.get(timeout=self.timeout)
            except queue.Empty:
                self.close()
                raise PooltoolUnavailable(f"pooltool did not answer within {self.timeout:.0f} s") from None
            if line is None:
                raise PooltoolUnavailable(f"pooltool process ended (exit {self.proc.wait()}): {self._err_tail()}")
            line = line.strip()
            if line.startswith("{"):  # skip anything pooltool itself prints
                return json.loads(line)

    def _err_tail(self) -> str:
        return " ".join(s.strip() for s in self._stderr[-3:])

    def time(self, kind: str, repeats: int) -> dict[str, Any]:
        return self._send({"kind": kind, "repeats": repeats})

    def close(self) -> None:
        if self.proc.poll() is None:
            try:
                self.proc.stdin.write(json.dumps({"quit": True}) + "\n")
                self.proc.stdin.close()
                self.proc.wait(timeout=30)
            except (OSError, subprocess.TimeoutExpired, ValueError):
                self.proc.kill()
                self.proc.wait()

    def __enter__(self) -> "PooltoolSession":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
