"""billiards_env.envs: the Gymnasium environments (one module per scene family) and their configuration.

Registered ids (``import billiards_env`` registers them; the list is :data:`billiards_env.registration.ENVS`):
``BilliardsOneBall-v0`` (:class:`OneBallEnv`), ``BilliardsThreeBalls-v0`` (:class:`ThreeBallsEnv`),
``BilliardsRack-v0`` (:class:`RackEnv`), and one per registered game (:data:`billiards_env.games.GAMES`):
``Billiards9Ball-v0`` (:class:`NineBallEnv`), ``Billiards8Ball-v0`` (:class:`EightBallEnv`). Their defaults are
the YAML files in ``billiards_env/envs/scenes/``; every key is documented in :mod:`.config`.
"""
from gymnasium.envs.registration import load_env_creator

from billiards_env.registration import ENVS

from .base import RENDER_MODES, BilliardsEnv
from .config import ConfigError, EnvConfig, UnknownKeyError, load_config
from .eight_ball import EightBallEnv
from .nine_ball import NineBallEnv
from .one_ball import OneBallEnv
from .rack import RackEnv
from .three_balls import ThreeBallsEnv

#: Registered id -> environment class (the ids are billiards_env.registration.ENV_IDS).
ENV_CLASSES: dict[str, type[BilliardsEnv]] = {env_id: load_env_creator(entry) for env_id, entry in ENVS.items()}

__all__ = ["BilliardsEnv", "OneBallEnv", "ThreeBallsEnv", "RackEnv", "NineBallEnv", "EightBallEnv", "EnvConfig",
           "ConfigError", "UnknownKeyError", "load_config", "RENDER_MODES", "ENV_CLASSES"]
