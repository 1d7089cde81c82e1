"""billiards_env: Gymnasium pool environments on an exact, fast billiards physics engine.

Importing the package registers the environment ids with Gymnasium (the list: :data:`ENV_IDS`)::

    import gymnasium as gym
    import billiards_env  # noqa: F401

    env = gym.make("BilliardsOneBall-v0")  # also BilliardsThreeBalls-v0, BilliardsRack-v0
"""
from .registration import ENV_IDS, register_envs

register_envs()

__all__ = ["ENV_IDS"]
