"""The search player: simulate candidate shots with the exact solver and play the best (:func:`search_shot`)."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from billiards_env.physics import Balls

from .context import ShotContext, shot_context, to_action
from .shots import direct_hit, ghost_ball_shots, position_score


@dataclass
class Outcome:
    angle: float
    speed: float
    pots: int
    scratch: bool
    hit: bool
    value: float  #: pots - 3 * scratch - 0.5 * (no ball hit)
    robust: float = math.nan  #: mean value under perturbations
    position: float = 0.0  #: next-shot ease from the final layout
    source: str = ""


def _simulate(ctx: ShotContext, angle: float, speed: float) -> tuple[int, bool, bool, Balls]:
    res = ctx.simulator.run(ctx.balls.strike(ctx.cue, angle, speed), validate=False)
    pots = int(sum(1 for j in ctx.targets if res.pocket[j] >= 0))
    scratch = bool(res.pocket[ctx.cue] >= 0)
    hit = res.first_contact(ctx.cue) >= 0
    return pots, scratch, hit, res.balls


def _value(pots: int, scratch: bool, hit: bool) -> float:
    return pots - 3.0 * scratch - (0.5 if not hit else 0.0)


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
        pots, scratch, hit, _ = _simulate(ctx, angle, speed)
        outs.append(Outcome(angle, speed, pots, scratch, hit, _value(pots, scratch, hit), source=src))
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
            vals.append(_value(*_simulate(ctx, a, v)[:3]))
        o.robust = float(np.mean(vals))
        if remaining - o.pots > 0 and not o.scratch:
            _, _, _, final = _simulate(ctx, o.angle, o.speed)
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
        angle, speed, self.last = search_shot(shot_context(env), self.settings, self.rng)
        return to_action(env, angle, speed)



__all__ = ["Outcome", "SearchSettings", "search_shot", "SearchPlayer"]
