"""Native Gymnasium vector envs: N tables of one id stepped by array code, one compiled physics call per step.

``gymnasium.make_vec(id, num_envs)`` returns one (each id is registered with a ``vector_entry_point``)::

    import gymnasium as gym
    import billiards_env  # noqa: F401

    envs = gym.make_vec("BilliardsOneBall-v0", num_envs=256)        # vectorization_mode="vector_entry_point"
    obs, info = envs.reset(seed=0)                                   # sub-env k seeded with 0 + k
    obs, reward, terminated, truncated, info = envs.step(envs.action_space.sample())

Sub-env ``k`` behaves exactly as ``gym.make(id, **kwargs)`` reset with the same seed and fed the same actions:
the same observations, rewards, terminations, truncations and info, bit for bit, as Gymnasium's
``SyncVectorEnv`` over single envs would return (``tests/envs/test_vector_env.py`` checks it for every id). The
difference is speed: for the pot task (``BilliardsOneBall-v0``, ``BilliardsThreeBalls-v0``, ``BilliardsRack-v0``
and any config of them) a step runs the actions, noise, strikes, scoring, re-spotting, resets and observations
of all tables in compiled array code, and every table's shot in one call of the batch physics
(:mod:`billiards_env.physics.batch`, slices of the tables on threads); each sub-env draws from its own
``numpy.random.Generator``, seeded as the single env is. 9-ball and 8-ball (``Billiards9Ball-v0``,
``Billiards8Ball-v0``) against the geometric opponent or alone run whole games per table in compiled code, the
opponent's turns inside the step (:mod:`._vector_games`, :mod:`._game_kernels`: the rules compiled, the geometric
player's decision on arrays, the ``candidates`` types), their infos built as arrays; the ``features`` observation
type and reset options stay in Python per table. Other opponents, rendering and the ``step`` solver run
their sub-envs one by one (the same results, at single-env speed; ``not_native`` says why).

Options (keyword arguments besides the env's own config keys): ``autoreset_mode`` (``"next_step"``, Gymnasium's
default, ``"same_step"`` or ``"disabled"``; declared in ``metadata["autoreset_mode"]``), ``render_mode`` and
``render_env`` (the sub-env drawn; ``rgb_array`` returns its frame, ``rgb_array_list`` its animated shots),
``threads`` (threads for the physics: None chooses, 1 runs serially; the results do not depend on it; the pot
task runs slices of its tables on Python threads, one compiled call each, as the games do).
"""
from __future__ import annotations

from typing import Any, ClassVar

import gymnasium as gym
import numpy as np
from gymnasium.envs.registration import load_env_creator
from gymnasium.vector import AutoresetMode, SyncVectorEnv, VectorEnv
from gymnasium.vector.utils import batch_space
from numba import typed

from billiards_env.physics.balls import Balls
from billiards_env.physics.batch import new_outputs, simulate_into, use_parallel
from billiards_env.physics.layout import PLACE_BATCH, PLACE_TRIES
from billiards_env.physics.threads import default_threads
from billiards_env.registration import ENVS, vector_entry_point
from billiards_env.table_state import TableState

from ._pot_fast import compiled_action
from ._seeding import np_random
from ._vector_games import GameTables, InfoColumns, native_games, stack_columns, stack_infos
from ._vector_kernels import (PLACED, POT_FLOATS, POT_INTS, draw_noise, finish_shots, new_step_outputs,
                              observe_positions, pack_config, place_tables, pot_step, prepare_shots)
from .base import RENDER_MODES, BilliardsEnv, check_options_mapping
from .config import ConfigError


