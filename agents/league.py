"""A league: head-to-head matches between players on seeded racks, win rates with 95% intervals, an Elo table, and
each player's break-and-run and run-out-from-ball-in-hand rates.

    python -m agents.league --game nine_ball --players random geometric search --games 40
    python -m agents.league --game nine_ball --players random geometric search --games 40 --spin --noise fastfiz
    python -m agents.league --game eight_ball --players geometric search --games 40 --noise 0.005
    python -m agents.league --game nine_ball --players geometric search runs/main/nine_ball/<run> --games 100

A player is a baseline name (``random``, ``geometric``, ``search``: :mod:`billiards_env.players`) or a trained policy:
an SB3 run folder or model zip, or an RLlib checkpoint or run folder (with the ``rllib`` extra), played with
deterministic actions in its own action and observation types (:class:`agents.games.TrainedPlayer`); ``prior:<run>``
is the search player with that policy's proposals in place of its sweep, at its own simulation budget
(:mod:`agents.prior_search`; ``prior-plain:<run>`` the same without spending the sweep's simulations on re-runs
under noise, ``prior-always:<run>`` spending them on every table with a pot, hard ones too); ``scorer:<file>`` an
option-scoring policy of :mod:`agents.scorer` (``scorer-fallback:<file>``: the same that leaves ball in hand to its
fallback policy, as scorers before the ball-in-hand places did) and
``position_rule`` the hand-written rule of :mod:`agents.position_rule` (9-ball, on the ``candidates_position``
observation). Every pair
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
import importlib
import itertools
import json
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
    innings: tuple[int, int] = (0, 0)  #: a's and b's innings (visits to the table)
    scored: tuple[float, float] = (0.0, 0.0)  #: what a's and b's shots scored (the game's Verdict.scored)
    shots: tuple[int, int] = (0, 0)  #: a's and b's shots
    #: Games over before either player came back to the table (two innings at most: a break-and-run, or a run-out
    #: by the player who came to the table after the breaker); where both run out from nearly every table, most.
    no_return: int = 0

    @property
    def rate_a(self) -> float:
        return self.wins_a / max(self.games, 1)


def load_player(spec: str, seed: int = 0, game: str = "nine_ball") -> tuple[str, Any]:
    """``(name, policy)`` for a baseline name or a trained policy (SB3 run folder or zip, RLlib checkpoint or run
    folder: a :class:`agents.games.TrainedPlayer`)."""
    if spec in BASELINES:
        return spec, make_player(spec, seed=seed, game=game)
    for prefix, kw in (("prior:", {}), ("prior-plain:", {"reallocate": False}),
                       ("prior-always:", {"min_pot_chance": 0.0})):
        if spec.startswith(prefix):  # the search player with a trained policy's proposals (agents.prior_search)
            from .prior_search import prior_search_player

            p = prior_search_player(spec[len(prefix):], game, seed, **kw)
            return p.name, p
    for prefix, hand in (("scorer:", None), ("scorer-fallback:", False)):
        if spec.startswith(prefix):  # an option-scoring policy on the candidates_position types (agents.scorer)
            from .option_policies import scorer_player

            if game != "nine_ball":
                raise ValueError(f"{spec}: a scorer plays 9-ball, not {game}")
            p = scorer_player(spec[len(prefix):], hand=hand)
            return p.name, p
    if spec == "position_rule":  # the hand-written rule on the candidates_position observation
        from .option_policies import rule_player

        p = rule_player()
        return p.name, p
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

    def act(self, state: Any, obs: Any, codec: Any) -> Any:
        """The policy's action on the table state ``state`` in the action type ``codec``, timed."""
        t = time.perf_counter()
        a = self._act(state, obs, codec)
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
    decisions: int = 0

    @property
    def rate(self) -> float:
        return self.run_outs / max(self.racks, 1)


