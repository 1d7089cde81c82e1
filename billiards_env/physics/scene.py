"""Scene files: a table, physics parameters, balls, and optionally a shot and solver settings (JSON/YAML dicts).

Every field is checked; an error names the field (``balls[2].radius``) and what to do about it.
See the README for the full format and an example.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, fields
from pathlib import Path
from typing import Any, Mapping

import numpy as np

from .balls import BALL_MASS, BALL_RADIUS, Balls, check_speed, validate_balls
from .errors import SceneError, check_finite, check_non_negative, check_number, check_positive
from .model import Physics
from .result import ShotResult
from .simulate import DEFAULT_DT, DEFAULT_MAX_EVENTS, DEFAULT_MAX_TIME, Simulator, SolverSettings
from .pocket_specs import PocketSpecs
from .table import (CORNER_POCKET_RADIUS, POCKET_MODELS, SIDE_POCKET_RADIUS, TABLE_PRESETS, Table, capture_table,
                    default_pockets, jaw_table)

TABLE_FIELDS = {"preset", "length", "width", "cushion_restitution", "pockets", "corner_pocket_radius",
                "side_pocket_radius", "specs"}
POCKET_FIELDS = {"x", "y", "radius"}
#: The physics section's fields are :class:`Physics`'s (one set of names and defaults for scenes and envs), and
#: ``preset``: a named set of them (:data:`.model.PRESETS`) that the fields given override.
PHYSICS_FIELDS = {f.name for f in fields(Physics)} | {"preset"}
#: Physics fields that may be null (None: see :class:`Physics`).
NULLABLE_PHYSICS_FIELDS = {"cushion_height"}
BALL_FIELDS = {"id", "x", "y", "vx", "vy", "wx", "wy", "wz", "radius", "mass"}
SHOT_FIELDS = {"ball", "angle", "speed", "side", "top"}
SOLVER_FIELDS = {"name", "dt", "contact"}
SCENE_FIELDS = {"table", "physics", "balls", "shot", "solver", "max_time", "max_events"}


@dataclass(frozen=True)
class Shot:
    """Strike ball ``ball`` at ``speed`` m/s in direction ``angle`` rad (0 = +x, counter-clockwise), with the cue
    tip ``side`` and ``top`` ball radii off centre (spin model; see :meth:`.Balls.strike`)."""

    ball: str
    angle: float
    speed: float
    side: float = 0.0
    top: float = 0.0


@dataclass(frozen=True)
class Scene:
    table: Table
    physics: Physics
    balls: Balls
    shot: Shot | None = None
    solver: str = "exact"
    dt: float = DEFAULT_DT
    contact: str = "lecture"
    max_time: float = DEFAULT_MAX_TIME
    max_events: int = DEFAULT_MAX_EVENTS

    def simulator(self, solver: str | None = None, dt: float | None = None, contact: str | None = None) -> Simulator:
        """A simulator for this scene; arguments override the scene's solver settings."""
        return Simulator(self.table, self.physics, solver=solver or self.solver,
                         dt=self.dt if dt is None else dt, contact=contact or self.contact,
                         max_time=self.max_time, max_events=self.max_events)

    def initial_balls(self) -> Balls:
        """The balls with the shot applied (if the scene has one)."""
        if self.shot is None:
            return self.balls.copy()
        return self.balls.strike(self.shot.ball, self.shot.angle, self.shot.speed, side=self.shot.side,
                                 top=self.shot.top, physics=self.physics)

    def run(self, solver: str | None = None, dt: float | None = None, contact: str | None = None,
            record: bool = False) -> ShotResult:
        """Strike (if the scene has a shot) and simulate until rest or a cap."""
        return self.simulator(solver, dt, contact).run(self.initial_balls(), record=record)

    @classmethod
    def load(cls, path: str | Path, preset: str | None = None) -> "Scene":
        """Read a scene from a JSON (or YAML, by extension) file. ``preset``: play it under this physics preset
        (:data:`.model.PRESETS`) instead of the file's physics section."""
        data = read_scene_file(path)
        if preset is not None and isinstance(data, Mapping):
            data = {**data, "physics": {"preset": preset}}
        return cls.from_dict(data)

    @classmethod
    def from_dict(cls, data: Any) -> "Scene":
        """Build and check a scene from a parsed JSON/YAML document."""
        d = _mapping("scene", data, SCENE_FIELDS)
        table = parse_table(d.get("table", {}))
        physics = parse_physics(d.get("physics", {}))
        if "balls" not in d:
            raise SceneError("scene: missing 'balls'; give a list of balls, e.g. [{\"id\": \"cue\", \"x\": 0.6, \"y\": 0.6}]")
        balls = _balls(d["balls"])
        validate_balls(balls, table, allow_spin=physics.has_spin)
        physics.check_cushion_height(balls.radius)
        shot = _shot(d["shot"], balls, physics) if d.get("shot") is not None else None
        solver = parse_solver(d.get("solver", {}))
        max_time = check_positive("max_time", d.get("max_time", DEFAULT_MAX_TIME))
        max_events = d.get("max_events", DEFAULT_MAX_EVENTS)
        if isinstance(max_events, bool) or not isinstance(max_events, int) or max_events < 1:
            raise SceneError(f"max_events: must be a positive integer, got {max_events!r}")
        scene = cls(table, physics, balls, shot, solver=solver.name, dt=solver.dt, contact=solver.contact,
                    max_time=max_time, max_events=max_events)
        scene.simulator()  # checks solver name, contact and dt
        if shot is not None:
            scene.initial_balls()  # checks the shot (e.g. the tip offset's miscue limit)
        return scene


