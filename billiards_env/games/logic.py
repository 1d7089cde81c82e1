"""What a game does besides its rules: :class:`GameLogic` (one per registered game, see :mod:`.registry`)."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from billiards_env.physics.table import Table
from billiards_env.rules.ruleset import Ruleset

#: ``(x0, x1, y0, y1)``: where the cue ball may be placed.
Area = tuple[float, float, float, float]


@dataclass(frozen=True)
class GameLogic:
    """A game's parts above its ruleset:

    ``ruleset`` and ``options_type`` (its options dataclass), ``env_option_defaults`` (the env's defaults, under the
    user's ``rules``); ``declarations(rules)``: what the shooter declares besides the shot, as action dims
    (``"pocket"``: the pocket called for the 8; ``"push"``: a push-out); ``place_area(state, table, radius)``: where
    the shooter may put the cue ball (None: it plays from where it lies); ``features(rules, state, player)``:
    ``n_features`` values in [0, 1], the game seen by ``player`` (what an agent observes besides the balls);
    ``hud_targets(state, targets)``: the balls the HUD rings; ``order_rack(n_slots, rng)``: the ball number of
    each rack slot, drawn as the rules say (None: the config's layout stands); ``opening_respot``: the ball put back
    after the ``ball_in_hand`` opening's break if it dropped (the game's last ball)."""

    ruleset: type[Ruleset]
    options_type: type
    declarations: Callable[[Ruleset], tuple[str, ...]]
    place_area: Callable[[Any, Table, float], Area | None]
    features: Callable[[Ruleset, Any, int], np.ndarray]
    n_features: int
    hud_targets: Callable[[Any, tuple[int, ...]], tuple[int, ...]]
    order_rack: Callable[[int, np.random.Generator], tuple[int, ...]] | None = None
    opening_respot: int | None = None
    env_option_defaults: dict[str, Any] = field(default_factory=dict)

    def options(self, overrides: Any = None) -> Any:
        """The ruleset's options: the env's defaults, then ``overrides`` (a mapping; the options class refuses an
        unknown key with the allowed ones)."""
        return self.options_type(**{**self.env_option_defaults, **dict(overrides or {})})

    def make_rules(self, overrides: Any = None) -> Ruleset:
        """The ruleset with the env's defaults and ``overrides``."""
        return self.ruleset(self.options(overrides))


__all__ = ["GameLogic", "Area"]
