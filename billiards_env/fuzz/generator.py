"""Random scenes and shots for the fuzz command and the stability tests.

:func:`random_scene` makes a scene dict in the scene-file format of :mod:`billiards_env.physics.scene`: 1 to 16
balls placed at random (touching each other and the cushions on purpose, in corners, as racks), a random
friction law and constants, restitutions and solver settings, and a random cue strike. It draws every decision
through a small :class:`Source` interface: :class:`NumpySource` for the fuzz (shot ``i`` of seed ``S`` from
:func:`shot_rng`), a Hypothesis-backed source in ``tests/stability``, so both drive the very same generator and
Hypothesis can shrink its draws.
"""
from __future__ import annotations

import math
from typing import Any, Sequence

import numpy as np

from ..physics.layout import triangle_positions

DEFAULT_MAX_TIME = 60.0
DEFAULT_STEP_MAX_TIME = 20.0
DEFAULT_MAX_EVENTS = 20_000
STEP_DTS = (5e-4, 1e-3, 2e-3)
CONTACT_MODES = ("lecture", "rewind")
TABLE_KINDS = ("rect", "jaws")
#: The jaw presets the fuzz draws from (:data:`billiards_env.physics.table.TABLE_PRESETS`).
JAW_PRESETS = ("wpa", "pooltool", "snooker_match")

L_DEFAULT = 2.54
W_DEFAULT = 1.27
R_DEFAULT = 0.028575


# --------------------------------------------------------------------------------------------- random source
class Source:
    """Where the scene generator gets its random decisions (numpy for the fuzz, Hypothesis in the tests)."""

    def uniform(self, lo: float, hi: float) -> float:
        raise NotImplementedError

    def integer(self, lo: int, hi: int) -> int:
        """An integer in ``[lo, hi]`` (both included)."""
        raise NotImplementedError

    def choice(self, options: Sequence[Any]) -> Any:
        return options[self.integer(0, len(options) - 1)]

    def chance(self, p: float) -> bool:
        return self.uniform(0.0, 1.0) < p

    def log_uniform(self, lo: float, hi: float) -> float:
        return float(math.exp(self.uniform(math.log(lo), math.log(hi))))


class NumpySource(Source):
    def __init__(self, rng: np.random.Generator) -> None:
        self.rng = rng

    def uniform(self, lo: float, hi: float) -> float:
        return float(self.rng.uniform(lo, hi))

    def integer(self, lo: int, hi: int) -> int:
        return int(self.rng.integers(lo, hi + 1))


def shot_rng(seed: int, index: int) -> np.random.Generator:
    """The random generator of shot ``index`` of a fuzz run with ``seed``: every shot is reproducible alone."""
    return np.random.default_rng(np.random.SeedSequence([int(seed), int(index)]))



# --------------------------------------------------------------------------------------------- scene generator
def _unit_or_special(src: Source) -> float:
    """A restitution: the ends 0 and 1 often, otherwise uniform."""
    return float(src.choice((0.0, 1.0, src.uniform(0.0, 1.0), src.uniform(0.0, 1.0), src.uniform(0.9, 1.0))))


def _fits(p: tuple[float, float], placed: list[tuple[float, float]], r: float, length: float, width: float) -> bool:
    x, y = p
    if not (r <= x <= length - r and r <= y <= width - r):
        return False
    for q in placed:
        # validate_balls accepts overlaps up to 1e-9; touching placements from cos/sin are off by ~1e-17.
        if math.hypot(x - q[0], y - q[1]) < 2.0 * r - 1e-12:
            return False
    return True


def _gap(src: Source) -> float:
    return float(src.choice((0.0, 0.0, 0.0, 1e-12, src.log_uniform(1e-12, 1e-3), src.uniform(0.0, 0.05))))