class BilliardsVectorEnv(VectorEnv):
    """``num_envs`` tables of the id :attr:`env_id` (see the module docstring). Constructor:
    ``BilliardsVectorEnv(num_envs=1, *, autoreset_mode="next_step", render_mode=None, render_env=0, threads=None,
    config=None, **overrides)``, the last two as for the single env."""

    #: The registered id whose env this vectorises (set by the per-id subclasses below).
    env_id: ClassVar[str] = "BilliardsOneBall-v0"
    metadata: dict[str, Any] = {"render_modes": RENDER_MODES, "autoreset_mode": AutoresetMode.NEXT_STEP}

    def __init__(self, num_envs: int = 1, *, autoreset_mode: str | AutoresetMode = AutoresetMode.NEXT_STEP,
                 render_mode: str | None = None, render_env: int = 0, threads: int | None = None,
                 max_episode_steps: int | None = None, **kwargs: Any) -> None:
        if isinstance(num_envs, bool) or not isinstance(num_envs, (int, np.integer)) or num_envs < 1:
            raise ValueError(f"num_envs: must be a positive integer, got {num_envs!r}")
        if not 0 <= render_env < num_envs:
            raise ValueError(f"render_env: the sub-env to draw must be in [0, {num_envs}), got {render_env}")
        if threads is not None and (isinstance(threads, bool) or not isinstance(threads, (int, np.integer))
                                    or threads < 1):
            raise ValueError(f"threads: threads for the physics, an integer >= 1 or None (chosen by the load), "
                             f"got {threads!r}")
        if max_episode_steps is not None:
            raise ValueError("max_episode_steps: the billiards envs end episodes themselves; set the max_shots "
                             "config key instead")
        self.autoreset_mode = _autoreset_mode(autoreset_mode)
        self.num_envs = int(num_envs)
        self.render_mode = render_mode
        self.render_env = int(render_env)
        self.threads = threads
        self._kwargs = dict(kwargs)
        env_cls = load_env_creator(ENVS[self.env_id])
        #: The env whose config, spaces and parts every sub-env shares; it also draws ``render_env``.
        self.template: BilliardsEnv = env_cls(render_mode=render_mode, **kwargs)
        t = self.template
        c = t.config
        self.metadata = {**type(self).metadata, "render_fps": c.render_fps, "autoreset_mode": self.autoreset_mode}
        self.single_observation_space = t.observation_space
        #: The info's keys and forms (every sub-env's: :func:`~.info.info_schema`, ``docs/infos.md``).
        self.info_schema = t.info_schema
        self.single_action_space = t.action_space
        self.observation_space = batch_space(t.observation_space, self.num_envs)
        self.action_space = batch_space(t.action_space, self.num_envs)
        self.spec = None
        self.closed = False
        #: Native array path (the pot task on the exact solver, or a game of :mod:`._vector_games`); otherwise the
        #: sub-envs run one by one.
        self.native = c.task == "pot" and c.solver.name == "exact" and compiled_action(c)
        #: The games' tables (9-ball, 8-ball: rules and opponents compiled), or None.
        self.games: GameTables | None = None
        #: Why a game runs its sub-envs one by one (None: it does not, or not a game).
        self.not_native: str | None = None
        # The native games' per-table infos (sub_infos), made when asked for from the last reset or step's columns.
        self._sub_rows: np.ndarray | None = None
        self._sub_parts: list[Any] = []
        self._sub_given: dict[int, dict[str, Any]] = {}
        self._sub_cache: list[dict[str, Any]] | None = None
        if not self.native and c.task != "pot":
            self.not_native = native_games(t, render_mode)
            self.native = self.not_native is None
        if self.native:
            self._setup_native(t)
        else:
            self._sync = SyncVectorEnv(
                [lambda k=k: env_cls(render_mode=render_mode if k == self.render_env else None, **kwargs)
                 for k in range(self.num_envs)], copy=True, autoreset_mode=self.autoreset_mode)

    # ======================================================================================================
    # Native path: set-up
    # ======================================================================================================
    def _setup_native(self, t: BilliardsEnv) -> None:
        c = t.config
        n, nb = self.num_envs, t.n_balls
        self.ball_ids = t.ball_ids
        self.pos = np.zeros((n, nb, 2))
        self.vel = np.zeros((n, nb, 2))
        self.ang = np.zeros((n, nb, 3))
        self.on_table = np.ones((n, nb), np.bool_)
        self.shots = np.zeros(n, np.int64)
        self._radius = np.ascontiguousarray(t.balls.radius, dtype=float).reshape(1, nb)
        self._mass = np.ascontiguousarray(t.balls.mass, dtype=float).reshape(1, nb)
        self._struck = np.zeros(n, np.int64)
        self._out = new_outputs(n, nb)
        # Per table: the reward and the shot as played (POT_SHOT); terminated, truncated, success, scratch, pocketed
        # (POT_OUTCOME).
        self._fout, self._iout = new_step_outputs(n)
        game = c.task != "pot"
        # The pot task's packed config (one-record arrays of POT_FLOATS, POT_INTS); the games pack their own.
        self._cfg, self._icfg = (np.zeros(1, POT_FLOATS), np.zeros(1, POT_INTS)) if game else \
            pack_config(t.config, t.action_type, t.observation_type)
        c = t.config
        self._noisy = c.angle_noise > 0.0 or c.speed_noise > 0.0 or c.tip_noise > 0.0
        self._noise = np.zeros((n, 4))  # each table's shot noise (drawn by draw_noise when there is noise)
        self._obs = np.zeros((n,) + t.observation_space.shape, np.float32)
        self._needs_reset = np.ones(n, np.bool_)
        self._ever_reset = False
        self._has_shot = np.zeros(n, np.bool_)  # a shot since the last reset (the rendered cue line)
        # Layout of a reset (the template's, checked when it was made).
        lay = t.start_layout
        self._fixed_rows = np.asarray(lay.fixed_rows, np.int64)
        self._fixed_xy = np.ascontiguousarray(lay.fixed_xy, dtype=float).reshape(-1, 2)
        self._rand_rows = np.asarray(lay.random_rows, np.int64)
        self._regions = np.asarray(lay.regions, dtype=float).reshape(-1, 4)
        self._pockets = np.asarray(lay.pockets, dtype=float).reshape(-1, 2)
        # Shots and scoring.
        self._spin_model = t.physics.has_spin
        self._positions_obs = bool(self._icfg[0]["positions_obs"])
        self._bits = np.arange(nb, dtype=np.int64)  # a pocketed bit mask -> its row mask
        # Per-sub-env random generators (as each single env's np_random), and the compiled code's view of them.
        self._rngs: list[np.random.Generator | None] = [None] * n
        self._rng_seeds: list[int | None] = [None] * n
        self._gens: Any = None
        # One table state per table (views of the batch arrays) for the parts that stay in Python (the features and
        # candidates observations, reset options).
        s = t.table_state
        self._states = [TableState(Balls(self.ball_ids, self.pos[k], self.vel[k], t.balls.radius, t.balls.mass,
                                         self.on_table[k], self.ang[k]), s.table, s.physics, s.simulator, s.numbers,
                                   s.settings) for k in range(n)]
        if game:
            self.games = GameTables(self)

    # ======================================================================================================
    # Gymnasium API
    # ======================================================================================================
    def reset(self, *, seed: int | list[int | None] | None = None, options: dict[str, Any] | None = None
              ) -> tuple[np.ndarray, dict[str, Any]]:
        """Reset every sub-env (or those of ``options["reset_mask"]``): ``seed`` None, an int (sub-env ``k`` gets
        ``seed + k``) or one seed per sub-env, as ``SyncVectorEnv``. Other options go to every sub-env."""
        if not self.native:
            return self._sync.reset(seed=seed, options=options)
        n = self.num_envs
        if seed is None:
            seeds: list[int | None] = [None] * n
        elif isinstance(seed, (int, np.integer)) and not isinstance(seed, bool):
            seeds = [int(seed) + k for k in range(n)]
        else:
            seeds = list(seed)
            if len(seeds) != n:
                raise ValueError(f"seed: {len(seeds)} seeds for num_envs={n}; give one per sub-env, an int or None")
        if options:
            check_options_mapping(options)
        options = dict(options) if options else {}
        mask = options.pop("reset_mask", None)
        if mask is None:
            rows = np.arange(n)
        else:
            mask = np.asarray(mask)
            if mask.shape != (n,) or mask.dtype != np.bool_ or not mask.any():
                raise ValueError(f"options['reset_mask']: expected a bool array of shape ({n},) with at least one "
                                 "True")
            rows = np.flatnonzero(mask)
        self._seed_rows(rows, seeds)
        self._reset_rows(rows, options or None)
        self._observe(rows)
        self._ever_reset = True
        if self.games is not None:  # the games' reset info, stacked as SyncVectorEnv stacks it
            return self._obs.copy(), self._game_infos([(rows, False)], rows)
        return self._obs.copy(), _select(self._blank_info(), rows, n, fresh=True)

    def step(self, actions: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, dict[str, Any]]:
        """Step every sub-env (one shot each; sub-envs whose episode ended reset as ``autoreset_mode`` says)."""
        if not self.native:
            return self._sync.step(self._parse(actions, clip=False))
        if not self._ever_reset:
            raise gym.error.ResetNeeded("call reset() before step(): the tables have no balls yet")
        n = self.num_envs
        act = self._parse(actions)
        if self.games is not None:
            return self._step_games(act)
        mode = self.autoreset_mode
        if mode == AutoresetMode.NEXT_STEP:
            resetting = self._needs_reset.copy()
            active = ~resetting
        else:
            if mode == AutoresetMode.DISABLED and self._needs_reset.any():
                k = int(np.flatnonzero(self._needs_reset)[0])
                raise gym.error.ResetNeeded(f"sub-env {k}: its episode ended; with autoreset_mode='disabled' reset it "
                                            "(options={'reset_mask': ...}) before stepping")
            resetting = np.zeros(n, np.bool_)
            active = np.ones(n, np.bool_)
        t = self.template
        sim = t.simulator
        fout, iout, out = self._fout, self._iout, self._out
        noise = self._noise
        if self._noisy:
            draw_noise(active, self.generators(), self._cfg, noise)
        # Serially: one compiled call for the whole step; in parallel, one per thread on a slice of the tables.
        # Animating the rendered table: strike, simulate and score in three calls.
        split = self.render_mode in ("rgb_array_list", "human")
        render_before = None
        step_args = (self.pos, self.vel, self.ang, self.on_table, self.shots, self._radius, self._mass, sim.pocket_xy,
                     sim.pocket_r, sim.params, int(sim.max_events), self._cfg, self._icfg, noise, out, fout, iout,
                     self._obs)
        if split:
            prepare_shots(act, active, self.pos, self.on_table, self._radius[0], self._cfg, self._icfg, noise,
                          self.vel, self.ang, fout)
            render_before = self._render_snapshot(active)
            simulate_into(sim, self.pos, self.vel, self.on_table, self._radius, self._mass, self.ang, self._struck,
                          out, self.threads)
            ok = finish_shots(active, out[3], out[5], self.pos, self.on_table, self.vel, self.ang, self.shots,
                              self._cfg, self._icfg, fout, iout)
        else:
            threads = (self.threads or default_threads()) if use_parallel(n, self.threads) else 1
            ok = pot_step(self._spin_model, threads, act, active, *step_args)
        if not ok:
            raise ConfigError(f"{self.env_id}: could not re-spot the cue ball: the head of the table is full")
        status, sim_time, n_events, _, _, first = out[:6]
        stepped = np.flatnonzero(active)
        self._has_shot |= active
        if render_before is not None:
            self._render_shot(render_before)
        reward = np.where(active, fout["reward"], 0.0)
        term = active & (iout["terminated"] != 0)
        trunc = active & (iout["truncated"] != 0)
        done = term | trunc
        step_info = self._step_info(status, sim_time, n_events, first)
        if split or not self._positions_obs:
            self._observe(stepped)
        infos: dict[str, Any] = {}
        if mode == AutoresetMode.SAME_STEP and done.any():
            ended = np.flatnonzero(done)
            final_obs = _object_rows(n, ended, self._obs)
            final_mask = done.copy()
            final = {"final_obs": final_obs, "_final_obs": final_mask,
                     "final_info": _select(step_info, ended, n), "_final_info": final_mask.copy()}
            infos = _select(self._blank_info(step_info, ended), stepped, n)  # the ended tables' reset info
            # Keyed as SyncVectorEnv keys it: the first sub-env's entries first.
            infos = {**final, **infos} if done[0] else {**infos, **final}
            self._reset_rows(ended, None)
            self._observe(ended)
            self._needs_reset[:] = False
        else:
            infos = _select(self._blank_info(step_info, np.flatnonzero(resetting)), np.arange(n), n, fresh=True)
            self._needs_reset = done
        if resetting.any():
            rows = np.flatnonzero(resetting)
            self._reset_rows(rows, None)
            self._observe(rows)
        return self._obs.copy(), reward, term, trunc, infos

    def render(self) -> Any:
        """The rendered sub-env (``render_env``) as its single env renders: ``rgb_array`` its table now,
        ``rgb_array_list`` its frames since the last call (shots animated), ``human`` its window."""
        if not self.native:
            return self._sync.envs[self.render_env].render()
        self._sync_template()
        return self.template.render()

    def close_extras(self, **kwargs: Any) -> None:
        if not hasattr(self, "native"):  # construction failed before the sub-envs existed
            return
        if self.native:
            self.template.close()
        else:
            self._sync.close()

    @property
    def np_random_seed(self) -> tuple[int | None, ...]:
        """The seed of each sub-env's generator (None: drawn from the OS)."""
        if not self.native:
            return self._sync.np_random_seed
        return tuple(self._rng_seeds)

    @property
    def envs(self) -> list[gym.Env]:
        """The sub-env objects of the one-by-one path (games, step solver); the native path has none."""
        if self.native:
            raise AttributeError("the native vector env keeps its tables as arrays (pos, on_table, shots...), not as "
                                 "env objects")
        return self._sync.envs

    # ======================================================================================================
    # Native path: what the games' tables read
    # ======================================================================================================
    @property
    def table_states(self) -> list[TableState]:
        """One table state per sub-env (views of the batch arrays ``pos``, ``vel``, ``on_table``...)."""
        return self._states

    @property
    def table_rngs(self) -> list[np.random.Generator | None]:
        """Each sub-env's random generator (as a single env's ``np_random``; None until its first reset)."""
        return self._rngs

    @property
    def observations(self) -> np.ndarray:
        """The batch of observations ``(N, ...)`` the native path writes in place (``step`` returns a copy)."""
        return self._obs

    @property
    def ball_radius(self) -> np.ndarray:
        """The balls' radii as a ``(1, B)`` float64 row (what the kernels take)."""
        return self._radius

    @property
    def ball_mass(self) -> np.ndarray:
        """The balls' masses as a ``(1, B)`` float64 row."""
        return self._mass

    @property
    def layout_arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The template's start layout as the kernels take it: fixed rows, their points, random rows, their regions
        ``(x0, x_span, y0, y_span)`` and the pocket centres."""
        return self._fixed_rows, self._fixed_xy, self._rand_rows, self._regions, self._pockets

    # ======================================================================================================
    # Native path: the parts of a step
    # ======================================================================================================
    def _parse(self, actions: Any, clip: bool = True) -> np.ndarray:
        """Actions as a C-contiguous (N, n) float64 array clipped to [-1, 1] (NaN/inf raise, as in the env); the
        one-by-one path gets them unclipped (each sub-env clips its own)."""
        n_act = self.template.action_type.n
        try:
            act = np.asarray(actions, dtype=np.float64)
            if act.size != self.num_envs * n_act:
                raise ValueError
            act = act.reshape(self.num_envs, n_act)
        except (ValueError, TypeError):
            raise ValueError(f"actions: expected a batch of shape ({self.num_envs}, {n_act}) (num_envs x "
                             f"{self.template.action_type.layout()}), got shape {np.shape(actions)}") from None
        if not clip:
            return act
        if not np.isfinite(act).all():
            k = int(np.flatnonzero(~np.isfinite(act).all(axis=1))[0])
            raise ValueError(f"actions[{k}]: must be finite numbers, got {act[k].tolist()}; check the policy's output "
                             "for NaN/inf")
        return np.ascontiguousarray(np.clip(act, -1.0, 1.0))

    def _seed_rows(self, rows: np.ndarray, seeds: list[int | None]) -> None:
        changed = False
        for k in rows.tolist():
            s = seeds[k]
            if s is not None or self._rngs[k] is None:
                self._rngs[k], self._rng_seeds[k] = np_random(s)
                changed = True
        if changed:
            self._gens = None

    def generators(self) -> Any:
        """The sub-envs' generators as a numba typed list, for compiled code that draws per table (rebuilt only
        when a generator was replaced)."""
        if self._gens is None:
            self._gens = typed.List(self._rngs)
        return self._gens

    def _reset_rows(self, rows: np.ndarray, options: dict[str, Any] | None) -> None:
        if rows.size == 0:
            return
        for k in rows.tolist():
            if self._rngs[k] is None:
                self._seed_rows(np.array([k]), [None] * self.num_envs)
        rows = np.ascontiguousarray(rows, dtype=np.int64)
        self.shots[rows] = 0
        self._needs_reset[rows] = False
        self._has_shot[rows] = False
        if self.games is not None:
            self.games.reset(rows, options)
            return
        if options:
            for k in rows.tolist():
                self._reset_with_options(k, options)
            self._render_reset(rows)
            return
        t = self.template
        c = t.config
        bad = place_tables(rows, self.generators(), self.pos, self.vel, self.ang, self.on_table, self._fixed_rows,
                           self._fixed_xy, self._rand_rows, self._regions, self._pockets, c.pocket_margin,
                           2.0 * c.ball_radius + c.ball_gap, PLACE_BATCH, PLACE_TRIES)
        if bad != PLACED:
            raise ConfigError(f"{self.env_id}: could not place the balls at random; lower n_object_balls, "
                              "pocket_margin, ball_gap or cushion_margin")
        self._render_reset(rows)

    def _reset_with_options(self, k: int, options: dict[str, Any]) -> None:
        """A scene set by ``reset(options=...)`` for sub-env ``k``, with the single env's own checks."""
        state = self._states[k]
        b = state.balls
        b.vel.fill(0.0)
        b.ang.fill(0.0)
        b.on_table.fill(True)
        self.template.set_positions(options, b, self._rngs[k])
        state.changed()

    def _observe(self, rows: np.ndarray) -> None:
        if rows.size == 0:
            return
        if self.games is not None:
            self.games.observe(rows)
            return
        if self._positions_obs:
            observe_positions(np.ascontiguousarray(rows, dtype=np.int64), self.pos, self.on_table,
                              self._cfg[0]["sx"], self._cfg[0]["sy"], self._obs)
        else:
            ot = self.template.observation_type
            for k in rows.tolist():
                state = self._states[k]
                state.changed()  # the table moved on since the last observation
                self._obs[k] = ot.observe(state)

    def _step_games(self, act: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, dict[str, Any]]:
        """A step of the games' tables (:class:`._vector_games.GameTables`): the agent's shots and the opponents'
        replies in one compiled call, the autoreset, and the info stacked as ``SyncVectorEnv`` stacks it."""
        n = self.num_envs
        g = self.games
        assert g is not None
        mode = self.autoreset_mode
        if mode == AutoresetMode.NEXT_STEP:
            resetting = self._needs_reset.copy()
        else:
            if mode == AutoresetMode.DISABLED and self._needs_reset.any():
                k = int(np.flatnonzero(self._needs_reset)[0])
                raise gym.error.ResetNeeded(f"sub-env {k}: its episode ended; with autoreset_mode='disabled' reset it "
                                            "(options={'reset_mask': ...}) before stepping")
            resetting = np.zeros(n, np.bool_)
        stepped = np.flatnonzero(~resetting)
        reset_rows = np.flatnonzero(resetting)
        if stepped.size:
            g.step(stepped, act)
            g.observe(stepped)
        if reset_rows.size:
            self._reset_rows(reset_rows, None)
            self._observe(reset_rows)
        reward = np.zeros(n)
        reward[stepped] = g.reward[stepped]
        term = np.zeros(n, np.bool_)
        term[stepped] = g.tout["terminated"][stepped] != 0
        trunc = np.zeros(n, np.bool_)
        trunc[stepped] = g.tout["truncated"][stepped] != 0
        done = term | trunc
        if mode == AutoresetMode.SAME_STEP:
            g.prepare_infos()
            final = g.columns(stepped, step=True)  # before the ended tables reset
            ended = np.flatnonzero(done)
            kept = np.flatnonzero(~done)
            if ended.size:
                final_obs = _object_rows(n, ended, self._obs)
                self._reset_rows(ended, None)
                self._observe(ended)
            extra = None
            if ended.size:  # each ended table's final entry comes before its reset info
                extra = (2 * int(ended[0]), {"final_obs": (final_obs, done.copy()),
                                             "final_info": (stack_columns(n, [(0, InfoColumns(ended, final.cols))]),
                                                            done.copy())})
            infos = self._game_infos([(kept, final), (ended, False)], stepped, dicts_of=final, extra=extra)
            self._needs_reset[:] = False
        else:
            infos = self._game_infos([(stepped, True), (reset_rows, False)], np.arange(n))
            self._needs_reset = done
        return self._obs.copy(), reward, term, trunc, infos

    def _game_infos(self, parts: list[tuple[np.ndarray, Any]], rows: np.ndarray, dicts_of: Any = None,
                    extra: tuple[int, dict[str, Any]] | None = None) -> dict[str, Any]:
        """The games' vector info of ``parts`` (``(tables, what)``: ``True`` their step info, ``False`` their reset
        info, or the :class:`._vector_games.InfoColumns` to take their rows from), stacked as ``SyncVectorEnv``
        stacks the tables' dicts (``extra``: ``(position, keys already stacked)``, the same-step autoreset's
        ``final_obs`` and ``final_info``); the per-table dicts of ``rows`` (:attr:`sub_infos`; ``dicts_of``: the
        columns to take them from instead) are made when asked for."""
        g = self.games
        assert g is not None
        n = self.num_envs
        g.prepare_infos()
        built: list[tuple[np.ndarray, InfoColumns]] = []
        given: dict[int, dict[str, Any]] = {}
        for tables, what in parts:
            if not tables.size:
                continue
            if isinstance(what, InfoColumns):
                built.append((tables, InfoColumns(tables, what.cols)))
                continue
            if not what:
                for k in tables.tolist():
                    info = g.given_reset_info(k)
                    if info is not None:  # a scene set by reset(options=...): the template env's own info
                        given[k] = info
            built.append((tables, g.columns(tables, step=bool(what))))
        self._sub_rows = rows
        self._sub_parts = [dicts_of] if dicts_of is not None else [c for _, c in built]
        self._sub_given = given
        self._sub_cache = None
        if given:  # rare (reset options, no autoreset): stack the tables' dicts one by one
            assert extra is None
            return stack_infos(n, list(zip(rows.tolist(), self._sub_dicts(rows))))
        return stack_columns(n, [(2 * int(c.rows[0]) + 1, c) for _, c in built] + ([extra] if extra else []))

    def _sub_dicts(self, rows: np.ndarray) -> list[dict[str, Any]]:
        """The per-table info dicts of ``rows`` from the last reset or step's parts."""
        by_row: dict[int, dict[str, Any]] = {}
        for part in self._sub_parts:
            for k, info in zip(part.rows.tolist(), part.dicts()):
                by_row[k] = info
        by_row.update(self._sub_given)
        return [by_row[k] for k in rows.tolist()]

    @property
    def sub_infos(self) -> list[dict[str, Any]] | None:
        """The native games' info of the last reset or step as one dict per sub-env, as the single env returns it
        (for a sub-env that ended in a same-step autoreset: its last step's; ``{}`` for one not reset), before
        Gymnasium's stacking makes one array per key. None on the pot task or before the first reset. Made when asked
        for, once per step. SB3's adapter reads it."""
        if self.games is None or self._sub_rows is None:
            return None
        if self._sub_cache is None:
            out: list[dict[str, Any]] = [{} for _ in range(self.num_envs)]
            for k, info in zip(self._sub_rows.tolist(), self._sub_dicts(self._sub_rows)):
                out[k] = info
            self._sub_cache = out
        return self._sub_cache

    def _step_info(self, status, sim_time, n_events, first) -> dict[str, np.ndarray]:
        """The pot task's step ``info`` of every table, as one array per key of the schema (rows that did not
        shoot are filler)."""
        iout, fout = self._iout, self._fout
        info = {
            "is_success": iout["success"] != 0,
            "pocketed": (iout["pocketed"][:, None] >> self._bits) & 1 != 0,
            "scratch": iout["scratch"] != 0,
            "first_contact": first.astype(np.int64),
            "n_events": n_events.astype(np.int64),
            "sim_time": sim_time.astype(np.float64),
            "status": status.astype(np.int64),
            "shots": self.shots.copy(),
            "angle": fout["angle"].copy(),
            "speed": fout["speed"].copy(),
            "side": fout["side"].copy(),
            "top": fout["top"].copy(),
        }
        assert list(info) == list(self.info_schema)
        return info

    def _blank_info(self, info: dict[str, np.ndarray] | None = None, rows: Any = slice(None)
                    ) -> dict[str, np.ndarray]:
        """``info`` (default: new arrays for every table) with the tables ``rows`` holding a reset's values (the
        schema's blanks: no shot yet)."""
        n = self.num_envs
        if info is None:
            info = {k: np.zeros((n, *spec.shape), spec.dtype) for k, spec in self.info_schema.items()}
        for k, spec in self.info_schema.items():
            info[k][rows] = spec.blank
        return info

    # ======================================================================================================
    # Rendering (the template env draws sub-env render_env)
    # ======================================================================================================
    def _sync_template(self) -> None:
        k = self.render_env
        b = self.template.balls
        b.pos[...] = self.pos[k]
        b.on_table[...] = self.on_table[k]
        self.template.last_shot = None
        if self._has_shot[k]:
            f = self._fout[k]
            self.template.last_shot = (float(f["start_x"]), float(f["start_y"]), float(f["angle"]),
                                       float(f["speed"]))

    def _render_reset(self, rows: np.ndarray) -> None:
        """The rendered table was reset: start its frame list (``rgb_array_list``) or show it (``human``), as the
        single env's ``reset`` does."""
        if self.render_mode not in ("rgb_array_list", "human") or self.render_env not in rows:
            return
        self._sync_template()
        self.template.show_new_episode()

    def _render_snapshot(self, active: np.ndarray) -> Balls | None:
        """The rendered table before its shot (animated modes only), to re-simulate with the trajectory kept."""
        k = self.render_env
        if self.render_mode not in ("rgb_array_list", "human") or not active[k]:
            return None
        t = self.template
        return Balls(self.ball_ids, self.pos[k].copy(), self.vel[k].copy(), t.balls.radius.copy(),
                     t.balls.mass.copy(), self.on_table[k].copy(), self.ang[k].copy())

    def _render_shot(self, before: Balls) -> None:
        """Animate the rendered table's shot: the same shot simulated again with its trajectory (bit-identical to
        the one played), drawn by the template env."""
        t = self.template
        res = t.simulator.run(before, record=True, validate=False)
        self._sync_template()
        t.animate(res.trajectory, final=True)


