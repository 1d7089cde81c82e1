"""The configuration schema of the billiards environments: every knob, its default, its meaning and its checks.

A scene is data. Each registered id reads its defaults from a YAML file shipped inside the package,
``billiards_env/envs/scenes/<scene>.yaml`` (the canonical copy; ``configs/envs/<scene>.yaml`` at the repository
root is the user-facing copy of the same file and a test keeps the two identical). Keys are flat, so any of them
can be overridden when the env is made::

    gym.make("BilliardsOneBall-v0", speed_max=3.0, angle_noise=0.01)
    gym.make("BilliardsOneBall-v0", config="my_scene.yaml", aim="relative")

Precedence (later wins): the dataclass defaults below < the id's scene YAML < the ``config`` file or dict <
keyword arguments. A ``config`` file may be partial: keys it omits keep the id's defaults. An unknown key, a
value of the wrong type or a value out of range raises :class:`ConfigError` naming the key and the fix.

Run ``python -m billiards_env.envs.config`` to print the table of keys.
"""
from __future__ import annotations

import difflib
import math
import os
from dataclasses import MISSING, asdict, dataclass, field, fields, replace
from pathlib import Path
from typing import Any, Mapping

import numpy as np

from billiards_env.physics.balls import BALL_MASS, BALL_RADIUS
from billiards_env.physics.errors import SceneError
from billiards_env.physics.model import FRICTION_LAWS
from billiards_env.physics.simulate import SOLVERS
from billiards_env.physics.table import (CORNER_POCKET_RADIUS, DEFAULT_CUSHION_RESTITUTION, DEFAULT_LENGTH,
                                         DEFAULT_WIDTH, SIDE_POCKET_RADIUS)

#: Directory of the packaged scene files (one per registered id).
SCENES_DIR = Path(__file__).resolve().parent / "scenes"

PLACEMENTS = ("random", "rack")
CUE_PLACEMENTS = ("random", "kitchen", "head_spot")
AIM_MODES = ("absolute", "relative")
MAX_OBJECT_BALLS = 15


class ConfigError(SceneError):
    """A bad environment configuration: the message names the key and says how to fix it (a ``ValueError``)."""


def _doc(text: str, **kw: Any) -> Any:
    return field(metadata={"doc": text}, **kw)


