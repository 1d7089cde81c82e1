"""The search player: simulate candidate shots with the exact solver and play the best (:func:`search_shot`)."""
from __future__ import annotations

import contextlib
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from billiards_env.physics import Balls
from billiards_env.physics.batch import BatchResult, run_shots
from billiards_env.rules import ShotInfo, summarize_arrays

from .context import ShotContext, shot_context, to_action
from .geometric import break_shot, choose_placement
from .shots import direct_hit, ghost_ball_shots, position_score


@dataclass
class Outcome:
    angle: float
    speed: float
    pots: int
    scratch: bool
    hit: bool
    value: float  #: pots - 3 * scratch - 0.5 * (no ball hit); in a game the rules' verdict (_game_value)
    robust: float = math.nan  #: mean value under perturbations
    position: float = 0.0  #: next-shot ease from the final layout
    source: str = ""


def _simulate(ctx: ShotContext, angles: Any, speeds: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray,
                                                                   np.ndarray, BatchResult]:
    """Play candidate shots, all in one batch (:func:`~billiards_env.physics.batch.run_shots`; each row is the
    single ``Simulator.run`` of its shot): ``(pots, scratch, hit, value, batch result)`` per candidate. Without a
    game the value is :func:`_value`; in a game it is the rules' verdict (:func:`_game_value`)."""
    game = ctx.game is not None
    res = run_shots(ctx.simulator, ctx.balls, angles, speeds, ball=ctx.cue, validate=False, events=game)
    targets = np.asarray(ctx.targets, dtype=np.int64)
    pots = (res.pocket[:, targets] >= 0).sum(axis=1)
    scratch = res.pocket[:, ctx.cue] >= 0
    hit = res.first_contact >= 0
    if not game:
        return pots, scratch, hit, _value(pots, scratch, hit), res
    values = np.array([_game_value(ctx, res.events.row(k), res.pocket[k]) for k in range(len(res.time))])
    return pots, scratch, hit, values, res


def _value(pots: Any, scratch: Any, hit: Any) -> Any:
    """``pots - 3 scratch - 0.5 (no ball hit)``, for one candidate or arrays of them."""
    return pots - 3.0 * scratch - np.where(hit, 0.0, 0.5)


def _game_value(ctx: ShotContext, events: Any, pocket: np.ndarray) -> float:
    """A candidate's value under the game's rules (from its event log and pockets): +10 for a won game, -10 for a
    lost one, -3 for a foul, +1 for keeping the turn plus 0.1 per ball that counts."""
    game = ctx.game
    summary = summarize_arrays(np.stack([events.kind, events.ball, events.other], axis=1), pocket, game.numbers)
    eight = pocket[game.row_of[8]] if game.needs_called_pocket() and 8 in game.row_of else None
    call = game.rules.call(game.state, summary, ShotInfo(called_pocket=None if eight is None or eight < 0
                                                         else int(eight)))
    if call.game_over:
        return 10.0 if call.winner == call.shooter else -10.0
    if call.foul:
        return -3.0
    return (0.0 if call.turn_over else 1.0) + 0.1 * len(set(call.pocketed) - set(call.respot))


@dataclass
class SearchSettings:
    n_geometric: int = 8  #: ghost-ball candidates refined
    angle_offsets: tuple[float, ...] = (0.0, 0.0015, -0.0015, 0.004, -0.004, 0.01, -0.01)
    speed_factors: tuple[float, ...] = (1.0, 0.6, 1.6, 2.5)
    sweep_angles: int = 72  #: coarse sweep over all directions...
    sweep_speeds: tuple[float, ...] = (0.25, 0.6, 1.0)  #: ...at these fractions of the speed range
    top_k: int = 6  #: best candidates checked for robustness and position
    robust_samples: int = 8
    robust_angle: float = 0.002  #: perturbation (rad) when the env has no angle noise
    robust_speed: float = 0.05  #: relative perturbation when the env has no speed noise
    position_weight: float = 0.5  #: weight of next-shot ease (scaled to [0, 1]) against robustness