def read_scene_file(path: str | Path) -> Any:
    """The parsed document of a scene file (JSON, or YAML by extension), unchecked."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except OSError as exc:
        raise SceneError(f"{path}: cannot read the scene file ({exc.strerror})") from None
    except UnicodeDecodeError:
        raise SceneError(f"{path}: not UTF-8 text; save the scene as UTF-8 JSON or YAML") from None
    if p.suffix.lower() in (".yaml", ".yml"):
        import yaml

        try:
            data = yaml.safe_load(text)
        except yaml.YAMLError as exc:
            raise SceneError(f"{path}: not valid YAML ({exc})") from None
    else:
        try:
            data = json.loads(text)
        except json.JSONDecodeError as exc:
            raise SceneError(f"{path}: not valid JSON: {exc.msg} at line {exc.lineno} column {exc.colno}") from None
        except ValueError as exc:  # e.g. an integer literal longer than Python's digit limit
            raise SceneError(f"{path}: not valid JSON: {exc}") from None
    return data


def _mapping(name: str, value: Any, allowed: set[str]) -> Mapping[str, Any]:
    if not isinstance(value, Mapping):
        raise SceneError(f"{name}: expected an object with fields {sorted(allowed)}, got {type(value).__name__}")
    unknown = sorted(set(map(str, value)) - allowed)
    if unknown:
        raise SceneError(f"{name}: unknown field(s) {unknown}; allowed: {sorted(allowed)}")
    return value


def _string(name: str, value: Any) -> str:
    if not isinstance(value, str):
        raise SceneError(f"{name}: expected a string, got {value!r}")
    return value


def parse_table(value: Any, where: str = "table") -> Table:
    """A :class:`Table` from a scene's (or an env config's) ``table`` section.

    ``preset`` (:data:`.table.TABLE_PRESETS`: ``pool``, ``snooker``, ``carom`` with capture circles or no pockets;
    ``wpa``, ``pooltool``, ``snooker_match`` with jaws), whose fields the others given override; ``specs`` (the
    fields of :class:`.pocket_specs.PocketSpecs`, over the preset's); ``pockets``: the pocket model, ``jaws`` (the
    default with specs) or ``capture``, or a list of capture circles ``{x, y, radius}`` (``[]`` for none);
    ``length``, ``width``, ``cushion_restitution``; under the capture model the radii of the six standard pockets,
    ``corner_pocket_radius`` and ``side_pocket_radius``."""
    t = _mapping(where, value, TABLE_FIELDS)
    base: Table | None = None
    if "preset" in t:
        name = _string(f"{where}.preset", t["preset"])
        if name not in TABLE_PRESETS:
            raise SceneError(f"{where}.preset: unknown table {name!r}; use one of {', '.join(TABLE_PRESETS)}")
        base = TABLE_PRESETS[name]()
    specs = base.specs if base is not None else None
    model = base.pocket_model if base is not None else "capture"
    if "specs" in t:
        given = t["specs"]
        if isinstance(given, Mapping):
            given = {**(specs.to_dict() if specs is not None else {}), **given}
        specs = PocketSpecs.from_dict(given, f"{where}.specs")
        model = "jaws"
    pockets = t.get("pockets")
    if isinstance(pockets, str):
        if pockets not in POCKET_MODELS:
            raise SceneError(f"{where}.pockets: unknown pocket model {pockets!r}; use one of "
                             f"{', '.join(POCKET_MODELS)}, or a list of capture circles {{x, y, radius}}")
        model = pockets
    elif pockets is not None:
        model = "capture"
    e_c = check_number(f"{where}.cushion_restitution", t["cushion_restitution"]) if "cushion_restitution" in t \
        else (base.cushion_restitution if base is not None else Table.cushion_restitution)
    if model == "jaws":
        if specs is None:
            raise SceneError(f"{where}.pockets: 'jaws' needs the table's geometry: give {where}.specs or a preset "
                             "with jaws (wpa, pooltool, snooker_match)")
        for f in ("corner_pocket_radius", "side_pocket_radius"):
            if f in t:
                raise SceneError(f"{where}.{f}: a jaw table's pocket circles are set in {where}.specs "
                                 f"({f}, and the pocket's depth); move it there")
        size = {k: check_positive(f"{where}.{f}", t[f]) for k, f in (("l", "length"), ("w", "width")) if f in t}
        if size:
            specs = PocketSpecs.from_dict({**specs.to_dict(), **size}, f"{where}.specs")
        return jaw_table(specs, e_c)
    kw: dict[str, Any] = {}
    if base is not None:
        if specs is not None and base.has_jaws:  # a jaw preset under the capture model: its calibrated circles
            base = capture_table(specs, cushion_restitution=e_c)
        kw = {"length": base.length, "width": base.width, "pocket_xy": base.pocket_xy,
              "pocket_radius": base.pocket_radius}
    elif specs is not None:
        base = capture_table(specs, cushion_restitution=e_c)
        kw = {"length": base.length, "width": base.width, "pocket_xy": base.pocket_xy,
              "pocket_radius": base.pocket_radius}
    kw["cushion_restitution"] = e_c
    for f in ("length", "width"):
        if f in t:
            kw[f] = check_number(f"{where}.{f}", t[f])
    radii = {f: check_positive(f"{where}.{f}", t[f]) for f in ("corner_pocket_radius", "side_pocket_radius") if f in t}
    if radii and isinstance(pockets, list):
        raise SceneError(f"{where}: give either 'pockets' (a list) or corner_pocket_radius/side_pocket_radius, "
                         "not both")
    if radii:
        kw["pocket_xy"], kw["pocket_radius"] = default_pockets(
            kw.get("length", Table.length), kw.get("width", Table.width),
            radii.get("corner_pocket_radius", CORNER_POCKET_RADIUS), radii.get("side_pocket_radius", SIDE_POCKET_RADIUS))
    if isinstance(pockets, list) or (pockets is not None and not isinstance(pockets, str)):
        if not isinstance(pockets, list):
            raise SceneError(f"{where}.pockets: expected 'jaws', 'capture' or a list of {{x, y, radius}} objects "
                             "([] for no pockets)")
        xy = np.zeros((len(pockets), 2))
        r = np.zeros(len(pockets))
        for k, p in enumerate(pockets):
            pm = _mapping(f"{where}.pockets[{k}]", p, POCKET_FIELDS)
            for f in POCKET_FIELDS:
                if f not in pm:
                    raise SceneError(f"{where}.pockets[{k}]: missing '{f}'")
            xy[k] = (check_finite(f"{where}.pockets[{k}].x", pm["x"]),
                     check_finite(f"{where}.pockets[{k}].y", pm["y"]))
            r[k] = check_positive(f"{where}.pockets[{k}].radius", pm["radius"])
        kw["pocket_xy"] = xy
        kw["pocket_radius"] = r
    return Table(**kw)


def parse_physics(value: Any, where: str = "physics") -> Physics:
    """A :class:`Physics` from a scene's (or an env config's) ``physics`` section: the fields of Physics, and
    ``preset`` (a name of :data:`.model.PRESETS`, e.g. ``"pooltool"``), whose values the fields given override."""
    p = _mapping(where, value, PHYSICS_FIELDS)
    kw: dict[str, Any] = {}
    for f in fields(Physics):
        if f.name in p:
            if f.name in NULLABLE_PHYSICS_FIELDS and p[f.name] is None:
                kw[f.name] = None
            elif f.type in ("str", str):
                kw[f.name] = _string(f"{where}.{f.name}", p[f.name])
            else:
                kw[f.name] = check_number(f"{where}.{f.name}", p[f.name])
    preset = p.get("preset")
    if preset is not None:
        return Physics.from_preset(_string(f"{where}.preset", preset), **kw)
    return Physics(**kw)


def parse_solver(value: Any, where: str = "solver") -> SolverSettings:
    """The ``solver`` section: a mapping ``{name, dt, contact}`` or just the solver's name."""
    if isinstance(value, str):
        value = {"name": value}
    s = _mapping(where, value, SOLVER_FIELDS)
    return SolverSettings(_string(f"{where}.name", s.get("name", "exact")),
                          check_positive(f"{where}.dt", s.get("dt", DEFAULT_DT)),
                          _string(f"{where}.contact", s.get("contact", "lecture")))


