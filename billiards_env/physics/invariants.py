"""The invariants every simulated shot must satisfy, checked on a shot recorded with ``record=True``.

Shared by the fuzz command (``python -m billiards_env.fuzz``) and the stability tests (``tests/stability``):
:func:`check_shot` checks a ``ShotResult`` of a ``Scene``; :func:`run_case` builds a scene dict (the scene-file
format of :mod:`billiards_env.physics.scene`), runs it and checks it, turning a crash into an ``exception``
violation. The checks read the result; they change nothing.

Invariants (tolerances are the module constants below):

- ``finite``: no NaN or infinity in the final state, the event log or the state log.
- ``bounds``: every ball on the table has its centre in ``[r, L-r] x [r, W-r]`` (up to ``BOUNDS_TOL``), in the
  final state and in every logged state.
  On a jaw table: within the cushion lines ``[0, L] x [0, W]`` or in a pocket's mouth or circle
  (:func:`.pocket_specs.in_mouth_region`); clear of the walls is the ``walls`` check.
- ``walls`` (jaw table): no ball on the table overlaps a rail, jaw face or tip (:func:`.pocket_specs.wall_overlaps`)
  by more than ``WALL_TOL`` (exact: final state and every logged state) or the step solver's overlap tolerance
  (final state).
- ``overlap``: no two balls on the table closer than the sum of their radii minus the solver's tolerance
  (``EXACT_OVERLAP_TOL``; step: :func:`step_overlap_tolerance` of the fastest initial ball, its speed under the
  spin model counted as ``|v| + R |w|``: spin turns into speed) in the final state. ``overlap_during`` (exact):
  the same at every event time and half-way between consecutive event times (a missed collision shows here).
- ``energy`` (exact, per event from the state log): the kinetic energy of the two balls of a collision, or of the
  ball of a cushion hit, does not rise by more than ``ENERGY_REL_TOL`` relative. ``energy`` (step): the total
  kinetic energy over the solver's snapshots never rises. Under the spin model the kinetic energy includes the
  rotation (``I = 2/5 m R^2``) and every event is checked (motion transitions too: relative to the larger of the
  energy just before and at the start of the piece that ends, whose closed form the end state is computed from).
- ``momentum`` (exact, per collision): the pair's momentum is unchanged up to ``MOMENTUM_REL_TOL`` relative (plus
  ``m * min_speed`` for a ball stopped by the minimum-speed rule right after the hit).
- ``contact`` (exact): two balls collide at contact distance (``|d - (r_i + r_j)| <= CONTACT_TOL``); a cushion hit
  happens with the ball on the wall; a pocketed ball's centre is within the capture radius.
- ``continuity`` (exact): the position logged after an event is where the closed-form motion from the ball's
  previous logged state puts it (up to ``CONTINUITY_TOL``): no jumps.
- ``pocket``: a pocketed ball stays pocketed (its on-table flag never comes back), takes part in no later event,
  and the result's pocket list agrees with the final on-table flags.
- ``spin_state`` (spin model, exact): a transition leaves the state its kind names (``roll``: rolling, ``spin``:
  spinning, ``stop``: stationary), and a logged rolling state does not slip.
- ``status``: the shot ended with ``rest`` (then every ball on the table has zero velocity, and under the spin
  model zero angular velocity), ``time_cap`` (at
  ``max_time``) or ``event_cap`` (exact, at ``max_events``); event times are ascending and within the cap.
- ``zeno`` (exact): more than ``ZENO_BURST`` events at one instant (consecutive events less than ``ZENO_SPAN``
  apart), or an event cap reached while the last half of the events spans less than ``ZENO_SPAN``: endless
  micro-collisions instead of progress in time.
- ``exception``: the solver raised.
"""
from __future__ import annotations

import math
import traceback
from collections import Counter
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .codes import (EV_COLLISION, EV_CUSHION, EV_JAM, EV_POCKET, EV_ROLL, EV_SPIN, EV_STOP, MS_ROLLING, MS_SPINNING,
                    MS_STATIONARY, SPIN, STATUS_NAMES)
from .model import G
from .pocket_specs import in_mouth_region, wall_gaps, wall_overlaps
from .motion import advance_many
from .scene import Scene
from .spin_motion import carry_rows

