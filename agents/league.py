"""A league: head-to-head matches between players on seeded racks, win rates with 95% intervals, an Elo table.

    python -m agents.league --game nine_ball --players random geometric search --games 40
    python -m agents.league --game eight_ball --players geometric search --games 40 --noise 0.005
    python -m agents.league --game nine_ball --players geometric runs/nine_ball/best_model.zip --games 100

A player is a baseline name (``random``, ``geometric``, ``search``: :mod:`billiards_env.players`) or a trained SB3
model (a run folder or a model zip, played with deterministic actions). Every pair plays ``--games`` games on the
two-player env (:mod:`billiards_env.multi`), seats swapped every game so each breaks as often as the other; game
``k`` of a match uses the rack of seed ``seed + k``, so every pair meets on the same racks. ``--noise`` plays with
shot noise (the angle's standard deviation in rad; the speed's is 3x it, relative): the FastFiz-like tournament
setting. The report: each pair's wins, the row player's win rate with its Wilson 95% interval, break-and-run
rate (the breaker wins before the opponent shoots), and Elo ratings fitted to all games (Bradley-Terry maximum
likelihood, random = 1000 when present, else the mean at 1500).
"""
from __future__ import annotations

import argparse
import itertools
import json
import math
import sys
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from billiards_env.players import BASELINES, make_player

from .evaluate import wilson_interval

GAMES = {"nine_ball": "nine_ball_v0", "eight_ball": "eight_ball_v0"}


@dataclass
class PairResult:
    """The games between ``a`` and ``b`` (names), from ``a``'s side."""

    a: str
    b: str
    games: int
    wins_a: int
    wins_b: int
    unfinished: int
    break_and_runs: int  #: games won by the breaker before the opponent took a shot
    seconds: float
    reasons: dict[str, int] = field(default_factory=dict)  #: how the games ended

    @property
    def rate_a(self) -> float:
        return self.wins_a / max(self.games, 1)


def load_player(spec: str, seed: int = 0) -> tuple[str, Any]:
    """``(name, policy)`` for a baseline name or a trained model (run folder or zip)."""
    if spec in BASELINES:
        return spec, make_player(spec, seed=seed)
    from .evaluate import resolve_model
    from .train import algo_class

    model_zip, run_dir = resolve_model(spec)
    algo = "sac"
    if run_dir is not None and (run_dir / "run.json").exists():
        algo = json.loads((run_dir / "run.json").read_text()).get("algo", "sac")
    model = algo_class(algo).load(str(model_zip), device="cpu")
    return (run_dir.name if run_dir is not None else model_zip.stem), model


def play_pair(game: str, a: tuple[str, Any], b: tuple[str, Any], n_games: int, seed: int,
              env_kwargs: dict[str, Any]) -> PairResult:
    """``n_games`` games of ``a`` against ``b`` (seats swapped every game)."""
    import importlib

    from billiards_env.multi import play_match

    module = importlib.import_module(f"billiards_env.multi.{GAMES[game]}")
    t0 = time.perf_counter()
    res = play_match(lambda: module.env(**env_kwargs), [a[1], b[1]], n_games, seed=seed)
    reasons: dict[str, int] = {}
    bnr = 0
    for g in res.games:
        reasons[g.reason] = reasons.get(g.reason, 0) + 1
        breaker = g.seats[0]
        if g.winner == breaker and g.shots[1 - breaker] == 0:
            bnr += 1
    wins = res.wins
    return PairResult(a[0], b[0], n_games, wins[0], wins[1], res.unfinished, bnr, time.perf_counter() - t0, reasons)


def fit_elo(names: Sequence[str], pairs: Sequence[PairResult], anchor: str | None = "random",
            iterations: int = 2000) -> dict[str, float]:
    """Elo ratings from all games (Bradley-Terry maximum likelihood by the MM algorithm; a draw or an unfinished
    game counts half to each). ``anchor`` gets 1000 if present, else the mean is 1500. A player who won (or lost)
    every game has no finite rating: the fit is regularised by one virtual draw against every other player."""
    idx = {n: k for k, n in enumerate(names)}
    n = len(names)
    w = np.zeros((n, n))  # w[i, j]: games i won against j (halves for unfinished)
    for p in pairs:
        i, j = idx[p.a], idx[p.b]
        w[i, j] += p.wins_a + 0.5 * p.unfinished
        w[j, i] += p.wins_b + 0.5 * p.unfinished
    games = w + w.T
    w = w + 0.5 * (1 - np.eye(n))  # one virtual draw per pair
    games = games + (1 - np.eye(n))
    gamma = np.ones(n)
    for _ in range(iterations):
        wins = w.sum(axis=1)
        denom = np.array([sum(games[i, j] / (gamma[i] + gamma[j]) for j in range(n) if j != i) for i in range(n)])
        new = wins / np.maximum(denom, 1e-300)
        new /= np.exp(np.mean(np.log(new)))
        if np.allclose(new, gamma, rtol=1e-12, atol=0):
            gamma = new
            break
        gamma = new
    elo = 400.0 * np.log10(gamma)
    base = 1000.0 - elo[idx[anchor]] if anchor in idx else 1500.0 - elo.mean()
    return {name: float(elo[idx[name]] + base) for name in names}


