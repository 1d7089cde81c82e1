"""Training configs: RL Baselines3 Zoo hyperparameter files plus a ``billiards:`` section for ``agents.train``.

A config file is a YAML mapping. The entry named after the env id is in the RL Zoo format, so
``python -m rl_zoo3.train --algo sac --env BilliardsOneBall-v0 --gym-packages billiards_env
--conf-file configs/train/one_ball_sac.yaml ...`` trains from the same file as it is (the README gives the command;
the zoo knows only ``lin_`` schedules, so a cosine goes in the ``billiards:`` section's ``hyperparams``, which only
``agents.train`` reads)::

    BilliardsOneBall-v0:
      n_timesteps: !!float 1e6
      policy: MlpPolicy
      n_envs: 8
      learning_rate: !!float 1e-3        # or "lin_1e-3"; "cos_3e-3_1e-5" only under billiards.hyperparams
      batch_size: 256
      policy_kwargs: "dict(net_arch=[128, 128])"
      env_kwargs: {action_type: ghost, observation_type: features}   # RL Zoo >= 2.7 reads this
      ...                                # any other constructor argument of the algorithm

    billiards:                           # agents.train only (the RL Zoo ignores other top-level keys)
      hyperparams: {learning_rate: cos_3e-3_1e-5}   # laid over the entry above: what the zoo cannot parse
      algo: sac                          # sac | td3 | ppo | a2c | ddpg
      env_id: BilliardsOneBall-v0        # which entry above to use (default: the only env entry)
      seed: 0
      name: one_ball_sac                 # run folder runs/<name>-<timestamp>/
      max_seconds: 780                   # wall-clock training budget (0 = none)
      eval_freq: 20000                   # env steps between evaluations (EvalCallback)
      n_eval_episodes: 500
      checkpoint_freq: 50000             # env steps between checkpoints
      ...                                # see TrainSettings

Zoo keys understood here: ``n_timesteps``, ``policy``, ``n_envs``, ``env_kwargs``, ``env_wrapper`` (a dotted
name, a list of them, or ``{name: kwargs}`` items), ``normalize`` (bool, dict or "dict(...)" string),
``policy_kwargs`` (dict or "dict(...)" string), ``learning_rate`` / ``clip_range`` (number, ``lin_<x>[_<final>]`` or
``cos_<x>[_<final>]``: :class:`Schedule`, which follows the wall-clock budget too),
``train_freq`` (int or list), ``noise_type`` / ``noise_std`` (action noise), ``monitor_kwargs``,
``frame_stack`` (not supported: an error). Everything else goes to the algorithm's constructor.
"""
from __future__ import annotations

import copy
import importlib
import math
import sys
from dataclasses import asdict, dataclass, field, fields
from pathlib import Path
from typing import Any, Callable, Mapping

import cloudpickle
import yaml

from billiards_env.registration import check_env_id

SECTION = "billiards"
ALGOS = ("sac", "td3", "ppo", "a2c", "ddpg")
OFF_POLICY = ("sac", "td3", "ddpg")
BUDGET_CLOCKS = ("wall", "cpu")
#: Zoo keys consumed by the training script (never passed to the algorithm).
ZOO_META_KEYS = ("n_timesteps", "policy", "n_envs", "env_kwargs", "env_wrapper", "normalize", "monitor_kwargs",
                 "noise_type", "noise_std", "frame_stack", "callback", "vec_env_wrapper")


class TrainConfigError(ValueError):
    """A bad training config: the message names the key and the fix."""


