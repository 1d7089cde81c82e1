"""Action types: how an action vector becomes a cue shot, and back (chosen by the ``action_type`` config key).

Every action is a ``Box(-1, 1)`` vector laid out as::

    [aim, power]  (+ [side, top] with spin_action)  (+ [place_x, place_y] in games)  (+ [pocket] / [push])

- ``aim`` depends on the type: :class:`AbsoluteAim` (``angle = pi a``), :class:`RelativeAim` (``pi a`` from the
  direction cue -> target ball), :class:`GhostAim` (the direction the target ball leaves in, ``a *
  ghost_max_angle`` from the cue -> target line; the cue is aimed at the ghost-ball position that sends it there),
  :class:`CandidateShots` (``candidates``: one of the candidate (ball, pocket) shots of
  :mod:`billiards_env.envs.candidates`; ``power`` then scales that shot's own speed, and with ball in hand the
  placement is set relative to it: see the class); :class:`CandidateAim` (``candidates_aim``) adds a last dim,
  ``offset``: where in the chosen pot's entry window the object ball is sent (:mod:`billiards_env.envs.window_offsets`).
- ``power``: ``speed = speed_min + (a + 1) / 2 (speed_max - speed_min)``.
- ``side``, ``top``: the square ``[-1, 1]^2`` mapped onto the disc of tip offsets of radius ``max_tip_offset``
  (fractions of the ball radius) by the elliptical grid mapping ``(u, v) = (x sqrt(1 - y^2/2), y sqrt(1 - x^2/2))``:
  the corners reach the rim, the axes keep their meaning (side only, top only), and every action is a legal tip
  position (never a miscue).
- ``place_x``, ``place_y``: where the cue ball goes when the shooter has ball in hand, linearly over the allowed
  area; ignored otherwise. A point that overlaps a ball or leaves the area is moved to the nearest legal point
  (:func:`billiards_env.physics.layout.nearest_free_point`).
- the game's declarations, one dim each, as the game declares them
  (:class:`~billiards_env.games.declarations.Declaration`): ``pocket`` (8-ball with called 8s: the pocket called
  for the 8, ``k = floor((a + 1) / 2 * n_pockets)`` in the table's pocket order, read only when the shooter is on
  the 8; straight pool: the called ball's pocket), ``ball`` (straight pool: the called ball, row
  ``1 + floor((a + 1) / 2 * n_object_balls)``), ``push`` (9-ball with push-outs: ``a > 0`` declares a push-out
  when one is allowed; ignored otherwise. After a push-out the incoming player always plays: the envs do not
  offer the pass-back of :meth:`billiards_env.rules.NineBall.pass_back`).

Finite values outside ``[-1, 1]`` are clipped (a policy outputs anything); NaN/inf or a wrong number of values
raise ``ValueError``. Any array holding the right number of values is accepted (``(2,)``, ``(1, 2)``...).
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np
from gymnasium import spaces
from numba import njit

from billiards_env.games.declarations import Declaration
from billiards_env.physics.aim import (aim_angle, direction_vector, ghost_ball_aim, ray_circle_entry, wrap_angle)
from billiards_env.physics.layout import py_hypot
from billiards_env.players.geometry import (ARRIVE_SPEED, COL_ANGLE, COL_POCKET, COL_SPEED, SPEED_FACTORS, ghost_shots,
                                            state_model)
from billiards_env.players.shots import direct_hit
from billiards_env.shot_path import CueShot, noisy_shot

from .candidates import candidate_slots
from .window_offsets import OFFSET_SPAN, OFFSETS, offset_ghost, offset_of

if TYPE_CHECKING:  # pragma: no cover
    from billiards_env.table_state import TableState

    from .config import EnvConfig


@njit(cache=True)
def _clip(v: float) -> float:
    return -1.0 if v < -1.0 else (1.0 if v > 1.0 else v)


# --- the arithmetic of a shot, compiled once: the single env calls it, and so does the native vector env ------------
#: Codes of the aim components computed by :func:`aim_to_angle`.
AIM_ABSOLUTE, AIM_RELATIVE, AIM_GHOST = 0, 1, 2


@njit(cache=True)
def aim_to_angle(code: int, a: float, cx: float, cy: float, tx: float, ty: float, has_target: bool,
                 contact: float, max_ghost: float) -> float:
    """The cue direction of aim component ``a`` for the cue ball at ``(cx, cy)`` and the target ball at
    ``(tx, ty)`` (``contact``: the two radii summed): absolute ``pi a``; relative ``pi a`` from the direction to the
    target; ghost: the ghost-ball aim that sends the target ``a * max_ghost`` (rad) off the cue -> target line.
    Without a target: relative counts from 0, ghost aims at 0."""
    if code == AIM_ABSOLUTE:
        return math.pi * a
    if code == AIM_RELATIVE:
        return math.pi * a + (math.atan2(ty - cy, tx - cx) if has_target else 0.0)
    if not has_target:
        return 0.0
    return ghost_ball_aim(cx, cy, tx, ty, math.atan2(ty - cy, tx - cx) + a * max_ghost, contact)


@njit(cache=True)
def _wrap(angle: float) -> float:
    """:func:`billiards_env.physics.aim.wrap_angle` of one angle, compiled."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


