"""Where the cue ball goes after contact, for each candidate shot: the ``candidates_path`` observation.

47 of the one-ball SAC agent's 59 failures were scratches after potting: the cue ball, deflected along the tangent
line, runs on into a pocket. Its observation (``features``) shows the pockets as seen from the object ball, nothing
of the cue ball's path; the ``candidates`` observation flags a scratch risk at the shot's own speed only. What the
choice needs is, per candidate shot, the range of speeds that pot the ball *and* leave the cue ball on the table.
This module computes it in closed form from the engine's own formulas (no simulation):

- the collision (:func:`billiards_env.physics.aim.collide_into`, the solvers' law): per unit impact speed, the
  object ball's speed and the cue ball's velocity after contact;
- the cue ball's path from the ghost-ball point: straight lines reflected off the cushions with the table's
  restitution (the normal component scaled, the tangential kept: under the ``rolling`` and ``drag`` laws the path's
  shape does not depend on the speed), up to :data:`MAX_BOUNCES` cushions, to the first pocket whose capture circle
  it enters (:func:`~billiards_env.physics.aim.ray_circle_entry`, :func:`~billiards_env.physics.aim.ray_cushion_hit`);
- the motion law (:func:`~billiards_env.physics.motion.launch_speed`): the least launch speed at which the object
  ball reaches its pocket's capture circle, and the least at which the cue ball reaches that pocket (backwards
  along the path: each cushion divides the speed by its factor).

Both thresholds are given in the units of the ``candidates`` action's ``power`` dim (``a[1]``: the shot's own speed
times ``candidate_speed_factor ** a[1]``), so "which ``a[1]`` pots without a scratch" is an interval the
observation states: ``[pot_at, scratch_at)``. The speed is not the only lever: where the object ball enters its
pocket's window moves the cut, and with it the cue ball's line, so the thresholds are given at five offsets across
the window (:data:`OFFSETS`), and the action type :class:`CandidateAim` (``candidates`` plus an ``offset`` dim)
plays exactly those offsets. A second collision (the cue ball coming back into the object ball) is not modelled.
Under the ``spin`` law the cue ball slides and curves after contact; the straight path is then an approximation
(stun shots, the players' own assumption).

Where it goes in the package (today both are installed on an env by the wrapper :class:`CandidateAimTypes`,
``env_wrapper: agents.cue_path.CandidateAimTypes`` in a training config, on an env made with
``action_type="candidates", observation_type="candidates"``): :class:`CuePathFeatures` is an observation type (a
subclass of the env's ``candidates`` type: its values, then :data:`PATH_FEATURES` per slot), for
``billiards_env/envs/observations.py`` as ``"candidates_path"``; :class:`CandidateAim` an action type (a subclass of
``CandidateShots``), for ``billiards_env/envs/actions.py`` as ``"candidates_aim"``; the compiled path functions for
``billiards_env/physics/aim.py`` beside ``lone_path_pocket``. ``python -m agents.cue_path`` plays a hand-written
rule on the observation (:func:`interval_action`): what the observation alone allows.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import gymnasium as gym
import numpy as np
from numba import njit

from billiards_env.envs.candidates import candidate_slots
from billiards_env.envs.actions import CandidateShots
from billiards_env.envs.observations import CandidateFeatures
from billiards_env.physics.aim import collide_into, ray_circle_entry, ray_cushion_hit, wrap_angle
from billiards_env.physics.motion import launch_speed, speed_after_distance, stop_distance

if TYPE_CHECKING:  # pragma: no cover
    from billiards_env.envs.config import EnvConfig
    from billiards_env.physics.table import Table
    from billiards_env.table_state import TableState

#: Cushion bounces followed along the cue ball's path (it stops long before them at the speeds the envs allow).
MAX_BOUNCES = 40
#: Values per slot appended by :class:`CuePathFeatures`: two per offset of :data:`OFFSETS`, then ``top``.
PATH_FEATURES = 11
#: A threshold beyond every speed (no pocket on the path, or out of reach): reads as +1.
NEVER = math.inf


@njit(cache=True)
def path_pocket_speed(x: float, y: float, ux: float, uy: float, s_max: float, radius: float, length: float,
                      width: float, e_cushion: float, pocket_xy: np.ndarray, pocket_r: np.ndarray, law: int, a: float,
                      k: float, v_min: float, max_bounces: int) -> tuple:
    """The first pocket a lone ball leaving ``(x, y)`` along the unit direction ``(ux, uy)`` at speed ``s_max``
    would enter (straight lines reflected off the cushions: the normal component scaled by ``e_cushion``; up to
    ``max_bounces`` cushions), the least speed it needs at ``(x, y)`` to reach that pocket's capture circle, and the
    cushions it meets first: ``(pocket, speed, bounces)``; ``(-1, inf, -1)`` when it stops first. The path's shape
    does not depend on the speed, so at any speed below the one returned the ball stops on the table."""
    lengths = np.empty(max_bounces + 1)
    factors = np.empty(max_bounces + 1)  # speed after / before each bounce
    s = s_max
    for n in range(max_bounces + 1):
        if s <= v_min or s < 1e-9:
            return -1, math.inf, -1
        reach = stop_distance(s, law, a, k, v_min)
        t_wall = ray_cushion_hit(x, y, ux, uy, length, width, radius)[0]
        best = math.inf
        pocket = -1
        for p in range(pocket_r.shape[0]):
            t = ray_circle_entry(x, y, ux, uy, pocket_xy[p, 0], pocket_xy[p, 1], pocket_r[p])
            if t <= t_wall + 1e-9 and t < best:
                best = t
                pocket = p
        if pocket >= 0 and best < reach:
            # backwards: the speed to arrive (just moving), then each segment and bounce before it
            need = launch_speed(best, v_min * 1.05 + 1e-6, law, a, k)
            for m in range(n - 1, -1, -1):
                need = launch_speed(lengths[m], need / factors[m], law, a, k)
            return pocket, need, n
        if reach <= t_wall:
            return -1, math.inf, -1
        s = speed_after_distance(s, t_wall, law, a, k)
        x = x + ux * t_wall
        y = y + uy * t_wall
        vx = ux
        vy = uy
        if x <= radius + 1e-9 or x >= length - radius - 1e-9:
            vx = -e_cushion * vx
        if y <= radius + 1e-9 or y >= width - radius - 1e-9:
            vy = -e_cushion * vy
        f = math.hypot(vx, vy)
        if f < 1e-9:
            return -1, math.inf, -1
        lengths[n] = t_wall
        factors[n] = f
        s *= f
        ux = vx / f
        uy = vy / f
    return -1, math.inf, -1


@njit(cache=True)
def shot_thresholds(cx: float, cy: float, gx: float, gy: float, obj_angle: float, d_obj: float, v_top: float,
                    rc: float, mc: float, mo: float, length: float, width: float, e_cushion: float, e_ball: float,
                    pocket_xy: np.ndarray, pocket_r: np.ndarray, law: int, a: float, k: float, v_min: float,
                    max_bounces: int) -> tuple:
    """For the ghost-ball shot from the cue ball at ``(cx, cy)`` through the ghost point ``(gx, gy)``, sending the
    object ball along ``obj_angle`` for ``d_obj`` to its capture circle: ``(pot, scratch, pocket, bounces)``: the
    least cue launch speed that gets the object ball there, the least at which the cue ball, deflected, reaches a
    pocket (inf: launched at ``v_top``, the top of the speed range, it stops first), that pocket and the cushions
    before it."""
    dx = gx - cx
    dy = gy - cy
    d_cue = math.hypot(dx, dy)
    if d_cue < 1e-12:
        return math.inf, 0.0, -1, 0
    ux = math.cos(obj_angle)
    uy = math.sin(obj_angle)
    vel = np.empty((2, 2))
    collide_into(vel, dx / d_cue, dy / d_cue, 0.0, 0.0, -ux, -uy, mc, mo, e_ball)  # per unit impact speed
    v_obj = math.hypot(vel[1, 0], vel[1, 1])
    v_cue = math.hypot(vel[0, 0], vel[0, 1])
    pot = math.inf
    if v_obj > 1e-9:
        pot = launch_speed(d_cue, launch_speed(d_obj, v_min * 1.05 + 1e-6, law, a, k) / v_obj, law, a, k)
    if v_cue < 1e-9:
        return pot, math.inf, -1, -1
    s_max = v_cue * speed_after_distance(v_top, d_cue, law, a, k)
    pocket, s, bounces = path_pocket_speed(gx, gy, vel[0, 0] / v_cue, vel[0, 1] / v_cue, s_max, rc, length, width,
                                           e_cushion, pocket_xy, pocket_r, law, a, k, v_min, max_bounces)
    if pocket < 0:
        return pot, math.inf, -1, -1
    return pot, launch_speed(d_cue, s / v_cue, law, a, k), pocket, bounces


@njit(cache=True)
def rows_thresholds(cx: float, cy: float, rows: np.ndarray, v_top: float, rc: float, mc: float, mo: float,
                    length: float, width: float, e_cushion: float, e_ball: float, pocket_xy: np.ndarray,
                    pocket_r: np.ndarray, law: int, a: float, k: float, v_min: float, max_bounces: int) -> np.ndarray:
    """:func:`shot_thresholds` of many shots from the cue ball at ``(cx, cy)``: ``rows`` ``(N, 4)`` of ghost point
    ``x, y``, object-ball direction and distance to its capture circle (a NaN row: no shot); ``(N, 2)`` of ``pot``
    and ``scratch`` launch speeds (inf: never)."""
    out = np.full((rows.shape[0], 2), np.inf)
    for i in range(rows.shape[0]):
        if not math.isfinite(rows[i, 3]):
            continue
        r = shot_thresholds(cx, cy, rows[i, 0], rows[i, 1], rows[i, 2], rows[i, 3], v_top, rc, mc, mo, length,
                            width, e_cushion, e_ball, pocket_xy, pocket_r, law, a, k, v_min, max_bounces)
        out[i, 0] = r[0]
        out[i, 1] = r[1]
    return out


#: The ``offset`` dim of :class:`CandidateAim`: ``a = +-1`` sends the object ball this fraction of its pocket
#: window's half-width off the window's middle (the edges are left: the window is sampled).
OFFSET_SPAN = 0.8
#: The offsets at which :class:`CuePathFeatures` states the thresholds.
OFFSETS = (-1.0, -0.5, 0.0, 0.5, 1.0)
#: The largest cut an offset may ask for (beyond it the shot is not played: the window's middle is).
MAX_OFFSET_CUT = math.radians(88.0)


def offset_ghost(state: "TableState", slot: Any, offset: float) -> tuple[float, float, float, float] | None:
    """The shot of pot ``slot`` (cue ball where it lies) sending the object ball ``offset * OFFSET_SPAN`` of its
    window's half-width off the window's middle: ``(ghost x, ghost y, object direction, distance to the capture
    circle)``; None when that direction misses the pocket, asks for a cut beyond :data:`MAX_OFFSET_CUT` or puts the
    ghost ball off the table."""
    b = state.balls
    t = state.table
    j = slot.target
    contact = float(b.radius[0] + b.radius[j])
    direction = slot.obj_angle + offset * OFFSET_SPAN * slot.half
    ux, uy = math.cos(direction), math.sin(direction)
    ox, oy = float(b.pos[j, 0]), float(b.pos[j, 1])
    d_obj = ray_circle_entry(ox, oy, ux, uy, float(t.pocket_xy[slot.pocket, 0]), float(t.pocket_xy[slot.pocket, 1]),
                             float(t.pocket_radius[slot.pocket]))
    if not math.isfinite(d_obj):
        return None
    gx, gy = ox - contact * ux, oy - contact * uy
    rc = float(b.radius[0])
    if not (rc <= gx <= t.length - rc and rc <= gy <= t.width - rc):
        return None
    cx, cy = float(b.pos[0, 0]), float(b.pos[0, 1])
    d = math.hypot(gx - cx, gy - cy)
    if d < 1e-9 or ((gx - cx) * ux + (gy - cy) * uy) / d < math.cos(MAX_OFFSET_CUT):
        return None
    return gx, gy, direction, d_obj


def offset_rows(state: "TableState", slots: Any, offsets: Any = OFFSETS) -> np.ndarray:
    """``(len(slots.slots) * len(offsets), 4)``: :func:`offset_ghost` of every pot slot (cue ball where it lies) at
    every offset, NaN rows where there is none."""
    rows = np.full((len(slots.slots) * len(offsets), 4), np.nan)
    for i, s in enumerate(slots.slots):
        if s.shot is None:
            continue
        for m, off in enumerate(offsets):
            g = offset_ghost(state, s, float(off))
            if g is not None:
                rows[i * len(offsets) + m] = g
    return rows


def thresholds(state: "TableState", rows: np.ndarray, v_top: float) -> np.ndarray:
    """:func:`rows_thresholds` of ``rows`` on the table state now (the cue ball row 0, the object ball of each row:
    the masses are all the cue ball's and ball 1's; the one-ball and pool tables have equal masses)."""
    b = state.balls
    t = state.table
    ph = state.physics
    law, acc, kk = ph.path_args
    mo = float(b.mass[1]) if len(b.mass) > 1 else float(b.mass[0])
    return rows_thresholds(float(b.pos[0, 0]), float(b.pos[0, 1]), np.ascontiguousarray(rows, dtype=np.float64),
                           float(v_top), float(b.radius[0]), float(b.mass[0]), mo, float(t.length), float(t.width),
                           float(t.cushion_restitution), float(ph.ball_restitution),
                           np.ascontiguousarray(t.pocket_xy, dtype=np.float64),
                           np.ascontiguousarray(t.pocket_radius, dtype=np.float64), int(law), float(acc), float(kk),
                           float(ph.min_speed), MAX_BOUNCES)


def power_of(speed: Any, base: Any, log_factor: float) -> np.ndarray:
    """The ``candidates`` action's ``power`` value that plays ``speed`` on a shot of own speed ``base`` (+inf for
    an infinite speed)."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        return np.log(np.maximum(speed, 1e-12) / np.maximum(base, 1e-12)) / log_factor


