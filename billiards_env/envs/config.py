"""The configuration schema of the billiards environments: every knob, its default, its meaning and its checks.

A scene is data. Each registered id reads its defaults from a YAML file shipped inside the package,
``billiards_env/envs/scenes/<scene>.yaml``, which holds only what differs from the defaults below. Any key can be
overridden when the env is made::

    gym.make("BilliardsOneBall-v0", speed_max=3.0, angle_noise=0.01)
    gym.make("BilliardsOneBall-v0", config="my_scene.yaml", action_type="relative")
    gym.make("BilliardsOneBall-v0", physics={"mu_roll": 0.02}, table={"length": 2.84, "width": 1.42})

The physics of a table has ONE schema, shared with scene files (:mod:`billiards_env.physics.scene`): the sections
``table`` (``length``, ``width``, ``cushion_restitution``, ``corner_pocket_radius``/``side_pocket_radius`` or a
``pockets`` list), ``physics`` (the fields of :class:`~billiards_env.physics.Physics`: ``friction``, ``mu_roll``...)
and ``solver`` (``name``, ``dt``, ``contact``, or just the name), plus ``max_time`` and ``max_events``: the same
names, the same defaults and the same parser as a scene file. As a shorthand a physics field may be given on its
own (``gym.make(id, friction="spin")`` is ``physics={"friction": "spin"}``).

Precedence (later wins): the defaults below < the id's scene YAML < the ``config`` file or dict < keyword
arguments; sections merge field by field. An unknown key, a value of the wrong type or a value out of range
raises :class:`ConfigError` naming the key and the fix. ``python -m billiards_env.envs`` prints the keys.
"""
from __future__ import annotations

import difflib
import math
import os
from dataclasses import MISSING, asdict, dataclass, field, fields
from pathlib import Path
from typing import Any, Mapping

import numpy as np

from billiards_env.games import GAMES, game_spec
from billiards_env.physics.balls import BALL_MASS, BALL_RADIUS, MAX_BALL_SPEED
from billiards_env.physics.errors import SceneError
from billiards_env.physics.layout import rack_fits
from billiards_env.physics.model import Physics
from billiards_env.physics.scene import PHYSICS_FIELDS, parse_physics, parse_solver, parse_table, table_to_dict
from billiards_env.physics.simulate import DEFAULT_MAX_EVENTS, DEFAULT_MAX_TIME, SolverSettings
from billiards_env.physics.table import Table
from billiards_env.rules.errors import RulesError

from .actions import ACTION_TYPES as _ACTION_TYPES
from .observations import OBSERVATION_TYPES as _OBSERVATION_TYPES

#: Directory of the packaged scene files (one per registered id).
SCENES_DIR = Path(__file__).resolve().parent / "scenes"

#: The generic placements; a game adds its own (:attr:`GameSession.placements
#: <billiards_env.games.session.GameSession.placements>`: snooker's ``"snooker"``, three-cushion's ``"carom"``).
PLACEMENTS = ("random", "rack", "diamond")
CUE_PLACEMENTS = ("random", "kitchen", "head_spot")
#: The action and observation types' names (each type registers itself in its module's dict).
ACTION_TYPES = tuple(_ACTION_TYPES)
OBSERVATION_TYPES = tuple(_OBSERVATION_TYPES)
OPENINGS = ("break", "ball_in_hand", "either")
#: ``pot`` (the scenes without rules) and every registered game (:data:`billiards_env.games.GAMES`).
TASKS = ("pot",) + tuple(GAMES)
#: The players every game has by name (a game may add its own: :attr:`GameSession.players
#: <billiards_env.games.session.GameSession.players>`, which the ``opponent`` key reads).
OPPONENTS = ("geometric", "search", "random")
SPEED_NOISE_MODES = ("relative", "absolute")
#: The named shot noises (config key ``noise``): the keys they set (tip_noise only under the spin model; a tip
#: noise in mm is a fraction of the config's ball radius).
NOISE_PRESETS: dict[str, dict[str, Any]] = {
    "olympiad": {"angle_noise": math.radians(0.125), "speed_noise": 0.075, "speed_noise_mode": "absolute",
                 "tip_noise_mm": 0.5},
    "fastfiz": {"angle_noise": math.radians(0.125), "speed_noise": 0.075 / 2.0, "speed_noise_mode": "relative",
                "tip_noise_mm": 0.5},
}
FIRST_SHOOTERS = ("agent", "opponent", "random")
MAX_OBJECT_BALLS = 15
#: The sections shared with scene files, and the parser of each.
SECTIONS = {"table": parse_table, "physics": parse_physics, "solver": parse_solver}
#: Keys of earlier versions and where they went (for a helpful error).
RENAMED = {
    "table_length": "table={'length': ...}", "table_width": "table={'width': ...}",
    "cushion_restitution": "table={'cushion_restitution': ...}",
    "corner_pocket_radius": "table={'corner_pocket_radius': ...}",
    "side_pocket_radius": "table={'side_pocket_radius': ...}",
    "aim": "action_type='absolute' or 'relative'",
}


