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
- :class:`CandidateFeatures` (``"candidates"``): the positions, then the candidate (ball, pocket) shots that the
  ``candidates`` action type chooses among (:mod:`billiards_env.envs.candidates`), a fixed number of slots of 12
  values each (pocket, cut, distances, ease, clear paths, scratch risk, speed), best first.
- :class:`CuePathFeatures` (``"candidates_path"``): the ``candidates`` values, then per slot where the cue ball goes
  after contact: at five offsets across the pocket's window, the least ``power`` that pots the ball and the least at
  which the deflected cue ball follows into a pocket (:mod:`billiards_env.envs.window_offsets`); for the
  ``candidates_aim`` action type.
- :class:`CuePositionFeatures` (``"candidates_position"``): the ``candidates`` values, then per slot a *position
  map*: on a grid of the ``candidates`` action's own ``power`` and ``top`` values, whether the ball drops, whether
  the cue ball scratches, where it comes to rest and how easy the next shot is from there
  (:mod:`billiards_env.envs.position`, closed form: :mod:`billiards_env.physics.cue_rest`); for the ``candidates``
  action type in the games.

A game appends its features (the turn, ball in hand, group...: its session's ``features``,
:mod:`billiards_env.games`), seen by the shooter or by the player asked for (the two-player env).
Every type reads a :class:`~billiards_env.table_state.TableState`, never the env: the single env, the native vector
env (one state per table) and a trained player observe through the same code.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from gymnasium import spaces

from billiards_env.physics.aim import pocket_bearings, pocket_mouth_axes, wrap_angle

from ._kernels import observation
from .candidates import EASY_TOLERANCE, SLOT_FEATURES, candidate_slots, slot_features  # noqa: F401
from .window_offsets import OFFSETS, PATH_FEATURES, offset_rows, power_of, thresholds
from .position import POINT_VALUES, POSITION_FEATURES, POWERS, TOPS, position_features

if TYPE_CHECKING:  # pragma: no cover
    from billiards_env.physics.table import Table
    from billiards_env.table_state import TableState

    from .config import EnvConfig


class ObservationType:
    """Builds the observation space, and the observation of a table state.

    ``ObservationType(config, table, n_balls, n_game_features=0)``: ``config`` sets the type's own settings (a policy
    trained on another config of the same game observes as it was trained to), ``n_game_features`` the game's
    features appended last (values in [0, 1])."""

    name = "positions"

    def __init__(self, config: "EnvConfig", table: "Table", n_balls: int, n_game_features: int = 0) -> None:
        n = int(n_balls)
        self._sx = 1.0 / table.length
        self._sy = 1.0 / table.width
        self.n_game = int(n_game_features)
        low = np.concatenate([np.zeros(3 * n, np.float32), -np.ones(self.n_extra, np.float32),
                              np.zeros(self.n_game, np.float32)])
        high = np.ones(3 * n + self.n_extra + self.n_game, np.float32)
        self.space = spaces.Box(low, high, dtype=np.float32)

    #: Values of the type's own features (:meth:`features`), after the positions; each in ``[-1, 1]``.
    n_extra = 0

    def features(self, state: "TableState") -> np.ndarray:
        """The type's own features (``n_extra`` values): none here."""
        return np.zeros(0, np.float32)

    def observe(self, state: "TableState", player: int | None = None) -> np.ndarray:
        """Positions and pocketed flags, the type's features, the game's features (seen by ``player``: default the
        shooter)."""
        b = state.balls
        parts = [observation(b.pos, b.on_table, self._sx, self._sy)]
        if self.n_extra:
            parts.append(self.features(state))
        if self.n_game:
            parts.append(state.game.features(player))
        return parts[0] if len(parts) == 1 else np.concatenate(parts)


class Positions(ObservationType):
    """Ball positions and pocketed flags (see the module docstring)."""

    name = "positions"


