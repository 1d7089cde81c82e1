"""The games at engine speed, from the repository root:

    python -m benchmarks --only games [--quick] [--write | --out DIR]

- shots and agent steps per second through ``Billiards9Ball-v0`` and ``Billiards8Ball-v0`` (single env, seeded
  uniform random actions, resetting when an episode ends; a shot is the agent's or the built-in opponent's, breaks
  included): alone (``opponent=None``), against the geometric opponent, and with the ``candidates`` action and
  observation types (alone and against it). Per CPU-second of this process (steadier than wall time on a shared
  machine) and per wall second; the configurations are timed in interleaved rounds, so that a change of the
  machine's load hits them alike. The targets compare each with the env alone on its plain types;
- the geometric decision (``geometric_decision`` on the env's arrays, ball in hand and breaks included) median and
  worst over the tables of seeded games, and the search decision (``SearchPlayer.act``; 9-ball, breaks excluded)
  median, its time in the batch simulation and its own, and the shots it simulates;
- the native vector env (``gymnasium.make_vec(id, 256)``) with the geometric opponent: agent steps per second, the
  CPU time in its compiled kernel and in Python; the physics bound (:func:`physics_bound`: the same games' shots
  replayed through the exact kernel alone, the agent steps per CPU-second if nothing but the simulation cost), and
  the shots per step, events per shot, and physics and geometric decisions per shot beside it;
- the 9-ball training job's env (``configs/train/nine_ball_sac.yaml``, run-out practice, and
  ``nine_ball_sac_vs_geometric.yaml``, games against the geometric player): its ``n_envs`` single envs stepped in
  turn as SB3's DummyVecEnv steps them, random actions, shots per CPU-second. *Before*: the same envs with the Python
  of before the games were compiled (2026-12-02) swapped in (``benchmarks/reference_players.py``: the candidate slot lists, the ``candidates``
  observation's loop and the next shot's ease in Python, and the geometric opponent of before, observed for at every
  shot); *after*: as they are; and the native vector env of the same tables.

Prints the figures (and the targets); writes ``games.json`` and ``games.md`` only with ``--write``/``--out``.
"""
from __future__ import annotations

import contextlib
import os
import statistics
import time
from pathlib import Path
from types import SimpleNamespace
from typing import Any, Callable, Iterator

import numpy as np

from billiards_env.players import BasePlayer

from .common import fmt_rate, fmt_time, load_now, log, machine_info, machine_markdown, publish, rerender, time_call



def njit_lazy(fn: Callable[..., Any]) -> Callable[..., Any]:
    """``fn`` compiled by numba on its first call (numba imported then, not when the benchmarks are listed)."""
    compiled: list[Any] = []

    def call(*args: Any) -> Any:
        if not compiled:
            from numba import njit

            compiled.append(njit(fn))
        return compiled[0](*args)

    call.__doc__ = fn.__doc__
    return call


GAMES = ("Billiards9Ball-v0", "Billiards8Ball-v0")
#: The single-env configurations timed (name, env kwargs).
CONFIGS = (("alone", {"opponent": None}),
           ("geometric", {}),
           ("candidates alone", {"opponent": None, "action_type": "candidates", "observation_type": "candidates"}),
           ("candidates vs geometric", {"action_type": "candidates", "observation_type": "candidates"}))
#: The issue-21 targets.
TARGETS = {"slowdown": 1.5, "geometric_median": 1e-4, "geometric_worst": 2e-3, "search_median_9ball": 1e-2,
           "vector": {"Billiards9Ball-v0": 20_000, "Billiards8Ball-v0": 10_000}}
#: The training job's configs (phase 1: run-out practice; phase 2: against the geometric player).
JOB_CONFIGS = ("configs/train/nine_ball_sac.yaml", "configs/train/nine_ball_sac_vs_geometric.yaml")


def _sizes(quick: bool) -> dict[str, Any]:
    if quick:
        return {"seconds": 0.6, "rounds": 2, "games": 3, "steps": 10, "search_every": 3, "vector_tables": 64,
                "vector_seconds": 1.0, "job_seconds": 0.8, "bound_steps": 60, "bound_repeats": 2}
    return {"seconds": 6.0, "rounds": 3, "games": 20, "steps": 30, "search_every": 1, "vector_tables": 256,
            "vector_seconds": 6.0, "job_seconds": 8.0, "bound_steps": 1500, "bound_repeats": 6}


# --- single env: shots and steps per second ----------------------------------------------------------------------

