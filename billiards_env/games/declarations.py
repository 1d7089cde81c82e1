"""What a shooter declares besides the shot (a called pocket, a called ball, a push-out), as data a game declares.

A game's session names its declarations (:meth:`GameSession.declared <billiards_env.games.session.GameSession>`),
each a :class:`Declaration`: its name (the action dim's and the key in :attr:`CueShot.calls
<billiards_env.shot_path.CueShot>`), what it chooses among (``"pocket"``: a pocket of the table; ``"ball"``: an
object ball, by its row; ``"flag"``: yes or no) and how an action value in [-1, 1] maps to it and back. The action
types, the env's ``action_from_shot`` and the players read only this: a game with a new declaration adds a
:class:`Declaration`, not a branch in the env. No Gymnasium.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

#: The kinds of declaration: a pocket index, an object ball's row, or yes / no.
KINDS = ("pocket", "ball", "flag")


@dataclass(frozen=True)
class Declaration:
    """One declaration: ``name`` (the action dim and the :class:`~billiards_env.shot_path.CueShot` call key),
    ``kind`` (one of :data:`KINDS`) and ``doc`` (what it means, for the action's manual).

    ``pocket``: ``k = floor((a + 1) / 2 * n_pockets)``; ``ball``: row ``1 + floor((a + 1) / 2 * (n_balls - 1))``
    (the object balls); ``flag``: ``a > 0``. The value of a choice not made is None (a flag's False)."""

    name: str
    kind: str
    doc: str = ""

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"Declaration {self.name!r}: kind {self.kind!r}; use one of {', '.join(KINDS)}")

    @property
    def default(self) -> Any:
        """The value when nothing is declared: None (a choice), False (a flag)."""
        return False if self.kind == "flag" else None

    def n_choices(self, n_pockets: int, n_balls: int) -> int:
        """How many values a choice has on a table of ``n_pockets`` pockets and ``n_balls`` rows (flag: 2)."""
        if self.kind == "pocket":
            return n_pockets
        if self.kind == "ball":
            return max(n_balls - 1, 1)
        return 2

    def decode(self, a: float, n_pockets: int, n_balls: int) -> Any:
        """The value of action value ``a`` (in [-1, 1])."""
        if self.kind == "flag":
            return a > 0.0
        n = self.n_choices(n_pockets, n_balls)
        k = min(int(0.5 * (a + 1.0) * n), n - 1)
        return k if self.kind == "pocket" else k + 1

    def encode(self, value: Any, n_pockets: int, n_balls: int) -> float:
        """The action value of ``value`` (the middle of its interval; a choice not made: the first one)."""
        if self.kind == "flag":
            return 1.0 if value else -1.0
        n = self.n_choices(n_pockets, n_balls)
        first = 0 if self.kind == "pocket" else 1
        k = 0 if value is None else min(max(int(value) - first, 0), n - 1)
        return (2.0 * k + 1.0) / n - 1.0

    def check(self, value: Any, n_pockets: int, n_balls: int) -> None:
        """Raise ``ValueError`` naming the valid values if ``value`` cannot be declared (None: nothing declared)."""
        if self.kind == "flag":
            if not isinstance(value, bool):
                raise ValueError(f"{self.name}: must be True or False, got {value!r}")
            return
        if value is None:
            return
        n = self.n_choices(n_pockets, n_balls)
        lo = 0 if self.kind == "pocket" else 1
        what = "a pocket index" if self.kind == "pocket" else "an object ball's row"
        if isinstance(value, bool) or not hasattr(value, "__index__") or not lo <= int(value) < lo + n:
            raise ValueError(f"{self.name}: must be {what} {lo}..{lo + n - 1}, got {value!r}")


#: The pocket called for a shot (8-ball: the 8's pocket; straight pool: the called ball's pocket).
CALLED_POCKET = Declaration("pocket", "pocket", "the pocket called (the table's pocket order)")
#: The ball called for a shot (straight pool), by its row.
CALLED_BALL = Declaration("ball", "ball", "the object ball called (its row)")
#: A 9-ball push-out.
PUSH_OUT = Declaration("push", "flag", "> 0 declares a push-out")


def calls_of(declarations: tuple[Declaration, ...], given: dict[str, Any]) -> tuple[tuple[str, Any], ...]:
    """The ``(name, value)`` pairs of ``given`` that ``declarations`` declare, in their order (a value not given:
    the declaration's default); what a :class:`~billiards_env.shot_path.CueShot` carries."""
    return tuple((d.name, given.get(d.name, d.default)) for d in declarations)


__all__ = ["Declaration", "KINDS", "CALLED_POCKET", "CALLED_BALL", "PUSH_OUT", "calls_of"]
