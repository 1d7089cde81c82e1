"""``BilliardsThreeBalls-v0``: clear three randomly placed object balls within a shot limit."""
from __future__ import annotations

from .base import BilliardsEnv


class ThreeBallsEnv(BilliardsEnv):
    """
    ## Description

    A pool table (2.54 m x 1.27 m, six pockets) with the cue ball and three object balls (``1``, ``2``,
    ``3``) placed at random. Each step is one shot of the cue ball (direction and speed), simulated with the
    exact event-driven physics until every ball is at rest. The task is to pocket all three object balls in
    as few shots as possible, within a limit of 15 shots, without pocketing the cue ball.

    ## Action Space

    ``Box(-1, 1, (2,), float32)``. Finite values outside the box are clipped; NaN or inf raise ``ValueError``.
    Any array of exactly two numbers is read as ``(a[0], a[1])``, so a batched ``(1, 2)`` action is accepted.

    | Num | Action | Min | Max | Meaning |
    |-----|--------|-----|-----|---------|
    | 0 | aim | -1 | 1 | ``action_type="absolute"`` (default): angle = pi * a[0] (0 = +x, counter-clockwise). ``action_type="relative"``: angle = direction cue -> lowest-numbered object ball on the table + pi * a[0] |
    | 1 | power | -1 | 1 | speed = speed_min + (a[1] + 1) / 2 * (speed_max - speed_min); default 0.5 .. 5.0 m/s |

    ``env.unwrapped.action_from_shot(angle, speed)`` gives the action of a shot (in the active aim mode).

    ## Observation Space

    ``Box(0, 1, (12,), float32)``: positions normalised by the table size, then pocketed flags. A pocketed
    ball's position reads 0.

    | Num | Observation | Min | Max |
    |-----|-------------|-----|-----|
    | 0, 1 | cue ball x / length, y / width | 0 | 1 |
    | 2, 3 | ball 1 x / length, y / width | 0 | 1 |
    | 4, 5 | ball 2 x / length, y / width | 0 | 1 |
    | 6, 7 | ball 3 x / length, y / width | 0 | 1 |
    | 8 | cue ball pocketed (always 0: a pocketed cue ball is re-spotted) | 0 | 1 |
    | 9, 10, 11 | balls 1, 2, 3 pocketed | 0 | 1 |

    ## Rewards

    Per shot: ``pot_reward`` (1.0) per object ball pocketed, ``- scratch_penalty`` (1.0) if the cue ball is
    pocketed, ``- miss_penalty`` (0.0) if the cue ball touches no ball, ``- step_penalty`` (0.0). A Python
    float.

    ## Starting State

    All four balls uniformly at random, at least ``cushion_margin`` (0.05 m) from the cushions,
    ``pocket_margin`` (0.15 m) from every pocket centre and ``ball_gap`` (0.01 m) apart, drawn from
    ``env.np_random`` (``reset(seed=s)`` is reproducible bit for bit). ``reset(options={"positions": ...,
    "pocketed": ...})`` sets a scene instead.

    ## Episode End

    Terminated when every object ball is pocketed; ``info["is_success"]`` is then True unless the cue ball
    was pocketed on that last shot. Truncated after ``max_shots`` (15) shots otherwise. A pocketed cue ball
    (scratch) is put back on the head spot, or the nearest free point along the head string, and play goes on;
    object balls pocketed on a scratch stay down and count.

    ``step()`` after a step that returned ``terminated`` or ``truncated`` raises
    ``gymnasium.error.ResetNeeded``: call ``reset()`` (vector envs and SB3 do).

    ``info`` (the same keys at reset and every step: ``docs/infos.md``): ``is_success``, ``pocketed``, ``scratch``,
    ``first_contact``, ``n_events``, ``sim_time``, ``status``, ``shots``, ``angle``, ``speed``, ``side``, ``top``.

    ## Arguments

    ``gym.make("BilliardsThreeBalls-v0", render_mode=None, config=None, **overrides)``; render modes
    ``"human"``, ``"rgb_array"``, ``"rgb_array_list"``. Any key of
    :class:`billiards_env.envs.config.EnvConfig` can be overridden; ``config="scene.yaml"`` layers a YAML file
    over the defaults in ``billiards_env/envs/scenes/three_balls.yaml``.

    ## Version History

    * v0: initial version.
    """

    scene = "three_balls"
    env_id = "BilliardsThreeBalls-v0"