class _Stepper:
    """Envs stepped with seeded uniform random actions in turn (one env: a single env; ``n``: as DummyVecEnv steps
    ``n`` envs), counting agent steps and shots (the agent's and the opponent's, from ``info["opponent_shots"]``,
    the opponent's break at a reset included)."""

    def __init__(self, make: Callable[[], Any], n: int = 1, seed: int = 0) -> None:
        self.envs = [make() for _ in range(n)]
        self.rng = np.random.default_rng(seed)
        self.steps = 0
        self.shots = 0
        for k, env in enumerate(self.envs):
            self.shots += env.reset(seed=seed + k)[1].get("opponent_shots", 0)

    def run(self, seconds: float) -> tuple[float, float]:
        """Step for ``seconds`` of wall time; returns the ``(wall, CPU)`` seconds taken (the counts accumulate)."""
        t0, c0 = time.perf_counter(), time.process_time()
        first = True
        while first or time.perf_counter() - t0 < seconds:  # one round at least, however busy the machine
            first = False
            for env in self.envs:
                a = self.rng.uniform(-1.0, 1.0, env.action_space.shape).astype(np.float32)
                _, _, term, trunc, info = env.step(a)
                self.steps += 1
                self.shots += 1 + int(info.get("opponent_shots", 0))
                if term or trunc:
                    self.shots += env.reset()[1].get("opponent_shots", 0)
        return time.perf_counter() - t0, time.process_time() - c0

    def close(self) -> None:
        for env in self.envs:
            env.close()


def _interleaved(steppers: dict[str, _Stepper], seconds: float, rounds: int) -> dict[str, dict[str, float]]:
    """Each stepper for ``seconds`` in total, in ``rounds`` interleaved slices: rates per CPU and wall second."""
    wall = dict.fromkeys(steppers, 0.0)
    cpu = dict.fromkeys(steppers, 0.0)
    base = {k: (s.steps, s.shots) for k, s in steppers.items()}
    for _ in range(rounds):
        for k, s in steppers.items():
            w, c = s.run(seconds / rounds)
            wall[k] += w
            cpu[k] += c
    out = {}
    for k, s in steppers.items():
        steps, shots = s.steps - base[k][0], s.shots - base[k][1]
        out[k] = {"steps": steps, "shots": shots, "wall_s": wall[k], "cpu_s": cpu[k],
                  "shots_per_cpu_s": shots / cpu[k], "steps_per_cpu_s": steps / cpu[k],
                  "shots_per_s": shots / wall[k], "steps_per_s": steps / wall[k]}
    return out


def single_env_rates(env_id: str, sizes: dict[str, Any]) -> dict[str, dict[str, float]]:
    """The configurations of :data:`CONFIGS` on ``env_id`` (see the module docstring)."""
    import gymnasium as gym

    steppers = {name: _Stepper(lambda kw=kw: gym.make(env_id, **kw)) for name, kw in CONFIGS}
    for s in steppers.values():  # load the compiled code outside the timings
        s.run(0.05)
    try:
        return _interleaved(steppers, sizes["seconds"], sizes["rounds"])
    finally:
        for s in steppers.values():
            s.close()


# --- the decisions -----------------------------------------------------------------------------------------------

def decisions(env_id: str, sizes: dict[str, Any], search: bool) -> dict[str, Any]:
    """The geometric decision on every table of seeded games, and the search decision on some (see the module
    docstring)."""
    from billiards_env.players import SearchPlayer, shot_context
    from billiards_env.players.geometric import context_model
    from billiards_env.players.geometry import geometric_decision

    from .players import SimClock, game_decisions

    geo: list[float] = []
    geo_hand: list[float] = []
    found: dict[str, list[float]] = {"wall": [], "cpu": [], "sim": [], "own": [], "shots": []}
    k = 0
    warm = False
    with SimClock() as clock:
        for env, obs in game_decisions(env_id, sizes["games"], sizes["steps"]):
            ctx = shot_context(env)
            b = ctx.balls
            brk = bool(ctx.game.game_state.break_shot)
            args = (b.pos, b.on_table, b.radius, b.mass, np.asarray(ctx.targets, dtype=np.int64), context_model(ctx),
                    ctx.speed_range, ctx.place_area, brk)
            if not warm:  # load the compiled code outside the timings
                geometric_decision(*args)
                if search:
                    SearchPlayer().act(env, obs)
                warm = True
            t, _ = time_call(lambda: geometric_decision(*args))
            geo.append(t)
            if ctx.place_area is not None and not brk:
                geo_hand.append(t)
            k += 1
            if not search or brk or ctx.place_area is not None or k % sizes["search_every"]:
                continue
            player = SearchPlayer(seed=k)
            clock.reset()
            c0, t0 = time.process_time(), time.perf_counter()
            player.act(env, obs)
            wall, cpu = time.perf_counter() - t0, time.process_time() - c0
            found["wall"].append(wall)
            found["cpu"].append(cpu)
            found["sim"].append(clock.seconds)
            found["own"].append(wall - clock.seconds)
            found["shots"].append(clock.shots)
    out: dict[str, Any] = {"geometric": _stats(geo), "geometric_in_hand": _stats(geo_hand)}
    if search:
        out["search"] = {name: (statistics.median(v) if v else None) for name, v in found.items()}
        out["search"]["n"] = len(found["wall"])
    return out


