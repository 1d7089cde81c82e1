"""Record an episode as an animated GIF (every shot animated, balls moving).

    from billiards_env.envs.recording import record_episode_gif
    record_episode_gif("BilliardsOneBall-v0", policy=None, path="runs/episode.gif", seed=0, fps=30)

``policy`` is a callable ``obs -> action``, an SB3-style model (``predict(obs, deterministic=True)``) or None
for random actions (drawn from the action space seeded with ``seed``).
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import gymnasium as gym
import numpy as np

from .base import make_policy


def record_episode_gif(env_id_or_env: str | gym.Env, policy: Any, path: str | os.PathLike[str], seed: int | None = 0,
                       fps: int = 30, max_shots: int | None = None, **env_kwargs: Any) -> dict[str, Any]:
    """Play one episode with ``policy`` and write it to ``path`` as an animated GIF at ``fps``.

    ``env_id_or_env``: a registered id (the env is made with ``render_mode="rgb_array_list"``,
    ``render_fps=fps`` and ``env_kwargs``, e.g. ``render_width=400, render_speedup=2.0``, and closed after) or
    an env made with ``render_mode="rgb_array_list"`` (left open). ``max_shots`` stops early (e.g. to keep a
    rack episode short). Returns ``{"path", "frames", "shots", "return", "is_success"}``.
    """
    own = isinstance(env_id_or_env, str)
    if own:
        import billiards_env  # noqa: F401  (registers the ids)

        env = gym.make(env_id_or_env, render_mode="rgb_array_list", render_fps=fps, **env_kwargs)
    else:
        env = env_id_or_env
        if env_kwargs:
            raise ValueError(f"record_episode_gif: env_kwargs {sorted(env_kwargs)} only apply when an env id is "
                             "given; configure the env when you make it")
        if env.render_mode != "rgb_array_list":
            raise ValueError(f"record_episode_gif: the env must be made with render_mode='rgb_array_list' (got "
                             f"{env.render_mode!r}) so that every shot is animated")
    from billiards_env.render import write_gif

    try:
        act = make_policy(policy, env)
        if policy is None and seed is not None:
            env.action_space.seed(seed)
        obs, _ = env.reset(seed=seed)
        frames: list[np.ndarray] = list(env.render())
        shots, total, success = 0, 0.0, False
        done = False
        while not done:
            obs, reward, terminated, truncated, info = env.step(act(obs))
            frames.extend(env.render())
            shots += 1
            total += float(reward)
            success = bool(info.get("is_success", False))
            done = terminated or truncated or (max_shots is not None and shots >= max_shots)
        out = write_gif(frames, path, fps=fps)
    finally:
        if own:
            env.close()
    return {"path": Path(out), "frames": len(frames), "shots": shots, "return": total, "is_success": success}


__all__ = ["record_episode_gif"]
