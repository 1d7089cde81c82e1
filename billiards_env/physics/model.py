"""Physics parameters of a scene: friction law, its constants, ball-ball restitution and (spin model) friction in
collisions."""
from __future__ import annotations

import math
from dataclasses import dataclass

from .codes import DRAG, FRICTION_LAWS, ROLLING, SPIN
from .errors import SceneError, check_non_negative, check_positive, check_unit_interval

G = 9.81  #: gravitational acceleration (m/s^2), fixed by the spec


@dataclass(frozen=True)
class Physics:
    """How balls slow down and bounce.

    ``rolling``: constant deceleration ``mu_roll * g`` against the velocity until the ball stops.
    ``drag``: ``dv/dt = -drag_k * v`` (the lecture's per-frame friction factor ``f`` over a frame ``dt0`` is
    ``drag_k = -ln(f) / dt0``, see :meth:`drag_k_from_factor`); a ball stops when its speed falls below
    ``min_speed``. ``min_speed`` also applies under ``rolling`` (default 0: roll until the closed-form stop).
    ``spin``: balls slide (``mu_slide``), roll (``mu_roll``) and spin about the vertical (``mu_spin``), and
    collisions exchange spin through ``ball_friction`` (throw; 0: none) and ``cushion_friction``
    (see :mod:`.spin_motion` and :mod:`.spin_collide`). The spin fields are unused by the other laws.
    """

    friction: str = "rolling"
    mu_roll: float = 0.01
    drag_k: float = 0.0
    min_speed: float = 0.0
    ball_restitution: float = 0.95
    mu_slide: float = 0.2
    mu_spin: float = 0.0127
    ball_friction: float = 0.0
    cushion_friction: float = 0.2

    def __post_init__(self) -> None:
        if self.friction not in FRICTION_LAWS:
            raise SceneError(
                f"physics.friction: unknown law {self.friction!r}; use one of {', '.join(FRICTION_LAWS)}"
            )
        check_non_negative("physics.mu_roll", self.mu_roll)
        check_non_negative("physics.drag_k", self.drag_k)
        check_non_negative("physics.min_speed", self.min_speed)
        check_unit_interval("physics.ball_restitution", self.ball_restitution)
        for name in ("mu_slide", "mu_spin", "ball_friction", "cushion_friction"):
            check_non_negative(f"physics.{name}", getattr(self, name))
        if self.friction == "spin" and self.min_speed != 0.0:
            raise SceneError(f"physics.min_speed: {self.min_speed} is not used by the spin model, whose balls stop "
                             "at their closed-form times; leave it 0 (it applies to 'rolling' and 'drag')")

    @property
    def law_code(self) -> int:
        return {"rolling": ROLLING, "drag": DRAG, "spin": SPIN}[self.friction]

    @property
    def deceleration(self) -> float:
        """Rolling deceleration ``mu_roll * g`` (m/s^2): of the ``rolling`` law, and of a rolling ball under
        ``spin``; 0 under ``drag``."""
        return self.mu_roll * G if self.friction != "drag" else 0.0

    @property
    def drag_rate(self) -> float:
        """Drag rate ``k`` (1/s); 0 under ``rolling``."""
        return self.drag_k if self.friction == "drag" else 0.0

    @property
    def path_args(self) -> tuple[int, float, float]:
        """``(law, a, k)`` for the distance-domain motion law of :mod:`.motion` (``stop_distance``,
        ``speed_after_distance``, ``launch_speed``): ``a`` the rolling deceleration, ``k`` the drag rate under
        ``drag`` or the sliding deceleration ``mu_slide g`` under ``spin`` (a ball set moving without spin slides
        before it rolls)."""
        if self.friction == "spin":
            return self.law_code, self.deceleration, self.mu_slide * G
        return self.law_code, self.deceleration, self.drag_rate

    @staticmethod
    def drag_k_from_factor(factor: float, frame_dt: float) -> float:
        """The drag rate ``k`` equivalent to the lecture's friction factor ``factor`` applied every ``frame_dt`` s."""
        if not 0.0 < factor <= 1.0:
            raise SceneError(f"friction factor: must be in (0, 1], got {factor}")
        check_positive("frame_dt", frame_dt)
        return -math.log(factor) / frame_dt
