"""Validation errors and checks shared by the scene parser, the Python API and the envs."""
from __future__ import annotations

import math
from numbers import Real


class SceneError(ValueError):
    """An invalid scene, table, physics parameter or ball: the message names the field and the fix."""


def check_number(name: str, value: object) -> float:
    """``value`` as a float, or a SceneError naming ``name`` if it is not a real number."""
    if isinstance(value, bool) or not isinstance(value, Real):
        raise SceneError(f"{name}: expected a number, got {type(value).__name__} {value!r}")
    try:
        return float(value)
    except OverflowError:
        raise SceneError(f"{name}: must be a finite number, got an integer too large for a float") from None


def check_finite(name: str, value: object) -> float:
    v = check_number(name, value)
    if not math.isfinite(v):
        raise SceneError(f"{name}: must be a finite number, got {v}")
    return v


def check_positive(name: str, value: object) -> float:
    v = check_finite(name, value)
    if v <= 0.0:
        raise SceneError(f"{name}: must be > 0, got {v}")
    return v


def check_non_negative(name: str, value: object) -> float:
    v = check_finite(name, value)
    if v < 0.0:
        raise SceneError(f"{name}: must be >= 0, got {v}")
    return v


def check_unit_interval(name: str, value: object) -> float:
    v = check_finite(name, value)
    if not 0.0 <= v <= 1.0:
        raise SceneError(f"{name}: must be in [0, 1], got {v}")
    return v
