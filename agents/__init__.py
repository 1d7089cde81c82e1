"""agents: training, baselines and evaluation for the billiards environments.

- :mod:`agents.train` — ``python -m agents.train --config configs/train/<file>.yaml`` (SB3 SAC/TD3/PPO/A2C/DDPG).
- baseline players (``random``, ``geometric``, ``search``) live in the package: :mod:`billiards_env.players`.
- :mod:`agents.evaluate` — ``python -m agents.evaluate``: players side by side, Wilson intervals, report files.
- :mod:`agents.main` — the main job (``scripts/main.sh``): train the one-ball agent, evaluate, report.
- the configs choose the env's action and observation types (``action_type: ghost``, ``observation_type:
  features``): env options, so a saved model loads with ``gym.make(env_id, **env_kwargs)`` alone.

See ``agents/README.md``.
"""

import billiards_env  # noqa: E402,F401  (first: it sets numba's OpenMP wait policy before torch loads OpenMP)
