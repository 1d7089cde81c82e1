"""Time sampling for animations: which instants of a shot to draw (the physics layer gives the positions)."""
from __future__ import annotations

import math

import numpy as np

#: Two sample times closer than this fraction of a frame are the same frame (absorbs float rounding).
_SAME_FRAME = 1e-6


def frame_times(duration: float, fps: float) -> np.ndarray:
    """Times ``0, 1/fps, 2/fps, ...`` up to ``duration``, always ending exactly at ``duration``.

    The last frame is the final state even when ``duration`` is not a whole number of frames (the last
    interval is then shorter than ``1/fps``). ``duration == 0`` gives the single time ``[0.0]``.
    """
    if not math.isfinite(duration) or duration < 0:
        raise ValueError(f"frame_times: duration must be a finite number >= 0 (seconds), got {duration!r}")
    if not math.isfinite(fps) or fps <= 0:
        raise ValueError(f"frame_times: fps must be a finite number > 0, got {fps!r}")
    n_steps = int(math.floor(duration * fps + _SAME_FRAME))
    times = np.arange(n_steps + 1, dtype=float) / fps
    if duration - times[-1] > _SAME_FRAME / fps:
        times = np.append(times, duration)
    times[-1] = float(duration)
    return times