class ConfigError(SceneError):
    """A bad environment configuration: the message names the key and says how to fix it (a ``ValueError``)."""


class UnknownKeyError(ConfigError, TypeError):
    """An unknown keyword argument (a config key given to the constructor or ``gym.make`` that does not exist): a
    :class:`ConfigError` and, as Python's own ``got an unexpected keyword argument`` error, a ``TypeError``, so
    wrappers that try a keyword and fall back on a ``TypeError`` (TorchRL's ``GymEnv`` tries ``frameskip``) work."""


def _doc(text: str, **kw: Any) -> Any:
    return field(metadata={"doc": text}, **kw)


@dataclass(frozen=True)
class EnvConfig:
    """Every setting of a billiards environment (units SI: metres, seconds, radians, m/s)."""

    # --- scene: which balls and where -------------------------------------------------------------------------
    n_object_balls: int = _doc("Object balls besides the cue ball (1-15); ids '1'..'n', observation order.",
                               default=1)
    placement: str = _doc("How object balls start: 'random' (uniform, non-overlapping, clear of cushions and "
                          "pockets, drawn from the env's np_random at every reset), 'rack' (a touching triangle "
                          "at the foot spot, apex towards the cue; the standard 15-ball order when n = 15; the games "
                          "shuffle it as the rules say), 'diamond' (the 9-ball diamond: 1 at the apex, 9 in the "
                          "middle), or a game's own layout (its session's placements: snooker's 'snooker', the reds' "
                          "triangle and the colours on their spots, the cue ball in the D; three-cushion's 'carom', "
                          "the start position).", default="random")
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
    ball_radius: float = _doc("Radius (m) of every ball.", default=BALL_RADIUS)
    ball_mass: float = _doc("Mass (kg) of every ball.", default=BALL_MASS)

    # --- the table's physics: the sections of a scene file ------------------------------------------------------
    table: Table = _doc("Table section (as in scene files): length, width, cushion_restitution, "
                        "corner_pocket_radius, side_pocket_radius (or a pockets list).", default_factory=Table)
    physics: Physics = _doc("Physics section (as in scene files): friction ('rolling', 'drag' or 'spin'), mu_roll, "
                            "drag_k, min_speed, ball_restitution, and for 'spin' mu_slide, mu_spin, ball_friction, "
                            "cushion_friction. Each field may also be given on its own.", default_factory=Physics)
    solver: SolverSettings = _doc("Solver section (as in scene files): name ('exact', the fast path, or 'step'), "
                                  "dt, contact; or just the name.", default_factory=SolverSettings)
    max_time: float = _doc("Simulated-seconds cap per shot; a capped shot reports status 'time_cap' and the "
                           "balls are stopped where they are.", default=DEFAULT_MAX_TIME)
    max_events: int = _doc("Event cap per shot (exact solver); a capped shot reports status 'event_cap'.",
                           default=DEFAULT_MAX_EVENTS)

    # --- action -----------------------------------------------------------------------------------------------
    action_type: str = _doc("How a[0] aims: 'absolute' (angle = pi*a[0], 0 = +x, counter-clockwise), 'relative' "
                            "(angle = direction cue -> target ball + pi*a[0]: 0 hits it full) or 'ghost' (the "
                            "direction the target ball leaves in: ghost_max_angle*a[0] from the cue -> target "
                            "line; the cue ball is struck at the ghost-ball position that sends it there), or "
                            "'candidates' (a[0] chooses one of the candidate shots that pocket a legal ball, easiest "
                            "first; a[1] scales that shot's own speed; with ball in hand the placement is set "
                            "relative to it: billiards_env.envs.actions.CandidateShots), or 'candidates_aim' "
                            "('candidates' plus a last dim, offset: where in the pocket's window the object ball "
                            "is sent; billiards_env.envs.actions.CandidateAim). The target ball is the "
                            "lowest-numbered object ball on the table.", default="absolute")
    ghost_max_angle: float = _doc("action_type 'ghost': the object-ball angle (degrees, 0-90) that |a[0]| = 1 "
                                  "means.", default=90.0)
    candidate_slots: int = _doc("action/observation type 'candidates': how many candidate shots (easiest first) "
                                "the action chooses among and the observation describes (1-12).", default=4)
    candidate_speed_factor: float = _doc("action_type 'candidates': a[1] = +-1 plays the chosen shot at its own "
                                         "speed times / divided by this factor (> 1).", default=3.0)
    speed_min: float = _doc("Cue-ball speed (m/s) for a[1] = -1.", default=0.5)
    speed_max: float = _doc("Cue-ball speed (m/s) for a[1] = +1.", default=5.0)
    spin_action: bool = _doc("Add two action dims, side and top tip offsets in [-1, 1], mapped onto the disc of "
                             "radius max_tip_offset (needs physics friction 'spin').", default=False)
    max_tip_offset: float = _doc("spin_action: the largest tip offset (fraction of R; 0.5 is the miscue limit).",
                                 default=0.5)
    angle_noise: float = _doc("Shot noise: standard deviation (rad) of Gaussian noise added to the angle; 0 = off.",
                              default=0.0)
    speed_noise: float = _doc("Shot noise: standard deviation of the speed, relative (speed *= 1 + N(0, s)) or in "
                              "m/s (speed += N(0, s)) as speed_noise_mode says; 0 = off.", default=0.0)
    speed_noise_mode: str = _doc("'relative' (speed_noise a fraction of the speed) or 'absolute' (in m/s, as "
                                 "FastFiz's noise).", default="relative")
    noise: str | None = _doc("A named shot noise, setting angle_noise, speed_noise (and its mode) and, under the "
                             "spin model, tip_noise, unless given too: 'olympiad' (FastFiz's level-1 noise of the "
                             "Computational Pool Olympiads: aim 0.125 deg, speed 0.075 m/s, tip offsets 0.5 mm; "
                             "its 0.1 deg elevation noise has no counterpart on a level cue), 'fastfiz' (the older "
                             "FastFiz-like setting of the leagues: aim 0.125 deg, speed 3.75 %, tip 0.5 mm), or "
                             "None.", default=None)
    tip_noise: float = _doc("Shot noise: standard deviation (fraction of R) of Gaussian noise added to each tip "
                            "offset (spin model only; the result is kept inside the miscue limit); 0 = off.",
                            default=0.0)

    # --- observation ------------------------------------------------------------------------------------------
    observation_type: str = _doc("'positions' (ball positions and pocketed flags), 'features' (those, then the "
                                 "table seen from the target ball: the cue -> target direction and distance, and "
                                 "per pocket the cut it asks for, its distance and how squarely it is entered) or "
                                 "'candidates' (the positions, then the candidate shots of the 'candidates' action "
                                 "type: pocket, cut, distances, ease, clear paths, scratch risk, speed) or "
                                 "'candidates_path' (those, then per candidate shot and window offset the powers "
                                 "that pot it and that send the cue ball into a pocket after contact) or "
                                 "'candidates_position' (the 'candidates' values, then per candidate shot on a grid of "
                                 "power and top: whether the ball drops, whether the cue ball scratches, where it "
                                 "comes to rest and how easy the next shot is from there).",
                                 default="positions")

    # --- task: reward and episode ---------------------------------------------------------------------------------
    task: str = _doc("What the episode asks: 'pot' (pocket the object balls; success when the table is cleared), "
                     f"or a game under its rules against an opponent: {', '.join(map(repr, GAMES))}.", default="pot")
    pot_reward: float = _doc("Reward per object ball pocketed.", default=1.0)
    scratch_penalty: float = _doc("Subtracted when the cue ball is pocketed (then re-spotted).", default=1.0)
    miss_penalty: float = _doc("Subtracted when the cue ball touches no ball.", default=0.0)
    step_penalty: float = _doc("Subtracted every shot (a cost per shot).", default=0.0)
    single_shot: bool = _doc("True: the episode terminates after one shot whatever happens.", default=False)
    max_shots: int = _doc("Shot limit: the episode is truncated after this many shots if the table is not "
                          "cleared.", default=15)

    # --- games (task 'nine_ball' / 'eight_ball') ------------------------------------------------------------------
    opponent: str | None = _doc("Games: the opponent's policy, 'geometric', 'search' or 'random' (a player of "
                                "billiards_env.players; env.unwrapped.set_opponent(policy) sets any other), or None: "
                                "play alone, the episode ends at the first foul or miss (run-out practice).",
                                default="geometric")
    first_shooter: str = _doc("Games: who breaks: 'agent', 'opponent' or 'random' (drawn at every reset).",
                              default="agent")
    opening: str = _doc("Games: how a game starts: 'break' (the first shooter breaks with the cue ball in the "
                        "kitchen) or 'ball_in_hand' (the env breaks for nobody: a full-speed hit from the head spot "
                        "at the nearest ball, with the shot noise; balls pocketed stay down, the 9 (8-ball: the 8) is "
                        "respotted, and the first shooter has the cue ball in hand anywhere: run-out practice and "
                        "the league's run-out test), or 'either' (one of the two, drawn at every reset from "
                        "np_random: practice of the break and of the run-out).", default="break")
    rules: dict = _doc("Games: options of the ruleset (billiards_env.rules NineBallOptions / EightBallOptions), "
                       "e.g. {push_out: true} or {call_eight: false}; the env defaults are the rules' own, except "
                       "push_out false.", default_factory=dict)
    win_reward: float = _doc("Games: reward when the agent wins the game.", default=1.0)
    loss_penalty: float = _doc("Games: subtracted when the agent loses the game.", default=1.0)
    foul_penalty: float = _doc("Games (shaping): subtracted for each foul of the agent; 0 = off.", default=0.0)
    position_reward: float = _doc("Games (shaping): after a legal shot that keeps the turn, this times the chance "
                                  "of potting the easiest next shot (its ghost-ball tolerance against the angle "
                                  "noise, at least 0.002 rad: billiards_env.envs.candidates.next_shot_ease): "
                                  "position play; 0 = off.", default=0.0)
    opponent_infos: bool = _doc("Games: True adds info['opponent_turns'], the opponent's reply shot by shot (a list "
                                "of dicts, one per shot: shooter, pocketed, scratch, first_contact, foul, "
                                "foul_reason, call, turn_over, angle, speed and the game's own keys, in the forms of "
                                "docs/infos.md); its length varies, so it is off by default (the fixed keys "
                                "opponent_shots, opponent_pocketed and opponent_fouls sum the reply up).",
                                default=False)

    # --- rendering --------------------------------------------------------------------------------------------
    render_width: int = _doc("Width (px) of rendered frames; the height follows the table's aspect.", default=800)
    render_fps: int = _doc("Frames per simulated second of the shot animations (also metadata['render_fps']).",
                           default=30)
    render_max_frames: int = _doc("rgb_array_list: the most frames one step draws, all its shots together (a game "
                                  "step holds the opponent's reply too); a longer step is drawn at a lower frame "
                                  "rate, evenly in simulated time. 0 = no cap (an 800 px frame is 1.3 MB).",
                                  default=200)
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
        """A text table of every key: name, type, default, meaning (sections list their fields)."""
        rows = []
        for f in fields(cls):
            rows.append(f"{f.name:<18} {_type_name(f):<8} {_default_text(f):<14} {f.metadata['doc']}")
            if f.name in SECTIONS:
                for k, v in _section_dict(f.name, _default(f)).items():
                    rows.append(f"{'  ' + f.name + '.' + k:<27} {v!r}")
        return "\n".join(rows)

    def to_dict(self) -> dict[str, Any]:
        """Plain data (sections as mappings): what ``EnvConfig.from_mapping`` and ``gym.make(id, **d)`` read back."""
        out = {}
        for f in fields(self):
            v = getattr(self, f.name)
            out[f.name] = _section_dict(f.name, v) if f.name in SECTIONS else v
        return out

    def updated(self, overrides: Mapping[str, Any], source: str = "overrides") -> "EnvConfig":
        """A copy with ``overrides`` applied (checked: unknown keys and bad values raise :class:`ConfigError`)."""
        if not overrides:
            return self
        raw = self.to_dict()
        _merge(raw, overrides, source)
        return _build(raw, source)

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any], source: str = "config") -> "EnvConfig":
        """A config from the defaults and ``data`` (checked)."""
        return cls().updated(data, source)


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
        text = p.read_text(encoding="utf-8")
    except OSError as exc:
        raise ConfigError(f"config {str(path)!r}: cannot read the file ({exc.strerror}); give the path of a YAML "
                          f"file such as {scene_path('one_ball')}") from None
    except UnicodeDecodeError as exc:
        raise ConfigError(f"config {str(path)!r}: not UTF-8 text (byte {exc.start} is {exc.object[exc.start]:#04x}); "
                          "save the file as UTF-8 YAML (e.g. `iconv -f latin1 -t utf-8`)") from None
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


