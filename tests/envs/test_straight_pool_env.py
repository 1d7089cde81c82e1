"""BilliardsStraightPool-v0 on the table: the call through the action, the re-rack's geometry, the third foul's
re-break, the players' calls, the checkers, the vector env (the sub-envs one by one)."""
from __future__ import annotations

import os
from dataclasses import replace

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from gymnasium.utils.env_checker import check_env as gym_check_env  # noqa: E402

import billiards_env  # noqa: E402,F401
from billiards_env.physics.aim import aim_angle  # noqa: E402
from billiards_env.physics.layout import foot_spot, head_spot, head_string_x, triangle_positions  # noqa: E402
from billiards_env.players import make_player  # noqa: E402

ID = "BilliardsStraightPool-v0"


def _table(env: gym.Env, where: dict[int, tuple[float, float]], score=(0, 0)) -> None:
    """Set up rows ``where`` (the cue ball among them) with every other ball pocketed, the agent to shoot."""
    u = env.unwrapped
    pos = u.balls.pos.copy()
    off = np.ones(u.n_balls, bool)
    for row, xy in where.items():
        pos[row] = xy
        off[row] = False
    for row in np.flatnonzero(off):
        pos[row] = (0.1 + 0.06 * row, 0.05)  # (ignored: off the table)
    env.reset(options={"positions": pos, "pocketed": off, "score": score})


def _straight_in(env: gym.Env, row: int, pocket: int, dist: float = 0.25, back: float = 0.35) -> tuple:
    """Where ``row`` and the cue ball go for a straight-in shot into ``pocket`` of the env's table."""
    t = env.unwrapped.table
    p = np.asarray(t.pocket_xy[pocket], float)
    centre = np.array([t.length / 2, t.width / 2])
    d = (centre - p) / np.linalg.norm(centre - p)
    ball = p + dist * d
    return tuple(ball), tuple(ball + back * d)


def test_the_action_calls_a_ball_and_a_pocket_and_the_checkers_pass():
    env = gym.make(ID, opponent=None)
    u = env.unwrapped
    assert env.action_space.shape == (6,) and u.action_type.layout().endswith("ball, pocket")
    env.reset(seed=0)
    shot = u.shot_from_action(u.action_from_shot(0.3, 2.0, place=(0.4, 0.6), ball=7, pocket=4))
    assert shot.call("ball") == 7 and shot.call("pocket") == 4
    with pytest.raises(ValueError, match=r"ball: must be an object ball's row 1..15, got 16"):
        u.action_from_shot(0.3, 2.0, ball=16)
    with pytest.raises(ValueError, match="declares no 'push'"):
        u.action_from_shot(0.3, 2.0, push=True)
    gym_check_env(env.unwrapped)
    sb3 = pytest.importorskip("stable_baselines3.common.env_checker")
    sb3.check_env(gym.make(ID).unwrapped, warn=True)


def test_a_called_pot_scores_and_a_wrong_call_is_spotted():
    env = gym.make(ID, opponent=None)
    u = env.unwrapped
    ball, cue = _straight_in(env, 3, 2)
    where = {0: cue, 3: ball, 9: (1.0, 0.6), 12: (1.5, 0.9)}
    _table(env, where)
    _, _, _, _, info = env.step(u.action_from_shot(aim_angle(cue, ball), 1.5, ball=3, pocket=2))
    assert info["pocketed"][3] and info["points"] == 1 and tuple(info["score"]) == (1, 0)
    assert info["shooter"] == 0 and not info["turn_over"] and not u.balls.on_table[3]
    _table(env, where)
    _, _, terminated, _, info = env.step(u.action_from_shot(aim_angle(cue, ball), 1.5, ball=3, pocket=5))
    assert info["points"] == 0 and info["turn_over"] and terminated  # alone: the inning ended the practice
    assert u.balls.on_table[3] and np.allclose(u.balls.pos[3], foot_spot(u.table), atol=1e-9)  # spotted


def test_the_fourteenth_ball_re_racks_with_the_apex_empty_and_the_fifteenth_left_where_it_lies():
    env = gym.make(ID, opponent=None)
    u = env.unwrapped
    ball, cue = _straight_in(env, 3, 2)
    last = (1.0, 0.3)  # far from the rack and the head spot
    _table(env, {0: cue, 3: ball, 9: last}, score=(20, 7))
    _, _, _, _, info = env.step(u.action_from_shot(aim_angle(cue, ball), 1.5, ball=3, pocket=2))
    b = u.balls
    assert info["rerack"] == 14 and info["points"] == 1 and tuple(info["score"]) == (21, 7)
    assert b.on_table.all() and np.allclose(b.pos[9], last)
    slots = triangle_positions(foot_spot(u.table), float(b.radius[1]), rows=5)
    racked = [r for r in range(1, 16) if r != 9]
    assert sorted(np.argmin(np.hypot(*(slots - b.pos[r]).T)) for r in racked) == list(range(1, 15))
    assert u.task.game_state.on_table == tuple(range(1, 16)) and u.task.game_state.shooter == 0 and info["ball_in_hand"] == 0


