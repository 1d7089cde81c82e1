"""The interface of the compiled solvers: a named parameter record in, a named result out.

The kernels take the scene's constants as one record (``params[0]``, a numpy structured array of dtype
:data:`PARAMS_DTYPE`) and read them by name (``p.length``, ``p.decel``...): a model that needs more constants adds a
field here, nothing is renumbered. They return a :class:`KernelResult`, whose fields callers read by name.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from .codes import BALL_BALL_MODELS, CUSHION_MODELS
from .model import G
from .pocket_specs import N_SEGMENTS, N_TIPS, SEG_COLS, TIP_COLS

#: Room for a jaw table's cushions in the parameter record (a six-pocket table uses 18 segments and 12 tips).
MAX_SEGMENTS = N_SEGMENTS
MAX_TIPS = N_TIPS
#: A jaw table's pockets, each with its two jaw faces and two tips: the groups of :func:`wall_groups`.
MAX_GROUPS = N_TIPS // 2

if TYPE_CHECKING:  # pragma: no cover
    from .model import Physics
    from .table import Table

#: Separation-speed floor of the inelastic-collapse guard (m/s), see :mod:`.collide`.
CONTACT_SPEED_FLOOR = 1e-3

#: Columns of the state logs (``sc_state``): ``x, y, vx, vy, on_table``; the spin model's add ``wx, wy, wz,
#: motion_state``.
N_STATE_COLS = 5
N_STATE_COLS_SPIN = 9

#: The parameter record the kernels read. Fields a model does not use are ignored by its kernel.
PARAMS_DTYPE = np.dtype(
    [
        ("length", np.float64),  # table playing area (m)
        ("width", np.float64),
        ("e_cushion", np.float64),  # cushion restitution
        ("e_ball", np.float64),  # ball-ball restitution
        ("law", np.int64),  # friction law code (codes.ROLLING, codes.DRAG, ...)
        ("decel", np.float64),  # rolling deceleration mu_roll * g (m/s^2); 0 under drag
        ("drag_k", np.float64),  # drag rate k (1/s); 0 under rolling
        ("min_speed", np.float64),  # a ball slower than this stops (m/s)
        ("max_time", np.float64),  # simulated-time cap (s)
        ("speed_floor", np.float64),  # inelastic-collapse guard (m/s)
        ("g", np.float64),  # gravitational acceleration (m/s^2)
        ("mu_slide", np.float64),  # spin model: sliding friction
        ("mu_roll", np.float64),  # rolling resistance
        ("mu_spin", np.float64),  # spin model: spinning friction
        ("ball_friction", np.float64),  # spin model: ball-ball friction (throw)
        ("cushion_friction", np.float64),  # spin model: cushion friction
        ("ball_ball", np.int64),  # spin model: ball-ball model code (codes.BB_*)
        ("alciatore_a", np.float64),  # ball_ball alciatore: mu(v) = a + b exp(-c v)
        ("alciatore_b", np.float64),
        ("alciatore_c", np.float64),
        ("cushion", np.int64),  # spin model: cushion model code (codes.CU_*)
        ("cushion_height", np.float64),  # the cushion nose's height (m); -1: at each ball's equator
        ("omega_ratio", np.float64),  # cushion stronge: tangential / normal frequency ratio
        ("squirt", np.float64),  # squirt throttle of the strike (0: none)
        ("cue_end_mass", np.float64),  # the cue tip's end mass (kg) in the squirt angle
        # A jaw table's cushions (:mod:`.pocket_specs`); none (0 rows) under the capture model, whose cushions are
        # the four edges of the playing area.
        ("n_segs", np.int64),  # straight cushions used: rails, then jaw faces
        ("segs", np.float64, (MAX_SEGMENTS, SEG_COLS)),  # ax, ay, bx, by, nx, ny (normal to the open side)
        ("n_tips", np.int64),  # rounded jaw tips used
        ("tips", np.float64, (MAX_TIPS, TIP_COLS)),  # cx, cy, radius
        ("n_groups", np.int64),  # a jaw table's pockets' wall groups (wall_groups), 0 if its walls are not grouped
        ("groups", np.float64, (MAX_GROUPS, 3)),  # cx, cy, radius of a circle holding a pocket's faces and tips
    ],
    align=True,
)


def kernel_params(table: "Table", physics: "Physics", max_time: float) -> np.ndarray:
    """The parameter record of ``table`` and ``physics`` with the time cap ``max_time`` (shape ``(1,)``)."""
    p = np.zeros(1, PARAMS_DTYPE)
    r = p[0]
    r["length"] = table.length
    r["width"] = table.width
    r["e_cushion"] = table.cushion_restitution
    r["e_ball"] = physics.ball_restitution
    r["law"] = physics.law_code
    r["decel"] = physics.deceleration
    r["drag_k"] = physics.drag_rate
    r["min_speed"] = physics.min_speed
    r["max_time"] = max_time
    r["speed_floor"] = CONTACT_SPEED_FLOOR
    r["g"] = G
    r["mu_roll"] = physics.mu_roll
    for name in ("mu_slide", "mu_spin", "ball_friction", "cushion_friction", "alciatore_a", "alciatore_b",
                 "alciatore_c", "omega_ratio", "squirt", "cue_end_mass"):
        r[name] = getattr(physics, name)
    r["ball_ball"] = BALL_BALL_MODELS.index(physics.ball_ball)
    r["cushion"] = CUSHION_MODELS.index(physics.cushion)
    r["cushion_height"] = -1.0 if physics.cushion_height is None else physics.cushion_height
    segs, tips = table.walls()
    r["n_segs"] = len(segs)
    r["segs"][: len(segs)] = segs
    r["n_tips"] = len(tips)
    r["tips"][: len(tips)] = tips
    groups = wall_groups(segs, tips)
    r["n_groups"] = len(groups)
    r["groups"][: len(groups)] = groups
    return p


def wall_groups(segs: np.ndarray, tips: np.ndarray) -> np.ndarray:
    """Circles ``(cx, cy, radius)`` each holding one pocket's walls, so that the exact solver can pass over a pocket
    whose walls a ball cannot reach (:func:`.walls.ray_wall_hit`). The walls are in :func:`.pocket_specs.build_walls`'
    order: the rails, then two jaw faces per pocket; two tips per pocket. Group ``g``: the faces ``n_rails + 2g``,
    ``n_rails + 2g + 1`` and the tips ``2g``, ``2g + 1``; none (shape ``(0, 3)``) for walls not in that order."""
    n_tips = len(tips)
    n_rails = len(segs) - n_tips
    if n_tips == 0 or n_tips % 2 or n_rails < 0:
        return np.zeros((0, 3))
    out = np.zeros((n_tips // 2, 3))
    for g in range(n_tips // 2):
        ends = np.array([segs[n_rails + 2 * g + q, 2 * e:2 * e + 2] for q in range(2) for e in range(2)])
        centres = tips[2 * g:2 * g + 2, :2]
        c = np.vstack([ends, centres]).mean(axis=0)
        reach = max(float(np.hypot(*(ends - c).T).max()), float((np.hypot(*(centres - c).T) + tips[2 * g:2 * g + 2, 2]).max()))
        out[g] = (c[0], c[1], reach * (1.0 + 1e-9) + 1e-9)
    return out


class KernelResult(NamedTuple):
    """What a solver kernel returns (the ball arrays passed in are updated in place to the final state)."""

    status: int  #: codes.STATUS_*
    time: float  #: simulated time at the end (s)
    n_events: int
    pocket: np.ndarray  #: (N,) pocket index per ball, -1 if not pocketed in this shot
    pocketed_at: np.ndarray  #: (N,) time each ball was pocketed (NaN if not)
    ev_time: np.ndarray  #: (M,) event times
    ev_int: np.ndarray  #: (M, 3) kind, ball, other
    ev_speed: np.ndarray  #: (M,) impact speed (or the pocketed ball's speed)
    sc_time: np.ndarray  #: (K,) times of the logged state changes (only when recording)
    sc_ball: np.ndarray  #: (K,) ball of each logged state
    sc_state: np.ndarray  #: (K, C) the logged states: x, y, vx, vy, on_table (then model-specific columns)
    n_steps: int  #: time steps taken (step solver; 0 for exact)
    n_tunnelled: int  #: pairs that passed through each other within a step (step solver)


__all__ = ["wall_groups", "MAX_GROUPS", "N_STATE_COLS", "N_STATE_COLS_SPIN", "PARAMS_DTYPE", "CONTACT_SPEED_FLOOR", "kernel_params", "KernelResult"]
