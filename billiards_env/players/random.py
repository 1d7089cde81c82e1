"""The random player: uniformly random actions from the action space (seeded)."""
from __future__ import annotations

from typing import Any

import numpy as np

from .context import player_inputs


class RandomPlayer:
    """Uniformly random actions (seeded)."""

    name = "random"
    #: :meth:`act` does not read the observation (the env need not observe for it).
    reads_observation = False

    def __init__(self, seed: int | None = 0):
        self.rng = np.random.default_rng(seed)

    def reset(self, seed: int | None = None) -> None:
        if seed is not None:
            self.rng = np.random.default_rng(seed)

    def act(self, source: Any, obs: Any = None, codec: Any = None) -> np.ndarray:
        """A uniform action of ``codec``'s space (an action type; default the env's)."""
        _, codec = player_inputs(source, codec)
        space = codec.space
        return self.rng.uniform(space.low, space.high).astype(space.dtype)



__all__ = ["RandomPlayer"]
