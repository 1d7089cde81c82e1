"""The fuzz command: run random shots in worker processes, check every one, summarise, save the failing cases.

``python -m billiards_env.fuzz --shots 100000 [--seed S] [--solver exact|step|both] [--spin P] [--models P]
[--preset NAME] [--table rect|jaws] [--workers 2] [--out DIR]`` (``--spin``: the share of spin-model shots, 0 by default; 1 for spin
only; ``--models``: the share of those that draw the optional collision models too; ``--preset pooltool``: every
shot under that physics preset);
``--check FILE`` runs one scene file and prints its violations; ``--shrink FILE`` prints a smaller scene that
still fails. A failing case is saved as a scene file under ``--out`` (so that ``billiards-sim FILE --events``
reproduces it) and listed with its violations in ``--out/violations.jsonl``.
"""
from __future__ import annotations

import argparse
import json
import multiprocessing as mp
import sys
import time
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..physics.model import PRESETS
from ..physics.invariants import (CONTACT_TOL, CONTINUITY_TOL, ENERGY_REL_TOL, EXACT_OVERLAP_TOL, INVARIANTS,
                                  MOMENTUM_REL_TOL, STEP_OVERLAP_ABS, STEP_OVERLAP_FACTOR, ZENO_BURST, Report,
                                  run_case)
from .generator import TABLE_KINDS, DEFAULT_MAX_EVENTS, DEFAULT_MAX_TIME, DEFAULT_STEP_MAX_TIME, NumpySource, random_scene, shot_rng
from .shrink import shrink_case


def _solver_for(mode: str, rng: np.random.Generator) -> str:
    if mode == "both":
        return "exact" if rng.random() < 0.5 else "step"
    return mode


@dataclass
class Stats:
    shots: int = 0
    failing_shots: int = 0
    per_solver: Counter = field(default_factory=Counter)
    per_law: Counter = field(default_factory=Counter)  #: shots per friction law (rolling, drag, spin)
    violations: Counter = field(default_factory=Counter)
    violation_shots: Counter = field(default_factory=Counter)
    statuses: Counter = field(default_factory=Counter)
    events: int = 0
    collisions: int = 0
    max_events: int = 0
    worst_overlap: dict = field(default_factory=lambda: {"exact": 0.0, "step": 0.0})
    worst_overlap_ratio: float = 0.0  #: step: final overlap / (speed * dt)
    worst_overlap_during: dict = field(default_factory=lambda: {"exact": 0.0, "step": 0.0})
    worst_energy_gain: float = 0.0
    worst_wall_overlap: dict = field(default_factory=lambda: {"exact": 0.0, "step": 0.0})  #: jaw tables (m)
    worst_momentum_err: float = 0.0
    worst_contact_err: float = 0.0
    worst_jump: float = 0.0
    max_burst: int = 0
    sim_seconds: float = 0.0
    failures: list = field(default_factory=list)

    def add(self, rep: Report, scene_dict: dict, tag: str, keep_failure: bool) -> None:
        self.shots += 1
        solver = scene_dict["solver"]["name"]
        self.per_solver[solver] += 1
        ph = scene_dict["physics"]
        law = "spin" if "preset" in ph else ph.get("friction", "rolling")
        self.per_law[law] += 1
        if rep.violations:
            self.per_law[f"{law} failing"] += 1
        self.statuses[f"{solver}:{rep.status or 'crash'}"] += 1
        self.events += rep.n_events
        self.collisions += rep.n_collisions
        self.max_events = max(self.max_events, rep.n_events)
        self.worst_overlap[solver] = max(self.worst_overlap[solver], rep.max_overlap)
        if solver == "step":
            sd = scene_dict["shot"]["speed"] * scene_dict["solver"]["dt"]
            if sd > 0:
                self.worst_overlap_ratio = max(self.worst_overlap_ratio, rep.max_overlap / sd)
        self.worst_overlap_during[solver] = max(self.worst_overlap_during[solver], rep.max_overlap_during)
        self.worst_wall_overlap[solver] = max(self.worst_wall_overlap[solver], rep.max_wall_overlap)
        self.worst_energy_gain = max(self.worst_energy_gain, rep.max_energy_gain)
        self.worst_momentum_err = max(self.worst_momentum_err, rep.max_momentum_err)
        self.worst_contact_err = max(self.worst_contact_err, rep.max_contact_err)
        self.worst_jump = max(self.worst_jump, rep.max_jump)
        self.max_burst = max(self.max_burst, rep.max_burst)
        self.sim_seconds += rep.sim_time
        self.failing_shots += bool(rep.violations)
        for name in rep.violations:
            self.violations[name] += rep.counts[name]
            self.violation_shots[name] += 1
        if rep.violations and keep_failure:
            self.failures.append({"tag": tag, "solver": solver, "violations": rep.violations, "scene": scene_dict})

    def merge(self, other: "Stats") -> None:
        self.shots += other.shots
        self.failing_shots += other.failing_shots
        for name in ("per_solver", "per_law", "violations", "violation_shots", "statuses"):
            getattr(self, name).update(getattr(other, name))
        self.events += other.events
        self.collisions += other.collisions
        self.max_events = max(self.max_events, other.max_events)
        for s in ("exact", "step"):
            self.worst_overlap[s] = max(self.worst_overlap[s], other.worst_overlap[s])
            self.worst_overlap_during[s] = max(self.worst_overlap_during[s], other.worst_overlap_during[s])
            self.worst_wall_overlap[s] = max(self.worst_wall_overlap[s], other.worst_wall_overlap[s])
        for name in ("worst_overlap_ratio", "worst_energy_gain", "worst_momentum_err", "worst_contact_err",
                     "worst_jump", "max_burst"):
            setattr(self, name, max(getattr(self, name), getattr(other, name)))
        self.sim_seconds += other.sim_seconds
        self.failures.extend(other.failures)