def run_outs(game: str, player: tuple[str, Any], racks: int | Sequence[int], seed: int,
             env_kwargs: dict[str, Any]) -> RunOutResult:
    """``player``'s turns from ball in hand on ``racks`` layouts (a number, or the rack indices ``k``): the env breaks
    (``opening="ball_in_hand"``; rack and break from ``reset(seed=seed + k)``), player_0 has the cue ball in hand
    anywhere and shoots until the table passes. A run-out is a turn that wins the game (the 9 may drop early on a
    combination: slop counts)."""
    warm_up(game, [player[1]], env_kwargs)
    module = _aec_module(game)
    env = module.env(**{**env_kwargs, "opening": "ball_in_hand", "first_shooter": "agent"})
    raw = env.unwrapped
    timed = Timed(player[1])
    wins, balls = 0, 0
    t0 = time.perf_counter()
    ks = range(racks) if isinstance(racks, int) else [int(k) for k in racks]
    try:
        for k in ks:
            timed.reset(int(np.random.SeedSequence([seed, k, 7]).generate_state(1)[0]))
            env.reset(seed=seed + k)
            before = int(raw.game_env.balls.on_table[1:].sum())
            while raw.agent_selection == "player_0" and not (raw.terminations["player_0"]
                                                             or raw.truncations["player_0"]):
                g = raw.game_env
                env.step(timed.act(g.state, env.observe("player_0"), g.action_type))
            balls += before - int(raw.game_env.balls.on_table[1:].sum())
            wins += raw.task.session.winner == 0
    finally:
        env.close()
    return RunOutResult(player[0], len(ks), wins, balls / max(len(ks), 1), timed.ms_per_decision,
                        time.perf_counter() - t0, timed.decisions)


def merge_run_outs(parts: Sequence[RunOutResult], seconds: float) -> RunOutResult:
    """One player's :class:`RunOutResult` from its chunks."""
    racks = sum(p.racks for p in parts)
    dec = sum(p.decisions for p in parts)
    return RunOutResult(parts[0].player, racks, sum(p.run_outs for p in parts),
                        sum(p.balls * p.racks for p in parts) / max(racks, 1),
                        sum(p.ms_per_decision * p.decisions for p in parts) / max(dec, 1), seconds, dec)


def has_runouts(game: str) -> bool:
    """Whether ``game`` can open with the cue ball in hand after the env's break (the run-out test's layouts)."""
    return "ball_in_hand" in REGISTERED[game].session_class.openings


@dataclass
class GameStats:
    """One game of a pair, from the pair's side (policy 0 is ``a``): the seats, the winner (-1: none), how it
    ended, and per policy its shots, innings (visits to the table), what its shots scored (balls kept down in
    pool, points in snooker and three-cushion: the game's ``Verdict.scored``), and its decisions and their
    seconds."""

    k: int
    seats: tuple[int, int]
    winner: int
    reason: str
    shots: tuple[int, int]
    innings: tuple[int, int]
    scored: tuple[float, float]
    decisions: tuple[int, int]
    seconds: tuple[float, float]
    wall: float = 0.0  #: seconds the game took where it was played


_WARM: set[tuple[str, int]] = set()


#: Untimed decisions of each policy before its games (:func:`warm_up`).
WARM_DECISIONS = 4


def warm_up(game: str, policies: Sequence[Any], env_kwargs: dict[str, Any]) -> None:
    """A few untimed decisions of each policy on a fresh rack (the break and the positions after it; once per process
    and policy), so that loading the compiled kernels (numba's cache) and a model's first call are not counted in the
    decision times. Every game reseeds the players, so this changes no game."""

    todo = [p for p in policies if (game, id(p)) not in _WARM]
    if not todo:
        return
    module = _aec_module(game)
    env = module.env(**env_kwargs)
    try:
        for p in todo:
            env.reset(seed=0)
            for _ in range(WARM_DECISIONS):
                obs = env.observe(env.unwrapped.agent_selection)
                g = env.unwrapped.game_env
                env.step(Timed(p).act(g.state, obs, g.action_type))
                if any(env.terminations.values()) or any(env.truncations.values()):
                    break
            _WARM.add((game, id(p)))
    finally:
        env.close()