@dataclass(frozen=True)
class EnvConfig:
    """Every setting of a billiards environment (flat keys; units SI: metres, seconds, radians, m/s)."""

    # --- scene: which balls and where -------------------------------------------------------------------------
    n_object_balls: int = _doc("Object balls besides the cue ball (1-15); ids '1'..'n', observation order.",
                               default=1)
    placement: str = _doc("How object balls start: 'random' (uniform, non-overlapping, clear of cushions and "
                          "pockets, drawn from the env's np_random at every reset) or 'rack' (a touching triangle "
                          "at the foot spot, apex towards the cue; the standard 15-ball order when n = 15).",
                          default="random")
    cue_placement: str = _doc("Where the cue ball starts: 'random' (anywhere, like the object balls), 'kitchen' "
                              "(random behind the head string, x < length/4) or 'head_spot' (length/4, width/2).",
                              default="random")
    cushion_margin: float = _doc("Random placement: clearance (m) between a ball's edge and every cushion.",
                                 default=0.05)
    pocket_margin: float = _doc("Random placement: minimum distance (m) from a ball's centre to any pocket centre.",
                                default=0.15)
    ball_gap: float = _doc("Random placement: minimum gap (m) between two balls' surfaces.", default=0.01)
    rack_gap: float = _doc("Rack placement: gap (m) between neighbouring racked balls (0 = touching).",
                           default=0.0)

    # --- table ------------------------------------------------------------------------------------------------
    table_length: float = _doc("Playing-area length (m), along x.", default=DEFAULT_LENGTH)
    table_width: float = _doc("Playing-area width (m), along y.", default=DEFAULT_WIDTH)
    cushion_restitution: float = _doc("Coefficient of restitution of the cushions, in [0, 1].",
                                      default=DEFAULT_CUSHION_RESTITUTION)
    corner_pocket_radius: float = _doc("Capture radius (m) of the four corner pockets.", default=CORNER_POCKET_RADIUS)
    side_pocket_radius: float = _doc("Capture radius (m) of the two side pockets.", default=SIDE_POCKET_RADIUS)

    # --- balls and physics ------------------------------------------------------------------------------------
    ball_radius: float = _doc("Radius (m) of every ball.", default=BALL_RADIUS)
    ball_mass: float = _doc("Mass (kg) of every ball.", default=BALL_MASS)
    friction: str = _doc("Friction law: 'rolling' (constant deceleration mu_roll*g) or 'drag' (dv/dt = -drag_k v).",
                         default="rolling")
    mu_roll: float = _doc("Rolling-resistance coefficient (rolling law); 0.01 lets a 2 m/s ball roll ~20 m.",
                          default=0.01)
    drag_k: float = _doc("Drag rate (1/s) of the drag law.", default=0.0)
    min_speed: float = _doc("A ball stops when its speed falls below this (m/s); 0 = roll to the exact stop.",
                            default=0.0)
    ball_restitution: float = _doc("Coefficient of restitution of ball-ball collisions, in [0, 1].", default=0.95)

    # --- solver -----------------------------------------------------------------------------------------------
    solver: str = _doc("'exact' (event-driven, the reference and the fast path) or 'step' (fixed time step).",
                       default="exact")
    max_time: float = _doc("Simulated-seconds cap per shot; a capped shot reports status 'time_cap' and the "
                           "balls are stopped where they are.", default=600.0)
    max_events: int = _doc("Event cap per shot (exact solver); a capped shot reports status 'event_cap'.",
                           default=20_000)

    # --- action -----------------------------------------------------------------------------------------------
    aim: str = _doc("'absolute': angle = pi*a[0] (0 = +x, counter-clockwise). 'relative': angle measured from "
                    "the direction cue -> target ball (the lowest-numbered object ball on the table), so a[0] = 0 "
                    "hits it full.", default="absolute")
    speed_min: float = _doc("Cue-ball speed (m/s) for a[1] = -1.", default=0.5)
    speed_max: float = _doc("Cue-ball speed (m/s) for a[1] = +1.", default=5.0)
    angle_noise: float = _doc("Shot noise: standard deviation (rad) of Gaussian noise added to the angle; 0 = off.",
                              default=0.0)
    speed_noise: float = _doc("Shot noise: relative standard deviation of the speed (speed *= 1 + N(0, s)); "
                              "0 = off.", default=0.0)

    # --- reward -----------------------------------------------------------------------------------------------
    pot_reward: float = _doc("Reward per object ball pocketed.", default=1.0)
    scratch_penalty: float = _doc("Subtracted when the cue ball is pocketed (then re-spotted).", default=1.0)
    miss_penalty: float = _doc("Subtracted when the cue ball touches no ball.", default=0.0)
    step_penalty: float = _doc("Subtracted every shot (a cost per shot).", default=0.0)

    # --- episode ----------------------------------------------------------------------------------------------
    single_shot: bool = _doc("True: the episode terminates after one shot whatever happens.", default=False)
    max_shots: int = _doc("Shot limit: the episode is truncated after this many shots if the table is not "
                          "cleared.", default=15)

    # --- rendering --------------------------------------------------------------------------------------------
    render_width: int = _doc("Width (px) of rendered frames; the height follows the table's aspect.", default=800)
    render_fps: int = _doc("Frames per simulated second of the shot animations (also metadata['render_fps']).",
                           default=30)
    render_speedup: float = _doc("Animation playback speed: simulated seconds per second of animation (1 = real "
                                 "time; 4 = four times faster, a quarter of the frames).", default=1.0)

    def __post_init__(self) -> None:
        _validate(self)

    # ---------------------------------------------------------------------------------------------------------
    @classmethod
    def keys(cls) -> tuple[str, ...]:
        return tuple(f.name for f in fields(cls))

    @classmethod
    def describe(cls) -> str:
        """A text table of every key: name, type, default, meaning."""
        rows = []
        for f in fields(cls):
            tname = _type_name(f)
            rows.append(f"{f.name:<22} {tname:<6} {f.default!r:<12} {f.metadata['doc']}")
        return "\n".join(rows)

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)

    def updated(self, overrides: Mapping[str, Any], source: str = "overrides") -> "EnvConfig":
        """A copy with ``overrides`` applied (checked: unknown keys and bad values raise :class:`ConfigError`)."""
        if not overrides:
            return self
        return replace(self, **_coerce(overrides, source))

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any], source: str = "config") -> "EnvConfig":
        """A config from the dataclass defaults and ``data`` (checked)."""
        return cls(**_coerce(data, source))


