"""Gymnasium wrappers that make the billiards shot learnable in minutes (usable from the RL Zoo as ``env_wrapper``).

``GhostAimWrapper`` (the default agent's action): ``a[0] = phi`` is the direction the *target ball* should take,
``phi * 90 deg`` from the cue->target line; the wrapper strikes the cue ball towards the ghost-ball position
that sends it there. It inverts the two-ball collision geometry only: the agent still has to learn where the
pockets are, which one is makeable from where, and how hard to hit.

``CutAimWrapper``: ``a[0] = b`` is the cut fraction on the target ball (``b = 0`` full hit, ``|b| = 1`` a
graze): the cue's line passes the target's centre at ``b (r_cue + r_target)``. Distance-independent like the
ghost aim, with a ``sin`` between it and the object ball's direction.

Both take ``a[1]`` as power over ``[speed_min, speed_max]``, by default the env's range; a sub-range can be
given (the default configs use soft shots only, ``speed_max: 1.8``: see configs/train/one_ball_sac.yaml), and
both go through the env's ``action_from_shot``, so they work with either ``aim`` mode of the env. The target
ball is the lowest-numbered object ball on the table, the one ``aim="relative"`` measures from.

``ShotFeatures`` appends the table seen from the target ball: the cue->target direction and distance, and
per pocket the cut it asks for, its distance and how squarely it would be entered, sorted by cut (a set of
pockets in one canonical order).
"""
from __future__ import annotations

import math
from typing import Any

import gymnasium as gym
import numpy as np
from gymnasium import spaces

from billiards_env.physics.aim import (aim_angle, aim_offset, ghost_ball_position, offset_aim_angle, pocket_bearings,
                                       pocket_mouth_axes, wrap_angle)


def _target_row(env: Any) -> int | None:
    u = env.unwrapped
    if hasattr(u, "target_ball"):
        return u.target_ball()
    on = u.balls.on_table
    for i in range(1, len(on)):
        if on[i]:
            return i
    return None


def _speed_range(env: gym.Env, lo: float | None, hi: float | None, who: str) -> tuple[float, float]:
    """The wrapper's cue-speed range: a sub-range of the env's [speed_min, speed_max] (None: the env's)."""
    cfg = env.unwrapped.config
    lo = float(cfg.speed_min) if lo is None else float(lo)
    hi = float(cfg.speed_max) if hi is None else float(hi)
    if not (cfg.speed_min <= lo < hi <= cfg.speed_max):
        raise ValueError(f"{who}: speed range [{lo}, {hi}] must be a non-empty part of the env's "
                         f"[{cfg.speed_min}, {cfg.speed_max}] m/s")
    return lo, hi


class _ShotActionWrapper(gym.ActionWrapper):
    """An action wrapper that maps its own action ``[aim, power]`` to a shot ``(angle, speed)``
    (``shot_from_action``) and plays it through the env's own action mapping. ``power`` maps linearly onto
    the wrapper's speed range."""

    def __init__(self, env: gym.Env, speed_min: float | None, speed_max: float | None):
        super().__init__(env)
        self.speed_lo, self.speed_hi = _speed_range(env, speed_min, speed_max, type(self).__name__)
        self.action_space = spaces.Box(-1.0, 1.0, shape=(2,), dtype=np.float32)

    def _aim_and_speed(self, action: Any) -> tuple[float, float]:
        """The clipped aim component and the speed (m/s) of a wrapped action."""
        a = np.clip(np.asarray(action, dtype=np.float64).reshape(-1), -1.0, 1.0)
        return float(a[0]), float(self.speed_lo + 0.5 * (a[1] + 1.0) * (self.speed_hi - self.speed_lo))

    def shot_from_action(self, action: Any) -> tuple[float, float]:
        raise NotImplementedError

    def action(self, action: Any) -> np.ndarray:
        angle, speed = self.shot_from_action(action)
        return np.asarray(self.env.unwrapped.action_from_shot(angle, speed), dtype=np.float32)


class CutAimWrapper(_ShotActionWrapper):
    """Action ``[b, power]``: cut fraction ``b`` on the target ball, power as the env's ``a[1]``.

    ``max_cut``: ``|b| = 1`` maps to this fraction (1.0 = a full graze); lower it to spend the action range on
    makeable cuts.
    """

    def __init__(self, env: gym.Env, max_cut: float = 1.0, speed_min: float | None = None,
                 speed_max: float | None = None):
        if not 0.0 < max_cut <= 1.0:
            raise ValueError(f"CutAimWrapper: max_cut must be in (0, 1], got {max_cut}")
        super().__init__(env, speed_min, speed_max)
        self.max_cut = float(max_cut)

    def shot_from_action(self, action: Any) -> tuple[float, float]:
        """The ``(angle, speed)`` of a wrapped action (before the env's noise)."""
        aim, speed = self._aim_and_speed(action)
        u = self.env.unwrapped
        t = _target_row(self.env)
        b = u.balls
        if t is None:
            return 0.0, speed
        reach = float(b.radius[0] + b.radius[t])
        return offset_aim_angle(b.pos[0], b.pos[t], aim * self.max_cut * reach), speed

    def action_from_shot(self, angle: float, speed: float) -> np.ndarray:
        """Inverse mapping (for baselines played through the wrapper): the cut fraction of a cue direction."""
        u = self.env.unwrapped
        a1 = 2.0 * (speed - self.speed_lo) / (self.speed_hi - self.speed_lo) - 1.0
        t = _target_row(self.env)
        if t is None:
            return np.array([0.0, np.clip(a1, -1, 1)], dtype=np.float32)
        b = u.balls
        reach = float(b.radius[0] + b.radius[t])
        frac = aim_offset(b.pos[0], b.pos[t], angle) / (reach * self.max_cut)
        return np.clip(np.array([frac, a1], dtype=np.float32), -1.0, 1.0)


