"""The native vector env's games: 9-ball and 8-ball tables reset and stepped in compiled code, opponents and the
``candidates`` types included (:mod:`._game_kernels`), and what stays in Python: the ``features`` observation type
and resets with options (per table), and the infos.

:func:`native_games` says whether an env qualifies (9-ball or 8-ball on the exact solver, playing alone or against
the geometric player, an action type of the envs' own, nothing drawn); :class:`GameTables` holds the tables' game
states and runs them for :class:`~billiards_env.envs.vector.BilliardsVectorEnv`, which keeps the ball arrays, the
generators and the autoreset. The infos are built as arrays, one per key for all the tables
(:meth:`GameTables.columns` from the kernels' shot records and the game states; the opponent's turns, one dict per
shot, for all the tables at once), and stacked by :func:`stack_columns` as Gymnasium's ``VectorEnv._add_info``
stacks the single envs' dicts in sub-env order (the schema's dtypes and shapes, masks, key order), so the vector
info is the one ``SyncVectorEnv`` makes; the per-table dicts (:class:`InfoColumns.dicts`) are made only when asked
for (``BilliardsVectorEnv.sub_infos``).
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from billiards_env.games.infos import conform, unstack
from billiards_env.games.pool import RACK_EIGHT, RACK_NINE, EightBallSession, NineBallSession, pool_features
from billiards_env.physics.batch import use_parallel
from billiards_env.physics.errors import SceneError
from billiards_env.physics.threads import default_threads, on_slices
from billiards_env.physics.layout import DIAMOND_ORDER, RACK_ORDER, foot_spot, head_spot, head_string_x
from billiards_env.players.geometric import GeometricPlayer
from billiards_env.players.geometry import MAX_CUT, state_model
from billiards_env.rules import pool_judge as pj
from billiards_env.table_state import RectArea, ShotView, TableState

from . import _game_config as gc
from . import _game_kernels as gk
from .actions import AIM_ABSOLUTE, AIM_GHOST, AIM_RELATIVE, AbsoluteAim, CandidateShots, GhostAim, RelativeAim
from .candidates import EASE_SPREAD
from .config import ConfigError
from .games import MAX_RERACKS, MAX_TURN_SHOTS, GameTask
from .info import OPPONENT_TURNS
from .observations import CandidateFeatures, Positions

if TYPE_CHECKING:  # pragma: no cover
    from .base import BilliardsEnv
    from .vector import BilliardsVectorEnv

_AIM_CODES = {AbsoluteAim: AIM_ABSOLUTE, RelativeAim: AIM_RELATIVE, GhostAim: AIM_GHOST}
_SESSIONS = {NineBallSession: (RACK_NINE, "diamond", DIAMOND_ORDER), EightBallSession: (RACK_EIGHT, "rack",
                                                                                            RACK_ORDER)}


def native_games(env: "BilliardsEnv", render_mode: str | None) -> str | None:
    """Why the native game path does not apply to ``env`` (a made env of the id), or None when it does."""
    task = env.task
    if not isinstance(task, GameTask):
        return "not a game"
    c = env.config
    session = task.session
    if type(session) not in _SESSIONS:
        return f"the game {task.name!r} has no compiled rules"
    if render_mode is not None:
        return "rendering"
    if c.solver.name != "exact":
        return "the step solver"
    opp = task.opponent
    if opp is not None and not (type(opp) is GeometricPlayer and opp.max_cut == MAX_CUT):
        return "an opponent other than the geometric player"
    at = env.action_type
    if type(at) not in _AIM_CODES and type(at) is not CandidateShots:
        return f"the action type {at.name!r}"
    if type(env.acting_type()) not in _AIM_CODES:
        return "the opponent's action type"
    rack, placement, _ = _SESSIONS[type(session)]
    if c.placement not in (placement, "random"):
        return f"placement {c.placement!r}"
    full = session.rules.full_rack
    if c.n_object_balls != len(full) or tuple(env.table_state.numbers) != tuple(range(len(full) + 1)):
        return "the ball set"
    return None


class GameTables:
    """The game side of a native vector env's tables (see the module docstring)."""

    def __init__(self, venv: "BilliardsVectorEnv") -> None:
        self.venv = venv
        t = venv.template
        self.template = t
        c = t.config
        n, nb = venv.num_envs, t.n_balls
        task: GameTask = t.task  # type: ignore[assignment]
        session = task.session
        self.rules = session.rules
        at = t.action_type
        acting = t.acting_type()
        self.action_type = at
        self.opts = pj.options_row(self.rules)
        self.full = pj.mask_of(self.rules.full_rack)
        rack, placement, order = _SESSIONS[type(session)]
        table = t.table
        r = float(t.balls.radius[0])
        hx, hy = head_spot(table)
        fx, fy = foot_spot(table)
        cfg = np.zeros((), gc.GAME_FLOATS)[()]  # a record: the floats by name
        gc.put_shot_fields(cfg, at, c)
        cfg["ghost"] = at.max_angle
        cfg["act_ghost"] = acting.max_angle
        cfg["radius"] = r
        cfg["length"] = table.length
        cfg["width"] = table.width
        cfg["kitchen_x"] = head_string_x(table)
        cfg["head_x"], cfg["head_y"] = hx, hy
        cfg["foot_x"], cfg["foot_y"] = fx, fy
        cfg["speed_min"], cfg["speed_max"] = t.table_state.settings.speed_range
        cfg["win"] = c.win_reward
        cfg["loss"] = c.loss_penalty
        cfg["foul_penalty"] = c.foul_penalty
        cfg["pot_reward"] = c.pot_reward
        cfg["position_reward"] = c.position_reward
        cfg["ease_sigma"] = max(t.table_state.settings.angle_noise, EASE_SPREAD)
        cfg["sx"] = 1.0 / table.length
        cfg["sy"] = 1.0 / table.width
        cfg["pocket_margin"] = c.pocket_margin
        cfg["min_dist"] = 2.0 * c.ball_radius + c.ball_gap
        cfg["break_speed"] = float(c.speed_max)
        cfg["max_cut"] = MAX_CUT
        cfg["squirt"] = c.physics.squirt
        cfg["cue_end_mass"] = c.physics.cue_end_mass
        if type(at) is CandidateShots:
            cfg["cand_lo"], cfg["cand_hi"] = at.speed_range
            cfg["log_factor"] = at.log_factor
        ot = t.observation_type
        if type(ot) is CandidateFeatures:
            cfg["obs_lo"], cfg["obs_hi"] = ot.speed_range
        self.cfg = cfg
        icfg = np.zeros((), gc.GAME_INTS)[()]
        icfg["aim"] = gc.AIM_CANDIDATES if type(at) is CandidateShots else _AIM_CODES[type(at)]
        icfg["act_aim"] = _AIM_CODES[type(acting)]
        icfg["spin_dims"] = at.spin
        icfg["spin_model"] = t.physics.has_spin
        icfg["n_act"] = at.n
        icfg["place_at"] = at.place_at
        icfg["pocket_at"] = at.declare_at.get("pocket", -1)
        icfg["push_at"] = at.declare_at.get("push", -1)
        icfg["n_pockets"] = at.n_pockets
        icfg["opponent"] = gk.OPP_NONE if task.opponent is None else gk.OPP_GEOMETRIC
        icfg["first"] = {"agent": gk.FIRST_AGENT, "opponent": gk.FIRST_OPPONENT}.get(c.first_shooter,
                                                                                       gk.FIRST_RANDOM)
        icfg["opening"] = {"break": gk.OPEN_BREAK, "ball_in_hand": gk.OPEN_BALL_IN_HAND}.get(c.opening,
                                                                                              gk.OPEN_EITHER)
        icfg["max_shots"] = c.max_shots
        icfg["turn_cap"] = max(MAX_TURN_SHOTS, c.max_shots)
        icfg["rack"] = rack if c.placement == placement else gk.RACK_NONE
        self.positions_obs = type(ot) is Positions and ot.n_extra == 0 and ot.n_game == session.n_features
        cand_obs = type(ot) is CandidateFeatures and ot.n_game == session.n_features and \
            ot.n_slots == c.candidate_slots
        #: Whether the kernels make the observation (the positions and the candidates types).
        self.compiled_obs = self.positions_obs or cand_obs
        icfg["positions_obs"] = self.positions_obs
        icfg["candidates_obs"] = cand_obs
        icfg["speed_noise_abs"] = c.speed_noise_mode == "absolute"
        icfg["slots"] = c.candidate_slots
        icfg["max_events"] = t.simulator.max_events
        icfg["opening_respot"] = session.opening_respot
        icfg["max_reracks"] = MAX_RERACKS
        icfg["game"] = pj.GAME_NINE if type(session) is NineBallSession else pj.GAME_EIGHT
        self.icfg = icfg
        sim = t.simulator
        tm = state_model(t.table_state)
        holes = np.column_stack([table.pocket_xy, table.pocket_radius]).astype(np.float64) if table.n_pockets else \
            np.zeros((0, 3))
        self.consts = (venv.ball_radius[0], venv.ball_mass[0])
        self.tables = (sim.pocket_xy, sim.pocket_r, sim.params, tm.pocket_xy, tm.pocket_r, tm.params,
                       np.ascontiguousarray(holes))
        # The rack's slots as order_rack takes them (the positions of the numbers of the rack order in the layout).
        fixed = {int(row): xy for row, xy in zip(t.start_layout.fixed_rows, t.start_layout.fixed_xy)}
        self.rack_slots = np.array([fixed[n] for n in order], dtype=np.float64).reshape(-1, 2) \
            if icfg["rack"] != gk.RACK_NONE else np.zeros((0, 2))
        self.layout = venv.layout_arrays
        self._no_act = np.zeros((n, at.n))
        self.gst = np.zeros(n, pj.GAME_STATE_ROW)  # each table's game state, a record
        self.cap = int(icfg["turn_cap"])
        self.rec_agent = np.zeros(n, gk.SHOT_RECORD)
        self.rec_opp = np.zeros((n, self.cap), gk.SHOT_RECORD)
        self.reward = np.zeros(n)
        self.tout = np.zeros(n, gk.STEP_OUTCOME)
        self.kc = np.zeros(n, gc.KICK_CACHE)  # each table's kick cache (the candidates types)
        # Each table's cache of its balls' pocket windows (the geometric opponent's decisions; by position).
        self.windows = (np.zeros((n, nb, 2)), np.zeros((n, nb, tm.pocket_r.shape[0], 4)), np.zeros((n, nb), np.bool_))
        self.n_game = session.n_features
        # One table state per table (views of the batch arrays) for what stays in Python.
        self.states = []
        for k in range(n):
            st = TableState(venv.table_states[k].balls, table, t.physics, sim, t.table_state.numbers, t.table_state.settings)
            st.attach_game(_TableGame(self, k), lambda s, k=k: self.view(k))
            self.states.append(st)
        self.ids = t.ball_ids
        self._bits = np.arange(nb, dtype=np.int64)  # a bit mask over the rows -> its row mask
        self._numbers = np.asarray(t.table_state.numbers, np.int64)  # a bit mask over the numbers -> its row mask
        self._radius = r
        self._reset_infos: dict[int, dict[str, Any] | None] = {}
        self.legal = np.zeros(n, np.int64)

    # --- what Python parts read --------------------------------------------------------------------------------------
    def view(self, k: int) -> ShotView:
        """``PoolSession.view`` of table ``k``'s game state."""
        st = self.gst[k]
        legal = pj.numbers_of(pj.legal_mask(st))
        on = self.venv.on_table[k]
        over = bool(st["over"])
        area = None
        if st["bih"] != pj.BIH_NO and not over:
            r = self._radius
            x1 = self.cfg["kitchen_x"] if st["bih"] == pj.BIH_KITCHEN else self.cfg["length"] - r
            area = RectArea(r, x1, r, self.cfg["width"] - r)
        return ShotView(tuple(int(i) for i in legal if on[i] and i != 0), min(legal) if legal else None, area,
                        bool(st["break_shot"] and not over), bool(pj.needs_called_pocket(st, self.opts)),
                        bool(st["push_available"]), int(st["shooter"]))

    def game_state(self, k: int) -> Any:
        """Table ``k``'s game as a :class:`~billiards_env.rules.GameState`."""
        return pj.game_state(self.gst[k])

    # --- reset and step ----------------------------------------------------------------------------------------------
    def _play(self, rows: np.ndarray, resets: np.ndarray, act: np.ndarray) -> None:
        """:func:`._game_kernels.play_tables` on tables ``rows`` (a reset where ``resets``), on one thread when the
        batch or the machine says so (:func:`~billiards_env.physics.batch.use_parallel`)."""
        v = self.venv
        threads = min(v.threads or default_threads(), len(rows)) if use_parallel(len(rows), v.threads) else 1
        shared = (self.kc, v.pos, v.vel, v.ang, v.on_table, v.shots, *self.consts, v.generators(), self.gst, self.opts,
                  self.cfg, self.icfg, *self.tables, self.layout, self.rack_slots, self.full, self.rec_agent,
                  self.rec_opp, self.reward, self.tout, v.observations, self.windows)
        # Slices of the tables on threads (the kernel releases the GIL); each table's result is the same.
        on_slices(lambda s: gk.play_tables(rows[s], resets[s], act, *shared), len(rows), threads)
        self._check(rows)
        for k in rows.tolist():
            self.states[k].changed()

    def reset(self, rows: np.ndarray, options: dict[str, Any] | None) -> None:
        """Reset tables ``rows`` (``options``: a scene set by hand, per table through the template env)."""
        if options:
            for k in rows.tolist():
                self._reset_with_options(k, options)
            return
        self._play(rows, np.ones(len(rows), np.bool_), self._no_act)
        for k in rows.tolist():
            self._reset_infos[k] = None

    def _reset_with_options(self, k: int, options: dict[str, Any]) -> None:
        """A scene set by ``reset(options=...)`` for table ``k``: the template env's reset on the table's generator,
        its balls and game state copied to the table."""
        v = self.venv
        t = v.template
        t.np_random = v.table_rngs[k]
        _, info = t.reset(options=options)
        b = t.balls
        v.pos[k] = b.pos
        v.vel[k] = b.vel
        v.ang[k] = b.ang
        v.on_table[k] = b.on_table
        self.gst[k] = pj.state_row(t.task.session.game_state)
        self.kc[k]["valid"] = 0.0
        self.states[k].changed()
        self._reset_infos[k] = info
        self._observe_compiled(np.array([k], np.int64))

    def _observe_compiled(self, rows: np.ndarray) -> None:
        v = self.venv
        gk.observe_tables(rows, v.pos, v.on_table, *self.consts, self.gst, self.cfg, self.icfg, self.tables[3],
                          self.tables[4], self.tables[5], *self.tables[:3], self.kc, v.observations)

    def step(self, rows: np.ndarray, act: np.ndarray) -> None:
        """One step of tables ``rows`` (``act``: the batch's actions, float64 clipped)."""
        self._play(rows, np.zeros(len(rows), np.bool_), act)

    def observe(self, rows: np.ndarray) -> None:
        """The observations of tables ``rows`` (already made in the kernels for the positions and candidates
        types)."""
        if self.compiled_obs:
            return
        v = self.venv
        ot = v.template.observation_type
        for k in rows.tolist():
            v.observations[k] = ot.observe(self.states[k])

    def _check(self, rows: np.ndarray) -> None:
        err = self.tout["error"][rows]
        if not err.any():
            return
        k = int(rows[np.flatnonzero(err)[0]])
        code = int(self.tout[k]["error"])
        if code == gk.E_NO_PLACE:
            raise SceneError(f"sub-env {k}: no legal point for ball row 0 in the area: it is covered by other balls")
        if code == gk.E_RESPOT:
            raise SceneError(f"sub-env {k}: could not re-spot a ball: the long string is full")
        if code == gk.E_CUE_RESPOT:
            raise SceneError(f"sub-env {k}: could not re-spot the cue ball: the head of the table is full")
        if code == gk.E_PLACEMENT:
            raise ConfigError(f"{self.venv.env_id}: could not place the balls at random; lower n_object_balls, "
                              "pocket_margin, ball_gap or cushion_margin")
        if code == gk.E_TURN_CAP:
            raise RuntimeError(f"sub-env {k}: the opponent took {self.cap} shots in one turn without the game ending "
                               "or the turn passing; raise max_shots if its game allows longer turns")
        raise RuntimeError(f"sub-env {k}: the opponent won every game before the agent's first shot")

    # --- info ---------------------------------------------------------------------------------------------------------
    def prepare_infos(self) -> None:
        """Work out what the infos of the tables read from their game states (their legal balls), in one call;
        before :meth:`columns`."""
        gk.legal_masks(self.gst, self.legal)

    def given_reset_info(self, k: int) -> dict[str, Any] | None:
        """The info of table ``k``'s last reset when it was a scene set by ``reset(options=...)`` (the template
        env's own dict), else None."""
        return self._reset_infos.get(k)

    def _row_masks(self, masks: np.ndarray) -> np.ndarray:
        """Boolean arrays over the rows of bit masks over the rows, ``(len(masks), n_balls)``."""
        return (masks.astype(np.int64)[:, None] >> self._bits) & 1 != 0

    def _turn_lists(self, rows: np.ndarray) -> list[list[dict[str, Any]]]:
        """``info["opponent_turns"]`` (with ``opponent_infos``) of tables ``rows`` (``GameTask._turn_info`` per
        opponent shot), built from the shot records of all the tables at once."""
        counts = self.tout["n_opp"][rows]
        total = int(counts.sum())
        if total == 0:
            return [[] for _ in range(len(rows))]
        starts = np.cumsum(counts) - counts
        rec = self.rec_opp[np.repeat(rows, counts), np.arange(total) - np.repeat(starts, counts)]
        ints = [rec[f].astype(np.int64).tolist() for f in ("shooter", "reason", "first", "bih", "groups")]
        flags = [(rec[f] != 0).tolist() for f in ("foul", "scratch", "turn_over")]
        pocketed = list(self._row_masks(rec["pocketed"]))
        turns = [{"shooter": s, "pocketed": p, "scratch": sc, "first_contact": f, "foul": fo,
                  "foul_reason": r if fo else -1, "call": r, "turn_over": to, "angle": a, "speed": sp,
                  "ball_in_hand": b, "groups": g}
                 for s, r, f, b, g, fo, sc, to, p, a, sp in zip(*ints, *flags, pocketed, rec["angle"].tolist(),
                                                                rec["speed"].tolist())]
        schema = self.venv.info_schema
        for turn in turns:  # the single env's forms (numpy scalars, 0-d flags)
            conform(turn, schema)
        return [turns[s:s + c] for s, c in zip(starts.tolist(), counts.tolist())]

    def columns(self, rows: np.ndarray, step: bool) -> "InfoColumns":
        """The info of tables ``rows`` (ascending) after their last step (``step``) or reset (no shot of the agent
        yet: its keys blank), one array per key of the schema (``info_schema``: the single env's keys, dtypes and
        shapes, in its order), from the kernels' records and the game states; after :meth:`prepare_infos`."""
        n = self.venv.num_envs
        schema = self.venv.info_schema
        st = self.gst[rows]
        over = st["over"] != 0
        winner = st["winner"]
        cols = {k: np.zeros((n, *spec.shape), spec.dtype) for k, spec in schema.items()}

        def put(key: str, values: Any) -> None:
            cols[key][rows] = values

        counts = self.tout["n_opp"][rows]
        turn = np.arange(self.cap) < counts[:, None]  # the opponent's shots of each table's reply
        # The two fields read, each indexed alone: indexing the records would copy every field of every shot slot.
        opp_pocketed, opp_foul = self.rec_opp["pocketed"][rows], self.rec_opp["foul"][rows]
        put("is_success", over & (winner == 0))
        put("winner", np.where(winner < 0, -1, winner))
        put("shooter", st["shooter"])
        put("legal_targets", (np.where(over, 0, self.legal[rows])[:, None] >> self._numbers) & 1 != 0)
        put("opponent_shots", counts)
        put("opponent_pocketed", self._row_masks(np.bitwise_or.reduce(
            np.where(turn, opp_pocketed, 0).astype(np.int64), axis=1)))
        put("opponent_fouls", (turn & (opp_foul != 0)).sum(axis=1))
        put("ball_in_hand", np.where(over, pj.BIH_NO, st["bih"]))
        put("groups", st["groups"])
        if step:
            rec = self.rec_agent[rows]
            foul = rec["foul"] != 0
            reason = rec["reason"].astype(np.int64)
            put("foul", foul)
            put("foul_reason", np.where(foul, reason, -1))
            put("call", reason)
            put("turn_over", rec["turn_over"] != 0)
            put("pocketed", self._row_masks(rec["pocketed"]))
            put("scratch", rec["scratch"] != 0)
            put("first_contact", rec["first"])
            put("n_events", rec["n_events"])
            put("sim_time", rec["time"])
            put("status", rec["status"])
            put("shots", self.venv.shots[rows])
            for key in ("angle", "speed", "side", "top"):
                put(key, rec[key])
        else:
            for key in ("foul_reason", "call", "first_contact", "status"):
                put(key, schema[key].blank)
        if self.venv.template.config.opponent_infos:
            turns = np.full(n, None, dtype=object)
            for k, t in zip(rows.tolist(), self._turn_lists(rows)):
                turns[k] = t
            cols[OPPONENT_TURNS] = turns
        return InfoColumns(rows, cols)

    def outcome(self, k: int) -> tuple[float, bool, bool]:
        """Table ``k``'s reward, termination and truncation of its last step."""
        return float(self.reward[k]), bool(self.tout[k]["terminated"]), bool(self.tout[k]["truncated"])


