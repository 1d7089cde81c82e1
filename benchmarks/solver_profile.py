"""Where an event of the exact solvers goes: a profile per event, with and without spin, on four scenes.

    python -m benchmarks --only profile [--quick]
    python -m benchmarks.solver_profile [--quick] [--shots N]

Scenes (start states; the same ones under the ``rolling`` model and under ``spin``):

- ``one ball``: the one-ball env's shots (cue and object ball at random places, the object ball potted by the ghost
  ball; the capture-circle table), :func:`.ladder.one_ball_shots`;
- ``9-ball run-out``: the shots of seeded ``Billiards9Ball-v0`` games against the geometric opponent (the agent's
  random shots, the opponent's run-outs; the WPA table with jaws), as the games' physics bound replays them
  (:class:`.games.GameRecord`);
- ``break``: the 9-ball break on the same table (:func:`.ladder.break_shots`);
- ``8-ball``: the shots of seeded ``Billiards8Ball-v0`` games (16 balls).

How: a compiled kernel inlines its helpers, so a sampling profiler sees one function. Instead every shot of a scene is
run once through the kernel's own Python (a subprocess with ``NUMBA_DISABLE_JIT=1``), recording the inputs of
every call of the kernel's parts: the root finder (``roots.first_entry``, and the spin model's cushion quadratic
``walls.wall_time``), a pair's re-prediction, a ball's own next event, the choice of the next event, a ball's state
at the event time. Each recorded call list is then replayed through the compiled part, in a compiled loop; its time
per call times its calls per event is that part's time per event. The kernel's own time per event is measured on the
same shots; what the parts do not explain is the event's application (collision laws, logs) and bookkeeping, of
which the allocations are measured apart (a compiled function making the kernel's arrays). The root finder's time
is also inside the prediction it serves: the table gives both, the prediction's own share without it.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any, Callable

import numpy as np

from .common import log, machine_info, machine_markdown

SCENES = ("one ball", "9-ball run-out", "break", "8-ball")
MODELS = ("rolling", "spin")


def _sizes(quick: bool) -> dict[str, int]:
    return {"shots": 20 if quick else 120, "breaks": 4 if quick else 16, "game_steps": 40 if quick else 150,
            "repeats": 5 if quick else 9}


# --- scenes ----------------------------------------------------------------------------------------------------

def _struck_states(shots: list[Any], physics: Any) -> tuple[np.ndarray, ...]:
    bs = [s.balls(physics) for s in shots]
    return tuple(np.stack([getattr(b, f) for b in bs]).astype(t) for f, t in
                 (("pos", float), ("vel", float), ("ang", float), ("on_table", np.bool_)))


def _game_states(env_id: str, steps: int, spin: bool) -> tuple[np.ndarray, ...]:
    from .games import GameRecord

    rec = GameRecord(env_id, steps, seed=0)
    _, pos, vel, ang, on = rec.shot_args[:5]
    return pos, vel, ang if spin else np.zeros_like(ang), on


def build_scenes(sizes: dict[str, int]) -> dict[str, dict[str, Any]]:
    """Every scene's table and start states under each model: ``{scene: {"table": ..., model: (pos, vel, ang,
    on)}}``."""
    from billiards_env.physics import Physics, Table
    from billiards_env.physics.table import TABLE_PRESETS

    from .ladder import break_shots, one_ball_shots

    models = {"rolling": Physics(), "spin": Physics(friction="spin")}
    rng = np.random.default_rng(2026)
    capture = Table()
    jaws = TABLE_PRESETS["wpa"]()
    scenes: dict[str, dict[str, Any]] = {}
    one = one_ball_shots(sizes["shots"], rng, capture)
    scenes["one ball"] = {"table": capture, **{m: _struck_states(one, ph) for m, ph in models.items()}}
    states = _game_states("Billiards9Ball-v0", sizes["game_steps"], False)
    scenes["9-ball run-out"] = {"table": jaws, "rolling": states, "spin": states}
    brk = break_shots(sizes["breaks"], rng, jaws)
    scenes["break"] = {"table": jaws, **{m: _struck_states(brk, ph) for m, ph in models.items()}}
    states = _game_states("Billiards8Ball-v0", sizes["game_steps"] // 2, False)
    scenes["8-ball"] = {"table": jaws, "rolling": states, "spin": states}
    # Keep the shot count per scene bounded (the games record every shot of their steps).
    for sc in scenes.values():
        for m in MODELS:
            sc[m] = tuple(a[: sizes["shots"]] for a in sc[m])
    return scenes


def _simulator(table: Any, model: str) -> Any:
    from billiards_env.physics import Physics, Simulator

    return Simulator(table, Physics() if model == "rolling" else Physics(friction="spin"))


# --- recording (the kernel's Python, in a subprocess without the JIT) -------------------------------------------

def _record_calls(sim: Any, states: tuple[np.ndarray, ...]) -> dict[str, Any]:
    """Run every shot through the kernel's Python with its parts wrapped; returns the recorded inputs per part and
    the event count. Only meaningful with ``NUMBA_DISABLE_JIT=1``."""
    from billiards_env.physics import exact, exact_spin, walls

    spin = sim.kernels.spin
    mod = exact_spin if spin else exact
    rec: dict[str, list[Any]] = {k: [] for k in ("roots_pair", "roots_ball", "quad", "pair", "ball", "select",
                                                  "state")}
    stack: list[str] = []

    def wrap(module: Any, name: str, cat: str, conv: Callable[..., Any] | None) -> Callable[[], None]:
        f = getattr(module, name)

        def w(*args: Any) -> Any:
            if conv is not None:
                key = cat
                if cat == "roots":
                    key = "roots_pair" if "pair" in stack else "roots_ball"
                if cat != "state" or not ({"pair", "ball"} & set(stack)):
                    rec[key].append(conv(*args))
            stack.append(cat)
            try:
                return f(*args)
            finally:
                stack.pop()

        setattr(module, name, w)
        return lambda: setattr(module, name, f)

    undo = []
    roots = lambda *a: tuple(float(x) for x in a)  # noqa: E731
    undo.append(wrap(mod, "first_entry", "roots", roots))
    undo.append(wrap(walls, "first_entry", "roots", roots))
    if spin:
        undo.append(wrap(walls, "wall_time", "quad", roots))
        undo.append(wrap(exact_spin, "wall_time", "quad", roots))

        def pair_conv(i, j, t, *rest):
            s = [float(x) for x in rest[:16]]
            bt, rad, mt = rest[16], rest[17], rest[18]
            return (t, *s, bt[i], bt[j], rad[i], rad[j], mt)

        undo.append(wrap(exact_spin, "pair_from_states", "pair", pair_conv))

        def ball_conv(i, bs, st, radius, *rest):
            return (*bs[i].tolist(), float(st[i]), radius[i])

        undo.append(wrap(exact_spin, "predict_ball", "ball", ball_conv))

        def state_conv(bs, i, t):
            return (t, *bs[i].tolist())

        undo.append(wrap(exact_spin, "state_at", "state", state_conv))
    else:
        def pair_conv(i, j, t, xi, yi, vxi, vyi, si, xj, yj, vxj, vyj, sj, ball_t, radius, prm):
            return (t, xi, yi, vxi, vyi, si, xj, yj, vxj, vyj, sj, ball_t[i], ball_t[j], radius[i], radius[j])

        undo.append(wrap(exact, "pair_time_s", "pair", pair_conv))

        def ball_conv(i, t0, p0, v0, sp0, tstop, radius, *rest):
            return (t0[i], p0[i, 0], p0[i, 1], v0[i, 0], v0[i, 1], tstop[i], radius[i], sp0[i])

        undo.append(wrap(exact, "predict_ball", "ball", ball_conv))

        def state_conv(i, t, t0, p0, v0, sp0, tstop, *rest):
            return (t, t0[i], p0[i, 0], p0[i, 1], v0[i, 0], v0[i, 1], tstop[i], sp0[i])

        undo.append(wrap(exact, "state_at", "state", state_conv))

    def select_conv(*arrays):
        return tuple(a.copy() for a in arrays)

    undo.append(wrap(mod, "next_event", "select", select_conv))
    kernel = mod.simulate_exact_spin if spin else mod.simulate_exact
    params = sim.params.view(np.recarray)
    pos, vel, ang, on = states
    events = 0
    b = pos.shape[1]
    radius = np.full(b, 0.028575)
    mass = np.full(b, 0.17)
    try:
        for k in range(pos.shape[0]):
            res = kernel(pos[k].copy(), vel[k].copy(), ang[k].copy(), radius, mass, on[k].copy(), sim.pocket_xy,
                         sim.pocket_r, params, sim.max_events, False)
            events += int(res.n_events)
    finally:
        for u in undo:
            u()
    out: dict[str, Any] = {"events": events}
    for k, v in rec.items():
        if k == "select":
            out["select"] = tuple(np.stack([c[q] for c in v]) for q in range(len(v[0]))) if v else None
        else:
            out[k] = np.array(v, dtype=float).reshape(len(v), -1) if v else np.zeros((0, 1))
    return out


def _record_main(scene_file: str, out_file: str) -> None:
    """Subprocess entry: record every scene and model of ``scene_file`` (npz) into ``out_file`` (npz)."""
    import pickle

    with open(scene_file, "rb") as fh:
        scenes = pickle.load(fh)
    result = {}
    for name, sc in scenes.items():
        for model in MODELS:
            result[(name, model)] = _record_calls(_simulator(sc["table"], model), sc[model])
    with open(out_file, "wb") as fh:
        pickle.dump(result, fh)


def record(scenes: dict[str, dict[str, Any]]) -> dict[tuple[str, str], dict[str, Any]]:
    """:func:`_record_calls` of every scene and model, in a subprocess with ``NUMBA_DISABLE_JIT=1``."""
    import pickle

    with tempfile.TemporaryDirectory() as d:
        src, dst = os.path.join(d, "scenes.pkl"), os.path.join(d, "calls.pkl")
        with open(src, "wb") as fh:
            pickle.dump(scenes, fh)
        env = dict(os.environ, NUMBA_DISABLE_JIT="1")
        subprocess.run([sys.executable, "-m", "benchmarks.solver_profile", "--record", src, dst], check=True,
                       env=env, cwd=str(Path(__file__).resolve().parent.parent))
        with open(dst, "rb") as fh:
            return pickle.load(fh)


# --- compiled replays -------------------------------------------------------------------------------------------

_COMPILED: dict[str, Any] = {}


def _replays() -> dict[str, Any]:
    """The compiled replay loops (made on first use, so that listing the benchmarks imports no numba)."""
    if _COMPILED:
        return _COMPILED
    from numba import njit

    from billiards_env.physics import exact, exact_spin
    from billiards_env.physics.kernel_logs import next_event
    from billiards_env.physics.roots import first_entry
    from billiards_env.physics.walls import wall_time

    pair_l = exact.pair_time_s
    ball_l = exact.predict_ball
    state_l = exact.state_at
    pair_s = exact_spin.pair_from_states
    ball_s = exact_spin.predict_ball
    state_s = exact_spin.state_at

    @njit
    def roots(c):
        acc = 0.0
        for k in range(c.shape[0]):
            r = first_entry(c[k, 0], c[k, 1], c[k, 2], c[k, 3], c[k, 4], c[k, 5], c[k, 6])
            if r < math.inf:
                acc += r
        return acc

    @njit
    def quad(c):
        acc = 0.0
        for k in range(c.shape[0]):
            r = wall_time(c[k, 0], c[k, 1], c[k, 2], c[k, 3], c[k, 4])
            if r < math.inf:
                acc += r
        return acc

    @njit
    def pair_linear(c, params):
        prm = params[0]
        bt = np.empty(2)
        rad = np.empty(2)
        acc = 0.0
        for k in range(c.shape[0]):
            bt[0] = c[k, 11]
            bt[1] = c[k, 12]
            rad[0] = c[k, 13]
            rad[1] = c[k, 14]
            r = pair_l(0, 1, c[k, 0], c[k, 1], c[k, 2], c[k, 3], c[k, 4], c[k, 5], c[k, 6], c[k, 7], c[k, 8],
                       c[k, 9], c[k, 10], bt, rad, prm)
            if r < math.inf:
                acc += r
        return acc

    @njit
    def pair_spin(c):
        bt = np.empty(2)
        rad = np.empty(2)
        acc = 0.0
        for k in range(c.shape[0]):
            bt[0] = c[k, 17]
            bt[1] = c[k, 18]
            rad[0] = c[k, 19]
            rad[1] = c[k, 20]
            r = pair_s(0, 1, c[k, 0], c[k, 1], c[k, 2], c[k, 3], c[k, 4], c[k, 5], c[k, 6], c[k, 7], c[k, 8],
                       c[k, 9], c[k, 10], c[k, 11], c[k, 12], c[k, 13], c[k, 14], c[k, 15], c[k, 16], bt, rad,
                       c[k, 21])
            if r < math.inf:
                acc += r
        return acc

    @njit
    def ball_linear(c, pocket_xy, pocket_r, params):
        prm = params[0]
        w = np.empty((5, 1))
        p0 = np.empty((1, 2))
        v0 = np.empty((1, 2))
        acc = 0.0
        for k in range(c.shape[0]):
            w[0, 0] = c[k, 0]
            p0[0, 0] = c[k, 1]
            p0[0, 1] = c[k, 2]
            v0[0, 0] = c[k, 3]
            v0[0, 1] = c[k, 4]
            w[1, 0] = c[k, 5]
            w[2, 0] = c[k, 6]
            w[3, 0] = c[k, 7]
            t, kind, other = ball_l(0, w[0], p0, v0, w[3], w[1], w[2], pocket_xy, pocket_r, prm)
            if t < math.inf:
                acc += t + kind
        return acc

    @njit
    def ball_spin(c, pocket_xy, pocket_r, params):
        prm = params[0]
        bs = np.empty((1, 14))
        st = np.empty(1, np.int64)
        rad = np.empty(1)
        acc = 0.0
        for k in range(c.shape[0]):
            for q in range(14):
                bs[0, q] = c[k, q]
            st[0] = np.int64(c[k, 14])
            rad[0] = c[k, 15]
            t, kind, other = ball_s(0, bs, st, rad, pocket_xy, pocket_r, prm.length, prm.width, prm.max_time, prm)
            if t < math.inf:
                acc += t + kind
        return acc

    @njit
    def select(ball_t, ball_kind, ball_other, row_t, row_j):
        acc = 0.0
        for k in range(ball_t.shape[0]):
            best, kind, bi, bj = next_event(ball_t[k], ball_kind[k], ball_other[k], row_t[k], row_j[k])
            acc += kind + bi + bj
            if best < math.inf:
                acc += best
        return acc

    @njit
    def state_linear(c, params):
        prm = params[0]
        w = np.empty((3, 1))
        p0 = np.empty((1, 2))
        v0 = np.empty((1, 2))
        acc = 0.0
        for k in range(c.shape[0]):
            w[0, 0] = c[k, 1]
            p0[0, 0] = c[k, 2]
            p0[0, 1] = c[k, 3]
            v0[0, 0] = c[k, 4]
            v0[0, 1] = c[k, 5]
            w[1, 0] = c[k, 6]
            w[2, 0] = c[k, 7]
            x, y, vx, vy = state_l(0, c[k, 0], w[0], p0, v0, w[2], w[1], prm.law, prm.decel, prm.drag_k)
            acc += x + y + vx + vy
        return acc

    @njit
    def state_spin(c):
        bs = np.empty((1, 14))
        acc = 0.0
        for k in range(c.shape[0]):
            for q in range(14):
                bs[0, q] = c[k, 1 + q]
            x, y, vx, vy, wx, wy, wz = state_s(bs, 0, c[k, 0])
            acc += x + y + vx + vy + wx + wy + wz
        return acc

    @njit
    def alloc_linear(n, reps):
        """The rolling kernel's allocations for ``n`` balls (:func:`.exact.exact_scratch`, as
        :func:`.exact.simulate_exact` makes them for a shot; the batch rows and the pot step make them once a call)."""
        acc = 0
        for _ in range(reps):
            fw = np.empty((7, n))
            iw = np.empty((6, n), np.int64)
            p0 = np.empty((n, 2))
            v0 = np.empty((n, 2))
            pair_t = np.empty((n, n))
            st = np.empty((n, 5))
            ev_t = np.empty(64)
            ev_int = np.empty((64, 3), np.int64)
            ev_s = np.empty(64)
            sc_t = np.empty(1)
            sc_b = np.empty(1, np.int64)
            sc_s = np.empty((1, 5))
            acc += fw.shape[0] + iw.shape[1] + p0.shape[0] + v0.shape[0] + pair_t.shape[0] + st.shape[0] + \
                ev_t.shape[0] + ev_int.shape[0] + ev_s.shape[0] + sc_t.shape[0] + sc_b.shape[0] + sc_s.shape[0]
        return acc

    @njit
    def alloc_spin(n, reps):
        """The spin kernel's allocations for ``n`` balls (as :func:`.exact_spin.simulate_exact_spin` makes them)."""
        acc = 0
        for _ in range(reps):
            fbuf = np.empty(24 * n + n * n + 20 + 2 * 64 + 10)
            ibuf = np.empty(9 * n + 3 * 64 + 1, np.int64)
            acc += fbuf.shape[0] + ibuf.shape[0]
        return acc

    @njit
    def shots(kernel, pos, vel, ang, on, radius, mass, pocket_xy, pocket_r, params, max_events):
        events = 0
        for i in range(pos.shape[0]):
            res = kernel(pos[i].copy(), vel[i].copy(), ang[i].copy(), radius, mass, on[i].copy(), pocket_xy,
                         pocket_r, params, max_events, False)
            events += res.n_events
        return events

    @njit
    def copies(pos, vel, ang, on):
        """The copies :func:`shots` makes of every start state (its own overhead, subtracted)."""
        acc = 0
        for i in range(pos.shape[0]):
            a = pos[i].copy()
            b = vel[i].copy()
            c = ang[i].copy()
            d = on[i].copy()
            acc += a.shape[0] + b.shape[0] + c.shape[0] + d.shape[0]
        return acc

    _COMPILED.update(roots=roots, quad=quad, pair_linear=pair_linear, pair_spin=pair_spin, ball_linear=ball_linear,
                     ball_spin=ball_spin, select=select, state_linear=state_linear, state_spin=state_spin,
                     alloc_linear=alloc_linear, alloc_spin=alloc_spin, shots=shots, copies=copies)
    return _COMPILED


