"""The baseline players moved into the package: :mod:`billiards_env.players` (the game envs use them as
opponents). This module keeps the old import path for the agents code."""
from billiards_env.players import *  # noqa: F401,F403
from billiards_env.players import __all__  # noqa: F401