def search_shot(ctx: ShotContext, settings: SearchSettings | None = None,
                rng: np.random.Generator | None = None) -> tuple[float, float, Outcome]:
    """Simulate candidate shots with the exact solver (in batches: one compiled call for all candidates, one for
    the perturbed shots) and pick the best outcome.

    Candidates: every ghost-ball shot (best ``n_geometric``) at a few angle offsets and speed factors, plus a
    coarse sweep of directions and speeds (for kicks and banks when nothing is makeable). Ranking: the
    outcome value (pots, no scratch, a ball hit), then for the ``top_k`` best the mean value under angle/speed
    perturbations (the env's shot noise, or small defaults) plus a bonus for an easy next shot.
    """
    st = settings or SearchSettings()
    rng = rng or np.random.default_rng(0)
    lo, hi = ctx.speed_range
    cands: list[tuple[float, float, str]] = []
    shots = ghost_ball_shots(ctx.balls, ctx.table, ctx.physics, ctx.cue, ctx.targets, ctx.speed_range,
                             math.radians(85.0))
    for s in shots[: st.n_geometric]:
        for da in st.angle_offsets:
            for f in st.speed_factors:
                cands.append((s.angle + da, min(max(s.speed * f, lo), hi), f"ghost:{s.target}->{s.pocket}"))
    base = direct_hit(ctx.balls, ctx.cue, ctx.targets)[0]
    for k in range(st.sweep_angles):
        a = base + 2.0 * math.pi * k / st.sweep_angles
        for f in st.sweep_speeds:
            cands.append((a, lo + f * (hi - lo), "sweep"))
    # Every candidate in one batch; the ranking is a stable sort on the value, as a list sort would be.
    pots, scratch, hit, values, res = _simulate(ctx, [c[0] for c in cands], [c[1] for c in cands])
    order = np.argsort(-values, kind="stable")
    best_value = values[order[0]]
    top = [int(k) for k in order[: max(st.top_k * 4, st.top_k)] if values[k] >= best_value - 1e-9]
    # Spread the shortlist over distinct shots (not seven offsets of one).
    shortlist: list[Outcome] = []
    rows: list[int] = []
    for k in top:
        angle, speed, src = cands[k]
        if all(abs(angle - q.angle) > 1e-3 or abs(speed - q.speed) > 0.05 for q in shortlist):
            shortlist.append(Outcome(angle, speed, int(pots[k]), bool(scratch[k]), bool(hit[k]), float(values[k]),
                                     source=src))
            rows.append(k)
        if len(shortlist) >= st.top_k:
            break
    sa = ctx.angle_noise if ctx.angle_noise > 0 else st.robust_angle
    ss = ctx.speed_noise if ctx.speed_noise > 0 else st.robust_speed
    remaining = len(ctx.targets)
    # Robustness: the perturbed shots of the whole shortlist in one batch (drawn in the order of a loop).
    noisy_a: list[float] = []
    noisy_v: list[float] = []
    for o in shortlist:
        for _ in range(st.robust_samples):
            noisy_a.append(o.angle + rng.normal(0.0, sa))
            noisy_v.append(min(max(float(o.speed * (1.0 + rng.normal(0.0, ss))), lo), hi))
    noisy_values = _simulate(ctx, noisy_a, noisy_v)[3] if noisy_a else np.zeros(0)
    b = ctx.balls
    for q, (o, k) in enumerate(zip(shortlist, rows)):
        o.robust = float(np.mean(noisy_values[q * st.robust_samples:(q + 1) * st.robust_samples]))
        if remaining - o.pots > 0 and not o.scratch:
            final = Balls(b.ids, res.pos[k].copy(), res.vel[k].copy(), b.radius.copy(), b.mass.copy(),
                          res.on_table[k].copy())  # the candidate's own final layout (simulated above)
            left = [j for j in ctx.targets if final.on_table[j]]
            sc = position_score(final, ctx.table, ctx.physics, ctx.cue, left, ctx.speed_range)
            o.position = min(sc / 0.01, 1.0)  # ~0.01 rad of cue tolerance is an easy shot
    shortlist.sort(key=lambda o: -(o.value + o.robust + st.position_weight * o.position))
    best = shortlist[0]
    return best.angle, best.speed, best


class SearchPlayer:
    """Simulates candidate shots with the env's exact solver and plays the best (see :func:`search_shot`)."""

    name = "search"

    def __init__(self, seed: int | None = 0, settings: SearchSettings | None = None):
        self.settings = settings or SearchSettings()
        self.rng = np.random.default_rng(seed)
        self.last: Outcome | None = None

    def reset(self, seed: int | None = None) -> None:
        if seed is not None:
            self.rng = np.random.default_rng(seed)

    def act(self, env: Any, obs: Any) -> np.ndarray:
        """In a game it plays by the rules (candidates valued by the rules' call), breaks at full power and
        places a ball in hand where the geometric player would (:func:`.geometric.choose_placement`)."""
        ctx = shot_context(env)
        u = env.unwrapped
        if ctx.game is not None and ctx.game.state.break_shot:
            place, angle, speed = break_shot(ctx)
            return to_action(env, angle, speed, place=place)
        place = choose_placement(env, ctx) if ctx.place_area is not None else None
        with u.cue_moved_to(place) if place is not None else contextlib.nullcontext():
            angle, speed, self.last = search_shot(ctx, self.settings, self.rng)
            pocket = self._called_pocket(ctx, angle, speed)
        return to_action(env, angle, speed, place=place, pocket=pocket)

    @staticmethod
    def _called_pocket(ctx: ShotContext, angle: float, speed: float) -> int | None:
        """On the 8: the pocket the chosen shot sends it into (None if it does not)."""
        if ctx.game is None or not ctx.game.needs_called_pocket():
            return None
        res = ctx.simulator.run(ctx.balls.strike(ctx.cue, angle, speed), validate=False)
        k = int(res.pocket[ctx.game.row_of[8]])
        return k if k >= 0 else None



__all__ = ["Outcome", "SearchSettings", "search_shot", "SearchPlayer"]
