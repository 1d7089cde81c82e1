"""One game in progress on a table state: :class:`GameSession`, the base of every game's session class.

A session holds the rules' state, judges each shot's :class:`~billiards_env.physics.outcome.ShotOutcome` with the
ruleset, applies the call to the table (respotted balls, the cue ball in hand, a table put back...), keeps the
score, and tells the table state who is to shoot and what they may do (its
:class:`~billiards_env.table_state.ShotView`). It is the game for every driver: the single-agent env's task, the
two-player env and the players all read it through ``table_state.game``. A game is one subclass (9-ball and 8-ball:
:mod:`.pool`; snooker: :mod:`.snooker`; three-cushion: :mod:`.carom`) named by its registry entry. No Gymnasium.

Every call is summed up in a :class:`Verdict` (who shot, foul, why, turn over, game over, the winner, what the
shot scored), so the layers above treat every game alike; the call itself stays available for its own fields.
"""
from __future__ import annotations

import contextlib
from abc import ABC, abstractmethod
from dataclasses import fields
from typing import Any, ClassVar, Iterator, Mapping, NamedTuple

import numpy as np

from billiards_env.physics.outcome import ShotOutcome
from billiards_env.rules.errors import RulesError, check_keywords
from billiards_env.table_state import ShotView, TableState

from .declarations import Declaration
from .hud import Score
from .infos import InfoSpec, mask_of
from .registry import GameSpec


def pair_option(options: Mapping[str, Any], key: str, default: tuple[int, int] = (0, 0)) -> tuple[int, int]:
    """Reset option ``key`` (e.g. ``score``) as two whole numbers >= 0, or a ValueError saying what to give."""
    value = options.get(key, default)
    try:
        pair = tuple(value) if not isinstance(value, (str, bytes)) else ()
    except TypeError:
        pair = ()
    if len(pair) != 2 or not all(isinstance(x, (int, np.integer)) and not isinstance(x, (bool, np.bool_)) and x >= 0
                                 for x in pair):
        raise ValueError(f"reset options[{key!r}]: expected two whole numbers >= 0 (player 0's, player 1's), "
                         f"got {value!r}")
    return int(pair[0]), int(pair[1])


def flag_option(options: Mapping[str, Any], key: str, default: bool = False) -> bool:
    """Reset option ``key`` (e.g. ``break_shot``) as True or False, or a ValueError saying what to give."""
    value = options.get(key, default)
    if not isinstance(value, (bool, np.bool_)):
        raise ValueError(f"reset options[{key!r}]: expected True or False, got {value!r}")
    return bool(value)


class Verdict(NamedTuple):
    """A call in the terms every game shares. ``scored``: what the shot earned its shooter (balls kept down in
    pool, points in snooker and three-cushion): what the ``pot_reward`` shaping pays. ``call``: the ruleset's own
    call (its game-specific fields)."""

    shooter: int
    foul: bool
    reason: str
    turn_over: bool
    game_over: bool
    winner: int | None
    scored: float
    call: Any


