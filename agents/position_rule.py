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

    from .league import print_vs_geometric

    p = argparse.ArgumentParser(prog="python -m agents.position_rule", description=main.__doc__)
    p.add_argument("--games", type=int, default=400)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--c", type=float, default=0.3, help="weight of potting now against the next shot's ease")
    p.add_argument("--min-power", type=int, default=1, help="grid powers left out, softest first")
    p.add_argument("--noise", nargs="+", default=["0", "olympiad"])
    args = p.parse_args(argv)
    print_vs_geometric("position rule", league_player(args.c, args.min_power), args.games, args.seed, args.noise)
    return 0


__all__ = ["RULE_KWARGS", "position_action", "PositionRulePlayer", "league_player", "main"]


if __name__ == "__main__":
    import sys

    sys.exit(main())
