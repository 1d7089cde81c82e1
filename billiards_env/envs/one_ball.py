"""``BilliardsOneBall-v0``: pot one randomly placed object ball in one shot."""
from __future__ import annotations

from .base import BilliardsEnv


class OneBallEnv(BilliardsEnv):
    """
    ## Description

    A pool table (2.54 m x 1.27 m, six pockets) with the cue ball and one object ball (ball ``1``) placed at
    random. The agent takes one shot: it chooses the direction and the speed with which the cue ball is
    struck; the exact event-driven physics (rolling friction, ball and cushion restitution, pockets as capture
    circles) runs until every ball is at rest. The episode is that one shot: the task is to pocket the object
    ball without pocketing the cue ball.

    ## Action Space

    ``Box(-1, 1, (2,), float32)``. Finite values outside the box are clipped; NaN or inf raise ``ValueError``.
    Any array of exactly two numbers is read as ``(a[0], a[1])``, so a batched ``(1, 2)`` action is accepted.

    | Num | Action | Min | Max | Meaning |
    |-----|--------|-----|-----|---------|
    | 0 | aim | -1 | 1 | ``action_type="absolute"`` (default): angle = pi * a[0] (0 = +x, counter-clockwise). ``action_type="relative"``: angle = direction cue -> ball 1 + pi * a[0], so 0 hits it full |
    | 1 | power | -1 | 1 | speed = speed_min + (a[1] + 1) / 2 * (speed_max - speed_min); default 0.5 .. 5.0 m/s |

    ``env.unwrapped.action_from_shot(angle, speed)`` gives the action of a shot (in the active aim mode).

    ## Observation Space

    ``Box(0, 1, (6,), float32)``: positions normalised by the table size, then pocketed flags. A pocketed
    ball's position reads 0.

    | Num | Observation | Min | Max |
    |-----|-------------|-----|-----|
    | 0 | cue ball x / table length | 0 | 1 |
    | 1 | cue ball y / table width | 0 | 1 |
    | 2 | ball 1 x / table length | 0 | 1 |
    | 3 | ball 1 y / table width | 0 | 1 |
    | 4 | cue ball pocketed (always 0: a pocketed cue ball is re-spotted) | 0 | 1 |
    | 5 | ball 1 pocketed | 0 | 1 |

    ## Rewards

    ``pot_reward`` (1.0) if ball 1 is pocketed, ``- scratch_penalty`` (1.0) if the cue ball is pocketed,
    ``- miss_penalty`` (0.0) if the cue ball touches no ball, ``- step_penalty`` (0.0) per shot. A Python float.

    ## Starting State

    Both balls uniformly at random on the table, at least ``cushion_margin`` (0.05 m) from the cushions,
    ``pocket_margin`` (0.15 m, centre to pocket centre) from every pocket and ``ball_gap`` (0.01 m) apart,
    drawn from ``env.np_random``: ``reset(seed=s)`` gives the same table, and the same actions then give
    the same outcomes bit for bit. ``reset(options={"positions": [[x, y], [x, y]]})`` sets a scene instead.

    ## Episode End

    Terminated after the one shot (``single_shot: true``). ``info["is_success"]`` is True when ball 1 was
    pocketed and the cue ball was not. A pocketed cue ball is put back on the head spot (or the nearest free
    point along the head string) so the final observation is a valid table.

    ``step()`` after a step that returned ``terminated`` or ``truncated`` raises
    ``gymnasium.error.ResetNeeded``: call ``reset()`` (vector envs and SB3 do).

    ``info`` (the same keys at reset, blank, and at every step: ``docs/infos.md``): ``is_success``, ``pocketed``
    (a mask over the rows), ``scratch``, ``first_contact`` (the row of the first ball the cue ball hit, -1 none),
    ``n_events``, ``sim_time`` (simulated seconds), ``status`` (0 rest, 1 time_cap, 2 event_cap), ``shots``,
    ``angle``, ``speed``, ``side`` and ``top`` (of the shot actually played, noise included).

    ## Arguments

    ``gym.make("BilliardsOneBall-v0", render_mode=None, config=None, **overrides)``: ``render_mode`` is
    ``"human"`` (a window animating every shot; it needs a display, else ``reset()`` raises
    ``HeadlessDisplayError``), ``"rgb_array"`` (the table now) or ``"rgb_array_list"``
    (every animation frame since the last render, for ``RecordVideo``). Any key of
    :class:`billiards_env.envs.config.EnvConfig` can be overridden (``speed_max=3.0``, ``action_type="relative"``,
    ``angle_noise=0.01``, ``render_width=400``...) and ``config="scene.yaml"`` layers a YAML file over the
    defaults, which live in ``billiards_env/envs/scenes/one_ball.yaml``.

    ## Version History

    * v0: initial version.
    """

    scene = "one_ball"
    env_id = "BilliardsOneBall-v0"
