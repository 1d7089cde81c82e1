"""A league: head-to-head matches between players on seeded racks, win rates with 95% intervals, an Elo table, and
each player's break-and-run and run-out-from-ball-in-hand rates.

    python -m agents.league --game nine_ball --players random geometric search --games 40
    python -m agents.league --game nine_ball --players random geometric search --games 40 --spin --noise fastfiz
    python -m agents.league --game eight_ball --players geometric search --games 40 --noise 0.005
    python -m agents.league --game nine_ball --players geometric search runs/main/nine_ball/<run> --games 100

A player is a baseline name (``random``, ``geometric``, ``search``: :mod:`billiards_env.players`) or a trained policy:
an SB3 run folder or model zip, or an RLlib checkpoint or run folder (with the ``rllib`` extra), played with
deterministic actions in its own action and observation types (:class:`agents.games.TrainedPlayer`). Every pair
plays ``--games`` games on the two-player env (:mod:`billiards_env.multi`, absolute action type), seats swapped
every game so each breaks as often as the other; game ``k`` of a match uses the rack of seed ``seed + k``, so every
pair meets on the same racks. ``--spin`` plays under the spin model (friction ``spin``, tip offsets in the action);
a trained player brings its own physics (all must agree). ``--noise`` plays with shot noise: a named noise of the
envs (``olympiad``: FastFiz's level-1 noise of the Computational Pool Olympiads, aim 0.125 deg, speed 0.075 m/s, tip
offsets 0.5 mm; ``fastfiz``: the older setting with a relative speed spread of 3.75 %; see
:data:`billiards_env.envs.config.NOISE_PRESETS`) or an angle spread in rad (the speed's 3x it, relative).

The report: each pair's wins, the row player's win rate with its Wilson 95% interval, the break-and-run rate (the
breaker wins before the opponent shoots), Elo ratings fitted to all games (Bradley-Terry maximum likelihood,
random = 1000 when present, else the mean at 1500), and per player the run-out rate from ball in hand
(``--runouts`` racks broken by the env, the player with the cue ball in hand anywhere: does it win before giving up
the table; the same layouts for every player) and its mean decision time.
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

from billiards_env.games import GAMES as REGISTERED
from billiards_env.players import BASELINES, make_player

from .evaluate import wilson_interval

#: Each game's two-player module in billiards_env.multi, from the game registry.
GAMES = {g.name: g.aec_module for g in REGISTERED.values()}


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
    ms_per_decision: tuple[float, float] = (0.0, 0.0)  #: a's and b's mean decision time
    break_and_runs_by: tuple[int, int] = (0, 0)  #: break-and-runs of a and of b

    @property
    def rate_a(self) -> float:
        return self.wins_a / max(self.games, 1)


def load_player(spec: str, seed: int = 0, game: str = "nine_ball") -> tuple[str, Any]:
    """``(name, policy)`` for a baseline name or a trained policy (SB3 run folder or zip, RLlib checkpoint or run
    folder: a :class:`agents.games.TrainedPlayer`)."""
    if spec in BASELINES:
        return spec, make_player(spec, seed=seed, game=game)
    from .games import trained_player

    p = trained_player(spec, game)
    return p.name, p


class Timed:
    """A policy that counts its decisions and the time they take (``act``/``reset`` as the players)."""

    def __init__(self, policy: Any) -> None:
        from billiards_env.envs.games import as_policy

        self.policy = policy
        self._act = as_policy(policy)
        self.decisions = 0
        self.seconds = 0.0

    def reset(self, seed: int | None = None) -> None:
        if hasattr(self.policy, "reset"):
            self.policy.reset(seed)

    def act(self, env: Any, obs: Any) -> Any:
        t = time.perf_counter()
        a = self._act(env, obs)
        self.seconds += time.perf_counter() - t
        self.decisions += 1
        return a

    @property
    def ms_per_decision(self) -> float:
        return 1000.0 * self.seconds / max(self.decisions, 1)


@dataclass
class RunOutResult:
    """A player's run-outs from ball in hand after the break (see the module docstring)."""

    player: str
    racks: int
    run_outs: int  #: turns that won the game
    balls: float  #: object balls off the table at the end of the turn, per turn
    ms_per_decision: float
    seconds: float

    @property
    def rate(self) -> float:
        return self.run_outs / max(self.racks, 1)