#: Keys that only a game reads: given for a scene without rules they are refused (they would do nothing).
GAME_KEYS = ("opponent", "first_shooter", "opening", "rules", "win_reward", "loss_penalty", "foul_penalty",
             "position_reward", "opponent_infos")


def _check_game_keys(cfg: EnvConfig, given: set[str]) -> EnvConfig:
    """Refuse the game-only keys a user gave for a scene without rules (their defaults exist for every config)."""
    if cfg.task not in GAMES:
        wrong = sorted(k for k in given if k in GAME_KEYS)
        if wrong:
            raise ConfigError(f"{wrong[0]}: only the games (task {' or '.join(map(repr, GAMES))}, e.g. "
                              f"Billiards9Ball-v0) read it; task {cfg.task!r} has no opponent, rules or game "
                              f"rewards: leave out {', '.join(map(repr, wrong))}")
    return cfg


def _apply_noise(cfg: EnvConfig, given: set[str]) -> EnvConfig:
    """``cfg`` with its named noise (key ``noise``) filled into the noise keys not given explicitly."""
    if cfg.noise is None:
        return cfg
    preset = dict(NOISE_PRESETS[cfg.noise])
    tip_mm = preset.pop("tip_noise_mm")
    if cfg.physics.has_spin:
        preset["tip_noise"] = tip_mm * 1e-3 / cfg.ball_radius
    fill = {k: v for k, v in preset.items() if k not in given}
    return cfg.updated(fill, source=f"noise {cfg.noise!r}") if fill else cfg


