"""billiards_env.bench: the benchmark suite (``python -m billiards_env.bench``, console script ``billiards-bench``).

- :mod:`.accuracy`: speed against error, the ``step`` solver at a series of ``dt`` against ``exact``, and the
  chaos floor (``docs/bench/speed_vs_error.md/.json/.png``).
- :mod:`.speed`: time per shot of the ``exact`` solver, ``env.step`` per second, first-call latency in a fresh
  process, and the comparison with pooltool run in its own venv (``docs/bench/speed.md/.json``).

Methodology: ``time.perf_counter``, a warm-up call first, medians over repeats; ratios only between numbers
measured in the same run. Nothing here asserts on times.
"""