# --- loading ---------------------------------------------------------------------------------------------------

def scene_path(scene: str) -> Path:
    """The packaged YAML file of scene ``scene`` (e.g. ``"one_ball"``)."""
    p = SCENES_DIR / f"{scene}.yaml"
    if not p.is_file():
        known = sorted(q.stem for q in SCENES_DIR.glob("*.yaml"))
        raise ConfigError(f"scene {scene!r}: no file {p}; packaged scenes are {known}")
    return p


def read_yaml(path: str | os.PathLike[str]) -> dict[str, Any]:
    """The mapping in a YAML config file (a clear :class:`ConfigError` if it cannot be read or is not a mapping)."""
    import yaml

    p = Path(path)
    try:
        text = p.read_text()
    except OSError as exc:
        raise ConfigError(f"config {str(path)!r}: cannot read the file ({exc.strerror}); give the path of a YAML "
                          f"file such as {scene_path('one_ball')}") from None
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        raise ConfigError(f"config {str(path)!r}: not valid YAML ({exc})") from None
    if data is None:
        return {}
    if not isinstance(data, Mapping):
        raise ConfigError(f"config {str(path)!r}: expected a mapping of keys to values at the top level, "
                          f"got {type(data).__name__}")
    return dict(data)


def load_config(scene: str | None = None, config: Any = None, **overrides: Any) -> EnvConfig:
    """The configuration of an environment: packaged scene ``scene`` (defaults), then ``config`` (a YAML path,
    a mapping or an :class:`EnvConfig`), then keyword ``overrides``."""
    cfg = EnvConfig()
    if scene is not None:
        p = scene_path(scene)
        cfg = cfg.updated(read_yaml(p), source=str(p))
    if config is not None:
        if isinstance(config, EnvConfig):
            cfg = config
        elif isinstance(config, (str, os.PathLike)):
            cfg = cfg.updated(read_yaml(config), source=str(config))
        elif isinstance(config, Mapping):
            cfg = cfg.updated(config, source="config")
        else:
            raise ConfigError(f"config: expected a YAML file path, a mapping or an EnvConfig, got "
                              f"{type(config).__name__}")
    return cfg.updated(overrides, source="keyword arguments")


# --- checks ----------------------------------------------------------------------------------------------------

_FIELDS = {f.name: f for f in fields(EnvConfig)}


def _coerce(data: Mapping[str, Any], source: str) -> dict[str, Any]:
    """Check the keys and the types of ``data`` (ints accepted for float keys); ranges are checked later."""
    out: dict[str, Any] = {}
    for key, value in data.items():
        if key not in _FIELDS:
            close = difflib.get_close_matches(str(key), list(_FIELDS), n=1)
            hint = f"did you mean {close[0]!r}? " if close else ""
            raise ConfigError(f"unknown config key {key!r} (from {source}); {hint}valid keys: "
                              f"{', '.join(_FIELDS)}")
        tname = _type_name(_FIELDS[key])
        if tname == "bool":
            if not isinstance(value, (bool, np.bool_)):
                raise ConfigError(f"{key}: expected true or false, got {value!r}")
            value = bool(value)
        elif tname == "int":
            if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
                if isinstance(value, (float, np.floating)) and float(value).is_integer():
                    value = int(value)
                else:
                    raise ConfigError(f"{key}: expected an integer, got {value!r}")
            value = int(value)
        elif tname == "float":
            if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
                raise ConfigError(f"{key}: expected a number, got {type(value).__name__} {value!r}")
            value = float(value)
            if not math.isfinite(value):
                raise ConfigError(f"{key}: must be a finite number, got {value}")
        elif tname == "str":
            if not isinstance(value, str):
                raise ConfigError(f"{key}: expected a string, got {value!r}")
        out[str(key)] = value
    return out


def _type_name(f: Any) -> str:
    return f.type if isinstance(f.type, str) else f.type.__name__


def _require(ok: bool, key: str, message: str) -> None:
    if not ok:
        raise ConfigError(f"{key}: {message}")