@njit(cache=True)
def angle_to_aim(code: int, angle: float, cx: float, cy: float, tx: float, ty: float, has_target: bool,
                 contact: float, max_ghost: float) -> float:
    """Inverse of :func:`aim_to_angle`: the aim component of cue direction ``angle``. Absolute: ``angle / pi``
    (wrapped); relative: the angle from the direction to the target / pi; ghost: the direction the target leaves in
    (the line of centres at first contact) from the cue -> target line / ``max_ghost``, a cue line that misses the
    target mapping to the nearer end (+-1). Without a target: relative counts from 0, ghost gives 0."""
    if code == AIM_ABSOLUTE:
        return _wrap(angle) / math.pi
    if code == AIM_RELATIVE:
        base = math.atan2(ty - cy, tx - cx) if has_target else 0.0
        return _wrap(angle - base) / math.pi
    if not has_target:
        return 0.0
    base = math.atan2(ty - cy, tx - cx)
    ux = math.cos(angle)
    uy = math.sin(angle)
    d = ray_circle_entry(cx, cy, ux, uy, tx, ty, contact)
    if not math.isfinite(d):
        return -1.0 if _wrap(angle - base) > 0 else 1.0
    return _wrap(math.atan2(ty - (cy + uy * d), tx - (cx + ux * d)) - base) / max_ghost


@njit(cache=True)
def power_to_speed(a: float, speed_lo: float, speed_span: float) -> float:
    """The cue speed of power component ``a`` (in [-1, 1]): linear over ``[speed_lo, speed_lo + speed_span]``."""
    return speed_lo + 0.5 * (a + 1.0) * speed_span


@njit(cache=True)
def square_to_disc(x: float, y: float) -> tuple:
    """The elliptical grid mapping of the square ``[-1, 1]^2`` onto the unit disc."""
    return x * math.sqrt(1.0 - 0.5 * y * y), y * math.sqrt(1.0 - 0.5 * x * x)


@njit(cache=True)
def disc_to_square(u: float, v: float) -> tuple:
    """Inverse of :func:`square_to_disc` (points outside the unit disc are first moved onto its rim); compiled, so
    the native games' kernels call it too (``py_hypot``: CPython's hypot, bit for bit)."""
    r = py_hypot(u, v)
    if r > 1.0:
        u, v = u / r, v / r
    s2 = 2.0 * math.sqrt(2.0)
    a = 2.0 + u * u - v * v
    b = 2.0 - u * u + v * v
    x = 0.5 * math.sqrt(max(a + s2 * u, 0.0)) - 0.5 * math.sqrt(max(a - s2 * u, 0.0))
    y = 0.5 * math.sqrt(max(b + s2 * v, 0.0)) - 0.5 * math.sqrt(max(b - s2 * v, 0.0))
    return _clip(x), _clip(y)