#: The least CPU time one measurement of :func:`_cpu` spans: ``fn`` is called as often as that takes (as timeit
#: does), so a call of a few microseconds is not lost in the clock's and the scheduler's noise.
MIN_MEASURE_S = 2e-3


def _cpu(fn: Callable[[], Any], repeats: int) -> float:
    """Median CPU seconds of one call of ``fn`` over ``repeats`` measurements (after a warm-up call), each measurement
    looping ``fn`` for at least :data:`MIN_MEASURE_S`."""
    c = time.process_time_ns()
    fn()
    once = (time.process_time_ns() - c) * 1e-9
    loops = max(1, min(100_000, int(MIN_MEASURE_S / max(once, 1e-9)) + 1))
    times = []
    for _ in range(repeats):
        c = time.process_time_ns()
        for _ in range(loops):
            fn()
        times.append((time.process_time_ns() - c) * 1e-9 / loops)
    return statistics.median(times)


def _kernel_time(sim: Any, states: tuple[np.ndarray, ...], repeats: int) -> tuple[float, int]:
    """CPU seconds per shot of the scene through the compiled kernel (less the start states' copies), and the
    events of all its shots."""
    fns = _replays()
    pos, vel, ang, on = states
    b = pos.shape[1]
    radius = np.full(b, 0.028575)
    mass = np.full(b, 0.17)
    args = (sim.kernels.exact, pos, vel, ang, on, radius, mass, sim.pocket_xy, sim.pocket_r, sim.params,
            int(sim.max_events))
    events = fns["shots"](*args)
    total = _cpu(lambda: fns["shots"](*args), repeats)
    own = _cpu(lambda: fns["copies"](pos, vel, ang, on), repeats)
    return (total - own) / pos.shape[0], int(events)


