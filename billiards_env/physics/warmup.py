"""Compile (or load from numba's on-disk cache) every physics kernel once: ``python -m billiards_env.physics.warmup``.

The set-up script runs this after installing, so a user's first shot loads compiled code instead of compiling it.
"""
from __future__ import annotations

import time

from .balls import Balls
from .model import Physics
from .simulate import Simulator
from .table import Table


def warm_up() -> float:
    """Run one tiny shot through each solver and recording mode; returns the seconds it took."""
    start = time.perf_counter()
    balls = Balls.from_positions([[0.5, 0.5], [1.0, 0.5]]).strike(0, 0.0, 1.0)
    table = Table()
    for physics in (Physics(), Physics(friction="drag", drag_k=0.5, min_speed=0.01)):
        for solver, contact in (("exact", "lecture"), ("step", "lecture"), ("step", "rewind")):
            sim = Simulator(table, physics, solver=solver, contact=contact, dt=0.01, max_time=5.0)
            for record in (False, True):
                result = sim.run(balls, record=record)
                if record and result.trajectory is not None:
                    result.trajectory.sample([0.0, result.time])
    return time.perf_counter() - start


if __name__ == "__main__":
    print(f"billiards_env physics kernels ready ({warm_up():.1f} s)")
