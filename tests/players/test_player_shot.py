"""Players return a CueShot: ``player.shot(state, obs, codec)`` is the shot the action type reads back from the action
``player.act(state, obs, codec)`` gives (one decision, two forms), so the opponent plays exactly what the player's
action would play, float32 rounding and a discrete type's choices included."""
from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401  (registers the ids)
from billiards_env.players import BasePlayer, make_player, shot_context
from billiards_env.shot_path import CueShot

# (env id, env kwargs, player name, game of the player, steps): pot scenes, games, a discrete action type (the
# player then chooses among the shots it can express), ball in hand and the spin dims.
CASES = [
    ("BilliardsThreeBalls-v0", {}, "random", None, 3),
    ("BilliardsThreeBalls-v0", {}, "geometric", None, 3),
    ("BilliardsThreeBalls-v0", {"action_type": "relative"}, "search", None, 2),
    ("Billiards9Ball-v0", {"opponent": None}, "geometric", None, 3),
    ("Billiards9Ball-v0", {"opponent": None, "action_type": "candidates", "observation_type": "candidates"},
     "geometric", None, 3),
    ("Billiards9Ball-v0", {"opponent": None, "opening": "ball_in_hand", "friction": "spin", "spin_action": True},
     "random", None, 2),
    ("BilliardsThreeCushion-v0", {"opponent": None}, "geometric", "three_cushion", 2),
    ("BilliardsSnooker-v0", {"opponent": None}, "geometric", "snooker", 2),
]


@pytest.mark.parametrize("env_id,kwargs,name,game,steps", CASES,
                         ids=[f"{c[0]}-{c[2]}-{'-'.join(map(str, c[1].values()))}" for c in CASES])
def test_a_players_shot_is_its_codecs_reading_of_its_action(env_id, kwargs, name, game, steps):
    env = gym.make(env_id, **kwargs)
    obs, _ = env.reset(seed=11)
    u = env.unwrapped
    by_shot, by_act = make_player(name, seed=3, game=game), make_player(name, seed=3, game=game)
    assert isinstance(by_shot, BasePlayer)
    for _ in range(steps):
        state, codec = u.table_state, u.action_type
        shot = by_shot.shot(state, obs, codec)
        action = by_act.act(state, obs, codec)
        assert isinstance(shot, CueShot)
        assert action.dtype == np.float32 and env.action_space.contains(action)
        assert shot == codec.shot(state, action)  # bit for bit: the same decision, read back once
        obs, _, term, trunc, _ = env.step(action)
        if term or trunc:
            obs, _ = env.reset()
    env.close()


def test_a_players_shot_is_what_its_action_type_can_express():
    """A player's shot is the one its float32 action plays, not the float64 shot of its geometry: the two differ in
    the last digits, and encoding the shot again plays it unchanged."""
    env = gym.make("Billiards9Ball-v0", opponent=None)
    obs, _ = env.reset(seed=4)
    u = env.unwrapped
    env.step(make_player("geometric").act(u.table_state, obs, u.action_type))  # past the break
    state, codec = u.table_state, u.action_type
    player = make_player("geometric")
    shot = player.shot(state, None, codec)
    free = player.decide(shot_context(state, codec))
    assert shot.angle == pytest.approx(free.angle, abs=1e-5) and shot.speed == pytest.approx(free.speed, rel=1e-5)
    assert (shot.angle, shot.speed) != (free.angle, free.speed)  # quantized as the action type says
    again = codec.shot(state, codec.action(state, shot.angle, shot.speed, place=shot.place, **dict(shot.calls)))
    assert (again.angle, again.speed) == pytest.approx((shot.angle, shot.speed), abs=1e-6)
    env.close()


def test_a_player_without_an_action_type_says_which_to_give():
    env = gym.make("BilliardsThreeBalls-v0")
    env.reset(seed=0)
    with pytest.raises(TypeError, match="action type"):
        make_player("geometric").shot(env.unwrapped.table_state)
    with pytest.raises(NotImplementedError, match="choose"):
        BasePlayer().shot(env.unwrapped.table_state, None, env.unwrapped.action_type)