def load_config(scene: str | None = None, config: Any = None, **overrides: Any) -> EnvConfig:
    """The configuration of an environment: packaged scene ``scene`` (defaults), then ``config`` (a YAML path,
    a mapping or an :class:`EnvConfig`), then keyword ``overrides``."""
    if isinstance(config, EnvConfig):
        cfg = config.updated(overrides, source="keyword arguments")
        return _check_game_keys(_apply_noise(cfg, set(overrides)), set(overrides))
    raw = EnvConfig().to_dict()
    if scene is not None:
        p = scene_path(scene)
        _merge(raw, read_yaml(p), str(p))
    if config is not None:
        if isinstance(config, (str, os.PathLike)):
            _merge(raw, read_yaml(config), str(config))
        elif isinstance(config, Mapping):
            _merge(raw, config, "config")
        else:
            raise ConfigError(f"config: expected a YAML file path, a mapping or an EnvConfig, got "
                              f"{type(config).__name__}")
    _merge(raw, overrides, "keyword arguments")
    given = set(overrides)
    if isinstance(config, (str, os.PathLike)):
        given |= set(read_yaml(config))
    elif isinstance(config, Mapping):
        given |= set(config)
    cfg = _build(raw, "keyword arguments" if overrides else "config")
    return _check_game_keys(_apply_noise(cfg, given), given)


