"""billiards_env.envs: the Gymnasium environments (one module per scene family) and their configuration.

Registered ids (``import billiards_env`` registers them): ``BilliardsOneBall-v0`` (:class:`OneBallEnv`),
``BilliardsThreeBalls-v0`` (:class:`ThreeBallsEnv`), ``BilliardsRack-v0`` (:class:`RackEnv`). Their defaults
are the YAML files in ``billiards_env/envs/scenes/``; every key is documented in :mod:`.config`.
"""
from .base import RENDER_MODES, BilliardsEnv
from .config import ConfigError, EnvConfig, load_config
from .eight_ball import EightBallEnv
from .nine_ball import NineBallEnv
from .one_ball import OneBallEnv
from .rack import RackEnv
from .three_balls import ThreeBallsEnv

#: Registered id -> environment class (the ids are billiards_env.registration.ENV_IDS).
ENV_CLASSES = {env_id: cls for cls in (OneBallEnv, ThreeBallsEnv, RackEnv, NineBallEnv, EightBallEnv) for env_id in (cls.env_id,)}

__all__ = ["BilliardsEnv", "OneBallEnv", "ThreeBallsEnv", "RackEnv", "EnvConfig", "ConfigError", "load_config",
           "RENDER_MODES", "ENV_CLASSES"]