class GhostAimWrapper(_ShotActionWrapper):
    """Action ``[phi, power]``: send the target ball off at ``phi * max_angle`` from the cue->target direction.

    The wrapper places the cue ball's contact (ghost-ball) position ``G = O - (r_cue + r_obj) u(theta)`` behind
    the target ``O`` for the object-ball direction ``theta = dir(cue->O) + phi * max_angle`` and strikes the cue
    ball towards ``G``. This inverts the collision geometry only (no pocket knowledge): the agent still learns
    where the pockets are, which one is makeable, and how hard to hit. ``max_angle`` defaults to 90 deg (the
    whole half-plane of cut shots). If another ball is in the way the shot is played all the same.
    """

    def __init__(self, env: gym.Env, max_angle_deg: float = 90.0, speed_min: float | None = None,
                 speed_max: float | None = None):
        if not 0.0 < max_angle_deg <= 90.0:
            raise ValueError(f"GhostAimWrapper: max_angle_deg must be in (0, 90], got {max_angle_deg}")
        super().__init__(env, speed_min, speed_max)
        self.max_angle = math.radians(max_angle_deg)

    def shot_from_action(self, action: Any) -> tuple[float, float]:
        aim, speed = self._aim_and_speed(action)
        u = self.env.unwrapped
        t = _target_row(self.env)
        if t is None:
            return 0.0, speed
        b = u.balls
        C, O = b.pos[0], b.pos[t]
        theta = aim_angle(C, O) + aim * self.max_angle
        G = ghost_ball_position(O, theta, float(b.radius[0] + b.radius[t]))
        return aim_angle(C, G), speed

    def action_from_object_direction(self, theta: float, speed: float) -> np.ndarray:
        """The action sending the target ball in direction ``theta`` with cue speed ``speed``."""
        u = self.env.unwrapped
        a1 = 2.0 * (speed - self.speed_lo) / (self.speed_hi - self.speed_lo) - 1.0
        t = _target_row(self.env)
        if t is None:
            return np.array([0.0, np.clip(a1, -1, 1)], dtype=np.float32)
        C, O = u.balls.pos[0], u.balls.pos[t]
        phi = wrap_angle(theta - aim_angle(C, O))
        return np.clip(np.array([phi / self.max_angle, a1], dtype=np.float32), -1.0, 1.0)


class ShotFeatures(gym.ObservationWrapper):
    """Observation = the env's observation + the table seen from the target ball (see the module doc).

    Appended, all in [-1, 1]: the cue->target unit vector (2) and distance / table length (1); then one slot of
    three numbers per pocket: the signed angle between the cue->target direction and the target->pocket
    direction divided by pi (the cut that pocket asks for), the target->pocket distance / table length, and the
    cosine between the target->pocket direction and the pocket's mouth axis (how squarely the ball would
    enter). With ``sort_pockets`` (default) the slots are ordered by the size of the cut, smallest first, so
    "the straightest pocket" is always in the first slot: the pockets are a set, and sorting gives the network
    one canonical order instead of six arbitrary ones. Zeros when no target is left.
    """

    def __init__(self, env: gym.Env, sort_pockets: bool = True):
        super().__init__(env)
        base = env.observation_space
        table = env.unwrapped.table
        self.sort_pockets = bool(sort_pockets)
        self.n_pockets = int(table.n_pockets)
        self.n_extra = 3 + 3 * self.n_pockets
        low = np.concatenate([np.asarray(base.low, np.float32).reshape(-1), -np.ones(self.n_extra, np.float32)])
        high = np.concatenate([np.asarray(base.high, np.float32).reshape(-1), np.ones(self.n_extra, np.float32)])
        self.observation_space = spaces.Box(low, high, dtype=np.float32)
        self._axis = pocket_mouth_axes(table)  # corner: diagonal, side: perpendicular to the rail

    def features(self) -> np.ndarray:
        u = self.env.unwrapped
        t = _target_row(self.env)
        out = np.zeros(self.n_extra, np.float32)
        if t is None:
            return out
        b = u.balls
        scale = 1.0 / u.table.length
        v = b.pos[t] - b.pos[0]
        d = float(np.hypot(*v))
        out[0:2] = v / max(d, 1e-12)
        out[2] = min(d * scale, 1.0)
        bearing, dist, mouth = pocket_bearings(b.pos[t], u.table, self._axis)
        dw = np.maximum(dist, 1e-12)
        rel = wrap_angle(bearing - aim_angle(b.pos[0], b.pos[t]))
        order = np.argsort(np.abs(rel), kind="stable") if self.sort_pockets else np.arange(self.n_pockets)
        out[3::3] = rel[order] / math.pi
        out[4::3] = np.minimum(dw[order] * scale, 1.0)
        out[5::3] = mouth[order]
        return out

    def observation(self, observation: Any) -> np.ndarray:
        return np.concatenate([np.asarray(observation, np.float32).reshape(-1), self.features()])


WRAPPERS = {"CutAimWrapper": CutAimWrapper, "GhostAimWrapper": GhostAimWrapper, "ShotFeatures": ShotFeatures}

__all__ = ["CutAimWrapper", "GhostAimWrapper", "ShotFeatures", "WRAPPERS"]
