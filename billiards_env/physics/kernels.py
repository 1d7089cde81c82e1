"""Which compiled kernels run which physics model: the one table (:data:`KERNELS`) that every caller reads.

A friction law picks a *kernel set*: the ``rolling`` and ``drag`` laws share the linear kernels (:mod:`.exact`,
:mod:`.step`: balls move along straight lines, no spin), the spin model has its own (:mod:`.exact_spin`,
:mod:`.step_spin`). The spin model's optional collision models (Alciatore's ball-ball friction, the compliant
cushions, a raised cushion nose, squirt) are not kernels of their own: they are parameters of the spin kernels
(:mod:`.kernel_io`), read per collision. Every kernel of a kind takes the same arguments, so a caller looks its
model up here and calls, whatever the model:

    ks = kernels_for(physics)
    res = ks.exact(pos, vel, ang, radius, mass, on_table, pocket_xy, pocket_r, params, max_events, record)
    res = ks.step(pos, vel, ang, radius, mass, on_table, pocket_xy, pocket_r, params, dt, contact, record_dt)
    log = ks.rows(pos, vel, ang, on, radius, mass, pocket_xy, pocket_r, params, max_events, struck, out, keep, log)

``ang`` (angular velocities) is state only where ``ks.spin`` is True; the linear kernels do not read it (the batch
drivers of the linear set read one row, ``ang[0]``, for all tables). Compiled code cannot take a kernel as an
argument and still be cached by numba, so a compiled driver that runs a kernel (a vector env's step) is written once
per kernel set and looked up by the set's :attr:`KernelSet.name`.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from .batch_rows import rows_linear, rows_spin
from .codes import DRAG, ROLLING, SPIN
from .exact import simulate_exact
from .exact_spin import simulate_exact_spin
from .step import simulate_step
from .step_spin import simulate_step_spin

if TYPE_CHECKING:  # pragma: no cover
    from .model import Physics


@dataclass(frozen=True)
class KernelSet:
    """The compiled kernels of one kind of model."""

    name: str  #: ``"linear"`` (rolling, drag) or ``"spin"``
    spin: bool  #: balls carry angular velocities: ``ang`` is read and updated, strikes put spin on the ball
    exact: Any  #: event-driven solver (:func:`.exact.simulate_exact`'s arguments)
    step: Any  #: per-frame solver (:func:`.step.simulate_step`'s arguments)
    rows: Any  #: batch driver, rows one after the other (:mod:`.batch_rows`; on slices of the rows for threads)


LINEAR = KernelSet("linear", False, simulate_exact, simulate_step, rows_linear)
SPINNING = KernelSet("spin", True, simulate_exact_spin, simulate_step_spin, rows_spin)

#: Friction-law code (:data:`.codes.FRICTION_LAWS`) -> its kernel set.
KERNELS: dict[int, KernelSet] = {ROLLING: LINEAR, DRAG: LINEAR, SPIN: SPINNING}


def kernels_for(physics: "Physics") -> KernelSet:
    """The kernel set that runs ``physics``."""
    return KERNELS[physics.law_code]


__all__ = ["KernelSet", "KERNELS", "LINEAR", "SPINNING", "kernels_for"]
