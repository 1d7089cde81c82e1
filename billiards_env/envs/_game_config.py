"""The packed configuration of a compiled game env (9-ball, 8-ball in the native vector env): the columns of its float
row ``cfg`` (``K_*``) and int row ``icfg`` (``J_*``), and of a table's kick cache (``KC_*``). One place for the
compiled twins that read them (:mod:`._action_kernels`, :mod:`.candidates`, :mod:`._game_kernels`) and the code that
packs them (:func:`billiards_env.envs._vector_games.GameTables`).
"""
from __future__ import annotations

#: The ``candidates`` action type (``J_AIM``).
AIM_CANDIDATES = 4
# Floats of a game env (``cfg``) and ints (``icfg``): see :func:`billiards_env.envs._vector_games.pack_game`.
K_SPEED_LO, K_SPEED_SPAN, K_MAX_TIP, K_ANGLE_NOISE, K_SPEED_NOISE, K_TIP_NOISE, K_GHOST, K_ACT_GHOST, K_RADIUS, \
    K_LENGTH, K_WIDTH, K_KITCHEN_X, K_HEAD_X, K_HEAD_Y, K_FOOT_X, K_FOOT_Y, K_SPEED_MIN, K_SPEED_MAX, K_WIN, \
    K_LOSS, K_FOUL_PENALTY, K_POT_REWARD, K_POSITION_REWARD, K_EASE_SIGMA, K_SX, K_SY, K_POCKET_MARGIN, \
    K_MIN_DIST, K_BREAK_SPEED, K_MAX_CUT, K_CAND_LO, K_CAND_HI, K_LOG_FACTOR, K_OBS_LO, K_OBS_HI, K_SQUIRT, \
    K_CUE_END_MASS = range(37)
N_K = 37
J_AIM, J_ACT_AIM, J_SPIN_DIMS, J_SPIN_MODEL, J_N_ACT, J_PLACE_AT, J_POCKET_AT, J_PUSH_AT, J_N_POCKETS, J_OPPONENT, \
    J_FIRST, J_OPENING, J_MAX_SHOTS, J_TURN_CAP, J_RACK, J_POSITIONS_OBS, J_SPEED_NOISE_ABS, J_SLOTS, J_MAX_EVENTS, \
    J_OPENING_RESPOT, J_MAX_RERACKS, J_GAME, J_CANDIDATES_OBS = range(23)
N_J = 23
#: The kick cache of a table (``kc`` rows): valid, a kick found, its target, angle, speed, path length, and the speed
#: range it was worked out for.
KC_VALID, KC_FOUND, KC_TARGET, KC_ANGLE, KC_SPEED, KC_LENGTH, KC_LO, KC_HI = range(8)
N_KC = 8


__all__ = ["AIM_CANDIDATES", "N_K", "N_J", "N_KC"]
