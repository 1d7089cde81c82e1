"""An RLlib checkpoint as a player of :mod:`agents.evaluate`: the RLModule restored on the CPU, deterministic actions.

``python -m agents.evaluate --players runs/rllib_one_ball_ppo-<stamp> runs/one_ball_sac-<stamp> search geometric``
puts an RLlib agent, an SB3 agent and the baselines in one table. A player path is an RLlib run folder of
``agents.rllib`` (its ``best_checkpoint/``, else ``final_checkpoint/``, else the latest periodic checkpoint) or any
RLlib checkpoint folder (the one holding ``rllib_checkpoint.json``, from ``Algorithm.save_to_path``). The env is
the checkpoint's own (``billiards_env:<id>`` and its ``env_config``) unless ``--env`` says otherwise; a self-play
checkpoint plays the single-agent game env (``Billiards9Ball-v0``: against its built-in opponent) with the
module ``shared`` (``separate``: ``player_0``).

Acting: the observation goes through the module's ``forward_inference``; the action is the mode of its action
distribution (``to_deterministic()``), then as RLlib's default module-to-env connector does, unsquashed from
[-1, 1] to the action space (``normalize_actions``, RLlib's default) or clipped (``clip_actions``). That is the
whole inference path of the default connector pipelines for these envs' flat ``Box`` observations; a checkpoint
with connectors of its own (an observation filter, frame stacking) or a recurrent module is refused with a
message rather than played wrongly. Importing this module does not import Ray; restoring does (``[rllib]``
extra), and needs no running Ray.
"""
from __future__ import annotations

import json
import pickle
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .config import ENV_PREFIX, SELF_PLAY_PREFIX

CHECKPOINT_FILE = "rllib_checkpoint.json"
#: Where an Algorithm checkpoint keeps its modules (learner group -> learner -> multi-RLModule -> module id).
MODULES_DIR = Path("learner_group") / "learner" / "rl_module"
#: Run-folder checkpoints in the order a player prefers them.
RUN_CHECKPOINTS = ("best_checkpoint", "final_checkpoint")


def is_checkpoint(path: str | Path) -> bool:
    return (Path(path) / CHECKPOINT_FILE).is_file()


def is_rllib_run(path: str | Path) -> bool:
    run = Path(path) / "run.json"
    if not run.is_file():
        return False
    try:
        return json.loads(run.read_text()).get("framework") == "rllib"
    except (OSError, ValueError):
        return False


def is_rllib_path(path: str | Path) -> bool:
    """Whether ``path`` is an RLlib checkpoint or an ``agents.rllib`` run folder (no Ray import)."""
    return is_checkpoint(path) or is_rllib_run(path)


def resolve_checkpoint(path: str | Path) -> tuple[Path, Path | None]:
    """``(checkpoint folder, run folder or None)`` for a run folder or a checkpoint folder."""
    p = Path(path)
    if is_checkpoint(p):
        for run in (p.parent, p.parent.parent):
            if is_rllib_run(run):
                return p, run
        return p, None
    if not p.is_dir():
        raise FileNotFoundError(f"{p}: no such RLlib run folder or checkpoint")
    for name in RUN_CHECKPOINTS:
        if is_checkpoint(p / name):
            return p / name, p
    latest = p / "checkpoints" / "latest.json"
    if latest.is_file():
        return p / "checkpoints" / json.loads(latest.read_text())["checkpoint"], p
    raise FileNotFoundError(f"{p}: no best_checkpoint/, final_checkpoint/ or checkpoints/latest.json in this run folder")


def resume_checkpoint(path: str | Path) -> tuple[Path, Path | None]:
    """The checkpoint to continue training from: the newest periodic one of a run folder (``latest.json``), else
    its final one, or the checkpoint folder given."""
    p = Path(path)
    if not is_checkpoint(p):
        latest = p / "checkpoints" / "latest.json"
        if latest.is_file():
            return p / "checkpoints" / json.loads(latest.read_text())["checkpoint"], p
        if is_checkpoint(p / "final_checkpoint"):
            return p / "final_checkpoint", p
    return resolve_checkpoint(p)


def checkpoint_config(checkpoint: str | Path) -> dict[str, Any]:
    """The AlgorithmConfig (as a dict) an Algorithm checkpoint was made with (unpickling it imports Ray)."""
    with open(Path(checkpoint) / "class_and_ctor_args.pkl", "rb") as f:
        data = pickle.load(f)  # noqa: S301 - a checkpoint is trusted code by design (RLlib pickles it too)
    config = data["ctor_args_and_kwargs"][0][0]
    return config if isinstance(config, dict) else config.to_dict()


#: Options of the native vector env, not of a single env (dropped when a single env is made from a checkpoint).
VECTOR_ONLY_KEYS = ("threads", "autoreset_mode", "render_env", "num_envs")


def single_env_kwargs(kwargs: dict[str, Any]) -> dict[str, Any]:
    """``kwargs`` without the vector-env-only options: what ``gym.make(id, **...)`` takes."""
    return {k: v for k, v in kwargs.items() if k not in VECTOR_ONLY_KEYS}


def env_of(config: dict[str, Any]) -> tuple[str | None, dict[str, Any], bool]:
    """``(env id, env kwargs, self_play)`` from a checkpoint's config (None if the env is not one of ours)."""
    env = str(config.get("env") or "")
    kwargs = single_env_kwargs(dict(config.get("env_config") or {}))
    if env.startswith(SELF_PLAY_PREFIX):
        return env[len(SELF_PLAY_PREFIX):], kwargs, True
    if env.startswith(ENV_PREFIX):
        return env[len(ENV_PREFIX):], kwargs, False
    return (env or None), kwargs, False