def _stats(times: list[float]) -> dict[str, Any]:
    if not times:
        return {"n": 0, "median_s": None, "worst_s": None}
    return {"n": len(times), "median_s": statistics.median(times), "worst_s": max(times)}


# --- the native vector env ---------------------------------------------------------------------------------------

def vector_rate(env_id: str, n: int, seconds: float, rounds: int = 1, between: Callable[[], Any] | None = None,
                **kwargs: Any) -> dict[str, Any]:
    """Agent steps per second of ``gymnasium.make_vec(env_id, n)`` with seeded uniform random actions (and shots,
    from ``info["opponent_shots"]``); a table resetting (the step after its episode ended) counts no agent step.
    The CPU time inside the compiled ``play_tables`` calls (the games' kernel: physics, rules, opponents) is timed
    apart: the rest of the step (the infos, the autoreset's bookkeeping) is Python. ``seconds`` in ``rounds``
    slices, ``between`` called after each (other timings interleaved with these, under the same load)."""
    import gymnasium as gym

    from billiards_env.envs import _game_kernels as gk

    vec = gym.make_vec(env_id, n, **kwargs)
    rng = np.random.default_rng(0)
    kernel: list[float] = []  # CPU seconds of each kernel call (appended from the worker threads)
    play = gk.play_tables

    def timed_play(*args: Any) -> None:  # on the env's worker threads: each call counts its own thread's CPU
        c = time.thread_time()
        play(*args)
        kernel.append(time.thread_time() - c)

    steps = shots = 0
    wall = cpu = 0.0
    try:
        vec.reset(seed=0)
        vec.step(rng.uniform(-1.0, 1.0, vec.action_space.shape).astype(np.float32))  # compile outside the timing
        for _ in range(rounds):
            gk.play_tables = timed_play
            t0, c0 = time.perf_counter(), time.process_time()
            first = True
            while first or time.perf_counter() - t0 < seconds / rounds:  # one step at least
                first = False
                _, _, _, _, info = vec.step(rng.uniform(-1.0, 1.0, vec.action_space.shape).astype(np.float32))
                stepped = int(np.sum(info["shots"] > 0))  # (a table resetting took no shot: its info says 0 shots)
                steps += stepped
                shots += stepped + int(np.sum(info.get("opponent_shots", 0)))
            wall += time.perf_counter() - t0
            cpu += time.process_time() - c0
            gk.play_tables = play
            if between is not None:
                between()
        native = bool(getattr(vec.unwrapped, "native", False))
    finally:
        gk.play_tables = play
        vec.close()
    return {"tables": n, "native": native, "steps": steps, "shots": shots, "wall_s": wall, "cpu_s": cpu,
            "steps_per_s": steps / wall, "shots_per_s": shots / wall, "steps_per_cpu_s": steps / max(cpu, 1e-9),
            "kernel_cpu_s": sum(kernel), "kernel_us_per_shot": 1e6 * sum(kernel) / max(shots, 1),
            "python_share": 1.0 - sum(kernel) / max(cpu, 1e-9)}


@njit_lazy
def _replay_shots(kernel: Any, pos: np.ndarray, vel: np.ndarray, ang: np.ndarray, on: np.ndarray, radius: np.ndarray,
                  mass: np.ndarray, pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray,
                  max_events: int) -> int:
    """Every recorded shot (start states ``pos``, ``vel``, ``ang``, ``on``, one row per shot) through the exact
    kernel, as the games' kernel calls it; returns the events simulated."""
    events = 0
    for i in range(pos.shape[0]):
        res = kernel(pos[i].copy(), vel[i].copy(), ang[i].copy(), radius, mass, on[i].copy(), pocket_xy, pocket_r,
                     params, max_events, False)
        events += res.n_events
    return events


@njit_lazy
def _replay_decisions(decide: Any, pos: np.ndarray, on: np.ndarray, radius: np.ndarray, mass: np.ndarray,
                      targets: np.ndarray, counts: np.ndarray, area: np.ndarray, in_hand: np.ndarray,
                      is_break: np.ndarray, pocket_xy: np.ndarray, pocket_r: np.ndarray, params: np.ndarray, lo: float,
                      hi: float, max_cut: float) -> int:
    """Every recorded geometric decision through ``decide`` (``geometric_choice_cached``), in the order one table
    made them, as the games' kernel calls it: with one table's cache of its balls' pocket windows, empty at the
    start of the pass and kept from decision to decision (a ball that did not move keeps its windows)."""
    nb = radius.shape[0]
    cache_pos = np.zeros((nb, 2))
    cache_win = np.zeros((nb, pocket_r.shape[0], 4))
    cache_have = np.zeros(nb, np.bool_)
    placed = 0
    for i in range(pos.shape[0]):
        got = decide(pos[i], on[i], radius, mass, 0, targets[i, :counts[i]].copy(), pocket_xy, pocket_r, params, lo,
                     hi, area[i], in_hand[i], is_break[i], max_cut, cache_pos, cache_win, cache_have)
        placed += got[2]
    return placed


