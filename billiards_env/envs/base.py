"""The billiards environment: a simulator, an action type, an observation type and a task, joined.

Each registered id is a small subclass that names its packaged scene (``scene``) and documents itself (see
:mod:`.one_ball`, :mod:`.three_balls`, :mod:`.rack`, :mod:`.games`). The parts (as in HighwayEnv and panda-gym):

- physics (:mod:`billiards_env.physics`: table, balls, simulator) knows nothing of Gymnasium;
- :mod:`.actions`: the action type turns an action vector into a cue shot (``action_type`` key);
- :mod:`.observations`: the observation type turns the table into an observation (``observation_type`` key);
- :mod:`.tasks`: the task scores a shot: reward, termination, success, its part of ``info`` (``task`` key);
- drawing is delegated to :mod:`billiards_env.render`, imported only when a render mode is set.

Speed: ``step`` runs the compiled exact solver on the live ball arrays in place (no validation, no copies, no
result objects), the same kernel ``Simulator.run`` calls; the placements that ``reset`` draws are valid by
construction, and scenes given through ``reset(options=...)`` are validated there.
"""
from __future__ import annotations

import contextlib
import math
from typing import Any, Callable, ClassVar, Iterator, Sequence

import gymnasium as gym
import numpy as np

from billiards_env.physics.balls import Balls, validate_balls
from billiards_env.physics.errors import SceneError
from billiards_env.physics.layout import (DIAMOND_ORDER, RACK_ORDER, diamond_positions, foot_spot, head_spot,
                                          head_string_x, nearest_free_point, place_random, rack_rows,
                                          triangle_positions)
from billiards_env.physics.simulate import Simulator
from billiards_env.physics.spin_collide import strike_ball

from ._pot_fast import pot_fast_step
from ._seeding import np_random
from .actions import CueShot, action_factory, noisy_shot
from .config import ConfigError, EnvConfig, load_config
from .observations import observation_factory
from .tasks import ShotOutcome, task_factory

RENDER_MODES = ["human", "rgb_array", "rgb_array_list"]