@dataclass
class TrainSettings:
    """The ``billiards:`` section (``agents.train`` settings; every key optional)."""

    algo: str = "sac"
    env_id: str | None = None
    seed: int = 0
    name: str | None = None  #: run folder prefix (default: derived from the config file name)
    run_root: str = "runs"  #: where run folders are created
    max_seconds: float = 0.0  #: wall-clock budget for training (0 = until n_timesteps)
    #: What max_seconds counts: "wall" (elapsed time) or "cpu" (this process's CPU time: comparable runs on a
    #: machine shared with other jobs; equal to wall time on an idle one with torch and numba on one thread).
    budget_clock: str = "wall"
    eval_freq: int = 20_000  #: env steps (all envs together) between evaluations; 0 = no evaluation
    n_eval_episodes: int = 500
    n_eval_envs: int = 10  #: parallel eval envs (batched predictions)
    eval_seed: int = 10_000  #: every evaluation replays the same episodes (seeds eval_seed + k)
    checkpoint_freq: int = 50_000  #: env steps between checkpoints (0 = none)
    checkpoint_seconds: float = 120.0  #: also checkpoint after this many wall seconds (0 = only by steps)
    keep_checkpoints: int = 3  #: model checkpoints kept (the replay buffer: only the latest)
    save_replay_buffer: bool = True  #: off-policy: save the replay buffer with each checkpoint (for --resume)
    torch_threads: int = 1
    device: str = "cpu"
    stop_at_success: float = 0.0  #: stop when an evaluation's success rate reaches this (0 = never)
    progress_bar: bool = True
    log_interval: int = 0  #: SB3 console log interval (episodes for off-policy, rollouts for on-policy; 0 = off)
    verbose: int = 0
    #: Values laid over the env entry for agents.train only: what the RL Zoo cannot parse (its schedules are
    #: ``lin_<x>`` only), e.g. ``{learning_rate: cos_3e-3_3e-5}`` over the entry's constant, so the entry stays
    #: the zoo's verbatim.
    hyperparams: dict[str, Any] = field(default_factory=dict)

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any] | None, source: str) -> "TrainSettings":
        data = dict(data or {})
        known = {f.name for f in fields(cls)}
        unknown = sorted(set(data) - known)
        if unknown:
            raise TrainConfigError(f"{source}: unknown key(s) {unknown} in '{SECTION}:'; allowed: {sorted(known)}")
        s = cls(**data)
        if not isinstance(s.hyperparams, Mapping):
            raise TrainConfigError(f"{source}: {SECTION}.hyperparams: expected a mapping of zoo keys (e.g. "
                                   f"{{learning_rate: cos_3e-3_3e-5}}), got {s.hyperparams!r}")
        s.hyperparams = dict(s.hyperparams)
        if s.budget_clock not in BUDGET_CLOCKS:
            raise TrainConfigError(f"{source}: {SECTION}.budget_clock: unknown {s.budget_clock!r}; use one of "
                                   f"{BUDGET_CLOCKS}")
        if s.algo not in ALGOS:
            raise TrainConfigError(f"{source}: {SECTION}.algo: unknown algorithm {s.algo!r}; use one of {ALGOS}")
        return s


@dataclass
class TrainConfig:
    """A resolved training config: the settings, the env id, the zoo hyperparameters (raw, as in the file)."""

    settings: TrainSettings
    env_id: str
    hyperparams: dict[str, Any]
    source: str = "<dict>"
    extra: dict[str, Any] = field(default_factory=dict)  #: other top-level entries, kept for the run folder

    @property
    def algo(self) -> str:
        return self.settings.algo

    @property
    def n_timesteps(self) -> int:
        return int(float(self.hyperparams.get("n_timesteps", 100_000)))

    @property
    def n_envs(self) -> int:
        return int(self.hyperparams.get("n_envs", 1))

    @property
    def env_kwargs(self) -> dict[str, Any]:
        return dict(self.hyperparams.get("env_kwargs") or {})

    def to_yaml_dict(self) -> dict[str, Any]:
        """The config as a file (zoo entry + ``billiards:`` section) that reproduces this run."""
        out: dict[str, Any] = {self.env_id: copy.deepcopy(self.hyperparams)}
        s = asdict(self.settings)
        s["env_id"] = self.env_id
        out[SECTION] = s
        return out


def load_train_config(path: str | Path | Mapping[str, Any], env_id: str | None = None,
                      overrides: Mapping[str, Any] | None = None,
                      hyper_overrides: Mapping[str, Any] | None = None) -> TrainConfig:
    """Read a config file (or mapping), pick the env entry, apply overrides (``overrides`` for the
    ``billiards:`` section, ``hyper_overrides`` for the zoo entry)."""
    if isinstance(path, Mapping):
        data, source = copy.deepcopy(dict(path)), "<dict>"
    else:
        source = str(path)
        try:
            text = Path(path).read_text()
        except OSError as exc:
            raise TrainConfigError(f"{source}: cannot read the config ({exc.strerror}); see configs/train/") from None
        try:
            data = yaml.safe_load(text) or {}
        except yaml.YAMLError as exc:
            raise TrainConfigError(f"{source}: not valid YAML ({exc})") from None
    if not isinstance(data, Mapping):
        raise TrainConfigError(f"{source}: expected a mapping at the top level")
    settings = TrainSettings.from_mapping(data.get(SECTION), source)
    if overrides:
        settings = TrainSettings.from_mapping({**asdict(settings), **dict(overrides)}, source)
    env_entries = [k for k, v in data.items() if k != SECTION and isinstance(v, Mapping)]
    chosen = env_id or settings.env_id
    if chosen is None:
        if len(env_entries) != 1:
            raise TrainConfigError(f"{source}: {len(env_entries)} env entries {env_entries}; set {SECTION}.env_id "
                                   "or pass --env-id")
        chosen = env_entries[0]
    if chosen not in data:
        raise TrainConfigError(f"{source}: no entry for env {chosen!r}; entries: {env_entries}")
    try:
        check_env_id(chosen)
    except ValueError as exc:
        raise TrainConfigError(f"{source}: {exc}") from None
    hyper = copy.deepcopy(dict(data[chosen]))
    hyper.update(copy.deepcopy(settings.hyperparams))  # agents.train's own values (a cosine the zoo cannot read)
    if hyper_overrides:
        for k, v in hyper_overrides.items():
            if k == "env_kwargs" and isinstance(v, Mapping):
                hyper["env_kwargs"] = {**dict(hyper.get("env_kwargs") or {}), **dict(v)}
            else:
                hyper[k] = v
    if "frame_stack" in hyper:
        raise TrainConfigError(f"{source}: frame_stack is not supported by agents.train (the observation is the "
                               "full table state); remove it")
    settings.env_id = chosen
    extra = {k: v for k, v in data.items() if k not in (SECTION, chosen)}
    return TrainConfig(settings, chosen, hyper, source, extra)


