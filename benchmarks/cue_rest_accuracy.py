"""How well the ``candidates_position`` observation's closed form (billiards_env/physics/cue_rest.py) states what the
engine does: every grid point of every pot slot of the 9-ball tables met in random play (spin model), simulated by
the engine (:func:`billiards_env.physics.batch.run_shots`: the same shot, speed and tip), compared with the map's
rest point, scratch flag and pot flag.

    python -m benchmarks.cue_rest_accuracy --games 12

Prints the rest-point error split by what the engine's shot met (the object ball only, with or without cushions; a
second collision; another ball hit first, the slot's path being blocked: the last two not modelled), and the
agreement of the scratch and pot flags.
"""
from __future__ import annotations

import argparse
import math
import sys
from typing import Any, Sequence

import numpy as np


def measure(games: int, seed: int = 0) -> dict[str, Any]:
    """The comparison over ``games`` random-play games (seeds ``seed + k``)."""
    import gymnasium as gym

    import billiards_env  # noqa: F401
    from billiards_env.envs.candidates import candidate_slots
    from billiards_env.envs.position import POINT_VALUES, POWERS, TOPS, position_features
    from billiards_env.physics.batch import run_shots
    from billiards_env.physics.codes import EVENT_KINDS
    from billiards_env.players.geometry import COL_ANGLE, COL_SPEED, COL_TARGET

    env = gym.make("Billiards9Ball-v0", action_type="candidates", observation_type="candidates_position",
                   friction="spin", spin_action=True, opponent="geometric")
    u = env.unwrapped
    ot = u.observation_type
    collision = EVENT_KINDS.index("collision")
    rng = np.random.default_rng(seed)
    rows: list[tuple[int, int, float]] = []  # (collisions, cue cushions, rest error) where neither scratched
    scratch: list[tuple[bool, bool]] = []
    pots: list[tuple[bool, bool]] = []
    for k in range(games):
        env.reset(seed=seed + k)
        done = False
        while not done:
            st = u.table_state
            c = candidate_slots(st, ot.n_slots, ot.speed_range)
            if c.rows is not None and not c.in_hand and not c.break_shot and c.rows.shape[0]:
                feats = position_features(st, c, ot.n_slots, ot.speed_range, ot.log_factor, ot.max_tip)
                for i in range(min(c.rows.shape[0], ot.n_slots - 1)):
                    r = c.rows[i]
                    speeds = [min(max(r[COL_SPEED] * math.exp(p * ot.log_factor), ot.speed_range[0]),
                                  ot.speed_range[1]) for p in POWERS for _ in TOPS]
                    tops = [t * ot.max_tip for _ in POWERS for t in TOPS]
                    res = run_shots(u.simulator, u.balls, [r[COL_ANGLE]] * len(speeds), speeds, top=tops)
                    f = feats[i].reshape(-1, POINT_VALUES)
                    for g in range(len(speeds)):
                        eng_scratch = bool(res.pocket[g, 0] >= 0)
                        scratch.append((bool(f[g, 1] > 0.5), eng_scratch))
                        pots.append((bool(f[g, 0] > 0.5), bool(res.pocket[g, int(r[COL_TARGET])] >= 0)))
                        if not eng_scratch and f[g, 1] < 0.5:
                            err = math.hypot(f[g, 2] * u.table.length - res.pos[g, 0, 0],
                                             f[g, 3] * u.table.width - res.pos[g, 0, 1])
                            hit = int(res.first_contact[g]) == int(r[COL_TARGET])
                            n = int(res.event_counts[g, collision]) if hit else -1  # -1: another ball first
                            rows.append((n, int(res.cushions[g, 0]), err))
            _, _, term, trunc, _ = env.step(rng.uniform(-0.3, 0.3, env.action_space.shape).astype(np.float32))
            done = term or trunc
    env.close()
    e = np.array(rows, dtype=float).reshape(-1, 3)
    sc = np.array(scratch, dtype=bool).reshape(-1, 2)
    po = np.array(pots, dtype=bool).reshape(-1, 2)

    def part(mask: np.ndarray) -> dict[str, Any]:
        return {"points": int(mask.sum()), "median_error_m": float(np.median(e[mask, 2])) if mask.any() else None,
                "within_1mm": float((e[mask, 2] < 1e-3).mean()) if mask.any() else None}

    once = (e[:, 0] >= 0) & (e[:, 0] <= 1)
    return {"games": games, "grid_points": int(len(sc)),
            "one_collision_no_cushion": part(once & (e[:, 1] == 0)),
            "one_collision_cushions": part(once & (e[:, 1] > 0)),
            "second_collision": part(e[:, 0] > 1),
            "another_ball_first": part(e[:, 0] < 0),
            "scratch_agreement": float((sc[:, 0] == sc[:, 1]).mean()) if len(sc) else None,
            "scratches_map_engine_both": [int(sc[:, 0].sum()), int(sc[:, 1].sum()), int((sc[:, 0] & sc[:, 1]).sum())],
            "pot_agreement": float((po[:, 0] == po[:, 1]).mean()) if len(po) else None}


def main(argv: Sequence[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks.cue_rest_accuracy", description=__doc__.split("\n\n")[0])
    p.add_argument("--games", type=int, default=12)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--quick", action="store_true", help="a short run (1 game)")
    args = p.parse_args(argv)
    if args.quick:
        args.games = 1
    out = measure(args.games, args.seed)
    print(f"{out['grid_points']} grid points of {out['games']} games")
    for key in ("one_collision_no_cushion", "one_collision_cushions", "second_collision", "another_ball_first"):
        v = out[key]
        if v["points"]:
            print(f"  {key}: {v['points']} points (no scratch), median rest error {v['median_error_m']:.4f} m, "
                  f"{100 * v['within_1mm']:.0f}% within 1 mm")
    print(f"  scratch flag agrees on {100 * out['scratch_agreement']:.1f}% (map / engine / both: "
          f"{out['scratches_map_engine_both']}); pot flag on {100 * out['pot_agreement']:.1f}%")
    return 0


if __name__ == "__main__":
    sys.exit(main())