class ShotFeatures(ObservationType):
    """Positions, then the table seen from the target ball (see the module docstring)."""

    name = "features"

    def __init__(self, config: "EnvConfig", table: "Table", n_balls: int, n_game_features: int = 0) -> None:
        self.n_pockets = int(table.n_pockets)
        self.n_extra = 3 + 3 * self.n_pockets
        self._axes = pocket_mouth_axes(table)
        super().__init__(config, table, n_balls, n_game_features)

    def features(self, state: "TableState") -> np.ndarray:
        """The target-centred features (``3 + 3 * n_pockets`` values)."""
        out = np.zeros(self.n_extra, np.float32)
        t = state.view.target
        if t is None:
            return out
        b = state.balls
        scale = 1.0 / state.table.length
        v = b.pos[t] - b.pos[0]
        d = float(np.hypot(*v))
        out[0:2] = v / max(d, 1e-12)
        out[2] = min(d * scale, 1.0)
        bearing, dist, square = pocket_bearings(b.pos[t], state.table, self._axes)
        rel = wrap_angle(bearing - math.atan2(v[1], v[0]))
        order = np.argsort(np.abs(rel), kind="stable")
        out[3::3] = rel[order] / math.pi
        out[4::3] = np.minimum(np.maximum(dist[order], 1e-12) * scale, 1.0)
        out[5::3] = square[order]
        return out




class CandidateFeatures(ObservationType):
    """Positions, then the candidate shots of :mod:`billiards_env.envs.candidates` (what the ``candidates`` action
    type chooses among), ``candidate_slots`` slots of 12 values each, best first:

    ``0`` the slot holds a shot (else the slot's values are all 0), ``1`` the ball's number / 15, ``2-3`` the
    pocket's x / length and y / width (-1, -1 for the kick, the last slot; its ``5`` is the path's length), ``4`` the cut angle, signed (positive: the ball leaves to the left of the
    cue's line) / 90 deg, ``5`` the cue ball's distance to the ghost ball / length, ``6`` the ball's distance to the
    pocket / length, ``7`` the shot's ease (its cue-angle tolerance / 0.02 rad, at most 1; with ball in hand the
    window's half-width / (pi / 8)), ``8`` the paths are clear, ``9`` the speed needed is within range, ``10`` the
    cue ball risks following into a pocket, ``11`` the shot's speed / speed_max. With the cue ball in hand the
    cue-dependent values (4, 5, 9-11) are 0 and ``8`` is the ball's path only. Values in ``[-1, 1]``."""

    name = "candidates"

    def __init__(self, config: "EnvConfig", table: "Table", n_balls: int, n_game_features: int = 0) -> None:
        self.n_slots = int(config.candidate_slots)
        self.speed_range = (float(config.speed_min), float(config.speed_max))
        self.n_extra = SLOT_FEATURES * self.n_slots
        super().__init__(config, table, n_balls, n_game_features)

    def features(self, state: "TableState") -> np.ndarray:
        """The slots' values (``12 * candidate_slots``; one compiled call:
        :func:`billiards_env.envs.candidates.slot_features`)."""
        cands = candidate_slots(state, self.n_slots, self.speed_range)
        return slot_features(state, cands, self.n_slots, self.speed_range[1])


class CuePathFeatures(CandidateFeatures):
    """The ``candidates`` observation, then per slot :data:`~billiards_env.envs.window_offsets.PATH_FEATURES` values
    (where the cue ball goes after contact: :mod:`billiards_env.physics.cue_path`), in
    the units of the ``power`` dim of the ``candidates`` actions, each clipped to ``[-1, 1]``: for each offset of
    :data:`OFFSETS` (the ``offset`` dim of :class:`CandidateAim`), ``pot_at``, the least ``a[1]`` at which the
    object ball reaches its pocket, and ``scratch_at``, the least ``a[1]`` at which the cue ball, deflected, rolls
    into a pocket (+1 when it stops first at every speed of the range, or when that offset has no shot); then
    ``top``, the ``a[1]`` of ``speed_max``, beyond which the speed is clipped. Slots without a shot from where the
    cue ball lies (ball in hand, the kick, empty) read 0."""

    name = "candidates_path"

    def __init__(self, config: "EnvConfig", table: "Table", n_balls: int, n_game_features: int = 0) -> None:
        n_slots = int(config.candidate_slots)
        self.log_factor = math.log(float(config.candidate_speed_factor))
        self._n_path = PATH_FEATURES * n_slots
        super().__init__(config, table, n_balls, n_game_features)
        # the parent set n_extra and the space for its own values: widen both
        self.n_extra = self.n_extra + self._n_path
        n = 3 * int(n_balls)
        low = np.concatenate([np.zeros(n, np.float32), -np.ones(self.n_extra, np.float32),
                              np.zeros(self.n_game, np.float32)])
        self.space = spaces.Box(low, np.ones_like(low), dtype=np.float32)

    def path_features(self, state: "TableState") -> np.ndarray:
        """``(candidate_slots, PATH_FEATURES)``: the values above."""
        out = np.zeros((self.n_slots, PATH_FEATURES), np.float32)
        cands = candidate_slots(state, self.n_slots, self.speed_range)
        if not cands.slots or cands.slots[0].shot is None:
            return out
        k = len(OFFSETS)
        thr = thresholds(state, offset_rows(state, cands), self.speed_range[1]).reshape(len(cands.slots), k, 2)
        for i, s in enumerate(cands.slots):
            base = s.shot.speed
            out[i, 0:2 * k] = np.clip(power_of(thr[i], base, self.log_factor), -1.0, 1.0).reshape(-1)
            out[i, 2 * k] = np.clip(power_of(self.speed_range[1], base, self.log_factor), -1.0, 1.0)
        return out

    def features(self, state: "TableState") -> np.ndarray:
        """The ``candidates`` values, then the path values."""
        return np.concatenate([super().features(state), self.path_features(state).reshape(-1)])


