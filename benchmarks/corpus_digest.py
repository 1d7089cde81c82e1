"""A SHA-256 digest of a fixed corpus of shots and vector-env steps, to compare two versions of the code bit for bit.

``python -m benchmarks.corpus_digest [--shots 30000] [--workers 2] [--env-steps 200]`` from the repository root
prints one digest per part and one over everything. Run it at two commits (e.g. in a scratch ``git worktree``): the
same digest says the two simulate every shot of the corpus to the same bits.

The corpus:

- ``shots``: random scenes of the fuzz generator (:func:`billiards_env.fuzz.generator.random_scene`, shot ``i`` of
  seed 36), all on the exact solver, cycling through six kinds: the capture-pocket table with the rolling and drag
  laws, with the spin model, with the spin model and the optional collision models, under the pooltool preset; the
  jaw tables with the rolling and drag laws and with the spin model (half of them with the optional models). Each
  shot adds its status, end time, final positions, velocities, angular velocities, on-table flags, pockets, pocket
  times and its whole event log (time, kind, ball, other, speed) to the digest.
- ``vector``: the native vector env of a few pot-task ids (64 tables, seeded, random actions), stepped on one
  thread and on two: every observation, reward, termination, truncation and info array.
"""
from __future__ import annotations

import argparse
import hashlib
import multiprocessing as mp
import time
from typing import Any

import numpy as np

#: The corpus's fuzz seed (shot ``i`` is :func:`~billiards_env.fuzz.generator.shot_rng` ``(SEED, i)``).
SEED = 36
#: The kinds of shot, cycled by shot index: (table, spin share, models share, preset).
KINDS: tuple[tuple[str, float, float, str | None], ...] = (
    ("rect", 0.0, 0.0, None),
    ("rect", 1.0, 0.0, None),
    ("rect", 1.0, 1.0, None),
    ("rect", 1.0, 0.0, "pooltool"),
    ("jaws", 0.0, 0.0, None),
    ("jaws", 1.0, 0.5, None),
)
#: The native vector env ids of the ``vector`` part (positions observation, several observations, spin actions).
VECTOR_IDS = ("BilliardsOneBall-v0", "BilliardsThreeBalls-v0", "BilliardsRack-v0")


def _feed(h: Any, *arrays: Any) -> None:
    """Add arrays (their dtype, shape and bytes) to the hash ``h``."""
    for a in arrays:
        a = np.ascontiguousarray(np.asarray(a))
        h.update(str(a.dtype).encode())
        h.update(str(a.shape).encode())
        h.update(a.tobytes())


def shot_digest(index: int) -> bytes:
    """The digest of shot ``index`` of the corpus (its final state and event log)."""
    from billiards_env.fuzz.generator import NumpySource, random_scene, shot_rng
    from billiards_env.physics.scene import Scene

    table, spin, models, preset = KINDS[index % len(KINDS)]
    rng = shot_rng(SEED, index)
    scene = random_scene(NumpySource(rng), solver="exact", max_time=60.0, spin=spin, models=models, preset=preset,
                         table=table)
    h = hashlib.sha256()
    try:
        res = Scene.from_dict(scene).run()
    except Exception as exc:  # a scene the parser refuses is part of the corpus too (the same refusal)
        h.update(f"error {type(exc).__name__}: {exc}".encode())
        return h.digest()
    b = res.balls
    h.update(f"{res.status} {res.n_events}".encode())
    _feed(h, np.float64(res.time), b.pos, b.vel, b.on_table, res.pocket, res.pocketed_at)
    if getattr(b, "ang", None) is not None:
        _feed(h, b.ang)
    ev = res.events
    _feed(h, ev.time, ev.kind, ev.ball, ev.other, ev.speed)
    return h.digest()


def _chunk(bounds: tuple[int, int]) -> list[bytes]:
    lo, hi = bounds
    return [shot_digest(i) for i in range(lo, hi)]


def corpus_digest(shots: int, workers: int) -> tuple[str, dict[str, int]]:
    """The digest of the first ``shots`` shots (in index order, whatever the worker count) and the event count."""
    step = 500
    bounds = [(lo, min(lo + step, shots)) for lo in range(0, shots, step)]
    if workers > 1:
        with mp.get_context("spawn").Pool(workers) as pool:
            parts = pool.map(_chunk, bounds)
    else:
        parts = [_chunk(b) for b in bounds]
    h = hashlib.sha256()
    for part in parts:
        for d in part:
            h.update(d)
    return h.hexdigest(), {"shots": shots}


def vector_digest(steps: int, threads: int, num_envs: int = 64) -> str:
    """The digest of ``steps`` steps of the native vector env of every :data:`VECTOR_IDS` id on ``threads``."""
    import gymnasium as gym

    import billiards_env  # noqa: F401  (registers the ids)

    h = hashlib.sha256()
    for env_id in VECTOR_IDS:
        env = gym.make_vec(env_id, num_envs=num_envs, vectorization_mode="vector_entry_point", threads=threads)
        obs, info = env.reset(seed=7)
        _feed(h, obs)
        for key in sorted(info):
            _feed(h, np.asarray(info[key]))
        rng = np.random.default_rng(11)
        for _ in range(steps):
            act = rng.uniform(-1.0, 1.0, env.action_space.shape).astype(env.action_space.dtype)
            obs, rew, term, trunc, info = env.step(act)
            _feed(h, obs, rew, term, trunc)
            for key in sorted(info):
                val = info[key]
                if isinstance(val, np.ndarray) and val.dtype == object:
                    h.update(repr(val.tolist()).encode())
                elif isinstance(val, dict):
                    for k2 in sorted(val):
                        _feed(h, np.asarray(val[k2]))
                else:
                    _feed(h, np.asarray(val))
        env.close()
    return h.hexdigest()


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.corpus_digest", description=__doc__.split("\n\n")[0])
    ap.add_argument("--shots", type=int, default=30_000, help="shots of the corpus (default 30000)")
    ap.add_argument("--workers", type=int, default=2, help="worker processes for the shots (default 2)")
    ap.add_argument("--env-steps", type=int, default=200, help="vector-env steps per id (0: leave that part out)")
    args = ap.parse_args(argv)
    t = time.perf_counter()
    shots, _ = corpus_digest(args.shots, args.workers)
    print(f"shots  {args.shots:>7}  {shots}  ({time.perf_counter() - t:.1f} s)", flush=True)
    h = hashlib.sha256(shots.encode())
    if args.env_steps > 0:
        for threads in (1, 2):
            t = time.perf_counter()
            d = vector_digest(args.env_steps, threads)
            print(f"vector threads={threads}  {d}  ({time.perf_counter() - t:.1f} s)", flush=True)
            h.update(d.encode())
    print(f"all    {h.hexdigest()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
