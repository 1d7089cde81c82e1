"""The built-in opponent's turn: a player that does not read the observation (``reads_observation = False``: the
geometric, search and random players) is not observed for; any other policy gets the env's observation."""
from __future__ import annotations

import numpy as np
import pytest
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


def test_the_opponent_plays_on_the_table_state_it_is_given():
    """The opponent is an object the game's task is given: it chooses its shot from the table state handed to it;
    the task and its session hold no reference to the env."""
    from billiards_env.envs.opponent import Opponent, Seat
    from billiards_env.shot_path import CueShot

    env = gym.make("Billiards9Ball-v0")
    env.reset(seed=5)
    u = env.unwrapped
    task = u.task
    assert isinstance(task.opponent_player, Opponent) and isinstance(task.seat, Seat)
    assert task.seat.agent == 0 and task.seat.opponent == 1 and task.auto_opponent
    assert not hasattr(u, "_opponent_shot") and not hasattr(task, "opponent_action")
    assert all(v is not u for v in vars(task).values()) and all(v is not u for v in vars(task.session).values())
    shot = task.opponent_player.shot(u.table_state)
    assert isinstance(shot, CueShot)
    again = task.opponent_player.shot(u.table_state)  # the geometric player: deterministic on the same table
    assert (again.angle, again.speed) == (shot.angle, shot.speed)
    task.seat.auto = False  # two-player mode: nobody plays inside step
    assert not task.auto_opponent and task.names() == ("player 0", "player 1")


def test_an_opponent_without_a_policy_says_so():
    from billiards_env.envs.opponent import Opponent

    env = gym.make("Billiards9Ball-v0", opponent=None)
    env.reset(seed=0)
    opp = env.unwrapped.task.opponent_player
    assert opp.policy is None and opp.name() == "nobody" and env.unwrapped.task.names()[1] == "nobody"
    assert isinstance(opp, Opponent)
    with pytest.raises(RuntimeError, match="no policy"):
        opp.shot(env.unwrapped.table_state)
