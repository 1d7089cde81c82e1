"""RLlib training configs: RLlib's own ``AlgorithmConfig`` sections plus a ``billiards:`` section for ``agents.rllib``.

A config file is a YAML mapping with two entries::

    rllib:                               # each key is an AlgorithmConfig method, its mapping that method's kwargs
      env_runners:                       #   -> config.env_runners(num_env_runners=2, ...)
        num_env_runners: 2               # sampling actors (0: sample in the driver process)
        num_envs_per_env_runner: 16      # envs stepped together in each env runner
        gym_env_vectorize_mode: vector_entry_point   # the native vector env (default); or sync / async
      learners: {num_learners: 0}        # 0: learn in the driver; N: N learner actors (data parallel)
      training: {lr: 0.001, gamma: 0.0, train_batch_size_per_learner: 4000, minibatch_size: 256}
      rl_module: {model_config: {fcnet_hiddens: [64, 64]}}

    billiards:                           # agents.rllib only (see RLlibSettings)
      algo: PPO                          # PPO | APPO | IMPALA | SAC
      env_id: BilliardsOneBall-v0        # any registered id
      env_kwargs: {action_type: ghost}   # env options: gym.make(env_id, **env_kwargs)
      self_play: null                    # games: "shared" (one policy for both seats) or "separate" (one each)
      timesteps: 2000000                 # stop at this many env steps (also: iterations, max_seconds)
      ...

Every section name is a method of RLlib's ``AlgorithmConfig`` (``environment``, ``env_runners``, ``learners``,
``training``, ``rl_module``, ``multi_agent``, ``evaluation``, ``reporting``, ``checkpointing``, ``debugging``,
``fault_tolerance``, ``resources``, ``callbacks``, ``framework``), so every RLlib option is reachable under the
name RLlib documents. The env (``environment.env`` / ``env_config``) and, with ``self_play``, the policies come
from the ``billiards:`` section. YAML 1.1 reads ``1e-3`` as a string: such strings are read as numbers here.
"""
from __future__ import annotations

import copy
import re
from dataclasses import asdict, dataclass, field, fields
from pathlib import Path
from typing import Any, Mapping

import yaml

from billiards_env.registration import check_env_id

SECTION = "billiards"
RLLIB = "rllib"
#: Online algorithms of RLlib that take the envs' continuous (Box) actions.
ALGOS = ("PPO", "APPO", "IMPALA", "SAC")
#: AlgorithmConfig methods a config file may call.
CONFIG_SECTIONS = ("environment", "env_runners", "learners", "training", "rl_module", "multi_agent", "evaluation",
                   "reporting", "checkpointing", "debugging", "fault_tolerance", "resources", "callbacks",
                   "framework")
SELF_PLAY = ("shared", "separate")
#: Gymnasium vectorization modes RLlib's env runners accept (``gym_env_vectorize_mode``).
VECTORIZE_MODES = ("vector_entry_point", "sync", "async")
#: Prefix of the env name a checkpoint records for a single-agent env (Gymnasium imports the module first).
ENV_PREFIX = "billiards_env:"
#: Prefix of the registered name of a self-play (two-player) env.
SELF_PLAY_PREFIX = "billiards_selfplay:"

_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)$")


class RLlibConfigError(ValueError):
    """A bad RLlib training config: the message names the key and the fix."""


