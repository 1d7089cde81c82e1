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

from typing import Sequence

from .option_policies import RULE_KWARGS, PositionRulePlayer, position_action  # noqa: F401
from .option_policies import rule_player as league_player

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