class GameRecord:
    """What the simulation alone costs in the games the native vector env plays (see :func:`physics_bound`).

    Seeded single envs with the geometric opponent (each equal, bit for bit, to a vector env table with the same
    seed and actions) play ``steps`` agent steps of uniform random actions, every shot's start state (the agent's,
    the opponent's, breaks) and every geometric decision's inputs recorded. :meth:`replay` then runs the shots
    through the exact kernel alone and the decisions through ``geometric_choice_cached`` alone (as the kernel's
    opponent decides: one table's window cache carried from decision to decision), each in one compiled loop, and
    adds up their CPU time (call it between the slices of :func:`vector_rate`, so that both run under the same
    load)."""

    def __init__(self, env_id: str, steps: int, seed: int = 0) -> None:
        import gymnasium as gym

        from billiards_env.players import geometric as geo_module
        from billiards_env.players.geometry import MAX_CUT, geometric_choice_cached, state_model

        env = gym.make(env_id)
        u = env.unwrapped
        sim = u.simulator
        shots: list[tuple[np.ndarray, ...]] = []
        decisions: list[tuple[Any, ...]] = []
        run_in_place = sim.run_in_place
        decide = geo_module.geometric_decision

        def recorded_run(b: Any) -> Any:
            shots.append((b.pos.copy(), b.vel.copy(), b.ang.copy(), b.on_table.copy()))
            return run_in_place(b)

        def recorded_decision(pos: Any, on: Any, radius: Any, mass: Any, targets: Any, tm: Any, speed_range: Any,
                              place_area: Any = None, is_break: bool = False, max_cut: float = MAX_CUT,
                              cue: int = 0) -> Any:
            decisions.append((np.array(pos, dtype=float), np.array(on, dtype=np.bool_),
                              np.asarray(targets, np.int64), place_area, bool(is_break), cue))
            return decide(pos, on, radius, mass, targets, tm, speed_range, place_area, is_break, max_cut, cue)

        rng = np.random.default_rng(seed)
        sim.run_in_place = recorded_run
        geo_module.geometric_decision = recorded_decision
        try:
            env.reset(seed=seed)
            for _ in range(steps):
                _, _, term, trunc, _ = env.step(rng.uniform(-1.0, 1.0, env.action_space.shape).astype(np.float32))
                if term or trunc:
                    env.reset()
        finally:
            del sim.run_in_place
            geo_module.geometric_decision = decide
        b = u.balls
        radius = np.ascontiguousarray(b.radius, dtype=float)
        mass = np.ascontiguousarray(b.mass, dtype=float)
        pos, vel, ang, on = (np.stack([s[c] for s in shots]) for c in range(4))
        self.shot_args = (sim.kernels.exact, pos, vel, ang, on, radius, mass, sim.pocket_xy, sim.pocket_r,
                          sim.params, int(sim.max_events))
        assert all(d[5] == 0 for d in decisions), "the games' cue ball is row 0"
        if not decisions:  # (a tiny run whose opponent never shot)
            decisions.append((pos[0], on[0], np.arange(1, radius.shape[0], dtype=np.int64), None, False, 0))
        counts = np.array([len(d[2]) for d in decisions], np.int64)
        targets = np.zeros((len(decisions), radius.shape[0]), np.int64)
        for i, d in enumerate(decisions):
            targets[i, :counts[i]] = d[2]
        tm = state_model(u.table_state)
        lo, hi = u.table_state.settings.speed_range
        self.decision_args = (
            geometric_choice_cached, np.stack([d[0] for d in decisions]), np.stack([d[1] for d in decisions]),
            radius, mass, targets, counts,
            np.array([d[3] if d[3] is not None else (0.0, 0.0, 0.0, 0.0) for d in decisions], dtype=float),
            np.array([d[3] is not None for d in decisions], np.bool_), np.array([d[4] for d in decisions], np.bool_),
            tm.pocket_xy, tm.pocket_r, tm.params, float(lo), float(hi), MAX_CUT)
        env.close()
        self.steps = steps
        self.n_shots = len(shots)
        self.n_decisions = len(decisions)
        self.events = int(_replay_shots(*self.shot_args))  # (compiles the loops)
        _replay_decisions(*self.decision_args)
        self.passes = 0
        self.physics_s = 0.0
        self.decisions_s = 0.0

    def replay(self) -> None:
        """One timed pass of the recorded shots and decisions (CPU seconds added up)."""
        self.physics_s += _timed(lambda: _replay_shots(*self.shot_args))
        self.decisions_s += _timed(lambda: _replay_decisions(*self.decision_args))
        self.passes += 1

    def figures(self) -> dict[str, Any]:
        """Shots and events per agent step, the physics and decisions per shot (the mean of the passes), and the
        physics bound (:func:`physics_bound`)."""
        physics = self.physics_s / max(self.passes, 1)
        deciding = self.decisions_s / max(self.passes, 1)
        n = self.n_shots
        return {"steps": self.steps, "shots": n, "events": self.events, "decisions": self.n_decisions,
                "passes": self.passes, "shots_per_step": n / self.steps, "events_per_shot": self.events / n,
                "physics_us_per_shot": 1e6 * physics / n, "physics_us_per_event": 1e6 * physics / max(self.events, 1),
                "decision_us": 1e6 * deciding / max(self.n_decisions, 1),
                "decisions_us_per_shot": 1e6 * deciding / n, "bound_steps_per_cpu_s": self.steps / physics}


