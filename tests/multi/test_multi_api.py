"""The two-player envs (billiards_env.multi) against PettingZoo's API and seed tests, the single-agent env's spaces
and configs, determinism, rendering and bad input."""
from __future__ import annotations

import importlib

import os
import warnings

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

with warnings.catch_warnings():  # pettingzoo.test imports PettingZoo's own example envs through a deprecated path
    warnings.simplefilter("ignore", DeprecationWarning)
    from pettingzoo.test import api_test, seed_test

import billiards_env  # noqa: E402,F401
from billiards_env.envs.config import ConfigError  # noqa: E402
from billiards_env.games import GAMES as REGISTERED  # noqa: E402
from billiards_env.multi import AGENTS, eight_ball_v0, nine_ball_v0, snooker_v0, three_cushion_v0  # noqa: E402

#: Every registered game's two-player module and single-agent id (the game registry's list).
GAMES = [(importlib.import_module(f"billiards_env.multi.{g.aec_module}"), g.env_id) for g in REGISTERED.values()]
IDS = [g.name for g in REGISTERED.values()]


@pytest.mark.parametrize("module, config", [
    (nine_ball_v0, {}),
    (nine_ball_v0, {"rules": {"three_foul_rule": False}, "max_shots": 40, "friction": "spin", "spin_action": True,
                    "angle_noise": 0.01}),  # longer games (to the 9 or truncated), spin dims
    (eight_ball_v0, {}),
    (eight_ball_v0, {"rules": {"call_eight": False}, "observation_type": "features", "action_type": "relative"}),
    (snooker_v0, {"max_shots": 60}),
    (three_cushion_v0, {"rules": {"target_points": 3}}),
], ids=["nine_ball", "nine_ball_spin_long", "eight_ball", "eight_ball_features", "snooker", "three_cushion"])
def test_pettingzoo_api_test_passes(module, config):
    # api_test resets with options={"options": 1}: ignored with a warning naming the key.
    with pytest.warns(UserWarning, match=r"unknown key\(s\) \['options'\] ignored"):
        api_test(module.env(**config), num_cycles=200)


@pytest.mark.parametrize("module, _", GAMES, ids=IDS)
def test_pettingzoo_seed_test_passes(module, _):
    seed_test(lambda: module.env(angle_noise=0.01, speed_noise=0.02), num_cycles=100)


@pytest.mark.parametrize("module, env_id", GAMES, ids=IDS)
@pytest.mark.parametrize("config", [{}, {"friction": "spin", "spin_action": True, "angle_noise": 0.01},
                                    {"observation_type": "features", "action_type": "ghost"}])
def test_spaces_are_the_single_agent_envs(module, env_id, config):
    env = module.env(**config)
    single = gym.make(env_id, opponent=None, **config)
    for agent in AGENTS:
        assert env.action_space(agent) == single.action_space
        assert env.observation_space(agent) == single.observation_space
    assert env.action_space(AGENTS[0]) is not env.action_space(AGENTS[1])  # seeded apart
    if config.get("spin_action"):
        assert env.unwrapped.game_env.config.physics.friction == "spin"
        plain = gym.make(env_id, opponent=None).action_space.shape[0]  # a game registered later: two more dims
        expected = {nine_ball_v0: 6, eight_ball_v0: 7, snooker_v0: 6, three_cushion_v0: 4}.get(module, plain + 2)
        assert env.action_space(AGENTS[0]).shape[0] == single.action_space.shape[0] == expected


@pytest.mark.parametrize("module, env_id", GAMES, ids=IDS)
def test_player_0_sees_what_the_single_agent_env_returns(module, env_id):
    """A policy trained single-agent gets the same observation in the two-player env, and the same shot."""
    env = module.env(angle_noise=0.01)
    single = gym.make(env_id, opponent=None, angle_noise=0.01)
    env.reset(seed=5)
    obs1, _ = single.reset(seed=5)
    assert env.agent_selection == "player_0"
    np.testing.assert_array_equal(env.observe("player_0"), obs1)
    action = np.array([0.01, 1.0] + [0.0] * (single.action_space.shape[0] - 2), dtype=np.float32)
    env.step(action)
    obs2, _, _, _, info = single.step(action)
    np.testing.assert_array_equal(env.unwrapped.game_env.balls.pos, single.unwrapped.balls.pos)
    np.testing.assert_array_equal(env.observe(AGENTS[info["shooter"]]), obs2)  # the shooter's view, as single-agent


