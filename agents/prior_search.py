"""Search with a learned prior: the search player, with part of its candidate shots proposed by a trained policy.

The search player (:class:`billiards_env.players.search.SearchPlayer`) simulates a fixed list of candidates per
decision: the ghost-ball shots of the easiest pots at angle offsets, speed factors and tip offsets, then a sweep of
72 directions x 3 speeds for kicks and safeties. :class:`PriorSearchPlayer` keeps that budget, the same number of
simulated shots and the same valuation (the rules' verdict, the position left, the noisy re-runs of the best), and
spends the sweep's share on the policy's proposals instead: the shot the policy plays and variants of it (angle
offsets, speed factors, tip offsets), then the policy's speed and spin applied to every other candidate (ball,
pocket) of its action type. With the cue ball in hand the policy's place is searched first, then the search's own
best places (as many places in all as the search player searches, each with as many candidates; the search's
places keep its sweep). Under shot noise, when the policy has a pot to play and the table is not a hard one (the
easiest pot's chance under the noise at least :data:`REALLOCATE_POT_CHANCE`), the sweep shrinks to the proposals and
the simulations it frees re-run more of the best shots under noise, more times each
(:meth:`PriorSearchPlayer.settings_for`): the prior narrows the search, the budget buys a surer estimate of each
shot's chance (CueCard's Monte-Carlo over noisy shots). AlphaGo's use of a policy network, in pool terms: the prior
says where to look, the simulation decides.

The shots enter through the search's ``playable`` hook (the map of candidates to the shots an action type plays),
so the search itself is untouched: ``python -m agents.league --players search prior:runs/<run>`` plays it.
"""
from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from billiards_env.players import BasePlayer

#: Angle offsets (rad), speed factors and tip offsets of the variants of the policy's own shot.
PRIOR_ANGLES = (0.0, 0.0008, -0.0008, 0.002, -0.002, 0.005, -0.005)
PRIOR_SPEEDS = (1.0, 0.8, 1.25, 0.65, 1.5)
PRIOR_TIPS = ((0.0, 0.0), (0.0, -0.3), (0.0, 0.3), (-0.25, 0.0), (0.25, 0.0), (0.0, -0.15), (0.0, 0.15))
#: Shots re-run under noise when the sweep's simulations go to the re-runs (:meth:`PriorSearchPlayer.settings_for`).
REALLOCATED_TOP_K = 10
#: The pot chance of the easiest shot (under the noise's angle spread) below which the sweep stays under noise: on a
#: hard table its safeties and kicks are worth more than surer estimates of poor pots (with the 9-ball job's scorer,
#: 55.5% of 1000 games against the search with this, 52.7% reallocating on every table with a pot: agents/README.md).
REALLOCATE_POT_CHANCE = 0.3


def pot_chance(state: Any, ease_noise: float) -> float:
    """The chance of potting the easiest shot from where the cue ball lies, the cue angle erring with the env's
    angle noise (at least ``ease_noise``): the search's own position measure
    (:func:`billiards_env.players.search.next_shot_ease`) of the table as it stands."""
    from billiards_env.players.search import next_shot_ease

    b = state.balls
    sigma = max(state.settings.angle_noise, ease_noise)
    return float(next_shot_ease(state.table, b.radius, b.pos[None], b.on_table[None], 0, [list(state.view.targets)],
                                sigma, physics=state.physics)[0])


class _PriorPlayable:
    """The search's ``playable`` hook: candidates through an action type, except the sweep's, which become the
    policy's proposals (``proposals``: ``(angle, speed, side, top)`` rows, played through the same type)."""

    def __init__(self, inner: Any, proposals: np.ndarray) -> None:
        self.inner = inner
        self.proposals = proposals
        self.actions = getattr(inner, "actions", {})

    def __call__(self, cands: list[tuple[float, float, float, float, str]]
                 ) -> list[tuple[float, float, float, float, str]]:
        sweep = [k for k, c in enumerate(cands) if c[4] == "sweep"]
        out = list(cands)
        for m, k in enumerate(sweep[:len(self.proposals)]):
            a, v, sd, tp = (float(x) for x in self.proposals[m])
            out[k] = (a, v, sd, tp, "prior")
        played = self.inner(out) if self.inner is not None else out
        return [(p[0], p[1], p[2], p[3], c[4]) for p, c in zip(played, out)]

    def action_for(self, angle: float, speed: float, side: float, top: float) -> Any:
        return self.inner.action_for(angle, speed, side, top) if self.inner is not None else None