def physics_bound(env_id: str, steps: int, repeats: int = 3, seed: int = 0) -> dict[str, Any]:
    """The physics bound of ``env_id``'s games against the geometric opponent: the agent steps per CPU-second if
    everything but the simulation (rules, opponent, actions, observations, infos) cost nothing, from ``steps``
    recorded agent steps replayed ``repeats`` times (:class:`GameRecord`), with the shots and events per step, and
    the physics and geometric decisions per shot."""
    rec = GameRecord(env_id, steps, seed)
    for _ in range(repeats):
        rec.replay()
    return rec.figures()


def _timed(fn: Callable[[], Any]) -> float:
    c = time.process_time()
    fn()
    return time.process_time() - c


# --- the training job: before and after ----------------------------------------------------------------------------

def job_env_kwargs(path: str) -> tuple[str, dict[str, Any], int]:
    """The env id, env kwargs and ``n_envs`` of a training config (``configs/train/*.yaml``)."""
    import yaml

    doc = yaml.safe_load(Path(path).read_text())
    env_id = doc["billiards"]["env_id"]
    hyper = doc[env_id]
    return env_id, dict(hyper.get("env_kwargs") or {}), int(hyper.get("n_envs", 1))


class _ReferenceGeometric(BasePlayer):
    """The geometric player of before the games were compiled (2026-12-02) (``benchmarks/reference_players.py``), playing in the action type it is
    given."""

    name = "geometric"

    def choose(self, state: Any, obs: Any, codec: Any) -> np.ndarray:
        from benchmarks import reference_players as ref
        from billiards_env.players.context import to_action

        env = SimpleNamespace(unwrapped=SimpleNamespace(table_state=state, legal_cue_position=state.legal_cue_position,
                                                        cue_moved_to=state.cue_moved_to))
        place, angle, speed, cand = ref.reference_geometric_act(env)
        return to_action(codec, state, angle, speed, place=place, pocket=cand.pocket if cand is not None else None)


def _reference_slots(state: Any, n: int, speed_range: tuple[float, float] | None = None) -> Any:
    """``envs.candidates.candidate_slots`` on the Python slot lists of before the games were compiled (2026-12-02) (memoised as it is)."""
    from billiards_env.envs import candidates as envc
    from benchmarks import reference_players as ref

    b = state.balls
    if speed_range is None:
        speed_range = state.settings.speed_range
    view = state.view
    key = ("candidates", b.pos.tobytes(), b.on_table.tobytes(), n, speed_range)
    got = view.memo.get(key)
    if got is None:
        slots, kick = ref.reference_candidate_slots(state, n, speed_range)

        def conv(s: Any) -> Any:
            return envc.Slot(s.target, s.pocket, s.obj_angle, s.half, s.d_obj, s.clear_obj, s.shot)

        got = view.memo[key] = envc.Slots(tuple(map(conv, slots)), view.place_area is not None, view.break_shot,
                                          view.targets, conv(kick) if kick is not None else None)
    return got


def _reference_slot_values(self: Any, state: Any) -> np.ndarray:
    """``CandidateFeatures.features`` as the Python loop over the slots of before the games were compiled (2026-12-02)."""
    from benchmarks import reference_players as ref

    cands = _reference_slots(state, self.n_slots, self.speed_range)
    return ref.reference_slot_values(state, cands, self.n_slots, self.speed_range[1])


@contextlib.contextmanager
def before_issue_21() -> Iterator[None]:
    """The envs' candidate slot lists, the ``candidates`` observation's values and the next shot's ease as the
    Python of before the games were compiled (2026-12-02), for the block."""
    from billiards_env.envs import actions, games, observations
    from benchmarks import reference_players as ref

    cf = observations.CandidateFeatures
    saved = (actions.candidate_slots, cf.features, games.next_shot_ease)
    actions.candidate_slots = _reference_slots
    cf.features = _reference_slot_values  # type: ignore[method-assign]
    games.next_shot_ease = ref.reference_next_shot_ease
    try:
        yield
    finally:
        actions.candidate_slots, cf.features, games.next_shot_ease = saved  # type: ignore[method-assign]


