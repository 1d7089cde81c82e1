"""Local worker processes for the jobs that spread games over the cores (leagues, datasets, distillation labels)."""
from __future__ import annotations

import multiprocessing
from concurrent.futures import ProcessPoolExecutor


def process_pool(workers: int) -> ProcessPoolExecutor:
    """A pool of ``workers`` processes started by a fork server, not forked from this process: a process that has
    run numba's parallel kernels holds GNU OpenMP's threads, and a child forked from it is terminated ("fork()
    called from a process already using GNU OpenMP"). The results never depend on how the work is spread."""
    return ProcessPoolExecutor(max_workers=workers, mp_context=multiprocessing.get_context("forkserver"))


__all__ = ["process_pool"]
