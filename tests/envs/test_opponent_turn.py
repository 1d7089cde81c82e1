"""The built-in opponent's turn: a player that does not read the observation (``reads_observation = False``: the
geometric, search and random players) is not observed for; any other policy gets the env's observation."""
from __future__ import annotations

import numpy as np
from env_helpers import gym

from billiards_env.players import GeometricPlayer, RandomPlayer, SearchPlayer


class Spy(GeometricPlayer):
    """The geometric player, recording the observations it is handed."""

    def __init__(self, reads: bool) -> None:
        super().__init__()
        self.reads_observation = reads
        self.seen: list = []

    def act(self, source, obs=None, codec=None):
        self.seen.append(obs)
        return super().act(source, obs, codec)


def test_players_that_ignore_the_observation_are_not_observed_for():
    assert not GeometricPlayer.reads_observation and not SearchPlayer.reads_observation
    assert not RandomPlayer.reads_observation
    for reads in (False, True):
        env = gym.make("Billiards9Ball-v0", first_shooter="opponent", action_type="candidates",
                       observation_type="candidates")
        spy = Spy(reads)
        env.unwrapped.set_opponent(spy)
        obs, _ = env.reset(seed=3)
        for _ in range(3):
            obs, _, term, trunc, _ = env.step(np.zeros(env.action_space.shape, np.float32))
            if term or trunc:
                obs, _ = env.reset()
        assert spy.seen
        if reads:
            assert all(isinstance(o, np.ndarray) and o.shape == env.observation_space.shape for o in spy.seen)
        else:
            assert all(o is None for o in spy.seen)
