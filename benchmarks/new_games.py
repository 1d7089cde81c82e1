"""The players of snooker and three-cushion, measured, from the repository root:

    python -m benchmarks.new_games [--three-cushion N] [--frames F] [--match-frames M] [--seed S] [--json out.json]

- three-cushion: the search player (:func:`billiards_env.players.three_cushion.three_cushion_shot`, spin model) from
  ``N`` random positions of the three balls: how often it finds a point, how often the shot scores when played
  exactly and under FastFiz-like shot noise (angle 0.125 deg, speed 3.75 %, tip 0.5 mm), and its decision time;
  the geometric player's scoring rate from the same positions (spin model and rolling law);
- snooker: ``F`` frames of each player against itself from the break-off (rolling model), with and without that
  noise: breaks (a visit's points; the mean over visits that scored, and the highest), points per visit, and the
  decision time; with ``--match-frames M``, ``M`` frames of search against geometric under that noise.

The figures print as a table (and go to ``--json``). Decision times are wall-clock on the machine as it is
(the median of the decisions); compare players within one run.
"""
from __future__ import annotations

import argparse
import json
import math
import time
from typing import Any

import numpy as np

from billiards_env.physics import Balls, Physics, Simulator
from billiards_env.games.carom_layout import CAROM_IDS
from billiards_env.games.snooker_layout import snooker_balls
from billiards_env.physics.layout import place_random
from billiards_env.physics.table import CAROM_BALL_MASS, CAROM_BALL_RADIUS, carom_table, snooker_table
from billiards_env.players.referee import noisy, snooker_turn
from billiards_env.players.snooker import snooker_geometric_shot, snooker_search_shot
from billiards_env.players.three_cushion import three_cushion_geometric_shot, three_cushion_shot
from billiards_env.rules.snooker import Snooker, snooker_values
from billiards_env.rules.three_cushion import summarize_carom

#: FastFiz-like shot noise: angle (rad), speed (relative), tip (ball radii: 0.5 mm on a 61.5 mm ball).
FASTFIZ = (math.radians(0.125), 0.0375, 0.0005 / CAROM_BALL_RADIUS)


def random_carom(rng: np.random.Generator, table) -> Balls:
    """The three carom balls at uniformly random places (not touching each other)."""
    r = CAROM_BALL_RADIUS
    pos = np.zeros((3, 2))
    region = (r, table.length - 2 * r, r, table.width - 2 * r)
    place_random(rng, pos, [0, 1, 2], [region] * 3, [], [], 0.0, 2 * r + 1e-3)
    return Balls.from_positions(pos, ids=CAROM_IDS, radius=r, mass=CAROM_BALL_MASS)


def three_cushion(n: int, seed: int) -> dict[str, Any]:
    table = carom_table()
    sim = Simulator(table, Physics(friction="spin"))
    rng = np.random.default_rng(seed)
    noise_rng = np.random.default_rng(seed + 1)
    three_cushion_shot(sim, random_carom(np.random.default_rng(seed + 10**6), table), 0, 1, 2)  # compile
    found = scored = scored_noisy = 0
    times, sims = [], []
    for _ in range(n):
        balls = random_carom(rng, table)
        t0 = time.perf_counter()
        shot = three_cushion_shot(sim, balls, 0, 1, 2)
        times.append(time.perf_counter() - t0)
        sims.append(shot.simulated)
        found += shot.point
        for noise, count in ((None, "exact"), (FASTFIZ, "noisy")):
            a, v, sd, tp = noisy(shot.angle, shot.speed, shot.side, shot.top, noise_rng if noise else None,
                                 noise or (0.0, 0.0, 0.0))
            res = sim.run(balls.strike(0, a, v, sd, tp), validate=False)
            ev = np.stack([res.events.kind, res.events.ball, res.events.other], axis=1)
            point = summarize_carom(ev, (0, 1, 2)).point
            if count == "exact":
                scored += point
            else:
                scored_noisy += point
    return {"positions": n, "found": found / n, "scored": scored / n, "scored_fastfiz_noise": scored_noisy / n,
            "decision_s_median": float(np.median(times)), "decision_s_mean": float(np.mean(times)),
            "shots_simulated_median": float(np.median(sims))}


def three_cushion_geometric(n: int, seed: int) -> dict[str, Any]:
    """The geometric player from the same random positions, under the spin model and the rolling law."""
    table = carom_table()
    out: dict[str, Any] = {"positions": n}
    for law in ("spin", "rolling"):
        sim = Simulator(table, Physics(friction=law))
        rng = np.random.default_rng(seed)
        scored, times = 0, []
        for _ in range(n):
            balls = random_carom(rng, table)
            t0 = time.perf_counter()
            shot = three_cushion_geometric_shot(balls, table, sim.physics, 0, 1, 2, sim=sim)
            times.append(time.perf_counter() - t0)
            spin = {"side": shot.side, "top": shot.top} if law == "spin" else {}
            res = sim.run(balls.strike(0, shot.angle, shot.speed, **spin), validate=False)
            ev = np.stack([res.events.kind, res.events.ball, res.events.other], axis=1)
            scored += summarize_carom(ev, (0, 1, 2)).point
        out[law] = {"scored": scored / n, "decision_s_median": float(np.median(times))}
    return out


