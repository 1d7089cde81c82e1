"""Record episodes as one animated GIF (every shot animated, the balls moving): small and quick by default.

    from billiards_env.envs.recording import record_gif
    record_gif("BilliardsThreeBalls-v0", None, "episode.gif", seeds=0)          # a random-policy episode
    record_gif("BilliardsOneBall-v0", model, "runs/episodes.gif", seeds=range(5))  # five episodes, one GIF

``policy`` is a callable ``obs -> action``, an SB3-style model (``predict(obs, deterministic=True)``) or None
for random actions (the action space seeded with each episode's seed). The defaults keep a GIF short and light
(:data:`GIF_RENDER`: 400 px wide, 20 fps, shots played 4x faster than real time; at most
``max_frames_per_shot`` = 40 frames per shot, longer shots sampled down; the last table of each episode held for
``hold_frames`` = 20 frames). Rolling friction is low (``mu_roll = 0.01``), so a shot lasts 10-20 s: at real
time and 800 px a random three-ball episode is 4,000+ frames and 5 MB. ``agents.evaluate`` writes its
``episodes.gif`` with :func:`record_gif`.
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Callable, Iterable

import gymnasium as gym
import numpy as np

from .base import make_policy

#: Render settings of a recording env (``gym.make`` keys): small frames, 20 fps, 4x faster than real time.
GIF_RENDER: dict[str, Any] = {"render_width": 400, "render_fps": 20, "render_speedup": 4.0}
#: Frames kept per shot (2 s at 20 fps); a longer shot is sampled down evenly, first and last frames kept.
MAX_FRAMES_PER_SHOT = 40
#: Copies of each episode's last frame (1 s at 20 fps), so the outcome can be seen before the GIF moves on.
HOLD_FRAMES = 20


def record_gif(env: str | gym.Env, policy: Any, path: str | os.PathLike[str],
               seeds: int | Iterable[int] | None = 0, *, width: int | None = None, fps: int | None = None,
               speedup: float | None = None, max_frames_per_shot: int | None = MAX_FRAMES_PER_SHOT,
               hold_frames: int = HOLD_FRAMES, max_shots: int | None = None,
               reset_policy: Callable[[int | None], None] | None = None, **env_kwargs: Any) -> dict[str, Any]:
    """Play one episode per seed with ``policy`` and write them all to ``path`` as one looping GIF.

    ``env``: a registered id (made with ``render_mode="rgb_array_list"``, :data:`GIF_RENDER` overridden by
    ``width``, ``fps``, ``speedup``, plus ``env_kwargs``; closed after) or an env made with
    ``render_mode="rgb_array_list"`` (left open; its own render settings apply and the GIF plays at its
    ``render_fps``). ``seeds``: an int (one episode), several (one GIF, one after the other) or None (one
    unseeded episode). ``max_frames_per_shot`` (None: no cap) caps each shot's frames; ``hold_frames`` repeats
    each episode's final table; ``max_shots`` ends an episode early; ``reset_policy(seed)`` is called before
    each episode (players with state).

    Returns ``{"path", "frames", "fps", "seconds" (of animation), "episodes" (the seeds), "shots", "returns",
    "successes"}``, the last three per episode.
    """
    if max_frames_per_shot is not None and max_frames_per_shot < 2:
        raise ValueError(f"record_gif: max_frames_per_shot must be >= 2 (or None for no cap), got "
                         f"{max_frames_per_shot}")
    if hold_frames < 0:
        raise ValueError(f"record_gif: hold_frames must be >= 0, got {hold_frames}")
    own = isinstance(env, str)
    if own:
        import billiards_env  # noqa: F401  (registers the ids)

        settings = {**GIF_RENDER, **{k: v for k, v in (("render_width", width), ("render_fps", fps),
                                                       ("render_speedup", speedup)) if v is not None}}
        env = gym.make(env, render_mode="rgb_array_list", **settings, **env_kwargs)
    else:
        given = sorted(env_kwargs) + [k for k, v in (("width", width), ("fps", fps), ("speedup", speedup))
                                      if v is not None]
        if given:
            raise ValueError(f"record_gif: {given} only apply when an env id is given; set render_width, "
                             "render_fps, render_speedup and other keys when you make the env")
        if env.render_mode != "rgb_array_list":
            raise ValueError(f"record_gif: the env must be made with render_mode='rgb_array_list' (got "
                             f"{env.render_mode!r}) so that every shot is animated")
    episodes = [seeds] if seeds is None or isinstance(seeds, (int, np.integer)) else list(seeds)
    if not episodes:
        raise ValueError("record_gif: seeds is empty; give a seed, several seeds, or None")
    from billiards_env.render import write_gif

    rate = int(env.unwrapped.config.render_fps)
    frames: list[np.ndarray] = []
    shots: list[int] = []
    returns: list[float] = []
    successes: list[bool] = []
    try:
        act = make_policy(policy, env)
        for seed in episodes:
            if reset_policy is not None:
                reset_policy(seed)
            if policy is None and seed is not None:
                env.action_space.seed(int(seed))
            obs, _ = env.reset(seed=None if seed is None else int(seed))
            frames.extend(env.render())
            n, total, success, done = 0, 0.0, False, False
            while not done:
                obs, reward, terminated, truncated, info = env.step(act(obs))
                frames.extend(_cap(env.render(), max_frames_per_shot))
                n += 1
                total += float(reward)
                success = bool(info.get("is_success", False))
                done = terminated or truncated or (max_shots is not None and n >= max_shots)
            frames.extend([frames[-1]] * hold_frames)
            shots.append(n)
            returns.append(total)
            successes.append(success)
        out = write_gif(frames, path, fps=rate)
    finally:
        if own:
            env.close()
    return {"path": Path(out), "frames": len(frames), "fps": rate, "seconds": len(frames) / rate,
            "episodes": episodes, "shots": shots, "returns": returns, "successes": successes}


def _cap(frames: list[np.ndarray], limit: int | None) -> list[np.ndarray]:
    """At most ``limit`` of ``frames``, evenly spread, the first and the last kept."""
    if limit is None or len(frames) <= limit:
        return frames
    keep = np.unique(np.linspace(0, len(frames) - 1, limit).round().astype(int))
    return [frames[k] for k in keep]


__all__ = ["record_gif", "GIF_RENDER", "MAX_FRAMES_PER_SHOT", "HOLD_FRAMES"]
