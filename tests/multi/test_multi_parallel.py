"""The parallel API of the two-player games (``<game>_v0.parallel_env``) and ``max_cycles`` on both APIs: PettingZoo's
parallel_api_test, parallel_seed_test, max_cycles_test and render_test, the turn-based contract (the action of
the agent not to shoot is ignored), agreement with the AEC env shot for shot, and bad input."""
from __future__ import annotations

import importlib
import os
import types
import warnings

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from pettingzoo.utils.conversions import parallel_to_aec  # noqa: E402

with warnings.catch_warnings():  # pettingzoo.test imports PettingZoo's own example envs through a deprecated path
    warnings.simplefilter("ignore", DeprecationWarning)
    from pettingzoo.test import max_cycles_test, parallel_api_test, parallel_seed_test, render_test

import billiards_env  # noqa: E402,F401
from billiards_env.envs.config import ConfigError  # noqa: E402
from billiards_env.games import GAMES as REGISTERED  # noqa: E402
from billiards_env.multi import AGENTS, BilliardsParallelEnv, nine_ball_v0  # noqa: E402

MODULES = [importlib.import_module(f"billiards_env.multi.{g.aec_module}") for g in REGISTERED.values()]
IDS = [g.name for g in REGISTERED.values()]


@pytest.mark.parametrize("module", MODULES, ids=IDS)
def test_pettingzoo_parallel_api_test_passes(module):
    env = module.parallel_env(max_cycles=60)
    assert isinstance(env, BilliardsParallelEnv)
    with pytest.warns(UserWarning, match=r"unknown key\(s\) \['options'\] ignored"):
        parallel_api_test(env, num_cycles=200)
    assert env.agents == []  # every game reached its end (a winner or the 60-shot limit) within 200 steps


@pytest.mark.parametrize("module", MODULES, ids=IDS)
def test_pettingzoo_parallel_seed_test_passes(module):
    parallel_seed_test(lambda: module.parallel_env(angle_noise=0.01, speed_noise=0.02), num_cycles=50)


@pytest.mark.parametrize("module", MODULES, ids=IDS)
def test_pettingzoo_max_cycles_test_passes(module):
    """max_cycles_test runs ``parallel_env(max_cycles=4)`` (truncated after 4 steps) and counts the turns of each
    agent in ``env(max_cycles=4)``, expecting every agent once per cycle. The AEC env selects the agent to shoot
    (a player who pockets shoots again), so that count holds for PettingZoo's AEC view of the parallel env
    (``parallel_to_aec``: both agents step every cycle), which is what it is run on here; the native AEC env's
    shot limit is checked below."""
    mod = types.SimpleNamespace(parallel_env=lambda **kw: _seeded(module.parallel_env(**kw)),
                                env=lambda **kw: parallel_to_aec(_seeded(module.parallel_env(**kw))))
    max_cycles_test(mod)


def _seeded(env: BilliardsParallelEnv, default_seed: int = 0) -> BilliardsParallelEnv:
    """``env`` with its action spaces seeded and ``reset()`` seeded by default. max_cycles_test resets and samples
    unseeded and assumes no game ends within its 4 cycles; a random shot can pocket the 8 or the 9 early, so the
    test is made reproducible rather than left to chance (a game that ends early is a legal outcome)."""
    for k, agent in enumerate(env.possible_agents):
        env.action_space(agent).seed(default_seed + k)
    unseeded_reset = env.reset

    def reset(seed: int | None = None, options: dict | None = None):
        return unseeded_reset(seed=default_seed if seed is None else seed, options=options)

    env.reset = reset  # type: ignore[method-assign]
    return env


@pytest.mark.parametrize("module", MODULES, ids=IDS)
def test_max_cycles_truncates_both_apis_after_that_many_shots(module):
    n = 5
    par = module.parallel_env(max_cycles=n, rules=_no_early_end(module))
    _, infos = par.reset(seed=3)
    for k, a in enumerate(AGENTS):
        par.action_space(a).seed(k)
    played = []
    while par.agents:
        actions = {a: par.action_space(a).sample() for a in par.agents}
        played.append(actions[infos[AGENTS[0]]["active_agent"]])
        _, _, terminations, truncations, infos = par.step(actions)
    assert len(played) == n and all(truncations.values()) and not any(terminations.values())
    aec = module.env(max_cycles=n, rules=_no_early_end(module))
    aec.reset(seed=3)
    shots = 0
    for agent in aec.agent_iter():
        _, _, terminated, truncated, _ = aec.last()
        if terminated or truncated:
            assert truncated and not terminated
            aec.step(None)
            continue
        aec.step(played[shots])
        shots += 1
    assert shots == n
    assert aec.unwrapped.max_cycles == par.unwrapped.max_cycles == n
    assert aec.unwrapped.game_env.config.max_shots == n


def _no_early_end(module: types.ModuleType) -> dict:
    """Rules under which five random shots cannot end the game (three fouls, a 10-point game)."""
    return {"three_foul_rule": False} if module in (nine_ball_v0,) else {}


