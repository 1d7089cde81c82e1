"""The shot's part of every step's ``info``: one builder, :func:`shot_info`, for the single env's Python path and
its compiled fast path (the native vector env stacks the same keys, :data:`SHOT_INFO_KEYS`, as arrays)."""
from __future__ import annotations

from typing import Any

#: The keys :func:`shot_info` writes (and the native vector env's step info holds), in order.
SHOT_INFO_KEYS = ("pocketed", "scratch", "first_contact", "n_events", "sim_time", "status", "shots", "angle", "speed")
#: Added when the action has spin dims.
TIP_INFO_KEYS = ("side", "top")


def shot_info(pocketed: tuple[str, ...], scratch: bool, first_contact: str | None, n_events: int, sim_time: float,
              status: str, shots: int, played: Any, tip: bool) -> dict[str, Any]:
    """The shot keys of ``info``: ``pocketed`` (ids pocketed by this shot), ``scratch``, ``first_contact`` (id or
    None), ``n_events``, ``sim_time`` (simulated seconds), ``status`` (``rest`` / ``time_cap`` / ``event_cap``),
    ``shots`` (of the episode), ``angle`` and ``speed`` of the shot as played (noise included; ``played`` has
    ``angle``, ``speed``, ``side``, ``top``), and with ``tip`` (spin dims) its ``side`` and ``top``."""
    info = {
        "pocketed": pocketed,
        "scratch": bool(scratch),
        "first_contact": first_contact,
        "n_events": int(n_events),
        "sim_time": float(sim_time),
        "status": status,
        "shots": shots,
        "angle": played.angle,
        "speed": played.speed,
    }
    if tip:
        info["side"], info["top"] = played.side, played.top
    return info


__all__ = ["shot_info", "SHOT_INFO_KEYS", "TIP_INFO_KEYS"]
