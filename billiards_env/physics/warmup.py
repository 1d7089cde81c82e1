"""Compile (or load from numba's on-disk cache) every physics kernel once: ``python -m billiards_env.physics.warmup``.

The set-up script runs this after installing, so a user's first shot loads compiled code instead of compiling it.
"""
from __future__ import annotations

import time
from typing import Any

from .balls import Balls
from .model import Physics
from .simulate import Simulator
from .table import Table


#: The kernels :func:`warm_up` compiles, by name: each is one solver of one family of motion laws (``rolling`` and
#: ``drag`` share the linear kernels; ``spin`` and the pooltool preset share the spin kernels).
KERNELS = ("exact", "exact_spin", "step", "step_spin")


def warm_up(kernels: tuple[str, ...] = KERNELS) -> float:
    """Run one tiny shot through each solver and recording mode of ``kernels`` (:data:`KERNELS`), and a tiny batch
    through each exact model's batch drivers; returns the seconds it took."""
    unknown = sorted(set(kernels) - set(KERNELS))
    if unknown:
        raise ValueError(f"kernels: unknown {unknown}; choose from {list(KERNELS)}")
    start = time.perf_counter()
    plain = Balls.from_positions([[0.5, 0.5], [1.0, 0.5]]).strike(0, 0.0, 1.0)
    spin = Balls.from_positions([[0.5, 0.5], [1.0, 0.5]]).strike(0, 0.0, 1.0, side=0.2, top=-0.2)
    preset = Physics.from_preset("pooltool")
    squirted = Balls.from_positions([[0.5, 0.5], [1.0, 0.5]]).strike(0, 0.0, 1.0, side=0.2, top=-0.2, physics=preset)
    table = Table()
    for physics, balls in ((Physics(), plain), (Physics(friction="drag", drag_k=0.5, min_speed=0.01), plain),
                           (Physics(friction="spin"), spin), (preset, squirted)):
        family = "_spin" if physics.has_spin else ""
        for solver, contact in (("exact", "lecture"), ("step", "lecture"), ("step", "rewind")):
            if solver + family not in kernels:
                continue
            sim = Simulator(table, physics, solver=solver, contact=contact, dt=0.01, max_time=5.0)
            for record in (False, True):
                result = sim.run(balls, record=record)
                if record and result.trajectory is not None:
                    result.trajectory.sample([0.0, result.time])
                    result.trajectory.sample_states([0.0, result.time])
            if solver == "exact":
                sim.run_in_place(balls.copy())
                _warm_batch(sim, balls)
    return time.perf_counter() - start


def _warm_batch(sim: Simulator, balls: Balls) -> None:
    """The batch drivers of ``sim``'s model (:mod:`.batch`): serial with the event log, and on two threads
    (the same driver on slices of the rows)."""
    from .batch import run_shots

    spin = sim.physics.has_spin
    kw: dict[str, Any] = {"side": [0.1, 0.0], "top": [0.0, -0.1]} if spin else {}
    for threads, events in ((1, True), (2, False)):
        run_shots(sim, balls, [0.0, 1.0], [1.0, 0.5], threads=threads, events=events, **kw)


if __name__ == "__main__":
    print(f"billiards_env physics kernels ready ({warm_up():.1f} s)")