def _autoreset_mode(mode: str | AutoresetMode) -> AutoresetMode:
    """An :class:`AutoresetMode` from itself, its value (``"NextStep"``) or its name (``"next_step"``)."""
    if isinstance(mode, AutoresetMode):
        return mode
    for m in AutoresetMode:
        if str(mode) in (m.value, m.name, m.name.lower()):
            return m
    raise ValueError(f"autoreset_mode: {mode!r}; use one of {[m.name.lower() for m in AutoresetMode]} (or an "
                     "AutoresetMode)")


def _select(info: dict[str, np.ndarray], rows: np.ndarray, n: int, fresh: bool = False) -> dict[str, np.ndarray]:
    """The vector ``info`` of the sub-envs ``rows``: each key's array with the others blanked as Gymnasium's
    vector envs leave them (0, False or None), and its ``_key`` mask. Empty if ``rows`` is. ``fresh``: ``info``'s
    arrays are the caller's own new ones, returned as they are when ``rows`` holds every sub-env."""
    if rows.size == 0:
        return {}
    mask = np.zeros(n, np.bool_)
    mask[rows] = True
    every = rows.size == n  # (rows are distinct table indices: all of them, the arrays copied whole)
    out: dict[str, np.ndarray] = {}
    for key, arr in info.items():
        if every:
            out[key] = arr if fresh else arr.copy()
        else:
            blank = np.full(n, None, dtype=object) if arr.dtype == object else np.zeros(arr.shape, dtype=arr.dtype)
            np.copyto(blank, arr, where=mask.reshape((n,) + (1,) * (arr.ndim - 1)))
            out[key] = blank
        out["_" + key] = mask.copy()
    return out