def snooker_frames(player: str | tuple[str, str], frames: int, seed: int, noise: tuple[float, float, float],
                   max_shots: int = 400) -> dict[str, Any]:
    """``frames`` frames between ``player`` (one name: against itself; a pair: player 0 and player 1, who
    alternate breaking off), each from the break-off to its end (or ``max_shots``)."""
    names = (player, player) if isinstance(player, str) else tuple(player)
    table = snooker_table()
    sim = Simulator(table, Physics())
    rules = Snooker()
    breaks, visits, times = [], [], []
    by_player: dict[int, list[int]] = {0: [], 1: []}
    won = [0, 0]
    shots_total = 0
    for f in range(frames):
        rng = np.random.default_rng(seed + f)
        noise_rng = np.random.default_rng(seed + 1000 + f)
        balls = snooker_balls(table)
        values = snooker_values(balls.ids)
        state = rules.initial_state(f % 2)
        snk = False
        windows: dict = {}
        for _ in range(max_shots):
            t0 = time.perf_counter()
            if names[state.shooter] == "search":
                shot = snooker_search_shot(balls, sim, state, values, snookered=snk, rules=rules,
                                           angle_noise=noise[0], speed_noise=noise[1], rng=rng, windows=windows)
            else:
                shot = snooker_geometric_shot(balls, sim, state, values, snookered=snk, rules=rules,
                                              sigma=max(noise[0], 0.003))
            times.append(time.perf_counter() - t0)
            turn = snooker_turn(sim, balls, values, state, shot, rules, snk, noise_rng, noise)
            shots_total += 1
            c = turn.call
            if c.turn_over or c.frame_over or c.replace:
                visits.append(c.break_points)
                if c.break_points > 0:
                    breaks.append(c.break_points)
                    by_player[c.shooter].append(c.break_points)
            state, snk = turn.state, turn.snookered
            if state.frame_over:
                won[state.winner] += 1
                break
    return {"player": "/".join(names) if names[0] != names[1] else names[0], "frames": frames,
            "noise": list(noise), "shots": shots_total, "mean_break": float(np.mean(breaks)) if breaks else 0.0,
            "highest_break": int(max(breaks, default=0)), "breaks": len(breaks),
            "points_per_visit": float(np.mean(visits)) if visits else 0.0,
            "decision_s_median": float(np.median(times)), "frames_won": won,
            "mean_break_by_player": [float(np.mean(by_player[p])) if by_player[p] else 0.0 for p in (0, 1)]}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.new_games", description=__doc__.split("\n\n")[0])
    ap.add_argument("--three-cushion", type=int, default=200, help="random three-cushion positions (0: skip)")
    ap.add_argument("--frames", type=int, default=3, help="snooker frames per player and noise (0: skip)")
    ap.add_argument("--players", nargs="+", default=["geometric", "search"], choices=["geometric", "search"])
    ap.add_argument("--match-frames", type=int, default=0,
                    help="snooker frames of search (player 0) against geometric (player 1), with shot noise")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--json", default=None, help="write the figures to this file")
    args = ap.parse_args(argv)
    out: dict[str, Any] = {}
    if args.three_cushion:
        r = three_cushion(args.three_cushion, args.seed)
        out["three_cushion_search"] = r
        print(f"three-cushion search, {r['positions']} random positions (spin model): point found "
              f"{r['found']:.1%}, scored {r['scored']:.1%} (exact), {r['scored_fastfiz_noise']:.1%} (FastFiz-like "
              f"noise); decision {r['decision_s_median'] * 1e3:.0f} ms median ({r['shots_simulated_median']:.0f} "
              "shots simulated)")
        g = three_cushion_geometric(args.three_cushion, args.seed)
        out["three_cushion_geometric"] = g
        print(f"three-cushion geometric, the same positions: scored {g['spin']['scored']:.1%} under the spin model, "
              f"{g['rolling']['scored']:.1%} under the rolling law; decision "
              f"{g['spin']['decision_s_median'] * 1e3:.0f} ms median")
    if args.frames:
        out["snooker"] = []
        print("| snooker player | noise | frames | shots | breaks | mean break | highest | points/visit | decision |")
        print("|---|---|---|---|---|---|---|---|---|")
        for player in args.players:
            for noise, label in (((0.0, 0.0, 0.0), "none"), ((FASTFIZ[0], FASTFIZ[1], 0.0), "FastFiz-like")):
                r = snooker_frames(player, args.frames, args.seed, noise)
                out["snooker"].append(r)
                print(f"| {player} | {label} | {r['frames']} | {r['shots']} | {r['breaks']} | {r['mean_break']:.1f} "
                      f"| {r['highest_break']} | {r['points_per_visit']:.1f} | {r['decision_s_median'] * 1e3:.0f} ms |")
    if args.match_frames:
        r = snooker_frames(("search", "geometric"), args.match_frames, args.seed, (FASTFIZ[0], FASTFIZ[1], 0.0))
        out["snooker_match"] = r
        print(f"snooker, search against geometric, {r['frames']} frames with FastFiz-like noise: frames won "
              f"{r['frames_won'][0]}-{r['frames_won'][1]}, mean break {r['mean_break_by_player'][0]:.1f} against "
              f"{r['mean_break_by_player'][1]:.1f}")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as fh:
            json.dump(out, fh, indent=2)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
