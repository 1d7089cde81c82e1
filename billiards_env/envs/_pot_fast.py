"""The single env's fast step: a pot-task shot in one compiled call, the native vector env's
(:func:`._vector_kernels.pot_step_rows`) on the env's one table.

``BilliardsEnv.step`` takes it when nothing else is needed: the pot task on the exact solver, not recording. The
shot noise is drawn from ``env.np_random`` here, in the single env's order, and handed to the compiled code. It returns exactly what the Python path returns (the vector env tests compare
the compiled code with that path, and ``tests/envs/test_vector_env.py`` checks this step against it too): only
the Python around the shot goes (parsing the outcome, building intermediate objects, several compiled calls).
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np

from billiards_env.physics.batch import new_outputs

from billiards_env.shot_path import CueShot, draw_noise

from ._vector_kernels import new_step_outputs, pack_config, pot_step_rows, pot_step_rows_spin
from .config import ConfigError, EnvConfig
from .info import shot_info
from .tasks import PotTask

if TYPE_CHECKING:  # pragma: no cover
    from .base import BilliardsEnv

_ACTIVE = np.ones(1, np.bool_)
_ROWS = np.zeros(1, np.int64)  # the one table's row


class ShotValues(NamedTuple):
    """A table's :data:`~._vector_kernels.POT_SHOT` record as Python floats (one ``item()``: as cheap to read as
    the tuple); its fields are the record's, in order (a test holds them equal)."""

    reward: float
    angle: float
    speed: float
    side: float
    top: float
    start_x: float
    start_y: float


class OutcomeValues(NamedTuple):
    """A table's :data:`~._vector_kernels.POT_OUTCOME` record as Python ints, fields in the record's order."""

    terminated: int
    truncated: int
    success: int
    scratch: int
    pocketed: int


class FastStep(NamedTuple):
    """What a compiled step returns: the env's step tuple, then the shot as the env keeps it (``last_shot``:
    start x, y, angle, speed; ``last_tip``: side, top)."""

    obs: np.ndarray
    reward: float
    terminated: bool
    truncated: bool
    info: dict[str, Any]
    last_shot: tuple[float, float, float, float]
    last_tip: tuple[float, float]


class PotFastStep:
    """The compiled step of one pot env (see the module docstring); :func:`pot_fast_step` makes it from the env's
    parts (its table state, action and observation types, simulator), and it returns what the step did rather than
    writing to the env."""

    def __init__(self, env: "BilliardsEnv") -> None:
        self.cfg, self.icfg = pack_config(env.config, env.action_type, env.observation_type)
        nb = env.n_balls
        self.out = new_outputs(1, nb)
        self.fout, self.iout = new_step_outputs(1)
        self.act = np.zeros((1, env.action_type.n))
        self.shots = np.zeros(1, np.int64)
        self.obs = np.zeros((1,) + env.observation_space.shape, np.float32)
        self.positions = bool(self.icfg[0]["positions_obs"])
        self.kernel = pot_step_rows_spin if env.physics.has_spin else pot_step_rows
        self.settings = env.table_state.settings
        self.noisy = self.settings.noisy
        b = env.balls  # the live arrays (updated in place), as one-table batches
        self.table = (b.pos[None], b.vel[None], b.ang[None], b.on_table[None])
        sim = env.simulator
        self.consts = (b.radius[None], b.mass[None], sim.pocket_xy, sim.pocket_r, sim.params, sim.max_events,
                       self.cfg, self.icfg)
        self.noise = np.zeros((1, 4))
        self.masks: dict[int, np.ndarray] = {}  # a pocketed bit mask -> its row mask
        self.rows = np.arange(nb)
        self.action_type, self.observation_type = env.action_type, env.observation_type
        self.table_state = env.table_state
        self.env_id = env.env_id

    def step(self, action: Any, shots: int, np_random: np.random.Generator) -> FastStep:
        """The env's ``step(action)`` as shot number ``shots + 1`` with the env's generator (the caller has checked
        that a step is allowed, and keeps the count and the last shot from what this returns)."""
        self.act[0] = self.action_type.parse(action)
        if self.noisy:  # drawn as the shot path draws it
            self.noise[0] = draw_noise(np_random, self.settings)
        self.shots[0] = shots
        fout, iout, out = self.fout, self.iout, self.out
        if not self.kernel(_ROWS, self.act, _ACTIVE, *self.table, self.shots, *self.consts, self.noise, out, fout, iout,
                           self.obs):
            raise ConfigError(f"{self.env_id}: could not re-spot the cue ball: the head of the table is full")
        f = ShotValues._make(fout.item(0))
        i = OutcomeValues._make(iout.item(0))
        terminated = i.terminated != 0
        truncated = i.truncated != 0
        mask = i.pocketed
        pocketed = self.masks.get(mask)
        if pocketed is None:
            pocketed = self.masks[mask] = (mask >> self.rows) & 1 != 0
        info = {"is_success": np.array(i.success != 0, np.bool_)}
        info.update(shot_info(pocketed.copy(), i.scratch != 0, int(out[5][0]), int(out[2][0]), float(out[1][0]),
                              int(out[0][0]), shots + 1, CueShot(f.angle, f.speed, f.side, f.top)))
        self.table_state.changed()
        obs = self.obs[0].copy() if self.positions else self.observation_type.observe(self.table_state)
        return FastStep(obs, f.reward, terminated, truncated, info, (f.start_x, f.start_y, f.angle, f.speed),
                        (f.side, f.top))


def compiled_action(config: EnvConfig) -> bool:
    """Whether the compiled pot step plays this config's action type (absolute, relative and ghost aim; the
    ``candidates`` type, which lists shots in Python, runs the Python path)."""
    return config.action_type in ("absolute", "relative", "ghost")


def pot_fast_step(env: "BilliardsEnv") -> PotFastStep | None:
    """The fast step of ``env`` if it applies (the pot task on the exact solver), else None. The env still takes
    its Python path when recording or when ``env._fast`` is switched off."""
    if type(env.task) is not PotTask or env.config.solver.name != "exact" or not compiled_action(env.config):
        return None
    return PotFastStep(env)


__all__ = ["FastStep", "PotFastStep", "pot_fast_step", "compiled_action"]