@pytest.mark.parametrize("module, _", GAMES, ids=IDS)
def test_same_seed_and_actions_replay_bit_for_bit(module, _):
    def run(seed):
        env = module.env(angle_noise=0.02, speed_noise=0.05)
        env.reset(seed=seed)
        rng = np.random.default_rng(123)
        seen = []
        for agent in env.agent_iter(40):
            obs, reward, terminated, truncated, info = env.last()
            seen.append((agent, obs.copy(), reward, info.get("angle")))
            env.step(None if terminated or truncated else
                     rng.uniform(-1, 1, env.action_space(agent).shape).astype(np.float32))
        return seen

    a, b, c = run(3), run(3), run(4)
    assert len(a) == len(b) and len(a) > 2
    for (ag1, o1, r1, ang1), (ag2, o2, r2, ang2) in zip(a, b):
        assert ag1 == ag2 and r1 == r2 and ang1 == ang2
        np.testing.assert_array_equal(o1, o2)
    # another seed: another rack order, or (fixed layouts: snooker, three-cushion) other noise later on
    assert any(not np.array_equal(x[1], y[1]) for x, y in zip(a, c))


def test_first_shooter_random_draws_the_breaker_from_the_seed():
    env = nine_ball_v0.env(first_shooter="random")
    breakers = set()
    for seed in range(8):
        env.reset(seed=seed)
        breakers.add(env.agent_selection)
        assert env.unwrapped.game_state.shooter == AGENTS.index(env.agent_selection)
    assert breakers == set(AGENTS)
    env = nine_ball_v0.env(first_shooter="opponent")
    env.reset(seed=0)
    assert env.agent_selection == "player_1"


def test_opponent_key_is_ignored_and_config_round_trips():
    single = gym.make("Billiards9Ball-v0")  # opponent "geometric" by default
    env = nine_ball_v0.raw_env(**single.unwrapped.config.to_dict())
    assert env.game_env.config.opponent is None and env.task.opponent is None and not env.task.auto_opponent


def test_bad_input_gets_clear_errors():
    with pytest.raises(ConfigError, match="not a game"):
        nine_ball_v0.raw_env(task="pot")
    with pytest.raises(ConfigError, match="friction"):
        nine_ball_v0.env(friction="sticky")
    env = nine_ball_v0.raw_env()
    env.reset(seed=0)
    n = env.action_space("player_0").shape[0]
    with pytest.raises(ValueError, match="finite"):
        env.step(np.full(n, np.nan, dtype=np.float32))
    with pytest.raises(ValueError, match="None is only for an agent whose game is over"):
        env.step(None)
    with pytest.raises(ValueError, match="expected 4 numbers"):
        env.step(np.zeros(3, dtype=np.float32))
    with pytest.warns(UserWarning, match=r"unknown key\(s\) \['positons'\]"):
        env.reset(seed=0, options={"positons": np.zeros((10, 2))})  # a typo: warned, the rack is used
    assert env.game_env.task.game_state.break_shot


def test_step_after_the_game_raises_reset_needed():
    env = nine_ball_v0.raw_env(rules={"three_foul_rule": True})
    env.reset(seed=0)
    miss = np.array([1.0, -1.0, -1.0, -1.0], dtype=np.float32)  # from the kitchen's corner, slow, to the left
    for agent in env.agent_iter(50):
        _, _, terminated, truncated, _ = env.last()
        env.step(None if terminated or truncated else miss)
    assert env.agents == [] and env.winner is not None
    with pytest.raises(gym.error.ResetNeeded):
        env.step(None)


def test_render_modes_as_the_single_agent_env():
    env = nine_ball_v0.env(render_mode="rgb_array", render_width=200)
    env.reset(seed=0)
    frame = env.render()
    assert frame.dtype == np.uint8 and frame.shape[1] == 200 and frame.shape[2] == 3
    env.close()
    env = nine_ball_v0.env(render_mode="rgb_array_list", render_width=120, render_speedup=16.0)
    env.reset(seed=0)
    assert len(env.render()) == 1  # the table after reset
    env.step(np.array([0.0, 1.0, 0.0, 0.0], dtype=np.float32))  # the break, animated
    frames = env.render()
    assert len(frames) > 2 and all(f.shape == frames[0].shape for f in frames)
    assert env.metadata["render_fps"] == 30 and env.metadata["is_parallelizable"] is False
    env.close()
