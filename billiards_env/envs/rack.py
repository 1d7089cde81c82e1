"""``BilliardsRack-v0``: break a full 15-ball rack and clear the table within a shot limit."""
from __future__ import annotations

from .base import BilliardsEnv


class RackEnv(BilliardsEnv):
    """
    ## Description

    A pool table (2.54 m x 1.27 m, six pockets) set up for a game: the cue ball on the head spot and the 15
    object balls in a touching triangle whose apex sits on the foot spot (the standard order: 1 at the apex,
    8 in the middle of the third row). The first action is the break; then each step is one shot, simulated
    with the exact event-driven physics until every ball is at rest. The task is to pocket all 15 balls
    within 50 shots without pocketing the cue ball. There are no fouls other than the scratch and no called
    shots.

    ## Action Space

    ``Box(-1, 1, (2,), float32)``. Finite values outside the box are clipped; NaN or inf raise ``ValueError``.
    Any array of exactly two numbers is read as ``(a[0], a[1])``, so a batched ``(1, 2)`` action is accepted.

    | Num | Action | Min | Max | Meaning |
    |-----|--------|-----|-----|---------|
    | 0 | aim | -1 | 1 | ``action_type="absolute"`` (default): angle = pi * a[0] (0 = +x, towards the rack, counter-clockwise). ``action_type="relative"``: angle = direction cue -> lowest-numbered object ball on the table + pi * a[0] |
    | 1 | power | -1 | 1 | speed = speed_min + (a[1] + 1) / 2 * (speed_max - speed_min); default 0.5 .. 8.0 m/s (a harder top speed for the break) |

    ``env.unwrapped.action_from_shot(angle, speed)`` gives the action of a shot (in the active aim mode).

    ## Observation Space

    ``Box(0, 1, (48,), float32)``: positions normalised by the table size, then pocketed flags; rows are in
    ball-number order (cue, 1, 2, ..., 15). A pocketed ball's position reads 0.

    | Num | Observation | Min | Max |
    |-----|-------------|-----|-----|
    | 0, 1 | cue ball x / length, y / width | 0 | 1 |
    | 2k, 2k+1 | ball k x / length, y / width (k = 1..15) | 0 | 1 |
    | 32 | cue ball pocketed (always 0: a pocketed cue ball is re-spotted) | 0 | 1 |
    | 32 + k | ball k pocketed (k = 1..15) | 0 | 1 |

    ## Rewards

    Per shot: ``pot_reward`` (1.0) per object ball pocketed, ``- scratch_penalty`` (1.0) if the cue ball is
    pocketed, ``- miss_penalty`` (0.0) if the cue ball touches no ball, ``- step_penalty`` (0.0). A Python
    float.

    ## Starting State

    The same rack every episode (``placement: rack``, ``rack_gap`` 0: touching), cue ball on the head spot
    (``cue_placement: head_spot``; ``kitchen`` draws it behind the head string from ``env.np_random``
    instead). ``reset(options={"positions": ..., "pocketed": ...})`` sets a scene instead.

    ## Episode End

    Terminated when every object ball is pocketed (``info["is_success"]`` True unless the cue ball was
    pocketed on that last shot); truncated after ``max_shots`` (50) shots. A pocketed cue ball is put back
    on the head spot, or the nearest free point along the head string, and play goes on.

    ``step()`` after a step that returned ``terminated`` or ``truncated`` raises
    ``gymnasium.error.ResetNeeded``: call ``reset()`` (vector envs and SB3 do).

    ``info`` (the same keys at reset and every step: ``docs/infos.md``): ``is_success``, ``pocketed``, ``scratch``,
    ``first_contact``, ``n_events``, ``sim_time``, ``status``, ``shots``, ``angle``, ``speed``, ``side``, ``top``.

    ## Arguments

    ``gym.make("BilliardsRack-v0", render_mode=None, config=None, **overrides)``; render modes ``"human"``,
    ``"rgb_array"``, ``"rgb_array_list"``. Any key of :class:`billiards_env.envs.config.EnvConfig` can be
    overridden; ``config="scene.yaml"`` layers a YAML file over the defaults in
    ``billiards_env/envs/scenes/rack.yaml``.

    ## Version History

    * v0: initial version.
    """

    scene = "rack"
    env_id = "BilliardsRack-v0"