class _VectorStepper:
    """A native vector env of ``n`` tables stepped with seeded uniform random actions (counts as :class:`_Stepper`;
    a finished episode resets at the next step, as Gymnasium's default autoreset does)."""

    def __init__(self, make: Callable[[], Any], seed: int = 0) -> None:
        self.vec = make()
        self.rng = np.random.default_rng(seed)
        _, info = self.vec.reset(seed=seed)
        self.steps = 0
        self.shots = int(np.sum(info.get("opponent_shots", 0)))

    def run(self, seconds: float) -> tuple[float, float]:
        t0, c0 = time.perf_counter(), time.process_time()
        vec = self.vec
        first = True
        while first or time.perf_counter() - t0 < seconds:  # one step at least, however busy the machine
            first = False
            a = self.rng.uniform(-1.0, 1.0, vec.action_space.shape).astype(np.float32)
            _, _, _, _, info = vec.step(a)
            stepped = info["shots"] > 0  # (a table resetting took no shot: its reset info says 0 shots)
            self.steps += int(np.sum(stepped))
            self.shots += int(np.sum(stepped)) + int(np.sum(info.get("opponent_shots", 0)))
        return time.perf_counter() - t0, time.process_time() - c0

    def close(self) -> None:
        self.vec.close()


class _SwitchedStepper(_Stepper):
    """A :class:`_Stepper` that runs inside :func:`before_issue_21` (its envs' opponents the reference player)."""

    def __init__(self, make: Callable[[], Any], n: int, seed: int) -> None:
        with before_issue_21():
            super().__init__(make, n, seed)

    def run(self, seconds: float) -> tuple[float, float]:
        with before_issue_21():
            return super().run(seconds)


def training_job(sizes: dict[str, Any]) -> dict[str, Any]:
    """Shots per CPU-second of each training config's envs, before and after (see the module docstring)."""
    import gymnasium as gym

    out: dict[str, Any] = {}
    for path in JOB_CONFIGS:
        env_id, kwargs, n_envs = job_env_kwargs(path)

        def make_before(kwargs: dict[str, Any] = kwargs, env_id: str = env_id) -> Any:
            env = gym.make(env_id, **kwargs)
            if kwargs.get("opponent", "geometric") == "geometric":
                env.unwrapped.set_opponent(_ReferenceGeometric())
            return env

        steppers: dict[str, Any] = {
            "before": _SwitchedStepper(make_before, n_envs, 0),
            "after": _Stepper(lambda kwargs=kwargs, env_id=env_id: gym.make(env_id, **kwargs), n_envs, 0),
            "native": _VectorStepper(lambda kwargs=kwargs, env_id=env_id: gym.make_vec(env_id, n_envs, threads=1,
                                                                                       **kwargs))}
        for s in steppers.values():
            s.run(0.05)
        try:
            rates = _interleaved(steppers, sizes["job_seconds"], sizes["rounds"])
        finally:
            for s in steppers.values():
                s.close()
        before = rates["before"]["shots_per_cpu_s"]
        out[path] = {"env_id": env_id, "n_envs": n_envs, "env_kwargs": kwargs, **rates,
                     "native_path": bool(steppers["native"].vec.unwrapped.native),
                     "speedup": rates["after"]["shots_per_cpu_s"] / before,
                     "speedup_native": rates["native"]["shots_per_cpu_s"] / before}
    return out


# --- the run and its report ----------------------------------------------------------------------------------------

def run(quick: bool = False) -> dict[str, Any]:
    sizes = _sizes(quick)
    doc: dict[str, Any] = {"machine": machine_info(), "quick": quick, "sizes": sizes, "single": {},
                           "decisions": {}, "vector": {}, "bound": {}, "cores": os.cpu_count() or 1}
    for env_id in GAMES:
        log(f"[games] {env_id}: single env")
        doc["single"][env_id] = single_env_rates(env_id, sizes)
        log(f"[games] {env_id}: decisions")
        doc["decisions"][env_id] = decisions(env_id, sizes, search=env_id == "Billiards9Ball-v0")
        log(f"[games] {env_id}: native vector env, {sizes['vector_tables']} tables, and the physics bound "
            f"({sizes['bound_steps']} agent steps recorded, replayed between its slices)")
        rec = GameRecord(env_id, sizes["bound_steps"])
        doc["vector"][env_id] = vector_rate(env_id, sizes["vector_tables"], sizes["vector_seconds"],
                                            rounds=sizes["bound_repeats"], between=rec.replay)
        doc["bound"][env_id] = rec.figures()
    log("[games] the 9-ball training job's envs, before and after")
    doc["job"] = training_job(sizes)
    doc["end_load"] = load_now()
    return doc


