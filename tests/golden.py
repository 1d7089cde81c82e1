"""Recorded results of the Python the compiled players replaced: :class:`Golden`, the ``golden`` fixture's object
(``tests/conftest.py``).

The compiled players (``billiards_env/players/geometry.py``, ``slots.py``, ``search.py``, ``envs/candidates.py``)
must decide what the Python they replaced decided, bit for bit. That Python is kept with the benchmarks
(``benchmarks/reference_players.py``: outside the package, and built on live code), so the tests do not run it: they
compare the compiled results with records of it, ``tests/golden_records/<test>.json``, one digest per checked value.

Re-record (after a deliberate change of what the players decide, as with the env fingerprint) with
``BILLIARDS_GOLDEN=record python -m pytest -p no:xdist tests/players tests/envs/test_candidates.py``: each test then
runs the reference too, asserts that the compiled result equals it, and writes the digests of what it checked.
"""
from __future__ import annotations

import hashlib
import json
import math
import os
from collections.abc import Callable
from dataclasses import fields, is_dataclass
from pathlib import Path
from typing import Any

import numpy as np

GOLDEN_DIR = Path(__file__).resolve().parent / "golden_records"
RECORD = os.environ.get("BILLIARDS_GOLDEN", "") == "record"


def canonical(value: Any) -> Any:
    """``value`` as plain JSON data that two equal values share: floats exactly (``float.hex``; -0.0 as 0.0, as
    ``==`` has them), numpy scalars as Python's, arrays by dtype, shape and bytes, dataclasses by their fields."""
    if isinstance(value, np.ndarray):
        if value.dtype.kind == "f":
            value = value + 0.0  # -0.0 -> 0.0
        return ["ndarray", value.dtype.str, list(value.shape), np.ascontiguousarray(value).tobytes().hex()]
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, bool) or value is None or isinstance(value, (int, str)):
        return value
    if isinstance(value, float):
        return "nan" if math.isnan(value) else (value + 0.0).hex()
    if is_dataclass(value) and not isinstance(value, type):
        return [type(value).__name__] + [canonical(getattr(value, f.name)) for f in fields(value)]
    if isinstance(value, (tuple, list)):
        return [canonical(v) for v in value]
    if isinstance(value, dict):
        return {str(k): canonical(v) for k, v in sorted(value.items())}
    raise TypeError(f"golden: no canonical form for {type(value).__name__}")


def digest(value: Any) -> str:
    """A short digest of :func:`canonical` ``(value)``."""
    return hashlib.sha256(json.dumps(canonical(value)).encode()).hexdigest()[:20]


class Golden:
    """The records of one test: :meth:`check` each compiled result in turn."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self.seen: list[str] = []
        self.want: list[str] | None = None
        if not RECORD:
            if not path.exists():
                raise FileNotFoundError(f"{path}: no records for this test; record them (tests/conftest.py says how)")
            self.want = json.loads(path.read_text())

    def check(self, got: Any, reference: Callable[[], Any] | None = None,
              same: Callable[[Any, Any], bool] = lambda a, b: a == b) -> None:
        """``got`` is the recorded value at this point of the test. Recording: ``reference()`` (the Python's value,
        in the form ``got`` has) must equal it (``same``), and ``got`` is recorded."""
        k = len(self.seen)
        self.seen.append(digest(got))
        if RECORD:
            if reference is not None:
                assert same(got, reference()), f"check {k}: the compiled result differs from the reference"
            return
        assert self.want is not None
        assert k < len(self.want), f"check {k}: more values than the {len(self.want)} recorded ({self.path.name})"
        assert self.seen[k] == self.want[k], f"check {k} of {self.path.name}: not the recorded value"

    def finish(self) -> None:
        if RECORD:
            self.path.parent.mkdir(exist_ok=True)
            self.path.write_text(json.dumps(self.seen, indent=0) + "\n")
        else:
            assert self.want is not None
            assert len(self.seen) == len(self.want), (f"{len(self.seen)} values checked, {len(self.want)} recorded "
                                                      f"({self.path.name}): the test no longer reaches the same tables")


def reference_players() -> Any:
    """``benchmarks/reference_players.py``, imported only when recording."""
    assert RECORD, "the reference Python runs only when recording (BILLIARDS_GOLDEN=record)"
    from benchmarks import reference_players

    return reference_players