def play_games(game: str, policies: Sequence[Any], ks: Sequence[int], seed: int,
               env_kwargs: dict[str, Any]) -> list[GameStats]:
    """Games ``ks`` of a match between ``policies`` (two, policy 0 is ``a``) on the game's two-player env: game
    ``k`` on ``reset(seed=seed + k)``, policy 0 in seat ``k % 2`` (seats swapped every game) and each policy
    reseeded from ``(seed, k, j)``: :func:`billiards_env.multi.play_match`'s games, so a match cut into chunks and
    played anywhere gives the same games. Counts innings, scores and decision times besides."""

    warm_up(game, policies, env_kwargs)
    module = _aec_module(game)
    env = module.env(**env_kwargs)
    raw = env.unwrapped
    timed = [Timed(p) for p in policies]
    out: list[GameStats] = []
    try:
        for k in ks:
            seats = (1, 0) if k % 2 else (0, 1)
            for j, t in enumerate(timed):
                t.reset(int(np.random.SeedSequence([seed, k, j]).generate_state(1)[0]))
            t_game = time.perf_counter()
            env.reset(seed=seed + k)
            shots, innings, scored = [0, 0], [0, 0], [0.0, 0.0]
            dec0 = [t.decisions for t in timed]
            sec0 = [t.seconds for t in timed]
            last = -1
            for agent in env.agent_iter():
                obs, _, terminated, truncated, _ = env.last()
                if terminated or truncated:
                    env.step(None)
                    continue
                who = seats[raw.agent_index[agent]]
                env.step(timed[who].act(raw.game_env.state, obs, raw.game_env.action_type))
                shots[who] += 1
                if who != last:
                    innings[who] += 1
                    last = who
                verdict = raw.task.verdict
                if verdict is not None:
                    scored[who] += float(verdict.scored)
            over = raw.game_over
            w = raw.task.session.winner
            winner = -1 if (not over or w is None) else seats[w]
            verdict = raw.task.verdict
            reason = verdict.reason if over and verdict is not None else "max_shots"
            out.append(GameStats(int(k), seats, winner, reason, (shots[0], shots[1]), (innings[0], innings[1]),
                                 (scored[0], scored[1]),
                                 (timed[0].decisions - dec0[0], timed[1].decisions - dec0[1]),
                                 (timed[0].seconds - sec0[0], timed[1].seconds - sec0[1]),
                                 time.perf_counter() - t_game))
    finally:
        env.close()
    return out


def pair_result(a: str, b: str, games: Sequence[GameStats], seconds: float | None = None) -> PairResult:
    """The :class:`PairResult` of a pair's games (in any order); ``seconds`` default: the games' own times summed
    (worker seconds, wherever they were played)."""
    if seconds is None:
        seconds = sum(g.wall for g in games)
    games = sorted(games, key=lambda g: g.k)
    reasons: dict[str, int] = {}
    bnr = [0, 0]
    for g in games:
        reasons[g.reason] = reasons.get(g.reason, 0) + 1
        breaker = g.seats[0]
        if g.winner == breaker and g.shots[1 - breaker] == 0:
            bnr[breaker] += 1
    winners = [g.winner for g in games]

    def ms(j: int) -> float:
        n = sum(g.decisions[j] for g in games)
        return 1000.0 * sum(g.seconds[j] for g in games) / max(n, 1)

    return PairResult(a, b, len(games), winners.count(0), winners.count(1), winners.count(-1), sum(bnr), seconds,
                      reasons, (ms(0), ms(1)), (bnr[0], bnr[1]),
                      (sum(g.innings[0] for g in games), sum(g.innings[1] for g in games)),
                      (sum(g.scored[0] for g in games), sum(g.scored[1] for g in games)),
                      (sum(g.shots[0] for g in games), sum(g.shots[1] for g in games)),
                      sum(1 for g in games if g.winner >= 0 and g.innings[0] + g.innings[1] <= 2))


def play_pair(game: str, a: tuple[str, Any], b: tuple[str, Any], n_games: int, seed: int,
              env_kwargs: dict[str, Any]) -> PairResult:
    """``n_games`` games of ``a`` against ``b`` (seats swapped every game), in this process."""
    t0 = time.perf_counter()
    games = play_games(game, [a[1], b[1]], range(n_games), seed, env_kwargs)
    return pair_result(a[0], b[0], games, time.perf_counter() - t0)


