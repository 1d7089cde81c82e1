"""Shared helpers of the stability tests: a Hypothesis-backed random source for the fuzz scene generator, and
running a scene or ball set through the shared invariant checks of :mod:`billiards_env.physics.invariants`."""
from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np
from hypothesis import strategies as st

from billiards_env.fuzz.generator import Source
from billiards_env.physics import Balls, Physics, Simulator, Table
from billiards_env.physics.invariants import check_shot, run_case
from billiards_env.physics.scene import Scene

CASES = Path(__file__).parent / "cases"
R = 0.028575
L = 2.54
W = 1.27


class HypothesisSource(Source):
    """Draws every decision of :func:`billiards_env.fuzz.generator.random_scene` from Hypothesis (so it shrinks
    them)."""

    def __init__(self, data: st.DataObject) -> None:
        self.data = data

    def uniform(self, lo: float, hi: float) -> float:
        if lo == hi:
            return lo
        return self.data.draw(st.floats(min_value=lo, max_value=hi, allow_nan=False, allow_infinity=False))

    def integer(self, lo: int, hi: int) -> int:
        return self.data.draw(st.integers(min_value=lo, max_value=hi))

    def choice(self, options):
        return self.data.draw(st.sampled_from(list(options)))

    def log_uniform(self, lo: float, hi: float) -> float:
        return float(math.exp(self.uniform(math.log(lo), math.log(hi))))


def describe(rep, scene_dict: dict[str, Any]) -> str:
    """Failure message: the violations and the scene file that reproduces them."""
    lines = [f"{name}: {msg}" for name, msg in rep.violations.items()]
    lines.append("scene (save as JSON, run `billiards-sim FILE --events` or `python -m billiards_env.fuzz --check FILE`):")
    lines.append(json.dumps(scene_dict))
    return "\n".join(lines)


def assert_invariants(scene_dict: dict[str, Any], allow: tuple[str, ...] = ()):
    """Run a scene dict and assert every invariant holds (except those in ``allow``); returns (report, result)."""
    rep, res = run_case(scene_dict)
    bad = {k: v for k, v in rep.violations.items() if k not in allow}
    assert not bad, describe(rep, scene_dict)
    return rep, res


def scene_dict(balls: list[tuple[float, float]] | np.ndarray, *, velocities=None, shot=None, friction="rolling",
               mu_roll=0.01, drag_k=0.0, min_speed=0.0, e_ball=0.95, e_cushion=0.85, pockets: Any = "default",
               solver="exact", dt=1e-3, contact="lecture", max_time=60.0, max_events=20_000) -> dict[str, Any]:
    """A scene dict (scene-file format) from ball centres, optional per-ball velocities and a shot
    ``(angle, speed)`` of the cue (ball 0)."""
    bl = []
    for k, (x, y) in enumerate(np.asarray(balls, dtype=float).tolist()):
        b = {"id": "cue" if k == 0 else str(k), "x": x, "y": y}
        if velocities is not None:
            b["vx"], b["vy"] = (float(v) for v in velocities[k])
        bl.append(b)
    table: dict[str, Any] = {"cushion_restitution": e_cushion}
    if pockets != "default":
        table["pockets"] = [{"x": float(x), "y": float(y), "radius": float(r)} for x, y, r in pockets]
    physics: dict[str, Any] = {"friction": friction, "ball_restitution": e_ball, "min_speed": min_speed}
    if friction == "rolling":
        physics["mu_roll"] = mu_roll
    else:
        physics["drag_k"] = drag_k
    d: dict[str, Any] = {"table": table, "physics": physics, "balls": bl, "max_time": max_time,
                         "max_events": max_events, "solver": {"name": solver}}
    if solver == "step":
        d["solver"].update(dt=dt, contact=contact)
    if shot is not None:
        d["shot"] = {"ball": "cue", "angle": float(shot[0]), "speed": float(shot[1])}
    return d


def load_case(name: str) -> dict[str, Any]:
    return json.loads((CASES / name).read_text())


def run_scene(d: dict[str, Any]):
    """Run a scene dict with record=True: (scene, result)."""
    scene = Scene.from_dict(d)
    return scene, scene.run(record=True)


__all__ = ["HypothesisSource", "assert_invariants", "scene_dict", "load_case", "run_scene", "describe", "check_shot",
           "R", "L", "W", "Balls", "Physics", "Simulator", "Table", "CASES"]
