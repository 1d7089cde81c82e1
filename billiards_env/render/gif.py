"""Write rendered frames to disk: animated GIFs (one shared palette, looping) and PNG stills."""
from __future__ import annotations

import os
from pathlib import Path
from typing import Sequence

import numpy as np
from PIL import Image

#: Frames sampled to build the shared GIF palette (spread over the clip: start, end and in between).
_PALETTE_SAMPLES = 8


def write_gif(frames: Sequence[np.ndarray], path: str | os.PathLike[str], fps: float = 30) -> Path:
    """Write ``(H, W, 3) uint8`` frames as an animated GIF that loops forever; returns the path written.

    All frames share one adaptive 256-colour palette (built from frames spread over the clip) so the
    cloth does not flicker between frames, and Pillow's optimiser stores only what changes.
    """
    if not np.isfinite(fps) or fps <= 0:
        raise ValueError(f"write_gif: fps must be a finite number > 0, got {fps!r}")
    arrays = _check_frames(frames)
    palette = _shared_palette(arrays)
    images = [Image.fromarray(a).quantize(palette=palette, dither=Image.Dither.NONE) for a in arrays]
    out = _prepare(path)
    images[0].save(
        out,
        format="GIF",
        save_all=True,
        append_images=images[1:],
        duration=max(int(round(1000.0 / fps)), 10),
        loop=0,
        optimize=True,
        disposal=1,
    )
    return out


def write_png(frame: np.ndarray, path: str | os.PathLike[str]) -> Path:
    """Write one ``(H, W, 3) uint8`` frame as a PNG; returns the path written."""
    (array,) = _check_frames([frame])
    out = _prepare(path)
    Image.fromarray(array).save(out, format="PNG")
    return out


def _check_frames(frames: Sequence[np.ndarray]) -> list[np.ndarray]:
    """Frames as contiguous uint8 arrays of one common (H, W, 3) shape, or a ValueError saying what is wrong."""
    arrays = [np.asarray(f) for f in frames]
    if not arrays:
        raise ValueError("no frames to write: give at least one (H, W, 3) uint8 frame")
    shape = arrays[0].shape
    for k, a in enumerate(arrays):
        if a.ndim != 3 or a.shape[2] != 3 or a.dtype != np.uint8:
            raise ValueError(f"frame {k}: expected an (H, W, 3) uint8 array, got shape {a.shape} dtype {a.dtype}")
        if a.shape != shape:
            raise ValueError(f"frame {k}: shape {a.shape} differs from frame 0's {shape}; all frames must match")
    return [np.ascontiguousarray(a) for a in arrays]


def _shared_palette(arrays: list[np.ndarray]) -> Image.Image:
    """One adaptive palette for the whole clip, from a few frames stacked together.

    Fast octree keeps small saturated areas (the balls) close to their colours; median cut spends the
    palette on the large cloth and shifts the ball colours visibly.
    """
    picks = np.unique(np.linspace(0, len(arrays) - 1, min(_PALETTE_SAMPLES, len(arrays))).round().astype(int))
    sample = np.concatenate([arrays[k] for k in picks], axis=0)
    return Image.fromarray(sample).quantize(colors=256, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE)


def _prepare(path: str | os.PathLike[str]) -> Path:
    """The output path, with its parent directory created."""
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    return out
