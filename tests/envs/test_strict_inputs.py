"""Nothing is accepted silently: a programmer's bad argument gets one clear error naming the valid range (a policy's
actions are still clipped), the agent sees the opponent's shots, a recorded step cannot exhaust memory."""
from __future__ import annotations

import math

import numpy as np
import pytest
from env_helpers import gym

from billiards_env.envs.base import frame_shares
from billiards_env.envs.config import ConfigError


def _nine_ball(**kw):
    env = gym.make("Billiards9Ball-v0", **kw)
    env.reset(seed=3)
    return env, env.unwrapped


def test_set_opponent_takes_a_name_and_refuses_nonsense_at_once():
    env, u = _nine_ball()
    u.set_opponent("search")
    assert u.task.opponent.name == "search"
    with pytest.raises(ValueError, match="unknown player 'serch' for nine_ball; use one of random, geometric"):
        u.set_opponent("serch")
    with pytest.raises(TypeError, match="expected a player"):
        u.set_opponent(42)


def test_game_reset_options_need_positions_and_valid_values():
    env, u = _nine_ball()
    with pytest.raises(ValueError, match="need 'positions'"):
        env.reset(options={"ball_in_hand": "anywhere"})
    pos = u.balls.pos.copy()
    with pytest.raises(ValueError, match="ball_in_hand: must be False, 'anywhere' or 'kitchen'"):
        env.reset(options={"positions": pos, "ball_in_hand": "everywhere"})
    env.reset(options={"positions": pos, "ball_in_hand": "anywhere"})
    assert u.table_state.view.place_area is not None


@pytest.mark.parametrize("env_id, options, message", [
    ("BilliardsThreeCushion-v0", {"score": (20, 0)}, r"reset options\['score'\]: \(20, 0\) reaches target_points=10, "
     r"where the game is over; give scores below 10"),
    ("BilliardsThreeCushion-v0", {"score": "x"}, r"reset options\['score'\]: expected two whole numbers >= 0 "
     r"\(player 0's, player 1's\), got 'x'"),
    ("BilliardsThreeCushion-v0", {"score": (1, -2)}, r"expected two whole numbers >= 0 .*got \(1, -2\)"),
    ("BilliardsThreeCushion-v0", {"break_shot": 5}, r"reset options\['break_shot'\]: expected True or False, got 5"),
    ("BilliardsSnooker-v0", {"reds_left": 99}, r"reset options: unknown key\(s\) \['reds_left'\]; allowed: "
     r"'positions'.*'score'"),
    ("BilliardsSnooker-v0", {"score": "x"}, r"reset options\['score'\]: expected two whole numbers"),
    ("Billiards8Ball-v0", {"break_shot": "yes"}, r"reset options\['break_shot'\]: expected True or False, got 'yes'"),
])
def test_every_games_reset_options_are_checked(env_id, options, message):
    env = gym.make(env_id, opponent=None)
    env.reset(seed=0)
    pos = env.unwrapped.balls.pos.copy()
    with pytest.raises(ValueError, match=message):
        env.reset(options={"positions": pos, **options})
    env.close()


@pytest.mark.parametrize("env_id", ["BilliardsOneBall-v0", "Billiards9Ball-v0"])
def test_reset_options_must_be_a_dict(env_id):
    env = gym.make(env_id)
    with pytest.raises(ValueError, match=r"reset options must be a dict, got list \[1, 2\]; e.g. "
                                         r"reset\(options=\{'positions': ...\}\)"):
        env.reset(options=[1, 2])
    venv = gym.make_vec(env_id, 2, vectorization_mode="vector_entry_point")
    with pytest.raises(ValueError, match="reset options must be a dict, got list"):
        venv.reset(options=[1, 2])
    env.close()
    venv.close()


def test_a_three_cushion_score_below_the_target_still_sets_up_the_table():
    env = gym.make("BilliardsThreeCushion-v0", opponent=None)
    env.reset(seed=0)
    pos = env.unwrapped.balls.pos.copy()
    _, info = env.reset(options={"positions": pos, "score": (9, 3), "break_shot": False})
    assert tuple(info["score"]) == (9, 3) and info["winner"] == -1


@pytest.mark.parametrize("kwargs,message", [
    ({"place": (5.0, 5.0)}, r"outside the ball-in-hand area x in \[0.02857, 0.635\]"),
    ({"place": (math.nan, 0.6)}, "place must be finite"),
    ({"side": 0.3}, "no tip-offset dims"),
    ({"pocket": 2}, "declares no 'pocket'"),
    ({"push": True}, "declares no 'push'"),
    ({"speed": 9.0}, r"outside this env's range \[0.5, 8.0\]"),
])
def test_action_from_shot_refuses_what_it_cannot_play(kwargs, message):
    env, u = _nine_ball()
    speed = kwargs.pop("speed", 2.0)
    with pytest.raises(ValueError, match=message):
        u.action_from_shot(0.0, speed, **kwargs)


def test_eight_ball_called_pocket_is_checked_not_wrapped():
    env = gym.make("Billiards8Ball-v0")
    env.reset(seed=0)
    with pytest.raises(ValueError, match=r"pocket: must be a pocket index 0..5, got 7"):
        env.unwrapped.action_from_shot(0.0, 2.0, pocket=7)
    a = env.unwrapped.action_from_shot(0.0, 2.0, pocket=4)
    assert env.unwrapped.shot_from_action(a).call("pocket") == 4


def test_spin_tip_offset_beyond_the_limit_is_refused():
    env = gym.make("BilliardsOneBall-v0", friction="spin", spin_action=True, max_tip_offset=0.4)
    env.reset(seed=0)
    with pytest.raises(ValueError, match="the largest is max_tip_offset = 0.4"):
        env.unwrapped.action_from_shot(0.0, 2.0, side=0.3, top=0.3)
    shot = env.unwrapped.shot_from_action(env.unwrapped.action_from_shot(0.0, 2.0, side=0.2, top=-0.1))
    assert shot.side == pytest.approx(0.2) and shot.top == pytest.approx(-0.1)