def _pair_chunk(game: str, spec_a: str, spec_b: str, ks: list[int], seed: int,
                env_kwargs: dict[str, Any]) -> list[GameStats]:
    """A worker's chunk of a pair's games: the players loaded from their specs (names, run folders) here."""
    import torch

    torch.set_num_threads(1)
    a, b = load_player(spec_a, seed, game), load_player(spec_b, seed, game)
    return play_games(game, [a[1], b[1]], ks, seed, env_kwargs)


def _runout_chunk(game: str, spec: str, ks: list[int], seed: int, env_kwargs: dict[str, Any]) -> RunOutResult:
    import torch

    torch.set_num_threads(1)
    return run_outs(game, load_player(spec, seed, game), ks, seed, env_kwargs)


def _chunks(n: int, workers: int) -> list[list[int]]:
    """``range(n)`` cut into about four chunks per worker (the last ones smaller: slow games even out)."""
    k = max(1, min(n, 4 * max(workers, 1)))
    return [c.tolist() for c in np.array_split(np.arange(n), k) if len(c)]


class Pool:
    """Where the league's chunks run: this process (``workers=1``), local processes, or Ray workers on a cluster
    (``address``). ``map(fn, argument tuples)`` returns the results in order."""

    def __init__(self, workers: int = 1, address: str | None = None) -> None:
        self.workers = max(int(workers), 1)
        self.address = address
        self._pool: Any = None
        if address:
            import ray

            ray.init(address=address, ignore_reinit_error=True, log_to_driver=False)
        elif self.workers > 1:
            from .processes import process_pool

            self._pool = process_pool(self.workers)

    def map(self, fn: Any, args: Sequence[tuple[Any, ...]]) -> list[Any]:
        if self.address:
            import ray

            remote = ray.remote(fn)
            return ray.get([remote.remote(*a) for a in args])
        if self._pool is not None:
            futures = [self._pool.submit(fn, *a) for a in args]
            return [f.result() for f in futures]
        return [fn(*a) for a in args]

    def close(self) -> None:
        if self._pool is not None:
            self._pool.shutdown()


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
             "| player A | player B | A wins | B wins | unfinished | A win rate [95% CI] | break-and-run | worker time |",
             "|---|---|---|---|---|---|---|---|"]
    for p in pairs:
        lo, hi = wilson_interval(p.wins_a, p.games)
        lines.append(f"| {p.a} | {p.b} | {p.wins_a} | {p.wins_b} | {p.unfinished} | {100 * p.rate_a:.0f}% "
                     f"[{100 * lo:.0f}, {100 * hi:.0f}] | {100 * p.break_and_runs / p.games:.0f}% | "
                     f"{p.seconds:.0f} s |")
    stats = player_stats(pairs, runs)
    unit = scored_unit(game)
    lines += ["", f"| player | Elo | games won [95% CI] | break-and-run (breaks) | {unit} per inning | run-out from "
              "ball in hand [95% CI] | balls per turn in hand | ms / decision |", "|---|---|---|---|---|---|---|---|"]
    for name, r in sorted(elo.items(), key=lambda kv: -kv[1]):
        st = stats[name]
        lo, hi = wilson_interval(st["wins"], st["games"])
        row = f"| {name} | {r:.0f} | {100 * st['wins'] / max(st['games'], 1):.0f}% [{100 * lo:.0f}, {100 * hi:.0f}] " \
              f"| {100 * st['break_and_runs'] / max(st['breaks'], 1):.0f}% ({st['breaks']}) |"
        row += f" {st['per_inning']:.2f} ({st['innings']}) |" if st.get("per_inning") is not None else " - |"
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
    """Per player over all its pairs: games, wins, breaks (half its games: the seats alternate), break-and-runs,
    innings and what its shots scored (``per_inning``: the Olympiads' balls per inning) and the mean decision time
    (weighted by games)."""
    out: dict[str, dict[str, Any]] = {}
    for p in pairs:
        for name, wins, bnr_share, ms, inn, sc in ((p.a, p.wins_a, 0, p.ms_per_decision[0], p.innings[0], p.scored[0]),
                                                   (p.b, p.wins_b, 1, p.ms_per_decision[1], p.innings[1], p.scored[1])):
            st = out.setdefault(name, {"games": 0, "wins": 0, "breaks": 0, "break_and_runs": 0, "ms_sum": 0.0,
                                       "innings": 0, "scored": 0.0})
            st["games"] += p.games
            st["wins"] += wins
            st["breaks"] += (p.games + (1 - bnr_share)) // 2  # policy a breaks games 0, 2, 4...
            st["ms_sum"] += ms * p.games
            st["innings"] += inn
            st["scored"] += sc
    for p in pairs:  # break-and-runs are counted per pair for the winner who broke
        for name, k in ((p.a, 0), (p.b, 1)):
            out[name]["break_and_runs"] += p.break_and_runs_by[k]
    for st in out.values():
        st["ms"] = st.pop("ms_sum") / max(st["games"], 1)
        st["per_inning"] = st["scored"] / st["innings"] if st["innings"] else None
    for r in runs:
        out.setdefault(r.player, {"games": 0, "wins": 0, "breaks": 0, "break_and_runs": 0, "ms": r.ms_per_decision,
                                  "innings": 0, "scored": 0.0, "per_inning": None})
    return out


