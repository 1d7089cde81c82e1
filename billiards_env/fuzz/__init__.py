"""Numerical-stability fuzzing of the physics engine: random scenes, random shots, invariant checks.

``python -m billiards_env.fuzz --shots 100000 [--seed S] [--solver exact|step|both] [--workers 2] [--out DIR]``
(``--check FILE``: one scene file; ``--shrink FILE``: a smaller failing scene). Every shot is a random scene and
cue strike; after it the invariants of :mod:`billiards_env.physics.invariants` are checked.

- :mod:`.generator`: the random scene generator (:func:`~.generator.random_scene`) and its random sources.
- :mod:`.shrink`: :func:`~.shrink.shrink_case`, a smaller scene that still violates an invariant.
- :mod:`.cli`: the runner (worker processes, :class:`~.cli.Stats`, the summary, saving failing cases) and the
  command line.

The checks themselves (tolerances, :class:`~billiards_env.physics.invariants.Report`, ``check_shot``,
``run_case``) live in :mod:`billiards_env.physics.invariants`, shared with the tests in ``tests/stability``.
"""