class InfoColumns:
    """The infos of some tables (``rows``, ascending) as one array per key, in the info's key order: ``cols[key][k]``
    is table ``k``'s value (the arrays span every table; other rows are blank), of the schema's dtype and shape
    (``opponent_turns``, with ``opponent_infos``: an object array of lists)."""

    __slots__ = ("rows", "cols")

    def __init__(self, rows: np.ndarray, cols: dict[str, np.ndarray]) -> None:
        self.rows = rows
        self.cols = cols

    def dicts(self) -> list[dict[str, Any]]:
        """Table ``rows[i]``'s info as the single env returns it (numpy scalars, 0-d arrays for flags, arrays), for
        each ``i``."""
        keys = list(self.cols)
        rows = self.rows
        values = [unstack(arr[rows]) for arr in self.cols.values()]
        return [dict(zip(keys, vals)) for vals in zip(*values)]


def stack_columns(n: int, parts: list[tuple[int, Any]]) -> dict[str, Any]:
    """The vector info of ``n`` sub-envs from :class:`InfoColumns` of disjoint tables, as Gymnasium's
    ``VectorEnv._add_info`` stacks the tables' info dicts in its order: ``parts`` ``(position, columns)``, the
    position of the part's first info among those ``_add_info`` takes (for the key order), ``columns`` an
    :class:`InfoColumns` or a dict of keys already stacked (``key: (array, mask)``, e.g. ``final_obs``); each key's
    array of its columns' dtype and shape, a ``_key`` mask of the tables that have it, blanks (0, False, None)
    elsewhere."""
    order: list[str] = []
    seen: set[str] = set()
    for _, part in sorted(parts, key=lambda p: p[0]):
        for key in (part.cols if isinstance(part, InfoColumns) else part):
            if key not in seen:
                seen.add(key)
                order.append(key)
    out: dict[str, Any] = {}
    for key in order:
        ready = [p[key] for _, p in parts if not isinstance(p, InfoColumns) and key in p]
        if ready:
            out[key], out[f"_{key}"] = ready[0]
            continue
        have = [p for _, p in parts if isinstance(p, InfoColumns) and key in p.cols and p.rows.size]
        if not have:
            continue
        mask = np.zeros(n, np.bool_)
        array = None
        for p in have:
            v = p.cols[key]
            if array is None:
                array = np.full(n, None, dtype=object) if v.dtype == object else np.zeros(v.shape, dtype=v.dtype)
            array[p.rows] = v[p.rows]
            mask[p.rows] = True
        out[key], out[f"_{key}"] = array, mask
    return out


