"""Build an RLlib ``Algorithm`` from an :class:`~agents.rllib.config.RLlibConfig`, and start or join Ray.

The env reaches the env runners by name, so nothing of this repository has to be pickled for it:

- a single-agent id goes to RLlib as ``"billiards_env:<id>"``; Gymnasium imports ``billiards_env`` (which
  registers the ids) in each env runner before ``gym.make_vec(id, num_envs, vectorization_mode, **env_kwargs)``,
  and with ``gym_env_vectorize_mode: vector_entry_point`` (the default here) that is the package's native vector
  env (:mod:`billiards_env.envs.vector`: one compiled physics call steps every table of the runner);
- a self-play game is registered with Ray's env registry (:mod:`.selfplay`).

Code of ``agents/`` that runs in the actors (the success metric below, the self-play policy mapping) is shipped to
them with Ray's ``runtime_env={"py_modules": [agents/]}``, so cluster nodes need only the installed package
(``pip install "billiards_env[rllib]"``), not this repository.
"""
from __future__ import annotations

import os
import warnings
from pathlib import Path
from typing import Any

from .config import ENV_PREFIX, RLlibConfig, RLlibConfigError

AGENTS_DIR = Path(__file__).resolve().parent.parent

try:  # the callback base class (only when Ray is installed: this module is imported by the RLlib path alone)
    from ray.rllib.callbacks.callbacks import RLlibCallback
except ImportError:  # pragma: no cover - without Ray nothing here is used
    RLlibCallback = object  # type: ignore[assignment,misc]


class SuccessMetrics(RLlibCallback):  # type: ignore[misc,valid-type]
    """Logs each finished training episode's ``info["is_success"]`` (the env's success: pocketed, cleared, won)
    as ``env_runners/is_success`` (mean over the last 1000 episodes of each runner)."""

    def on_episode_end(self, *, episode: Any, metrics_logger: Any = None, **kwargs: Any) -> None:
        if metrics_logger is None or not hasattr(episode, "get_infos"):
            return
        try:
            info = episode.get_infos(-1)
        except (IndexError, KeyError, ValueError):  # pragma: no cover - an episode without infos
            return
        if isinstance(info, dict) and "is_success" in info:
            metrics_logger.log_value("is_success", float(bool(info["is_success"])), reduce="mean", window=1000)


def init_ray(address: str | None = None, quiet: bool = False) -> bool:
    """Start a local Ray with this machine's CPUs (``address=None``) or join a running cluster (``"auto"``,
    ``"ray://head:10001"``); ships ``agents/`` to the workers. Returns whether this call started Ray (then the
    caller shuts it down). Ray has no local mode any more: env runners are always separate processes."""
    import ray

    if ray.is_initialized():
        return False
    kwargs: dict[str, Any] = {
        "runtime_env": {"py_modules": [str(AGENTS_DIR)], "excludes": ["__pycache__", "*.pyc", "README.md"]},
        "include_dashboard": False,
        "log_to_driver": not quiet,
        "logging_level": "ERROR" if quiet else "WARNING",
    }
    if address:
        try:
            ray.init(address=address, **kwargs)
        except ConnectionError as exc:  # no cluster there: one line instead of Ray's traceback
            where = "on this node" if address == "auto" else f"at {address}"
            raise RLlibConfigError(
                f"--address {address}: no running Ray cluster {where} ({str(exc).split('. ')[0]}). Start one "
                "(`ray start --head` on the head node, `ray start --address=<head-ip>:6379` on the others; README, "
                "'On a Ray cluster'), or leave --address out to train on a local Ray with this machine's CPUs"
            ) from None
    else:  # "local": a new instance even where `ray start` left a cluster (which plain ray.init() would join)
        ray.init(address="local", num_cpus=os.cpu_count() or 1, **kwargs)
    return True


def env_descriptor(cfg: RLlibConfig) -> str:
    """What RLlib is given as ``env``: ``billiards_env:<id>``, or the self-play env's registered name."""
    from billiards_env.registration import ENV_IDS

    s = cfg.settings
    if s.env_id not in ENV_IDS:
        raise RLlibConfigError(f"billiards.env_id: unknown id {s.env_id!r}; registered ids: {', '.join(ENV_IDS)}")
    if s.self_play:
        from . import selfplay

        return selfplay.register(s.env_id)
    return ENV_PREFIX + s.env_id