def _run_chunk(args: tuple) -> Stats:
    seed, lo, hi, mode, max_time, max_events, keep, spin, models, preset, table = args
    stats = Stats()
    for idx in range(lo, hi):
        rng = shot_rng(seed, idx)
        solver = _solver_for(mode, rng)
        scene_dict = random_scene(NumpySource(rng), solver=solver, max_time=max_time, max_events=max_events,
                                  spin=spin, models=models, preset=preset, table=table)
        rep, _ = run_case(scene_dict)
        stats.add(rep, scene_dict, f"seed{seed}-shot{idx}", keep_failure=len(stats.failures) < keep)
    return stats


def _warm_up() -> None:
    """Compile (or load from cache) the numba kernels once per process before timing."""
    rng = shot_rng(0, 0)
    for solver in ("exact", "step"):
        for spin in (0.0, 1.0):
            run_case(random_scene(NumpySource(rng), solver=solver, max_time=1.0, spin=spin, models=spin))


def format_summary(stats: Stats, wall: float) -> str:
    lines = [f"shots run: {stats.shots}  ({', '.join(f'{k} {v}' for k, v in sorted(stats.per_solver.items()))})",
             f"per friction law: {', '.join(f'{k} {v}' for k, v in sorted(stats.per_law.items()))}",
             f"wall time: {wall:.1f} s  ({stats.shots / max(wall, 1e-9):.0f} shots/s); simulated {stats.sim_seconds:.0f} s",
             f"events/shot: {stats.events / max(stats.shots, 1):.1f} (max {stats.max_events}); "
             f"collisions/shot: {stats.collisions / max(stats.shots, 1):.1f}",
             f"most events at one instant: {stats.max_burst} (zeno above {ZENO_BURST})",
             "statuses: " + ", ".join(f"{k} {v}" for k, v in sorted(stats.statuses.items())),
             f"failing shots: {stats.failing_shots}",
             "violations (shots with / total occurrences):"]
    for name in INVARIANTS:
        lines.append(f"  {name:15s} {stats.violation_shots.get(name, 0):7d} / {stats.violations.get(name, 0)}")
    lines += [f"worst final overlap: exact {stats.worst_overlap['exact']:.3g} m (tol {EXACT_OVERLAP_TOL:g}), "
              f"step {stats.worst_overlap['step']:.3g} m (= {stats.worst_overlap_ratio:.3g} x speed*dt; "
              f"tol {STEP_OVERLAP_FACTOR:g} x speed*dt + {STEP_OVERLAP_ABS:g})",
              f"worst overlap during shot: exact {stats.worst_overlap_during['exact']:.3g} m, "
              f"step {stats.worst_overlap_during['step']:.3g} m",
              f"worst overlap with a wall (jaw tables): exact {stats.worst_wall_overlap['exact']:.3g} m, "
              f"step {stats.worst_wall_overlap['step']:.3g} m",
              f"worst energy gain (relative, per event): {stats.worst_energy_gain:.3g} (tol {ENERGY_REL_TOL:g})",
              f"worst momentum error (relative, per collision): {stats.worst_momentum_err:.3g} (tol {MOMENTUM_REL_TOL:g})",
              f"worst contact-distance error at a collision: {stats.worst_contact_err:.3g} m (tol {CONTACT_TOL:g})",
              f"worst position jump at an event: {stats.worst_jump:.3g} m (tol {CONTINUITY_TOL:g})"]
    return "\n".join(lines)


