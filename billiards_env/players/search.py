"""The search player: simulate candidate shots with the exact solver and play the best (:func:`search_shot`)."""
from __future__ import annotations

import contextlib
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from billiards_env.physics import Balls
from billiards_env.rules import ShotInfo, summarize_result

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


def _simulate(ctx: ShotContext, angle: float, speed: float) -> tuple[int, bool, bool, Balls, float]:
    """Play a candidate: ``(pots, scratch, hit, final balls, value)``. Without a game the value is
    :func:`_value`; in a game it is the rules' verdict (:func:`_game_value`)."""
    res = ctx.simulator.run(ctx.balls.strike(ctx.cue, angle, speed), validate=False)
    pots = int(sum(1 for j in ctx.targets if res.pocket[j] >= 0))
    scratch = bool(res.pocket[ctx.cue] >= 0)
    hit = res.first_contact(ctx.cue) >= 0
    if ctx.game is None:
        return pots, scratch, hit, res.balls, _value(pots, scratch, hit)
    return pots, scratch, hit, res.balls, _game_value(ctx, res)


def _value(pots: int, scratch: bool, hit: bool) -> float:
    return pots - 3.0 * scratch - (0.5 if not hit else 0.0)


def _game_value(ctx: ShotContext, res: Any) -> float:
    """A candidate's value under the game's rules: +10 for a won game, -10 for a lost one, -3 for a foul, +1 for
    keeping the turn plus 0.1 per ball that counts."""
    game = ctx.game
    summary = summarize_result(res, game.numbers)
    pocket = res.pocket[game.row_of[8]] if game.needs_called_pocket() and 8 in game.row_of else None
    call = game.rules.call(game.state, summary, ShotInfo(called_pocket=None if pocket is None or pocket < 0
                                                         else int(pocket)))
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
    """Simulate candidate shots with the exact solver and pick the best outcome.

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
                cands.append((s.angle + da, float(np.clip(s.speed * f, lo, hi)), f"ghost:{s.target}->{s.pocket}"))
    base = direct_hit(ctx.balls, ctx.cue, ctx.targets)[0]
    for k in range(st.sweep_angles):
        a = base + 2.0 * math.pi * k / st.sweep_angles
        for f in st.sweep_speeds:
            cands.append((a, lo + f * (hi - lo), "sweep"))
    outs: list[Outcome] = []
    for angle, speed, src in cands:
        pots, scratch, hit, _, value = _simulate(ctx, angle, speed)
        outs.append(Outcome(angle, speed, pots, scratch, hit, value, source=src))
    outs.sort(key=lambda o: -o.value)
    best_value = outs[0].value
    top = [o for o in outs if o.value >= best_value - 1e-9][: max(st.top_k * 4, st.top_k)]
    # Spread the shortlist over distinct shots (not seven offsets of one).
    shortlist: list[Outcome] = []
    for o in top:
        if all(abs(o.angle - q.angle) > 1e-3 or abs(o.speed - q.speed) > 0.05 for q in shortlist):
            shortlist.append(o)
        if len(shortlist) >= st.top_k:
            break
    sa = ctx.angle_noise if ctx.angle_noise > 0 else st.robust_angle
    ss = ctx.speed_noise if ctx.speed_noise > 0 else st.robust_speed
    remaining = len(ctx.targets)
    for o in shortlist:
        vals = []
        for _ in range(st.robust_samples):
            a = o.angle + rng.normal(0.0, sa)
            v = float(np.clip(o.speed * (1.0 + rng.normal(0.0, ss)), lo, hi))
            vals.append(_simulate(ctx, a, v)[4])
        o.robust = float(np.mean(vals))
        if remaining - o.pots > 0 and not o.scratch:
            _, _, _, final, _ = _simulate(ctx, o.angle, o.speed)
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