# --------------------------------------------------------------------------------------------- tolerances
BOUNDS_TOL = 1e-9  #: a centre may sit this far outside [r, L - r] (m)
EXACT_OVERLAP_TOL = 1e-9  #: exact solver: largest overlap of two balls on the table (m)
#: Step solver (both contact modes): the push-apart / rewind is one pass over the pairs in (i, j) order, and a later
#: push or the cushion clamp that follows can re-open an overlap already resolved; balls that come to rest keep it.
#: The residual overlap is bounded by the penetration a step allows, ``STEP_OVERLAP_FACTOR * v_max * dt``
#: (``v_max`` the cue speed), plus ``STEP_OVERLAP_ABS``. Measured by the fuzz (see the report / module docstring of
#: tests/stability/test_properties.py).
STEP_OVERLAP_FACTOR = 2.0
STEP_OVERLAP_ABS = 1e-9
ENERGY_REL_TOL = 1e-12  #: relative kinetic-energy rise allowed at one event (rounding)
MOMENTUM_REL_TOL = 1e-12  #: relative momentum change allowed at one ball-ball collision (rounding)
CONTACT_TOL = 1e-9  #: a collision happens at contact distance up to this (m)
WALL_TOL = 1e-9  #: exact solver, jaw table: largest overlap of a ball and a rail, jaw face or tip (m)
CONTINUITY_TOL = 1e-9  #: largest jump of a ball's position at an event (m)
ZENO_SPAN = 1e-9  #: events closer than this (s) form one burst (one instant, up to rounding)
#: A burst of more events than this at one instant is an inelastic-collapse storm (a 16-ball break needs a few
#: hundred at most); an event cap reached inside a burst is a Zeno hang.
ZENO_BURST = 5000

#: spin model: a logged rolling state may slip by this much relative to ``|v| + R |(wx, wy)|`` (round-off)
ROLLING_SLIP_TOL = 1e-12

INVARIANTS = ("exception", "finite", "bounds", "walls", "overlap", "overlap_during", "energy", "momentum", "contact",
              "continuity", "pocket", "status", "zeno", "spin_state")


def step_overlap_tolerance(speed: float, dt: float) -> float:
    """Largest final overlap (m) allowed of the step solver for a shot of cue speed ``speed`` and time step ``dt``."""
    return STEP_OVERLAP_FACTOR * max(speed, 0.0) * dt + STEP_OVERLAP_ABS



# --------------------------------------------------------------------------------------------- checks
@dataclass
class Report:
    """The outcome of checking one shot: violations (invariant -> first message) and measurements."""

    solver: str = ""
    status: str = ""
    n_events: int = 0
    n_collisions: int = 0
    sim_time: float = 0.0
    violations: dict[str, str] = field(default_factory=dict)
    counts: Counter = field(default_factory=Counter)
    max_overlap: float = 0.0  #: deepest overlap in the final state (m)
    max_wall_overlap: float = 0.0  #: jaw table: deepest overlap of a ball and a wall (final; exact: every logged state)
    max_overlap_during: float = 0.0  #: deepest overlap at/between events (exact) or at snapshots (step) (m)
    max_energy_gain: float = 0.0  #: largest relative energy rise at one event
    max_momentum_err: float = 0.0  #: largest relative momentum change at one collision
    max_contact_err: float = 0.0  #: largest |d - (ri + rj)| at a collision (m)
    max_jump: float = 0.0  #: largest position jump at an event (m)
    max_burst: int = 0  #: most events at one instant
    overlap_tol: float = 0.0

    def fail(self, name: str, msg: str) -> None:
        self.counts[name] += 1
        self.violations.setdefault(name, msg)

    @property
    def ok(self) -> bool:
        return not self.violations


def _pairwise_overlap(pos: np.ndarray, radius: np.ndarray, on: np.ndarray) -> tuple[float, tuple[int, int]]:
    """Deepest overlap ``(ri + rj) - d`` over pairs on the table (``-inf`` with fewer than two) and its pair."""
    idx = np.flatnonzero(on)
    if len(idx) < 2:
        return -math.inf, (-1, -1)
    p = pos[idx]
    d = np.sqrt(((p[:, None, :] - p[None, :, :]) ** 2).sum(-1))
    need = radius[idx][:, None] + radius[idx][None, :]
    ov = need - d
    np.fill_diagonal(ov, -math.inf)
    k = int(np.argmax(ov))
    a, b = divmod(k, len(idx))
    return float(ov[a, b]), (int(idx[a]), int(idx[b]))