def save_failures(failures: list[dict], out: Path) -> list[Path]:
    """Write every failing case as a scene file plus one line of ``violations.jsonl``; returns the files."""
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    with open(out / "violations.jsonl", "a") as index:
        for f in failures:
            kinds = "+".join(sorted(f["violations"]))
            path = out / f"{f['tag']}-{f['solver']}-{kinds}.json"
            path.write_text(json.dumps(f["scene"], indent=1) + "\n")
            index.write(json.dumps({"file": path.name, "solver": f["solver"], "violations": f["violations"]}) + "\n")
            paths.append(path)
    return paths


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m billiards_env.fuzz",
                                description="Fuzz the physics engine with random shots and check its invariants.")
    p.add_argument("--shots", type=int, default=100_000, help="number of random shots (default 100000)")
    p.add_argument("--seed", type=int, default=0, help="run seed; shot i of seed S is reproducible alone")
    p.add_argument("--solver", choices=("exact", "step", "both"), default="exact",
                   help="solver of every shot; 'both' draws one per shot")
    p.add_argument("--spin", type=float, default=0.0,
                   help="share of shots under the spin model (0 by default: rolling and drag only, the same shots "
                        "as before the spin model for a given seed; 1: spin only)")
    p.add_argument("--models", type=float, default=0.0,
                   help="share of the spin-model shots that also draw the optional collision models (alciatore "
                        "ball-ball friction, stronge/mathavan cushions, a raised cushion nose, squirt); default 0")
    p.add_argument("--preset", default=None,
                   help="every shot under this physics preset (e.g. pooltool; the tip offsets drawn), instead of "
                        "drawn friction laws and constants")
    p.add_argument("--table", choices=TABLE_KINDS, default="rect",
                   help="'rect' (default): the capture-pocket table; 'jaws': jaw tables (a preset among wpa, "
                        "pooltool, snooker_match with its specs perturbed), balls anywhere, the mouths included")
    p.add_argument("--workers", type=int, default=2, help="worker processes (default 2)")
    p.add_argument("--out", default="fuzz-failures", help="folder for failing cases (scene files)")
    p.add_argument("--max-time", type=float, default=None,
                   help=f"simulated-time cap per shot (default {DEFAULT_MAX_TIME:g} s exact, "
                        f"{DEFAULT_STEP_MAX_TIME:g} s step)")
    p.add_argument("--max-events", type=int, default=DEFAULT_MAX_EVENTS, help="event cap per shot (exact)")
    p.add_argument("--chunk", type=int, default=250, help="shots per work unit")
    p.add_argument("--keep", type=int, default=50, help="failing cases saved per work unit at most")
    p.add_argument("--start", type=int, default=0, help="index of the first shot (to resume or replay)")
    p.add_argument("--shrink", metavar="SCENE", help="instead of fuzzing: shrink this failing scene file (fewer balls, "
                                                    "round parameters) and print the smaller scene")
    p.add_argument("--invariant", help="with --shrink: the invariant to keep violating (default: the first)")
    p.add_argument("--check", metavar="SCENE", help="instead of fuzzing: run one scene file and print its report")
    return p


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if args.shots < 1 or args.workers < 1 or args.chunk < 1:
        print("fuzz: --shots, --workers and --chunk must be positive", file=sys.stderr)
        return 2
    if args.check or args.shrink:
        d = json.loads(Path(args.check or args.shrink).read_text())
        if args.shrink:
            d = shrink_case(d, args.invariant, log=lambda m: print(m, file=sys.stderr))
            print(json.dumps(d, indent=1))
        rep, _ = run_case(d)
        if rep.violations:
            print(f"status {rep.status}, {rep.n_events} events; {len(rep.violations)} violation(s):", file=sys.stderr)
            for name, msg in rep.violations.items():
                print(f"  {name}: {msg}", file=sys.stderr)
            return 1
        print(f"status {rep.status}, {rep.n_events} events; no violations")
        return 0
    out = Path(args.out)
    if not 0.0 <= args.spin <= 1.0 or not 0.0 <= args.models <= 1.0:
        print("fuzz: --spin and --models are shares of the shots, in [0, 1]", file=sys.stderr)
        return 2
    if args.preset is not None and args.preset not in PRESETS:
        print(f"fuzz: --preset: unknown preset {args.preset!r}; use one of {', '.join(PRESETS)}", file=sys.stderr)
        return 2
    chunks = [(args.seed, lo, min(lo + args.chunk, args.start + args.shots), args.solver, args.max_time,
               args.max_events, args.keep, args.spin, args.models, args.preset, args.table)
              for lo in range(args.start, args.start + args.shots, args.chunk)]
    total = Stats()
    _warm_up()
    t0 = time.perf_counter()
    last_print = t0
    saved: list[Path] = []
    if args.workers == 1:
        results = map(_run_chunk, chunks)
        pool = None
    else:
        ctx = mp.get_context("fork" if sys.platform != "win32" else "spawn")
        pool = ctx.Pool(args.workers, initializer=_warm_up)
        results = pool.imap_unordered(_run_chunk, chunks)
    try:
        for st in results:
            saved += save_failures(st.failures, out) if st.failures else []
            st.failures = []
            total.merge(st)
            now = time.perf_counter()
            if now - last_print > 30 or total.shots == args.shots:
                last_print = now
                print(f"[fuzz] {total.shots}/{args.shots} shots, {now - t0:.0f} s, {total.failing_shots} failing "
                      f"({dict(total.violation_shots)})", file=sys.stderr, flush=True)
    finally:
        if pool is not None:
            pool.close()
            pool.join()
    wall = time.perf_counter() - t0
    what = f"preset {args.preset}" if args.preset else f"spin share {args.spin:g}, models share {args.models:g}"
    what += f", table {args.table}"
    print(f"fuzz: seed {args.seed}, solver {args.solver}, {what}, workers {args.workers}")
    print(format_summary(total, wall))
    if saved:
        print(f"failing cases: {len(saved)} scene files under {out}/ (index: {out}/violations.jsonl); "
              f"reproduce with `billiards-sim FILE --events`")
    else:
        print("failing cases: none")
    return 1 if total.failing_shots else 0


