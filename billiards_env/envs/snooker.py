"""``BilliardsSnooker-v0``: a frame of snooker under WPBSA-style rules against an opponent policy."""
from __future__ import annotations

from typing import Any

from .base import BilliardsEnv


class SnookerEnv(BilliardsEnv):
    """
    ## Description

    Snooker on the 12 ft table (3.569 m x 1.778 m, six rounded snooker pockets with their jaws) with 52.5 mm balls: 15 reds in a triangle
    behind the pink, the six colours on their spots, the cue ball in the D. The players alternate visits under
    :class:`billiards_env.rules.snooker.Snooker`: a red, then a colour (re-spotted), while reds remain, then the
    colours in order (yellow 2 .. black 7); a foul gives the opponent 4 points or the value of the ball concerned;
    after an in-off the next striker plays from the D. The colour after a red is the first colour hit (no
    nomination needed); a free ball is taken automatically (rules option ``auto_free_ball``); the miss rule is an
    option (``rules={"miss_rule": True}``). The frame goes to the higher score (a tie is decided on the
    re-spotted black). Each ``step`` is one shot of the agent; when the turn passes the opponent (``opponent``,
    default the geometric player) plays its visit inside the same ``step``. Rules and simplifications:
    docs/rules.md.

    ## Action Space

    ``Box(-1, 1, (4,), float32)`` (more with ``spin_action``). Finite values outside the box are clipped; NaN or
    inf raise ``ValueError``.

    | Num | Action | Min | Max | Meaning |
    |-----|--------|-----|-----|---------|
    | 0 | aim | -1 | 1 | by ``action_type``: ``absolute`` (default) angle = pi * a[0]; ``relative`` / ``ghost`` from a ball on |
    | 1 | power | -1 | 1 | speed = speed_min + (a[1] + 1) / 2 * (speed_max - speed_min); default 0.3 .. 6.0 m/s |
    | 2, 3 | place_x, place_y | -1 | 1 | with the cue ball in hand only: where it goes in the D (place_y across the table, place_x from the arc to the baulk line); moved to the nearest legal point |

    ## Observation Space

    ``Box(0, 1, (76,), float32)``: 22 ball positions (cue, red1..red15, yellow, green, brown, blue, pink, black)
    normalised by the table size, 22 pocketed flags, then 10 game features: ball in hand, on a red, on any colour,
    the named colour on / 7, own score / 147, opponent's score / 147, points left / 147, own break / 147, a free
    ball possible, the agent's turn.

    ## Rewards

    ``+win_reward`` (1.0) for a frame won, ``-loss_penalty`` (1.0) for one lost; shaping (off by default):
    ``+pot_reward`` per point the agent scores, ``-foul_penalty`` per foul. A Python float.

    ## Starting State

    The frame's opening layout, the agent to break off from the D (``first_shooter``). ``reset(options={"positions":
    (22, 2), "pocketed": (22,), "on": "red" | "colour" | a colour, "score": (a, b), "ball_in_hand": False | "d"})``
    sets up a table by hand with the agent to play.

    ## Episode End

    Terminated when the frame is over (``info["winner"]``: 0 the agent, 1 the opponent); truncated after
    ``max_shots`` (250) shots of the agent. ``info`` (fixed keys and forms: ``docs/infos.md``):
    the keys every game shares (``Billiards9Ball-v0``), ``points`` (scored by the shot), ``foul_points``, ``score``,
    ``on`` (the ball on now, a code), ``break``, ``ball_in_hand`` (1: in the D) and the shot keys of every env.

    ## Arguments

    ``gym.make("BilliardsSnooker-v0", render_mode=None, config=None, **overrides)``: any key of
    :class:`billiards_env.envs.config.EnvConfig`: ``opponent`` (``"geometric"``, ``"search"``, ``"random"`` or
    None), ``rules`` (``SnookerOptions``: ``free_ball``, ``auto_free_ball``, ``miss_rule``, ``miss_limit``),
    ``noise="olympiad"``... Two players: :mod:`billiards_env.multi.snooker_v0`.

    ## Version History

    * v0: initial version.
    """

    scene = "snooker"
    env_id = "BilliardsSnooker-v0"

    def set_opponent(self, policy: Any) -> None:
        """Play against ``policy`` (a player, a player's name, an SB3 model, a callable, or None)."""
        self.task.set_opponent(policy)