def run_outs(game: str, player: tuple[str, Any], racks: int, seed: int, env_kwargs: dict[str, Any]) -> RunOutResult:
    """``player``'s turns from ball in hand on ``racks`` layouts: the env breaks (``opening="ball_in_hand"``; rack and
    break from ``reset(seed=seed + k)``), player_0 has the cue ball in hand anywhere and shoots until the table
    passes. A run-out is a turn that wins the game (the 9 may drop early on a combination: slop counts)."""
    import importlib

    module = importlib.import_module(f"billiards_env.multi.{GAMES[game]}")
    env = module.env(**{**env_kwargs, "opening": "ball_in_hand", "first_shooter": "agent"})
    raw = env.unwrapped
    timed = Timed(player[1])
    wins, balls = 0, 0
    t0 = time.perf_counter()
    try:
        for k in range(racks):
            timed.reset(int(np.random.SeedSequence([seed, k, 7]).generate_state(1)[0]))
            env.reset(seed=seed + k)
            before = int(raw.game_env.balls.on_table[1:].sum())
            while raw.agent_selection == "player_0" and not (raw.terminations["player_0"]
                                                             or raw.truncations["player_0"]):
                env.step(timed.act(raw.game_env, env.observe("player_0")))
            balls += before - int(raw.game_env.balls.on_table[1:].sum())
            wins += raw.task.session.winner == 0
    finally:
        env.close()
    return RunOutResult(player[0], racks, wins, balls / max(racks, 1), timed.ms_per_decision,
                        time.perf_counter() - t0)


def play_pair(game: str, a: tuple[str, Any], b: tuple[str, Any], n_games: int, seed: int,
              env_kwargs: dict[str, Any]) -> PairResult:
    """``n_games`` games of ``a`` against ``b`` (seats swapped every game)."""
    import importlib

    from billiards_env.multi import play_match

    module = importlib.import_module(f"billiards_env.multi.{GAMES[game]}")
    t0 = time.perf_counter()
    ta, tb = Timed(a[1]), Timed(b[1])
    res = play_match(lambda: module.env(**env_kwargs), [ta, tb], n_games, seed=seed)
    reasons: dict[str, int] = {}
    bnr = [0, 0]
    for g in res.games:
        reasons[g.reason] = reasons.get(g.reason, 0) + 1
        breaker = g.seats[0]
        if g.winner == breaker and g.shots[1 - breaker] == 0:
            bnr[breaker] += 1
    wins = res.wins
    return PairResult(a[0], b[0], n_games, wins[0], wins[1], res.unfinished, sum(bnr), time.perf_counter() - t0,
                      reasons, (ta.ms_per_decision, tb.ms_per_decision), (bnr[0], bnr[1]))


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


def markdown(game: str, pairs: Sequence[PairResult], elo: dict[str, float], info: dict[str, Any],
             runs: Sequence[RunOutResult] = ()) -> str:
    lines = [f"# League: {game.replace('_', '-')}", "",
             f"{info['games']} games per pair{info.get('fewer', '')} on seeded racks (seed {info['seed']}), seats "
             "swapped every game; "
             f"{info['setting']}. Command: `{info['command']}`. {info['machine']}", "",
             "| player A | player B | A wins | B wins | unfinished | A win rate [95% CI] | break-and-run | time |",
             "|---|---|---|---|---|---|---|---|"]
    for p in pairs:
        lo, hi = wilson_interval(p.wins_a, p.games)
        lines.append(f"| {p.a} | {p.b} | {p.wins_a} | {p.wins_b} | {p.unfinished} | {100 * p.rate_a:.0f}% "
                     f"[{100 * lo:.0f}, {100 * hi:.0f}] | {100 * p.break_and_runs / p.games:.0f}% | "
                     f"{p.seconds:.0f} s |")
    stats = player_stats(pairs, runs)
    lines += ["", "| player | Elo | games won [95% CI] | break-and-run (breaks) | run-out from ball in hand [95% CI] "
              "| balls per turn in hand | ms / decision |", "|---|---|---|---|---|---|---|"]
    for name, r in sorted(elo.items(), key=lambda kv: -kv[1]):
        st = stats[name]
        lo, hi = wilson_interval(st["wins"], st["games"])
        row = f"| {name} | {r:.0f} | {100 * st['wins'] / max(st['games'], 1):.0f}% [{100 * lo:.0f}, {100 * hi:.0f}] " \
              f"| {100 * st['break_and_runs'] / max(st['breaks'], 1):.0f}% ({st['breaks']}) |"
        ro = next((x for x in runs if x.player == name), None)
        if ro is not None:
            rlo, rhi = wilson_interval(ro.run_outs, ro.racks)
            row += f" {100 * ro.rate:.0f}% [{100 * rlo:.0f}, {100 * rhi:.0f}] ({ro.racks} racks) | {ro.balls:.1f} |"
        else:
            row += " - | - |"
        row += f" {st['ms']:.1f} |"
        lines.append(row)
    lines += ["", "How the games ended:", ""]
    for p in pairs:
        ends = ", ".join(f"{k}: {v}" for k, v in sorted(p.reasons.items(), key=lambda kv: -kv[1]))
        lines.append(f"- {p.a} vs {p.b}: {ends}")
    return "\n".join(lines) + "\n"