def offset_of(a: float) -> float:
    """The offset of :data:`OFFSETS` an ``offset`` action value picks (equal bins over ``[-1, 1]``)."""
    k = min(int(0.5 * (min(max(a, -1.0), 1.0) + 1.0) * len(OFFSETS)), len(OFFSETS) - 1)
    return OFFSETS[k]


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

    def __init__(self, config: "EnvConfig", placement: bool = False, declarations: tuple[str, ...] = (),
                 n_pockets: int = 6) -> None:
        super().__init__(config, placement, declarations, n_pockets)
        self._offset_at = self.n
        self.n += 1
        self.space = gym.spaces.Box(-1.0, 1.0, shape=(self.n,), dtype=np.float32)

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
               place: tuple[float, float] | None = None, pocket: int | None = None,
               push: bool = False) -> np.ndarray:
        """The nearest action (as ``candidates``: the slot whose aim is closest, its speed factor), with the
        ``offset`` that sends the slot's ball where the cue direction ``angle`` sends it (the line of centres at
        contact), when it is a pot from where the cue ball lies."""
        out = super().action(state, angle, speed, side, top, place, pocket, push)
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


class CuePathFeatures(CandidateFeatures):
    """The ``candidates`` observation, then per slot :data:`PATH_FEATURES` values (see the module docstring), in
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
        self.space = gym.spaces.Box(low, np.ones_like(low), dtype=np.float32)

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


class CandidateAimTypes(gym.Wrapper):
    """Puts :class:`CandidateAim` and :class:`CuePathFeatures` on a billiards env, as ``gym.make(id,
    action_type="candidates_aim", observation_type="candidates_path")`` will once they are registered in the env's
    type lists: the env's own ``action_type`` and ``observation_type`` are replaced, so ``step``, ``reset`` and
    ``action_from_shot`` use them. The env's config sets ``candidate_slots``, ``candidate_speed_factor`` and the
    speed range."""

    def __init__(self, env: gym.Env) -> None:
        super().__init__(env)
        u = env.unwrapped
        if u.config.action_type != "candidates":
            raise ValueError(f"CandidateAimTypes: make the env with action_type='candidates' (and its "
                             f"candidate_slots, candidate_speed_factor), got {u.config.action_type!r}")
        at = u.action_type
        u.action_type = CandidateAim(u.config, at.placement, at.declarations, at.n_pockets)
        u.observation_type = CuePathFeatures(u.config, u.table, u.n_balls, u.task.n_features)
        u.action_space = self.action_space = u.action_type.space
        u.observation_space = self.observation_space = u.observation_type.space


def interval_action(obs: np.ndarray, n_slots: int, n_balls: int = 2) -> np.ndarray:
    """A hand-written rule on the ``candidates_path`` observation (no learning; what the observation alone allows):
    the (slot, offset) whose interval ``[pot_at, min(scratch_at, top))`` is widest, at the interval's middle;
    the widest first among those at least half an action unit wide, the easiest slot first."""
    base = 3 * n_balls
    has = obs[base:base + 12 * n_slots].reshape(n_slots, 12)[:, 0]
    path = obs[base + 12 * n_slots:base + (12 + PATH_FEATURES) * n_slots].reshape(n_slots, PATH_FEATURES)
    k = len(OFFSETS)
    best, act = -np.inf, np.array([0.5 / n_slots, 0.0, 0.0], np.float32)
    for i in range(n_slots - 1):
        if not has[i]:
            continue
        for m in range(k):
            lo, hi = path[i, 2 * m], min(path[i, 2 * m + 1], path[i, 2 * k], 1.0)
            if hi - lo > best and best < 0.5:  # keep the first (easiest) wide enough interval
                best = hi - lo
                act = np.array([(i + 0.5) / n_slots, 0.5 * (lo + hi), 2.0 * (m + 0.5) / k - 1.0], np.float32)
    return act


def main(argv: Any = None) -> int:
    """``python -m agents.cue_path``: the pocket rate of :func:`interval_action` on the one-ball tables."""
    import argparse

    import billiards_env  # noqa: F401

    p = argparse.ArgumentParser(prog="python -m agents.cue_path", description=main.__doc__)
    p.add_argument("--episodes", type=int, default=1000)
    p.add_argument("--seed", type=int, default=100_000)
    p.add_argument("--slots", type=int, default=7)
    args = p.parse_args(argv)
    env = CandidateAimTypes(gym.make("BilliardsOneBall-v0", action_type="candidates", observation_type="candidates",
                                     candidate_slots=args.slots, candidate_speed_factor=3.0))
    ok = 0
    for k in range(args.episodes):
        obs, _ = env.reset(seed=args.seed + k)
        _, _, _, _, info = env.step(interval_action(obs, args.slots))
        ok += bool(info["is_success"])
    print(f"interval rule on the candidates_path observation: {ok}/{args.episodes} = {100 * ok / args.episodes:.1f}% "
          f"(tables {args.seed}..{args.seed + args.episodes - 1})")
    return 0


__all__ = ["CuePathFeatures", "CandidateAim", "CandidateAimTypes", "interval_action", "path_pocket_speed",
           "shot_thresholds", "rows_thresholds", "offset_ghost", "offset_of", "offset_rows", "thresholds", "power_of", "MAX_BOUNCES",
           "PATH_FEATURES", "OFFSETS", "OFFSET_SPAN"]


if __name__ == "__main__":
    import sys

    sys.exit(main())
