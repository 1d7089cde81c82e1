"""Observation types: what the agent sees (chosen by the ``observation_type`` config key).

- :class:`Positions` (``"positions"``): every ball's position, x divided by the table length and y by its width
  (cue ball first, then balls 1..n; a pocketed ball reads 0), then one pocketed flag per ball. ``Box(0, 1)``.
- :class:`ShotFeatures` (``"features"``): the positions, then the table seen from the target ball (the lowest-
  numbered object ball on the table, or the legal ball in a game): the cue -> target unit vector (2) and distance
  / table length (1); then per pocket the signed angle between the cue -> target direction and the target ->
  pocket direction divided by pi (the cut that pocket asks for), the target -> pocket distance / table length, and
  the cosine between the target -> pocket direction and the pocket's mouth axis (how squarely it is entered),
  sorted by the size of the cut so that the straightest pocket is always first (the pockets are a set; sorting
  gives one canonical order). Zeros when no target is left. Values in ``[-1, 1]``.

A task may append features of its own (a game's turn, ball in hand, group...): :meth:`Task.features`.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from gymnasium import spaces

from billiards_env.physics.aim import pocket_bearings, pocket_mouth_axes, wrap_angle

from ._kernels import observation

if TYPE_CHECKING:  # pragma: no cover
    from .base import BilliardsEnv


class ObservationType:
    """Builds the observation space and the observation of an env's current state."""

    name = "positions"

    def __init__(self, env: "BilliardsEnv") -> None:
        n = env.n_balls
        self._sx = 1.0 / env.table.length
        self._sy = 1.0 / env.table.width
        low, high = np.zeros(3 * n, np.float32), np.ones(3 * n, np.float32)
        t_low, t_high = env.task.feature_bounds(env)
        self.n_task = len(t_low)
        self.space = spaces.Box(np.concatenate([low, self._extra_low(env), t_low]).astype(np.float32),
                                np.concatenate([high, self._extra_high(env), t_high]).astype(np.float32),
                                dtype=np.float32)

    def _extra_low(self, env: "BilliardsEnv") -> np.ndarray:
        return np.zeros(0, np.float32)

    def _extra_high(self, env: "BilliardsEnv") -> np.ndarray:
        return np.zeros(0, np.float32)

    def observe(self, env: "BilliardsEnv") -> np.ndarray:
        b = env.balls
        obs = observation(b.pos, b.on_table, self._sx, self._sy)
        if self.n_task:
            obs = np.concatenate([obs, env.task.features(env)])
        return obs


class Positions(ObservationType):
    """Ball positions and pocketed flags (see the module docstring)."""

    name = "positions"


class ShotFeatures(ObservationType):
    """Positions, then the table seen from the target ball (see the module docstring)."""

    name = "features"

    def __init__(self, env: "BilliardsEnv") -> None:
        self.n_pockets = int(env.table.n_pockets)
        self.n_extra = 3 + 3 * self.n_pockets
        self._axes = pocket_mouth_axes(env.table)
        super().__init__(env)

    def _extra_low(self, env: "BilliardsEnv") -> np.ndarray:
        return -np.ones(self.n_extra, np.float32)

    def _extra_high(self, env: "BilliardsEnv") -> np.ndarray:
        return np.ones(self.n_extra, np.float32)

    def features(self, env: "BilliardsEnv") -> np.ndarray:
        """The target-centred features (``3 + 3 * n_pockets`` values)."""
        out = np.zeros(self.n_extra, np.float32)
        t = env.target_ball()
        if t is None:
            return out
        b = env.balls
        scale = 1.0 / env.table.length
        v = b.pos[t] - b.pos[0]
        d = float(np.hypot(*v))
        out[0:2] = v / max(d, 1e-12)
        out[2] = min(d * scale, 1.0)
        bearing, dist, square = pocket_bearings(b.pos[t], env.table, self._axes)
        rel = wrap_angle(bearing - math.atan2(v[1], v[0]))
        order = np.argsort(np.abs(rel), kind="stable")
        out[3::3] = rel[order] / math.pi
        out[4::3] = np.minimum(np.maximum(dist[order], 1e-12) * scale, 1.0)
        out[5::3] = square[order]
        return out

    def observe(self, env: "BilliardsEnv") -> np.ndarray:
        b = env.balls
        parts = [observation(b.pos, b.on_table, self._sx, self._sy), self.features(env)]
        if self.n_task:
            parts.append(env.task.features(env))
        return np.concatenate(parts)


OBSERVATION_TYPES = {"positions": Positions, "features": ShotFeatures}


def observation_factory(env: "BilliardsEnv") -> ObservationType:
    """The observation type named by ``env.config.observation_type``."""
    return OBSERVATION_TYPES[env.config.observation_type](env)


__all__ = ["ObservationType", "Positions", "ShotFeatures", "OBSERVATION_TYPES", "observation_factory"]