def table_to_dict(table: Table) -> dict[str, Any]:
    """The ``table`` section that :func:`parse_table` reads back into ``table``."""
    if table.has_jaws:
        assert table.specs is not None
        return {"specs": table.specs.to_dict(), "pockets": "jaws", "cushion_restitution": table.cushion_restitution}
    return {"length": table.length, "width": table.width, "cushion_restitution": table.cushion_restitution,
            "pockets": [{"x": float(x), "y": float(y), "radius": float(r)}
                        for (x, y), r in zip(table.pocket_xy.tolist(), table.pocket_radius.tolist())]}


def _balls(value: Any) -> Balls:
    if not isinstance(value, list):
        raise SceneError("balls: expected a list of ball objects with at least x and y")
    if not value:
        raise SceneError("balls: the scene has no balls; add at least one")
    n = len(value)
    ids, pos, vel, ang = [], np.zeros((n, 2)), np.zeros((n, 2)), np.zeros((n, 3))
    radius, mass = np.full(n, BALL_RADIUS), np.full(n, BALL_MASS)
    for i, b in enumerate(value):
        name = f"balls[{i}]"
        bm = _mapping(name, b, BALL_FIELDS)
        for f in ("x", "y"):
            if f not in bm:
                raise SceneError(f"{name}: missing '{f}'")
        bid = bm.get("id", "cue" if i == 0 else str(i))
        if not isinstance(bid, (str, int)) or isinstance(bid, bool):
            raise SceneError(f"{name}.id: expected a string, got {bid!r}")
        ids.append(str(bid))
        pos[i] = (check_finite(f"{name}.x", bm["x"]), check_finite(f"{name}.y", bm["y"]))
        vel[i] = (check_finite(f"{name}.vx", bm.get("vx", 0.0)), check_finite(f"{name}.vy", bm.get("vy", 0.0)))
        ang[i] = [check_finite(f"{name}.{f}", bm.get(f, 0.0)) for f in ("wx", "wy", "wz")]
        radius[i] = check_positive(f"{name}.radius", bm.get("radius", BALL_RADIUS))
        mass[i] = check_positive(f"{name}.mass", bm.get("mass", BALL_MASS))
    return Balls(tuple(ids), pos, vel, radius, mass, np.ones(n, dtype=bool), ang)


def _shot(value: Any, balls: Balls, physics: Physics) -> Shot:
    s = _mapping("shot", value, SHOT_FIELDS)
    ball = s.get("ball", balls.ids[0])
    if str(ball) not in balls.ids:
        raise SceneError(f"shot.ball: unknown ball id {ball!r}; the scene's balls are {', '.join(balls.ids)}")
    for f in ("angle", "speed"):
        if f not in s:
            raise SceneError(f"shot: missing '{f}' (angle in radians, speed in m/s)")
    angle = check_finite("shot.angle", s["angle"])
    speed = check_speed("shot.speed", check_non_negative("shot.speed", s["speed"]))
    side = check_finite("shot.side", s.get("side", 0.0))
    top = check_finite("shot.top", s.get("top", 0.0))
    if (side != 0.0 or top != 0.0) and physics.friction != "spin":
        raise SceneError(f"shot.side, shot.top: ({side}, {top}) puts spin on the ball, but spin needs "
                         f"physics.friction 'spin' (the scene's is {physics.friction!r}); set it, or strike with "
                         "side = top = 0")
    return Shot(str(ball), angle, speed, side, top)