def _overlap_series(pos: np.ndarray, radius: np.ndarray, on: np.ndarray) -> tuple[float, int, tuple[int, int]]:
    """Deepest overlap over samples: ``pos (T, N, 2)``, ``on (T, N)``; returns (overlap, sample, pair)."""
    n = pos.shape[1]
    if n < 2 or pos.shape[0] == 0:
        return -math.inf, -1, (-1, -1)
    iu, ju = np.triu_indices(n, 1)
    d = np.hypot(pos[:, iu, 0] - pos[:, ju, 0], pos[:, iu, 1] - pos[:, ju, 1])
    ov = (radius[iu] + radius[ju])[None, :] - d
    ov = np.where(on[:, iu] & on[:, ju], ov, -math.inf)
    k = int(np.argmax(ov))
    s, q = divmod(k, len(iu))
    return float(ov[s, q]), s, (int(iu[q]), int(ju[q]))


def check_shot(scene: Any, result: Any, sample_between: bool = True) -> Report:
    """Check every invariant of the module docstring on ``result`` (a ``ShotResult`` recorded with
    ``record=True``) of ``scene`` (a ``Scene``). Returns a :class:`Report`."""
    rep = Report(solver=result.solver, status=result.status, n_events=int(result.n_events),
                 sim_time=float(result.time))
    table, phys = scene.table, scene.physics
    L, W = table.length, table.width
    b0 = scene.initial_balls()
    radius, mass = b0.radius, b0.mass
    n = len(b0)
    fin = result.balls
    ev = result.events
    tr = result.trajectory
    exact = result.solver == "exact"
    law, a, k, v_min = phys.law_code, phys.deceleration, phys.drag_rate, phys.min_speed
    speed0 = float(np.max(np.hypot(b0.vel[:, 0], b0.vel[:, 1]))) if n else 0.0
    if law == SPIN and n:  # spin turns into speed (a spinning ball at rest sets off): |v| + R |w| bounds it
        speed0 = float(np.max(np.hypot(b0.vel[:, 0], b0.vel[:, 1]) + radius * np.linalg.norm(b0.ang, axis=1)))

    # ---- finite
    arrays = {"final pos": fin.pos, "final vel": fin.vel, "final ang": fin.ang, "event time": ev.time,
              "event speed": ev.speed}
    if tr is not None:
        arrays["state log"] = tr.state
        arrays["state-log time"] = tr.times
    for name, arr in arrays.items():
        if not np.all(np.isfinite(arr)):
            rep.fail("finite", f"{name} holds NaN/inf")
    if not math.isfinite(result.time):
        rep.fail("finite", f"end time {result.time}")

    # ---- status
    if result.status not in STATUS_NAMES:
        rep.fail("status", f"unknown status {result.status!r}")
    on_f = np.asarray(fin.on_table, bool)
    if result.status == "rest":
        mv = on_f & ((fin.vel[:, 0] != 0.0) | (fin.vel[:, 1] != 0.0) | np.any(fin.ang != 0.0, axis=1))
        if mv.any():
            rep.fail("status", f"status rest but balls {np.flatnonzero(mv).tolist()} still moving")
    elif result.status == "time_cap":
        if not result.time >= scene.max_time - (scene.dt if not exact else 0.0) - 1e-9:
            rep.fail("status", f"time_cap at t={result.time} < max_time {scene.max_time}")
    elif result.status == "event_cap":
        if not exact or result.n_events != scene.max_events:
            rep.fail("status", f"event_cap with {result.n_events} events (max_events {scene.max_events})")
    if result.time > scene.max_time + 1e-9:
        rep.fail("status", f"end time {result.time} past max_time {scene.max_time}")
    if len(ev) and (np.any(np.diff(ev.time) < 0) or ev.time[-1] > scene.max_time + 1e-9 or ev.time[0] < 0):
        rep.fail("status", "event times not ascending within [0, max_time]")
    kinds = np.asarray(ev.kind)
    rep.n_collisions = int(np.sum(kinds == EV_COLLISION))

    # ---- zeno: a burst of events at one instant, or an event cap hit while time (almost) stands still
    if len(ev) >= 2:
        brk = np.flatnonzero(np.diff(ev.time) > ZENO_SPAN)
        edges = np.concatenate([[0], brk + 1, [len(ev)]])
        sizes = np.diff(edges)
        q = int(np.argmax(sizes))
        rep.max_burst = int(sizes[q])
        if sizes[q] > ZENO_BURST:
            rep.fail("zeno", f"{int(sizes[q])} events within {float(ev.time[edges[q + 1] - 1] - ev.time[edges[q]]):.3g} s "
                             f"at t={float(ev.time[edges[q]])!r}")
    if result.status == "event_cap" and len(ev) >= 2:
        half = len(ev) // 2
        span = float(ev.time[-1] - ev.time[half])
        if span < ZENO_SPAN:
            rep.fail("zeno", f"event cap: the last {len(ev) - half} events span {span:.3g} s at t={float(ev.time[-1])!r}")

    # ---- bounds (final and every logged state); on a jaw table also walls
    jaws = bool(getattr(table, "has_jaws", False))
    if jaws:
        segs, tips = table.walls()

        def bounds_bad(x, y, r):
            # On the table: within the cushion lines (clear of the walls: the walls check), or in a mouth.
            out = (x < -BOUNDS_TOL) | (x > L + BOUNDS_TOL) | (y < -BOUNDS_TOL) | (y > W + BOUNDS_TOL)
            for q in np.flatnonzero(out):
                if in_mouth_region(segs, tips, table.pocket_xy, table.pocket_radius, float(x[q]), float(y[q])):
                    out[q] = False
            return out
    else:
        def bounds_bad(x, y, r):
            return (x < r - BOUNDS_TOL) | (x > L - r + BOUNDS_TOL) | (y < r - BOUNDS_TOL) | (y > W - r + BOUNDS_TOL)

    bad = on_f & bounds_bad(fin.pos[:, 0], fin.pos[:, 1], radius)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        rep.fail("bounds", f"final: ball {i} at ({float(fin.pos[i, 0])!r}, {float(fin.pos[i, 1])!r}) off the table")
    if tr is not None and len(tr.times):
        st = tr.state
        rb = radius[tr.ball]
        bad = (st[:, 4] > 0.5) & bounds_bad(st[:, 0], st[:, 1], rb)
        if bad.any():
            q = int(np.flatnonzero(bad)[0])
            rep.fail("bounds", f"logged state at t={float(tr.times[q])!r}: ball {int(tr.ball[q])} at "
                               f"({float(st[q, 0])!r}, {float(st[q, 1])!r}) off the table")

    # ---- overlap (final)
    tol = EXACT_OVERLAP_TOL if exact else step_overlap_tolerance(speed0, scene.dt)
    rep.overlap_tol = tol
    if jaws:  # walls: no ball overlaps a rail, jaw face or tip (final state; exact: every logged state)
        wtol = WALL_TOL if exact else tol
        ov_w, wall_w = wall_overlaps(segs, tips, fin.pos[:, 0], fin.pos[:, 1], radius)
        ov_w = np.where(on_f, ov_w, -np.inf)
        q = int(np.argmax(ov_w)) if n else 0
        if n and ov_w[q] > 0.0:
            rep.max_wall_overlap = float(ov_w[q])
        if n and ov_w[q] > wtol:
            rep.fail("walls", f"final: ball {q} at ({float(fin.pos[q, 0])!r}, {float(fin.pos[q, 1])!r}) overlaps wall "
                              f"{int(wall_w[q])} by {float(ov_w[q]):.3g} m (tolerance {wtol:.3g})")
        if exact and tr is not None and len(tr.times):
            st = tr.state
            ov_w, wall_w = wall_overlaps(segs, tips, st[:, 0], st[:, 1], radius[tr.ball])
            ov_w = np.where(st[:, 4] > 0.5, ov_w, -np.inf)
            q = int(np.argmax(ov_w))
            rep.max_wall_overlap = max(rep.max_wall_overlap, float(ov_w[q]), 0.0)
            if ov_w[q] > wtol:
                rep.fail("walls", f"logged state at t={float(tr.times[q])!r}: ball {int(tr.ball[q])} at "
                                  f"({float(st[q, 0])!r}, {float(st[q, 1])!r}) overlaps wall {int(wall_w[q])} by "
                                  f"{float(ov_w[q]):.3g} m (tolerance {wtol:.3g})")
    ov, (i, j) = _pairwise_overlap(fin.pos, radius, on_f)
    rep.max_overlap = max(ov, 0.0)
    if ov > tol:
        rep.fail("overlap", f"final: balls {i} and {j} overlap by {ov:.3g} m (tolerance {tol:.3g})")

    # ---- pocket
    pocket = np.asarray(result.pocket)
    b_on0 = np.asarray(b0.on_table, bool)
    bad = b_on0 & ((pocket >= 0) == on_f)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        rep.fail("pocket", f"ball {i}: pocket {int(pocket[i])} but on_table {bool(on_f[i])}")
    if tr is not None and len(tr.times):
        for b in range(n):
            flags = tr.state[tr.ball == b, 4] > 0.5
            if len(flags) and np.any(~flags):
                first_off = int(np.argmax(~flags))
                if flags[first_off:].any():
                    rep.fail("pocket", f"ball {b} back on the table after being pocketed")
    pocket_t: dict[int, int] = {}  # ball -> its pocket event
    for q in np.flatnonzero(kinds == EV_POCKET).tolist():
        pocket_t.setdefault(int(ev.ball[q]), q)
    if pocket_t:
        for q in range(len(ev)):
            kd, bb, oo = int(kinds[q]), int(ev.ball[q]), int(ev.other[q])
            involved = (bb, oo) if kd == EV_COLLISION else (bb,)
            for x in involved:
                if x in pocket_t and q > pocket_t[x]:
                    rep.fail("pocket", f"ball {x} in event {q} ({kd}) after it was pocketed (event {pocket_t[x]})")

    if tr is None:
        return rep
    if exact:
        _check_exact_events(rep, scene, result, radius, mass, law, a, k, v_min, sample_between)
    else:
        _check_step_snapshots(rep, result, mass, radius)
    return rep


