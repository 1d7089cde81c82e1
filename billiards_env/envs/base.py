"""The billiards environment: a table state, an action type, an observation type and a task, joined.

Each registered id is a small subclass that names its packaged scene (``scene``) and documents itself (see
:mod:`.one_ball`, :mod:`.three_balls`, :mod:`.rack`, :mod:`.nine_ball`, :mod:`.eight_ball`). The parts (as in
HighwayEnv and panda-gym) read the :class:`~billiards_env.table_state.TableState`, never the env:

- the table state (:mod:`billiards_env.table_state`): the balls as arrays, the table, the physics and solver, the
  shot settings, and who is to shoot and what they may do (the task's view, computed once per shot);
- :mod:`.actions`: the action type turns an action vector into a cue shot (``action_type`` key);
- :mod:`.observations`: the observation type turns the table state into an observation (``observation_type``);
- :mod:`.tasks` / :mod:`.games`: the task scores a shot: reward, termination, success, its part of ``info``;
- every shot goes through the one shot path, :func:`billiards_env.shot_path.play_shot`;
- drawing is delegated to :mod:`billiards_env.render`, imported only when a render mode is set.

Speed: with the pot task on the exact solver ``step`` is one compiled call on the live arrays (the native vector
env's step on one table, :mod:`._pot_fast`); the placements that ``reset`` draws are valid by construction, and
scenes given through ``reset(options=...)`` are validated there.
"""
from __future__ import annotations

from typing import Any, Callable, ClassVar, Mapping, NamedTuple, Sequence

import gymnasium as gym
import numpy as np

from billiards_env.physics.balls import Balls, validate_balls
from billiards_env.physics.errors import SceneError
from billiards_env.games import GAMES
from billiards_env.games.infos import conform, mask_of
from billiards_env.games.session import GameSession
from billiards_env.physics.codes import STATUS_NAMES
from billiards_env.physics.layout import (DIAMOND_ORDER, RACK_ORDER, diamond_positions, foot_spot, head_spot,
                                          head_string_x, place_random, rack_rows, triangle_positions)
from billiards_env.physics.model import Physics
from billiards_env.physics.simulate import Simulator
from billiards_env.physics.table import Table
from billiards_env.shot_path import CueShot, PlayedShot, play_shot
from billiards_env.table_state import ShotSettings, TableState

from ._pot_fast import pot_fast_step
from ._seeding import np_random
from .actions import AbsoluteAim, ActionType, action_factory
from .config import ConfigError, EnvConfig, load_config
from .info import OPPONENT_TURNS, blank_info, info_schema, info_words, shot_info
from .observations import observation_factory
from .games import GameTask, task_factory
from .opponent import Opponent
from .tasks import Driver

RENDER_MODES = ["human", "rgb_array", "rgb_array_list"]



def frame_shares(durations: list[float], cap: int) -> list[int]:
    """How many frames each of a step's shots gets when they must share ``cap`` frames (``rgb_array_list``): while
    ``cap`` allows two a shot (its first and last state), two each and the rest in proportion to the shots'
    durations; else one (its last state) for each of the last ``cap`` shots and none for the earlier ones. The
    shares sum to at most ``cap``."""
    n = len(durations)
    if cap >= 2 * n:
        total = sum(durations) or 1.0
        spare = cap - 2 * n
        return [2 + int(spare * d / total) for d in durations]
    return [0] * max(n - cap, 0) + [1] * min(n, cap)

def check_options_mapping(options: Any) -> None:
    """Refuse reset ``options`` that are not a dict (``options=[1, 2]``) with what to give instead."""
    if not isinstance(options, Mapping):
        raise ValueError(f"reset options must be a dict, got {type(options).__name__} {options!r}; e.g. "
                         "reset(options={'positions': ...}) or reset() for the usual start")


class StartLayout(NamedTuple):
    """Where ``reset`` puts the balls: ``fixed_rows`` at ``fixed_xy`` (a rack, a head-spot cue ball, a game's own
    layout), the ``random_rows`` each uniformly in its region (``regions`` rows ``(x0, x_span, y0, y_span)``), clear
    of the ``pockets`` (centres ``(P, 2)``)."""

    fixed_rows: list[int]
    fixed_xy: np.ndarray
    random_rows: np.ndarray
    regions: np.ndarray
    pockets: np.ndarray