@dataclass
class RLlibSettings:
    """The ``billiards:`` section (every key optional)."""

    algo: str = "PPO"
    env_id: str = "BilliardsOneBall-v0"
    env_kwargs: dict[str, Any] = field(default_factory=dict)  #: env options (``gym.make(env_id, **env_kwargs)``)
    self_play: str | None = None  #: games only: "shared" (one policy plays both seats) or "separate"
    seed: int = 0
    name: str | None = None  #: run folder prefix (default: the config file's name, else rllib_<env>_<algo>)
    run_root: str = "runs"
    timesteps: float = 0  #: stop after this many env steps (0 = no limit)
    iterations: int = 0  #: stop after this many training iterations (0 = no limit)
    max_seconds: float = 0.0  #: wall-clock budget (0 = none)
    checkpoint_every: int = 10  #: iterations between checkpoints (0 = only at the end)
    checkpoint_seconds: float = 120.0  #: also checkpoint after this many wall seconds (0 = only by iterations)
    keep_checkpoints: int = 2
    eval_every: int = 0  #: iterations between evaluations with the project's evaluation (0 = none)
    eval_episodes: int = 200
    eval_seed: int = 10_000  #: every evaluation replays the same tables (seeds eval_seed + k)
    stop_at_success: float = 0.0  #: stop when an evaluation's success rate reaches this (0 = never)
    address: str | None = None  #: Ray cluster to join ("auto", "ray://host:10001"); None starts a local Ray
    torch_threads: int = 1  #: torch threads of the driver (the local learner and the evaluations)
    verbose: int = 1

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any] | None, source: str) -> "RLlibSettings":
        data = dict(data or {})
        known = {f.name for f in fields(cls)}
        unknown = sorted(set(data) - known)
        if unknown:
            raise RLlibConfigError(f"{source}: unknown key(s) {unknown} in '{SECTION}:'; allowed: {sorted(known)}")
        s = cls(**{k: _numbers(v) for k, v in data.items()})
        s.algo = normalize_algo(s.algo, source)
        s.env_kwargs = dict(s.env_kwargs or {})
        if s.self_play is not None and s.self_play not in SELF_PLAY:
            raise RLlibConfigError(f"{source}: {SECTION}.self_play: {s.self_play!r}; use one of {SELF_PLAY} or null")
        for key in ("timesteps", "iterations", "max_seconds", "checkpoint_every", "checkpoint_seconds",
                    "eval_every", "eval_episodes"):
            if float(getattr(s, key)) < 0:
                raise RLlibConfigError(f"{source}: {SECTION}.{key} must be >= 0, got {getattr(s, key)}")
        return s


def normalize_algo(name: str, source: str = "algo") -> str:
    """RLlib's spelling of an algorithm name (case-insensitive), or a clear error."""
    for a in ALGOS:
        if str(name).upper() == a:
            return a
    raise RLlibConfigError(f"{source}: unknown or unsupported algorithm {name!r}; use one of {ALGOS} (the envs' "
                           "actions are continuous: DQN needs discrete actions; BC, CQL, IQL, MARWIL learn offline)")


@dataclass
class RLlibConfig:
    """A resolved config: the ``billiards:`` settings and the AlgorithmConfig sections (raw, as in the file)."""

    settings: RLlibSettings
    sections: dict[str, dict[str, Any]]
    source: str = "<dict>"

    @property
    def env_id(self) -> str:
        return self.settings.env_id

    @property
    def algo(self) -> str:
        return self.settings.algo

    def section(self, name: str) -> dict[str, Any]:
        return dict(self.sections.get(name) or {})

    @property
    def vectorize_mode(self) -> str:
        """The vectorization the env runners use: the native vector env unless the file says otherwise (a
        self-play env has no native vector env: sync)."""
        default = "sync" if self.settings.self_play else "vector_entry_point"
        return str(self.section("env_runners").get("gym_env_vectorize_mode", default))

    def to_yaml_dict(self) -> dict[str, Any]:
        """The config as a file that reproduces this run."""
        return {RLLIB: copy.deepcopy(self.sections), SECTION: asdict(self.settings)}