# --- zoo value parsing -----------------------------------------------------------------------------------------

def _eval_kwargs_string(text: str, key: str) -> Any:
    """Evaluate a zoo ``"dict(...)"`` string with only ``dict``, ``nn``/``th`` (torch) and numbers in scope."""
    import torch as th
    from torch import nn

    try:
        return eval(text, {"__builtins__": {}}, {"dict": dict, "nn": nn, "th": th, "list": list, "tuple": tuple,
                                                  "True": True, "False": False, "None": None})
    except Exception as exc:  # noqa: BLE001 - report any parse error with the key
        raise TrainConfigError(f"{key}: cannot evaluate {text!r} ({exc}); write e.g. \"dict(net_arch=[256, 256])\"")


def resolve_class(name: str, key: str) -> Any:
    """A class from a dotted name (``gymnasium.wrappers.TimeAwareObservation``)."""
    module, _, attr = name.rpartition(".")
    if not module:
        raise TrainConfigError(f"{key}: {name!r} is not a dotted name (module.Class)")
    try:
        return getattr(importlib.import_module(module), attr)
    except (ImportError, AttributeError) as exc:
        raise TrainConfigError(f"{key}: cannot import {name!r} ({exc})") from None


def wrapper_factory(spec: Any) -> Callable[[Any], Any] | None:
    """The zoo ``env_wrapper`` value as one callable ``env -> wrapped env`` (None if no wrapper)."""
    if spec in (None, "", []):
        return None
    items = spec if isinstance(spec, list) else [spec]
    chain: list[tuple[Any, dict[str, Any]]] = []
    for item in items:
        if isinstance(item, str):
            chain.append((resolve_class(item, "env_wrapper"), {}))
        elif isinstance(item, Mapping) and len(item) == 1:
            (name, kwargs), = item.items()
            chain.append((resolve_class(name, "env_wrapper"), dict(kwargs or {})))
        else:
            raise TrainConfigError(f"env_wrapper: expected a dotted class name or {{name: kwargs}}, got {item!r}")

    def wrap(env: Any) -> Any:
        for cls, kwargs in chain:
            env = cls(env, **kwargs)
        return env

    return wrap


#: Schedule shapes of ``<shape>_<initial>[_<final>]`` values (``lin_3e-3``, ``cos_3e-3_1e-5``).
SCHEDULES = ("lin", "cos")


class Schedule:
    """A learning-rate (or clip-range) schedule from ``initial`` to ``final`` over the run: ``lin`` (straight line)
    or ``cos`` (half a cosine: flat at both ends). SB3 calls it with the progress remaining (1 -> 0, by steps);
    :class:`agents.callbacks.TrainingClock` also sets :attr:`clock_remaining` (1 -> 0 over a wall-clock budget),
    and the schedule follows whichever is further along, so it reaches ``final`` when the budget runs out."""

    def __init__(self, shape: str, initial: float, final: float = 0.0) -> None:
        if shape not in SCHEDULES:
            raise TrainConfigError(f"schedule: unknown shape {shape!r}; use one of {SCHEDULES}")
        self.shape, self.initial, self.final = shape, float(initial), float(final)
        self.clock_remaining = 1.0  #: set by the training clock (1 at the start, 0 when the budget is spent)

    def __call__(self, progress_remaining: float) -> float:
        q = min(max(min(float(progress_remaining), self.clock_remaining), 0.0), 1.0)
        w = q if self.shape == "lin" else 0.5 * (1.0 - math.cos(math.pi * q))
        return self.final + (self.initial - self.final) * w

    def __repr__(self) -> str:
        return f"Schedule({self.shape!r}, {self.initial}, {self.final})"


