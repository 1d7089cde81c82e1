"""Physics parameters of a scene: friction law, its constants, ball-ball restitution, and under the spin model the
collision models (ball-ball friction, cushion, squirt) and their constants; presets of them (:data:`PRESETS`)."""
from __future__ import annotations

import difflib
import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from .codes import BALL_BALL_MODELS, CUSHION_MODELS, DRAG, FRICTION_LAWS, ROLLING, SPIN
from .errors import SceneError, check_finite, check_non_negative, check_positive, check_unit_interval

G = 9.81  #: gravitational acceleration (m/s^2), fixed by the spec

#: pooltool's cue end mass (kg): its cue tip's effective mass in the squirt formula (``CueSpecs.end_mass``).
POOLTOOL_CUE_END_MASS = 0.170097 / 30
#: pooltool's cushion height (m) for pocket tables, ``0.64 * 2R`` (``PocketTableSpecs.cushion_height``).
POOLTOOL_CUSHION_HEIGHT = 0.64 * 2 * 0.028575

#: Named sets of physics fields. ``pooltool``: pooltool 0.6.0's default physics (``default_resolver()`` and
#: ``BallParams``; sources in docs/physics.md): the spin model with its friction constants, Alciatore's
#: speed-dependent ball-ball friction, Stronge's compliant cushion with the nose above the ball's centre, squirt.
PRESETS: dict[str, dict[str, Any]] = {
    "pooltool": {
        "friction": "spin", "mu_slide": 0.2, "mu_roll": 0.01, "mu_spin": 0.0127, "ball_restitution": 0.95,
        "cushion_friction": 0.2, "ball_ball": "alciatore", "alciatore_a": 0.009951, "alciatore_b": 0.108,
        "alciatore_c": 1.088, "cushion": "stronge", "cushion_height": POOLTOOL_CUSHION_HEIGHT, "omega_ratio": 1.8,
        "squirt": 1.0, "cue_end_mass": POOLTOOL_CUE_END_MASS,
    },
}


