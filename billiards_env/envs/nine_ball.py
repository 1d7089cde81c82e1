"""``Billiards9Ball-v0``: a game of 9-ball under WPA-style rules against an opponent policy."""
from __future__ import annotations

from typing import Any

from .base import BilliardsEnv


class NineBallEnv(BilliardsEnv):
    """
    ## Description

    9-ball on a WPA 9-ft table (2.54 m x 1.27 m; six pockets with their jaws, ``table={"preset": "wpa"}``):
    balls 1-9 racked in a diamond on the foot spot (1 at
    the apex, 9 in the middle, the others shuffled from ``env.np_random``). The agent breaks with the cue ball in
    hand behind the head string, then the players alternate turns under :class:`billiards_env.rules.NineBall`:
    the lowest ball on the table must be hit first, a ball must be pocketed or some ball must reach a cushion
    after the contact, a scratch or any other foul gives the opponent the cue ball in hand anywhere, and the 9
    pocketed on a legal shot wins (on a foul it is respotted). Three fouls in a row lose. Each ``step`` is one
    shot of the agent; when the turn passes, the opponent (``opponent``, default the geometric player) shoots
    inside the same ``step`` until it is the agent's turn again or the game is over. Rules and simplifications:
    docs/rules.md.

    ## Action Space

    ``Box(-1, 1, (4,), float32)`` (more with options). Finite values outside the box are clipped; NaN or inf
    raise ``ValueError``.

    | Num | Action | Min | Max | Meaning |
    |-----|--------|-----|-----|---------|
    | 0 | aim | -1 | 1 | by ``action_type``: ``absolute`` (default) angle = pi * a[0]; ``relative`` from the direction to the lowest ball; ``ghost`` the direction the lowest ball leaves in |
    | 1 | power | -1 | 1 | speed = speed_min + (a[1] + 1) / 2 * (speed_max - speed_min); default 0.5 .. 8.0 m/s |
    | 2, 3 | place_x, place_y | -1 | 1 | with ball in hand only: where the cue ball goes, linearly over the allowed area (the kitchen on the break, the table after a foul); moved to the nearest legal point if it overlaps a ball |

    With ``spin_action`` (and ``friction="spin"``) two dims ``side``, ``top`` come after ``power``; with
    ``rules={"push_out": True}`` a last dim ``push`` (> 0 declares a push-out on the shot after the break).
    ``env.unwrapped.action_from_shot(angle, speed, place=(x, y))`` gives the action of a shot.

    ## Observation Space

    ``Box(0, 1, (41,), float32)``: ball positions (cue, 1..9) normalised by the table size, 10 pocketed flags,
    then 11 game features: ball in hand, ball in hand in the kitchen, break shot, lowest ball / 15, own group
    (solids, stripes: 0 in 9-ball), on the 8 (0), own fouls in a row / 2, opponent's fouls in a row / 2, push-out
    available, the agent's turn. ``observation_type="features"`` adds the pockets seen from the lowest ball.

    ## Rewards

    ``+win_reward`` (1.0) when the agent wins, ``-loss_penalty`` (1.0) when it loses; shaping (off by default):
    ``+pot_reward`` per ball pocketed by the agent on a legal shot, ``-foul_penalty`` per foul. A Python float.

    ## Starting State

    The rack on the foot spot, the cue ball on the head spot, the agent to break with the cue ball in hand in the
    kitchen (``first_shooter``: ``agent``, ``opponent`` or ``random``). ``reset(options={"positions": ...,
    "pocketed": ..., "ball_in_hand": False | "anywhere" | "kitchen", "break_shot": False})`` sets up a table
    after the break with the agent to shoot.

    ## Episode End

    Terminated when the game is over (``info["winner"]``: 0 the agent, 1 the opponent, -1 while it goes on), or with
    ``opponent=None`` (run-out practice) at the agent's first foul or miss. Truncated after ``max_shots`` (100)
    shots of the agent. ``info`` (the same keys at reset and every step, fixed
    forms: ``docs/infos.md``, ``env.unwrapped.info_schema``): ``is_success`` (the agent won), ``foul``,
    ``foul_reason`` and ``call`` (reason codes), ``turn_over``, ``winner``, ``shooter``, ``legal_targets`` (a mask
    over the rows), ``opponent_shots``, ``opponent_pocketed``, ``opponent_fouls``, ``ball_in_hand`` (a code, for the
    agent's next shot), ``groups`` and the shot keys of every env (``pocketed``, ``scratch``, ``first_contact``,
    ``n_events``, ``sim_time``, ``status``, ``shots``, ``angle``, ``speed``, ``side``, ``top``).

    ## Arguments

    ``gym.make("Billiards9Ball-v0", render_mode=None, config=None, **overrides)``. Any key of
    :class:`billiards_env.envs.config.EnvConfig`: ``opponent`` (``"geometric"``, ``"search"``, ``"random"`` or
    None), ``rules`` (``NineBallOptions``: ``push_out``, ``three_foul_rule``, ``break_rail_balls``),
    ``angle_noise``... ``env.unwrapped.set_opponent(policy)`` plays against any policy (a player, an SB3 model,
    a callable). Two players: :mod:`billiards_env.multi` (PettingZoo).

    ## Version History

    * v0: initial version.
    """

    scene = "nine_ball"
    env_id = "Billiards9Ball-v0"

    def set_opponent(self, policy: Any) -> None:
        """Play against ``policy`` (a player, ``shot(state, obs, codec)``; an SB3 model, a callable, or None)."""
        self.task.set_opponent(policy)