# A model saved by SB3 pickles its learning-rate schedule. Pickled by value (cloudpickle, as SB3 saves), a
# :class:`Schedule` loads where this training code is not importable: ``SAC.load(path)`` in any script.
cloudpickle.register_pickle_by_value(sys.modules[__name__])


def linear_schedule(initial: float) -> Callable[[float], float]:
    """``lin_<initial>``: from ``initial`` down to 0 (RL Zoo's linear schedule)."""
    return Schedule("lin", initial)


def parse_schedule(key: str, value: str) -> Schedule:
    """A ``<shape>_<initial>[_<final>]`` string (``lin_1e-3``, ``cos_3e-3_1e-5``) as a :class:`Schedule`."""
    shape, *numbers = value.split("_")
    try:
        if shape not in SCHEDULES or len(numbers) not in (1, 2):
            raise ValueError
        return Schedule(shape, *(float(x) for x in numbers))
    except ValueError:
        raise TrainConfigError(f"{key}: unknown schedule {value!r}; use a number, 'lin_<initial>[_<final>]' or "
                               "'cos_<initial>[_<final>]' (e.g. 'cos_3e-3_1e-5')") from None


@dataclass
class AlgoSetup:
    """Everything the zoo entry means, split into what builds the envs and what builds the algorithm."""

    policy: Any
    algo_kwargs: dict[str, Any]
    n_envs: int
    n_timesteps: int
    env_kwargs: dict[str, Any]
    wrapper: Callable[[Any], Any] | None
    normalize: dict[str, Any] | None
    monitor_kwargs: dict[str, Any]
    noise: tuple[str, float] | None


def parse_hyperparams(cfg: TrainConfig) -> AlgoSetup:
    """Turn the zoo entry into constructor arguments (schedules, policy_kwargs, noise, wrappers...)."""
    h = copy.deepcopy(cfg.hyperparams)
    for key in ("callback", "vec_env_wrapper"):
        if h.get(key):
            raise TrainConfigError(f"{cfg.source}: {key} is not supported by agents.train; remove it")
        h.pop(key, None)
    policy = h.pop("policy", "MlpPolicy")
    n_envs = int(h.pop("n_envs", 1))
    n_timesteps = int(float(h.pop("n_timesteps", 100_000)))
    env_kwargs = dict(h.pop("env_kwargs", None) or {})
    wrapper = wrapper_factory(h.pop("env_wrapper", None))
    normalize = h.pop("normalize", None)
    norm_kwargs: dict[str, Any] | None = None
    if isinstance(normalize, str):
        norm_kwargs = _eval_kwargs_string(normalize, "normalize")
    elif isinstance(normalize, Mapping):
        norm_kwargs = dict(normalize)
    elif normalize:
        norm_kwargs = {}
    if norm_kwargs is not None and "gamma" in h:
        norm_kwargs.setdefault("gamma", h["gamma"])
    monitor_kwargs = h.pop("monitor_kwargs", None) or {}
    if isinstance(monitor_kwargs, str):
        monitor_kwargs = _eval_kwargs_string(monitor_kwargs, "monitor_kwargs")
    noise = None
    if h.get("noise_type") is not None:
        noise = (str(h.pop("noise_type")).strip(), float(h.pop("noise_std", 0.1)))
    h.pop("noise_type", None)
    h.pop("noise_std", None)
    for key in ("learning_rate", "clip_range", "clip_range_vf"):
        v = h.get(key)
        if isinstance(v, str):
            h[key] = parse_schedule(key, v)
        elif isinstance(v, (int, float)) and not isinstance(v, bool):
            h[key] = float(v)
    for key in ("policy_kwargs", "replay_buffer_kwargs"):
        if isinstance(h.get(key), str):
            h[key] = _eval_kwargs_string(h[key], key)
    if isinstance(h.get("train_freq"), list):
        h["train_freq"] = tuple(h["train_freq"])
    for key in ("buffer_size", "batch_size", "learning_starts", "gradient_steps", "n_steps", "n_epochs",
                "policy_delay"):
        if isinstance(h.get(key), float) and float(h[key]).is_integer():
            h[key] = int(h[key])
    return AlgoSetup(policy, h, n_envs, n_timesteps, env_kwargs, wrapper, norm_kwargs, dict(monitor_kwargs), noise)


__all__ = ["SECTION", "ALGOS", "OFF_POLICY", "TrainConfigError", "TrainSettings", "TrainConfig",
           "load_train_config", "parse_hyperparams", "wrapper_factory", "resolve_class", "AlgoSetup", "Schedule",
           "SCHEDULES", "linear_schedule", "parse_schedule"]
