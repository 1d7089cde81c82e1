"""The benchmark suite of the repository (not part of the installed package): run from the repository root with
``python -m benchmarks [--quick] [--only SECTION] [--write | --out DIR]`` (see :mod:`benchmarks.__main__`).

Sections (``--only`` takes one, repeatable; default all):

- ``accuracy`` (:mod:`.accuracy`): speed against error, the ``step`` solver at a series of ``dt`` against
  ``exact``, and the chaos floor (``docs/bench/speed_vs_error.md/.json/.png``).
- ``speed``, ``env``, ``pooltool``, ``latency`` (:mod:`.speed`): time per shot of the ``exact`` solver,
  ``env.step`` per second of every registered id (:func:`.speed.time_env`, also printed as a table),
  pooltool 0.6.0 on the same shots in its own venv (:mod:`.pooltool_runner` drives :mod:`.pooltool_bench`,
  venv made by ``benchmarks/pooltool_setup.sh``), first-call latency in a fresh process
  (:mod:`.first_call`); all in ``docs/bench/speed.md/.json``. ``speed.json`` keeps the sections of earlier runs
  that a run did not redo, each with its own time stamp.

Not a section: ``python -m benchmarks.spin_crosscheck`` (:mod:`.spin_crosscheck`) compares the spin model with
pooltool 0.6.0 scene by scene and prints the differences (evidence, no report file).

Adding a section: write ``run_<name>(quick) -> dict`` (in :mod:`.speed` when its figures belong in
``speed.md``, else a module of its own with a ``main(out, quick)`` that writes its report), store its dict
under a key of ``speed.json`` in :func:`.speed.main`, render it in :func:`.speed.render_markdown` (and a target
in :func:`.speed.targets` if it has one), add its name to ``SECTIONS`` in :mod:`.__main__`, and test it in
``tests/bench`` in a tiny configuration (no timed assertions).

Methodology: ``time.perf_counter``, a warm-up call first, medians over repeats; ratios only between numbers
measured in the same run. Nothing here asserts on times. Shared helpers (seeded shot sets, machine description,
formatting, strict JSON) are in :mod:`.common`.
"""