class BilliardsEnv(gym.Env[np.ndarray, np.ndarray]):
    """Base class of the billiards environments (see the subclasses for each id's manual).

    Constructor: ``BilliardsEnv(render_mode=None, config=None, **overrides)``; ``config`` is a YAML path, a
    mapping or an :class:`~billiards_env.envs.config.EnvConfig` layered over the class's packaged scene, and
    ``overrides`` are config keys (see :mod:`billiards_env.envs.config`).

    Live state for players and tools: ``balls`` (a :class:`~billiards_env.physics.Balls`, updated IN PLACE by
    every shot: ``copy()`` it to keep a snapshot), ``table``, ``physics``, ``simulator`` (to try shots:
    ``simulator.run(balls.strike(0, angle, speed), validate=False)``), ``config``, ``task``, ``action_type``,
    ``observation_type``, ``shots`` (shots taken in this episode), ``last_shot`` (``(x, y, angle, speed)`` of the
    last shot or None).
    """

    metadata: ClassVar[dict[str, Any]] = {"render_modes": RENDER_MODES, "render_fps": 30}
    #: Packaged scene file (``billiards_env/envs/scenes/<scene>.yaml``) holding this id's defaults.
    scene: ClassVar[str | None] = None
    #: Registered id (for window titles and messages).
    env_id: ClassVar[str] = "Billiards"

    def __init__(self, render_mode: str | None = None, config: Any = None, **overrides: Any) -> None:
        if render_mode is not None and render_mode not in RENDER_MODES:
            raise ValueError(f"render_mode: unknown mode {render_mode!r}; use one of {RENDER_MODES} or None")
        self.config: EnvConfig = load_config(self.scene, config, **overrides)
        c = self.config
        self.render_mode = render_mode
        self.metadata = {**type(self).metadata, "render_fps": c.render_fps}

        self.table = c.table
        self.physics = c.physics
        self.simulator = Simulator(self.table, self.physics, solver=c.solver.name, dt=c.solver.dt,
                                   contact=c.solver.contact, max_time=c.max_time, max_events=c.max_events)

        n = c.n_object_balls + 1
        self.n_balls = n
        self.ball_ids: tuple[str, ...] = ("cue",) + tuple(str(k) for k in range(1, n))
        #: Ball number of each row for drawing (0 = cue ball).
        self.ball_numbers: tuple[int, ...] = tuple(range(n))
        # Live state: one Balls object whose arrays the kernel updates in place.
        self.balls = Balls.from_positions(np.zeros((n, 2)), ids=self.ball_ids, radius=c.ball_radius,
                                          mass=c.ball_mass)
        self.shots = 0
        self.last_shot: tuple[float, float, float, float] | None = None
        #: Tip offsets ``(side, top)`` of the last shot (fractions of R; spin model).
        self.last_tip: tuple[float, float] = (0.0, 0.0)
        self._needs_reset = True

        self.task = task_factory(self)
        self.action_type = action_factory(c, self.task.has_ball_in_hand, self.task.declarations,
                                          self.table.n_pockets)
        self.observation_type = observation_factory(self)
        self.action_space = self.action_type.space
        self.observation_space = self.observation_type.space

        # Fast path: Simulator.run_in_place on the live arrays (exact solver, no copies, no result objects).
        self._fast = c.solver.name == "exact"
        self._spin = self.physics.friction == "spin"
        # Fastest (the pot task on the exact solver): the whole shot in one compiled call (envs/_pot_fast.py).
        self._pot_fast = pot_fast_step(self)
        self._pockets = [(float(px), float(py)) for px, py in self.table.pocket_xy]

        # Fixed part of the starting layout (rack and/or head-spot cue), checked once here.
        self._fixed_rows, self._fixed_xy = self._fixed_layout()
        self._fixed_points = [(float(x), float(y)) for x, y in self._fixed_xy]
        self._random_rows = [i for i in range(n) if i not in self._fixed_rows]
        self._regions = [self._region(i) for i in self._random_rows]
        self._check_layout()

        # Rendering (created lazily: pygame is imported only when something is drawn).
        self._record = render_mode in ("human", "rgb_array_list")
        self._renderer: Any = None
        self._window: Any = None
        self._frames: list[np.ndarray] = []
        self._animations: list[tuple[Any, dict[str, Any]]] = []  # (trajectory, what to draw with it)
        self._shot_view: dict[str, Any] = {}  # what to draw with the shot just played (recording modes)
        self._orientations: np.ndarray | None = None  # the balls' orientations (spin model, animations)

    # ======================================================================================================
    # Gymnasium API
    # ======================================================================================================
    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None
              ) -> tuple[np.ndarray, dict[str, Any]]:
        """Start an episode. ``options`` may set the scene: ``{"positions": (N,2) metres}`` (rows: cue, 1..n)
        with an optional ``"pocketed": (N,) bool`` (object balls already off the table); it is validated."""
        if seed is not None:  # what gymnasium.Env.reset(seed=seed) does, with the same generator, faster
            self._np_random, self._np_random_seed = np_random(seed)
        b = self.balls
        b.vel.fill(0.0)
        b.ang.fill(0.0)
        b.on_table.fill(True)
        if options:
            self._set_positions(options)
        else:
            self._place(self.np_random, b.pos)
        self.shots = 0
        self.last_shot = None
        self.last_tip = (0.0, 0.0)
        self._orientations = None
        self._needs_reset = False
        info = self.task.reset(self, options)
        if self.render_mode == "rgb_array_list":
            self._frames = [self._draw_state()]
        elif self.render_mode == "human":
            self._show(None)
        return self.observation_type.observe(self), info

    def step(self, action: Any) -> tuple[np.ndarray, float, bool, bool, dict[str, Any]]:
        """Strike the cue ball with ``action``, simulate until every ball is at rest, score the shot.
        Raises ``gymnasium.error.ResetNeeded`` before the first ``reset()`` and after the episode has ended."""
        if self._needs_reset:
            if self.shots:  # the last step ended the episode
                raise gym.error.ResetNeeded(
                    f"step() after the end of the episode (shot {self.shots} returned terminated or truncated); call "
                    "reset() to start a new one (vector envs and SB3 do this for you)")
            raise gym.error.ResetNeeded("call reset() before step(): the table has no balls yet")
        if self._pot_fast is not None and self._fast and not self._record:
            return self._pot_fast.step(self, action)
        shot = self.action_type.shot(self, action)
        if shot.place is not None:
            self.balls.pos[0] = shot.place
        self.task.before_shot(self, shot)
        outcome, trajectory, played = self.play_shot(shot)
        view = self._shot_view
        self.shots += 1
        self._animations = []
        reward, terminated, truncated, info = self.task.on_shot(self, outcome)
        info.update({
            "pocketed": tuple(self.ball_ids[i] for i in outcome.pocketed),
            "scratch": outcome.scratch,
            "first_contact": self.ball_ids[outcome.first_contact] if outcome.first_contact >= 0 else None,
            "n_events": outcome.n_events,
            "sim_time": outcome.sim_time,
            "status": outcome.status,
            "shots": self.shots,
            "angle": played.angle,
            "speed": played.speed,
        })
        if self.action_type.spin:
            info["side"], info["top"] = played.side, played.top
        if self._record:
            later = self._animations
            self._animate(trajectory, view, final=not later)
            for k, (traj, seen) in enumerate(later):  # the opponent's reply in a game
                self._animate(traj, seen, final=k == len(later) - 1)
        self._needs_reset = terminated or truncated  # stepping on after the end raises ResetNeeded
        return self.observation_type.observe(self), reward, terminated, truncated, info

    def play_shot(self, shot: CueShot) -> tuple[ShotOutcome, Any, CueShot]:
        """Add the shot noise, strike the cue ball and simulate until every ball is at rest (the live balls are
        updated in place). Returns the outcome, the trajectory (when recording) and the shot as played."""
        rng = self.np_random
        c = self.config
        n_angle = float(rng.normal(0.0, c.angle_noise)) if c.angle_noise > 0.0 else 0.0
        n_speed = float(rng.normal(0.0, c.speed_noise)) if c.speed_noise > 0.0 else 0.0
        n_side = float(rng.normal(0.0, c.tip_noise)) if c.tip_noise > 0.0 else 0.0
        n_top = float(rng.normal(0.0, c.tip_noise)) if c.tip_noise > 0.0 else 0.0
        angle, speed, side, top = noisy_shot(shot.angle, shot.speed, shot.side, shot.top, n_angle, n_speed, n_side,
                                             n_top, c.angle_noise > 0.0, c.speed_noise > 0.0, c.tip_noise > 0.0)
        b = self.balls
        x0, y0 = float(b.pos[0, 0]), float(b.pos[0, 1])
        b.vel[0, 0] = speed * math.cos(angle)
        b.vel[0, 1] = speed * math.sin(angle)
        if self._spin:  # the tip offsets' spin, and the squirt of the physics
            p = self.physics
            b.vel[0, 0], b.vel[0, 1], b.ang[0, 0], b.ang[0, 1], b.ang[0, 2] = strike_ball(
                angle, speed, side, top, float(b.radius[0]), float(b.mass[0]), p.squirt, p.cue_end_mass)
        self.last_shot = (x0, y0, angle, speed)
        self.last_tip = (side, top)
        if self._record:  # drawn with this shot's animation: its cue and tip, a game's HUD before the call
            self._shot_view = self.render_data(orientations=False)

        trajectory = None
        if self._fast and not self._record:
            status, sim_time, n_events, pocket_of, ev_int = self.simulator.run_in_place(b)
        else:
            res = self.simulator.run(b, record=self._record, validate=False)
            fb = res.balls
            b.pos[...] = fb.pos
            b.on_table[...] = fb.on_table
            status, sim_time, n_events, pocket_of = res.status, res.time, res.n_events, res.pocket
            ev = res.events
            ev_int = np.stack([ev.kind, ev.ball, ev.other], axis=1) if len(ev) else np.zeros((0, 3), np.int64)
            trajectory = res.trajectory
        b.vel.fill(0.0)  # at rest (a capped shot is stopped where it is)
        if self._spin:
            b.ang.fill(0.0)
        outcome = ShotOutcome.from_arrays(status, sim_time, n_events, pocket_of, ev_int)
        return outcome, trajectory, CueShot(angle, speed, side, top, shot.place)

    def observe(self, player: int | None = None) -> np.ndarray:
        """The observation of the table now (what ``reset`` and ``step`` return). ``player`` (games: 0 or 1): the
        game features take that player's point of view (own group, own fouls, whose turn) instead of the shooter's;
        the two-player env (:mod:`billiards_env.multi`) observes each agent so."""
        if player is None:
            return self.observation_type.observe(self)
        seen_by = getattr(self.task, "seen_by", None)
        if seen_by is None:
            raise ValueError(f"observe(player={player!r}): task {self.task.name!r} has no players; call observe()")
        with seen_by(player):
            return self.observation_type.observe(self)

    def queue_animation(self, trajectory: Any) -> None:
        """Animate a shot the task played within this step (an opponent's), after the agent's (recording modes)."""
        if self._record and trajectory is not None:
            self._animations.append((trajectory, self._shot_view))

    def render(self) -> np.ndarray | list[np.ndarray] | None:
        """``rgb_array``: the table now, ``(H, W, 3) uint8`` (the last shot's cue line drawn).
        ``rgb_array_list``: the frames since the last ``render``/``reset`` (every shot animated), then cleared.
        ``human``: shows the table now in the window (shots animate during ``step``); returns None."""
        if self.render_mode is None:
            gym.logger.warn("render() called without a render_mode; make the env with render_mode='rgb_array', "
                            "'rgb_array_list' or 'human'")
            return None
        if self.render_mode == "rgb_array":
            return self._draw_state()
        if self.render_mode == "rgb_array_list":
            frames, self._frames = self._frames, []
            return frames
        self._show(None)
        return None

    def close(self) -> None:
        if self._window is not None:
            self._window.close()
            self._window = None
        self._renderer = None
        self._frames = []

    # ======================================================================================================
    # Actions
    # ======================================================================================================
    def shot_from_action(self, action: Any) -> CueShot:
        """The shot an action means now (no noise): a :class:`~billiards_env.envs.actions.CueShot` ``(angle rad,
        speed m/s, side, top, place)``. NaN/inf raise ValueError; finite values outside [-1, 1] are clipped."""
        return self.action_type.shot(self, action)

    def action_from_shot(self, angle: float, speed: float, side: float = 0.0, top: float = 0.0,
                         place: tuple[float, float] | None = None, pocket: int | None = None,
                         push: bool = False) -> np.ndarray:
        """The action that strikes the cue ball at ``angle`` (rad, 0 = +x, CCW) and ``speed`` (m/s) with tip
        offsets ``side``/``top`` (spin dims) from ``place`` (ball in hand), calling ``pocket`` for the 8 or
        declaring ``push`` (games), in the active action type (inverse of :meth:`shot_from_action`). Speeds
        outside [speed_min, speed_max] clip; dims not given are neutral."""
        return self.action_type.action(self, angle, speed, side, top, place, pocket, push)

    def target_ball(self) -> int | None:
        """Row of the ball to hit first (the relative and ghost aim's target): the task's choice (the lowest-
        numbered object ball on the table, or the legal ball of a game), or None."""
        return self.task.target_ball(self)

    def legal_cue_position(self, x: float, y: float) -> tuple[float, float]:
        """Where a ball-in-hand cue ball asked for at ``(x, y)`` goes: the nearest legal point of the task's
        placement area not overlapping another ball nor inside a pocket's capture circle (where it would drop at
        once) (:func:`~billiards_env.physics.layout.nearest_free_point`)."""
        area = self.task.ball_in_hand_area(self)
        if area is None:
            area = self._table_area()
        b, t = self.balls, self.table
        return nearest_free_point(x, y, b.pos, b.on_table, b.radius, 0, area,
                                  holes=np.column_stack([t.pocket_xy, t.pocket_radius]))

    @contextlib.contextmanager
    def cue_moved_to(self, place: tuple[float, float]) -> Iterator[None]:
        """Temporarily put the cue ball at ``place`` (on the table), e.g. to aim from a ball-in-hand position."""
        b = self.balls
        saved, on = b.pos[0].copy(), bool(b.on_table[0])
        b.pos[0] = place
        b.on_table[0] = True
        try:
            yield
        finally:
            b.pos[0] = saved
            b.on_table[0] = on

    def _table_area(self) -> tuple[float, float, float, float]:
        r = self.config.ball_radius
        return r, self.table.length - r, r, self.table.width - r

    # ======================================================================================================
    # Placement
    # ======================================================================================================
    def _fixed_layout(self) -> tuple[list[int], np.ndarray]:
        """Rows placed at fixed points every reset (the rack, a head-spot cue) and their positions."""
        c = self.config
        rows: list[int] = []
        pts: list[tuple[float, float]] = []
        if c.cue_placement == "head_spot":
            rows.append(0)
            pts.append(head_spot(self.table))
        if c.placement == "rack":
            m = c.n_object_balls
            tri = triangle_positions(foot_spot(self.table), c.ball_radius, rows=rack_rows(m), gap=c.rack_gap)
            order = RACK_ORDER if m == len(RACK_ORDER) else tuple(range(1, m + 1))
            for slot, number in enumerate(order):
                rows.append(number)
                pts.append((float(tri[slot, 0]), float(tri[slot, 1])))
        if c.placement == "diamond":
            dia = diamond_positions(foot_spot(self.table), c.ball_radius, gap=c.rack_gap)
            for slot, number in enumerate(DIAMOND_ORDER):
                rows.append(number)
                pts.append((float(dia[slot, 0]), float(dia[slot, 1])))
        return rows, np.array(pts, dtype=float).reshape(-1, 2)

    def _check_layout(self) -> None:
        """Validate the fixed layout and make sure the random placement can succeed (raise at make time)."""
        c = self.config
        biggest = float(self.table.pocket_radius.max()) if self.table.n_pockets else 0.0
        if c.placement == "random" and c.pocket_margin <= biggest:
            raise ConfigError(f"pocket_margin: {c.pocket_margin} m would let a ball start inside a pocket's "
                             f"capture radius; use more than {biggest}")
        trial = self.balls.copy()
        self._place(np.random.default_rng(0), trial.pos)
        try:
            validate_balls(trial, self.table)
        except SceneError as exc:
            raise ConfigError(f"starting layout of {self.env_id}: {exc}") from None

    def _region(self, row: int) -> tuple[float, float, float, float]:
        """Random-placement region of ``row`` as ``(x0, x_span, y0, y_span)``."""
        c = self.config
        m = c.ball_radius + c.cushion_margin
        x1 = self.table.length - m
        if row == 0 and c.cue_placement == "kitchen":
            x1 = head_string_x(self.table)
        return m, x1 - m, m, self.table.width - 2.0 * m

    def _place(self, rng: np.random.Generator, pos: np.ndarray) -> None:
        """Fill ``pos`` with a starting layout: the fixed rows, then each random row uniformly in its region
        (:func:`~billiards_env.physics.layout.place_random`, drawing from ``rng``)."""
        if self._fixed_rows:
            pos[self._fixed_rows] = self._fixed_xy
        c = self.config
        try:
            place_random(rng, pos, self._random_rows, self._regions, self._fixed_points, self._pockets,
                         c.pocket_margin, 2.0 * c.ball_radius + c.ball_gap)
        except SceneError:
            raise ConfigError(
                f"{self.env_id}: could not place the balls at random; lower n_object_balls, pocket_margin, "
                "ball_gap or cushion_margin") from None

    def _set_positions(self, options: dict[str, Any]) -> None:
        b = self.balls
        unknown = sorted(set(options) - {"positions", "pocketed"} - set(self.task.option_keys))
        if unknown:
            extra = "".join(f", {k!r}" for k in self.task.option_keys)
            raise ValueError(f"reset options: unknown key(s) {unknown}; allowed: 'positions' ((N,2) metres, rows "
                             f"cue, 1..n), 'pocketed' ((N,) bool){extra}")
        if "positions" in options:
            p = np.asarray(options["positions"], dtype=float)
            if p.shape != (self.n_balls, 2):
                raise ValueError(f"reset options['positions']: expected shape ({self.n_balls}, 2) (rows: "
                                 f"{', '.join(self.ball_ids)}), got {p.shape}")
            b.pos[...] = p
        else:
            self._place(self.np_random, b.pos)
        if "pocketed" in options:
            off = np.asarray(options["pocketed"], dtype=bool).reshape(-1)
            if off.shape != (self.n_balls,) or off[0]:
                raise ValueError(f"reset options['pocketed']: expected {self.n_balls} booleans with the cue ball "
                                 "(first) on the table")
            b.on_table[...] = ~off
        validate_balls(b, self.table)

    # ======================================================================================================
    # Rendering (drawing itself lives in billiards_env.render)
    # ======================================================================================================
    @property
    def renderer(self) -> Any:
        """The :class:`~billiards_env.render.TableRenderer` drawing this env (created, and pygame imported,
        on first use); front-ends such as ``billiards-play`` use its pixel mapping (``to_pixels``)."""
        return self._ensure_renderer()

    def _ensure_renderer(self) -> Any:
        if self._renderer is None:
            from billiards_env.render import TableRenderer

            self._renderer = TableRenderer(self.table, self.config.ball_radius, width_px=self.config.render_width,
                                           hud=self.task.hud(self) is not None)
        return self._renderer

    def _cue_overlay(self) -> tuple[float, float, float] | None:
        s = self.last_shot
        return None if s is None else (s[0], s[1], s[2])

    def render_data(self, orientations: bool = True) -> dict[str, Any]:
        """What is drawn besides the balls, as plain data (keywords of ``TableRenderer.draw``): the last shot's cue
        (``cue``), under the spin model its tip offset (``tip``, on a cue-ball diagram) and the balls' orientations
        (``orientations``, turned by the animated shots), and a game's HUD (``hud``, from ``task.hud``; players,
        turn, the last call, the score). Front-ends (``billiards-play``) draw with it."""
        data: dict[str, Any] = {"cue": self._cue_overlay()}
        if self._spin:
            data["tip"] = self.last_tip
            if orientations:
                data["orientations"] = self._orientations_now()
        hud = self.task.hud(self)
        if hud is not None:
            data["hud"] = hud
        return data

    def _orientations_now(self) -> np.ndarray:
        if self._orientations is None:
            self._orientations = np.tile(np.eye(3), (self.n_balls, 1, 1))
        return self._orientations

    def _draw_state(self, positions: np.ndarray | None = None, on_table: np.ndarray | None = None,
                    surface: bool = False, view: dict[str, Any] | None = None,
                    orientations: np.ndarray | None = None) -> Any:
        """The table with the balls at ``positions`` (default: now), as an array (or a pygame surface); ``view``
        (an animated shot's cue, tip and HUD) and ``orientations`` replace those of now."""
        r = self._ensure_renderer()
        pos = self.balls.pos if positions is None else positions
        on = self.balls.on_table if on_table is None else on_table
        data = self.render_data()
        if view:
            data.update(view)
        if orientations is not None:
            data["orientations"] = orientations
        draw = r.draw if surface else r.render_array
        return draw(pos, on, self.ball_numbers, **data)

    def animation_times(self, duration: float) -> np.ndarray:
        """Simulated instants (s) drawn for a shot lasting ``duration`` s: ``frame_times(duration, render_fps)``
        (with ``render_speedup`` s != 1: ``frame_times(duration / s, render_fps) * s``); the last is ``duration``."""
        from billiards_env.render import frame_times

        s = self.config.render_speedup
        if s == 1.0:
            return frame_times(duration, self.config.render_fps)
        times = frame_times(duration / s, self.config.render_fps) * s
        times[-1] = duration
        return times

    def _animate(self, trajectory: Any, view: dict[str, Any] | None = None, final: bool = True) -> None:
        """Draw a shot just simulated: frames at :meth:`animation_times` of its trajectory, with ``view`` (the
        shot's cue, tip and HUD); the last one is the state after the shot (``final``: the table now, cue ball
        re-spotted if it was pocketed; else the trajectory's own end, when another shot follows in the same step).
        Under the spin model the balls turn with their spins (:func:`~billiards_env.render.animation.sample_frames`)
        and keep the orientation they end in."""
        if trajectory is None:  # pragma: no cover - the record path always has one
            return
        from billiards_env.render.animation import sample_frames

        times = self.animation_times(trajectory.duration)
        pos, on, turned = sample_frames(trajectory, times, self._orientations_now() if self._spin else None)
        if turned is not None:
            self._orientations = turned[-1]
        shown = len(times) - 1 if final else len(times)
        for k in range(shown):
            state = (pos[k], on[k], None if turned is None else turned[k])
            if self.render_mode == "rgb_array_list":
                self._frames.append(self._draw_state(state[0], state[1], view=view, orientations=state[2]))
            elif not self._show(state, view):
                return
        if final:
            if self.render_mode == "rgb_array_list":
                self._frames.append(self._draw_state())
            else:
                self._show(None)

    def _show(self, state: tuple[np.ndarray, np.ndarray, np.ndarray | None] | None,
              view: dict[str, Any] | None = None) -> bool:
        """Human mode: show one frame (``state``: positions, flags, orientations, drawn with ``view``; or now) at
        render_fps, as soon as it is drawn; False once the user closed the window. The window is a :class:`~billiards_env.render.HumanWindow` made on first use, or
        whatever a front-end put in ``_window`` before (``closed``, ``show(surface, fps)``, ``close()``):
        ``billiards-play`` shows the env's frames in its own window that way."""
        import pygame

        from billiards_env.render import HumanWindow

        r = self._ensure_renderer()
        w = self._window
        if w is not None and not pygame.display.get_init():
            # pygame has one display per process: another window's close() (e.g. a second env) shut it down.
            try:
                if w.closed:  # closed by the user (or by us): stays closed
                    return False
            except pygame.error:
                w = None
        if w is None:
            w = self._window = HumanWindow(r.size, title=self.env_id)
        if w.closed:
            return False
        surf = self._draw_state(surface=True) if state is None else \
            self._draw_state(state[0], state[1], True, view, state[2])
        w.show(surf, self.config.render_fps)
        return True


def make_policy(policy: Any, env: gym.Env) -> Callable[[np.ndarray], np.ndarray]:
    """A callable ``obs -> action`` from a callable, an SB3-style model (``predict``), or None (random
    actions from the env's action space)."""
    if policy is None:
        return lambda obs: env.action_space.sample()
    if hasattr(policy, "predict"):
        return lambda obs: policy.predict(obs, deterministic=True)[0]
    if callable(policy):
        return policy
    raise TypeError(f"policy: expected a callable obs -> action, a model with predict(), or None; got "
                    f"{type(policy).__name__}")


__all__: Sequence[str] = ["BilliardsEnv", "RENDER_MODES", "make_policy"]
