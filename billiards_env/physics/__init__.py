"""billiards_env.physics: the billiards engine (no Gymnasium, no pygame).

Models (see README "Physics"): two friction laws (``rolling``, ``drag``), cushions and ball-ball collisions with
restitution, pockets as capture circles. Two solvers of the same model: ``exact`` (event-driven, closed-form,
the reference) and ``step`` (the lecture's per-frame algorithm). :mod:`.aim`: the aiming geometry (rays to
pockets and cushions, ghost ball, cut angle, pocket windows, clear paths, the cue ball's deflection) that the
solver, the players and the renderer share.
"""
from . import compile_notice  # noqa: F401  (first: one line on stderr when a cold cache makes the kernels compile)
from . import aim
from .balls import BALL_MASS, BALL_RADIUS, MAX_BALL_SPEED, OVERLAP_TOLERANCE, Balls, validate_balls
from .errors import SceneError
from .model import G, Physics
from .result import EventLog, ShotResult
from .simulate import SOLVERS, Simulator, kinetic_energy, momentum, simulate
from .table import Table, default_pockets
from .trajectory import Trajectory

__all__ = [
    "aim", "BALL_MASS", "BALL_RADIUS", "MAX_BALL_SPEED", "OVERLAP_TOLERANCE", "Balls", "validate_balls", "SceneError",
    "G", "Physics",
    "EventLog", "ShotResult", "SOLVERS", "Simulator", "kinetic_energy", "momentum", "simulate", "Table",
    "default_pockets", "Trajectory",
]
