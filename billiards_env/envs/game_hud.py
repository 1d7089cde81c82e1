"""What a game shows on screen: the plain data of its HUD (:meth:`GameTask.hud`, drawn by
:mod:`billiards_env.render.hud`) and the score kept for it. No drawing here: names, numbers and words."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from billiards_env.physics.layout import head_string_x
from billiards_env.rules import EIGHT_BALL, KITCHEN, NINE_BALL
from billiards_env.rules.state import Call

if TYPE_CHECKING:  # pragma: no cover
    from .base import BilliardsEnv
    from .games import GameTask

GAME_TITLES = {NINE_BALL: "9-ball", EIGHT_BALL: "8-ball"}


class Score:
    """Games won by each player over the env's life, and the object balls each player pocketed in the current
    game (balls that stay down: a respotted ball does not count)."""

    def __init__(self) -> None:
        self.wins = [0, 0]
        self.pocketed: tuple[list[int], list[int]] = ([], [])

    def new_game(self) -> None:
        self.pocketed = ([], [])

    def record(self, call: Call) -> None:
        """Count a judged shot: the balls it pocketed for its shooter, the game for its winner."""
        self.pocketed[call.shooter].extend(n for n in call.pocketed if n not in call.respot)
        if call.game_over and call.winner is not None:
            self.wins[call.winner] += 1


def player_names(task: "GameTask") -> tuple[str, str]:
    """The two players' names: ``task.player_names`` if set; else ``"agent"`` and the opponent policy's ``name``
    (its class name without one; ``"nobody"`` when the agent plays alone), or ``"player 0"``/``"player 1"`` when
    nobody plays automatically (two players)."""
    names = getattr(task, "player_names", None)
    if names:
        return str(names[0]), str(names[1])
    if not task.auto_opponent:
        return "player 0", "player 1"
    opp = task.opponent
    if opp is None:
        return "agent", "nobody"
    return "agent", str(getattr(opp, "name", None) or type(opp).__name__)


def call_text(call: Call, names: tuple[str, str]) -> str:
    """The referee's call in words: ``"FOUL: scratch (geometric)"``, ``"9 pocketed: agent wins"``,
    ``"agent: pocketed 3, 5"``, ``"agent: no ball pocketed"``, ``"geometric: push-out"``."""
    who = names[call.shooter]
    if call.game_over:
        return f"{call.reason}: {names[call.winner] if call.winner is not None else 'nobody'} wins"
    if call.foul:
        return f"FOUL: {call.reason} ({who})"
    if call.push_out:
        return f"{who}: push-out"
    kept = [n for n in call.pocketed if n not in call.respot]
    return f"{who}: pocketed {', '.join(map(str, kept))}" if kept else f"{who}: no ball pocketed"


def game_hud(task: "GameTask", env: "BilliardsEnv") -> dict[str, Any]:
    """The HUD of a game now (keys: :mod:`billiards_env.render.hud`). The ringed target: 9-ball the lowest ball,
    8-ball the 8 once it is the target (a group's seven rings would hide the table). While a shot is under way
    (the frames of its animation) the cue ball is no longer in hand and the called pocket is ringed."""
    s = task.state
    names = player_names(task)
    over = s.game_over
    targets = () if over else tuple(task.rules.legal_targets(s))
    ring = targets[:1] if s.game == NINE_BALL else (targets if targets == (8,) else ())
    shot = task._shot  # a shot under way (between before_shot and its call): the cue ball is no longer in hand
    in_hand = False if (over or shot is not None) else s.ball_in_hand
    calling = bool(not over and task.needs_called_pocket())
    call = task.last_call
    score = task.score
    return {
        "game": GAME_TITLES.get(s.game, s.game),
        "players": names,
        "shooter": None if over else s.shooter,
        "groups": s.groups,
        "ball_in_hand": in_hand,
        "kitchen_x": head_string_x(env.table) if in_hand == KITCHEN else None,
        "call": call_text(call, names) if call is not None else None,
        "foul": bool(call is not None and call.foul),
        "winner": s.winner,
        "wins": (score.wins[0], score.wins[1]),
        "pocketed": (tuple(score.pocketed[0]), tuple(score.pocketed[1])),
        "targets": ring,
        "call_pocket": calling and shot is None,
        "called_pocket": shot.pocket if (calling and shot is not None) else None,
    }


__all__ = ["Score", "player_names", "call_text", "game_hud", "GAME_TITLES"]