def markdown(game: str, pairs: Sequence[PairResult], elo: dict[str, float], info: dict[str, Any]) -> str:
    lines = [f"# League: {game.replace('_', '-')}", "",
             f"{info['games']} games per pair on seeded racks (seed {info['seed']}), seats swapped every game; "
             f"shot noise: angle {info['noise']} rad, speed {3 * info['noise']:.3g} relative. Command: "
             f"`{info['command']}`. {info['machine']}", "",
             "| player A | player B | A wins | B wins | unfinished | A win rate [95% CI] | break-and-run | time |",
             "|---|---|---|---|---|---|---|---|"]
    for p in pairs:
        lo, hi = wilson_interval(p.wins_a, p.games)
        lines.append(f"| {p.a} | {p.b} | {p.wins_a} | {p.wins_b} | {p.unfinished} | {100 * p.rate_a:.0f}% "
                     f"[{100 * lo:.0f}, {100 * hi:.0f}] | {100 * p.break_and_runs / p.games:.0f}% | "
                     f"{p.seconds:.0f} s |")
    lines += ["", "| player | Elo |", "|---|---|"]
    for name, r in sorted(elo.items(), key=lambda kv: -kv[1]):
        lines.append(f"| {name} | {r:.0f} |")
    lines += ["", "How the games ended:", ""]
    for p in pairs:
        ends = ", ".join(f"{k}: {v}" for k, v in sorted(p.reasons.items(), key=lambda kv: -kv[1]))
        lines.append(f"- {p.a} vs {p.b}: {ends}")
    return "\n".join(lines) + "\n"


def run_league(game: str, specs: Sequence[str], n_games: int, seed: int, noise: float, out: Path | None,
               env_kwargs: dict[str, Any] | None = None, quiet: bool = False) -> dict[str, Any]:
    """Every pair of ``specs`` plays ``n_games``; returns (and writes under ``out``) the report."""
    say = (lambda *a: None) if quiet else (lambda *a: print(*a, flush=True))
    kw = dict(env_kwargs or {})
    if noise > 0:
        kw.setdefault("angle_noise", noise)
        kw.setdefault("speed_noise", 3 * noise)
    players = [load_player(s, seed) for s in specs]
    pairs = []
    for a, b in itertools.combinations(players, 2):
        p = play_pair(game, a, b, n_games, seed, kw)
        lo, hi = wilson_interval(p.wins_a, p.games)
        say(f"{p.a} vs {p.b}: {p.wins_a}-{p.wins_b} ({p.unfinished} unfinished), {p.a} wins "
            f"{100 * p.rate_a:.0f}% [{100 * lo:.0f}, {100 * hi:.0f}], {p.seconds:.0f} s")
        pairs.append(p)
    names = [p[0] for p in players]
    elo = fit_elo(names, pairs)
    from benchmarks.common import machine_info, machine_markdown

    command = "python -m agents.league " + " ".join(sys.argv[1:]) if "league" in sys.argv[0] \
        else f"agents.league.run_league({game!r}, {list(specs)!r}, {n_games}, {seed}, {noise})"
    info = {"game": game, "games": n_games, "seed": seed, "noise": noise, "env_kwargs": kw, "command": command,
            "machine": machine_markdown(machine_info())}
    report = {"info": info, "pairs": [asdict(p) for p in pairs], "elo": elo}
    md = markdown(game, pairs, elo, info)
    say(md)
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
        (out / "league.json").write_text(json.dumps(report, indent=2))
        (out / "league.md").write_text(md)
    return report


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m agents.league", description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog=__doc__.split("\n\n", 1)[1])
    p.add_argument("--game", choices=sorted(GAMES), default="nine_ball")
    p.add_argument("--players", nargs="+", default=["random", "geometric", "search"],
                   help="baseline names or trained model paths")
    p.add_argument("--games", type=int, default=40, help="games per pair")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--noise", type=float, default=0.0, help="angle noise (rad); speed noise is 3x (relative)")
    p.add_argument("--out", type=Path, default=None, help="folder for league.md / league.json")
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if len(args.players) < 2:
        print("league: error: give at least two players", file=sys.stderr)
        return 2
    run_league(args.game, args.players, args.games, args.seed, args.noise, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
