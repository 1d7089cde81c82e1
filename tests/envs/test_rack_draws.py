"""The compiled rack (:func:`billiards_env.games.pool.rack_rows`) draws what the Python sessions draw, in the same
order, so a vector env's table and a single env's table with the same seed are racked alike."""
from __future__ import annotations

import numpy as np
import pytest
from numba import njit

from billiards_env.games.pool import (RACK_EIGHT, RACK_NINE, EightBallSession, NineBallSession, permutation_of,
                                      rack_rows)


@njit(cache=False)
def _draws_around(g: np.random.Generator, n: int) -> tuple:
    """A draw before and after the permutation: numpy buffers half of a 64-bit word for 32-bit draws, so the
    permutation must leave the generator where numpy's leaves it."""
    before = g.integers(0, 2)
    perm = permutation_of(g, n)
    after = g.integers(0, 7)
    return before, perm, after


@pytest.mark.parametrize("n", [0, 1, 2, 7, 12, 40])
def test_permutation_of_is_numpys_permutation_and_leaves_the_generator_where_numpy_does(n: int) -> None:
    for seed in range(100):
        ours, theirs = np.random.default_rng(seed), np.random.default_rng(seed)
        before, perm, after = _draws_around(ours, n)
        assert before == theirs.integers(0, 2)
        assert np.array_equal(perm, theirs.permutation(n)), (seed, n)
        assert after == theirs.integers(0, 7)
        assert ours.integers(0, 2 ** 62) == theirs.integers(0, 2 ** 62)


@pytest.mark.parametrize("session, mode, n_slots", [(NineBallSession, RACK_NINE, 9), (EightBallSession, RACK_EIGHT, 15)])
def test_the_compiled_rack_puts_each_number_where_the_session_does(session: type, mode: int, n_slots: int) -> None:
    slots = np.arange(2.0 * n_slots).reshape(n_slots, 2)
    racker = object.__new__(session)  # rack_order reads no state of the session
    seen = set()
    for seed in range(200):
        pos = np.full((1, 16, 2), -1.0)
        ours, theirs = np.random.default_rng(seed), np.random.default_rng(seed)
        rack_rows(0, ours, pos, slots, mode)
        order = racker.rack_order(n_slots, theirs)
        for slot, number in enumerate(order):
            assert np.array_equal(pos[0, number], slots[slot]), (seed, slot, number)
        assert ours.integers(0, 2 ** 62) == theirs.integers(0, 2 ** 62)
        seen.add(order)
    assert len(seen) > 150  # the draws do vary the rack
