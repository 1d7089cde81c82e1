"""``envs/_seeding.np_random`` returns Gymnasium's generator for a seed: the same PCG64 state and stream, for small
and large seeds, and the same errors for bad seeds; the generator still spawns."""
from __future__ import annotations

import numpy as np
import pytest
from gymnasium import error
from gymnasium.utils import seeding

from billiards_env.envs._seeding import np_random


def test_same_state_and_stream_as_gymnasium():
    rng = np.random.default_rng(0)
    seeds = list(range(300)) + [2**32 - 1, 2**32, 2**63 - 1, 2**64, 2**100 + 12345, 2**160 + 7] \
        + [int(s) for s in rng.integers(0, 2**63 - 1, 300)]
    for seed in seeds:
        fast, fast_seed = np_random(seed)
        ref, ref_seed = seeding.np_random(seed)
        assert fast_seed == ref_seed == seed
        assert fast.bit_generator.state == ref.bit_generator.state, seed
        assert np.array_equal(fast.random(5), ref.random(5)) and fast.normal() == ref.normal()


def test_spawn_and_other_states_come_from_a_real_seed_sequence():
    fast, _ = np_random(42)
    ref, _ = seeding.np_random(42)
    assert np.array_equal(fast.spawn(2)[1].random(3), ref.spawn(2)[1].random(3))
    assert np.array_equal(fast.bit_generator.seed_seq.generate_state(3), np.random.SeedSequence(42).generate_state(3))
    assert fast.bit_generator.seed_seq.spawn_key == ()


def test_bad_seeds_fail_as_in_gymnasium():
    for bad in (-1, 1.5, "3"):
        with pytest.raises(error.Error):
            np_random(bad)
    rng, seed = np_random(None)
    assert isinstance(rng, np.random.Generator) and isinstance(seed, int)