# --- sections --------------------------------------------------------------------------------------------------

_FIELDS = {f.name: f for f in fields(EnvConfig)}


def _default(f: Any) -> Any:
    return f.default_factory() if f.default is MISSING else f.default


def _default_text(f: Any) -> str:
    return "(section)" if f.name in SECTIONS else repr(_default(f))


def _section_dict(name: str, value: Any) -> dict[str, Any]:
    """A section object (Table, Physics, SolverSettings) as the mapping its parser reads."""
    if name == "table":
        t = table_to_dict(value)
        if value.has_jaws:  # its specs say it all
            return t
        default = Table(t["length"], t["width"], t["cushion_restitution"])
        if value == default:  # the standard six pockets: say so by their radii (readable, and scales with size)
            del t["pockets"]
            t["corner_pocket_radius"] = float(value.pocket_radius[0])
            t["side_pocket_radius"] = float(value.pocket_radius[1])
        return t
    return asdict(value)


def _section_input(key: str, value: Any, source: str) -> dict[str, Any]:
    """A section value from a config layer as a mapping (an object of the section's type is accepted too)."""
    if isinstance(value, (Table, Physics, SolverSettings)):
        return _section_dict(key, value)
    if key == "solver" and isinstance(value, str):
        return {"name": value}
    if not isinstance(value, Mapping):
        raise ConfigError(f"{key}: expected a mapping of its fields (from {source}), got {type(value).__name__} "
                          f"{value!r}; e.g. {key}={{...}}")
    return dict(value)


