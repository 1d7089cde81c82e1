"""The search player simulates its candidates in batches (``physics/batch.py``): every candidate's outcome and
value equal those of its own ``Simulator.run``, so the player chooses what one-by-one simulation would choose."""
from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401
from billiards_env.players.context import shot_context
from billiards_env.players.search import _simulate, _value, search_shot


@pytest.mark.parametrize("env_id,seed", [("BilliardsThreeBalls-v0", 3), ("BilliardsOneBall-v0", 8),
                                         ("Billiards9Ball-v0", 1)])
def test_batch_values_equal_single_runs(env_id, seed):
    env = gym.make(env_id)
    env.reset(seed=seed)
    ctx = shot_context(env)
    rng = np.random.default_rng(seed)
    angles = rng.uniform(-math.pi, math.pi, 40)
    speeds = rng.uniform(*ctx.speed_range, 40)
    pots, scratch, hit, values, res = _simulate(ctx, angles, speeds)
    for k in range(40):
        single = ctx.simulator.run(ctx.balls.strike(ctx.cue, angles[k], speeds[k]), validate=False)
        assert pots[k] == sum(1 for j in ctx.targets if single.pocket[j] >= 0)
        assert scratch[k] == (single.pocket[ctx.cue] >= 0)
        assert hit[k] == (single.first_contact(ctx.cue) >= 0)
        assert np.array_equal(res.pos[k], single.balls.pos)
        if ctx.game is None:
            assert values[k] == _value(pots[k], scratch[k], hit[k])
    assert len(set(values.tolist())) > 1 or ctx.game is not None  # the candidates differ (a break may all foul)
    assert (res.first_contact >= 0).any()


def test_search_is_deterministic_and_plays_a_pot():
    env = gym.make("BilliardsOneBall-v0")
    env.reset(seed=2)
    ctx = shot_context(env)
    a1 = search_shot(ctx, None, np.random.default_rng(0))
    a2 = search_shot(ctx, None, np.random.default_rng(0))
    assert a1[:2] == a2[:2] and a1[2].value == a2[2].value
    _, _, _, info = env.step(env.unwrapped.action_from_shot(a1[0], a1[1]))[1:]
    assert info["pocketed"] == ("1",)