def test_policy_actions_are_still_clipped():
    env, u = _nine_ball()
    shot = u.shot_from_action(np.array([0.0, 40.0, -9.0, 9.0], np.float32))
    assert shot.speed == pytest.approx(u.config.speed_max)
    x0, x1, y0, y1 = u.table_state.view.place_area
    assert x0 - 1e-12 <= shot.place[0] <= x1 + 1e-12 and y0 - 1e-12 <= shot.place[1] <= y1 + 1e-12


@pytest.mark.parametrize("key,value", [("opponent", "search"), ("opponent", None), ("win_reward", 2.0),
                                       ("first_shooter", "opponent")])
def test_game_keys_on_a_scene_without_rules_are_refused(key, value):
    with pytest.raises(ConfigError, match=f"{key}: only the games"):
        gym.make("BilliardsOneBall-v0", **{key: value})


def test_vector_env_threads_must_be_positive():
    with pytest.raises(ValueError, match="threads: .* integer >= 1 or None"):
        gym.make_vec("BilliardsOneBall-v0", 2, threads=-3)


def test_game_vector_env_names_the_batch_shape():
    vec = gym.make_vec("Billiards9Ball-v0", 3, opponent="random")
    vec.reset(seed=0)
    with pytest.raises(ValueError, match=r"batch of shape \(3, 4\)"):
        vec.step(np.zeros(4))
    vec.close()


def test_info_describes_every_opponent_shot():
    """With opponent_infos=True, info["opponent_turns"] describes each shot of the reply in the info's forms, and the
    fixed keys (opponent_shots, opponent_pocketed, opponent_fouls) sum it up; without it they alone are there."""
    env = gym.make("Billiards9Ball-v0", opponent="geometric", opponent_infos=True)
    plain = gym.make("Billiards9Ball-v0", opponent="geometric")
    assert "opponent_turns" not in plain.reset(seed=1)[1]
    env.reset(seed=1)
    seen = 0
    for _ in range(20):
        action = env.action_space.sample()
        obs, reward, term, trunc, info = env.step(action)
        assert "opponent_turns" not in plain.step(action)[4]
        turns = info["opponent_turns"]
        assert len(turns) == info["opponent_shots"]
        assert info["opponent_fouls"] == sum(t["foul"] for t in turns)
        pocketed = np.zeros(env.unwrapped.n_balls, bool)
        for t in turns:
            pocketed |= t["pocketed"]
            assert t["shooter"] == 1
            assert set(t) >= {"pocketed", "foul", "foul_reason", "call", "scratch", "first_contact", "turn_over"}
            assert (t["foul_reason"] >= 0) == t["foul"] and t["call"] >= 0
            assert t["scratch"] == t["pocketed"][0]  # row 0: the cue ball
        assert np.array_equal(info["opponent_pocketed"], pocketed)
        if turns:
            # Only the last shot of a reply passes the turn back (or ends the game).
            assert all(not t["turn_over"] for t in turns[:-1])
            assert turns[-1]["turn_over"] or info["winner"] != -1
            seen += len(turns)
        if term or trunc:
            env.reset()
            plain.reset()
    assert seen > 0


def test_a_recorded_step_draws_at_most_render_max_frames():
    env = gym.make("Billiards9Ball-v0", render_mode="rgb_array_list", render_width=120, render_max_frames=40)
    env.reset(seed=0)
    env.render()
    lengths = []
    for _ in range(3):
        *_, term, trunc, info = env.step(env.action_space.sample())
        frames = env.render()
        lengths.append(len(frames))
        assert 2 <= len(frames) <= 40
        if term or trunc:
            break
    uncapped = gym.make("Billiards9Ball-v0", render_mode="rgb_array_list", render_width=120, render_max_frames=0)
    uncapped.reset(seed=0)
    uncapped.render()
    uncapped.step(np.zeros(4, np.float32))
    assert len(uncapped.render()) > 40  # a break lasts seconds at 30 fps: the cap above did bite


@pytest.mark.parametrize("n_shots", [1, 3, 7, 19, 20, 21, 45])
@pytest.mark.parametrize("cap", [1, 2, 5, 40])
def test_frame_shares_never_exceed_the_cap_and_keep_the_last_state(n_shots, cap):
    rng = np.random.default_rng(n_shots * 100 + cap)
    durations = list(rng.exponential(2.0, n_shots) * rng.integers(0, 2, n_shots))  # some shots last 0 s
    shares = frame_shares(durations, cap)
    assert len(shares) == n_shots
    assert sum(shares) <= cap
    assert shares[-1] >= 1  # the table after the step is always drawn
    if cap >= 2 * n_shots:
        assert min(shares) >= 2  # every shot's first and last state
    else:
        assert shares == sorted(shares)  # the latest shots are the ones kept


def test_many_short_shots_in_one_step_stay_under_the_frame_cap():
    """A game reply of many shots: the floors of two frames a shot used to push the total past the cap."""
    env = gym.make("Billiards9Ball-v0", render_mode="rgb_array_list", render_width=64, render_max_frames=40)
    inner = env.unwrapped
    inner.reset(seed=0)
    inner.render()
    rng = np.random.default_rng(3)
    for _ in range(40):
        *_, term, trunc, info = inner.step(rng.uniform(-1, 1, inner.action_space.shape).astype(np.float32))
        assert 1 <= len(inner.render()) <= 40
        if term or trunc:
            inner.reset(seed=1)
            inner.render()
