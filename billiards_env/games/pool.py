"""9-ball and 8-ball: their :class:`~.logic.GameLogic` (the rules themselves are :mod:`billiards_env.rules`).

Both are pool games on a pool table: the cue ball in hand behind the head string (the kitchen) or anywhere, the
same eleven game features, the rack ordered as the rules say (9-ball: the 1 at the apex, the 9 in the middle;
8-ball: the 8 in the middle of the third row, a solid and a stripe in the back corners).
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from billiards_env.physics.layout import head_string_x
from billiards_env.physics.table import Table
from billiards_env.rules import (EIGHT_BALL, KITCHEN, SOLIDS, STRIPES, EightBall, EightBallOptions, GameState,
                                 NineBall, NineBallOptions, Ruleset)

from .logic import Area, GameLogic

#: The game features every pool game observes (see :func:`pool_features`).
N_POOL_FEATURES = 11


def pool_place_area(state: GameState, table: Table, radius: float) -> Area | None:
    """Where the shooter may place the cue ball: behind the head string (kitchen) or anywhere on the table."""
    bih = state.ball_in_hand
    if not bih or state.game_over:
        return None
    x1 = head_string_x(table) if bih == KITCHEN else table.length - radius
    return radius, x1, radius, table.width - radius


def pool_features(rules: Ruleset, s: GameState, me: int) -> np.ndarray:
    """The game seen by player ``me``: ball in hand (anywhere / kitchen), break shot, its lowest legal target / 15,
    its group (solids, stripes), on the 8, its own and its opponent's fouls in a row / 2, push-out available, and
    whether it is its turn (eleven values in [0, 1])."""
    out = np.zeros(N_POOL_FEATURES, np.float32)
    mine = s.shooter == me and not s.game_over
    out[0] = 1.0 if (mine and s.ball_in_hand) else 0.0
    out[1] = 1.0 if (mine and s.ball_in_hand == KITCHEN) else 0.0
    out[2] = 1.0 if s.break_shot else 0.0
    # The viewer's own targets (8-ball: its group) also when it is not its turn (the two-player env).
    targets = rules.legal_targets(s if me == s.shooter else replace(s, shooter=me)) if not s.game_over else ()
    out[3] = targets[0] / 15.0 if targets else 0.0
    if s.groups is not None:
        out[4] = 1.0 if s.groups[me] == SOLIDS else 0.0
        out[5] = 1.0 if s.groups[me] == STRIPES else 0.0
    out[6] = 1.0 if (s.game == EIGHT_BALL and targets == (8,)) else 0.0
    out[7] = min(s.fouls_in_a_row[me] / 2.0, 1.0)
    out[8] = min(s.fouls_in_a_row[1 - me] / 2.0, 1.0)
    out[9] = 1.0 if s.push_out_available else 0.0
    out[10] = 1.0 if mine else 0.0
    return out


def _order(fixed: dict[int, int], free: list[int], n_slots: int, rng: np.random.Generator) -> tuple[int, ...]:
    free = [free[k] for k in rng.permutation(len(free))]
    it = iter(free)
    return tuple(fixed[slot] if slot in fixed else next(it) for slot in range(n_slots))


def nine_ball_rack(n_slots: int, rng: np.random.Generator) -> tuple[int, ...]:
    """The diamond's numbers slot by slot: the 1 at the apex, the 9 in the middle, the others drawn."""
    return _order({0: 1, 4: 9}, list(range(2, 9)), n_slots, rng)


def eight_ball_rack(n_slots: int, rng: np.random.Generator) -> tuple[int, ...]:
    """The triangle's numbers slot by slot: the 8 in the middle of the third row, a solid and a stripe in the back
    corners (which corner drawn), the others drawn."""
    corner_solid = int(rng.integers(2))
    solid = int(rng.choice(np.arange(1, 8)))
    stripe = int(rng.choice(np.arange(9, 16)))
    fixed = {4: 8, 10: solid if corner_solid else stripe, 14: stripe if corner_solid else solid}
    return _order(fixed, [n for n in range(1, 16) if n not in fixed.values()], n_slots, rng)


NINE_BALL_LOGIC = GameLogic(
    ruleset=NineBall, options_type=NineBallOptions, env_option_defaults={"push_out": False},
    declarations=lambda rules: ("push",) if rules.options.push_out else (),
    place_area=pool_place_area, features=pool_features, n_features=N_POOL_FEATURES,
    hud_targets=lambda state, targets: targets[:1],
    order_rack=nine_ball_rack, opening_respot=9)

EIGHT_BALL_LOGIC = GameLogic(
    ruleset=EightBall, options_type=EightBallOptions,
    declarations=lambda rules: ("pocket",) if rules.options.call_eight else (),
    place_area=pool_place_area, features=pool_features, n_features=N_POOL_FEATURES,
    hud_targets=lambda state, targets: targets if targets == (8,) else (),
    order_rack=eight_ball_rack, opening_respot=8)

__all__ = ["NINE_BALL_LOGIC", "EIGHT_BALL_LOGIC", "N_POOL_FEATURES", "pool_features", "pool_place_area", "nine_ball_rack",
           "eight_ball_rack"]
