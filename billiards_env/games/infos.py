"""The form of an ``info`` value: :class:`InfoSpec` (dtype, shape, meaning, the value when there is nothing to say, and
the names of a code), and the helpers that make values of that form.

Every info value has one fixed type, dtype and shape per env id (RL libraries stack infos step by step, average them
or write them to HDF5, or read them into tensors): every value carries its dtype, which TorchRL's info reader asks of
each. Numbers are numpy scalars (``np.int64``, ``np.float64``); flags are 0-d boolean arrays (numpy's ``np.bool_`` is
no ``np.number``, so Gymnasium's ``SyncVectorEnv`` would stack it as objects; a 0-d array stacks as ``bool``); the
rest are numpy arrays (a boolean mask over the ball rows instead of a tuple of ids), an integer code instead of a
string (``names[code]`` is its name, -1 none). The games' own keys are declared beside the values they give (each
session's ``info_keys``); the env's schema joins them (:func:`billiards_env.envs.info.info_schema`). No Gymnasium
here.
"""
from __future__ import annotations

from typing import Any, Iterable, NamedTuple

import numpy as np


class InfoSpec(NamedTuple):
    """One info key: ``dtype`` (``np.bool_``, ``np.int64`` or ``np.float64``), ``shape`` (``()`` a single value: a 0-d
    boolean array for ``np.bool_``, else a numpy scalar of the dtype; else a numpy array), ``meaning`` (for the
    docs), ``blank`` (the value when there is nothing to report: a reset's shot keys, no call yet) and ``names`` (a
    code's names: ``names[code]``; empty if not a code)."""

    dtype: type
    shape: tuple[int, ...]
    meaning: str
    blank: Any = 0
    names: tuple[str, ...] = ()


def flag(meaning: str) -> InfoSpec:
    """A flag: a 0-d boolean array (False when there is nothing to report)."""
    return InfoSpec(np.bool_, (), meaning, False)


def integer(meaning: str, blank: int = 0) -> InfoSpec:
    """An ``np.int64`` key."""
    return InfoSpec(np.int64, (), meaning, blank)


def real(meaning: str) -> InfoSpec:
    """An ``np.float64`` key (0.0 when there is nothing to report)."""
    return InfoSpec(np.float64, (), meaning, 0.0)


def code(meaning: str, names: Iterable[str], blank: int = -1) -> InfoSpec:
    """An ``np.int64`` code: ``names[code]`` is its name; ``blank`` (-1 unless given) when there is none."""
    return InfoSpec(np.int64, (), meaning, blank, tuple(names))


def row_mask(meaning: str, n_balls: int) -> InfoSpec:
    """A ``(n_balls,)`` boolean array over the ball rows (all False when there is nothing to report)."""
    return InfoSpec(np.bool_, (n_balls,), meaning, False)


def blank_value(spec: InfoSpec) -> Any:
    """A fresh value of ``spec`` saying nothing: its ``blank`` in the form of :func:`single`, or an array filled
    with it."""
    if spec.shape:
        return np.full(spec.shape, spec.blank, dtype=spec.dtype)
    return single(spec.dtype, spec.blank)


def single(dtype: type, value: Any) -> Any:
    """``value`` as an info value of shape ``()`` and ``dtype``: a 0-d boolean array for ``np.bool_`` (Gymnasium's
    vector envs stack it as ``bool``; an ``np.bool_`` they would stack as objects), else a numpy scalar
    (``np.int64``, ``np.float64``). Each has a ``dtype``, as TorchRL's info reader needs."""
    if dtype is np.bool_:
        return np.array(value, np.bool_)
    return dtype(value)


def unstack(column: np.ndarray) -> list[Any]:
    """The per-table values of a stacked info column (``(n, *shape)``, a vector env's ``info[key]``) in the single
    env's forms (:func:`single` for shape ``()``, fresh arrays otherwise; an object column's items as they are)."""
    if column.dtype == object:
        return list(column)
    if column.ndim == 1:
        return [np.array(v) for v in column] if column.dtype == np.bool_ else list(column)
    return [v.copy() for v in column]


def conform(info: dict[str, Any], schema: dict[str, InfoSpec]) -> dict[str, Any]:
    """``info`` with its keys of shape ``()`` in ``schema`` in the form of :func:`single`, in place (returned too):
    the games and tasks write plain Python values where they decide them; this is the one place they take the
    schema's form. Arrays and keys outside the schema stay as they are."""
    for key, value in info.items():
        spec = schema.get(key)
        if spec is not None and not spec.shape:
            info[key] = single(spec.dtype, value)
    return info


def mask_of(rows: Iterable[int], n: int) -> np.ndarray:
    """A ``(n,)`` boolean array, True at ``rows``."""
    out = np.zeros(n, np.bool_)
    out[list(rows)] = True
    return out


def code_of(names: tuple[str, ...], name: Any) -> int:
    """The code of ``name`` among ``names`` (-1 for None: nothing)."""
    return -1 if name is None else names.index(name)


__all__ = ["InfoSpec", "flag", "integer", "real", "code", "row_mask", "blank_value", "single", "unstack", "conform",
           "mask_of", "code_of"]
