"""Worker threads for compiled kernels that release the GIL (``nogil=True``): a batch of independent rows split
into contiguous slices, one kernel call per slice.

Threads rather than numba's ``prange``: a ``parallel=True`` kernel is a compile unit of its own (its loop body is
compiled again as a gufunc, with the solver it calls), about 10 CPU-seconds of compile per solver family, for the
same machine code the serial kernel already has. Each row runs the serial kernel's code, so results do not depend on
the number of threads.
"""
from __future__ import annotations

from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import TypeVar

import numpy as np

T = TypeVar("T")

#: One pool of worker threads per thread count, kept for the process (a batch is too short to start threads).
_POOLS: dict[int, ThreadPoolExecutor] = {}


def pool(threads: int) -> ThreadPoolExecutor:
    """The pool of ``threads`` worker threads (created on first use, kept)."""
    if threads not in _POOLS:
        _POOLS[threads] = ThreadPoolExecutor(threads, thread_name_prefix="billiards-rows")
    return _POOLS[threads]


def default_threads() -> int:
    """Threads for a parallel batch left open (``threads=None``): numba's thread count, i.e. the cores it may use
    (``NUMBA_NUM_THREADS`` lowers it)."""
    import numba

    return int(numba.get_num_threads())


def on_slices(run: Callable[[slice], T], n: int, threads: int) -> list[T]:
    """``run(s)`` for ``threads`` contiguous slices ``s`` of ``range(n)`` (fewer if ``n`` is smaller), on the pool's
    threads; the results in slice order."""
    threads = max(1, min(threads, n))
    if threads == 1:
        return [run(slice(0, n))]
    edges = np.linspace(0, n, threads + 1).round().astype(int)
    parts = [slice(int(a), int(b)) for a, b in zip(edges[:-1], edges[1:])]
    return list(pool(threads).map(run, parts))


__all__ = ["default_threads", "on_slices", "pool"]