def test_a_fifteenth_ball_in_the_rack_goes_to_the_head_spot():
    env = gym.make(ID, opponent=None)
    u = env.unwrapped
    ball, cue = _straight_in(env, 3, 2)
    apex = foot_spot(u.table)
    _table(env, {0: cue, 3: ball, 9: (apex[0] + 0.01, apex[1])})
    _, _, _, _, info = env.step(u.action_from_shot(aim_angle(cue, ball), 1.5, ball=3, pocket=2))
    assert info["rerack"] == 14
    assert np.allclose(u.balls.pos[9], head_spot(u.table)) and u.balls.on_table.all()
    assert not np.any(np.hypot(*(u.balls.pos[1:] - u.balls.pos[0]).T) < 2 * u.balls.radius[0])  # nothing overlaps


def test_the_third_foul_costs_sixteen_and_racks_fifteen_for_the_offenders_re_break():
    env = gym.make(ID, opponent=None)
    u = env.unwrapped
    _table(env, {0: (0.6, 0.3), 3: (1.8, 0.9), 9: (2.0, 1.0)}, score=(10, 0))
    u.task.game_state = replace(u.task.game_state, fouls_in_a_row=(2, 0))
    _, _, terminated, _, info = env.step(u.action_from_shot(-np.pi / 2, 0.6))  # into the near cushion: no contact
    assert info["foul"] and info["points"] == -16 and tuple(info["score"]) == (-6, 0) and info["rerack"] == 15
    assert not terminated and info["shooter"] == 0 and info["ball_in_hand"] == 2
    st = u.task.game_state
    assert st.break_shot and st.fouls_in_a_row == (0, 0) and u.balls.on_table.all()
    assert u.balls.pos[0, 0] <= head_string_x(u.table) and u.table_state.view.break_shot


@pytest.mark.parametrize("name", ["geometric", "search"])
def test_the_players_call_the_ball_and_pocket_they_play(name):
    env = gym.make(ID, opponent=None)
    u = env.unwrapped
    ball, cue = _straight_in(env, 5, 3, dist=0.3, back=0.3)
    _table(env, {0: cue, 5: ball, 11: (1.2, 0.35), 14: (0.9, 0.9)})
    player = make_player(name, seed=0, game="straight_pool")
    obs = u.observe()
    action = player.act(env, obs)
    shot = u.shot_from_action(action)
    _, _, _, _, info = env.step(action)
    potted = [int(r) for r in np.flatnonzero(info["pocketed"][1:]) + 1]
    assert shot.call("ball") in potted and info["points"] >= 1, (shot, potted, info["call"])


def test_the_vector_env_plays_straight_pool_one_table_at_a_time_with_the_single_envs_results():
    vec = gym.make_vec(ID, 2, rules={"target": 10})
    assert not vec.unwrapped.native and "no compiled rules" in vec.unwrapped.not_native
    singles = [gym.make(ID, rules={"target": 10}) for _ in range(2)]
    obs, _ = vec.reset(seed=[4, 9])
    for k, (s, seed) in enumerate(zip(singles, (4, 9), strict=True)):
        assert np.array_equal(obs[k], s.reset(seed=seed)[0])
    rng = np.random.default_rng(0)
    for _ in range(3):
        actions = rng.uniform(-1, 1, vec.action_space.shape).astype(np.float32)
        obs, rewards, term, trunc, info = vec.step(actions)
        for k, s in enumerate(singles):
            o, r, te, tr, i = s.step(actions[k])
            assert np.array_equal(obs[k], o) and rewards[k] == r and term[k] == te
            assert np.array_equal(info["score"][k], i["score"])
            if te or tr:
                return
    vec.close()


def test_the_target_is_a_rules_option_and_a_bad_one_is_refused():
    env = gym.make(ID, rules={"target": 3}, opponent=None)
    assert env.unwrapped.task.rules.options.target == 3
    with pytest.raises(ValueError, match="target: must be a whole number >= 1"):
        gym.make(ID, rules={"target": 0})
    with pytest.raises(ValueError, match="unknown player 'serch'"):
        gym.make(ID, opponent="serch")


def test_a_table_set_up_by_hand_takes_a_score_below_zero():
    env = gym.make(ID, opponent=None)
    env.reset(seed=0)
    pos = env.unwrapped.balls.pos.copy()
    _, info = env.reset(options={"positions": pos, "score": (-3, 5), "ball_in_hand": "kitchen"})
    assert tuple(info["score"]) == (-3, 5) and info["ball_in_hand"] == 2
    with pytest.raises(ValueError, match=r"reset options\['score'\]: expected two whole numbers"):
        env.reset(options={"positions": pos, "score": (1.5, 0)})
