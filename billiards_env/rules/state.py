"""The data a ruleset reads and returns: :class:`GameState` (between shots), :class:`ShotInfo` (what the shooter
declares before a shot) and :class:`Call` (the referee's call on a shot). All frozen: pure data in, data out."""
from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any, Callable, Final, Literal, Union

from .errors import RulesError

NINE_BALL = "nine_ball"
EIGHT_BALL = "eight_ball"
#: The games a :class:`GameState` may hold: name -> its ruleset class. Not a list kept by hand: every
#: :class:`~.ruleset.Ruleset` subclass that names its ``game`` adds itself (:func:`register_rules`), so 10-ball is its
#: ruleset module and nothing else here.
GAMES: dict[str, type] = {}
#: Each game's legal-target function (the balls the shooter may hit first), by name (filled with :data:`GAMES`).
TARGETS: dict[str, Callable[["GameState"], tuple[int, ...]]] = {}


def register_rules(game: str, ruleset: type, targets: Callable[["GameState"], tuple[int, ...]]) -> None:
    """Add ``game`` (its ruleset class and legal-target function) to :data:`GAMES` and :data:`TARGETS`; a name taken
    by another ruleset is an error."""
    if not isinstance(game, str) or not game:
        raise RulesError(f"register_rules: game must be a non-empty name, got {game!r}")
    known: Any = GAMES.get(game)
    if known is not None and known.__qualname__ != ruleset.__qualname__:
        raise RulesError(f"register_rules: game {game!r} is played by {known.__name__} already")
    GAMES[game] = ruleset
    TARGETS[game] = targets

#: Ball in hand for the next shooter: ``False`` (play the cue ball where it lies), ``"anywhere"`` on the table,
#: or ``"kitchen"`` (behind the head string). The env places the cue ball; the rules only say where it may go.
ANYWHERE: Final = "anywhere"
KITCHEN: Final = "kitchen"
BallInHand = Union[Literal[False], Literal["anywhere"], Literal["kitchen"]]
BALL_IN_HAND = (False, ANYWHERE, KITCHEN)

SOLIDS = "solids"  #: balls 1-7
STRIPES = "stripes"  #: balls 9-15
GROUPS = (SOLIDS, STRIPES)

# Reasons (``Call.reason``): one short string per outcome.
LEGAL = "legal"
PUSH_OUT = "push-out"
# Fouls, in the order ``Call.fouls`` lists them (the first is the call's reason).
SCRATCH = "scratch"  #: cue ball pocketed
NO_CONTACT = "no contact"  #: the cue ball touched no ball
WRONG_BALL_FIRST = "wrong ball first"  #: the first ball touched was not a legal target
NO_RAIL = "no rail"  #: after the first contact no ball was pocketed and no ball touched a cushion
ILLEGAL_BREAK = "illegal break"  #: a break that pocketed nothing and drove too few object balls to a cushion
FOULS = (SCRATCH, NO_CONTACT, WRONG_BALL_FIRST, NO_RAIL, ILLEGAL_BREAK)
# Game-ending outcomes.
NINE_POCKETED = "9 pocketed"  #: 9-ball won: the 9 on a legal shot (the break included)
EIGHT_POCKETED = "8 pocketed"  #: 8-ball won: the 8 legally, in the called pocket when calls are on
EIGHT_ON_BREAK = "8 on the break"  #: 8-ball won on the break (option ``eight_on_break="win"``)
EIGHT_EARLY = "8 pocketed early"  #: 8-ball lost: the 8 down before the shooter's group was cleared
EIGHT_ON_FOUL = "8 pocketed on a foul"  #: 8-ball lost: the 8 down on a shot that fouled (a scratch included)
EIGHT_WRONG_POCKET = "8 in an uncalled pocket"  #: 8-ball lost: the 8 down in another pocket than the call
EIGHT_NOT_CALLED = "8 not called"  #: 8-ball lost: the 8 down while calls are on but no pocket was called
THREE_FOULS = "three fouls"  #: lost on a third foul in a row (option ``three_foul_rule``)


def _check_player(name: str, value: object) -> None:
    if isinstance(value, bool) or value not in (0, 1):
        raise RulesError(f"{name}: must be player 0 or 1, got {value!r}")


def _check_ball_in_hand(name: str, value: object) -> None:
    if not any(value is v or (isinstance(value, str) and value == v) for v in BALL_IN_HAND):
        raise RulesError(f"{name}: must be False, 'anywhere' or 'kitchen', got {value!r}")


