"""A policy that scores the shots the ``candidates_position`` observation lists, trained on a teacher's choices.

The teacher's choices in the ``candidates`` action type are discrete in effect (a pot slot, one of a few speeds, draw
/ none / follow) and depend on the position each leaves. Cloned into a Gaussian policy (SAC's actor, agents.distill)
they are averaged where the teacher picks between modes: a follow and a draw shot average to a half-follow that
leaves the cue ball where neither would, and the clones stay below the geometric player whichever teacher they copy
(agents/README.md, "Distillation"). This policy chooses instead: every (pot slot, power, top) of the observation's
grid is an *option* with its own features (the slot's 12 ``candidates`` values, the grid point's 5 position-map
values, the power and top, the game's features); a small MLP scores each option (the same weights for all: the
options are a set) and the policy plays the best (``top`` as the tip, no side). Trained by cross-entropy on the
teacher's choices mapped to the nearest option (:func:`fit`); several fits with different seeds can be summed (an
ensemble). The break is action 0 (the geometric player's full break). With the cue ball in hand it chooses the place
too: the observation is made again with the cue ball lying at each of the search player's own places
(``option_policies.hand_places``: the teacher searches from the same ones), the options of all places are scored
together and the best (place, shot, power, top) is played; the teacher's ball-in-hand labels train that choice as
one softmax over all places (``option_policies.hand_label``). Where no option exists (no pot from where the cue ball
lies, nor from any place) a fallback policy plays (the SAC clone of the same labels), else action 0.

    python -m agents.scorer --labels runs/<distill run>/labels.npz [more.npz ...] --ensemble 3 \
        --fallback runs/<distill run>/bc_model.zip --out runs/scorer.pt --games 400

A saved scorer plays in the league as ``scorer:<path>``. The policy itself is :class:`agents.option_policies.Scorer`.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Sequence

import numpy as np

from .option_policies import (N_GRID, N_SLOTS, OPTION_FEATURES, RULE_KWARGS, Scorer, action_of, fit, option_of,  # noqa: F401
                              options, reinforce)
from .option_policies import scorer_player as league_player

def main(argv: Sequence[str] | None = None) -> int:
    """``python -m agents.scorer``: train a scorer on label files (agents.distill's ``labels.npz``) and play it
    against the geometric player without noise and under olympiad noise."""
    import torch

    p = argparse.ArgumentParser(prog="python -m agents.scorer", description=main.__doc__)
    p.add_argument("--labels", type=Path, nargs="*", default=[], help="label files to fit on (cross-entropy)")
    p.add_argument("--init", type=Path, default=None, help="a saved scorer to start from instead of fitting")
    p.add_argument("--reinforce", type=int, default=0, help="games of RL fine-tuning (REINFORCE) after")
    p.add_argument("--rl-lr", type=float, default=3e-4)
    p.add_argument("--out", type=Path, required=True)
    p.add_argument("--epochs", type=int, default=60)
    p.add_argument("--hidden", type=int, default=64)
    p.add_argument("--ensemble", type=int, default=1, help="nets fitted with different seeds, their scores summed")
    p.add_argument("--fallback", type=Path, default=None, help="an SB3 model zip in the same types for the states "
                   "without options (ball in hand, no pot), e.g. agents.distill's bc_model.zip of the same labels")
    p.add_argument("--games", type=int, default=400, help="league games against the geometric player (0: none)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--league-seed", type=int, default=0, help="the league's racks: game k on seed league_seed + k")
    args = p.parse_args(argv)
    torch.set_num_threads(1)
    if args.init is not None:
        nets, info = Scorer.load(args.init).nets, {"init": str(args.init)}
    else:
        if not args.labels:
            p.error("give --labels to fit on, or --init")
        obs = np.concatenate([np.load(f)["obs"] for f in args.labels])
        act = np.concatenate([np.load(f)["actions"] for f in args.labels])
        nets, infos = [], []
        for k in range(max(args.ensemble, 1)):
            net, one = fit(obs, act, args.epochs, args.hidden, seed=args.seed + k)
            nets.append(net)
            infos.append(one)
        info = {**infos[0], "holdout_agreement": [i["holdout_agreement"] for i in infos]}
    print(f"scorer: {info}", flush=True)
    net = nets[0]
    if args.reinforce:
        kw = {**RULE_KWARGS, "opponent": "geometric", "first_shooter": "random"}
        rl = reinforce(net, args.reinforce, kw, lr=args.rl_lr, seed=args.seed,
                       log=lambda m: print(m, flush=True))
        print(f"reinforce: {rl}", flush=True)
    sc = Scorer(nets, args.fallback)
    sc.save(args.out)
    print(f"saved {args.out}")
    if args.games:
        from .league import print_vs_geometric

        print_vs_geometric("scorer", league_player(args.out), args.games, args.league_seed, ("0", "olympiad"))
    return 0


__all__ = ["options", "option_of", "action_of", "fit", "reinforce", "Scorer", "league_player", "main", "OPTION_FEATURES"]


if __name__ == "__main__":
    sys.exit(main())
