"""``BilliardsThreeCushion-v0``: a game of three-cushion (carom) under UMB-style rules against an opponent policy."""
from __future__ import annotations

from typing import Any

from .base import BilliardsEnv


class ThreeCushionEnv(BilliardsEnv):
    """
    ## Description

    Three-cushion on the pocketless match table (2.84 m x 1.42 m) with 61.5 mm balls, under the spin model
    (sliding, rolling, spin, throw off the cushions): the shooter's cue ball, the opponent's cue ball and the red.
    A point is scored when the shooter's cue ball meets both other balls and at least three cushions before it
    meets the second one; the shooter plays on after a point, else the turn passes
    (:class:`billiards_env.rules.three_cushion.ThreeCushion`). The game goes to ``rules={"target_points": N}``
    (default 10). The agent plays the white, the opponent the yellow. Each ``step`` is one shot of the agent; the
    opponent's inning (``opponent``, default the geometric player; ``"search"`` simulates spin shots and is far
    stronger) is played inside the same ``step``. Rules and
    simplifications: docs/rules.md.

    ## Action Space

    ``Box(-1, 1, (4,), float32)``: aim, power, side, top (the tip offsets, on the disc of legal offsets); no ball in
    hand in three-cushion.

    | Num | Action | Min | Max | Meaning |
    |-----|--------|-----|-----|---------|
    | 0 | aim | -1 | 1 | by ``action_type``: ``absolute`` (default) angle = pi * a[0]; ``relative`` / ``ghost`` from the red |
    | 1 | power | -1 | 1 | speed = speed_min + (a[1] + 1) / 2 * (speed_max - speed_min); default 0.5 .. 6.0 m/s |
    | 2, 3 | side, top | -1 | 1 | tip offsets, the square mapped onto the disc of radius max_tip_offset |

    ## Observation Space

    ``Box(0, 1, (15,), float32)``: the positions of the shooter's cue ball, the opponent's cue ball and the red
    (always in that order: the rows follow the turn), their pocketed flags (always 0), then 6 game features: own
    points / target, opponent's points / target, own run / target, the opening shot, the agent's turn, own innings /
    the innings limit.

    ## Rewards

    ``+win_reward`` (1.0) for a game won, ``-loss_penalty`` (1.0) for one lost; shaping (off by default):
    ``+pot_reward`` per point the agent scores, ``-foul_penalty`` per foul. A Python float.

    ## Starting State

    The UMB start position of the breaker (``first_shooter``), whose opening shot must meet the red first.
    ``reset(options={"positions": (3, 2) rows white, yellow, red, "score": (a, b), "break_shot": False})`` sets up a
    table by hand with the agent to play.

    ## Episode End

    Terminated when a player reaches the target (``info["winner"]``; -1 for a draw with an innings limit);
    truncated after ``max_shots`` (200) shots of the agent. ``info`` (fixed keys and forms:
    ``docs/infos.md``; rows shooter first): the keys every game shares (``Billiards9Ball-v0``), ``point``,
    ``cushions`` (the cue ball's cushion contacts before the second ball), ``score``, ``run`` and the shot keys of
    every env.

    ## Arguments

    ``gym.make("BilliardsThreeCushion-v0", render_mode=None, config=None, **overrides)``: any key of
    :class:`billiards_env.envs.config.EnvConfig`: ``opponent`` (``"geometric"``, ``"search"``, ``"random"`` or
    None), ``rules`` (``ThreeCushionOptions``: ``target_points``, ``break_red_first``, ``miss_is_foul``,
    ``max_innings``, ``equalizing_inning``)... Two players: :mod:`billiards_env.multi.three_cushion_v0`.

    ## Version History

    * v0: initial version.
    """

    scene = "three_cushion"
    env_id = "BilliardsThreeCushion-v0"

    def set_opponent(self, policy: Any) -> None:
        """Play against ``policy`` (a player, a player's name, an SB3 model, a callable, or None)."""
        self.task.set_opponent(policy)
