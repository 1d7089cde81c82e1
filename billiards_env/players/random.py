"""The random player: uniformly random actions from the env's action space (seeded)."""
from __future__ import annotations

from typing import Any

import numpy as np


class RandomPlayer:
    """Uniformly random actions (seeded)."""

    name = "random"

    def __init__(self, seed: int | None = 0):
        self.rng = np.random.default_rng(seed)

    def reset(self, seed: int | None = None) -> None:
        if seed is not None:
            self.rng = np.random.default_rng(seed)

    def act(self, env: Any, obs: Any) -> np.ndarray:
        space = env.action_space
        return self.rng.uniform(space.low, space.high).astype(space.dtype)



__all__ = ["RandomPlayer"]
