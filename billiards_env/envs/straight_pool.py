"""``BilliardsStraightPool-v0``: straight pool (14.1 continuous) under WPA-style rules against an opponent policy."""
from __future__ import annotations

from typing import Any

from .base import BilliardsEnv


class StraightPoolEnv(BilliardsEnv):
    """
    ## Description

    Straight pool (14.1 continuous) on a WPA 9-ft table (2.54 m x 1.27 m; six pockets with their jaws,
    ``table={"preset": "wpa"}``): balls 1-15 racked on the foot spot (the 1 and the 5 in the back corners, the
    others shuffled from ``env.np_random``). The agent breaks with the cue ball in hand behind the head string,
    then the players alternate innings under :class:`billiards_env.rules.straight_pool.StraightPool`: every shot
    calls a ball and a pocket; the called ball in the called pocket scores a point for it and one for every other
    ball of the stroke, and the shooter continues; otherwise the balls pocketed are spotted and the inning ends.
    A foul costs a point (a scratch gives the cue ball in hand behind the head string); a third foul in a row costs
    15 more and the offender re-breaks a full rack. The opening break must pocket the called ball or drive the cue
    ball and two object balls to a cushion (else -2, the table as it lies). When one ball is left the 14 others are
    re-racked and play goes on. The first to ``rules["target"]`` points (150) wins. Each ``step`` is one shot of the
    agent; when the turn passes the opponent (``opponent``, default the geometric player) shoots inside the same
    ``step``. Rules and simplifications: docs/games.md.

    ## Action Space

    ``Box(-1, 1, (6,), float32)`` (more with ``spin_action``). Finite values outside the box are clipped; NaN or
    inf raise ``ValueError``.

    | Num | Action | Min | Max | Meaning |
    |-----|--------|-----|-----|---------|
    | 0 | aim | -1 | 1 | ``absolute`` (default): angle = pi * a[0]; ``relative`` / ``ghost``: from the lowest ball |
    | 1 | power | -1 | 1 | speed = speed_min + (a[1] + 1) / 2 * (speed_max - speed_min); default 0.5 .. 8.0 m/s |
    | 2, 3 | place_x, place_y | -1 | 1 | ball in hand only: where the cue ball goes (moved to the nearest legal point) |
    | 4 | ball | -1 | 1 | the ball called: row 1 + floor((a + 1) / 2 * 15) (a ball not on the table: no call) |
    | 5 | pocket | -1 | 1 | the pocket called: floor((a + 1) / 2 * 6), the table's pocket order |

    With ``spin_action`` (and ``friction="spin"``) two dims ``side``, ``top`` come after ``power``.
    ``env.unwrapped.action_from_shot(angle, speed, place=(x, y), ball=row, pocket=k)`` gives the action of a shot.

    ## Observation Space

    ``Box(0, 1, (56,), float32)``: ball positions (cue, 1..15) normalised by the table size, 16 pocketed flags,
    then 8 game features: ball in hand, break shot, own score / target, opponent's score / target (clipped to
    [0, 1]), own fouls in a row / 2, opponent's fouls in a row / 2, object balls on the table / 15, the agent's turn.

    ## Rewards

    ``+win_reward`` (1.0) when the agent wins, ``-loss_penalty`` (1.0) when it loses; shaping (off by default):
    ``+pot_reward`` per point the agent scores, ``-foul_penalty`` per foul. A Python float.

    ## Starting State

    The rack on the foot spot, the cue ball on the head spot, the agent to break with the cue ball in hand behind
    the head string (``first_shooter``). ``reset(options={"positions": (16, 2), "pocketed": (16,), "score": (a, b),
    "ball_in_hand": False | "kitchen" | "anywhere", "break_shot": False})`` sets up a table with the agent to shoot.

    ## Episode End

    Terminated when a player reaches the target (``info["winner"]``: 0 the agent, 1 the opponent, -1 while the
    game goes on), or with ``opponent=None`` at the agent's first shot that passes the turn. Truncated after
    ``max_shots`` (400) shots of the agent. ``info`` (fixed keys and forms: ``docs/infos.md``): the keys every
    game shares (``Billiards9Ball-v0``), ``points`` (the shot's change of its shooter's score), ``score``,
    ``ball_in_hand`` (a code), ``rerack`` (balls racked after the shot) and the shot keys of every env.

    ## Arguments

    ``gym.make("BilliardsStraightPool-v0", render_mode=None, config=None, **overrides)``: any key of
    :class:`billiards_env.envs.config.EnvConfig`: ``opponent`` (``"geometric"``, ``"search"``, ``"random"`` or
    None), ``rules`` (``StraightPoolOptions``: ``target``, ``break_rail_balls``, ``break_violation_points``,
    ``three_foul_penalty``), ``noise="olympiad"``... Two players: :mod:`billiards_env.multi.straight_pool_v0`.
    The native vector env plays it one table at a time (its compiled games are 9-ball and 8-ball).

    ## Version History

    * v0: initial version.
    """

    scene = "straight_pool"
    env_id = "BilliardsStraightPool-v0"

    def set_opponent(self, policy: Any) -> None:
        """Play against ``policy`` (a player, a player's name, an SB3 model, a callable, or None)."""
        self.task.set_opponent(policy)
