"""Named codes shared by the compiled kernels and their Python callers: event kinds, shot status, ball motion
states, friction laws and the spin model's collision models.

The kernels use the plain ``int`` constants (numba reads module globals as compile-time constants); Python code
may use the :class:`enum.IntEnum` views, which compare equal to the same ints. This module is the one home of
these numbers: everything else imports them from here (or from :mod:`billiards_env.physics`).
"""
from __future__ import annotations

from enum import IntEnum

# --- event kinds (the event log's ``kind`` column) --------------------------------------------------------------
EV_COLLISION = 0  #: two balls collide (``other``: the other ball's row)
EV_CUSHION = 1  #: a ball hits a cushion (``other``: 0 left, 1 right, 2 bottom, 3 top)
EV_POCKET = 2  #: a ball is pocketed (``other``: the pocket index)
EV_STOP = 3  #: a ball comes to rest
EV_JAM = 4  #: a contact cluster is jammed (``other``: the number of balls in it), see :mod:`.collide`
EV_ROLL = 5  #: spin model: a sliding ball starts rolling (its slip reaches 0)
EV_SPIN = 6  #: spin model: a rolling ball stops moving but still spins about the vertical
EVENT_KINDS = ("collision", "cushion", "pocket", "stop", "jam", "roll", "spin")


class EventKind(IntEnum):
    """The event log's ``kind`` column as an enum (equal to the ``EV_*`` ints)."""

    COLLISION = EV_COLLISION
    CUSHION = EV_CUSHION
    POCKET = EV_POCKET
    STOP = EV_STOP
    JAM = EV_JAM
    ROLL = EV_ROLL
    SPIN = EV_SPIN


# --- shot status ------------------------------------------------------------------------------------------------
STATUS_REST = 0  #: every ball at rest or pocketed
STATUS_TIME_CAP = 1  #: balls still moving at ``max_time``
STATUS_EVENT_CAP = 2  #: ``max_events`` reached
STATUS_NAMES = ("rest", "time_cap", "event_cap")


class Status(IntEnum):
    """How a shot ended (equal to the ``STATUS_*`` ints; ``STATUS_NAMES[code]`` is its name)."""

    REST = STATUS_REST
    TIME_CAP = STATUS_TIME_CAP
    EVENT_CAP = STATUS_EVENT_CAP


# --- friction laws ----------------------------------------------------------------------------------------------
ROLLING = 0  #: constant deceleration ``mu_roll g`` against the velocity
DRAG = 1  #: ``dv/dt = -k v``
SPIN = 2  #: the spin model: sliding, rolling and spinning balls (see :mod:`.spin_motion`)
FRICTION_LAWS = ("rolling", "drag", "spin")

# --- collision models of the spin model (see :mod:`.model`) ------------------------------------------------------
BB_FRICTIONLESS = 0  #: ball-ball: the normal impulse (plus the constant Coulomb friction ``ball_friction`` if > 0)
BB_ALCIATORE = 1  #: ball-ball: friction mu(v) = a + b exp(-c v) of the contact points' slip speed v (pooltool's)
BALL_BALL_MODELS = ("frictionless", "alciatore")
CU_IMPULSE = 0  #: cushion: one frictional impulse (restitution, Coulomb friction capped at no-slip)
CU_STRONGE = 1  #: cushion: Stronge's compliant frictional impact (pooltool's StrongeCompliant)
CU_MATHAVAN = 2  #: cushion: Mathavan et al. (2010), integrated over the impulse
CUSHION_MODELS = ("impulse", "stronge", "mathavan")

# --- ball motion states (spin model; the same numbers as pooltool's) --------------------------------------------
MS_STATIONARY = 0  #: at rest
MS_SPINNING = 1  #: not moving, spinning about the vertical
MS_SLIDING = 2  #: the cloth contact point slips
MS_ROLLING = 3  #: rolling without slipping
MS_POCKETED = 4
MOTION_STATES = ("stationary", "spinning", "sliding", "rolling", "pocketed")

# --- cushions ---------------------------------------------------------------------------------------------------
#: Cushion ids used in event records: the wall each one is (x=0, x=L, y=0, y=W).
CUSHION_NAMES = ("left", "right", "bottom", "top")

__all__ = [
    "EV_COLLISION", "EV_CUSHION", "EV_POCKET", "EV_STOP", "EV_JAM", "EVENT_KINDS", "EventKind",
    "EV_ROLL", "EV_SPIN", "STATUS_REST", "STATUS_TIME_CAP", "STATUS_EVENT_CAP", "STATUS_NAMES", "Status",
    "ROLLING", "DRAG", "SPIN", "FRICTION_LAWS", "CUSHION_NAMES", "BB_FRICTIONLESS", "BB_ALCIATORE",
    "BALL_BALL_MODELS", "CU_IMPULSE", "CU_STRONGE", "CU_MATHAVAN", "CUSHION_MODELS",
    "MS_STATIONARY", "MS_SPINNING", "MS_SLIDING", "MS_ROLLING", "MS_POCKETED", "MOTION_STATES",
]