def test_pettingzoo_render_test_passes():
    """Every render mode of the AEC env and of the parallel env's AEC view (one game: the drawing is shared)."""
    module = nine_ball_v0
    small = {"render_max_frames": 3, "render_width": 160}
    render_test(lambda render_mode=None: module.env(render_mode=render_mode, **small))
    render_test(lambda render_mode=None: parallel_to_aec(module.parallel_env(render_mode=render_mode, **small)))


def _play(module, seed: int, other: object, n: int = 12):
    """Up to ``n`` steps of ``parallel_env`` with a fixed shot for the shooter and ``other`` for the agent not to
    shoot; the observations, rewards and active agents."""
    env = module.parallel_env()
    obs, infos = env.reset(seed=seed)
    rng = np.random.default_rng(seed)
    trace = [(obs, infos[AGENTS[0]]["active_agent"])]
    for _ in range(n):
        if not env.agents:
            break
        active = infos[AGENTS[0]]["active_agent"]
        shot = rng.uniform(-1, 1, env.action_space(active).shape).astype(np.float32)
        actions = {a: (shot if a == active else other) for a in env.agents}
        obs, rewards, terminations, truncations, infos = env.step(actions)
        trace.append((obs, rewards, infos[AGENTS[0]]["active_agent"]))
    return trace


def _equal(a, b) -> bool:
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(_equal(a[k], b[k]) for k in a)
    if isinstance(a, (tuple, list)):
        return len(a) == len(b) and all(_equal(x, y) for x, y in zip(a, b))
    return bool(np.array_equal(a, b))


@pytest.mark.parametrize("module", MODULES, ids=IDS)
def test_the_action_of_the_agent_not_to_shoot_is_ignored(module):
    n_dims = module.parallel_env().action_space(AGENTS[0]).shape
    ones = _play(module, seed=11, other=np.ones(n_dims, np.float32))
    junk = _play(module, seed=11, other=np.full(n_dims, -1.0, np.float32))
    left_out = _play(module, seed=11, other=None)  # None: the agent not to shoot may give nothing
    assert _equal(ones, junk) and _equal(ones, left_out)
    assert len(ones) > 2


def test_parallel_agrees_with_aec_shot_for_shot():
    par = nine_ball_v0.parallel_env(angle_noise=0.01)
    aec = nine_ball_v0.env(angle_noise=0.01)
    obs_p, infos = par.reset(seed=7)
    aec.reset(seed=7)
    rng = np.random.default_rng(0)
    shooters = []
    while par.agents:
        active = infos[AGENTS[0]]["active_agent"]
        assert active == aec.agent_selection
        for a in AGENTS:
            np.testing.assert_array_equal(obs_p[a], aec.observe(a))
        shot = rng.uniform(-1, 1, par.action_space(active).shape).astype(np.float32)
        obs_p, rewards, terminations, truncations, infos = par.step({active: shot})
        aec.step(shot)
        shooters.append(active)
        assert rewards == aec.unwrapped.rewards
        assert terminations == aec.terminations and truncations == aec.truncations
    assert len(set(shooters)) == 2  # the turn passed at least once


def test_infos_name_the_active_agent_at_reset_and_every_step():
    env = nine_ball_v0.parallel_env(max_cycles=6)
    _, infos = env.reset(seed=0)
    env.action_space(AGENTS[0]).seed(0)
    env.action_space(AGENTS[1]).seed(1)
    assert infos[AGENTS[0]]["active_agent"] == infos[AGENTS[1]]["active_agent"] == "player_0"
    keys = set(infos[AGENTS[0]])
    while env.agents:
        _, _, _, _, infos = env.step({a: env.action_space(a).sample() for a in env.agents})
        for a in AGENTS:
            assert set(infos[a]) == keys  # as after reset; the last step's too, after the game ended
            assert infos[a]["active_agent"] == AGENTS[infos[a]["shooter"]]


def test_bad_input_gets_clear_errors():
    env = nine_ball_v0.parallel_env(max_cycles=2)
    env.reset(seed=0)
    sample = env.action_space(AGENTS[0]).sample()
    with pytest.raises(ValueError, match=r"no action for 'player_0', the agent to shoot"):
        env.step({"player_1": sample})
    with pytest.raises(ValueError, match=r"unknown agent\(s\) \['player_2'\]"):
        env.step({"player_0": sample, "player_2": sample})
    with pytest.raises(TypeError, match="expected a dict agent -> action"):
        env.step(sample)
    with pytest.raises(ValueError, match="NaN"):
        env.step({"player_0": np.full_like(sample, np.nan)})
    env.reset(seed=0)
    while env.agents:
        env.step({a: env.action_space(a).sample() for a in env.agents})
    with pytest.raises(gym.error.ResetNeeded):
        env.step({"player_0": sample})
    for bad in (0, -3, 2.5, "4", True):
        with pytest.raises(ConfigError, match="max_cycles: expected an int >= 1"):
            nine_ball_v0.parallel_env(max_cycles=bad)
    with pytest.raises(ConfigError, match="both are the shot limit"):
        nine_ball_v0.env(max_cycles=4, max_shots=5)
    assert nine_ball_v0.env(max_cycles=4, max_shots=4).unwrapped.max_cycles == 4
