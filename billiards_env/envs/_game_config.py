"""The packed configuration of a compiled game env (9-ball, 8-ball in the native vector env) as numpy records: the
floats ``cfg`` (:data:`GAME_FLOATS`) and the ints ``icfg`` (:data:`GAME_INTS`) of a table, and a table's kick cache
(:data:`KICK_CACHE`). The compiled twins read the fields by name (``cfg["speed_lo"]``, numba's records), in
:mod:`._action_kernels`, :mod:`.candidates` and :mod:`._game_kernels`; :class:`billiards_env.envs._vector_games.GameTables`
packs them.
"""
from __future__ import annotations

from typing import Any

import numpy as np

#: The ``candidates`` action type (``icfg["aim"]``).
AIM_CANDIDATES = 4

#: The floats of a game env: the action type's speed and tip scales, the noise, the ghost-ball limits, the table's
#: size and spots, the speed range, the rewards, the ease's spread, the observation's scales, the pockets' margin, the
#: least distance between placed balls, the break's speed, the largest cut, the candidates' speed ranges and the cue's
#: squirt.
GAME_FLOATS = np.dtype([(name, np.float64) for name in (
    "speed_lo", "speed_span", "max_tip", "angle_noise", "speed_noise", "tip_noise", "ghost", "act_ghost", "radius",
    "length", "width", "kitchen_x", "head_x", "head_y", "foot_x", "foot_y", "speed_min", "speed_max", "win", "loss",
    "foul_penalty", "pot_reward", "position_reward", "ease_sigma", "sx", "sy", "pocket_margin", "min_dist",
    "break_speed", "max_cut", "cand_lo", "cand_hi", "log_factor", "obs_lo", "obs_hi", "squirt", "cue_end_mass")])
#: The ints of a game env: how the agent's and the acting type aim, the spin dimensions and model, the action's size
#: and the places of its placement and declarations, the opponent, who breaks, the opening, the caps, the rack, the
#: observation made by the kernels, the noise mode, the candidate slots, the events' cap, the respot at the opening,
#: the game.
GAME_INTS = np.dtype([(name, np.int64) for name in (
    "aim", "act_aim", "spin_dims", "spin_model", "n_act", "place_at", "pocket_at", "push_at", "n_pockets", "opponent",
    "first", "opening", "max_shots", "turn_cap", "rack", "positions_obs", "speed_noise_abs", "slots", "max_events",
    "opening_respot", "max_reracks", "game", "candidates_obs")])
#: A table's kick cache (the candidates types): valid, a kick found, its target, angle, speed, path length, and the
#: speed range it was worked out for.
KICK_CACHE = np.dtype([(name, np.float64) for name in (
    "valid", "found", "target", "angle", "speed", "length", "lo", "hi")])



def put_shot_fields(cfg: Any, a: Any, c: Any) -> None:
    """The fields every compiled config shares (:data:`GAME_FLOATS`, the pot task's ``POT_FLOATS``) into the record
    ``cfg``: the action type ``a``'s power and tip ranges and the config ``c``'s shot noise."""
    cfg["speed_lo"] = a.speed_lo
    cfg["speed_span"] = a.speed_span
    cfg["max_tip"] = a.max_tip
    cfg["angle_noise"] = c.angle_noise
    cfg["speed_noise"] = c.speed_noise
    cfg["tip_noise"] = c.tip_noise


__all__ = ["AIM_CANDIDATES", "GAME_FLOATS", "GAME_INTS", "KICK_CACHE", "put_shot_fields"]