def _place(src: Source, placed: list[tuple[float, float]], r: float, length: float, width: float
           ) -> tuple[float, float] | None:
    """One more ball position (or None if the drawn placement does not fit)."""
    mode = src.choice(("free", "free", "touch_ball", "touch_ball", "touch_cushion", "touch_both", "corner"))
    if mode == "free" or not placed and mode in ("touch_ball", "touch_both"):
        p = (src.uniform(r, length - r), src.uniform(r, width - r))
    elif mode == "touch_ball":
        q = placed[src.integer(0, len(placed) - 1)]
        th = src.choice((src.uniform(-math.pi, math.pi), src.integer(0, 11) * math.pi / 6.0))
        d = 2.0 * r + _gap(src)
        p = (q[0] + d * math.cos(th), q[1] + d * math.sin(th))
    elif mode == "touch_cushion":
        side = src.integer(0, 3)
        if side < 2:
            p = (r if side == 0 else length - r, src.uniform(r, width - r))
        else:
            p = (src.uniform(r, length - r), r if side == 2 else width - r)
    elif mode == "touch_both":  # on a cushion and touching a ball
        q = placed[src.integer(0, len(placed) - 1)]
        side = src.integer(0, 3)
        d = 2.0 * r + _gap(src)
        sgn = src.choice((-1.0, 1.0))
        if side < 2:
            x = r if side == 0 else length - r
            h = d * d - (x - q[0]) ** 2
            if h < 0.0:
                return None
            p = (x, q[1] + sgn * math.sqrt(h))
        else:
            y = r if side == 2 else width - r
            h = d * d - (y - q[1]) ** 2
            if h < 0.0:
                return None
            p = (q[0] + sgn * math.sqrt(h), y)
    else:  # corner
        p = (src.choice((r, length - r)), src.choice((r, width - r)))
    return p if _fits(p, placed, r, length, width) else None


def _rack(src: Source, n: int, r: float, length: float, width: float) -> list[tuple[float, float]]:
    gap = float(src.choice((0.0, 0.0, 1e-12, src.log_uniform(1e-12, 1e-4))))
    apex = (0.75 * length, 0.5 * width)
    tri = triangle_positions(apex, r, gap=gap)
    cue = (src.choice((0.25 * length, src.uniform(r, 0.6 * length))), src.choice((0.5 * width, src.uniform(r, width - r))))
    return [cue] + [(float(x), float(y)) for x, y in tri[: n - 1]]


