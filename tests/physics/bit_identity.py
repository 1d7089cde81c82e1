"""Fingerprint of the physics engine on fixed seeded scenes, for the bit-identity test (``test_bit_identity.py``).

Scenes: the fuzz generator's (``random_scene``), shots ``0..N-1`` of fixed seeds, for the ``rolling``/``drag``
laws and the spin model, each on the ``exact`` solver (with and without recording the trajectory) and the ``step``
solver (``lecture`` and ``rewind``); plus candidate shots through the batch API (``run_shots``) for each law. Each
group's fingerprint is the SHA-256 of every scene's final state (positions, velocities, angular velocities,
on-table flags), pockets and when, status, time, event and step counts, the whole event log and (recorded runs)
the state log, as raw float64/int64 bytes. The scene dicts are hashed too, so that a change of the generator is told
apart from a change of the physics.

    python tests/physics/bit_identity.py            # print the fingerprints
    python tests/physics/bit_identity.py --write    # write them to tests/physics/data/bit_identity.json
"""
from __future__ import annotations

import hashlib
import json
import math
import sys
from pathlib import Path

import numpy as np

from billiards_env.fuzz.generator import NumpySource, random_scene, shot_rng
from billiards_env.physics import Balls, Physics, Simulator, Table
from billiards_env.physics.batch import run_shots
from billiards_env.physics.scene import Scene

DATA = Path(__file__).with_name("data") / "bit_identity.json"
N_SCENES = 24  #: scenes per group
SEED = 20261202


def _update(h: "hashlib._Hash", *arrays) -> None:
    for a in arrays:
        a = np.ascontiguousarray(a)
        h.update(str(a.dtype).encode())
        h.update(str(a.shape).encode())
        h.update(a.tobytes())


def _scene_dicts(spin: float, solver: str, offset: int) -> list[dict]:
    return [random_scene(NumpySource(shot_rng(SEED + offset, i)), solver=solver, spin=spin) for i in range(N_SCENES)]


def _run_group(spin: float, solver: str, contact: str | None, record: bool, offset: int) -> tuple[str, str]:
    """(physics fingerprint, scene-dict fingerprint) of one group."""
    h = hashlib.sha256()
    hs = hashlib.sha256()
    for d in _scene_dicts(spin, solver, offset):
        if contact is not None:
            d["solver"]["contact"] = contact
        hs.update(json.dumps(d, sort_keys=True).encode())
        scene = Scene.from_dict(d)
        res = scene.run(record=record)
        b = res.balls
        _update(h, b.pos, b.vel, b.ang, b.on_table, res.pocket, res.pocketed_at,
                np.array([res.time]), np.array([res.n_events, res.n_steps, res.n_tunnelled]))
        h.update(res.status.encode())
        ev = res.events
        _update(h, ev.time, ev.kind, ev.ball, ev.other, ev.speed)
        if record and res.trajectory is not None:
            tr = res.trajectory
            _update(h, tr.times, tr.ball, tr.state)
    return h.hexdigest(), hs.hexdigest()


def _batch_group(friction: str) -> str:
    physics = {"rolling": Physics(), "drag": Physics(friction="drag", drag_k=0.4, min_speed=0.01),
               "spin": Physics(friction="spin", ball_friction=0.06)}[friction]
    sim = Simulator(Table(), physics)
    balls = Balls.from_positions([[0.62, 0.58], [1.9, 0.95], [2.3, 0.18], [1.2, 1.1], [1.7, 0.4]])
    rng = np.random.default_rng(5)
    n = 64
    angles = rng.uniform(-math.pi, math.pi, n)
    speeds = rng.uniform(0.3, 6.0, n)
    kw = {}
    if friction == "spin":
        r = 0.5 * np.sqrt(rng.uniform(0, 1, n))
        phi = rng.uniform(-math.pi, math.pi, n)
        kw = {"side": r * np.cos(phi), "top": r * np.sin(phi)}
    res = run_shots(sim, balls, angles, speeds, events=True, threads=1, **kw)
    h = hashlib.sha256()
    _update(h, res.status, res.time, res.n_events, res.pos, res.vel, res.on_table, res.pocket, res.pocketed_at,
            res.first_contact, res.cushions, res.rail_after_contact, res.event_counts)
    if res.ang is not None:
        _update(h, res.ang)
    ev = res.events
    _update(h, ev.offsets, ev.time, ev.kind, ev.ball, ev.other, ev.speed)
    return h.hexdigest()


#: name -> (spin chance, solver, contact, record, seed offset)
GROUPS = {
    "rolling_drag/exact": (0.0, "exact", None, False, 0),
    "rolling_drag/exact_record": (0.0, "exact", None, True, 1),
    "rolling_drag/step_lecture": (0.0, "step", "lecture", False, 2),
    "rolling_drag/step_rewind": (0.0, "step", "rewind", False, 3),
    "spin/exact": (1.0, "exact", None, False, 4),
    "spin/exact_record": (1.0, "exact", None, True, 5),
    "spin/step_lecture": (1.0, "step", "lecture", False, 6),
    "spin/step_rewind": (1.0, "step", "rewind", False, 7),
}


def fingerprints() -> dict[str, dict[str, str]]:
    out = {}
    for name, (spin, solver, contact, record, offset) in GROUPS.items():
        phys, scenes = _run_group(spin, solver, contact, record, offset)
        out[name] = {"physics": phys, "scenes": scenes}
    for friction in ("rolling", "drag", "spin"):
        out[f"batch/{friction}"] = {"physics": _batch_group(friction), "scenes": ""}
    return out


def main(argv: list[str]) -> int:
    fp = fingerprints()
    text = json.dumps(fp, indent=1, sort_keys=True) + "\n"
    if "--write" in argv:
        DATA.parent.mkdir(exist_ok=True)
        DATA.write_text(text)
        print(f"wrote {DATA}")
    else:
        print(text, end="")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