class ActionType:
    """Maps an action vector to a :class:`CueShot` and back. Subclasses define the aim component."""

    name = "absolute"
    #: Whether :meth:`action` is the exact inverse of :meth:`shot` (every shot has its action).
    exact_inverse = True

    def __init__(self, config: "EnvConfig", placement: bool = False, declarations: tuple[Declaration, ...] = (),
                 n_pockets: int = 6) -> None:
        for d in declarations:
            if not isinstance(d, Declaration):
                raise TypeError(f"declarations: expected Declaration objects (billiards_env.games.declarations), got "
                                f"{type(d).__name__} {d!r}")
        self.speed_lo = float(config.speed_min)
        self.speed_span = float(config.speed_max - config.speed_min)
        self.spin = bool(config.spin_action)
        self.max_tip = float(config.max_tip_offset)
        self.placement = bool(placement)
        self.declarations = tuple(declarations)
        self.n_pockets = int(n_pockets)
        #: Rows of the table (the ``ball`` declaration chooses among the object balls).
        self.n_balls = int(config.n_object_balls) + 1
        self._spin_at = 2
        self._place_at = 4 if self.spin else 2
        at = self._place_at + (2 if self.placement else 0)
        self._declare_at = {d.name: at + k for k, d in enumerate(self.declarations)}
        self.n = at + len(self.declarations)
        self.space = spaces.Box(-1.0, 1.0, shape=(self.n,), dtype=np.float32)

    @property
    def place_at(self) -> int:
        """Index of the ``place_x`` dim (``place_y`` follows) when the action has placement dims."""
        return self._place_at

    @property
    def declare_at(self) -> dict[str, int]:
        """Index of each declaration's dim, by its name."""
        return dict(self._declare_at)

    def with_calls(self, action: np.ndarray, **calls: Any) -> np.ndarray:
        """``action`` with the dims of the declarations in ``calls`` set to their values (names this type does not
        declare are ignored; the other dims stay as they are)."""
        out = np.array(action, dtype=np.float32, copy=True)
        for d in self.declarations:
            if d.name in calls:
                out[self._declare_at[d.name]] = np.float32(np.clip(d.encode(calls[d.name], self.n_pockets,
                                                                            self.n_balls), -1.0, 1.0))
        return out

    # --- the aim component (a subclass's part) ----------------------------------------------------------------
    #: The :func:`aim_to_angle` code of this aim type.
    code = AIM_ABSOLUTE
    max_angle = 0.0

    def angle(self, state: "TableState", a: float) -> float:
        """Cue direction (rad) of aim component ``a`` (in [-1, 1]): :func:`aim_to_angle` (so does its compiled twin,
        :func:`._action_kernels.angle_of_action`)."""
        b = state.balls
        t = state.view.target if self.code != AIM_ABSOLUTE else None
        if t is None:
            return aim_to_angle(self.code, a, float(b.pos[0, 0]), float(b.pos[0, 1]), 0.0, 0.0, False, 0.0,
                                self.max_angle)
        return aim_to_angle(self.code, a, float(b.pos[0, 0]), float(b.pos[0, 1]), float(b.pos[t, 0]),
                            float(b.pos[t, 1]), True, float(b.radius[0] + b.radius[t]), self.max_angle)

    def aim(self, state: "TableState", angle: float) -> float:
        """Aim component of cue direction ``angle`` (inverse of :meth:`angle`): :func:`angle_to_aim` (so does its
        compiled twin, :func:`._action_kernels.aim_of_angle`)."""
        b = state.balls
        t = state.view.target if self.code != AIM_ABSOLUTE else None
        if t is None:
            return angle_to_aim(self.code, float(angle), float(b.pos[0, 0]), float(b.pos[0, 1]), 0.0, 0.0, False,
                                0.0, self.max_angle)
        return angle_to_aim(self.code, float(angle), float(b.pos[0, 0]), float(b.pos[0, 1]), float(b.pos[t, 0]),
                            float(b.pos[t, 1]), True, float(b.radius[0] + b.radius[t]), self.max_angle)

    # --- the whole vector ------------------------------------------------------------------------------------
    def parse(self, action: Any) -> list[float]:
        """The action's values, clipped to [-1, 1] (NaN/inf and a wrong count raise ValueError)."""
        try:
            values = np.asarray(action, dtype=np.float64).reshape(-1).tolist()
        except (ValueError, TypeError):
            raise ValueError(f"action: expected {self.n} numbers in [-1, 1] ({self.layout()}), got "
                             f"{action!r}") from None
        if len(values) != self.n:
            raise ValueError(f"action: expected {self.n} numbers in [-1, 1] ({self.layout()}), got {len(values)}: "
                             f"{action!r}")
        for v in values:
            if not math.isfinite(v):
                raise ValueError(f"action: must be finite numbers, got {values}; check the policy's output for "
                                 "NaN/inf")
        return [_clip(v) for v in values]

    def layout(self) -> str:
        names = ["aim", "power"] + (["side", "top"] if self.spin else []) \
            + (["place_x", "place_y"] if self.placement else []) + [d.name for d in self.declarations]
        return ", ".join(names)

    def shot(self, state: "TableState", action: Any) -> CueShot:
        """The shot an action means now (no noise). Placement is read only when the shooter has ball in hand.
        Compiled twin (the native vector env's pool tables): :func:`._action_kernels.shot_of_action`."""
        a = self.parse(action)
        speed = power_to_speed(a[1], self.speed_lo, self.speed_span)
        side = top = 0.0
        if self.spin:
            u, v = square_to_disc(a[self._spin_at], a[self._spin_at + 1])
            side, top = self.max_tip * u, self.max_tip * v
        calls = tuple((d.name, d.decode(a[self._declare_at[d.name]], self.n_pockets, self.n_balls))
                      for d in self.declarations)
        area = state.view.place_area if self.placement else None
        if area is None:
            return CueShot(self.angle(state, a[0]), speed, side, top, None, calls)
        k = self._place_at
        place = state.legal_cue_position(*area.point(a[k], a[k + 1]))
        with state.cue_moved_to(place):  # the aim is relative to where the cue ball will be
            angle = self.angle(state, a[0])
        return CueShot(angle, speed, side, top, place, calls)

    def action(self, state: "TableState", angle: float, speed: float, side: float = 0.0, top: float = 0.0,
               place: tuple[float, float] | None = None, **calls: Any) -> np.ndarray:
        """The action of a shot (inverse of :meth:`shot`); ``calls``: the declarations by name (those the type does
        not declare are ignored: a player states its whole call). Speeds outside the range clip, extra dims not
        given take neutral values (no spin; the placement dims the middle of the area; a choice its first value,
        e.g. pocket 0; a flag False). Compiled twin (of a shot without tip offsets nor push-out, the geometric
        opponent's in the native vector env): :func:`._action_kernels.action_of_shot`."""
        for name, v in (("angle", angle), ("speed", speed), ("side", side), ("top", top)):
            if not math.isfinite(float(v)):
                raise ValueError(f"action_from_shot: {name} must be finite, got {v!r}")
        out = np.zeros(self.n, dtype=np.float64)
        area = state.view.place_area if (self.placement and place is not None) else None
        if area is not None:
            out[self._place_at], out[self._place_at + 1] = area.square(float(place[0]), float(place[1]))
            with state.cue_moved_to(state.legal_cue_position(float(place[0]), float(place[1]))):
                out[0] = self.aim(state, angle)
        else:
            out[0] = self.aim(state, angle)
        out[1] = 2.0 * (float(speed) - self.speed_lo) / self.speed_span - 1.0
        if self.spin:
            out[self._spin_at], out[self._spin_at + 1] = disc_to_square(side / self.max_tip, top / self.max_tip)
        for d in self.declarations:
            out[self._declare_at[d.name]] = d.encode(calls.get(d.name, d.default), self.n_pockets, self.n_balls)
        return np.clip(out, -1.0, 1.0).astype(np.float32)


    # --- many shots at once (the search player values what an action plays) ---------------------------------------
    @property
    def plain_absolute(self) -> bool:
        """Whether this type is the plain absolute aim (the base class's arithmetic, untouched by a subclass), whose
        round trip :meth:`round_trip_arrays` computes on arrays."""
        cls = type(self)
        return self.code == AIM_ABSOLUTE and all(getattr(cls, name) is getattr(ActionType, name)
                                                 for name in ("angle", "aim", "shot", "action", "parse"))

    def round_trip_arrays(self, angles: np.ndarray, speeds: np.ndarray, sides: np.ndarray, tops: np.ndarray
                          ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """For the plain absolute aim (:attr:`plain_absolute`): the shots ``(angles, speeds, sides, tops)`` played
        by the float32 actions of the given ones (:meth:`action` then :meth:`shot`, the same float operations,
        element by element; the tip dims per distinct tip offset), and those actions' shot dims ``(N, 2 or 4)``."""
        if not self.plain_absolute:
            raise TypeError(f"round_trip_arrays: only the plain absolute aim maps arrays, not {self.name!r}")
        lo, span = self.speed_lo, self.speed_span
        angles = np.asarray(angles, dtype=np.float64)
        a0 = np.clip(((angles + math.pi) % (2.0 * math.pi) - math.pi) / math.pi, -1.0, 1.0).astype(np.float32)
        a1 = np.clip(2.0 * (np.asarray(speeds, dtype=np.float64) - lo) / span - 1.0, -1.0, 1.0).astype(np.float32)
        angle = math.pi * np.clip(a0.astype(np.float64), -1.0, 1.0)
        speed = lo + 0.5 * (np.clip(a1.astype(np.float64), -1.0, 1.0) + 1.0) * span
        side = np.zeros(len(angles))
        top = np.zeros(len(angles))
        dims = [a0, a1]
        if self.spin:
            a2 = np.zeros(len(angles), np.float32)
            a3 = np.zeros(len(angles), np.float32)
            sides = np.asarray(sides, dtype=np.float64)
            tops = np.asarray(tops, dtype=np.float64)
            for sd0, tp0 in set(zip(sides.tolist(), tops.tolist())):
                sel = (sides == sd0) & (tops == tp0)
                x, y = np.clip(np.array(disc_to_square(sd0 / self.max_tip, tp0 / self.max_tip)), -1.0,
                               1.0).astype(np.float32)
                u, w = square_to_disc(min(max(float(x), -1.0), 1.0), min(max(float(y), -1.0), 1.0))
                a2[sel], a3[sel] = x, y
                side[sel], top[sel] = self.max_tip * u, self.max_tip * w
            dims += [a2, a3]
        return angle, speed, side, top, np.stack(dims, axis=1)


class AbsoluteAim(ActionType):
    """``angle = pi * a[0]`` (0 = +x, counter-clockwise)."""

    name = "absolute"


class RelativeAim(ActionType):
    """``angle = direction(cue -> target) + pi * a[0]``: ``a[0] = 0`` hits the target ball full."""

    name = "relative"
    code = AIM_RELATIVE


class GhostAim(ActionType):
    """``a[0]``: the direction the target ball leaves in, ``a[0] * ghost_max_angle`` from the cue -> target line;
    the cue ball is struck towards the ghost-ball position that sends it there. This inverts the two-ball collision
    geometry only: which pocket, and how hard, is still the agent's to learn. Another ball in the way is not
    checked."""

    name = "ghost"
    code = AIM_GHOST

    def __init__(self, config: "EnvConfig", placement: bool = False, declarations: tuple[Declaration, ...] = (),
                 n_pockets: int = 6) -> None:
        super().__init__(config, placement, declarations, n_pockets)
        self.max_angle = math.radians(config.ghost_max_angle)



#: ``candidates`` with the cue ball in hand: its distance (m) behind the ghost ball for ``place_x`` = -1 and +1, and
#: the cut angle (rad) of the placement for ``|place_y|`` = 1.
PLACE_BACK = (0.08, 0.8)
PLACE_MAX_CUT = math.radians(60.0)
#: ``candidates`` with the cue ball in hand: the largest cut of the ghost-ball shot played from the place.
PLACED_MAX_CUT = math.radians(89.0)
_SPEED_FACTORS = np.array(SPEED_FACTORS)
#: ``candidates``: the speed (m/s) of the fallback full-ball hit when no candidate shot exists (the geometric
#: player's firm hit); ``power`` scales it as it scales a candidate's speed.
FALLBACK_SPEED = 2.0


class CandidateShots(ActionType):
    """Choose one of the candidate shots (:mod:`billiards_env.envs.candidates`) and play it for position.

    - ``aim`` picks slot ``k = min(floor(|a| * candidate_slots), candidate_slots - 1)``: the pots are the first
      ``candidate_slots - 1`` (the easiest first, so values near 0 play the geometric player's choice; a slot past
      the end of a short list is its last one), the last slot is the kick (a one-rail kick at a legal ball, when
      the cue ball is where it lies and a kick exists, played at the speed and without the tip offsets it was
      verified with: ``power``, ``side`` and ``top`` are ignored; else the easiest pot).
    - ``power``: the candidate's own speed (the ghost-ball speed that gets the ball to the pocket, as the geometric
      player computes it) times ``candidate_speed_factor ** a``: softer below 0, firmer above.
    - ``side``, ``top``: as every type.
    - ``place_x``, ``place_y`` with the cue ball in hand: where to put it for the chosen (ball, pocket):
      ``PLACE_BACK`` metres behind the ghost ball (``place_x`` -1 .. 1, 0.44 m at 0), at a cut of
      ``place_y * 60`` degrees (0: straight in); moved to the nearest legal point. The cue is then aimed at that
      ghost ball from where it stands.
    - the declarations ``pocket`` and ``ball`` (8-ball's 8, straight pool's call): ignored; the chosen candidate's
      ball and pocket are called.
    - The break: a full-ball hit on the nearest legal ball at ``speed_max * candidate_speed_factor ** min(a, 0)``
      (full power from 0 up), the cue ball at ``x = x1 - |place_x| (x1 - x0)`` (0: on the head string) and ``y``
      linear over the kitchen (0: the middle), as the geometric player breaks at 0.
    - No candidate at all (no legal ball has a pocket window): a full-ball hit on the nearest legal ball at
      ``FALLBACK_SPEED`` scaled by ``power``; in hand, placed as every type places it.

    :meth:`action` (``action_from_shot``) is the nearest this type can express: the slot whose aim is closest to the
    angle given, and its speed factor. It is not an exact inverse: players that aim shots of their own
    (:mod:`billiards_env.players`) play as the env's opponent through an exact type (see
    :meth:`billiards_env.envs.games.GameTask.set_opponent`).
    """

    name = "candidates"
    exact_inverse = False

    def __init__(self, config: "EnvConfig", placement: bool = False, declarations: tuple[Declaration, ...] = (),
                 n_pockets: int = 6) -> None:
        super().__init__(config, placement, declarations, n_pockets)
        self.n_slots = int(config.candidate_slots)
        self.log_factor = math.log(float(config.candidate_speed_factor))
        self.speed_range = (self.speed_lo, self.speed_lo + self.speed_span)

    def slots(self, state: "TableState") -> Any:
        """The candidate list of the table now (:func:`billiards_env.envs.candidates.candidate_slots`)."""
        return candidate_slots(state, self.n_slots, self.speed_range)

    def _slot(self, a: float, n: int) -> int:
        return min(int(abs(a) * self.n_slots), self.n_slots - 1, n - 1)

    def _kicks(self, a: float) -> bool:
        """Whether aim value ``a`` picks the kick slot (the last of several)."""
        return self.n_slots > 1 and int(abs(a) * self.n_slots) >= self.n_slots - 1

    def _pot(self, cands: Any, a: float) -> Any:
        """The pot slot aim value ``a`` plays (the easiest when it picks the kick slot and there is no kick)."""
        return cands.at(0 if self._kicks(a) else self._slot(a, cands.count))

    def chosen_pot(self, state: "TableState", action: Any) -> Any:
        """The pot slot (:class:`~billiards_env.envs.candidates.Slot`: its ball and pocket) ``action`` plays on the
        table now; None for the break, the kick or when there is no candidate."""
        a = self.parse(action)
        cands = self.slots(state)
        if cands.break_shot or (cands.kick is not None and self._kicks(a[0])) or cands.count == 0:
            return None
        return self._pot(cands, a[0])

    def _speed(self, base: float, a: float) -> float:
        """``base`` times the speed factor to the power ``a``, within the range (compiled twin:
        :func:`._action_kernels.candidate_speed`)."""
        lo, hi = self.speed_range
        return min(max(base * math.exp(a * self.log_factor), lo), hi)

    def _power(self, speed: float, base: float) -> float:
        return math.log(max(float(speed), 1e-9) / max(base, 1e-9)) / self.log_factor

    def _placed_shot(self, state: "TableState", slot: Any, place: tuple[float, float]) -> tuple[float, float]:
        """Aim and base speed of ``slot`` from the cue ball placed at ``place``: the ghost-ball shot at its pocket
        (cut up to 89 degrees; :func:`billiards_env.players.geometry.ghost_shots`), else a hit at its ghost ball at
        :data:`FALLBACK_SPEED`."""
        b = state.balls
        with state.cue_moved_to(place):
            rows = ghost_shots(b.pos, b.on_table, b.radius, b.mass, 0, np.array([slot.target], dtype=np.int64),
                               *state_model(state), float(self.speed_range[0]), float(self.speed_range[1]),
                               PLACED_MAX_CUT, ARRIVE_SPEED, _SPEED_FACTORS, True)
            ghost = slot.ghost(float(b.radius[0] + b.radius[slot.target]), b.pos)
            angle = aim_angle(b.pos[0], ghost)
        for r in rows.tolist():
            if int(r[COL_POCKET]) == slot.pocket:
                return r[COL_ANGLE], r[COL_SPEED]
        return angle, FALLBACK_SPEED

    def _place_for(self, state: "TableState", slot: Any, px: float, py: float) -> tuple[float, float]:
        b = state.balls
        ghost = slot.ghost(float(b.radius[0] + b.radius[slot.target]), b.pos)
        back = PLACE_BACK[0] + 0.5 * (px + 1.0) * (PLACE_BACK[1] - PLACE_BACK[0])
        x, y = ghost - back * direction_vector(slot.obj_angle + py * PLACE_MAX_CUT)
        x0, x1, y0, y1 = state.view.place_area
        return state.legal_cue_position(min(max(x, x0), x1), min(max(y, y0), y1))

    def _direct(self, state: "TableState", targets: Any) -> float:
        return direct_hit(state.balls, 0, list(targets))[0]

    def shot(self, state: "TableState", action: Any) -> CueShot:
        """The chosen candidate's shot (see the class). Compiled twin: :func:`._action_kernels.candidates_shot`."""
        base = super().shot(state, action)  # side, top, declarations and the plain placement
        a = self.parse(action)
        cands = self.slots(state)
        if cands.break_shot:
            place = base.place
            area = state.view.place_area if self.placement else None
            if area is not None:
                x0, x1, y0, y1 = area
                k = self._place_at
                place = state.legal_cue_position(x1 - abs(a[k]) * (x1 - x0), y0 + 0.5 * (a[k + 1] + 1.0) * (y1 - y0))
            with state.cue_moved_to(place):
                angle = self._direct(state, cands.targets)
            speed = self.speed_range[1] * math.exp(min(a[1], 0.0) * self.log_factor)
            return base._replace(angle=angle, speed=max(speed, self.speed_range[0]), place=place)
        if cands.kick is not None and self._kicks(a[0]):  # as verified: its speed, no tip offsets
            return base._replace(angle=cands.kick.shot.angle, speed=cands.kick.shot.speed, side=0.0, top=0.0)
        n = cands.count
        if n == 0:
            with state.cue_moved_to(base.place):
                angle = self._direct(state, cands.targets)
            return base._replace(angle=angle, speed=self._speed(FALLBACK_SPEED, a[1]))
        slot = self._pot(cands, a[0])
        base = base.with_calls(pocket=slot.pocket, ball=slot.target)  # the call is the chosen shot's
        if cands.in_hand:
            k = self._place_at
            place = self._place_for(state, slot, a[k], a[k + 1])
            angle, speed = self._placed_shot(state, slot, place)
            return base._replace(angle=angle, speed=self._speed(speed, a[1]), place=place)
        return base._replace(angle=slot.shot.angle, speed=self._speed(slot.shot.speed, a[1]))

    def action(self, state: "TableState", angle: float, speed: float, side: float = 0.0, top: float = 0.0,
               place: tuple[float, float] | None = None, **calls: Any) -> np.ndarray:
        out = np.asarray(super().action(state, angle, speed, side, top, place, **calls), dtype=np.float64)
        cands = self.slots(state)
        out[0] = 0.0
        if cands.break_shot:
            area = state.view.place_area if (self.placement and place is not None) else None
            if area is not None:
                x0, x1, y0, y1 = area
                k = self._place_at
                out[k] = (x1 - float(place[0])) / max(x1 - x0, 1e-12)
                out[k + 1] = 2.0 * (float(place[1]) - y0) / max(y1 - y0, 1e-12) - 1.0
            out[1] = min(self._power(speed, self.speed_range[1]), 0.0)
            return np.clip(out, -1.0, 1.0).astype(np.float32)
        if not cands.slots and cands.kick is None:
            out[1] = self._power(speed, FALLBACK_SPEED)
            return np.clip(out, -1.0, 1.0).astype(np.float32)
        b = state.balls
        k_best, best = 0, math.inf
        if cands.in_hand and place is not None:
            where = state.legal_cue_position(float(place[0]), float(place[1]))
            for k, slot in enumerate(cands.slots):
                g = slot.ghost(float(b.radius[0] + b.radius[slot.target]), b.pos)
                err = abs(wrap_angle(float(angle) - aim_angle(where, g)))
                if err < best:
                    k_best, best = k, err
            slot = cands.slots[k_best]
            g = slot.ghost(float(b.radius[0] + b.radius[slot.target]), b.pos)
            back = float(np.hypot(g[0] - where[0], g[1] - where[1]))
            phi = wrap_angle(aim_angle(where, g) - slot.obj_angle)
            k = self._place_at
            out[k] = 2.0 * (back - PLACE_BACK[0]) / (PLACE_BACK[1] - PLACE_BACK[0]) - 1.0
            out[k + 1] = phi / PLACE_MAX_CUT
            base_speed = self._placed_shot(state, slot, self._place_for(state, slot, _clip(out[k]), _clip(out[k + 1])))[1]
        else:
            options = list(cands.slots) + ([cands.kick] if cands.kick is not None else [])
            for k, slot in enumerate(options):
                err = abs(wrap_angle(float(angle) - slot.shot.angle)) if slot.shot is not None else math.inf
                if err < best:
                    k_best, best = k, err
            slot = options[k_best]
            base_speed = slot.shot.speed if slot.shot is not None else FALLBACK_SPEED
            if slot is cands.kick:
                k_best = self.n_slots - 1
        out[0] = (k_best + 0.5) / self.n_slots
        out[1] = self._power(speed, base_speed)
        return np.clip(out, -1.0, 1.0).astype(np.float32)


class CandidateAim(CandidateShots):
    """The ``candidates`` action type with one more dim, ``offset`` (the last): where in the chosen pot's entry
    window the object ball is sent, one of :data:`OFFSETS` (:func:`offset_of`: equal bins of the action value,
    the middle bin 0) times ``OFFSET_SPAN`` of the window's half-width off its middle (0: the middle, as
    ``candidates``): exactly the offsets the ``candidates_path`` observation describes. It moves the cut, and with it the line the cue ball leaves on after contact: a
    second way, beside the speed, to keep the cue ball out of the pockets. Read only for a pot with the cue ball
    where it lies (not the kick, the break or ball in hand); an offset whose direction misses the pocket or asks
    for a cut beyond :data:`MAX_OFFSET_CUT` plays the middle. ``power`` scales the slot's own speed as in
    ``candidates``."""

    name = "candidates_aim"

    def __init__(self, config: "EnvConfig", placement: bool = False, declarations: tuple[Declaration, ...] = (),
                 n_pockets: int = 6) -> None:
        super().__init__(config, placement, declarations, n_pockets)
        self._offset_at = self.n
        self.n += 1
        self.space = spaces.Box(-1.0, 1.0, shape=(self.n,), dtype=np.float32)

    def layout(self) -> str:
        return super().layout() + ", offset"

    def shot(self, state: "TableState", action: Any) -> Any:
        played = super().shot(state, action)
        a = self.parse(action)
        cands = self.slots(state)
        if cands.break_shot or cands.in_hand or not cands.slots or (cands.kick is not None and self._kicks(a[0])):
            return played
        slot = cands.slots[0 if self._kicks(a[0]) else self._slot(a[0], len(cands.slots))]
        g = offset_ghost(state, slot, offset_of(a[self._offset_at]))
        if g is None:
            return played
        angle = math.atan2(g[1] - float(state.balls.pos[0, 1]), g[0] - float(state.balls.pos[0, 0]))
        return played._replace(angle=angle)

    def action(self, state: "TableState", angle: float, speed: float, side: float = 0.0, top: float = 0.0,
               place: tuple[float, float] | None = None, **calls: Any) -> np.ndarray:
        """The nearest action (as ``candidates``: the slot whose aim is closest, its speed factor), with the
        ``offset`` that sends the slot's ball where the cue direction ``angle`` sends it (the line of centres at
        contact), when it is a pot from where the cue ball lies."""
        out = super().action(state, angle, speed, side, top, place, **calls)
        cands = self.slots(state)
        if cands.break_shot or cands.in_hand or not cands.slots:
            return out
        k = min(int(abs(float(out[0])) * self.n_slots), self.n_slots - 1)
        if k >= len(cands.slots):
            return out
        s = cands.slots[k]
        b = state.balls
        cx, cy = float(b.pos[0, 0]), float(b.pos[0, 1])
        ox, oy = float(b.pos[s.target, 0]), float(b.pos[s.target, 1])
        d = ray_circle_entry(cx, cy, math.cos(angle), math.sin(angle), ox, oy, float(b.radius[0] + b.radius[s.target]))
        if not math.isfinite(d) or s.half <= 0.0:
            return out
        direction = math.atan2(oy - (cy + math.sin(angle) * d), ox - (cx + math.cos(angle) * d))
        off = wrap_angle(direction - s.obj_angle) / (OFFSET_SPAN * s.half)
        m = int(np.argmin(np.abs(np.asarray(OFFSETS) - off)))  # the nearest offset, as the middle of its bin
        out[self._offset_at] = np.float32(2.0 * (m + 0.5) / len(OFFSETS) - 1.0)
        return out


ACTION_TYPES = {"absolute": AbsoluteAim, "relative": RelativeAim, "ghost": GhostAim, "candidates": CandidateShots,
                "candidates_aim": CandidateAim}


def action_factory(config: "EnvConfig", placement: bool = False, declarations: tuple[Declaration, ...] = (),
                   n_pockets: int = 6) -> ActionType:
    """The action type named by ``config.action_type`` (with spin dims per ``config.spin_action``, placement dims
    when the task has ball in hand, and the task's declarations)."""
    return ACTION_TYPES[config.action_type](config, placement, declarations, n_pockets)


__all__ = ["CueShot", "ActionType", "AbsoluteAim", "RelativeAim", "GhostAim", "CandidateShots", "CandidateAim", "ACTION_TYPES",
           "action_factory", "PLACE_BACK", "PLACE_MAX_CUT", "PLACED_MAX_CUT", "FALLBACK_SPEED",
           "square_to_disc", "disc_to_square", "aim_to_angle", "angle_to_aim", "power_to_speed", "noisy_shot", "AIM_ABSOLUTE",
           "AIM_RELATIVE", "AIM_GHOST"]