def random_scene(src: Source, solver: str | None = None, max_time: float | None = None,
                 max_events: int = DEFAULT_MAX_EVENTS, spin: float = 0.0, models: float = 0.0,
                 preset: str | None = None, table: str = "rect") -> dict[str, Any]:
    """A random scene dict in the scene-file format, with a shot and solver settings.

    ``solver``: ``"exact"``, ``"step"`` or None (drawn). The cue is ball 0 (id ``"cue"``). ``spin``: the chance
    that the scene uses the spin model (:func:`spin_physics`); its draws come after all the others, so with the
    default 0 a seed gives the same rolling/drag scenes as before the spin model existed. ``models``: the chance
    that a spin-model scene also draws the optional collision models (:func:`model_physics`). ``preset``: every
    scene uses the spin model with this physics preset (``{"preset": name}``; the tip offsets and spinning balls
    drawn as for the spin model). The draws of ``models`` and ``preset`` come last too: without them a seed gives
    the same scenes as before they existed. ``table``: ``"rect"`` (the capture-pocket table of ``L_DEFAULT`` x
    ``W_DEFAULT``, as before) or ``"jaws"`` (:func:`jaw_specs`: a jaw preset with its specs perturbed; the balls
    placed as on the rectangle, those that overlap a wall there dropped, and some put into the mouths by
    :func:`mouth_balls`; its draws come first and last, so ``"rect"`` scenes stay the same).
    """
    if table not in TABLE_KINDS:
        raise ValueError(f"table: {table!r} is not one of {', '.join(TABLE_KINDS)}")
    length, width, r = L_DEFAULT, W_DEFAULT, R_DEFAULT
    jaws = None
    if table == "jaws":
        jaws = jaw_specs(src)
        length, width = jaws["specs"]["l"], jaws["specs"]["w"]
    # table
    table_d: dict[str, Any] = {"length": length, "width": width, "cushion_restitution": _unit_or_special(src)}
    if src.chance(0.3) and jaws is None:
        table_d["pockets"] = []
    # physics
    friction = src.choice(("rolling", "drag"))
    physics: dict[str, Any] = {"friction": friction, "ball_restitution": _unit_or_special(src)}
    if friction == "rolling":
        physics["mu_roll"] = float(src.choice((0.0, 0.01, src.uniform(0.0, 0.05), src.uniform(0.0, 0.05))))
        physics["min_speed"] = float(src.choice((0.0, 0.0, 0.0, src.uniform(0.0, 0.05))))
    else:
        physics["drag_k"] = float(src.choice((0.0, src.uniform(0.0, 2.0), src.uniform(0.0, 2.0))))
        physics["min_speed"] = float(src.choice((0.0, 0.01, src.uniform(0.0, 0.05), src.uniform(0.0, 0.05))))
    # balls
    n = src.integer(1, 16)
    if n >= 2 and src.chance(0.15):
        placed = _rack(src, n, r, length, width)
    else:
        placed = []
        for _ in range(n):
            p = _place(src, placed, r, length, width)
            if p is not None:
                placed.append(p)
        if not placed:
            placed.append((src.uniform(r, length - r), src.uniform(r, width - r)))
    if jaws is not None:
        placed = mouth_balls(src, jaws, placed, r)
    balls = [{"id": "cue" if i == 0 else str(i), "x": float(x), "y": float(y)} for i, (x, y) in enumerate(placed)]
    # shot: a random direction, or aimed at a ball (head-on, tiny offset, or grazing at 2R +- eps), or a cushion
    aim = src.choice(("random", "random", "ball", "ball", "axis"))
    cx, cy = placed[0]
    if aim == "ball" and len(placed) > 1:
        tx, ty = placed[src.integer(1, len(placed) - 1)]
        d = math.hypot(tx - cx, ty - cy)
        base = math.atan2(ty - cy, tx - cx)
        off = src.choice(("head", "head", "tiny", "graze"))
        if off == "head":
            angle = base
        elif off == "tiny":
            angle = base + src.choice((-1.0, 1.0)) * src.log_uniform(1e-15, 1e-3)
        else:
            b = 2.0 * r + src.choice((-1.0, 1.0)) * float(src.choice((0.0, src.log_uniform(1e-14, 1e-4))))
            angle = base + src.choice((-1.0, 1.0)) * math.asin(min(b / d, 1.0))
    elif aim == "axis":
        angle = src.integer(0, 7) * math.pi / 4.0
    else:
        angle = src.uniform(-math.pi, math.pi)
    speed = src.log_uniform(1e-3, 10.0)
    # solver
    if solver is None:
        solver = src.choice(("exact", "step"))
    solver_d: dict[str, Any] = {"name": solver}
    if solver == "step":
        solver_d["dt"] = float(src.choice(STEP_DTS))
        solver_d["contact"] = src.choice(CONTACT_MODES)
    if max_time is None:
        max_time = DEFAULT_MAX_TIME if solver == "exact" else DEFAULT_STEP_MAX_TIME
    scene = {"table": table_d, "physics": physics, "balls": balls,
             "shot": {"ball": "cue", "angle": float(angle), "speed": float(speed)},
             "solver": solver_d, "max_time": float(max_time), "max_events": int(max_events)}
    if jaws is not None:
        scene["table"] = {"preset": jaws["preset"], "specs": jaws["specs"],
                          "cushion_restitution": table_d["cushion_restitution"]}
    if preset is not None:
        spin_physics(src, scene)
        scene["physics"] = {"preset": preset}
    elif spin >= 1.0 or (spin > 0.0 and src.chance(spin)):
        spin_physics(src, scene)
        if models >= 1.0 or (models > 0.0 and src.chance(models)):
            model_physics(src, scene)
    return scene


