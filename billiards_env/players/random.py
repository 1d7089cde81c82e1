"""The random player: uniformly random actions from the action space (seeded)."""
from __future__ import annotations

from typing import Any

import numpy as np

from billiards_env.table_state import TableState

from .context import BasePlayer


class RandomPlayer(BasePlayer):
    """Uniformly random actions (seeded)."""

    name = "random"
    #: It does not read the observation (the env need not observe for it).
    reads_observation = False

    def __init__(self, seed: int | None = 0):
        self.rng = np.random.default_rng(seed)

    def reset(self, seed: int | None = None) -> None:
        if seed is not None:
            self.rng = np.random.default_rng(seed)

    def choose(self, state: TableState, obs: Any, codec: Any) -> np.ndarray:
        """A uniform action of ``codec``'s space (an action type)."""
        space = codec.space
        return self.rng.uniform(space.low, space.high).astype(space.dtype)


__all__ = ["RandomPlayer"]
