"""What the ``candidates_path`` observation alone allows on the one-ball tables: a hand-written rule, no learning.

47 of the one-ball SAC agent's 59 failures were scratches after potting: the cue ball, deflected along the tangent
line, runs on into a pocket, which its observation did not show. The ``candidates_path`` observation
(:class:`billiards_env.envs.observations.CuePathFeatures`) states, per candidate shot and offset across the pocket's
window, the interval of the ``power`` dim that pots the ball and leaves the cue ball on the table; the
``candidates_aim`` action type (:class:`billiards_env.envs.actions.CandidateAim`) plays exactly those offsets.
:func:`interval_action` plays the widest interval at its middle: ``python -m agents.path_rule`` prints its pocket
rate, the ceiling of what the observation alone states (the main job's agent learns from the same types).
"""
from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np

from billiards_env.envs.window_offsets import OFFSETS, PATH_FEATURES


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
    """``python -m agents.path_rule``: the pocket rate of :func:`interval_action` on the one-ball tables."""
    import argparse

    import billiards_env  # noqa: F401

    p = argparse.ArgumentParser(prog="python -m agents.path_rule", description=main.__doc__)
    p.add_argument("--episodes", type=int, default=1000)
    p.add_argument("--seed", type=int, default=100_000)
    p.add_argument("--slots", type=int, default=7)
    args = p.parse_args(argv)
    env = gym.make("BilliardsOneBall-v0", action_type="candidates_aim", observation_type="candidates_path",
                   candidate_slots=args.slots, candidate_speed_factor=3.0)
    ok = 0
    for k in range(args.episodes):
        obs, _ = env.reset(seed=args.seed + k)
        _, _, _, _, info = env.step(interval_action(obs, args.slots))
        ok += bool(info["is_success"])
    print(f"interval rule on the candidates_path observation: {ok}/{args.episodes} = {100 * ok / args.episodes:.1f}% "
          f"(tables {args.seed}..{args.seed + args.episodes - 1})")
    return 0


__all__ = ["interval_action", "main"]


if __name__ == "__main__":
    import sys

    sys.exit(main())
