"""Small compiled helpers of the env hot path (one call instead of a dozen tiny numpy operations)."""
from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True)
def observation(pos, on_table, sx, sy):  # pragma: no cover - compiled
    """``[x0*sx, y0*sy, x1*sx, ..., pocketed0, pocketed1, ...]`` as float32 clipped to [0, 1]; a pocketed
    ball's position reads 0."""
    out = np.empty(3 * pos.shape[0], np.float32)
    write_observation(pos, on_table, sx, sy, out)
    return out


@njit(cache=True)
def write_observation(pos, on_table, sx, sy, out):  # pragma: no cover - compiled
    """:func:`observation` into ``out`` (a row of a batch's observations): element by element, so that no array
    assignment (and its shape check, seconds of compile time) is needed."""
    n = pos.shape[0]
    for i in range(n):
        if on_table[i]:
            x = pos[i, 0] * sx
            y = pos[i, 1] * sy
            out[2 * i] = min(max(x, 0.0), 1.0)
            out[2 * i + 1] = min(max(y, 0.0), 1.0)
            out[2 * n + i] = 0.0
        else:
            out[2 * i] = 0.0
            out[2 * i + 1] = 0.0
            out[2 * n + i] = 1.0
