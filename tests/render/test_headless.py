"""Headless runs in a fresh process, with the environment variables a user's machine or CI job has.

Gymnasium's env checker on every registered id with ``SDL_VIDEODRIVER=dummy`` and no project variable: the
checker renders every declared mode, ``human`` included, and a driver the user chose means "draw invisibly".
``billiards-play`` where the X server does not answer: one line, no stray SDL message."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

SCRIPT = """
import os
assert "BILLIARDS_ALLOW_HEADLESS" not in os.environ
import gymnasium as gym
from gymnasium.utils.env_checker import check_env
import billiards_env
from billiards_env.registration import ENV_IDS

for env_id in ENV_IDS:
    env = gym.make(env_id)  # the checker also makes one env per declared render mode and renders it
    check_env(env.unwrapped)
    env.close()
env = gym.make("BilliardsOneBall-v0", render_mode="human")  # steps in human mode: every shot drawn, unseen
check_env(env.unwrapped)
env.close()
print("checked", len(ENV_IDS))
"""


def _env(**extra: str) -> dict[str, str]:
    drop = ("BILLIARDS_ALLOW_HEADLESS", "DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER", "XDG_RUNTIME_DIR")
    env = {k: v for k, v in os.environ.items() if k not in drop}
    env.update(SDL_AUDIODRIVER="dummy", PYTHONPATH=str(ROOT), **extra)
    return env


def test_check_env_passes_headless_on_every_id_without_a_project_variable():
    proc = subprocess.run([sys.executable, "-c", SCRIPT], cwd=ROOT, env=_env(SDL_VIDEODRIVER="dummy"),
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    from billiards_env.registration import ENV_IDS

    assert proc.stdout.strip().splitlines()[-1] == f"checked {len(ENV_IDS)}"


def test_play_without_an_answering_x_server_prints_one_line():
    """DISPLAY set but nothing there (and no XDG_RUNTIME_DIR, as over ssh or in a container): SDL's probe of
    Wayland used to print "error: XDG_RUNTIME_DIR is invalid or not set" before the project's own message."""
    proc = subprocess.run([sys.executable, "-m", "billiards_env.play", "--width", "200"], cwd=ROOT,
                          env=_env(DISPLAY=":97"), capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2
    assert proc.stdout == ""
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and "XDG_RUNTIME_DIR" not in proc.stderr, proc.stderr
    assert lines[0].startswith("billiards-play: error: ") and "no X server answered at DISPLAY=:97" in lines[0]