def model_physics(src: Source, scene: dict[str, Any]) -> None:
    """Add the spin model's optional collision models to a spin-model ``scene``, in place: ball-ball friction
    ``frictionless`` or ``alciatore`` (its constants near Alciatore's or random), cushion ``impulse``, ``stronge``
    or ``mathavan``, the cushion nose at the equator or anywhere in ``[R, 2R)``, Stronge's frequency ratio anywhere
    in (1, 2), squirt off, full or partial."""
    ph = scene["physics"]
    if src.chance(0.6):
        ph["ball_ball"] = "alciatore"
        ph["ball_friction"] = 0.0
        if src.chance(0.5):
            ph["alciatore_a"] = src.uniform(0.0, 0.1)
            ph["alciatore_b"] = src.uniform(0.0, 0.5)
            ph["alciatore_c"] = src.uniform(0.0, 5.0)
    ph["cushion"] = src.choice(("impulse", "stronge", "stronge", "mathavan"))
    if src.chance(0.7):
        ph["cushion_height"] = float(src.choice((0.036576, R_DEFAULT, src.uniform(R_DEFAULT, 1.999 * R_DEFAULT))))
    if src.chance(0.5):
        ph["omega_ratio"] = src.uniform(1.001, 1.999)
    ph["squirt"] = float(src.choice((0.0, 1.0, src.uniform(0.0, 1.0))))


def spin_physics(src: Source, scene: dict[str, Any]) -> None:
    """Turn ``scene`` (from :func:`random_scene`) into a spin-model scene, in place: random sliding, rolling and
    spinning friction (the defaults, random values, now and then 0), ball-ball friction (throw) and cushion
    friction, the ball restitution kept; a random tip offset anywhere on the disc ``side^2 + top^2 <= 0.25``
    (its edge included); now and then object balls that already spin."""
    e_b = scene["physics"]["ball_restitution"]

    def friction(default: float, hi: float) -> float:  # now and then 0: that ball or spin never stops
        return 0.0 if src.chance(0.04) else float(src.choice((default, src.uniform(0.0, hi))))

    scene["physics"] = {"friction": "spin", "ball_restitution": e_b, "mu_slide": friction(0.2, 0.5),
                        "mu_roll": friction(0.01, 0.05), "mu_spin": friction(0.0127, 0.05),
                        "ball_friction": float(src.choice((0.0, 0.0, 0.06, src.uniform(0.0, 0.5)))),
                        "cushion_friction": friction(0.2, 1.0)}
    radius = src.choice((0.0, src.uniform(0.0, 0.5), src.uniform(0.0, 0.5), 0.5))
    phi = src.uniform(-math.pi, math.pi)
    side, top = radius * math.cos(phi), radius * math.sin(phi)
    if side * side + top * top > 0.25:  # rounding on the edge
        side, top = side * (1 - 1e-15), top * (1 - 1e-15)
    scene["shot"]["side"] = float(side)
    scene["shot"]["top"] = float(top)
    for ball in scene["balls"][1:]:
        if src.chance(0.1):
            ball["wx"], ball["wy"], ball["wz"] = (float(src.uniform(-100.0, 100.0)) for _ in range(3))



# --------------------------------------------------------------------------------------------- jaw tables
def jaw_specs(src: Source) -> dict[str, Any]:
    """A random jaw table: ``{"preset": name, "specs": fields}``, a preset of :data:`JAW_PRESETS` whose spec fields
    are each, now and then, perturbed (lengths by up to 25 %, angles by up to 8 degrees); a perturbation that makes
    no table (:class:`~billiards_env.physics.pocket_specs.PocketSpecs` refuses it), a mouth a ball cannot pass or a
    throat a ball can leave past the pocket circle (:func:`~billiards_env.physics.pocket_specs.throat_leak`) is
    dropped, field by field."""
    from ..physics.errors import SceneError
    from ..physics.pocket_specs import throat_leak
    from ..physics.table import TABLE_PRESETS

    name = src.choice(JAW_PRESETS)
    base = TABLE_PRESETS[name]().specs
    specs = base.to_dict()
    for key in sorted(specs):
        if not src.chance(0.3):
            continue
        old = specs[key]
        if key.endswith("angle"):
            specs[key] = float(old + src.uniform(-8.0, 8.0))
        elif key in ("l", "w"):
            specs[key] = float(old * src.uniform(0.9, 1.1))
        else:
            specs[key] = float(old * src.uniform(0.75, 1.25))
        try:
            ok = type(base)(**specs)
            ok = (ok.corner_pocket_width > 2.0 * R_DEFAULT + 1e-3 and ok.side_pocket_width > 2.0 * R_DEFAULT + 1e-3
                  and throat_leak(ok, R_DEFAULT) is None)
        except SceneError:
            ok = False
        if not ok:
            specs[key] = old
    return {"preset": name, "specs": specs}