class BilliardsEnv(gym.Env[np.ndarray, np.ndarray]):
    """Base class of the billiards environments (see the subclasses for each id's manual).

    Constructor: ``BilliardsEnv(render_mode=None, config=None, **overrides)``; ``config`` is a YAML path, a
    mapping or an :class:`~billiards_env.envs.config.EnvConfig` layered over the class's packaged scene, and
    ``overrides`` are config keys (see :mod:`billiards_env.envs.config`).

    Live state for players and tools: ``table_state`` (the :class:`~billiards_env.table_state.TableState` every
    part reads: ``table_state.balls``, updated IN PLACE by every shot (``copy()`` it to keep a snapshot),
    ``table_state.view``: who is to shoot and what they may do; ``state`` is the same object), and as shortcuts ``balls``, ``table``, ``physics``, ``simulator`` (to try shots:
    ``simulator.run(balls.strike(0, angle, speed), validate=False)``); ``config``, ``task``, ``action_type``,
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

        n = c.n_object_balls + 1
        game = GAMES.get(c.task)
        ids, numbers = (game.session_class if game is not None else GameSession).ball_set(c.n_object_balls)
        balls = Balls.from_positions(np.zeros((n, 2)), ids=ids, radius=c.ball_radius, mass=c.ball_mass)
        simulator = Simulator(c.table, c.physics, solver=c.solver.name, dt=c.solver.dt, contact=c.solver.contact,
                              max_time=c.max_time, max_events=c.max_events)
        spin = c.physics.has_spin
        settings = ShotSettings(float(c.speed_min), float(c.speed_max), float(c.angle_noise), float(c.speed_noise),
                                float(c.tip_noise), spin and bool(c.spin_action), float(c.max_tip_offset),
                                c.speed_noise_mode == "absolute")
        #: The table state every part reads (see the class docstring).
        self.table_state = TableState(balls, c.table, c.physics, simulator, numbers, settings)
        self.shots = 0
        self.last_shot: tuple[float, float, float, float] | None = None
        #: Tip offsets ``(side, top)`` of the last shot (fractions of R; spin model).
        self.last_tip: tuple[float, float] = (0.0, 0.0)
        self._needs_reset = True

        self.task = task_factory(c, self.table_state)
        self.action_type: ActionType = action_factory(c, self.task.has_ball_in_hand, self.task.declarations,
                                                      c.table.n_pockets)
        self.observation_type = observation_factory(c, c.table, n, self.task.n_features)
        self.action_space = self.action_type.space
        self.observation_space = self.observation_type.space
        #: Every key of ``info`` with its dtype, shape and meaning: the same keys at reset and at every step
        #: (:func:`~billiards_env.envs.info.info_schema`; ``docs/infos.md``).
        self.info_schema = info_schema(c)
        self._driver = Driver(self._play)
        self._exact_type: ActionType | None = None  # see acting_type()
        if isinstance(self.task, GameTask):  # the opponent plays its shots on the table state the task gives it
            self.task.take_opponent(Opponent(self.observation_type, self.action_type, self.acting_type(),
                                             self.task.spec.name, policy=c.opponent))

        #: Whether steps may take the compiled fast path (tests switch it off to compare with the Python path).
        self._fast = True
        self._spin = spin
        # The pot task on the exact solver: the whole step in one compiled call (envs/_pot_fast.py).
        self._pot_fast = pot_fast_step(self)

        # Fixed part of the starting layout (rack and/or head-spot cue), checked once here.
        self._pockets = np.ascontiguousarray(self.table.pocket_xy, dtype=float).reshape(-1, 2)
        self._fixed_rows, self._fixed_xy = self._fixed_layout()
        self._random_rows = np.array([i for i in range(n) if i not in self._fixed_rows], np.int64)
        self._regions = np.array([self._region(i) for i in self._random_rows.tolist()], dtype=float).reshape(-1, 4)
        self._check_layout()

        # Rendering (created lazily: pygame is imported only when something is drawn).
        self._record = render_mode in ("human", "rgb_array_list")
        self._renderer: Any = None
        self._window: Any = None
        self._frames: list[np.ndarray] = []
        self._animations: list[tuple[Any, dict[str, Any]]] = []  # (trajectory, what to draw with it)
        self._shot_view: dict[str, Any] = {}  # what to draw with the shot just played (recording modes)
        self._orientations: np.ndarray | None = None  # the balls' orientations (spin model, animations)

    @property
    def start_layout(self) -> "StartLayout":
        """Where ``reset`` puts the balls (checked when the env was made): the native vector env places its tables
        by it."""
        return StartLayout(list(self._fixed_rows), self._fixed_xy, self._random_rows, self._regions, self._pockets)

    # --- the table state's parts, as shortcuts -------------------------------------------------------------------
    @property
    def state(self) -> TableState:
        """The same object as :attr:`table_state` (its earlier name, kept for code written against it)."""
        return self.table_state

    @property
    def balls(self) -> Balls:
        """The live balls (``state.balls``; updated in place by every shot)."""
        return self.table_state.balls

    @property
    def table(self) -> Table:
        return self.table_state.table

    @property
    def physics(self) -> Physics:
        return self.table_state.physics

    @property
    def simulator(self) -> Simulator:
        return self.table_state.simulator

    @property
    def fast_step(self) -> bool:
        """Whether steps may take the compiled fast path (the pot scenes' one-call step, when nothing is drawn);
        False plays every step through the Python path (tests and benchmarks compare the two)."""
        return self._fast

    @fast_step.setter
    def fast_step(self, on: bool) -> None:
        self._fast = bool(on)

    @property
    def n_balls(self) -> int:
        return self.table_state.n_balls

    @property
    def ball_ids(self) -> tuple[str, ...]:
        return self.table_state.ids

    @property
    def ball_numbers(self) -> tuple[int, ...]:
        """Ball number of each row for drawing (0 = cue ball)."""
        return self.table_state.numbers

    # ======================================================================================================
    # Gymnasium API
    # ======================================================================================================
    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None
              ) -> tuple[np.ndarray, dict[str, Any]]:
        """Start an episode. ``options`` may set the scene: ``{"positions": (N,2) metres}`` (rows: cue, 1..n)
        with an optional ``"pocketed": (N,) bool`` (object balls already off the table); it is validated. The
        games also read ``ball_in_hand``, ``groups`` and ``break_shot`` with ``positions``."""
        if seed is not None:  # what gymnasium.Env.reset(seed=seed) does, with the same generator, faster
            self._np_random, self._np_random_seed = np_random(seed)
        b = self.balls
        b.vel.fill(0.0)
        b.ang.fill(0.0)
        b.on_table.fill(True)
        if options:
            self.set_positions(options)
        else:
            self._place(self.np_random, b.pos)
        self.shots = 0
        self.last_shot = None
        self.last_tip = (0.0, 0.0)
        self._orientations = None
        self._needs_reset = False
        self.table_state.changed()
        info = blank_info(self.info_schema)  # the schema's keys: the task's, and no shot yet
        info.update(self.task.reset(self.table_state, self.np_random, options, self._driver))
        self.show_new_episode()
        return self.observation_type.observe(self.table_state), self._conformed(info)

    def show_new_episode(self) -> None:
        """What ``reset`` draws: the frame list started afresh with the table now (``rgb_array_list``), or the table
        shown (``human``); nothing otherwise. The native vector env calls it on the table it draws."""
        if self.render_mode == "rgb_array_list":
            self._frames = [self._draw_state()]
        elif self.render_mode == "human":
            self._show(None)

    def attach_window(self, window: Any) -> None:
        """Show the human mode's frames in ``window`` (an object with ``closed``, ``show(surface, fps)`` and
        ``close()``) instead of a window of the env's own: ``billiards-play`` shows them in its window so."""
        self._window = window

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
            fast = self._pot_fast.step(action, self.shots, self.np_random)
            obs, reward, terminated, truncated, info = fast[:5]
            self.shots += 1
            self.last_shot, self.last_tip = fast.last_shot, fast.last_tip
            self._animations = []
            self._needs_reset = terminated or truncated
            return obs, reward, terminated, truncated, info
        shot = self.action_type.shot(self.table_state, action)
        self.task.before_shot(shot)
        self._animations = []
        played = self._play(shot, "agent")
        view = self._shot_view
        self.shots += 1
        reward, terminated, truncated, info = self.task.on_shot(self.table_state, played, self.shots, self._driver)
        o = played.outcome
        info.update(shot_info(mask_of(o.pocketed, self.n_balls), o.scratch, o.first_contact, o.n_events, o.sim_time,
                              STATUS_NAMES.index(o.status), self.shots, played.shot))
        if OPPONENT_TURNS in info:  # (opponent_infos) last, as at reset
            info[OPPONENT_TURNS] = info.pop(OPPONENT_TURNS)
        if self._record:  # the agent's shot, then the opponent's reply in a game
            self._animate_step([(played.trajectory, view)] + self._animations)
        self._needs_reset = terminated or truncated  # stepping on after the end raises ResetNeeded
        return self.observation_type.observe(self.table_state), reward, terminated, truncated, self._conformed(info)

    def _conformed(self, info: dict[str, Any]) -> dict[str, Any]:
        """``info`` (and each of its ``opponent_turns``) in the schema's forms (numbers numpy scalars, flags 0-d
        boolean arrays: :func:`~billiards_env.games.infos.single`)."""
        conform(info, self.info_schema)
        for turn in info.get(OPPONENT_TURNS, ()):
            conform(turn, self.info_schema)
        return info

    def info_words(self, info: dict[str, Any], ids: Sequence[str] | None = None) -> dict[str, Any]:
        """``info`` in words (:func:`~billiards_env.envs.info.info_words`): the balls as ids, the codes as names.
        ``ids``: the rows' ids, by default the rows' now (three-cushion orders its rows shooter first, so a shot's
        rows are those of its shooter: give the ids as that shot saw them)."""
        return info_words(info, self.info_schema, tuple(self.ball_ids if ids is None else ids))

    def _play(self, shot: CueShot, by: str = "agent") -> PlayedShot:
        """Play ``shot`` through the shot path with the env's noise (``np_random``) and recording; ``by``:
        ``"agent"``, ``"opponent"`` (animated after the agent's shot) or ``"table"`` (nobody's shot: not drawn)."""
        played = play_shot(self.table_state, shot, self.np_random, record=self._record)
        if by == "table":
            self.last_shot, self.last_tip = None, (0.0, 0.0)
            return played
        p = played.shot
        self.last_shot = (played.start[0], played.start[1], p.angle, p.speed)
        self.last_tip = (p.side, p.top)
        if self._record:  # drawn with this shot's animation: its cue and tip, a game's HUD before the call
            self._shot_view = {**self.render_data(orientations=False), "numbers": self.ball_numbers}
            if by == "opponent" and played.trajectory is not None:
                self._animations.append((played.trajectory, self._shot_view))
        return played

    def acting_type(self) -> ActionType:
        """The action type a player acts in as the opponent: the env's, or, when the env's cannot express every shot
        (``candidates``), the absolute type with the same dims (so the player plays the shots it chose)."""
        at = self.action_type
        if at.exact_inverse:
            return at
        if self._exact_type is None:
            self._exact_type = AbsoluteAim(self.config, at.placement, at.declarations, at.n_pockets)
        return self._exact_type

    def observe(self, player: int | None = None) -> np.ndarray:
        """The observation of the table now (what ``reset`` and ``step`` return). ``player`` (games: 0 or 1): the
        game features take that player's point of view (own group, own fouls, whose turn) instead of the shooter's;
        the two-player env (:mod:`billiards_env.multi`) observes each agent so."""
        if player is not None:
            if self.table_state.game is None:
                raise ValueError(f"observe(player={player!r}): task {self.task.name!r} has no players; call "
                                 "observe()")
            if player not in (0, 1):
                raise ValueError(f"player: must be 0 or 1, got {player!r}")
        return self.observation_type.observe(self.table_state, player)

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
        """The shot an action means now (no noise): a :class:`~billiards_env.shot_path.CueShot` ``(angle rad,
        speed m/s, side, top, place, calls)``. NaN/inf raise ValueError; finite values outside [-1, 1] are
        clipped."""
        return self.action_type.shot(self.table_state, action)

    def action_from_shot(self, angle: float, speed: float, side: float = 0.0, top: float = 0.0,
                         place: tuple[float, float] | None = None, **calls: Any) -> np.ndarray:
        """The action that strikes the cue ball at ``angle`` (rad, 0 = +x, CCW) and ``speed`` (m/s) with tip
        offsets ``side``/``top`` (spin dims) from ``place`` (ball in hand), with the game's declarations ``calls``
        by name (:class:`~billiards_env.games.declarations.Declaration`: ``pocket=`` the pocket called for the 8 or
        straight pool's ball, ``ball=`` straight pool's called ball, ``push=True`` a 9-ball push-out), in the active
        action type (inverse of :meth:`shot_from_action`); dims not given are neutral. Arguments the env cannot play
        raise ``ValueError`` naming the valid range: a speed outside [speed_min, speed_max], tip offsets without spin
        dims or beyond ``max_tip_offset``, a place without ball in hand or outside its area, a declaration the game
        does not make or a value it cannot take. (A policy's actions are never refused: they are clipped, see
        :mod:`.actions`.)"""
        self._check_shot_arguments(float(angle), float(speed), float(side), float(top), place, calls)
        return self.action_type.action(self.table_state, angle, speed, side, top, place, **calls)

    def _check_shot_arguments(self, angle: float, speed: float, side: float, top: float,
                              place: Any, calls: dict[str, Any]) -> None:
        at = self.action_type
        s = self.table_state.settings
        for name, v in (("angle", angle), ("speed", speed), ("side", side), ("top", top)):
            if not np.isfinite(v):
                raise ValueError(f"action_from_shot: {name} must be a finite number, got {v!r}")
        lo, hi = s.speed_range
        if not lo - 1e-9 <= speed <= hi + 1e-9:
            raise ValueError(f"action_from_shot: speed {speed} m/s is outside this env's range [{lo}, {hi}] "
                             "(speed_min, speed_max); give a speed in it or make the env with another range")
        if (side or top) and not at.spin:
            raise ValueError("action_from_shot: side/top given, but this env's action has no tip-offset dims; make "
                             "it with friction='spin' and spin_action=True, or leave them 0")
        if at.spin and np.hypot(side, top) > s.max_tip_offset + 1e-12:
            raise ValueError(f"action_from_shot: tip offset (side {side}, top {top}) is {np.hypot(side, top):.3g} R "
                             f"from the centre; the largest is max_tip_offset = {s.max_tip_offset} R")
        if place is not None:
            try:
                x, y = (float(v) for v in place)
            except (TypeError, ValueError):
                raise ValueError(f"action_from_shot: place must be two numbers (x, y) in metres, got {place!r}") \
                    from None
            if not (np.isfinite(x) and np.isfinite(y)):
                raise ValueError(f"action_from_shot: place must be finite, got ({x}, {y})")
            area = self.table_state.view.place_area if at.placement else None
            if area is None:
                raise ValueError("action_from_shot: place given, but the shooter has no ball in hand now "
                                 "(state.view.place_area is None); leave place None")
            if not area.contains(x, y):
                raise ValueError(f"action_from_shot: place ({x:.4g}, {y:.4g}) is outside the ball-in-hand area "
                                 f"{area.describe()}")
        declared = {d.name: d for d in at.declarations}
        for name, value in calls.items():
            d = declared.get(name)
            if d is None:
                if value is None or value is False:  # nothing declared: fine for any game
                    continue
                makes = ", ".join(map(repr, declared)) or "none"
                raise ValueError(f"action_from_shot: {name}={value!r} given, but {self.task.name!r} declares no "
                                 f"{name!r} with its rules options (its declarations: {makes}; 8-ball calls a "
                                 "pocket with call_eight, 9-ball pushes out with push_out, straight pool calls a "
                                 "ball and a pocket); leave it out")
            try:
                d.check(value, at.n_pockets, at.n_balls)
            except ValueError as exc:
                raise ValueError(f"action_from_shot: {exc}") from None

    def target_ball(self) -> int | None:
        """Row of the ball to hit first (the relative and ghost aim's target): the lowest-numbered object ball on
        the table, or the legal ball of a game, or None (``state.view.target``)."""
        return self.table_state.view.target

    def legal_cue_position(self, x: float, y: float) -> tuple[float, float]:
        """Where a ball-in-hand cue ball asked for at ``(x, y)`` goes (:meth:`TableState.legal_cue_position`)."""
        return self.table_state.legal_cue_position(x, y)

    def cue_moved_to(self, place: tuple[float, float]) -> Any:
        """Temporarily put the cue ball at ``place`` (:meth:`TableState.cue_moved_to`)."""
        return self.table_state.cue_moved_to(place)

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
        game = GAMES.get(c.task)
        if game is not None and c.placement in game.session_class.placements:  # the game's own layout, every row
            spots = game.session_class.start_layout(c.placement, self.table, c.ball_radius)
            rows = list(range(len(spots)))
            pts = [(float(x), float(y)) for x, y in spots]
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
            place_random(rng, pos, self._random_rows, self._regions, self._fixed_xy, self._pockets,
                         c.pocket_margin, 2.0 * c.ball_radius + c.ball_gap)
        except SceneError:
            raise ConfigError(
                f"{self.env_id}: could not place the balls at random; lower n_object_balls, pocket_margin, "
                "ball_gap or cushion_margin") from None

    def set_positions(self, options: dict[str, Any], balls: Balls | None = None,
                       rng: np.random.Generator | None = None) -> None:
        """Set up ``balls`` (default: the env's) from reset ``options`` (checked), placing at random from ``rng``
        (default: ``np_random``) when no positions are given."""
        b = self.balls if balls is None else balls
        check_options_mapping(options)
        unknown = sorted(set(options) - {"positions", "pocketed"} - set(self.task.option_keys), key=str)
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
            self._place(self.np_random if rng is None else rng, b.pos)
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

            game = self.table_state.game
            self._renderer = TableRenderer(self.table, self.config.ball_radius, width_px=self.config.render_width,
                                           hud=self.task.hud() is not None,
                                           markings=game.markings() if game is not None else None,
                                           palette=game.palette if game is not None else None)
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
        hud = self.task.hud()
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
        numbers = data.pop("numbers", self.ball_numbers)  # an animated shot's rows as it saw them
        return draw(pos, on, numbers, **data)

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

    def _animate_step(self, shots: list[tuple[Any, dict[str, Any]]]) -> None:
        """Draw the shots of one step in order (each ``(trajectory, view)``). In ``rgb_array_list`` mode a step
        draws at most ``render_max_frames`` frames: when its shots would need more (a long reply of the opponent),
        each shot gets a share of them in proportion to its duration, evenly spaced in time (at least its first and
        last state)."""
        cap = self.config.render_max_frames
        times = [self.animation_times(t.duration) for t, _ in shots]
        if self.render_mode == "rgb_array_list" and cap and sum(len(t) for t in times) > cap:
            shares = frame_shares([float(t.duration) for t, _ in shots], cap)
            times = [np.linspace(0.0, float(t.duration), m) if m > 1 else np.full(m, float(t.duration))
                     for (t, _), m in zip(shots, shares)]
        for k, ((trajectory, view), when) in enumerate(zip(shots, times)):
            self.animate(trajectory, view, final=k == len(shots) - 1, times=when)

    def animate(self, trajectory: Any, view: dict[str, Any] | None = None, final: bool = True,
                 times: np.ndarray | None = None) -> None:
        """Draw a shot just simulated: frames at :meth:`animation_times` of its trajectory, with ``view`` (the
        shot's cue, tip and HUD); the last one is the state after the shot (``final``: the table now, cue ball
        re-spotted if it was pocketed; else the trajectory's own end, when another shot follows in the same step).
        Under the spin model the balls turn with their spins (:func:`~billiards_env.render.animation.sample_frames`)
        and keep the orientation they end in."""
        if trajectory is None:  # pragma: no cover - the record path always has one
            return
        from billiards_env.render.animation import sample_frames

        if times is None:
            times = self.animation_times(trajectory.duration)
        if len(times) == 0:  # a shot the frame cap leaves out: only the balls' turning is carried on
            times = np.array([float(trajectory.duration)])
            if self._spin:
                self._orientations = sample_frames(trajectory, times, self._orientations_now())[2][-1]
            return
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
        the one a front-end attached (:meth:`attach_window`) (``closed``, ``show(surface, fps)``, ``close()``):
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


__all__: Sequence[str] = ["BilliardsEnv", "StartLayout", "RENDER_MODES", "check_options_mapping", "make_policy"]
