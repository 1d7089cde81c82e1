"""The ``info`` of every env id, in one place: :func:`info_schema` (key -> :class:`~billiards_env.games.infos.InfoSpec`:
dtype, shape, meaning), which the env, its compiled pot step, the native vector env and the docs' table all read, and
:func:`shot_info`, the builder of the shot's keys.

The same keys come at reset and at every step, each of one type, dtype and shape, so that RL libraries can stack infos
step by step (Tianshou), write them to HDF5 (Minari), average them (PufferLib) or read them into tensors (TorchRL):
every value with a dtype (numbers ``np.int64``/``np.float64`` scalars, flags 0-d boolean arrays, the rest numpy
arrays: :func:`billiards_env.games.infos.single`); balls as boolean masks over the ball rows (``pocketed``,
``legal_targets``) or a row index (``first_contact``, -1 none); categories as integer codes (``status``, ``call``,
``foul_reason``, ``ball_in_hand``, ``groups``, ``on``: ``info_schema(config)[key].names[code]`` is the name, -1 none).
The opponent's shots one by one (a list of dicts, one per shot, in the same forms) come only with the config key
``opponent_infos=True`` (``info["opponent_turns"]``), outside the schema; by default the step sums them up
(``opponent_shots``, ``opponent_pocketed``, ``opponent_fouls``). See ``docs/infos.md``.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from billiards_env.games import GAMES
from billiards_env.games.infos import InfoSpec, blank_value, code, flag, integer, real, row_mask
from billiards_env.physics.codes import STATUS_NAMES

if TYPE_CHECKING:  # pragma: no cover
    from .config import EnvConfig

#: The key of the opponent's shots one by one (with ``opponent_infos=True``; not in the schema).
OPPONENT_TURNS = "opponent_turns"


def shot_keys(n_balls: int) -> dict[str, InfoSpec]:
    """The keys of the agent's shot, last in every info (blank at reset: no shot yet)."""
    return {
        "pocketed": row_mask("the balls this shot pocketed (rows as the shot saw them; row 0 the cue ball)", n_balls),
        "scratch": flag("the cue ball was pocketed"),
        "first_contact": integer("row of the first ball the cue ball hit (-1: none, or no shot yet)", -1),
        "n_events": integer("events the simulation of the shot took"),
        "sim_time": real("simulated seconds until every ball was at rest"),
        "status": code("how the simulation ended: 0 rest, 1 time_cap, 2 event_cap (-1: no shot yet)",
                       STATUS_NAMES),
        "shots": integer("the agent's shots in this episode"),
        "angle": real("the shot's angle as played (rad, noise included)"),
        "speed": real("the shot's speed as played (m/s, noise included)"),
        "side": real("the side tip offset as played (fraction of R; 0 without spin)"),
        "top": real("the top tip offset as played (fraction of R; 0 without spin)"),
    }


def game_keys(game: str, n_balls: int) -> dict[str, InfoSpec]:
    """The keys of a game's call and state (before the shot's keys): the ones every game shares, then the game's
    own (its session's ``info_keys``)."""
    session = GAMES[game].session_class
    reasons = session.reasons
    names = ", ".join(f"{k} {r}" for k, r in enumerate(reasons))
    return {
        "foul": flag("the agent's shot was a foul"),
        "foul_reason": code(f"why (a reason code, -1 no foul): {names}", reasons),
        "call": code("the referee's reason for the agent's shot (-1 at reset), a code as foul_reason", reasons),
        "turn_over": flag("the agent's shot passed the turn"),
        "winner": integer("0 the agent, 1 the opponent, -1 while the game goes on", -1),
        "shooter": integer("who shoots next (0 the agent)"),
        "legal_targets": row_mask("the balls the shooter may hit first (all False once the game is over)", n_balls),
        "opponent_shots": integer("shots of the opponent's reply in this step (at reset: its break)"),
        "opponent_pocketed": row_mask("the balls the opponent's reply pocketed", n_balls),
        "opponent_fouls": integer("fouls in the opponent's reply"),
        **session.info_keys(n_balls),
    }


def info_schema(config: "EnvConfig") -> dict[str, InfoSpec]:
    """Every key of the info of an env made with ``config``, in order, with its form: the same at reset and at
    every step (``opponent_turns`` aside, with ``opponent_infos=True``)."""
    n = config.n_object_balls + 1
    game = config.task in GAMES
    out = {"is_success": flag("the agent won the game" if game else
                              "the table cleared without a scratch on the last shot")}
    if game:
        out.update(game_keys(config.task, n))
    out.update(shot_keys(n))
    return out


def blank_info(schema: dict[str, InfoSpec], keys: Any = None) -> dict[str, Any]:
    """Fresh values saying nothing for ``keys`` (default all) of ``schema``, in the schema's order."""
    return {k: blank_value(spec) for k, spec in schema.items() if keys is None or k in keys}


def shot_info(pocketed: np.ndarray, scratch: bool, first_contact: int, n_events: int, sim_time: float,
              status: int, shots: int, played: Any) -> dict[str, Any]:
    """The shot keys of ``info`` (:func:`shot_keys`): ``pocketed`` (a mask over the rows), ``scratch``,
    ``first_contact`` (a row, -1 none), ``n_events``, ``sim_time``, ``status`` (a code), ``shots`` (of the episode),
    and the shot as played (``played``: ``angle``, ``speed``, ``side``, ``top``, noise included); single values in
    the schema's forms (:func:`~billiards_env.games.infos.single`)."""
    return {
        "pocketed": pocketed,
        "scratch": np.array(scratch, np.bool_),
        "first_contact": np.int64(first_contact),
        "n_events": np.int64(n_events),
        "sim_time": np.float64(sim_time),
        "status": np.int64(status),
        "shots": np.int64(shots),
        "angle": np.float64(played.angle),
        "speed": np.float64(played.speed),
        "side": np.float64(played.side),
        "top": np.float64(played.top),
    }


#: Keys whose value is a ball row (-1 none).
ROW_KEYS = ("first_contact",)


def info_words(info: dict[str, Any], schema: dict[str, InfoSpec], ids: tuple[str, ...]) -> dict[str, Any]:
    """``info`` in words, for people and logs: masks over the rows as tuples of the ball ids (``ids``, the rows'),
    rows as an id (None for -1), codes as their names (None for -1), other arrays as tuples; the entries of
    ``opponent_turns`` alike. The reverse of the schema's forms, losing nothing."""
    out: dict[str, Any] = {}
    for key, value in info.items():
        spec = schema.get(key)
        if key == OPPONENT_TURNS:
            out[key] = [info_words(t, schema, ids) for t in value]
        elif spec is None:
            out[key] = value
        elif spec.names:
            out[key] = spec.names[value] if value >= 0 else None
        elif key in ROW_KEYS:
            out[key] = ids[value] if value >= 0 else None
        elif spec.shape == (len(ids),) and spec.dtype is np.bool_:
            out[key] = tuple(ids[i] for i in np.flatnonzero(value))
        elif spec.shape:
            out[key] = tuple(np.asarray(value).tolist())
        else:
            out[key] = value
    return out


#: The keys :func:`shot_info` writes, in order.
SHOT_INFO_KEYS = tuple(shot_keys(1))

__all__ = ["info_schema", "shot_keys", "game_keys", "blank_info", "shot_info", "info_words", "SHOT_INFO_KEYS",
           "OPPONENT_TURNS", "ROW_KEYS"]
