"""Moved: :mod:`billiards_env.players.shots` (kept as an import path for the agents code)."""
from billiards_env.players.shots import *  # noqa: F401,F403