def _numbers(value: Any) -> Any:
    """Strings that spell a number in exponent form (``1e-3``, which YAML 1.1 leaves a string) as floats."""
    if isinstance(value, str) and _NUMBER.match(value.strip()):
        return float(value)
    if isinstance(value, Mapping):
        return {k: _numbers(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_numbers(v) for v in value]
    return value


def load_rllib_config(path: str | Path | Mapping[str, Any] | None = None,
                      overrides: Mapping[str, Any] | None = None,
                      section_overrides: Mapping[str, Mapping[str, Any]] | None = None) -> RLlibConfig:
    """Read a config file or mapping (None: all defaults), then apply ``overrides`` (``billiards:`` keys) and
    ``section_overrides`` (``{section: {key: value}}``, merged key by key)."""
    if path is None:
        data, source = {}, "<defaults>"
    elif isinstance(path, Mapping):
        data, source = copy.deepcopy(dict(path)), "<dict>"
    elif not isinstance(path, (str, Path)):
        raise RLlibConfigError(f"expected a config file or a mapping with '{RLLIB}:' and '{SECTION}:', got "
                               f"{type(path).__name__}")
    else:
        source = str(path)
        try:
            text = Path(path).read_text()
        except OSError as exc:
            raise RLlibConfigError(f"{source}: cannot read the config ({exc.strerror}); see configs/train/rllib_*.yaml"
                                   ) from None
        try:
            data = yaml.safe_load(text) or {}
        except yaml.YAMLError as exc:
            raise RLlibConfigError(f"{source}: not valid YAML ({exc})") from None
    if not isinstance(data, Mapping):
        raise RLlibConfigError(f"{source}: expected a mapping with '{RLLIB}:' and '{SECTION}:' at the top level")
    unknown = sorted(set(data) - {RLLIB, SECTION})
    if unknown:
        raise RLlibConfigError(f"{source}: unknown top-level key(s) {unknown}; an RLlib config has '{RLLIB}:' "
                               f"(AlgorithmConfig sections) and '{SECTION}:' (run settings)")
    settings_data = dict(data.get(SECTION) or {})
    settings_data.update(dict(overrides or {}))
    settings = RLlibSettings.from_mapping(settings_data, source)
    if settings.name is None and source not in ("<dict>", "<defaults>"):
        settings.name = Path(source).stem
    raw = data.get(RLLIB) or {}
    if not isinstance(raw, Mapping):
        raise RLlibConfigError(f"{source}: '{RLLIB}:' must map AlgorithmConfig sections to their settings")
    sections: dict[str, dict[str, Any]] = {}
    for name, body in {**raw}.items():
        sections[name] = _section(name, body, source)
    for name, body in (section_overrides or {}).items():
        sections[name] = {**sections.get(name, {}), **_section(name, body, "override")}
    try:
        check_env_id(settings.env_id)
    except ValueError as exc:
        raise RLlibConfigError(f"{source}: {SECTION}.env_id: {exc}") from None
    env = sections.get("environment", {})
    for reserved in ("env", "env_config"):
        if reserved in env:
            raise RLlibConfigError(f"{source}: {RLLIB}.environment.{reserved} is set from '{SECTION}:' (env_id, "
                                   "env_kwargs); move it there")
    if settings.self_play and "multi_agent" in sections and {"policies", "policy_mapping_fn"} & set(
            sections["multi_agent"]):
        raise RLlibConfigError(f"{source}: with {SECTION}.self_play the policies are set for you; remove "
                               f"{RLLIB}.multi_agent.policies / policy_mapping_fn")
    mode = sections.get("env_runners", {}).get("gym_env_vectorize_mode")
    if mode is not None and str(mode).lower() not in VECTORIZE_MODES:
        raise RLlibConfigError(f"{source}: {RLLIB}.env_runners.gym_env_vectorize_mode: {mode!r}; use one of "
                               f"{VECTORIZE_MODES}")
    if mode is not None:
        sections["env_runners"]["gym_env_vectorize_mode"] = str(mode).lower()
    if settings.self_play and str(mode).lower() == "vector_entry_point":
        raise RLlibConfigError(f"{source}: the two-player (self-play) env has no native vector env; set "
                               f"{RLLIB}.env_runners.gym_env_vectorize_mode to sync")
    return RLlibConfig(settings, sections, source)


def _section(name: str, body: Any, source: str) -> dict[str, Any]:
    if name not in CONFIG_SECTIONS:
        raise RLlibConfigError(f"{source}: {RLLIB}.{name}: not a section; use AlgorithmConfig methods "
                               f"{CONFIG_SECTIONS}")
    if body is None:
        return {}
    if not isinstance(body, Mapping):
        raise RLlibConfigError(f"{source}: {RLLIB}.{name} must be a mapping of that method's arguments")
    return {str(k): _numbers(v) for k, v in body.items()}


def parse_assignments(items: list[str] | None, flag: str) -> dict[str, dict[str, Any]]:
    """``section.key=value`` items (``--set training.lr=3e-4``) as ``{section: {key: value}}``."""
    out: dict[str, dict[str, Any]] = {}
    for item in items or []:
        key, sep, value = item.partition("=")
        section, dot, name = key.strip().partition(".")
        if not sep or not dot or not name:
            raise RLlibConfigError(f"{flag}: expected section.key=value (e.g. training.lr=3e-4), got {item!r}")
        out.setdefault(section, {})[name] = _numbers(yaml.safe_load(value))
    return out


__all__ = ["ALGOS", "CONFIG_SECTIONS", "SELF_PLAY", "VECTORIZE_MODES", "ENV_PREFIX", "SELF_PLAY_PREFIX",
           "RLlibConfigError", "RLlibSettings", "RLlibConfig", "load_rllib_config", "normalize_algo",
           "parse_assignments"]