def _check_exact_events(rep, scene, result, radius, mass, law, a, k, v_min, sample_between):
    tr, ev = result.trajectory, result.events
    n = len(radius)
    L, W = scene.table.length, scene.table.width
    kinds = np.asarray(ev.kind)
    n_ev = len(ev)
    # State-log rows: n initial rows, then one row per ball involved in each event (two for a collision, the
    # cluster's size for a jam).
    n_inv = np.where(kinds == EV_COLLISION, 2, np.where(kinds == EV_JAM, np.asarray(ev.other), 1))
    start = n + np.concatenate([[0], np.cumsum(n_inv)[:-1]]) if n_ev else np.zeros(0, int)
    if len(tr.times) != n + int(n_inv.sum()):
        rep.fail("continuity", f"state log has {len(tr.times)} rows, expected {n + int(n_inv.sum())}")
        return
    # previous row of the same ball, for every row
    prev = np.full(len(tr.times), -1)
    last = {}
    for q, b in enumerate(tr.ball.tolist()):
        prev[q] = last.get(b, -1)
        last[b] = q
    rows = np.arange(n, len(tr.times))
    if len(rows) == 0:
        return
    if np.any(prev[rows] < 0):
        rep.fail("continuity", "a logged event state has no earlier state of its ball")
        return
    st = tr.state
    p = prev[rows]
    spin = law == SPIN
    # closed-form state just before each logged event (pocketed balls do not move): x y vx vy wx wy wz
    before = np.zeros((len(tr.times), 7))
    if spin:
        ph = scene.physics
        before[rows] = carry_rows(tr.times, np.ascontiguousarray(st), np.ascontiguousarray(radius[tr.ball[rows]]),
                                  p, rows, ph.mu_slide * G, ph.mu_roll * G, ph.mu_spin * G)
    else:
        dt = tr.times[rows] - tr.times[p]
        on_prev = st[p, 4] > 0.5
        bx, by, bvx, bvy = advance_many(np.ascontiguousarray(st[p, 0]), np.ascontiguousarray(st[p, 1]),
                                        np.where(on_prev, st[p, 2], 0.0), np.where(on_prev, st[p, 3], 0.0),
                                        np.ascontiguousarray(dt, dtype=float), int(law), float(a), float(k),
                                        float(v_min))
        before[rows, :4] = np.stack([bx, by, bvx, bvy], axis=1)
    bx, by = before[rows, 0], before[rows, 1]
    # after each row: the logged state (angular velocity in columns 5-7 under spin)
    after_w = st[:, 5:8] if spin else np.zeros((len(tr.times), 3))
    rot = 0.2 * mass[tr.ball] * radius[tr.ball] ** 2  # I / 2

    def ke_before(rr):
        return 0.5 * mass[tr.ball[rr]] * (before[rr, 2] ** 2 + before[rr, 3] ** 2) + rot[rr] * (before[rr, 4:7] ** 2).sum(-1)

    def ke_after(rr):
        return 0.5 * mass[tr.ball[rr]] * (st[rr, 2] ** 2 + st[rr, 3] ** 2) + rot[rr] * (after_w[rr] ** 2).sum(-1)
    # continuity: logged position after the event vs the closed form before it
    jump = np.hypot(st[rows, 0] - bx, st[rows, 1] - by)
    if len(jump):
        q = int(np.argmax(jump))
        rep.max_jump = float(jump[q])
        if jump[q] > CONTINUITY_TOL:
            rep.fail("continuity", f"ball {int(tr.ball[rows[q]])} jumps {jump[q]:.3g} m at t={float(tr.times[rows[q]])!r}")
    if n_ev == 0:
        return
    # row bookkeeping check
    r0 = start
    if np.any(tr.ball[r0] != ev.ball) or np.any(tr.times[r0] != ev.time):
        rep.fail("continuity", "state log rows do not line up with the event log")
        return
    # ---- collisions
    ci = np.flatnonzero(kinds == EV_COLLISION)
    if len(ci):
        ri = start[ci]
        rj = ri + 1
        i = ev.ball[ci]
        j = ev.other[ci]
        mi, mj = mass[i], mass[j]
        vbi, vbj = before[ri, 2:4], before[rj, 2:4]
        vai, vaj = st[ri, 2:4], st[rj, 2:4]
        ke_b = ke_before(ri) + ke_before(rj)
        ke_a = ke_after(ri) + ke_after(rj)
        gain = np.where(ke_b > 0, (ke_a - ke_b) / np.where(ke_b > 0, ke_b, 1.0), np.where(ke_a > 0, np.inf, 0.0))
        q = int(np.argmax(gain))
        rep.max_energy_gain = max(rep.max_energy_gain, float(gain[q]))
        if gain[q] > ENERGY_REL_TOL:
            rep.fail("energy", f"collision event {int(ci[q])} (balls {int(i[q])},{int(j[q])}) at t={float(ev.time[ci[q]])!r}: "
                               f"kinetic energy {float(ke_b[q])!r} -> {float(ke_a[q])!r} (relative {gain[q]:.3g})")
        dp = mi[:, None] * (vai - vbi) + mj[:, None] * (vaj - vbj)
        scale = mi * np.hypot(vbi[:, 0], vbi[:, 1]) + mj * np.hypot(vbj[:, 0], vbj[:, 1])
        zero_i = (vai[:, 0] == 0.0) & (vai[:, 1] == 0.0)
        zero_j = (vaj[:, 0] == 0.0) & (vaj[:, 1] == 0.0)
        allow = v_min * (mi * zero_i + mj * zero_j) * (1.0 + 1e-9)
        err = np.hypot(dp[:, 0], dp[:, 1])
        rel = np.where(scale > 0, np.maximum(err - allow, 0.0) / np.where(scale > 0, scale, 1.0), np.where(err > allow, np.inf, 0.0))
        q = int(np.argmax(rel))
        rep.max_momentum_err = max(rep.max_momentum_err, float(rel[q]))
        if rel[q] > MOMENTUM_REL_TOL:
            rep.fail("momentum", f"collision event {int(ci[q])} (balls {int(i[q])},{int(j[q])}) at t={float(ev.time[ci[q]])!r}: "
                                 f"momentum change {err[q]:.3g} (relative {rel[q]:.3g})")
        dist = np.hypot(st[ri, 0] - st[rj, 0], st[ri, 1] - st[rj, 1])
        cerr = np.abs(dist - (radius[i] + radius[j]))
        q = int(np.argmax(cerr))
        rep.max_contact_err = max(rep.max_contact_err, float(cerr[q]))
        if cerr[q] > CONTACT_TOL:
            rep.fail("contact", f"collision event {int(ci[q])} (balls {int(i[q])},{int(j[q])}) at t={float(ev.time[ci[q]])!r}: "
                                f"centres {float(dist[q])!r} m apart, contact at {float(radius[i[q]] + radius[j[q]])!r}")
    # ---- cushions
    cu = np.flatnonzero(kinds == EV_CUSHION)
    if len(cu):
        rr = start[cu]
        if spin:  # spin turns into speed at a cushion (running english): only the total energy cannot rise
            sb, sa = ke_before(rr), ke_after(rr)
            gain = np.where(sb > 0, (sa - sb) / np.where(sb > 0, sb, 1.0), np.where(sa > 0, np.inf, 0.0))
            what = "kinetic energy"
        else:
            sb = np.hypot(before[rr, 2], before[rr, 3])
            sa = np.hypot(st[rr, 2], st[rr, 3])
            gain = np.where(sb > 0, (sa * sa - sb * sb) / np.where(sb > 0, sb * sb, 1.0), np.where(sa > 0, np.inf, 0.0))
            what = "speed"
        q = int(np.argmax(gain))
        rep.max_energy_gain = max(rep.max_energy_gain, float(gain[q]))
        if gain[q] > ENERGY_REL_TOL:
            rep.fail("energy", f"cushion event {int(cu[q])} (ball {int(ev.ball[cu[q]])}) at t={float(ev.time[cu[q]])!r}: "
                               f"{what} {float(sb[q])!r} -> {float(sa[q])!r}")
        b = ev.ball[cu]
        c = ev.other[cu]
        if scene.table.has_jaws:  # on its wall: the centre at the wall's reach
            werr = np.abs(wall_gaps(*scene.table.walls(), st[rr, 0], st[rr, 1], radius[b], c))
        else:
            wall = np.where(c == 0, radius[b], np.where(c == 1, L - radius[b],
                                                        np.where(c == 2, radius[b], W - radius[b])))
            coord = np.where(c < 2, st[rr, 0], st[rr, 1])
            werr = np.abs(coord - wall)
        q = int(np.argmax(werr))
        if werr[q] > CONTACT_TOL:
            rep.fail("contact", f"cushion event {int(cu[q])}: ball {int(b[q])} {werr[q]:.3g} m off cushion {int(c[q])}")
    # ---- jams: the cluster's kinetic energy never rises
    for q in np.flatnonzero(kinds == EV_JAM).tolist():
        rr = np.arange(start[q], start[q] + int(ev.other[q]))
        ke_b = float(np.sum(ke_before(rr)))
        ke_a = float(np.sum(ke_after(rr)))
        if ke_a > ke_b * (1.0 + ENERGY_REL_TOL) + 1e-300:
            rep.fail("energy", f"jam event {q} at t={float(ev.time[q])!r}: cluster kinetic energy {ke_b!r} -> {ke_a!r}")
    # ---- spin model: motion transitions (energy, and the state each one names); rolling states do not slip
    if spin:
        for code, kind, name in ((MS_ROLLING, EV_ROLL, "roll"), (MS_SPINNING, EV_SPIN, "spin"),
                                 (MS_STATIONARY, EV_STOP, "stop")):
            tq = np.flatnonzero(kinds == kind)
            if len(tq) == 0:
                continue
            rr = start[tq]
            bad = np.flatnonzero(st[rr, 8] != code)
            if len(bad):
                rep.fail("spin_state", f"{name} event {int(tq[bad[0]])} at t={float(ev.time[tq[bad[0]]])!r} leaves ball "
                                       f"{int(ev.ball[tq[bad[0]]])} in motion state {int(st[rr[bad[0]], 8])}")
            sb, sa = ke_before(rr), ke_after(rr)
            # The end state is computed from the piece's start in closed form: its rounding scales with the energy
            # there (a slide whose v0 and 2 u0 / 7 nearly cancel ends slow, with a relative error of
            # eps |v0| / |v_end|), so the tolerance is relative to the larger of both energies.
            scale = np.maximum(sb, ke_after(prev[rr]))
            gain = np.where(scale > 0, (sa - sb) / np.where(scale > 0, scale, 1.0), np.where(sa > 0, np.inf, 0.0))
            q = int(np.argmax(gain))
            rep.max_energy_gain = max(rep.max_energy_gain, float(gain[q]))
            if gain[q] > ENERGY_REL_TOL:
                rep.fail("energy", f"{name} event {int(tq[q])} (ball {int(ev.ball[tq[q]])}) at "
                                   f"t={float(ev.time[tq[q]])!r}: kinetic energy {float(sb[q])!r} -> {float(sa[q])!r}")
        rl = np.flatnonzero(st[:, 8] == MS_ROLLING)
        if len(rl):
            r_rl = radius[tr.ball[rl]]
            ux = st[rl, 2] - r_rl * st[rl, 6]
            uy = st[rl, 3] + r_rl * st[rl, 5]
            scale = np.hypot(st[rl, 2], st[rl, 3]) + r_rl * np.hypot(st[rl, 5], st[rl, 6])
            bad = np.flatnonzero(np.hypot(ux, uy) > ROLLING_SLIP_TOL * scale)
            if len(bad):
                q = int(rl[bad[0]])
                rep.fail("spin_state", f"ball {int(tr.ball[q])} logged rolling at t={float(tr.times[q])!r} slips at "
                                       f"{float(np.hypot(ux[bad[0]], uy[bad[0]])):.3g} m/s")
    # ---- pockets
    po = np.flatnonzero(kinds == EV_POCKET)
    if len(po):
        rr = start[po]
        pk = ev.other[po]
        pxy = scene.table.pocket_xy[pk]
        dd = np.hypot(st[rr, 0] - pxy[:, 0], st[rr, 1] - pxy[:, 1]) - scene.table.pocket_radius[pk]
        q = int(np.argmax(dd))
        if dd[q] > CONTACT_TOL:
            rep.fail("contact", f"pocket event {int(po[q])}: ball {int(ev.ball[po[q]])} {dd[q]:.3g} m outside the "
                                f"capture radius of pocket {int(pk[q])}")
    # ---- overlap at every event time and half-way between
    if n >= 2:
        tu = np.unique(ev.time)
        if sample_between and len(tu) > 1:
            tu = np.sort(np.concatenate([tu, 0.5 * (tu[1:] + tu[:-1])]))
        if len(tu) > 40_000:
            tu = tu[np.linspace(0, len(tu) - 1, 40_000).astype(int)]
        pos, on = tr.sample(tu)
        ov, s, (i, j) = _overlap_series(pos, radius, on)
        rep.max_overlap_during = max(ov, 0.0)
        if ov > EXACT_OVERLAP_TOL:
            rep.fail("overlap_during", f"balls {i} and {j} overlap by {ov:.3g} m at t={float(tu[s])!r}")