def stack_infos(n: int, entries: list[tuple[int, dict[str, Any]]]) -> dict[str, Any]:
    """The vector info of ``n`` sub-envs from their info dicts, ``entries`` ``(sub-env, info)`` in the order
    Gymnasium's ``VectorEnv._add_info`` would take them (``final_obs`` and nested dicts included): the same arrays,
    dtypes (each key's from its first value), masks and key order, built a key at a time."""
    first: dict[str, Any] = {}
    for _, info in entries:
        for key, value in info.items():
            if key not in first:
                first[key] = value
    out: dict[str, Any] = {}
    for key, value in first.items():
        rows = [(k, info[key]) for k, info in entries if key in info]
        if key == "final_obs":
            array: Any = np.full(n, None, dtype=object)
            for k, v in rows:
                array[k] = v
        elif isinstance(value, dict):
            array = stack_infos(n, rows)
        else:
            if type(value) in (int, float, bool) or issubclass(type(value), np.number):
                array = np.zeros(n, dtype=type(value))
            elif isinstance(value, np.ndarray):
                array = np.zeros((n, *value.shape), dtype=value.dtype)
            else:
                array = np.full(n, None, dtype=object)
            for k, v in rows:
                array[k] = v
        mask = np.zeros(n, dtype=np.bool_)
        for k, _ in rows:
            mask[k] = True
        out[key], out[f"_{key}"] = array, mask
    return out


class _TableGame:
    """What the observation types read of a table's game (``state.game``): its features."""

    def __init__(self, tables: GameTables, k: int) -> None:
        self.tables = tables
        self.k = k

    def features(self, player: int | None = None) -> np.ndarray:
        if player is not None:
            raise ValueError("the native vector env observes each table as its shooter sees it (player=None)")
        out = np.zeros(self.tables.n_game, np.float32)
        st = self.tables.gst[self.k]
        pool_features(st, st["shooter"], out)
        return out


__all__ = ["GameTables", "InfoColumns", "native_games", "stack_columns", "stack_infos"]