def mouth_balls(src: Source, jaws: dict[str, Any], placed: list[tuple[float, float]], r: float
                ) -> list[tuple[float, float]]:
    """The balls of a jaw-table scene: those of ``placed`` (drawn on the rectangle) that overlap no wall, then now
    and then a few more in the mouths: anywhere in a mouth or throat, against a jaw face, at a jaw tip's tangent
    point, or touching the ball placed before (two balls jammed in a mouth). The first ball kept is the cue; if every ball
    overlapped a wall, one at the table's centre is."""
    from ..physics.pocket_specs import (PocketSpecs, build_walls, clear_of_walls, in_mouth, mouth_polygons,
                                        pocket_circles)

    specs = PocketSpecs(**jaws["specs"])
    segs, tips = build_walls(specs)
    pxy, pr = pocket_circles(specs)
    polys = mouth_polygons(segs, tips)
    n_rails = len(segs) - len(tips)

    def free(p: tuple[float, float], balls: list[tuple[float, float]]) -> bool:
        x, y = p
        if not (math.isfinite(x) and math.isfinite(y)) or not clear_of_walls(segs, tips, x, y, r, 0.0):
            return False
        inside = r <= x <= specs.l - r and r <= y <= specs.w - r
        if not inside and not in_mouth(segs, tips, pxy, pr, x, y, r, 0.0):
            return False
        return all(math.hypot(x - q[0], y - q[1]) >= 2.0 * r - 1e-12 for q in balls)

    out: list[tuple[float, float]] = []
    for p in placed:
        if free(p, out):
            out.append(p)
    if not out:
        out.append((specs.l / 2.0, specs.w / 2.0))
    for _ in range(src.choice((0, 0, 1, 2, 3))):
        pocket = src.integer(0, len(pr) - 1)
        mode = src.choice(("anywhere", "anywhere", "face", "tip", "touch"))
        if mode == "anywhere":
            poly = polys[pocket]
            w = [src.uniform(0.0, 1.0) for _ in range(len(poly))]
            tot = sum(w) or 1.0
            p = (float(sum(w[k] * poly[k, 0] for k in range(len(poly))) / tot),
                 float(sum(w[k] * poly[k, 1] for k in range(len(poly))) / tot))
        elif mode == "face":
            ax, ay, bx, by, nx, ny = segs[n_rails + 2 * pocket + src.integer(0, 1)]
            s = src.uniform(0.0, 1.0)
            gap = _gap(src)
            p = (float(ax + s * (bx - ax) + (r + gap) * nx), float(ay + s * (by - ay) + (r + gap) * ny))
        elif mode == "tip":
            cx, cy, rad = tips[2 * pocket + src.integer(0, 1)]
            th = src.uniform(-math.pi, math.pi)
            d = r + rad + _gap(src)
            p = (float(cx + d * math.cos(th)), float(cy + d * math.sin(th)))
        else:
            q = out[-1]
            th = src.uniform(-math.pi, math.pi)
            d = 2.0 * r + _gap(src)
            p = (float(q[0] + d * math.cos(th)), float(q[1] + d * math.sin(th)))
        if free(p, out):
            out.append(p)
    return out