class PriorSearchPlayer(BasePlayer):
    """The search player with a trained policy's proposals (see the module docstring). ``policy``: a
    :class:`agents.games.TrainedPlayer` (it observes in its own types and names the shot it means). A player
    (:class:`~billiards_env.players.BasePlayer`: ``shot(state, obs, codec)``, ``act(state, obs, codec)``)."""

    def __init__(self, policy: Any, seed: int | None = 0, settings: Any = None, reallocate: bool = True,
                 min_pot_chance: float = REALLOCATE_POT_CHANCE) -> None:
        from billiards_env.players.search import SearchPlayer, SearchSettings

        self.policy = policy
        self.reallocate = reallocate
        self.min_pot_chance = min_pot_chance
        self.search = SearchPlayer(seed, settings or SearchSettings())
        self.name = f"search+prior({policy.name})"

    def reset(self, seed: int | None = None) -> None:
        self.search.reset(seed)
        self.policy.reset(seed)

    def budget(self) -> int:
        """Sweep candidates per decision: the proposals' share of the search's budget."""
        st = self.search.settings
        return int(st.sweep_angles) * len(st.sweep_speeds)

    def settings_for(self, state: Any, n_proposals: int, noisy: bool = True) -> Any:
        """The search's settings for a search with ``n_proposals`` proposals. Under shot noise (``noisy``), with
        ``reallocate`` and a pot to play (the policy's type lists one from where the cue ball is, and the easiest
        has at least a ``min_pot_chance`` chance, :data:`REALLOCATE_POT_CHANCE` by default: :func:`pot_chance`), the
        sweep shrinks to the proposals and the simulations it frees go to the noisy re-runs
        (:data:`REALLOCATED_TOP_K` shots, as many samples each as the budget allows): the same simulations per
        decision, spent on the proposals' margins
        instead of the directions the policy did not choose. Else the search's own (without noise the re-runs only
        break ties: 48.5% against the search with them, 50.3% without, over 1000 games)."""
        st = self.search.settings
        at = self.policy.action_type
        slots = at.slots(state) if hasattr(at, "slots") else None
        if not (self.reallocate and noisy) or slots is None or slots.count == 0 or n_proposals == 0:
            return st
        if self.min_pot_chance > 0.0 and pot_chance(state, st.ease_noise) < self.min_pot_chance:
            return st  # a hard table: the sweep's safeties and kicks stay
        n_speeds = len(st.sweep_speeds)
        angles = -(-n_proposals // n_speeds)
        freed = (int(st.sweep_angles) - angles) * n_speeds + st.top_k * st.robust_samples
        top_k = max(st.top_k, REALLOCATED_TOP_K)
        return dataclasses.replace(st, sweep_angles=angles, top_k=top_k, robust_samples=freed // top_k)

    def proposals(self, state: Any, shot: Any, spin: bool) -> np.ndarray:
        """``(angle, speed, side, top)`` rows: the policy's shot and its variants, then its speed factor and tip
        offsets on the other candidate shots of its type, at most :meth:`budget` rows."""
        rows: list[tuple[float, float, float, float]] = []
        lo, hi = state.settings.speed_range
        tips = PRIOR_TIPS if spin else ((0.0, 0.0),)
        own = (float(shot.side), float(shot.top))
        for da in PRIOR_ANGLES:  # the shot itself, aimed a little either side
            rows.append((shot.angle + da, shot.speed, *own))
        for f in PRIOR_SPEEDS[1:]:
            for sd, tp in ((own,) + tuple(t for t in tips if t != own)):
                rows.append((shot.angle, min(max(shot.speed * f, lo), hi), sd, tp))
        for sd, tp in tips:
            if (sd, tp) != own:
                rows.append((shot.angle, shot.speed, sd, tp))
        at = self.policy.action_type
        slots = at.slots(state) if hasattr(at, "slots") else None
        if slots is not None and not slots.in_hand:
            for s in slots.slots:  # every other (ball, pocket) at the policy's speed factor and spin
                if s.shot is None:
                    continue
                v = min(max(s.shot.speed * shot.speed / max(self._base_speed(state, shot), 1e-9), lo), hi)
                for f in PRIOR_SPEEDS:
                    rows.append((s.shot.angle, min(max(v * f, lo), hi), *own))
        out = np.array(rows[: self.budget()], dtype=np.float64).reshape(-1, 4)
        return out

    def _base_speed(self, state: Any, shot: Any) -> float:
        """The own speed of the candidate the policy chose (its shot's speed without the power factor)."""
        at = self.policy.action_type
        slots = at.slots(state)
        best = min((s for s in slots.slots if s.shot is not None), default=None,
                   key=lambda s: abs(math.remainder(s.shot.angle - shot.angle, 2 * math.pi)))
        return best.shot.speed if best is not None else shot.speed

    def choose(self, state: Any, obs: Any, codec: Any) -> np.ndarray:
        """The action (in ``codec``) of the best shot the search finds with the policy's proposals."""
        from billiards_env.players.context import shot_context, to_action
        from billiards_env.players.geometric import break_shot
        from billiards_env.players.search import Judge, placement_candidates, playable_shots, search_shot

        ctx = shot_context(state, codec)
        if ctx.game is not None and ctx.game.game_state.break_shot:
            place, angle, speed = break_shot(ctx)
            return to_action(codec, state, angle, speed, place=place)
        self.policy.prepare(state, codec)
        mine = self.policy.policy_shot(state)
        st = self.search.settings
        places: list[Any] = [None]
        if ctx.place_area is not None:
            sigma = max(ctx.angle_noise, st.ease_noise)
            own = placement_candidates(ctx, max(st.placements, 1), sigma=sigma)
            if mine.place is not None:  # the policy's place first (once: a scorer's is one of the search's own)
                own = [p for p in own if math.hypot(p[0] - mine.place[0], p[1] - mine.place[1]) > 1e-6]
            places = ([mine.place] if mine.place is not None else []) + own
            places = places[:max(st.placements, 1)]
        judge = Judge(ctx) if ctx.game is not None else None
        best = None
        for place in places:
            with state.cue_moved_to(place):
                # the policy's place gets its proposals; the search's own places keep its sweep
                prop = self.proposals(state, mine, ctx.tip_offsets) if place == mine.place else np.zeros((0, 4))
                play = _PriorPlayable(playable_shots(state, codec, place), prop)
                noisy = ctx.angle_noise > 0 or ctx.speed_noise > 0 or ctx.tip_noise > 0
                settings = self.settings_for(state, len(prop), noisy) if place == mine.place else st
                angle, speed, out = search_shot(ctx, settings, self.search.rng, None, play, judge)
            if best is None or out.robust > best[3].robust:
                best = (place, angle, speed, out, play)
        place, angle, speed, out, play = best
        with state.cue_moved_to(place):
            calls = self.search.calls_for(ctx, angle, speed, out)
        action = to_action(codec, state, angle, speed, place=place, side=out.side, top=out.top, **calls)
        searched = play.action_for(angle, speed, out.side, out.top)
        if searched is not None:
            dims = 4 if codec.spin else 2
            action[:dims] = searched[:dims]
        return action


def prior_search_player(path: str, game: str = "nine_ball", seed: int = 0,
                        reallocate: bool = True, min_pot_chance: float = REALLOCATE_POT_CHANCE
                        ) -> PriorSearchPlayer:
    """The search player with the trained policy at ``path`` (a run folder or model zip of ``game``, or
    ``scorer:<file>``, an option scorer of 9-ball) as its prior; ``reallocate``: see
    :meth:`PriorSearchPlayer.settings_for` (False: the league's ``prior-plain:<path>``, named so)."""
    if path.startswith("scorer:"):
        from .option_policies import scorer_player

        if game != "nine_ball":
            raise ValueError(f"{path}: a scorer plays 9-ball, not {game}")
        policy = scorer_player(path[len("scorer:"):])
    else:
        from .games import trained_player

        policy = trained_player(path, game)
    p = PriorSearchPlayer(policy, seed, reallocate=reallocate, min_pot_chance=min_pot_chance)
    if reallocate and min_pot_chance == 0.0:
        p.name += " reallocating on every table"
    if not reallocate:
        p.name += " without reallocation"
    return p


__all__ = ["PriorSearchPlayer", "prior_search_player", "pot_chance", "PRIOR_ANGLES", "PRIOR_SPEEDS", "PRIOR_TIPS",
           "REALLOCATE_POT_CHANCE"]
