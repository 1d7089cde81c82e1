"""``Billiards8Ball-v0``: a game of 8-ball under WPA-style rules against an opponent policy."""
from __future__ import annotations

from typing import Any

from .base import BilliardsEnv


class EightBallEnv(BilliardsEnv):
    """
    ## Description

    8-ball on a WPA 9-ft table (2.54 m x 1.27 m; six pockets with their jaws, ``table={"preset": "wpa"}``):
    balls 1-15 racked in a triangle on the foot spot (the 8
    in the middle, a solid and a stripe in the back corners, the others shuffled from ``env.np_random``). The agent
    breaks with the cue ball in hand behind the head string; the table is open after the break, the first ball
    legally pocketed gives its shooter that group (solids 1-7 or stripes 9-15), and the player who clears his
    group and then pockets the 8 in the called pocket wins (:class:`billiards_env.rules.EightBall`). Pocketing the
    8 early, on a foul or in another pocket loses. Fouls give the opponent the cue ball in hand anywhere (after a
    scratch on the break: in the kitchen). Each ``step`` is one shot of the agent; the opponent (``opponent``,
    default the geometric player) replies inside the same ``step``. Rules and simplifications: docs/rules.md.

    ## Action Space

    ``Box(-1, 1, (5,), float32)`` (more with options). Finite values outside the box are clipped; NaN or inf
    raise ``ValueError``.

    | Num | Action | Min | Max | Meaning |
    |-----|--------|-----|-----|---------|
    | 0 | aim | -1 | 1 | by ``action_type``: ``absolute`` (default) angle = pi * a[0]; ``relative`` / ``ghost`` from the lowest legal ball |
    | 1 | power | -1 | 1 | speed = speed_min + (a[1] + 1) / 2 * (speed_max - speed_min); default 0.5 .. 8.0 m/s |
    | 2, 3 | place_x, place_y | -1 | 1 | with ball in hand only: where the cue ball goes, linearly over the allowed area; moved to the nearest legal point if it overlaps a ball |
    | 4 | pocket | -1 | 1 | the pocket called for the 8, ``floor((a + 1) / 2 * 6)`` in the table's pocket order; read only when the agent is on the 8 |

    With ``rules={"call_eight": False}`` (any pocket wins, as pooltool relaxed it) there is no ``pocket`` dim; with
    ``spin_action`` two dims ``side``, ``top`` come after ``power``. ``env.unwrapped.action_from_shot(angle,
    speed, place=(x, y), pocket=k)`` gives the action of a shot.

    ## Observation Space

    ``Box(0, 1, (59,), float32)``: ball positions (cue, 1..15) normalised by the table size, 16 pocketed flags,
    then 11 game features: ball in hand, ball in hand in the kitchen, break shot, lowest legal ball / 15, own group
    (solids, stripes; both 0 on an open table), on the 8, own fouls in a row / 2, opponent's fouls in a row / 2,
    push-out available (0), the agent's turn.

    ## Rewards

    ``+win_reward`` (1.0) when the agent wins, ``-loss_penalty`` (1.0) when it loses; shaping (off by default):
    ``+pot_reward`` per ball pocketed by the agent on a legal shot, ``-foul_penalty`` per foul. A Python float.

    ## Starting State

    The rack on the foot spot, the cue ball on the head spot, the agent to break (``first_shooter``).
    ``reset(options={"positions": ..., "pocketed": ..., "ball_in_hand": ..., "groups": ("solids", "stripes"),
    "break_shot": False})`` sets up a table after the break with the agent (player 0) to shoot.

    ## Episode End

    Terminated when the game is over (``info["winner"]``: 0 the agent, 1 the opponent, -1 while it goes on), or with ``opponent=None`` at the agent's first foul or
    miss; truncated after ``max_shots`` (150) shots of the agent. ``info`` as in ``Billiards9Ball-v0`` (``groups``: 0
    open table, 1 the agent has the solids, 2 the stripes).

    ## Arguments

    ``gym.make("Billiards8Ball-v0", render_mode=None, config=None, **overrides)``: ``opponent``, ``rules``
    (``EightBallOptions``: ``call_eight``, ``eight_on_break``, ``break_scratch_ball_in_hand``...), and every key of
    :class:`billiards_env.envs.config.EnvConfig`. ``env.unwrapped.set_opponent(policy)``; two players:
    :mod:`billiards_env.multi`.

    ## Version History

    * v0: initial version.
    """

    scene = "eight_ball"
    env_id = "Billiards8Ball-v0"

    def set_opponent(self, policy: Any) -> None:
        """Play against ``policy`` (a player, ``shot(state, obs, codec)``; an SB3 model, a callable, or None)."""
        self.task.set_opponent(policy)