def _choice(cfg: EnvConfig, key: str, allowed: tuple[str, ...]) -> None:
    v = getattr(cfg, key)
    _require(v in allowed, key, f"unknown value {v!r}; use one of {', '.join(map(repr, allowed))}")


def _validate(cfg: EnvConfig) -> None:  # noqa: C901 - one flat list of checks
    """Range and consistency checks; the message names the key and the fix."""
    _coerce(cfg.to_dict(), "EnvConfig")  # types (also for direct EnvConfig(...) construction)
    n = cfg.n_object_balls
    _require(1 <= n <= MAX_OBJECT_BALLS, "n_object_balls", f"must be 1..{MAX_OBJECT_BALLS}, got {n}")
    _choice(cfg, "placement", PLACEMENTS)
    _choice(cfg, "cue_placement", CUE_PLACEMENTS)
    _choice(cfg, "friction", FRICTION_LAWS)
    _choice(cfg, "solver", SOLVERS)
    _choice(cfg, "aim", AIM_MODES)
    for key in ("cushion_margin", "pocket_margin", "ball_gap", "rack_gap", "drag_k", "mu_roll", "min_speed",
                "angle_noise", "speed_noise", "pot_reward", "scratch_penalty", "miss_penalty", "step_penalty"):
        v = getattr(cfg, key)
        _require(v >= 0, key, f"must be >= 0, got {v}" + (
            " (penalties are magnitudes: a positive value is subtracted from the reward)" if "penalty" in key else ""))
    for key in ("table_length", "table_width", "corner_pocket_radius", "side_pocket_radius", "ball_radius",
                "ball_mass", "max_time"):
        v = getattr(cfg, key)
        _require(v > 0, key, f"must be > 0, got {v}")
    for key in ("cushion_restitution", "ball_restitution"):
        v = getattr(cfg, key)
        _require(0 <= v <= 1, key, f"must be in [0, 1], got {v}")
    _require(cfg.speed_min >= 0, "speed_min", f"must be >= 0 m/s, got {cfg.speed_min}")
    _require(cfg.speed_max > cfg.speed_min, "speed_max",
             f"must be greater than speed_min ({cfg.speed_min} m/s), got {cfg.speed_max}; the speed range is "
             "[speed_min, speed_max]")
    _require(cfg.max_events >= 1, "max_events", f"must be >= 1, got {cfg.max_events}")
    _require(cfg.max_shots >= 1, "max_shots", f"must be >= 1, got {cfg.max_shots}")
    _require(64 <= cfg.render_width <= 8192, "render_width", f"must be 64..8192 pixels, got {cfg.render_width}")
    _require(1 <= cfg.render_fps <= 1000, "render_fps", f"must be 1..1000, got {cfg.render_fps}")
    _require(cfg.render_speedup > 0, "render_speedup", f"must be > 0, got {cfg.render_speedup}")
    r = cfg.ball_radius
    _require(4 * r < min(cfg.table_length, cfg.table_width), "ball_radius",
             f"{r} m is too large for a {cfg.table_length} x {cfg.table_width} m table")
    if cfg.placement == "random":
        free = min(cfg.table_length, cfg.table_width) - 2 * (r + cfg.cushion_margin)
        _require(free > 0, "cushion_margin", f"{cfg.cushion_margin} m leaves no room on the table; lower it")
    else:
        # the triangle (apex at 3/4 of the length) must fit between the apex and the foot cushion
        rows = _rack_rows(n)
        d = 2 * r + cfg.rack_gap
        depth = 0.75 * cfg.table_length + (rows - 1) * d * math.sqrt(3) / 2 + r
        spread = (rows - 1) * d + 2 * r
        _require(depth <= cfg.table_length and spread <= cfg.table_width, "rack_gap",
                 f"a {n}-ball rack with gap {cfg.rack_gap} m does not fit on the table; lower rack_gap")


def _rack_rows(n: int) -> int:
    rows = 1
    while rows * (rows + 1) // 2 < n:
        rows += 1
    return rows


def config_table_markdown() -> str:
    """The keys as a Markdown table (for docs)."""
    lines = ["| key | default | meaning |", "|---|---|---|"]
    for f in fields(EnvConfig):
        default = f.default if f.default is not MISSING else ""
        lines.append(f"| `{f.name}` | `{default!r}` | {f.metadata['doc']} |")
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover
    print(EnvConfig.describe())