def _unknown_key(key: str, source: str) -> ConfigError:
    """The error for an unknown key ``key`` from ``source``: a keyword argument's in Python's words (an
    :class:`UnknownKeyError`, a ``TypeError`` too), a file's or mapping's as a :class:`ConfigError`; either says
    where a renamed key went, or the closest valid key, and lists the valid keys."""
    keyword = source == "keyword arguments"
    head = f"__init__() got an unexpected keyword argument {key!r}" if keyword else \
        f"unknown config key {key!r} (from {source})"
    if key in RENAMED:
        return (UnknownKeyError if keyword else ConfigError)(f"{head}: it is now {RENAMED[key]}")
    close = difflib.get_close_matches(key, list(_FIELDS) + sorted(PHYSICS_FIELDS), n=1)
    hint = f"did you mean {close[0]!r}? " if close else ""
    return (UnknownKeyError if keyword else ConfigError)(
        f"{head}; {hint}valid keys: {', '.join(_FIELDS)} (and the physics fields "
        f"{', '.join(sorted(PHYSICS_FIELDS))})")


def _merge(raw: dict[str, Any], layer: Mapping[str, Any], source: str) -> None:
    """Apply one config layer to ``raw`` (plain data): sections merge field by field, physics fields given on
    their own go into the physics section, anything unknown raises."""
    flat_physics = {}
    for key, value in layer.items():
        key = str(key)
        if key in SECTIONS:
            section = _section_input(key, value, source)
            if key in ("table", "physics") and "preset" in section:  # a preset starts the section afresh
                raw[key] = {}
            elif key == "table" and ({"corner_pocket_radius", "side_pocket_radius", "pockets"} & set(section)):
                raw[key] = {k: v for k, v in raw[key].items()
                            if k not in ("corner_pocket_radius", "side_pocket_radius", "pockets", "preset")}
            raw[key] = {**raw[key], **section}
        elif key in _FIELDS:
            raw[key] = value
        elif key in PHYSICS_FIELDS:
            flat_physics[key] = value
        else:
            raise _unknown_key(key, source)
    if "preset" in flat_physics and "physics" not in layer:
        raw["physics"] = {}
    for key, value in flat_physics.items():
        if key in layer.get("physics", {}):
            raise ConfigError(f"{key}: given twice in {source}, on its own and in the physics section; keep one")
        raw["physics"] = {**raw["physics"], key: value}


def _build(raw: Mapping[str, Any], source: str) -> EnvConfig:
    """Check the types of plain data and build the config (sections through their parsers)."""
    kw: dict[str, Any] = {}
    for key, value in raw.items():
        if key in SECTIONS:
            if not isinstance(value, (Table, Physics, SolverSettings)):
                try:
                    value = SECTIONS[key](value, where=key)
                except ConfigError:
                    raise
                except SceneError as exc:
                    raise ConfigError(f"{exc} (from {source})") from None
        else:
            value = _coerce(key, value)
        kw[key] = value
    return EnvConfig(**kw)


def _coerce(key: str, value: Any) -> Any:
    """``value`` as the type of key ``key`` (ints accepted for float keys); ranges are checked later."""
    tname = _type_name(_FIELDS[key])
    if tname == "bool":
        if not isinstance(value, (bool, np.bool_)):
            raise ConfigError(f"{key}: expected true or false, got {value!r}")
        return bool(value)
    if tname == "int":
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
            if isinstance(value, (float, np.floating)) and float(value).is_integer():
                return int(value)
            raise ConfigError(f"{key}: expected an integer, got {value!r}")
        return int(value)
    if tname == "float":
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
            raise ConfigError(f"{key}: expected a number, got {type(value).__name__} {value!r}")
        value = float(value)
        if not math.isfinite(value):
            raise ConfigError(f"{key}: must be a finite number, got {value}")
        return value
    if tname == "str" and not isinstance(value, str):
        raise ConfigError(f"{key}: expected a string, got {value!r}")
    if tname == "str | None" and value is not None and not isinstance(value, str):
        raise ConfigError(f"{key}: expected a string or null, got {value!r}")
    if tname == "dict":
        if not isinstance(value, Mapping):
            raise ConfigError(f"{key}: expected a mapping, got {type(value).__name__} {value!r}")
        return dict(value)
    return value