def player_stats(pairs: Sequence[PairResult], runs: Sequence[RunOutResult] = ()) -> dict[str, dict[str, Any]]:
    """Per player over all its pairs: games, wins, breaks (half its games: the seats alternate), break-and-runs and
    the mean decision time (weighted by games)."""
    out: dict[str, dict[str, Any]] = {}
    for p in pairs:
        for name, wins, bnr_share, ms in ((p.a, p.wins_a, 0, p.ms_per_decision[0]),
                                          (p.b, p.wins_b, 1, p.ms_per_decision[1])):
            st = out.setdefault(name, {"games": 0, "wins": 0, "breaks": 0, "break_and_runs": 0, "ms_sum": 0.0})
            st["games"] += p.games
            st["wins"] += wins
            st["breaks"] += (p.games + (1 - bnr_share)) // 2  # policy a breaks games 0, 2, 4...
            st["ms_sum"] += ms * p.games
    for p in pairs:  # break-and-runs are counted per pair for the winner who broke
        for name, k in ((p.a, 0), (p.b, 1)):
            out[name]["break_and_runs"] += p.break_and_runs_by[k]
    for st in out.values():
        st["ms"] = st.pop("ms_sum") / max(st["games"], 1)
    for r in runs:
        out.setdefault(r.player, {"games": 0, "wins": 0, "breaks": 0, "break_and_runs": 0, "ms": r.ms_per_decision})
    return out


def league_env_kwargs(players: Sequence[tuple[str, Any]], spin: bool, noise: str | float,
                      extra: dict[str, Any] | None = None) -> dict[str, Any]:
    """The two-player env's kwargs: the physics (the spin model with ``spin``; trained players bring theirs, which
    must agree), the noise setting (:func:`agents.games.noise_kwargs`), then ``extra``. The action type stays the
    absolute one (exact for every player)."""
    from .games import TrainedPlayer, noise_kwargs, physics_kwargs

    kw: dict[str, Any] = {}
    if spin:
        kw.update(friction="spin", spin_action=True)
    trained = [p for _, p in players if isinstance(p, TrainedPlayer)]
    for t in trained:
        if t.physics != trained[0].physics:
            raise ValueError(f"players: {t.name} and {trained[0].name} were trained with different physics; a "
                             "league plays one")
    if trained:
        if spin and trained[0].physics.friction != "spin":
            raise ValueError(f"--spin: {trained[0].name} was trained without the spin model")
        kw = physics_kwargs(trained[0].config)
    kw.update(noise_kwargs(noise, kw.get("spin_action", False) or
                           kw.get("physics", {}).get("friction") == "spin" or kw.get("friction") == "spin"))
    kw.update(extra or {})
    return kw


def setting_text(kw: dict[str, Any]) -> str:
    friction = kw.get("friction") or kw.get("physics", {}).get("friction", "rolling")
    noise = ", ".join(f"{k} {kw[k]:.4g}" for k in ("angle_noise", "speed_noise", "tip_noise") if kw.get(k))
    if kw.get("speed_noise_mode") == "absolute":
        noise = noise.replace("speed_noise", "speed_noise (m/s)")
    return f"physics: {friction}" + (", tip offsets in the action" if kw.get("spin_action") else "") + \
        f"; shot noise: {noise or 'none'}"


