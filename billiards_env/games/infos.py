"""The form of an ``info`` value: :class:`InfoSpec` (dtype, shape, meaning, the value when there is nothing to say, and
the names of a code), and the helpers that make values of that form.

Every info value has one fixed type, dtype and shape per env id (RL libraries stack infos step by step, average them
or write them to HDF5): Python ``bool``/``int``/``float`` for scalars, numpy arrays for the rest (a boolean mask over
the ball rows instead of a tuple of ids), an ``int`` code instead of a string (``names[code]`` is its name, -1 none).
The games' own keys are declared beside the values they give (each session's ``info_keys``); the env's schema joins
them (:func:`billiards_env.envs.info.info_schema`). No Gymnasium here.
"""
from __future__ import annotations

from typing import Any, Iterable, NamedTuple

import numpy as np


class InfoSpec(NamedTuple):
    """One info key: ``dtype`` (``np.bool_``, ``np.int64`` or ``np.float64``), ``shape`` (``()`` a Python scalar of
    that kind, else a numpy array), ``meaning`` (for the docs), ``blank`` (the value when there is nothing to report:
    a reset's shot keys, no call yet) and ``names`` (a code's names: ``names[code]``; empty if not a code)."""

    dtype: type
    shape: tuple[int, ...]
    meaning: str
    blank: Any = 0
    names: tuple[str, ...] = ()


def flag(meaning: str) -> InfoSpec:
    """A Python ``bool`` key (False when there is nothing to report)."""
    return InfoSpec(np.bool_, (), meaning, False)


def integer(meaning: str, blank: int = 0) -> InfoSpec:
    """A Python ``int`` key."""
    return InfoSpec(np.int64, (), meaning, blank)


def real(meaning: str) -> InfoSpec:
    """A Python ``float`` key (0.0 when there is nothing to report)."""
    return InfoSpec(np.float64, (), meaning, 0.0)


def code(meaning: str, names: Iterable[str], blank: int = -1) -> InfoSpec:
    """An ``int`` code: ``names[code]`` is its name; ``blank`` (-1 unless given) when there is none."""
    return InfoSpec(np.int64, (), meaning, blank, tuple(names))


def row_mask(meaning: str, n_balls: int) -> InfoSpec:
    """A ``(n_balls,)`` boolean array over the ball rows (all False when there is nothing to report)."""
    return InfoSpec(np.bool_, (n_balls,), meaning, False)


def blank_value(spec: InfoSpec) -> Any:
    """A fresh value of ``spec`` saying nothing: its ``blank`` as a Python scalar, or an array filled with it."""
    if spec.shape:
        return np.full(spec.shape, spec.blank, dtype=spec.dtype)
    return {np.bool_: bool, np.int64: int, np.float64: float}[spec.dtype](spec.blank)


def mask_of(rows: Iterable[int], n: int) -> np.ndarray:
    """A ``(n,)`` boolean array, True at ``rows``."""
    out = np.zeros(n, np.bool_)
    out[list(rows)] = True
    return out


def code_of(names: tuple[str, ...], name: Any) -> int:
    """The code of ``name`` among ``names`` (-1 for None: nothing)."""
    return -1 if name is None else names.index(name)


__all__ = ["InfoSpec", "flag", "integer", "real", "code", "row_mask", "blank_value", "mask_of", "code_of"]