def targets(doc: dict[str, Any]) -> list[dict[str, Any]]:
    """The issue-21 targets with their figures."""
    rows = []
    for env_id, rates in doc["single"].items():
        base = rates["alone"]["shots_per_cpu_s"]
        for name in ("geometric", "candidates alone", "candidates vs geometric"):
            slow = base / rates[name]["shots_per_cpu_s"]
            rows.append({"name": f"shots/s, {name} vs alone ({env_id})",
                         "value": f"{fmt_rate(rates[name]['shots_per_cpu_s'])} vs {fmt_rate(base)} per CPU-s: "
                                  f"{slow:.2f}x {'slower' if slow > 1 else 'faster'}",
                         "target": f"<= {TARGETS['slowdown']}x slower", "ok": slow <= TARGETS["slowdown"]})
    for env_id, d in doc["decisions"].items():
        g = d["geometric"]
        rows.append({"name": f"geometric decision median / worst, ball in hand included ({env_id})",
                     "value": f"{fmt_time(g['median_s'])} / {fmt_time(g['worst_s'])}",
                     "target": "<= 0.1 ms / <= 2 ms",
                     "ok": g["median_s"] <= TARGETS["geometric_median"] and g["worst_s"] <= TARGETS["geometric_worst"]})
        s = d.get("search")
        if s and s["wall"] is not None:
            rows.append({"name": f"search decision median, cue ball where it lies ({env_id})",
                         "value": f"{fmt_time(s['wall'])} (CPU {fmt_time(s['cpu'])}; simulation "
                                  f"{fmt_time(s['sim'])}, own {fmt_time(s['own'])}; {s['shots']:.0f} shots)",
                         "target": "<= 10 ms", "ok": s["wall"] <= TARGETS["search_median_9ball"]})
    for env_id, v in doc["vector"].items():
        want = TARGETS["vector"][env_id]
        b = doc.get("bound", {}).get(env_id)
        bound = (f"; physics bound {fmt_rate(b['bound_steps_per_cpu_s'])} per CPU-s, "
                 f"{fmt_rate(b['bound_steps_per_cpu_s'] * doc.get('cores', 1))}/s on {doc.get('cores', 1)} free cores"
                 ) if b else ""
        rows.append({"name": f"native vector env, geometric opponent, {v['tables']} tables ({env_id})",
                     "value": f"{fmt_rate(v['steps_per_s'])} agent steps/s ({fmt_rate(v['steps_per_cpu_s'])} per "
                              f"CPU-s, {fmt_rate(v['shots_per_s'])} shots/s{bound}"
                              f"{'' if v['native'] else '; not native: sub-envs one by one'})",
                     "target": f">= {want:,}", "ok": v["steps_per_s"] >= want})
    return rows


