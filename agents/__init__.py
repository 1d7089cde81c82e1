"""agents: training, baselines and evaluation for the billiards environments.

- :mod:`agents.train` — ``python -m agents.train --config configs/train/<file>.yaml`` (SB3 SAC/TD3/PPO/A2C/DDPG).
- :mod:`agents.baselines` — ``random``, ``geometric`` (ghost-ball aiming) and ``search`` (simulated candidates).
- :mod:`agents.evaluate` — ``python -m agents.evaluate``: players side by side, Wilson intervals, report files.
- :mod:`agents.main` — the main job (``scripts/main.sh``): train the one-ball agent, evaluate, report.
- :mod:`agents.wrappers` — action/observation wrappers used by the configs (also usable from the RL Zoo).

See ``agents/README.md``.
"""
