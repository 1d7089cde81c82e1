"""agents.rllib: the billiards envs on Ray RLlib, to scale training out over env runners and learners on a cluster.

- ``python -m agents.rllib`` (:mod:`.train`): train PPO, APPO, IMPALA or SAC on any registered id with its env
  options, on this machine or on a Ray cluster (``--address auto``), checkpoints and resume; the two-player games
  by self-play on RLlib's multi-agent API (:mod:`.selfplay`).
- :mod:`.config`: the config files (``configs/train/rllib_*.yaml``): RLlib's AlgorithmConfig sections plus a
  ``billiards:`` section.
- :mod:`.player`: an RLlib checkpoint as a player of ``python -m agents.evaluate`` (beside SB3 agents and the
  baselines, the same report).

Needs the ``rllib`` extra (``pip install -e ".[agents,rllib]"``, or ``bash scripts/setup.sh --rllib`` for the
``.venv-rllib`` of this repository). Importing this package does not import Ray.
"""