class GameSession(ABC):
    """A game on ``table`` under the rules options ``rules`` (layered over the game's env defaults). Whoever runs it
    attaches it to the table (:meth:`TableState.attach_game <billiards_env.table_state.TableState.attach_game>`:
    ``table.game`` and the source of ``table.view``; the env's task does).

    ``state`` is the rules' state; ``last_call`` the call on the last shot; ``verdict`` its :class:`Verdict`;
    ``score`` the games won and the balls each player pocketed; ``shot_under_way`` the shot being played (between
    :meth:`begin_shot` and :meth:`judge`)."""

    #: The ruleset class and its options class; the env's defaults of the options (under the user's ``rules``).
    ruleset: ClassVar[type]
    options_type: ClassVar[type]
    env_option_defaults: ClassVar[dict[str, Any]] = {}
    #: Game features appended to every observation (values in [0, 1]).
    n_features: ClassVar[int] = 0
    #: Reset options a table set up by hand reads besides ``positions`` and ``pocketed``.
    option_keys: ClassVar[tuple[str, ...]] = ()
    #: Whether a shooter can get the cue ball in hand (the action then has the placement dims).
    ball_in_hand: ClassVar[bool] = True
    #: The env's ``opening`` values this game plays (``"break"`` always).
    openings: ClassVar[tuple[str, ...]] = ("break",)
    #: The config's ``placement`` values this game adds to the generic ones (``random``, ``rack``, ``diamond``): its
    #: own opening layouts, each placed by :meth:`start_layout` (snooker: ``"snooker"``; three-cushion: ``"carom"``).
    placements: ClassVar[tuple[str, ...]] = ()
    #: The built-in players by name: ``module:Class`` of each (a class taking ``seed``, with ``act(state, obs,
    #: codec)``); the env's ``opponent`` names one.
    players: ClassVar[dict[str, str]] = {}
    #: The colours of the game's plain balls by drawing number (above 15: the renderer draws 0-15 as the pool set),
    #: handed to the renderer as plain data (snooker's reds and colours, the carom set).
    palette: ClassVar[dict[int, tuple[int, int, int]]] = {}
    #: What :attr:`Verdict.scored` counts, in words (the league's "per inning" column): ``"balls"``, ``"points"``.
    scored_unit: ClassVar[str] = "balls"
    #: Every reason a call may give (``Verdict.reason``): the info's ``call`` and ``foul_reason`` are codes into it.
    reasons: ClassVar[tuple[str, ...]] = ()

    def __init__(self, spec: GameSpec, rules: Any, table: TableState) -> None:
        self.spec = spec
        self.rules = self.make_rules(rules)
        #: What the shooter declares besides the shot (action dims): :class:`~.declarations.Declaration` objects.
        self.declarations: tuple[Declaration, ...] = self.declared(self.rules)
        self.table = table
        self.game_state: Any = self.rules.initial_state()
        self.last_call: Any = None
        self.verdict: Verdict | None = None
        self.score = Score()
        self.shot_under_way: Any = None
        self._viewer: int | None = None

    # --- configuration -------------------------------------------------------------------------------------------
    @classmethod
    def options(cls, overrides: Any = None) -> Any:
        """The ruleset's options: the env's defaults, then ``overrides`` (a mapping; the options class refuses an
        unknown key with the allowed ones, the same for every game:
        :func:`~billiards_env.rules.errors.check_keywords`)."""
        if overrides is not None and not isinstance(overrides, Mapping):
            raise RulesError(f"rules must be a mapping of option names to values, got {type(overrides).__name__} "
                             f"{overrides!r}; e.g. {{'{fields(cls.options_type)[0].name}': ...}}")
        given = dict(overrides or {})
        check_keywords(cls.options_type, given)
        return cls.options_type(**{**cls.env_option_defaults, **given})

    @classmethod
    def make_rules(cls, overrides: Any = None) -> Any:
        return cls.ruleset(cls.options(overrides))

    @classmethod
    def declared(cls, rules: Any) -> tuple[Declaration, ...]:
        """The declarations of the action under ``rules``, one dim each (none by default)."""
        return ()

    @classmethod
    def start_layout(cls, placement: str, table: Any, radius: float) -> np.ndarray:
        """The positions ``(n_balls, 2)`` of every row in the game's own layout ``placement`` (one of
        :attr:`placements`) on ``table`` with balls of ``radius``: the env places them at every reset."""
        raise ValueError(f"placement {placement!r}: {cls.__name__} has no layouts of its own")

    @classmethod
    def ball_set(cls, n_object_balls: int) -> tuple[tuple[str, ...], tuple[int, ...]]:
        """The balls' ids and drawing numbers, row by row (row 0 the cue ball): ``"cue", "1" .. "n"`` and 0..n."""
        n = n_object_balls + 1
        return ("cue",) + tuple(str(k) for k in range(1, n)), tuple(range(n))

    # --- the game's state --------------------------------------------------------------------------------------------
    def set_state(self, state: Any) -> None:
        """Continue from ``state`` (a new game, a table set up by hand)."""
        self.game_state = state
        self.table.changed()

    @property
    def shooter(self) -> int:
        return int(self.game_state.shooter)

    @property
    def game_over(self) -> bool:
        return bool(self.game_state.game_over)

    @property
    def winner(self) -> int | None:
        return self.game_state.winner

    @abstractmethod
    def new_game(self, rng: np.random.Generator, placement: str) -> None:
        """Set up a new game's table from the layout the env placed (a rack ordered as the rules say, drawing from
        ``rng``); :meth:`start` then names the breaker."""

    @abstractmethod
    def start(self, first: int) -> None:
        """The game's first shot, by player ``first`` (the rules' initial state)."""

    @abstractmethod
    def setup(self, options: dict[str, Any], shooter: int) -> None:
        """A table set up by hand (reset options with ``positions``): the game's state from the balls on the table
        and the game's own option keys; bad values raise ``ValueError`` naming the key."""

    # --- what the shooter sees and may do ----------------------------------------------------------------------------
    @abstractmethod
    def view(self, table: TableState) -> ShotView:
        """Who is to shoot and what they may do (the table state's ``view``)."""

    @abstractmethod
    def features(self, player: int | None = None) -> np.ndarray:
        """The game features seen by ``player`` (default: the player of :meth:`seen_by`, else the shooter)."""

    def viewer(self, player: int | None) -> int:
        """Whose point of view the features take: ``player``, else the one of :meth:`seen_by`, else the shooter."""
        if player is not None:
            return player
        return self.shooter if self._viewer is None else self._viewer

    @contextlib.contextmanager
    def seen_by(self, player: int) -> Iterator[None]:
        """Within the block :meth:`features` takes ``player``'s point of view instead of the shooter's."""
        if player not in (0, 1):
            raise ValueError(f"player: must be 0 or 1, got {player!r}")
        saved, self._viewer = self._viewer, player
        try:
            yield
        finally:
            self._viewer = saved

    def legal_names(self) -> tuple[Any, ...]:
        """The balls the shooter may hit first, as the rules name them (the HUD's, the players')."""
        return () if self.game_over else tuple(self.rules.legal_targets(self.game_state))

    def legal_rows(self) -> list[int]:
        """Rows of the balls the shooter may hit first."""
        return list(self.view(self.table).targets)

    def legal_mask(self) -> np.ndarray:
        """The balls the shooter may hit first as a boolean array over the rows (``info["legal_targets"]``; all
        False once the game is over)."""
        return mask_of(() if self.game_over else self.legal_rows(), self.table.n_balls)

    # --- declarations ------------------------------------------------------------------------------------------------
    def needs_calls(self) -> bool:
        """Whether the next shot's declarations are read (a called pocket, a called ball...): players then say
        what their shot does with :meth:`calls_for`. None by default."""
        return False

    def calls_for(self, pocket: np.ndarray) -> dict[str, Any]:
        """The declarations (by :class:`~.declarations.Declaration` name) a shooter makes for a shot that sends each
        row into pocket ``pocket[row]`` (-1: stays on the table): what a player that simulated its shot calls.
        None by default."""
        return {}

    # --- shots -------------------------------------------------------------------------------------------------------
    def begin_shot(self, shot: Any) -> None:
        """A shot is under way (its declarations are read when it is judged; the HUD shows it)."""
        self.shot_under_way = shot

    def judge(self, outcome: ShotOutcome, shot: Any = None) -> Verdict:
        """Call the shot just played (``shot``: its :class:`~billiards_env.shot_path.CueShot`, for the
        declarations; default the one under way), apply the call to the table and the state, keep the score."""
        shot = self.shot_under_way if shot is None else shot
        call, state = self._call(outcome, shot)
        self.game_state = state
        self._apply(call, outcome)
        verdict = self._verdict(call)
        self.last_call = call
        self.verdict = verdict
        self.score.record(verdict, self._kept(call))
        self.shot_under_way = None
        self.table.changed()
        return verdict

    @abstractmethod
    def _call(self, outcome: ShotOutcome, shot: Any) -> tuple[Any, Any]:
        """The rules' call on the shot and the state after it."""

    @abstractmethod
    def _apply(self, call: Any, outcome: ShotOutcome) -> None:
        """Apply the call to the table (respots, the cue ball...)."""

    @abstractmethod
    def _verdict(self, call: Any) -> Verdict:
        """The call as a :class:`Verdict`."""

    def _kept(self, call: Any) -> tuple[Any, ...]:
        """The balls the shot pocketed for its shooter that stay down (the HUD's score)."""
        return ()

    @classmethod
    def info_keys(cls, n_balls: int) -> dict[str, InfoSpec]:
        """The form of :meth:`call_info`'s keys (in its order) on a table of ``n_balls`` rows."""
        return {}

    def call_info(self, verdict: Verdict | None) -> dict[str, Any]:
        """The game's own keys of a step's ``info`` after ``verdict`` (None: after a reset): what the state is
        now and what the call said, in the forms of :meth:`info_keys`."""
        return {}

    def markings(self) -> dict[str, Any] | None:
        """Lines the table carries for this game, as plain data in metres (``lines``, ``arcs``: see
        :class:`billiards_env.render.TableRenderer`); None: none."""
        return None

    @abstractmethod
    def hud(self, names: tuple[str, str]) -> dict[str, Any]:
        """The HUD of the game now (keys: :mod:`billiards_env.render.hud`)."""


__all__ = ["GameSession", "Verdict"]
