"""What an evaluation or a league needs of a player: :class:`PlayerSpec` (a label, how to make its env, how it
acts). Shared by :mod:`agents.evaluate` (SB3 models, baselines) and :mod:`agents.rllib.player` (RLlib checkpoints),
so neither imports the other."""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

import numpy as np


@dataclass
class PlayerSpec:
    """A player ready to run: a label, a factory for its env and an ``(env, obs) -> action`` function."""

    label: str
    kind: str  #: "baseline" or "model"
    make_env: Callable[..., Any]
    act: Callable[[Any, Any], np.ndarray]
    reset: Callable[[int], None] = lambda seed: None
    run_dir: Path | None = None
    model_path: Path | None = None
    env_id: str | None = None
    env_kwargs: dict[str, Any] = field(default_factory=dict)


def env_factory(env_id: str, env_kwargs: dict[str, Any], wrapper: Any = None) -> Callable[..., Any]:
    """A function making ``gym.make(env_id, **env_kwargs)`` (with ``render_mode`` and extra kwargs), wrapped in
    ``wrapper`` if given: how a player's env is made again wherever it plays."""

    def make(render_mode: str | None = None, **extra: Any) -> Any:
        import gymnasium as gym

        import billiards_env  # noqa: F401

        kw = {**env_kwargs, **extra}
        env = gym.make(env_id, render_mode=render_mode, **kw) if render_mode else gym.make(env_id, **kw)
        return wrapper(env) if wrapper is not None else env

    return make


__all__ = ["PlayerSpec", "env_factory"]
