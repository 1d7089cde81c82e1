"""Named shot noise: ``noise="olympiad"`` is FastFiz's level-1 noise (aim 0.125 deg, speed 0.075 m/s absolute,
tip offsets 0.5 mm), measured on the shots the env plays; explicit keys override a preset."""
from __future__ import annotations

import math

import numpy as np
import pytest
from env_helpers import gym


def _played(env_id: str, n: int, **kw) -> np.ndarray:
    env = gym.make(env_id, **kw)
    out = []
    env.reset(seed=0)
    a = np.zeros(env.action_space.shape, np.float32)  # the same shot every time: angle 0, mid power
    for k in range(n):
        *_, term, trunc, info = env.step(a)
        out.append((info["angle"], info["speed"], info.get("side", 0.0), info.get("top", 0.0)))
        env.reset(seed=k + 1)
    return np.array(out)


def test_olympiad_noise_has_fastfiz_level_one_spreads():
    shots = _played("BilliardsOneBall-v0", 3000, noise="olympiad", friction="spin", spin_action=True)
    nominal_speed = 0.5 + 0.5 * (5.0 - 0.5)
    assert np.std(shots[:, 0]) == pytest.approx(math.radians(0.125), rel=0.06)
    assert np.std(shots[:, 1]) == pytest.approx(0.075, rel=0.06)  # m/s, whatever the speed
    assert np.mean(shots[:, 1]) == pytest.approx(nominal_speed, abs=0.01)
    tip_mm = np.std(shots[:, 2:], axis=0) * 28.575
    assert tip_mm == pytest.approx([0.5, 0.5], rel=0.06)


def test_the_speed_noise_is_absolute_at_any_speed():
    slow = _played("BilliardsOneBall-v0", 2000, noise="olympiad", speed_min=0.5, speed_max=1.5)
    assert np.std(slow[:, 1]) == pytest.approx(0.075, rel=0.07)
    relative = _played("BilliardsOneBall-v0", 2000, speed_noise=0.075, speed_min=0.5, speed_max=1.5)
    assert np.std(relative[:, 1]) == pytest.approx(0.075 * 1.0, rel=0.07)  # relative to the 1.0 m/s shot


def test_explicit_keys_override_a_named_noise_and_no_tip_noise_without_spin():
    c = gym.make("Billiards9Ball-v0", noise="olympiad", angle_noise=0.01).unwrapped.config
    assert c.angle_noise == 0.01 and c.speed_noise == 0.075 and c.speed_noise_mode == "absolute"
    assert c.tip_noise == 0.0
    with pytest.raises(ValueError, match="noise: unknown value 'olimpiad'"):
        gym.make("BilliardsOneBall-v0", noise="olimpiad")


def test_vector_env_plays_absolute_speed_noise_as_the_single_env():
    kw = {"noise": "olympiad", "friction": "spin", "spin_action": True}
    vec = gym.make_vec("BilliardsThreeBalls-v0", 3, **kw)
    singles = [gym.make("BilliardsThreeBalls-v0", **kw) for _ in range(3)]
    obs, _ = vec.reset(seed=5)
    for k, e in enumerate(singles):
        assert np.array_equal(e.reset(seed=5 + k)[0], obs[k])
    rng = np.random.default_rng(1)
    for _ in range(6):
        a = rng.uniform(-1, 1, vec.action_space.shape).astype(np.float32)
        o, r, t, tr, info = vec.step(a)
        for k, e in enumerate(singles):
            ok, rk, tk, trk, ik = e.step(a[k])
            assert np.array_equal(ok, o[k]) and rk == r[k] and ik["speed"] == info["speed"][k]
            if tk or trk:
                e.reset()
        if (t | tr).any():
            break