def profile_scene(sim: Any, states: tuple[np.ndarray, ...], calls: dict[str, Any], repeats: int) -> dict[str, Any]:
    """The per-event profile of one scene and model (µs per event per part, calls per event)."""
    fns = _replays()
    spin = sim.kernels.spin
    per_shot, events = _kernel_time(sim, states, repeats)
    # The kernel's Python can round a libm function differently from the compiled kernel and, once in a long break,
    # take another event: the parts are per event of the recorded run, the total per event of the compiled one.
    recorded = calls["events"]
    n_shots = states[0].shape[0]
    ev_per_shot = events / n_shots
    params = sim.params

    def part(name: str, fn: Callable[[], Any], n: int) -> dict[str, float]:
        if n == 0:
            return {"us_per_event": 0.0, "calls_per_event": 0.0, "ns_per_call": 0.0}
        reps = max(1, 20000 // n)
        t = _cpu(lambda: [fn() for _ in range(reps)], repeats) / reps
        return {"us_per_event": 1e6 * t / recorded, "calls_per_event": n / recorded, "ns_per_call": 1e9 * t / n}

    out: dict[str, Any] = {}
    rp, rb, qd = calls["roots_pair"], calls["roots_ball"], calls["quad"]
    out["roots in pairs"] = part("roots_pair", lambda: fns["roots"](rp), rp.shape[0])
    out["roots in ball events"] = part("roots_ball", lambda: fns["roots"](rb), rb.shape[0])
    if spin:
        out["cushion quadratics"] = part("quad", lambda: fns["quad"](qd), qd.shape[0])
    pc, bc, sc = calls["pair"], calls["ball"], calls["state"]
    if spin:
        out["pair re-prediction"] = part("pair", lambda: fns["pair_spin"](pc), pc.shape[0])
        out["ball's own event"] = part("ball", lambda: fns["ball_spin"](bc, sim.pocket_xy, sim.pocket_r, params),
                                       bc.shape[0])
        out["state at the event"] = part("state", lambda: fns["state_spin"](sc), sc.shape[0])
    else:
        out["pair re-prediction"] = part("pair", lambda: fns["pair_linear"](pc, params), pc.shape[0])
        out["ball's own event"] = part("ball", lambda: fns["ball_linear"](bc, sim.pocket_xy, sim.pocket_r,
                                                                          params), bc.shape[0])
        out["state at the event"] = part("state", lambda: fns["state_linear"](sc, params), sc.shape[0])
    sel = calls["select"]
    out["event selection"] = part("select", lambda: fns["select"](*sel), sel[0].shape[0])
    n = states[0].shape[1]
    alloc = fns["alloc_spin" if spin else "alloc_linear"]
    t_alloc = _cpu(lambda: alloc(n, 2000), repeats) / 2000
    out["allocation"] = {"us_per_event": 1e6 * t_alloc / ev_per_shot, "calls_per_event": 1.0 / ev_per_shot,
                         "ns_per_call": 1e9 * t_alloc}
    total = 1e6 * per_shot / ev_per_shot
    roots_ball = out["roots in ball events"]["us_per_event"] + out.get("cushion quadratics", {}).get("us_per_event",
                                                                                                      0.0)
    explained = sum(out[k]["us_per_event"] for k in ("pair re-prediction", "ball's own event", "state at the event",
                                                     "event selection", "allocation"))
    out["event application and bookkeeping"] = {"us_per_event": total - explained, "calls_per_event": 1.0,
                                                "ns_per_call": 1e3 * (total - explained)}
    return {"shots": n_shots, "balls": n, "events_per_shot": ev_per_shot, "us_per_shot": 1e6 * per_shot,
            "us_per_event": total, "parts": out,
            "pair_own_us_per_event": out["pair re-prediction"]["us_per_event"] - out["roots in pairs"]["us_per_event"],
            "ball_own_us_per_event": out["ball's own event"]["us_per_event"] - roots_ball}


ROWS = ("pair re-prediction", "roots in pairs", "ball's own event", "roots in ball events", "cushion quadratics",
        "state at the event", "event selection", "allocation", "event application and bookkeeping")


def report(results: dict[str, Any]) -> str:
    """The profile as Markdown tables (one per model)."""
    lines = []
    for model in MODELS:
        lines += ["", f"**{model}** (µs per event; in brackets calls per event)", "",
                  "| part | " + " | ".join(SCENES) + " |", "|---" * (len(SCENES) + 1) + "|"]
        r = {s: results[f"{s}/{model}"] for s in SCENES}
        lines.append("| shot: events, µs | " + " | ".join(f"{r[s]['events_per_shot']:.1f} ev, {r[s]['us_per_shot']:.1f} µs"
                                                       for s in SCENES) + " |")
        lines.append("| **per event** | " + " | ".join(f"**{r[s]['us_per_event']:.3f}**" for s in SCENES) + " |")
        for row in ROWS:
            if row not in r[SCENES[0]]["parts"]:
                continue
            cells = []
            for s in SCENES:
                p = r[s]["parts"][row]
                share = p["us_per_event"] / r[s]["us_per_event"]
                cells.append(f"{p['us_per_event']:.3f} ({p['calls_per_event']:.2f}) {100 * share:.0f}%")
            lines.append(f"| {row} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def run(quick: bool = False, shots: int | None = None, sizes: dict[str, int] | None = None) -> dict[str, Any]:
    """Profile every scene under both models: ``{"sizes", "machine", "results": {"scene/model": ...}}``."""
    sizes = dict(sizes or _sizes(quick))
    if shots:
        sizes["shots"] = shots
    log("[profile] building the scenes")
    scenes = build_scenes(sizes)
    log("[profile] recording the kernels' calls (their Python, no JIT)")
    calls = record(scenes)
    results = {}
    for name, sc in scenes.items():
        for model in MODELS:
            sim = _simulator(sc["table"], model)
            log(f"[profile] {name}, {model}")
            results[f"{name}/{model}"] = profile_scene(sim, sc[model], calls[(name, model)], sizes["repeats"])
    return {"sizes": sizes, "machine": machine_info(), "results": results}


def main(out: Path | None = None, quick: bool = False, shots: int | None = None) -> dict[str, Any]:
    res = run(quick, shots)
    text = report(res["results"])
    print(text)
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
        (out / "solver_profile.json").write_text(json.dumps(res, indent=1, default=str))
        (out / "solver_profile.md").write_text(
            "# Where an event of the exact solvers goes\n\n`python -m benchmarks --only profile`; "
            f"{machine_markdown(res['machine'])} The method: benchmarks/solver_profile.py.\n" + text + "\n")
    return res


if __name__ == "__main__":
    ap = argparse.ArgumentParser(prog="python -m benchmarks.solver_profile")
    ap.add_argument("--record", nargs=2, metavar=("SCENES", "OUT"), help=argparse.SUPPRESS)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--shots", type=int, default=None)
    ap.add_argument("--out", type=Path, default=None)
    a = ap.parse_args()
    if a.record:
        _record_main(*a.record)
    else:
        main(a.out, a.quick, a.shots)
