"""Decision time of trained 9-ball players in one process, on the same positions: every player decides at every
position of games on the league's two-player env (spin model, olympiad noise; the position played on is one of the
players' choices at random), so their times are ratios measured together.

    python -m benchmarks.decision_time --games 60 runs/<sac run>/best_model.zip scorer:runs/scorer.pt

A player is an SB3 model zip or run folder in 9-ball types, ``scorer:<file>`` (agents.scorer) or ``position_rule``.
Prints per player the median and mean wall time of a decision (observation, policy, action) and of its observation
alone; the table state's memo is cleared before each, so every decision computes its candidate list afresh.
"""
from __future__ import annotations

import argparse
import sys
import time
from typing import Any, Sequence

import numpy as np


def _player(spec: str) -> Any:
    from agents.league import load_player

    return load_player(spec, 0, "nine_ball")[1]


def measure(specs: Sequence[str], games: int, seed: int = 0) -> dict[str, dict[str, float]]:
    """``{player name: {"median_ms", "mean_ms", "obs_median_ms", "decisions"}}`` over ``games`` games."""
    import torch

    from billiards_env.multi import nine_ball_v0

    torch.set_num_threads(1)
    players = [_player(s) for s in specs]
    env = nine_ball_v0.env(friction="spin", spin_action=True, noise="olympiad")
    raw = env.unwrapped
    times: list[list[float]] = [[] for _ in players]
    obs_t: list[list[float]] = [[] for _ in players]
    rng = np.random.default_rng(seed)
    for g in range(games):
        env.reset(seed=seed + g)
        for _ in env.agent_iter():
            obs, _, term, trunc, _ = env.last()
            if term or trunc:
                env.step(None)
                continue
            ge = raw.game_env
            u = ge.unwrapped
            acts = []
            for i, p in enumerate(players):
                p.prepare(u.table_state, u.action_type)
                u.table_state.changed()
                t0 = time.perf_counter()
                p.observation_type.observe(u.table_state)
                t1 = time.perf_counter()
                u.table_state.changed()
                t2 = time.perf_counter()
                acts.append(p.act(u.table_state, obs, u.action_type))
                t3 = time.perf_counter()
                times[i].append(t3 - t2)
                obs_t[i].append(t1 - t0)
            env.step(acts[int(rng.integers(len(acts)))])
    env.close()
    out = {}
    for p, t, o in zip(players, times, obs_t):
        t, o = np.asarray(t[5:]), np.asarray(o[5:])  # the first decisions warm up
        out[p.name] = {"median_ms": 1e3 * float(np.median(t)), "mean_ms": 1e3 * float(t.mean()),
                       "obs_median_ms": 1e3 * float(np.median(o)), "decisions": int(len(t))}
    return out


def main(argv: Sequence[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks.decision_time", description=__doc__.split("\n\n")[0])
    p.add_argument("players", nargs="+")
    p.add_argument("--games", type=int, default=60)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--quick", action="store_true", help="a short run (1 game)")
    args = p.parse_args(argv)
    if args.quick:
        args.games = 1
    for name, r in measure(args.players, args.games, args.seed).items():
        print(f"{name}: decision {r['median_ms']:.3f} ms median, {r['mean_ms']:.3f} ms mean; observation "
              f"{r['obs_median_ms']:.3f} ms median ({r['decisions']} decisions)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