def _object_rows(n: int, rows: np.ndarray, obs: np.ndarray) -> np.ndarray:
    """An object array of ``n`` entries, entry ``k`` of ``rows`` the row ``k`` of a fresh copy of ``obs`` (a view
    of it), the others None: the final observations as Gymnasium's vector envs stack them, without a Python loop
    over the tables."""
    out = np.full(n, None, dtype=object)
    out[rows] = np.fromiter(obs[rows], dtype=object, count=rows.size)
    return out


def _vector_class(env_id: str) -> type[BilliardsVectorEnv]:
    """The subclass of :class:`BilliardsVectorEnv` for ``env_id``, named as its ``vector_entry_point`` says."""
    name = vector_entry_point(env_id).rsplit(":", 1)[1]
    return type(name, (BilliardsVectorEnv,), {"env_id": env_id, "__module__": __name__,
                                               "__doc__": f"The native vector env of ``{env_id}``."})


#: Registered id -> its vector env class (``vector_entry_point`` of each id; one module attribute per class).
VECTOR_ENVS: dict[str, type[BilliardsVectorEnv]] = {env_id: _vector_class(env_id) for env_id in ENVS}
globals().update({cls.__name__: cls for cls in VECTOR_ENVS.values()})

__all__ = ["BilliardsVectorEnv", "VECTOR_ENVS"] + [c.__name__ for c in VECTOR_ENVS.values()]