def _type_name(f: Any) -> str:
    return f.type if isinstance(f.type, str) else f.type.__name__


# --- checks ----------------------------------------------------------------------------------------------------

def _require(ok: bool, key: str, message: str) -> None:
    if not ok:
        raise ConfigError(f"{key}: {message}")


def _choice(cfg: EnvConfig, key: str, allowed: tuple[str, ...]) -> None:
    v = getattr(cfg, key)
    _require(v in allowed, key, f"unknown value {v!r}; use one of {', '.join(map(repr, allowed))}")


def _validate(cfg: EnvConfig) -> None:  # noqa: C901 - one flat list of checks
    """Range and consistency checks; the message names the key and the fix."""
    for f in fields(cfg):
        if f.name not in SECTIONS:
            _coerce(f.name, getattr(cfg, f.name))  # types (also for direct EnvConfig(...) construction)
    for key, kind in (("table", Table), ("physics", Physics), ("solver", SolverSettings)):
        _require(isinstance(getattr(cfg, key), kind), key, f"expected a {kind.__name__} or a mapping of its fields")
    n = cfg.n_object_balls
    _require(1 <= n <= MAX_OBJECT_BALLS or cfg.task in GAMES, "n_object_balls",
             f"must be 1..{MAX_OBJECT_BALLS}, got {n}")
    own = game_spec(cfg.task).session_class.placements if cfg.task in GAMES else ()
    _choice(cfg, "placement", PLACEMENTS + tuple(own))
    _choice(cfg, "cue_placement", CUE_PLACEMENTS)
    _choice(cfg, "action_type", ACTION_TYPES)
    _choice(cfg, "observation_type", OBSERVATION_TYPES)
    _choice(cfg, "task", TASKS)
    _choice(cfg, "first_shooter", FIRST_SHOOTERS)
    _choice(cfg, "opening", OPENINGS)
    _choice(cfg, "speed_noise_mode", SPEED_NOISE_MODES)
    _require(cfg.noise is None or cfg.noise in NOISE_PRESETS, "noise",
             f"unknown value {cfg.noise!r}; use one of {', '.join(map(repr, NOISE_PRESETS))} or None")
    game = cfg.task in GAMES
    _require(cfg.opening == "break" or game, "opening",
             f"only the games (task {' or '.join(map(repr, GAMES))}) have an opening; leave it 'break'")
    _require(1 <= cfg.candidate_slots <= 12, "candidate_slots", f"must be 1..12, got {cfg.candidate_slots}")
    _require(cfg.candidate_speed_factor > 1.0, "candidate_speed_factor",
             f"must be > 1 (a[1] = +-1 multiplies / divides the shot's speed by it), got {cfg.candidate_speed_factor}")
    players = tuple(game_spec(cfg.task).session_class.players) if cfg.task in GAMES else OPPONENTS
    _require(cfg.opponent is None or cfg.opponent in players, "opponent",
             f"unknown player {cfg.opponent!r}; use one of {', '.join(map(repr, players))} or None (play alone)")
    if game:
        spec = game_spec(cfg.task)
        _require(cfg.n_object_balls == spec.n_object_balls, "n_object_balls",
                 f"{cfg.task} is played with {spec.n_object_balls} object balls, got {cfg.n_object_balls}")
        try:
            spec.session_class.options(cfg.rules)
        except (RulesError, TypeError) as exc:
            raise ConfigError(f"rules: {exc}") from None
        openings = spec.session_class.openings
        _require(cfg.opening in openings, "opening",
                 f"{cfg.task} opens with {' or '.join(map(repr, openings))}, got {cfg.opening!r}")
    else:
        _require(not cfg.rules, "rules", f"only the games (task {' or '.join(map(repr, GAMES))}) have rules")
    for key in ("cushion_margin", "pocket_margin", "ball_gap", "rack_gap", "angle_noise", "speed_noise", "tip_noise",
                "pot_reward", "scratch_penalty", "miss_penalty", "step_penalty", "win_reward", "loss_penalty",
                "foul_penalty", "position_reward"):
        v = getattr(cfg, key)
        _require(v >= 0, key, f"must be >= 0, got {v}" + (
            " (penalties are magnitudes: a positive value is subtracted from the reward)" if "penalty" in key else ""))
    for key in ("ball_radius", "ball_mass", "max_time"):
        v = getattr(cfg, key)
        _require(v > 0, key, f"must be > 0, got {v}")
    _require(0 < cfg.ghost_max_angle <= 90, "ghost_max_angle", f"must be in (0, 90] degrees, got {cfg.ghost_max_angle}")
    _require(0 < cfg.max_tip_offset <= 0.5, "max_tip_offset",
             f"must be in (0, 0.5] (fraction of the ball radius; 0.5 is the miscue limit), got {cfg.max_tip_offset}")
    spin = cfg.physics.has_spin
    _require(spin or not cfg.spin_action, "spin_action",
             f"needs the spin model: add friction='spin' (the physics friction is {cfg.physics.friction!r})")
    _require(spin or cfg.tip_noise == 0, "tip_noise", "needs the spin model: add friction='spin'")
    _require(cfg.speed_min >= 0, "speed_min", f"must be >= 0 m/s, got {cfg.speed_min}")
    _require(cfg.speed_max > cfg.speed_min, "speed_max",
             f"must be greater than speed_min ({cfg.speed_min} m/s), got {cfg.speed_max}; the speed range is "
             "[speed_min, speed_max]")
    _require(cfg.speed_max <= MAX_BALL_SPEED, "speed_max",
             f"{cfg.speed_max} m/s is faster than any ball can move here (at most {MAX_BALL_SPEED:g} m/s; the hardest "
             "break is about 15 m/s)")
    _require(cfg.max_events >= 1, "max_events", f"must be >= 1, got {cfg.max_events}")
    _require(cfg.max_shots >= 1, "max_shots", f"must be >= 1, got {cfg.max_shots}")
    _require(64 <= cfg.render_width <= 8192, "render_width", f"must be 64..8192 pixels, got {cfg.render_width}")
    _require(1 <= cfg.render_fps <= 1000, "render_fps", f"must be 1..1000, got {cfg.render_fps}")
    _require(cfg.render_speedup > 0, "render_speedup", f"must be > 0, got {cfg.render_speedup}")
    _require(cfg.render_max_frames >= 0, "render_max_frames",
             f"must be >= 0 (0: no cap), got {cfg.render_max_frames}")
    t = cfg.table
    r = cfg.ball_radius
    _require(4 * r < min(t.length, t.width), "ball_radius",
             f"{r} m is too large for a {t.length} x {t.width} m table")
    if cfg.placement == "random":
        free = min(t.length, t.width) - 2 * (r + cfg.cushion_margin)
        _require(free > 0, "cushion_margin", f"{cfg.cushion_margin} m leaves no room on the table; lower it")
    elif cfg.placement in own:  # the game's own layout: its ball count is the game's (checked above)
        pass
    elif cfg.placement == "diamond":
        _require(n == 9, "placement", f"'diamond' racks 9 object balls, got n_object_balls {n}")
        _require(rack_fits(t, 15, r, cfg.rack_gap), "rack_gap",
                 f"a diamond with gap {cfg.rack_gap} m does not fit on the table; lower rack_gap")
    else:
        _require(rack_fits(t, n, r, cfg.rack_gap), "rack_gap",
                 f"a {n}-ball rack with gap {cfg.rack_gap} m does not fit on the table; lower rack_gap")


def config_table_markdown() -> str:
    """The keys as a Markdown table (for docs)."""
    lines = ["| key | default | meaning |", "|---|---|---|"]
    for f in fields(EnvConfig):
        lines.append(f"| `{f.name}` | `{_default_text(f)}` | {f.metadata['doc']} |")
        if f.name in SECTIONS:
            for k, v in _section_dict(f.name, _default(f)).items():
                lines.append(f"| `{f.name}.{k}` | `{v!r}` | |")
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover - old habit; the key listing is `python -m billiards_env.envs`
    import sys

    from .__main__ import main

    print("note: the listing is `python -m billiards_env.envs` (this module is imported by its package before it "
          "runs, hence runpy's RuntimeWarning)", file=sys.stderr)
    sys.exit(main(sys.argv[1:]))