def render_markdown(doc: dict[str, Any]) -> str:
    m = doc["machine"]
    lines = ["# Games at engine speed", "",
             f"Measured by `python -m benchmarks --only games{' --quick' if doc['quick'] else ''}` on {m['time']} "
             "(all figures from this one run).", "", machine_markdown(m, doc.get("end_load")), "",
             "## Targets", "", "| | measured | target | |", "|---|---|---|---|"]
    for r in targets(doc):
        lines.append(f"| {r['name']} | {r['value']} | {r['target']} | {'pass' if r['ok'] else '**miss**'} |")
    lines += ["", "## Single env", "",
              "Seeded uniform random actions; a shot is the agent's or the opponent's (breaks included). Per "
              "CPU-second of the benchmark process, then per wall second; the configurations ran in interleaved "
              "rounds.", "",
              "| game | configuration | shots/CPU-s | agent steps/CPU-s | shots/s | steps/s |",
              "|---|---|---|---|---|---|"]
    for env_id, rates in doc["single"].items():
        for name, r in rates.items():
            lines.append(f"| {env_id} | {name} | {fmt_rate(r['shots_per_cpu_s'])} | {fmt_rate(r['steps_per_cpu_s'])} | "
                         f"{fmt_rate(r['shots_per_s'])} | {fmt_rate(r['steps_per_s'])} |")
    lines += ["", "## Decisions", "",
              "The geometric decision (`geometric_decision` on the env's arrays) on every table of seeded games (the "
              "agent plays the geometric player's shot or, one time in four, a random action): the median of repeated "
              "calls per table, then the median and the worst over the tables. The search decision "
              "(`SearchPlayer.act`, cue ball where it lies): one run per table.", "",
              "| game | geometric median / worst | ball in hand median / worst | search median (CPU) | simulation | "
              "own | shots simulated |", "|---|---|---|---|---|---|---|"]
    for env_id, d in doc["decisions"].items():
        g, h, s = d["geometric"], d["geometric_in_hand"], d.get("search")
        srch = (f"{fmt_time(s['wall'])} ({fmt_time(s['cpu'])}) | {fmt_time(s['sim'])} | {fmt_time(s['own'])} | "
                f"{s['shots']:.0f}") if s and s["wall"] is not None else "- | - | - | -"
        lines.append(f"| {env_id} | {fmt_time(g['median_s'])} / {fmt_time(g['worst_s'])} | "
                     f"{fmt_time(h['median_s'])} / {fmt_time(h['worst_s'])} | {srch} |")
    lines += ["", "## Native vector env", "",
              "| game | tables | native | agent steps/s | shots/s | agent steps/CPU-s |", "|---|---|---|---|---|---|"]
    for env_id, v in doc["vector"].items():
        lines.append(f"| {env_id} | {v['tables']} | {'yes' if v['native'] else 'no'} | {fmt_rate(v['steps_per_s'])} | "
                     f"{fmt_rate(v['shots_per_s'])} | {fmt_rate(v['steps_per_cpu_s'])} |")
    if doc.get("bound"):
        cores = doc.get("cores", 1)
        lines += ["", "Where a step's CPU time goes, and the physics bound. The compiled `play_tables` (the games' "
                  "kernel) is timed inside the vector env's steps above; the rest of a step is Python (the infos, "
                  "built as arrays, and the autoreset). The physics alone: seeded single envs with the geometric "
                  "opponent (each a vector env table, bit for bit) play uniform random actions with every shot's "
                  "start state and every geometric decision recorded, then the shots are replayed through the exact "
                  "kernel alone and the decisions through `geometric_choice_cached` alone, as the kernel's "
                  "opponent makes them (one table's window cache kept from decision to decision; compiled loops, CPU "
                  "time), once after each slice of the vector env's timing, so that both see the same load (the "
                  "mean of the passes). The rest of the kernel (the kernel less the two: the rules, the action "
                  "types, the observations, the bookkeeping) is small, within the noise of a shared machine (it can "
                  "come out below zero). The physics bound is the agent steps per CPU-second if everything but the "
                  f"simulation cost nothing, and that times {cores} on {cores} cores left free.",
                  "", "| game | shots / agent step | events / shot | kernel us / shot | physics us / shot | "
                  "geometric decisions us / shot | rest of the kernel us / shot | Python share of a step | "
                  "physics bound: agent steps / CPU-s | on all cores, per s |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        for env_id, b in doc["bound"].items():
            v = doc["vector"][env_id]
            rest = v["kernel_us_per_shot"] - b["physics_us_per_shot"] - b["decisions_us_per_shot"]
            lines.append(f"| {env_id} | {b['shots_per_step']:.2f} | {b['events_per_shot']:.1f} | "
                         f"{v['kernel_us_per_shot']:.1f} | {b['physics_us_per_shot']:.1f} | "
                         f"{b['decisions_us_per_shot']:.1f} ({b['decision_us']:.1f} per decision) | {rest:.1f} | "
                         f"{100 * v['python_share']:.0f}% | {fmt_rate(b['bound_steps_per_cpu_s'])} | "
                         f"{fmt_rate(b['bound_steps_per_cpu_s'] * cores)} |")
    lines += ["", "## The 9-ball training job's envs", "",
              "Each config's `n_envs` single envs stepped in turn (as SB3's DummyVecEnv steps them), seeded random "
              "actions. Before: the Python of before the games were compiled swapped in "
              "(`benchmarks/reference_players.py`: the candidate slot lists, the next shot's ease, the geometric "
              "opponent, observed for at every shot); after: the "
              "envs as they are. Interleaved rounds in this one run.", "",
              "The native vector env of the same `n_envs` tables (`gymnasium.make_vec`, one thread) is what "
              "`agents.train` steps through `agents.vec.BilliardsVecEnv` where it applies (no env wrapper).", "",
              "| config | shots/CPU-s before | after (single envs) | speed-up | native vector env | speed-up | "
              "agent steps/CPU-s before | after | native |", "|---|---|---|---|---|---|---|---|---|"]
    for path, j in doc["job"].items():
        b, a, v = j["before"], j["after"], j["native"]
        lines.append(f"| `{path}` | {fmt_rate(b['shots_per_cpu_s'])} | {fmt_rate(a['shots_per_cpu_s'])} | "
                     f"{j['speedup']:.2f}x | {fmt_rate(v['shots_per_cpu_s'])} | {j['speedup_native']:.2f}x | "
                     f"{fmt_rate(b['steps_per_cpu_s'])} | {fmt_rate(a['steps_per_cpu_s'])} | "
                     f"{fmt_rate(v['steps_per_cpu_s'])} |")
    return "\n".join(lines) + "\n"


def render(out: Path) -> None:
    """Re-write ``games.md`` from ``games.json``, without measuring."""
    rerender(out, "games", render_markdown)


def main(out: Path | None, quick: bool = False) -> dict[str, Any]:
    """Measure, print the figures, and write ``games.json`` and ``games.md`` into ``out`` if given."""
    doc = run(quick)
    publish(doc, render_markdown(doc), out, "games")
    return doc


__all__ = ["run", "targets", "render_markdown", "render", "main", "before_issue_21", "physics_bound", "vector_rate",
           "GameRecord", "TARGETS"]
