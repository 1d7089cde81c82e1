"""OpenMP's wait policy for numba's thread pool, set before the pool starts.

numba's ``omp`` threading layer (the default where GNU OpenMP is present) keeps its worker threads spinning after each
parallel batch. Between batches a training loop runs Python (the policy, SB3's buffers), and the spinning thread
burns a core the whole time: a process's CPU clock runs at twice its wall clock on an idle 2-core machine (a CPU
budget buys half the steps), and on a busy one the spinner takes the core from the main thread (a loop of short
batches ran 3-5x slower in wall time here). ``PASSIVE`` makes the workers sleep between batches, for a wake-up per
batch (``python -m benchmarks.openmp_wait``: on idle cores, half the CPU time for about 10% more wall time on
sub-millisecond batches; a batch of the vector envs' size takes milliseconds). A value the user set is kept. libgomp reads the variable
once, when it is loaded: importing torch (which loads its own copy under the same name) before this package fixes
the policy already, so the agents import this package first.
"""
from __future__ import annotations

import os

#: The variable and the value set when the user has not set one.
WAIT_POLICY_VAR = "OMP_WAIT_POLICY"
DEFAULT_WAIT_POLICY = "PASSIVE"


def default_wait_policy() -> str:
    """Set ``OMP_WAIT_POLICY=PASSIVE`` unless the user set it; returns the value in force."""
    return os.environ.setdefault(WAIT_POLICY_VAR, DEFAULT_WAIT_POLICY)
