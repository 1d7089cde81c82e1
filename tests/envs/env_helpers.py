"""Shared bits of the env tests: ids, fast rendering settings, constructed scenes."""
from __future__ import annotations

import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
os.environ.setdefault("BILLIARDS_ALLOW_HEADLESS", "1")  # render_mode="human" into an invisible window

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402

import billiards_env  # noqa: E402,F401  (registers the ids)
from billiards_env.registration import ENV_IDS  # noqa: E402

IDS = list(ENV_IDS)
#: The pot-the-balls scenes (one ball, three balls, rack) and the games.
POT_IDS = ["BilliardsOneBall-v0", "BilliardsThreeBalls-v0", "BilliardsRack-v0"]
GAME_IDS = [i for i in IDS if i not in POT_IDS]
RENDER_MODES = ["human", "rgb_array", "rgb_array_list"]
#: Small frames and few of them: rendering tests stay fast (a 20 s shot becomes a handful of frames).
FAST_RENDER = {"render_width": 160, "render_fps": 1000, "render_speedup": 5000.0}

L, W = 2.54, 1.27


def make(env_id: str = "BilliardsOneBall-v0", **kwargs):
    return gym.make(env_id, **kwargs)


def corner_pot_scene() -> tuple[np.ndarray, float, float]:
    """Cue ball and ball 1 on the diagonal to the top-right corner pocket: a straight shot pots ball 1.

    Returns positions (2, 2), the shot angle (rad) and a speed (m/s)."""
    pos = np.array([[L - 0.8, W - 0.8], [L - 0.35, W - 0.35]])
    return pos, np.pi / 4, 2.0


def scratch_scene() -> tuple[np.ndarray, float, float]:
    """Cue ball near the bottom-left corner aimed straight into it; ball 1 far away."""
    pos = np.array([[0.35, 0.35], [1.8, 0.9]])
    return pos, -3 * np.pi / 4, 1.5
