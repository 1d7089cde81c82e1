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

    def choose(self, state, obs, codec):
        self.seen.append(obs)
        return super().choose(state, obs, codec)


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


def test_the_opponent_hands_its_policy_the_table_state_never_the_env():
    """Every policy form is asked with the table state (and an action type), and nothing the opponent holds is the
    env: it calls no env."""
    import inspect

    from billiards_env.envs.opponent import Opponent
    from billiards_env.table_state import TableState

    assert "handle" not in inspect.signature(Opponent).parameters
    seen = []

    class Player(GeometricPlayer):
        def shot(self, source, obs=None, codec=None):
            seen.append(("shot", source, codec))
            return super().shot(source, obs, codec)

    class Policy:
        def act(self, state, obs, codec):
            seen.append(("act", state, codec))
            return np.zeros(codec.space.shape, np.float32)

    env = gym.make("Billiards9Ball-v0", first_shooter="opponent", action_type="candidates",
                   observation_type="candidates")
    u = env.unwrapped
    opp = u.task.opponent_player
    assert all(v is not u and v is not env for v in vars(opp).values())
    for policy in (Player(), Policy()):
        u.set_opponent(policy)
        seen.clear()
        env.reset(seed=2)  # the opponent breaks
        assert seen
        for form, source, codec in seen:
            assert isinstance(source, TableState) and source is u.table_state
            # a player plays in the exact type (candidates cannot express every shot); a policy in the env's own
            assert codec is (u.acting_type() if form == "shot" else u.action_type)
    env.close()


def test_an_old_style_act_env_obs_policy_is_refused_with_the_new_form():
    from billiards_env.envs.games import as_policy
    from billiards_env.multi import nine_ball_v0, play_match

    class Old:
        def act(self, env, obs):
            return env.unwrapped.action_space.sample()

    env = gym.make("Billiards9Ball-v0")
    with pytest.raises(TypeError, match=r"old form act\(env, obs\).*act\(state, obs, codec\).*shot\(state, obs, codec\)"):
        env.unwrapped.set_opponent(Old())
    assert env.unwrapped.task.opponent_player.name() == "geometric"  # the refused policy left the seat as it was
    with pytest.raises(TypeError, match=r"act\(state, obs, codec\)"):
        as_policy(Old())
    with pytest.raises(TypeError, match="old form"):
        play_match(nine_ball_v0.env, [Old(), GeometricPlayer()], n_games=1)
    with pytest.raises(TypeError, match="expected a player"):
        env.unwrapped.set_opponent(42)
    env.close()