def check_env(cfg: RLlibConfig) -> None:
    """Make the env once in this process, so a bad env option fails here with the env's own message
    (ConfigError names the key) instead of inside a remote env runner."""
    s = cfg.settings
    if s.self_play:
        from . import selfplay

        env = selfplay.make_env(s.env_id, s.env_kwargs)
    else:
        import gymnasium as gym

        import billiards_env  # noqa: F401

        if cfg.vectorize_mode == "vector_entry_point":
            env = gym.make_vec(s.env_id, 1, vectorization_mode="vector_entry_point", **s.env_kwargs)
        else:
            env = gym.make(s.env_id, **s.env_kwargs)
    env.close()


def algorithm_config(cfg: RLlibConfig) -> Any:
    """The ``AlgorithmConfig`` of ``cfg``: RLlib's defaults for the algorithm, the env and seed of the
    ``billiards:`` section, then every section of the file (``config.<section>(**kwargs)``)."""
    from ray.tune.registry import get_trainable_cls

    s = cfg.settings
    config = get_trainable_cls(s.algo).get_default_config()
    config.environment(env=env_descriptor(cfg), env_config=dict(s.env_kwargs))
    config.env_runners(gym_env_vectorize_mode=cfg.vectorize_mode)
    config.debugging(seed=int(s.seed))
    config.reporting(min_sample_timesteps_per_iteration=0)
    if s.self_play:
        from . import selfplay

        modules, mapping = selfplay.policies(s.self_play)
        config.multi_agent(policies=modules, policy_mapping_fn=mapping)
    else:
        config.callbacks(SuccessMetrics)
    for name, kwargs in cfg.sections.items():
        try:
            getattr(config, name)(**kwargs)
        except TypeError as exc:
            raise RLlibConfigError(f"{cfg.source}: rllib.{name}: {exc}; see RLlib's AlgorithmConfig.{name}()") from None
    if cfg.vectorize_mode == "vector_entry_point" and "threads" not in s.env_kwargs:
        # The native vector env's physics threads: the runner's CPUs. numba's thread pool left to choose would
        # spin beside torch's in the same process: measured 4x slower sampling in an env runner.
        cpus = float(config.num_cpus_per_env_runner or 1)
        config.environment(env_config={**s.env_kwargs, "threads": max(1, int(cpus))})
    return config


def cpus_needed(config: Any) -> float:
    """CPUs the algorithm's actors reserve: env runners and learner actors (the driver reserves none)."""
    runners = int(config.num_env_runners or 0) * float(config.num_cpus_per_env_runner or 0)
    per_learner = config.num_cpus_per_learner
    if per_learner == "auto":
        per_learner = 0 if config.num_gpus_per_learner else 1
    return runners + int(config.num_learners or 0) * float(per_learner)


def check_resources(config: Any, local: bool) -> None:
    """Refuse (local Ray) or warn (cluster: the autoscaler may add nodes) when the actors ask for more CPUs than
    Ray has: otherwise they would wait for resources for ever."""
    import ray

    have = float(ray.cluster_resources().get("CPU", 0.0))
    need = cpus_needed(config)
    if need <= have:
        return
    msg = (f"the env runners and learners reserve {need:g} CPUs but Ray has {have:g} "
           f"(num_env_runners={config.num_env_runners} x num_cpus_per_env_runner={config.num_cpus_per_env_runner}, "
           f"num_learners={config.num_learners}); lower --num-env-runners / --num-learners, set "
           "env_runners.num_cpus_per_env_runner to a fraction (e.g. 0.5), or join a cluster with --address")
    if local:
        raise RLlibConfigError(msg)
    warnings.warn(msg + " (waiting for the cluster to provide them)", stacklevel=2)


def build_algorithm(cfg: RLlibConfig, local: bool = True) -> Any:
    """Check the env and the resources, then build the algorithm (its env runners and learners start)."""
    check_env(cfg)
    config = algorithm_config(cfg)
    check_resources(config, local)
    return config.build_algo()


__all__ = ["SuccessMetrics", "init_ray", "env_descriptor", "check_env", "algorithm_config", "cpus_needed",
           "check_resources", "build_algorithm", "AGENTS_DIR"]