@dataclass(frozen=True, slots=True)
class GameState:
    """Where a game stands before a shot.

    ``shooter``: the player to shoot (0 or 1). ``ball_in_hand``: where that player may place the cue ball
    (False: where it lies). ``on_table``: object-ball numbers on the table, ascending (the cue ball is not
    listed). ``groups`` (8-ball): None while the table is open, else the group of player 0 and of player 1.
    ``fouls_in_a_row``: each player's consecutive fouls. ``break_shot``: the next shot is the opening break.
    ``push_out_available`` (9-ball): the next shot may be declared a push-out (the shot right after the break).
    ``push_out_pending`` (9-ball): the last shot was a legal push-out, so the shooter may play or hand the shot
    back (:meth:`NineBall.pass_back`). ``game_over`` / ``winner``: the game has ended and who won.
    ``shot_number``: shots played so far.
    """

    game: str
    on_table: tuple[int, ...]
    shooter: int = 0
    ball_in_hand: BallInHand = KITCHEN
    groups: tuple[str, str] | None = None
    fouls_in_a_row: tuple[int, int] = (0, 0)
    break_shot: bool = True
    push_out_available: bool = False
    push_out_pending: bool = False
    game_over: bool = False
    winner: int | None = None
    shot_number: int = 0

    def __post_init__(self) -> None:
        if self.game not in GAMES:
            raise RulesError(f"GameState.game: unknown game {self.game!r}; use one of {', '.join(GAMES)}")
        _check_player("GameState.shooter", self.shooter)
        _check_ball_in_hand("GameState.ball_in_hand", self.ball_in_hand)
        balls = tuple(sorted(int(n) for n in self.on_table))
        if len(set(balls)) != len(balls) or any(not 1 <= n <= 15 for n in balls):
            raise RulesError(f"GameState.on_table: {self.on_table!r} must list distinct object-ball numbers 1..15")
        object.__setattr__(self, "on_table", balls)
        if self.groups is not None:
            if tuple(sorted(self.groups)) != (SOLIDS, STRIPES):
                raise RulesError(f"GameState.groups: {self.groups!r}; use None (open table), ('solids', 'stripes') "
                                 "or ('stripes', 'solids')")
            if self.game != EIGHT_BALL:
                raise RulesError("GameState.groups: only 8-ball has groups; leave it None")
            object.__setattr__(self, "groups", tuple(self.groups))
        fouls = tuple(self.fouls_in_a_row)
        if len(fouls) != 2 or any(isinstance(f, bool) or not isinstance(f, int) or f < 0 for f in fouls):
            raise RulesError(f"GameState.fouls_in_a_row: {self.fouls_in_a_row!r}; give two counts >= 0")
        object.__setattr__(self, "fouls_in_a_row", fouls)
        if self.winner is not None:
            _check_player("GameState.winner", self.winner)
        if self.winner is not None and not self.game_over:
            raise RulesError("GameState.winner: set only when game_over is True")

    @property
    def opponent(self) -> int:
        """The player who is not shooting."""
        return 1 - self.shooter

    @classmethod
    def trusted(cls, game: str, on_table: tuple[int, ...], shooter: int, ball_in_hand: BallInHand,
                 groups: tuple[str, str] | None, fouls_in_a_row: tuple[int, int], break_shot: bool,
                 push_out_available: bool, push_out_pending: bool, game_over: bool, winner: int | None,
                 shot_number: int) -> "GameState":
        """A state from fields a ruleset derived from a checked state and its own call (skips the checks of
        ``__post_init__``, which cost more than the rest of a call; ``on_table`` must be sorted). For the rulesets
        and the compiled rules only: anything else builds a ``GameState`` (checked)."""
        obj = object.__new__(cls)
        for name, value in zip(_STATE_FIELDS, (game, on_table, shooter, ball_in_hand, groups, fouls_in_a_row,
                                               break_shot, push_out_available, push_out_pending, game_over, winner,
                                               shot_number)):
            object.__setattr__(obj, name, value)
        return obj


_STATE_FIELDS = tuple(f.name for f in fields(GameState))


@dataclass(frozen=True, slots=True)
class ShotInfo:
    """What the shooter declares before a shot (not its outcome, unlike pooltool's ``ShotInfo``).

    ``push_out`` (9-ball): this shot is a push-out; only allowed when ``GameState.push_out_available``.
    ``called_pocket`` (8-ball): the pocket called for the 8 (index into the table's pockets), needed when the
    shooter is on the 8 and the option ``call_eight`` is on.
    """

    push_out: bool = False
    called_pocket: int | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.push_out, bool):
            raise RulesError(f"ShotInfo.push_out: must be True or False, got {self.push_out!r}")
        cp = self.called_pocket
        if cp is not None and (isinstance(cp, bool) or not isinstance(cp, int) or cp < 0):
            raise RulesError(f"ShotInfo.called_pocket: must be None or a pocket index >= 0, got {cp!r}")


@dataclass(frozen=True, slots=True)
class Call:
    """The call on one shot.

    ``legal``: the shot broke no rule. ``foul``: a foul was committed (``fouls`` lists each, in the order of
    :data:`FOULS`). ``reason``: one short string: :data:`LEGAL`, :data:`PUSH_OUT`, the first foul, or what ended
    the game. ``shooter``: who shot. ``turn_over``: the other player shoots next. ``next_shooter`` and
    ``ball_in_hand``: who shoots next and where they may place the cue ball. ``pocketed``: object balls pocketed on
    this shot; all stay down except those in ``respot``, which the env puts back on the table.
    ``cue_pocketed``: the cue ball went in (the next shooter then has it in hand). ``game_over`` / ``winner``.
    ``groups``: 8-ball groups after the shot (None: open table). ``push_out``: the shot was a declared push-out.
    When ``game_over`` is True no shot follows and ``ball_in_hand`` is False.
    """

    legal: bool
    foul: bool
    reason: str
    fouls: tuple[str, ...]
    shooter: int
    turn_over: bool
    next_shooter: int
    ball_in_hand: BallInHand
    pocketed: tuple[int, ...] = ()
    respot: tuple[int, ...] = ()
    cue_pocketed: bool = False
    game_over: bool = False
    winner: int | None = None
    groups: tuple[str, str] | None = None
    push_out: bool = False


__all__ = [
    "NINE_BALL", "EIGHT_BALL", "GAMES", "TARGETS", "register_rules", "ANYWHERE", "KITCHEN", "BallInHand", "SOLIDS", "STRIPES", "GROUPS",
    "LEGAL", "PUSH_OUT", "SCRATCH", "NO_CONTACT", "WRONG_BALL_FIRST", "NO_RAIL", "ILLEGAL_BREAK", "FOULS",
    "NINE_POCKETED", "EIGHT_POCKETED", "EIGHT_ON_BREAK", "EIGHT_EARLY", "EIGHT_ON_FOUL", "EIGHT_WRONG_POCKET",
    "EIGHT_NOT_CALLED", "THREE_FOULS", "GameState", "ShotInfo", "Call",
]
