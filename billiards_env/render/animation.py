"""Animations: which instants of a shot to draw (the trajectory gives the positions), and how the balls turn
(their spins integrated into orientations, so a marker on each ball rolls and spins with it)."""
from __future__ import annotations

import math
from typing import Any

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


#: Longest simulated time (s) one step of the spin integration covers, and the most steps between two frames.
SPIN_STEP = 1.0 / 240.0
MAX_SPIN_STEPS = 64


def integrate_orientations(start: np.ndarray, times: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """Every ball's orientation at each of ``times`` (S,): ``start`` (N, 3, 3) at ``times[0]``, then turned by the
    angular velocities ``omega`` (S, N, 3) (rad/s, table frame): ``dR/dt = [w]x R``, with ``w`` constant over each
    interval at the mean of its two ends (exact for a constant spin). Returns (S, N, 3, 3) rotation matrices
    (body to table). A ball whose spin is 0 over an interval keeps its orientation bit for bit."""
    t = np.asarray(times, dtype=float).reshape(-1)
    w = np.nan_to_num(np.asarray(omega, dtype=float))
    out = np.empty((len(t),) + np.shape(start))
    out[0] = start
    if len(t) < 2:
        return out
    mean = 0.5 * (w[1:] + w[:-1]) * np.diff(t)[:, None, None]  # rotation vector of each interval (S-1, N, 3)
    turns = _rotations(mean)
    for s in range(len(t) - 1):
        out[s + 1] = np.matmul(turns[s], out[s])
    return out


def _rotations(vec: np.ndarray) -> np.ndarray:
    """Rotation matrices ``exp([v]x)`` of rotation vectors ``(..., 3)`` (Rodrigues); exactly I for v = 0."""
    theta = np.linalg.norm(vec, axis=-1)
    safe = np.where(theta > 0.0, theta, 1.0)
    k = vec / safe[..., None]
    kx, ky, kz = k[..., 0], k[..., 1], k[..., 2]
    zero = np.zeros_like(kx)
    cross = np.stack([np.stack([zero, -kz, ky], -1), np.stack([kz, zero, -kx], -1),
                      np.stack([-ky, kx, zero], -1)], -2)
    s, c = np.sin(theta)[..., None, None], (1.0 - np.cos(theta))[..., None, None]
    out = np.eye(3) + s * cross + c * np.matmul(cross, cross)
    out[theta == 0.0] = np.eye(3)
    return out


def spin_times(times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A finer grid for integrating spins between the frame ``times``: each interval split into equal steps of
    at most :data:`SPIN_STEP` s (at most :data:`MAX_SPIN_STEPS`). Returns the grid and the index of each frame
    time in it."""
    t = np.asarray(times, dtype=float).reshape(-1)
    if len(t) < 2:
        return t.copy(), np.arange(len(t))
    gaps = np.diff(t)
    steps = np.clip(np.ceil(gaps / SPIN_STEP), 1, MAX_SPIN_STEPS).astype(int)
    start = np.repeat(t[:-1], steps)
    frac = np.arange(steps.sum()) - np.repeat(np.cumsum(steps) - steps, steps)
    fine = np.append(start + np.repeat(gaps / steps, steps) * frac, t[-1])
    at = np.append(0, np.cumsum(steps))
    fine[at] = t  # the frame times exactly
    return fine, at


def sample_frames(trajectory: Any, times: np.ndarray, orientations: np.ndarray | None = None
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """A shot's frames at ``times``: positions (T, N, 2), on-table flags (T, N) and, when the balls'
    ``orientations`` (N, 3, 3) before the shot are given, their orientations (T, N, 3, 3), the trajectory's angular
    velocities integrated on a finer grid (:func:`spin_times`, :func:`integrate_orientations`)."""
    if orientations is None:
        pos, on = trajectory.sample(times)
        return pos, on, None
    fine, at = spin_times(times)
    states, on, _ = trajectory.sample_states(fine)
    turned = integrate_orientations(orientations, fine, states[:, :, 4:7])
    return np.ascontiguousarray(states[at, :, :2]), on[at], turned[at]
