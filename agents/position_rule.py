"""What the ``candidates_position`` observation alone allows in 9-ball: a hand-written rule, no learning, no search.

The ``candidates_position`` observation (:class:`billiards_env.envs.observations.CuePositionFeatures`) states, for
every candidate pot and every (``power``, ``top``) of its grid, whether the ball drops, whether the cue ball
scratches, and the chance of potting the next ball from where it stops. :func:`position_action` plays the grid point
that maximises ``ease now x drops x no scratch x (c + ease next)`` (``ease now``: the slot's own ease value of the
``candidates`` observation), softest power excluded by default (under the olympiad speed noise the geometric
player's speed, which brings the ball to the pocket just rolling, falls short; the search player's labels lie at
1.6-3 times it); with nothing playable (ball in hand, the break, no pot) it plays action 0, the geometric player's
shot. ``python -m agents.position_rule`` plays it against the geometric player on the league's two-player env
(:func:`agents.league.play_pair`): the ceiling of what the observation alone states, for the distilled agents that
learn from the same types (agents/README.md, "9-ball").
"""
from __future__ import annotations

from typing import Any, Sequence

import numpy as np

from billiards_env.envs.candidates import SLOT_FEATURES
from billiards_env.envs.position import POINT_VALUES, POSITION_FEATURES, POWERS, TOPS

#: The env kwargs the rule plays in (the 9-ball distillation's types, spin model).
RULE_KWARGS = {"action_type": "candidates", "observation_type": "candidates_position", "friction": "spin",
               "spin_action": True, "noise": "olympiad"}


def position_action(obs: np.ndarray, n_slots: int = 4, n_balls: int = 10, c: float = 0.3,
                    min_power: int = 1, n_action: int = 6) -> np.ndarray:
    """The rule of the module docstring on one ``candidates_position`` observation (``n_slots`` candidate slots,
    ``n_balls`` balls); ``min_power``: the grid powers left out, softest first. Returns the ``candidates`` action
    (``n_action`` dims: slot, power, side, top, then placement, 0)."""
    o = np.asarray(obs, dtype=np.float64).reshape(-1)
    base = 3 * n_balls
    slots = o[base:base + SLOT_FEATURES * n_slots].reshape(n_slots, SLOT_FEATURES)
    grid = o[base + SLOT_FEATURES * n_slots:base + (SLOT_FEATURES + POSITION_FEATURES) * n_slots].reshape(
        n_slots, len(POWERS) * len(TOPS), POINT_VALUES)
    act = np.zeros(n_action, np.float32)
    best, choice = 0.0, None
    for k in range(n_slots - 1):
        if slots[k, 0] == 0.0 or slots[k, 2] == -1.0 or not grid[k, :, 2:4].any():
            continue
        v = slots[k, 7] * grid[k, :, 0] * (1.0 - grid[k, :, 1]) * (c + grid[k, :, 4])
        v[:min_power * len(TOPS)] = 0.0
        g = int(np.argmax(v))
        if v[g] > best:
            best, choice = float(v[g]), (k, g)
    if choice is None:
        return act
    k, g = choice
    act[0] = (k + 0.5) / n_slots
    act[1] = POWERS[g // len(TOPS)]
    act[3] = TOPS[g % len(TOPS)]
    return act


class PositionRulePlayer:
    """:func:`position_action` as a player of the 9-ball env whose observation it is given (``act(env, obs)``: the
    env must be in :data:`RULE_KWARGS`' types); a distillation teacher (``python -m agents.distill --teacher
    position_rule``)."""

    name = "position_rule"

    def __init__(self, c: float = 0.3, min_power: int = 1) -> None:
        self.c = c
        self.min_power = min_power

    def reset(self, seed: int | None = None) -> None:
        """No state."""

    def act(self, env: Any, obs: Any) -> np.ndarray:
        u = env.unwrapped
        if u.config.observation_type != "candidates_position" or u.config.action_type != "candidates":
            raise ValueError("position_rule: plays the 'candidates' action on the 'candidates_position' observation, "
                             f"not {u.config.action_type!r} on {u.config.observation_type!r}")
        return position_action(obs, u.config.candidate_slots, u.n_balls, self.c, self.min_power,
                               u.action_space.shape[0])


def league_player(c: float = 0.3, min_power: int = 1) -> Any:
    """The rule as a league player (:class:`agents.games.TrainedPlayer`: it observes the table in its own types and
    plays on the league's absolute-action env)."""
    from .games import TrainedPlayer

    n_slots, n_balls = 4, 10
    return TrainedPlayer(f"position_rule(c={c}, min_power={min_power})",
                         lambda o: position_action(o, n_slots, n_balls, c, min_power), RULE_KWARGS)


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m agents.position_rule``: the rule against the geometric player, without noise and under
    ``noise="olympiad"``, on the league's racks (seats swapped every game)."""
    import argparse

    import billiards_env  # noqa: F401
    from billiards_env.players import make_player

    from .evaluate import wilson_interval as wilson
    from .league import league_env_kwargs, play_pair

    p = argparse.ArgumentParser(prog="python -m agents.position_rule", description=main.__doc__)
    p.add_argument("--games", type=int, default=400)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--c", type=float, default=0.3, help="weight of potting now against the next shot's ease")
    p.add_argument("--min-power", type=int, default=1, help="grid powers left out, softest first")
    p.add_argument("--noise", nargs="+", default=["0", "olympiad"])
    args = p.parse_args(argv)
    rule = ("position_rule", league_player(args.c, args.min_power))
    geo = ("geometric", make_player("geometric", seed=args.seed, game="nine_ball"))
    for noise in args.noise:
        kw = league_env_kwargs([rule, geo], True, noise if noise != "0" else 0.0)
        r = play_pair("nine_ball", rule, geo, args.games, args.seed, kw)
        lo, hi = wilson(r.wins_a, r.games)
        print(f"position rule vs geometric, noise {noise}: {r.wins_a}-{r.wins_b} = {100 * r.wins_a / r.games:.1f}% "
              f"[{100 * lo:.0f}, {100 * hi:.0f}], break-and-runs {r.break_and_runs_by[0]} vs {r.break_and_runs_by[1]}, "
              f"{r.ms_per_decision[0]:.2f} ms a decision")
    return 0


__all__ = ["RULE_KWARGS", "position_action", "PositionRulePlayer", "league_player", "main"]


if __name__ == "__main__":
    import sys

    sys.exit(main())