#: What a game's ``Verdict.scored`` counts (the league's "per inning" column).
def _aec_module(game: str) -> Any:
    """The PettingZoo module of ``game`` (``billiards_env.multi.<game>_v0``)."""
    return importlib.import_module(f"billiards_env.multi.{GAMES[game]}")


def scored_unit(game: str) -> str:
    """What ``game``'s ``Verdict.scored`` counts (``"balls"``, ``"points"``): its session's ``scored_unit``."""
    from billiards_env.games import game_spec

    return game_spec(game).session_class.scored_unit


def league_env_kwargs(players: Sequence[tuple[str, Any]], spin: bool, noise: str | float,
                      extra: dict[str, Any] | None = None) -> dict[str, Any]:
    """The two-player env's kwargs: the physics (the spin model with ``spin``; trained players bring theirs, which
    must agree), the noise setting (:func:`agents.games.noise_kwargs`), then ``extra``. The action type stays the
    absolute one (exact for every player)."""
    from .games import TrainedPlayer, noise_kwargs, physics_kwargs

    kw: dict[str, Any] = {}
    if spin:
        kw.update(friction="spin", spin_action=True)
    trained = [t for t in (getattr(p, "policy", p) for _, p in players) if isinstance(t, TrainedPlayer)]
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


def print_vs_geometric(name: str, player: Any, games: int, seed: int, noises: Sequence[str]) -> None:
    """Play ``player`` against the geometric player on 9-ball, ``games`` games under each of ``noises`` ("0" or a
    noise name; spin model), and print the win rate with its Wilson interval, break-and-runs and decision time: the
    check that the option policies' command lines end with."""
    geo = ("geometric", make_player("geometric", seed=seed, game="nine_ball"))
    me = (name, player)
    for noise in noises:
        kw = league_env_kwargs([me, geo], True, noise if noise != "0" else 0.0)
        r = play_pair("nine_ball", me, geo, games, seed, kw)
        lo, hi = wilson_interval(r.wins_a, r.games)
        print(f"{name} vs geometric, noise {noise}: {r.wins_a}-{r.wins_b} = {100 * r.wins_a / r.games:.1f}% "
              f"[{100 * lo:.0f}, {100 * hi:.0f}], break-and-runs {r.break_and_runs_by[0]} vs {r.break_and_runs_by[1]}, "
              f"{r.ms_per_decision[0]:.2f} ms a decision")


def setting_text(game: str, kw: dict[str, Any]) -> str:
    """The physics and shot noise the league's games are played under: the two-player env's resolved config (the
    game's defaults where ``kw`` says nothing: three-cushion is played under the spin model by default)."""
    from billiards_env.envs.config import load_config

    game_class = _aec_module(game).raw_env.game_class  # the config only: no env, no kernel run before a fork
    cfg = load_config(game_class.scene, None, **{**kw, "opponent": None})
    noise = ", ".join(f"{k} {getattr(cfg, k):.4g}" for k in ("angle_noise", "speed_noise", "tip_noise")
                      if getattr(cfg, k))
    if cfg.speed_noise_mode == "absolute":
        noise = noise.replace("speed_noise", "speed_noise (m/s)")
    return f"physics: {cfg.physics.friction}" + (", tip offsets in the action" if cfg.spin_action else "") + \
        f"; shot noise: {noise or 'none'}"


