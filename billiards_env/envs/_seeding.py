"""``reset(seed=s)`` without most of its cost: :func:`np_random` returns the generator
``gymnasium.utils.seeding.np_random(s)`` returns (``Generator(PCG64(SeedSequence(s)))``, the same state, hence the
same stream), about ten times faster.

Almost all of the cost of seeding is numpy's ``SeedSequence`` hashing the seed into the PCG64 state, in Python
(object set-up, error-state contexts, small arrays). :func:`_pcg64_words` computes the same four words with the
same hash (numpy's ``SeedSequence``: ``mix_entropy`` into a pool of four 32-bit words, then ``generate_state``), and
the generator gets them through a minimal seed sequence object; anything else asked of it (``spawn``, other
sizes) goes to a real ``SeedSequence`` of the seed. ``tests/envs/test_seeding.py`` compares the state and the
stream with numpy's on many seeds, small and large.
"""
from __future__ import annotations

from typing import Any

import numpy as np
from numba import njit
from numpy.random.bit_generator import ISpawnableSeedSequence

_M32 = 0xFFFFFFFF
_INIT_A = 0x43B0D7E5
_MULT_A = 0x931E8875
_INIT_B = 0x8B51F9DD
_MULT_B = 0x58F38DED
_MIX_MULT_L = 0xCA01F9DD
_MIX_MULT_R = 0x4973F715
_POOL = 4


@njit(cache=True)
def _pcg64_words(entropy):
    """The four uint64 words ``SeedSequence(entropy).generate_state(4, np.uint64)`` returns, for a root seed
    sequence whose entropy is the little-endian 32-bit words ``entropy`` (uint64 values below 2**32)."""
    m32 = np.uint64(_M32)
    mult_a = np.uint64(_MULT_A)
    pool = np.zeros(_POOL, np.uint64)
    hc = np.uint64(_INIT_A)
    n = entropy.shape[0]
    for i in range(_POOL):  # hashmix each entropy word (or 0) into the pool
        v = entropy[i] if i < n else np.uint64(0)
        v = v ^ hc
        hc = (hc * mult_a) & m32
        v = (v * hc) & m32
        pool[i] = v ^ (v >> np.uint64(16))
    for i_src in range(_POOL):  # mix every pool word into every other
        for i_dst in range(_POOL):
            if i_src != i_dst:
                v = pool[i_src] ^ hc
                hc = (hc * mult_a) & m32
                v = (v * hc) & m32
                v = v ^ (v >> np.uint64(16))
                r = (np.uint64(_MIX_MULT_L) * pool[i_dst] - np.uint64(_MIX_MULT_R) * v) & m32
                pool[i_dst] = r ^ (r >> np.uint64(16))
    for i_src in range(_POOL, n):  # entropy beyond the pool size
        for i_dst in range(_POOL):
            v = entropy[i_src] ^ hc
            hc = (hc * mult_a) & m32
            v = (v * hc) & m32
            v = v ^ (v >> np.uint64(16))
            r = (np.uint64(_MIX_MULT_L) * pool[i_dst] - np.uint64(_MIX_MULT_R) * v) & m32
            pool[i_dst] = r ^ (r >> np.uint64(16))
    out = np.zeros(4, np.uint64)
    hb = np.uint64(_INIT_B)
    for i_dst in range(8):  # generate_state: eight 32-bit words, paired little-endian into four uint64
        v = pool[i_dst % _POOL] ^ hb
        hb = (hb * np.uint64(_MULT_B)) & m32
        v = (v * hb) & m32
        v = v ^ (v >> np.uint64(16))
        if i_dst % 2 == 0:
            out[i_dst // 2] = v
        else:
            out[i_dst // 2] |= v << np.uint64(32)
    return out


class _RootSeed(ISpawnableSeedSequence):
    """The seed sequence of ``SeedSequence(seed)`` as PCG64 reads it: the four state words, computed by
    :func:`_pcg64_words`; everything else from a real ``SeedSequence(seed)`` made on first use."""

    def __init__(self, seed: int, words: np.ndarray) -> None:
        self.entropy = seed
        self._words = words
        self._real: np.random.SeedSequence | None = None

    def _seq(self) -> np.random.SeedSequence:
        if self._real is None:
            self._real = np.random.SeedSequence(self.entropy)
        return self._real

    def generate_state(self, n_words: int, dtype: Any = np.uint32) -> np.ndarray:
        if n_words == 4 and np.dtype(dtype) == np.uint64:
            return self._words.copy()
        return self._seq().generate_state(n_words, dtype)

    def spawn(self, n_children: int) -> list[np.random.SeedSequence]:
        return self._seq().spawn(n_children)

    def __getattr__(self, name: str) -> Any:  # spawn_key, pool_size, n_children_spawned, state...
        if name.startswith("_"):
            raise AttributeError(name)
        return getattr(self._seq(), name)


def np_random(seed: int | None = None) -> tuple[np.random.Generator, Any]:
    """``gymnasium.utils.seeding.np_random(seed)``: the same generator (state and stream), and the seed it
    reports; seeds other than non-negative ints (and None) go to Gymnasium's own function (its errors too)."""
    if type(seed) is not int or seed < 0:
        from gymnasium.utils import seeding

        return seeding.np_random(seed)
    words = []
    n = seed
    while True:
        words.append(n & _M32)
        n >>= 32
        if n == 0:
            break
    return np.random.Generator(np.random.PCG64(_RootSeed(seed, _pcg64_words(np.array(words, np.uint64))))), seed


__all__ = ["np_random"]