def _check_step_snapshots(rep, result, mass, radius):
    """Step solver: rebuild the full state at each all-ball snapshot (pocket rows in between only remove balls);
    the total kinetic energy (with the rotation, under the spin model) must never rise from one snapshot to the
    next. Also measures overlaps."""
    tr = result.trajectory
    n = int(tr.n_balls)
    if len(tr.times) == 0:
        return
    tu, cnt = np.unique(tr.times, return_counts=True)
    full = tu[cnt >= n]
    if len(full) == 0:
        return
    pos = np.zeros((len(full), n, 2))
    vel = np.zeros((len(full), n, 2))
    ang = np.zeros((len(full), n, 3))
    on = np.zeros((len(full), n), bool)
    spin = tr.state.shape[1] >= 9
    for b in range(n):
        rows = np.flatnonzero(tr.ball == b)
        k = np.searchsorted(tr.times[rows], full, side="right") - 1
        ok = k >= 0
        r = rows[np.maximum(k, 0)]
        pos[:, b] = np.where(ok[:, None], tr.state[r, 0:2], np.nan)
        vel[:, b] = np.where(ok[:, None], tr.state[r, 2:4], 0.0)
        if spin:
            ang[:, b] = np.where(ok[:, None], tr.state[r, 5:8], 0.0)
        on[:, b] = ok & (tr.state[r, 4] > 0.5)
    ke_ball = mass[None, :] * (vel ** 2).sum(-1)
    if spin:
        ke_ball = 0.5 * ke_ball + 0.2 * (mass * radius ** 2)[None, :] * (ang ** 2).sum(-1)
    else:
        ke_ball = 0.5 * ke_ball
    ke = np.sum(np.where(on, ke_ball, 0.0), axis=1)
    if len(ke) > 1:
        prev, nxt = ke[:-1], ke[1:]
        gain = np.where(prev > 0, (nxt - prev) / np.where(prev > 0, prev, 1.0), np.where(nxt > 0, np.inf, 0.0))
        q = int(np.argmax(gain))
        rep.max_energy_gain = max(rep.max_energy_gain, float(gain[q]))
        if gain[q] > ENERGY_REL_TOL:
            rep.fail("energy", f"step: total kinetic energy rises {float(prev[q])!r} -> {float(nxt[q])!r} between the snapshots at "
                               f"t={float(full[q])!r} and t={float(full[q + 1])!r}")
    ov, _, _ = _overlap_series(pos, result.balls.radius, on)
    rep.max_overlap_during = max(ov, 0.0)



# --------------------------------------------------------------------------------------------- running a case
def run_case(scene_dict: dict[str, Any], sample_between: bool = True):
    """Build the scene, run it with ``record=True`` and check it. Returns ``(report, result or None)``."""
    try:
        scene = Scene.from_dict(scene_dict)
        result = scene.run(record=True)
    except Exception as exc:  # noqa: BLE001 - a crash is a finding
        rep = Report(solver=str(scene_dict.get("solver", {}).get("name", "exact")))
        rep.fail("exception", f"{type(exc).__name__}: {exc}\n{traceback.format_exc(limit=4)}")
        return rep, None
    return check_shot(scene, result, sample_between=sample_between), result