def run_league(game: str, specs: Sequence[str], n_games: int, seed: int, noise: str | float, out: Path | None,
               env_kwargs: dict[str, Any] | None = None, quiet: bool = False, spin: bool = False,
               runouts: int = 0, runout_seed: int = 50_000, command: str | None = None,
               pair_games: dict[str, int] | None = None) -> dict[str, Any]:
    """Every pair of ``specs`` plays ``n_games`` (a pair with a player named in ``pair_games`` at most that many:
    slow players); each player's run-outs from ball in hand on ``runouts`` racks; returns (and writes under
    ``out``) the report."""
    say = (lambda *a: None) if quiet else (lambda *a: print(*a, flush=True))
    players = [load_player(s, seed, game) for s in specs]
    kw = league_env_kwargs(players, spin, noise, env_kwargs)
    say(setting_text(kw))
    pairs = []
    limits = pair_games or {}
    for a, b in itertools.combinations(players, 2):
        n = min([n_games] + [limits[x[0]] for x in (a, b) if x[0] in limits])
        p = play_pair(game, a, b, n, seed, kw)
        lo, hi = wilson_interval(p.wins_a, p.games)
        say(f"{p.a} vs {p.b}: {p.wins_a}-{p.wins_b} ({p.unfinished} unfinished), {p.a} wins "
            f"{100 * p.rate_a:.0f}% [{100 * lo:.0f}, {100 * hi:.0f}], {p.seconds:.0f} s")
        pairs.append(p)
    runs = []
    if runouts > 0:
        for pl in players:
            r = run_outs(game, pl, runouts, runout_seed, kw)
            say(f"{r.player}: run-outs from ball in hand {r.run_outs}/{r.racks}, {r.balls:.1f} balls per turn, "
                f"{r.seconds:.0f} s")
            runs.append(r)
    names = [p[0] for p in players]
    elo = fit_elo(names, pairs)
    from billiards_env.machine import machine_info, machine_markdown

    if command is None:
        command = "python -m agents.league " + " ".join(sys.argv[1:]) if "league" in sys.argv[0] \
            else f"agents.league.run_league({game!r}, {list(specs)!r}, {n_games}, {seed}, {noise!r})"
    fewer = "".join(f" ({v} for the pairs of {k})" for k, v in limits.items() if v < n_games and k in names)
    info = {"game": game, "games": n_games, "fewer": fewer, "seed": seed, "noise": noise, "spin": spin,
            "env_kwargs": kw,
            "setting": setting_text(kw), "runouts": runouts, "runout_seed": runout_seed, "command": command,
            "machine": machine_markdown(machine_info())}
    report = {"info": info, "pairs": [asdict(p) for p in pairs], "elo": elo,
              "run_outs": [{**asdict(r), "rate": r.rate, "ci": wilson_interval(r.run_outs, r.racks)} for r in runs],
              "players": player_stats(pairs, runs)}
    md = markdown(game, pairs, elo, info, runs)
    say(md)
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
        (out / "league.json").write_text(json.dumps(report, indent=2, default=str))
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
    p.add_argument("--search-games", type=int, default=None, help="games of the pairs with the search player "
                   "(default: --games)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--noise", default="0", help="'olympiad' (FastFiz level-1 noise), 'fastfiz' (the older "
                   "tournament-like noise) or an angle spread (rad; the speed's is 3x it, relative); default 0: none")
    p.add_argument("--spin", action="store_true", help="the spin model (tip offsets in the action)")
    p.add_argument("--runouts", type=int, default=0, help="racks of the run-out-from-ball-in-hand test per player")
    p.add_argument("--runout-seed", type=int, default=50_000)
    p.add_argument("--out", type=Path, default=None, help="folder for league.md / league.json")
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if len(args.players) < 2:
        print("league: error: give at least two players", file=sys.stderr)
        return 2
    try:
        run_league(args.game, args.players, args.games, args.seed, args.noise, args.out, spin=args.spin,
                   runouts=args.runouts, runout_seed=args.runout_seed,
                   pair_games={"search": args.search_games} if args.search_games else None)
    except (ValueError, FileNotFoundError) as exc:
        print(f"league: error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