@dataclass
class RLlibPolicy:
    """An RLModule acting deterministically: ``policy(obs) -> action`` for one unbatched observation (a callable
    ``obs -> action``: game envs accept it as an opponent, acting in their own action type)."""

    module: Any
    action_space: Any
    normalize_actions: bool = True
    clip_actions: bool = False
    module_id: str = "default_policy"
    info: dict[str, Any] = field(default_factory=dict)  #: env id, env kwargs, algo, checkpoint

    def __post_init__(self) -> None:
        import torch

        if self.module.is_stateful():
            raise ValueError(f"module {self.module_id!r} is recurrent (stateful); the evaluation player plays "
                             "feed-forward modules only")
        self._torch = torch
        self._dist_cls = self.module.get_inference_action_dist_cls()
        self.module.eval()

    def __call__(self, obs: Any) -> np.ndarray:
        from ray.rllib.core.columns import Columns
        from ray.rllib.utils.spaces.space_utils import clip_action, unsquash_action

        torch = self._torch
        x = torch.as_tensor(np.asarray(obs, dtype=np.float32)[None])
        with torch.no_grad():
            out = self.module.forward_inference({Columns.OBS: x})
            if Columns.ACTIONS in out:
                action = out[Columns.ACTIONS]
            else:
                action = self._dist_cls.from_logits(out[Columns.ACTION_DIST_INPUTS]).to_deterministic().sample()
        a = np.asarray(action[0].cpu().numpy(), dtype=np.float32)
        if self.normalize_actions:
            return unsquash_action(a, self.action_space)
        if self.clip_actions:
            return clip_action(a, self.action_space)
        return a

    @classmethod
    def from_checkpoint(cls, checkpoint: str | Path, module_id: str | None = None) -> "RLlibPolicy":
        """Restore the module ``module_id`` (default: the only one, else ``shared``, else ``player_0``)."""
        from ray.rllib.core.rl_module.rl_module import RLModule

        ckpt = Path(checkpoint).resolve()  # RLlib reads checkpoints through pyarrow: an absolute path, not a URI
        config = checkpoint_config(ckpt)
        for key in ("_env_to_module_connector", "_module_to_env_connector"):
            if config.get(key) is not None:
                raise ValueError(f"{ckpt}: the run used a custom {key.strip('_')} (observation filters, frame "
                                 "stacking...); the evaluation player applies the default pipeline only")
        root = ckpt / MODULES_DIR
        ids = sorted(p.name for p in root.iterdir() if p.is_dir()) if root.is_dir() else []
        if not ids:
            raise FileNotFoundError(f"{ckpt}: no RLModule under {MODULES_DIR} (is this an Algorithm checkpoint?)")
        if module_id is None:
            module_id = ids[0] if len(ids) == 1 else next((m for m in ("shared", "player_0") if m in ids), ids[0])
        if module_id not in ids:
            raise ValueError(f"{ckpt}: no module {module_id!r}; modules: {ids}")
        module = RLModule.from_checkpoint(root / module_id)
        env_id, env_kwargs, self_play = env_of(config)
        info = {"env_id": env_id, "env_kwargs": env_kwargs, "self_play": self_play, "checkpoint": str(ckpt),
                "algo": config.get("algo_class").__name__ if isinstance(config.get("algo_class"), type) else None}
        return cls(module, module.action_space, bool(config.get("normalize_actions", True)),
                   bool(config.get("clip_actions", False)), module_id, info)

    @classmethod
    def from_algorithm(cls, algo: Any, module_id: str | None = None) -> "RLlibPolicy":
        """The current weights of a running algorithm (for evaluations during training). The driver's copy is
        used: the local learner's module (num_learners=0) or the local env runner's (synced every iteration)."""
        c = algo.config
        if module_id is None:
            module_id = "default_policy" if not c.is_multi_agent else sorted(c.policies)[0]
        module = algo.get_module(module_id)
        if module is None:  # pragma: no cover - remote learners and no local env runner
            raise RuntimeError("the algorithm has no module in this process; evaluate a saved checkpoint instead")
        return cls(module, module.action_space, bool(c.normalize_actions), bool(c.clip_actions), module_id)


def rllib_player(path: str | Path, env_id: str | None = None, label: str | None = None,
                 module_id: str | None = None) -> Any:
    """An RLlib checkpoint or run folder as a :class:`agents.player_spec.PlayerSpec` (deterministic actions)."""
    from ..player_spec import PlayerSpec, env_factory

    ckpt, run_dir = resolve_checkpoint(path)
    policy = RLlibPolicy.from_checkpoint(ckpt, module_id)
    env_kwargs = dict(policy.info["env_kwargs"])
    if run_dir is not None:
        env_json = run_dir / "env.json"
        if env_json.is_file():
            env_kwargs = dict(json.loads(env_json.read_text()).get("kwargs") or {})
    env_id = env_id or policy.info["env_id"]
    if env_id is None:
        raise ValueError(f"{path}: the checkpoint does not name a billiards env; give --env")
    name = label or (run_dir.name if run_dir is not None else ckpt.name)
    return PlayerSpec(name, "model", env_factory(env_id, env_kwargs), lambda env, obs: policy(obs),
                      run_dir=run_dir, model_path=ckpt, env_id=env_id, env_kwargs=env_kwargs)


__all__ = ["RLlibPolicy", "rllib_player", "is_rllib_path", "is_rllib_run", "is_checkpoint", "resolve_checkpoint",
           "resume_checkpoint", "checkpoint_config", "env_of", "single_env_kwargs", "VECTOR_ONLY_KEYS"]