class CuePositionFeatures(CandidateFeatures):
    """The ``candidates`` observation, then per slot :data:`~billiards_env.envs.position.POSITION_FEATURES` values:
    for each ``power`` of :data:`~billiards_env.envs.position.POWERS` (``a[1]``) and each ``top`` of
    :data:`~billiards_env.envs.position.TOPS` (``a[3]``, side 0), power-major, :data:`POINT_VALUES` values in
    ``[0, 1]``: the ball reaches its pocket (1/0), the cue ball runs into a pocket (1/0), its rest x / length and
    y / width, the chance of potting the next legal ball from there (the search player's position term; 0 after a
    scratch, 1 when the pot clears the table). Slots without a shot from where the cue ball lies (ball in hand, the
    break, the kick, empty) read 0. Closed form, no simulation (:mod:`billiards_env.envs.position`)."""

    name = "candidates_position"

    def __init__(self, config: "EnvConfig", table: "Table", n_balls: int, n_game_features: int = 0) -> None:
        n_slots = int(config.candidate_slots)
        self.log_factor = math.log(float(config.candidate_speed_factor))
        self.max_tip = float(config.max_tip_offset)
        self._n_pos = POSITION_FEATURES * n_slots
        super().__init__(config, table, n_balls, n_game_features)
        self.n_extra = self.n_extra + self._n_pos
        n = 3 * int(n_balls)
        low = np.concatenate([np.zeros(n, np.float32), -np.ones(self.n_extra, np.float32),
                              np.zeros(self.n_game, np.float32)])
        self.space = spaces.Box(low, np.ones_like(low), dtype=np.float32)

    def position_features(self, state: "TableState") -> np.ndarray:
        """``(candidate_slots, POSITION_FEATURES)``: the values above."""
        cands = candidate_slots(state, self.n_slots, self.speed_range)
        return position_features(state, cands, self.n_slots, self.speed_range, self.log_factor, self.max_tip)

    def features(self, state: "TableState") -> np.ndarray:
        """The ``candidates`` values, then the position map."""
        return np.concatenate([super().features(state), self.position_features(state).reshape(-1)])


OBSERVATION_TYPES = {"positions": Positions, "features": ShotFeatures, "candidates": CandidateFeatures,
                     "candidates_path": CuePathFeatures, "candidates_position": CuePositionFeatures}


def observation_factory(config: "EnvConfig", table: "Table", n_balls: int, n_game_features: int = 0
                        ) -> ObservationType:
    """The observation type named by ``config.observation_type``."""
    return OBSERVATION_TYPES[config.observation_type](config, table, n_balls, n_game_features)


__all__ = ["ObservationType", "Positions", "ShotFeatures", "CandidateFeatures", "CuePathFeatures",
           "CuePositionFeatures", "POINT_VALUES", "POWERS", "TOPS", "OBSERVATION_TYPES",
           "observation_factory", "SLOT_FEATURES"]