def run_league(game: str, specs: Sequence[str], n_games: int, seed: int, noise: str | float, out: Path | None,
               env_kwargs: dict[str, Any] | None = None, quiet: bool = False, spin: bool = False,
               runouts: int = 0, runout_seed: int = 50_000, command: str | None = None,
               pair_games: dict[str, int] | None = None, workers: int = 1,
               address: str | None = None) -> dict[str, Any]:
    """Every pair of ``specs`` plays ``n_games`` (a pair with a player named in ``pair_games``, or whose spec starts
    with one of its keys, at most that many: slow players); each player's run-outs from ball in hand on ``runouts`` racks (games that open with ball in hand
    only); returns (and writes under ``out``) the report. The games are cut into chunks played on ``workers`` local
    processes, or on Ray workers with ``address``; the results do not depend on how (each game is seeded by its
    index, :func:`play_games`)."""
    if n_games < 1 or any(v < 1 for v in (pair_games or {}).values()):
        raise ValueError(f"games per pair must be at least 1, got {min([n_games, *(pair_games or {}).values()])}; "
                         "a league of no games has no result to report")
    say = (lambda *a: None) if quiet else (lambda *a: print(*a, flush=True))
    players = [load_player(s, seed, game) for s in specs]
    kw = league_env_kwargs(players, spin, noise, env_kwargs)
    setting = setting_text(game, kw)
    say(setting + (f"; on Ray at {address}" if address else f"; {max(workers, 1)} process(es)"))
    limits = pair_games or {}
    pool = Pool(workers, address)
    tasks: list[tuple[Any, ...]] = []
    owners: list[tuple[str, int]] = []
    combos = list(itertools.combinations(range(len(players)), 2))
    def limit(x: int) -> list[int]:  # a key names a player, or starts its spec ("prior:")
        return [v for k, v in limits.items() if players[x][0] == k or specs[x] == k or specs[x].startswith(k)]

    for i, j in combos:
        n = min([n_games] + limit(i) + limit(j))
        for ks in _chunks(n, pool.workers):
            tasks.append((game, specs[i], specs[j], ks, seed, kw))
            owners.append(("pair", combos.index((i, j))))
    rtasks: list[tuple[Any, ...]] = []
    rowners: list[int] = []
    if runouts > 0 and not has_runouts(game):
        say(f"run-outs: {game} has no ball-in-hand opening; not played")
        runouts = 0
    if runouts > 0:
        for i in range(len(players)):
            for ks in _chunks(runouts, pool.workers):
                rtasks.append((game, specs[i], ks, runout_seed, kw))
                rowners.append(i)
    for _, pl in players:  # compiled code loaded before the processes fork (they inherit it)
        warm_up(game, [pl], kw)
    t0 = time.perf_counter()
    try:
        if pool.workers == 1 and not address:  # in this process: the players loaded above, no reloading
            results = [play_games(game, [players[i][1], players[j][1]], t[3], seed, kw)
                       for t, (_, c) in zip(tasks, owners) for i, j in [combos[c]]]
            rresults = [run_outs(game, players[i], t[2], runout_seed, kw) for t, i in zip(rtasks, rowners)]
        else:
            both = pool.map(_pair_chunk, tasks) if tasks else []
            rresults = pool.map(_runout_chunk, rtasks) if rtasks else []
            results = both
    finally:
        pool.close()
    seconds = time.perf_counter() - t0
    pairs = []
    for c, (i, j) in enumerate(combos):
        games = [g for r, (_, o) in zip(results, owners) if o == c for g in r]
        p = pair_result(players[i][0], players[j][0], games)
        lo, hi = wilson_interval(p.wins_a, p.games)
        say(f"{p.a} vs {p.b}: {p.wins_a}-{p.wins_b} ({p.unfinished} unfinished), {p.a} wins "
            f"{100 * p.rate_a:.0f}% [{100 * lo:.0f}, {100 * hi:.0f}]")
        pairs.append(p)
    runs = []
    for i in sorted(set(rowners)):
        r = merge_run_outs([x for x, o in zip(rresults, rowners) if o == i], 0.0)
        r.player = players[i][0]
        say(f"{r.player}: run-outs from ball in hand {r.run_outs}/{r.racks}, {r.balls:.1f} balls per turn")
        runs.append(r)
    names = [p[0] for p in players]
    elo = fit_elo(names, pairs)
    from billiards_env.machine import machine_info, machine_markdown

    if command is None:
        command = "python -m agents.league " + " ".join(sys.argv[1:]) if "league" in sys.argv[0] \
            else f"agents.league.run_league({game!r}, {list(specs)!r}, {n_games}, {seed}, {noise!r})"
    fewer = "".join(f" ({v} for the pairs of {k})" for k, v in limits.items()
                    if v < n_games and any(n == k or sp.startswith(k) for n, sp in zip(names, specs)))
    info = {"game": game, "games": n_games, "fewer": fewer, "seed": seed, "noise": noise, "spin": spin,
            "env_kwargs": kw, "seconds": seconds, "workers": pool.workers, "address": address,
            "setting": setting, "runouts": runouts, "runout_seed": runout_seed, "command": command,
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


def positive_int(text: str) -> int:
    """An argparse type: a whole number >= 1 (``--games 0`` is refused by argparse with this message)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {value} (a league of no games has no result)")
    return value


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m agents.league", description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog=__doc__.split("\n\n", 1)[1])
    p.add_argument("--game", choices=sorted(GAMES), default="nine_ball")
    p.add_argument("--players", nargs="+", default=["random", "geometric", "search"],
                   help="baseline names or trained model paths")
    p.add_argument("--games", type=positive_int, default=40, help="games per pair")
    p.add_argument("--search-games", type=positive_int, default=None, help="games of the pairs with the search player "
                   "(default: --games)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--noise", default="0", help="'olympiad' (FastFiz level-1 noise), 'fastfiz' (the older "
                   "tournament-like noise) or an angle spread (rad; the speed's is 3x it, relative); default 0: none")
    p.add_argument("--spin", action="store_true", help="the spin model (tip offsets in the action)")
    p.add_argument("--runouts", type=int, default=0, help="racks of the run-out-from-ball-in-hand test per player")
    p.add_argument("--runout-seed", type=int, default=50_000)
    p.add_argument("--rules", default=None, help="the game's rules options as JSON, e.g. '{\"target_points\": 3}' "
                   "for short three-cushion games")
    p.add_argument("--max-shots", type=int, default=None, help="shots of the two players together before a game is "
                   "called unfinished (default: the game's)")
    p.add_argument("--workers", type=int, default=1, help="local processes playing the games (default 1)")
    p.add_argument("--address", default=None, help="a Ray cluster's address (e.g. auto): play the games on its "
                   "workers (the rllib extra)")
    p.add_argument("--out", type=Path, default=None, help="folder for league.md / league.json")
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if len(args.players) < 2:
        print("league: error: give at least two players", file=sys.stderr)
        return 2
    extra: dict[str, Any] = {}
    try:
        if args.rules:
            extra["rules"] = json.loads(args.rules)
        if args.max_shots is not None:
            extra["max_shots"] = args.max_shots
        run_league(args.game, args.players, args.games, args.seed, args.noise, args.out, env_kwargs=extra,
                   spin=args.spin, runouts=args.runouts, runout_seed=args.runout_seed,
                   pair_games={"search": args.search_games} if args.search_games else None,
                   workers=args.workers, address=args.address)
    except json.JSONDecodeError as exc:
        print(f"league: error: --rules: not JSON ({exc}); e.g. '{{\"target_points\": 3}}'", file=sys.stderr)
        return 2
    except (ValueError, FileNotFoundError, KeyError) as exc:
        print(f"league: error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