def _choice(name: str, value: str, allowed: tuple[str, ...]) -> None:
    if value not in allowed:
        close = difflib.get_close_matches(str(value), allowed, n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise SceneError(f"{name}: unknown value {value!r}{hint}; use one of {', '.join(allowed)}")


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

    Collision models of the spin model (refused by the other laws; the defaults are the models above):

    - ``ball_ball``: ``"frictionless"`` (the normal impulse, plus the constant Coulomb friction ``ball_friction``
      when it is > 0) or ``"alciatore"`` (pooltool's frictional inelastic collision: friction
      ``mu(v) = alciatore_a + alciatore_b exp(-alciatore_c v)`` of the contact points' slip speed ``v``, its
      Coulomb limit scaled by the separation speed: the throw of cut shots; :mod:`.spin_collide`);
    - ``cushion``: ``"impulse"`` (one frictional impulse), ``"stronge"`` (Stronge's compliant impact, tangential
      to normal frequency ratio ``omega_ratio`` in (1, 2); :mod:`.stronge`) or ``"mathavan"`` (Mathavan et al.
      2010, integrated over the impulse; :mod:`.cushion_models`); ``cushion_height``: the height (m) of the
      cushion's nose above the table, where the ball meets it (None: at each ball's equator);
    - ``squirt``: how much of the squirt of TP A-31 a side-english strike gets (0: none, 1: in full): the cue
      ball leaves at an angle to the cue that grows with the tip offset and the ratio of the ball's mass to the
      cue tip's end mass ``cue_end_mass`` (:func:`.spin_collide.strike_spin`).

    :meth:`from_preset` (and ``{"preset": name}`` in a scene's physics section) starts from a named set of these
    fields (:data:`PRESETS`), the fields given overriding it.
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
    ball_ball: str = "frictionless"
    alciatore_a: float = 0.009951
    alciatore_b: float = 0.108
    alciatore_c: float = 1.088
    cushion: str = "impulse"
    cushion_height: float | None = None
    omega_ratio: float = 1.8
    squirt: float = 0.0
    cue_end_mass: float = POOLTOOL_CUE_END_MASS

    @classmethod
    def from_preset(cls, preset: str, **overrides: Any) -> "Physics":
        """The physics of preset ``preset`` (:data:`PRESETS`, e.g. ``"pooltool"``) with ``overrides`` applied."""
        _choice("physics.preset", preset, tuple(PRESETS))
        return cls(**{**PRESETS[preset], **overrides})

    def with_fields(self, **changes: Any) -> "Physics":
        """A copy with ``changes`` applied (checked)."""
        return replace(self, **changes)

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
        self._check_collision_models()

    def _check_collision_models(self) -> None:
        _choice("physics.ball_ball", self.ball_ball, BALL_BALL_MODELS)
        _choice("physics.cushion", self.cushion, CUSHION_MODELS)
        for name in ("alciatore_a", "alciatore_b", "alciatore_c", "squirt"):
            check_non_negative(f"physics.{name}", getattr(self, name))
        check_positive("physics.cue_end_mass", self.cue_end_mass)
        check_finite("physics.omega_ratio", self.omega_ratio)
        if not 1.0 < self.omega_ratio < 2.0:
            raise SceneError(f"physics.omega_ratio: {self.omega_ratio} is outside (1, 2); Stronge's compliant "
                             "cushion needs a tangential to normal frequency ratio between 1 and 2 (pooltool: 1.8)")
        if self.cushion_height is not None:
            check_positive("physics.cushion_height", self.cushion_height)
        if self.friction != "spin":
            extra = [f"{name} {getattr(self, name)!r}" for name, plain in self.PLAIN_MODELS.items()
                     if getattr(self, name) != plain]
            if extra:
                raise SceneError(f"physics: {', '.join(extra)} needs the spin model (friction 'spin'); the scene's "
                                 f"friction is {self.friction!r}: set friction to 'spin' (or use the preset "
                                 f"'pooltool'), or leave "
                                 + ", ".join(f"{n} {p!r}" for n, p in self.PLAIN_MODELS.items() if any(
                                     e.startswith(n + " ") for e in extra)))
        if self.ball_ball == "alciatore" and self.ball_friction != 0.0:
            raise SceneError(f"physics.ball_friction: {self.ball_friction} is the constant friction coefficient of "
                             "ball_ball 'frictionless'; ball_ball 'alciatore' has its own, mu(v) = alciatore_a + "
                             "alciatore_b exp(-alciatore_c v): leave ball_friction 0")

    #: The collision-model fields and their values that every law runs (the others need the spin model).
    PLAIN_MODELS = {"ball_ball": "frictionless", "cushion": "impulse", "cushion_height": None, "squirt": 0.0}

    @property
    def plain_collisions(self) -> bool:
        """True if the spin model's optional collision models are all off (the kernels' original laws)."""
        return all(getattr(self, name) == plain for name, plain in self.PLAIN_MODELS.items())

    def check_cushion_height(self, radius: Any) -> None:
        """Raise if the cushion's nose height is outside ``[R, 2R)`` for a ball of radius ``R`` in ``radius``
        (the nose meets the ball between its equator and its top)."""
        h = self.cushion_height
        if h is None:
            return
        for r in np.asarray(radius, dtype=float).tolist():
            if not r <= h < 2.0 * r:
                raise SceneError(f"physics.cushion_height: {h} m puts the cushion's nose outside [R, 2R) = "
                                 f"[{r}, {2 * r}) m for a ball of radius {r} m; give a height between the ball's "
                                 "equator and its top (pooltool: 0.64 * 2R), or null for the equator")

    @property
    def law_code(self) -> int:
        return {"rolling": ROLLING, "drag": DRAG, "spin": SPIN}[self.friction]

    @property
    def has_spin(self) -> bool:
        """Balls carry angular velocities (the ``spin`` law): a strike's tip offsets put spin on the ball, and the
        spin kernels (:mod:`.kernels`) run its shots. The rolling and drag laws have no spin."""
        return self.friction == "spin"

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
