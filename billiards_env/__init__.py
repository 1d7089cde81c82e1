"""billiards_env: Gymnasium pool environments on an exact, fast billiards physics engine.

The layers (``docs/architecture.md``): :mod:`.physics` (the engine) <- :mod:`.rules` (the rules of the games) <-
:mod:`.games` (the game registry and sessions) <- :mod:`.table_state` and :mod:`.shot_path` (what every part reads,
and the one way a shot is played) <- :mod:`.players` and :mod:`.envs` (Gymnasium) <- :mod:`.multi` (PettingZoo);
:mod:`.render` draws plain data.

Importing the package registers the environment ids with Gymnasium (the list: :data:`ENV_IDS`)::

    import gymnasium as gym
    import billiards_env  # noqa: F401

    env = gym.make("BilliardsOneBall-v0")  # every id: billiards_env.ENV_IDS
"""
from ._openmp import default_wait_policy
from .kernel_cache import install_prebuilt

default_wait_policy()  # before numba's thread pool starts (see ._openmp)
install_prebuilt()  # before any kernel compiles or loads: the prebuilt kernels, if they fit (see .kernel_cache)

from .registration import ENV_IDS, register_envs  # noqa: E402

register_envs()

__all__ = ["ENV_IDS"]
