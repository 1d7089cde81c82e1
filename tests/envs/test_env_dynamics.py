"""Actions, seeding, rewards, episode ends and the fast step path, on constructed and random scenes."""
from __future__ import annotations

import math
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from billiards_env.physics import Balls, Simulator  # noqa: E402
from env_helpers import IDS, POT_IDS, L, W, corner_pot_scene, scratch_scene  # noqa: E402


def rollout(env, seed, actions):
    out = []
    obs, _ = env.reset(seed=seed)
    out.append(obs)
    for a in actions:
        obs, r, term, trunc, info = env.step(a)
        out.append((obs, r, term, trunc, info["pocketed"].tolist(), info["n_events"], info["sim_time"]))
        if term or trunc:
            obs, _ = env.reset()
            out.append(obs)
    return out


def same(a, b):
    if isinstance(a, tuple):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, np.ndarray):
        return a.dtype == b.dtype and np.array_equal(a, b)
    return a == b


# --- seeding --------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("env_id", IDS)
def test_same_seed_same_trajectory_bit_for_bit(env_id):
    n_act = gym.make(env_id).action_space.shape[0]
    actions = np.random.default_rng(7).uniform(-1, 1, (6, n_act)).astype(np.float32)
    kw = {"angle_noise": 0.02, "speed_noise": 0.05, "cue_placement": "kitchen"} if env_id != "BilliardsOneBall-v0" \
        else {"angle_noise": 0.02, "speed_noise": 0.05}
    a = rollout(gym.make(env_id, **kw), 11, actions)
    b = rollout(gym.make(env_id, **kw), 11, actions)
    assert all(same(x, y) for x, y in zip(a, b))
    c = rollout(gym.make(env_id, **kw), 12, actions)
    assert not all(same(x, y) for x, y in zip(a, c)), "another seed gives another episode"


def test_random_placement_respects_margins():
    env = gym.make("BilliardsThreeBalls-v0").unwrapped
    c = env.config
    for seed in range(50):
        env.reset(seed=seed)
        p = env.balls.pos
        m = c.ball_radius + c.cushion_margin
        assert np.all(p[:, 0] >= m - 1e-12) and np.all(p[:, 0] <= env.table.length - m + 1e-12)
        assert np.all(p[:, 1] >= m - 1e-12) and np.all(p[:, 1] <= env.table.width - m + 1e-12)
        d_pocket = np.linalg.norm(p[:, None] - env.table.pocket_xy[None], axis=-1)
        assert d_pocket.min() >= c.pocket_margin
        d = np.linalg.norm(p[:, None] - p[None], axis=-1) + np.eye(len(p)) * 9
        assert d.min() >= 2 * c.ball_radius + c.ball_gap
    seen = {tuple(np.round(gym.make("BilliardsThreeBalls-v0").reset(seed=s)[0], 6)) for s in range(5)}
    assert len(seen) == 5


def test_noise_changes_outcomes_and_is_seeded():
    pos, angle, speed = corner_pot_scene()
    env = gym.make("BilliardsOneBall-v0", angle_noise=0.05).unwrapped
    angles = []
    for seed in (0, 1, 2):
        env.reset(seed=seed, options={"positions": pos})
        angles.append(env.step(env.action_from_shot(angle, speed))[4]["angle"])
    assert len(set(angles)) == 3 and all(abs(a - angle) < 0.5 for a in angles)
    env.reset(seed=0, options={"positions": pos})
    assert env.step(env.action_from_shot(angle, speed))[4]["angle"] == angles[0]


# --- actions --------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("bad", [[np.nan, 0.0], [0.0, np.inf], [-np.inf, 1.0]])
def test_non_finite_actions_raise(bad):
    env = gym.make("BilliardsOneBall-v0").unwrapped
    env.reset(seed=0)
    with pytest.raises(ValueError, match="finite"):
        env.step(np.array(bad, dtype=np.float32))


def test_malformed_actions_raise():
    env = gym.make("BilliardsOneBall-v0").unwrapped
    env.reset(seed=0)
    for bad in ([0.1], [0.1, 0.2, 0.3], "left"):
        with pytest.raises(ValueError, match="action"):
            env.step(bad)


def test_out_of_range_actions_are_clipped():
    a = gym.make("BilliardsOneBall-v0").unwrapped
    b = gym.make("BilliardsOneBall-v0").unwrapped
    a.reset(seed=5)
    b.reset(seed=5)
    oa = a.step(np.array([3.0, -7.0], dtype=np.float32))
    ob = b.step(np.array([1.0, -1.0], dtype=np.float32))
    assert np.array_equal(oa[0], ob[0]) and oa[4]["speed"] == a.config.speed_min
    assert a.shot_from_action([-2.0, 2.0]) == b.shot_from_action([-1.0, 1.0])


@pytest.mark.parametrize("aim", ["absolute", "relative"])
def test_action_from_shot_inverts_the_mapping(aim):
    env = gym.make("BilliardsThreeBalls-v0", action_type=aim).unwrapped
    env.reset(seed=2)
    for angle, speed in [(0.3, 1.0), (-2.9, 4.5), (3.1, 0.5), (7.0, 2.0)]:
        got_angle, got_speed = env.shot_from_action(env.action_from_shot(angle, speed))[:2]
        assert math.cos(got_angle - angle) == pytest.approx(1.0, abs=1e-10)
        assert got_speed == pytest.approx(speed, rel=1e-6)
    # A policy's action is clipped; a programmer's argument out of range is refused with the range.
    assert env.shot_from_action([0.0, 7.0])[1] == pytest.approx(env.config.speed_max)
    with pytest.raises(ValueError, match=r"speed 99.0 m/s is outside this env's range \[0.5, 5.0\]"):
        env.action_from_shot(0.0, 99.0)


def test_relative_aim_zero_hits_the_target_full():
    pos = np.array([[0.6, 0.5], [1.4, 0.8]])
    env = gym.make("BilliardsOneBall-v0", action_type="relative").unwrapped
    env.reset(seed=0, options={"positions": pos})
    angle = env.shot_from_action([0.0, 0.0]).angle
    assert angle == pytest.approx(math.atan2(0.3, 0.8))
    info = env.step(np.array([0.0, 0.0], dtype=np.float32))[4]
    assert info["first_contact"] == 1 and env.info_words(info)["first_contact"] == "1"  # row 1: ball "1"
    absolute = gym.make("BilliardsOneBall-v0").unwrapped
    absolute.reset(seed=0, options={"positions": pos})
    assert absolute.shot_from_action([0.0, 0.0])[0] == 0.0


# --- rewards and episode ends ---------------------------------------------------------------------------------
def test_potting_the_object_ball_succeeds():
    pos, angle, speed = corner_pot_scene()
    env = gym.make("BilliardsOneBall-v0").unwrapped
    env.reset(seed=0, options={"positions": pos})
    obs, reward, terminated, truncated, info = env.step(env.action_from_shot(angle, speed))
    assert info["pocketed"].tolist() == [False, True] and not info["scratch"] and info["first_contact"] == 1
    assert reward == env.config.pot_reward and terminated and not truncated and info["is_success"]
    assert obs[5] == 1.0 and obs[2] == 0.0 and obs[3] == 0.0 and obs[4] == 0.0  # flags, zeroed position
    assert not env.balls.on_table[1] and info["status"] == 0
    words = env.info_words(info)
    assert words["pocketed"] == ("1",) and words["first_contact"] == "1" and words["status"] == "rest"


def test_scratch_is_penalised_and_the_cue_ball_respotted():
    pos, angle, speed = scratch_scene()
    env = gym.make("BilliardsOneBall-v0", scratch_penalty=0.7, miss_penalty=0.2).unwrapped
    env.reset(seed=0, options={"positions": pos})
    obs, reward, terminated, truncated, info = env.step(env.action_from_shot(angle, speed))
    assert info["scratch"] and info["pocketed"].tolist() == [True, False] and info["first_contact"] == -1
    assert env.info_words(info)["pocketed"] == ("cue",) and env.info_words(info)["first_contact"] is None
    assert reward == pytest.approx(-0.7 - 0.2) and not info["is_success"] and terminated
    assert env.balls.on_table[0] and np.allclose(env.balls.pos[0], (L / 4, W / 2))  # head spot
    assert obs[4] == 0.0 and obs[0] == pytest.approx(0.25) and obs[1] == pytest.approx(0.5)


def test_scratch_respots_beside_a_ball_on_the_head_spot():
    pos, angle, speed = scratch_scene()
    pos[1] = (L / 4, W / 2)  # ball 1 sits on the head spot
    env = gym.make("BilliardsOneBall-v0").unwrapped
    env.reset(seed=0, options={"positions": pos})
    info = env.step(env.action_from_shot(angle, speed))[4]
    assert info["scratch"]
    cue = env.balls.pos[0]
    r = env.config.ball_radius
    assert cue[0] == pytest.approx(L / 4)  # on the head string
    gap = np.linalg.norm(cue - env.balls.pos[1])
    assert 2 * r <= gap <= 2 * r + r / 4 + 1e-6  # the nearest free point


def test_miss_and_step_penalties():
    pos = np.array([[0.6, 0.6], [2.0, 0.3]])
    env = gym.make("BilliardsOneBall-v0", miss_penalty=0.3, step_penalty=0.05).unwrapped
    env.reset(seed=0, options={"positions": pos})
    # straight up at low speed: touches no ball and no pocket
    _, reward, *_, info = env.step(env.action_from_shot(math.pi / 2, 0.6))
    assert info["first_contact"] == -1 and not info["pocketed"].any()
    assert reward == pytest.approx(-0.35)


def test_multi_shot_episode_terminates_when_cleared_and_truncates_at_the_limit():
    env = gym.make("BilliardsThreeBalls-v0", max_shots=2).unwrapped
    pos = np.array([[L - 0.8, W - 0.8], [L - 0.35, W - 0.35], [1.0, 0.3], [1.5, 0.3]])
    env.reset(seed=0, options={"positions": pos, "pocketed": [False, False, True, True]})
    obs, reward, terminated, truncated, info = env.step(env.action_from_shot(math.pi / 4, 2.0))
    assert env.info_words(info)["pocketed"] == ("1",) and info["pocketed"].shape == (4,)
    assert reward == 1.0 and terminated and not truncated and info["is_success"]
    assert np.array_equal(obs[8:], [0, 1, 1, 1])

    env.reset(seed=0, options={"positions": pos})
    soft = env.action_from_shot(-math.pi / 2, 0.5)  # a soft shot away from every ball
    out1 = env.step(soft)
    assert not out1[2] and not out1[3] and out1[4]["shots"] == 1
    out2 = env.step(soft)
    assert not out2[2] and out2[3] and not out2[4]["is_success"]  # truncated by the shot limit


# --- the fast path is the simulator ---------------------------------------------------------------------------
@pytest.mark.parametrize("env_id", POT_IDS)  # (a game's step also plays the opponent's reply)
def test_fast_step_matches_simulator_run(env_id):
    """``step`` runs the exact kernel in place; the result equals ``Simulator.run`` on the same shot."""
    env = gym.make(env_id).unwrapped
    rng = np.random.default_rng(0)
    env.reset(seed=4)
    for _ in range(3):
        before = env.balls.copy()
        action = rng.uniform(-1, 1, 2).astype(np.float32)
        angle, speed = env.shot_from_action(action)[:2]
        ref = Simulator(env.table, env.physics, max_time=env.config.max_time,
                        max_events=env.config.max_events).run(before.strike(0, angle, speed))
        _, _, term, trunc, info = env.step(action)
        assert info["n_events"] == ref.n_events and info["sim_time"] == ref.time
        assert env.info_schema["status"].names[info["status"]] == ref.status
        assert np.flatnonzero(info["pocketed"]).tolist() == list(ref.newly_pocketed)
        assert info["first_contact"] == ref.first_contact(0)
        objects = slice(1, None)
        assert np.array_equal(env.balls.pos[objects], ref.balls.pos[objects])
        assert np.array_equal(env.balls.on_table[objects], ref.balls.on_table[objects])
        if not info["scratch"]:
            assert np.array_equal(env.balls.pos[0], ref.balls.pos[0])
        if term or trunc:
            break


def test_step_solver_and_render_path_agree_with_fast_path():
    actions = np.random.default_rng(3).uniform(-1, 1, (3, 2)).astype(np.float32)
    fast = rollout(gym.make("BilliardsThreeBalls-v0"), 9, actions)
    recorded = rollout(gym.make("BilliardsThreeBalls-v0", render_mode="rgb_array_list", render_width=64,
                                render_speedup=1000.0), 9, actions)
    assert all(same(x, y) for x, y in zip(fast, recorded))
    env = gym.make("BilliardsOneBall-v0", solver="step")
    env.reset(seed=0)
    obs, reward, *_ = env.step(np.array([0.2, 0.0], dtype=np.float32))
    assert env.observation_space.contains(obs) and isinstance(reward, float)


def test_reset_options_are_validated():
    env = gym.make("BilliardsOneBall-v0").unwrapped
    with pytest.raises(ValueError, match="shape"):
        env.reset(options={"positions": [[0.5, 0.5]]})
    with pytest.raises(ValueError, match="overlap"):
        env.reset(options={"positions": [[0.5, 0.5], [0.51, 0.5]]})
    with pytest.raises(ValueError, match="unknown"):
        env.reset(options={"balls": 3})
    with pytest.raises(ValueError, match="cue ball"):
        env.reset(options={"positions": [[0.5, 0.5], [1.0, 0.5]], "pocketed": [True, False]})


def test_live_state_for_players():
    env = gym.make("BilliardsThreeBalls-v0").unwrapped
    env.reset(seed=0)
    assert isinstance(env.balls, Balls) and env.balls.ids == ("cue", "1", "2", "3")
    balls = env.balls
    before = balls.pos.copy()
    env.step(np.array([0.0, 1.0], dtype=np.float32))
    assert env.balls is balls and not np.array_equal(before, balls.pos)  # updated in place
    assert env.shots == 1 and env.last_shot is not None and np.all(env.balls.vel == 0)
    trial = env.simulator.run(env.balls.strike(0, 0.0, 1.0), validate=False)  # players can try shots
    assert trial.status == "rest"


def test_step_takes_the_compiled_fast_path(monkeypatch):
    """``step`` runs the compiled kernel on the live arrays: no validation and no ``Simulator.run`` (result
    objects, copies) in the hot path. (Its speed is measured by the benchmarks, not asserted here.)"""
    import billiards_env.envs.base as base

    def forbidden(*args, **kwargs):
        raise AssertionError("the fast path must not call this")

    env = gym.make("BilliardsOneBall-v0").unwrapped
    env.reset(seed=0)
    monkeypatch.setattr(Simulator, "run", forbidden)
    monkeypatch.setattr(base, "validate_balls", forbidden)
    for a in np.random.default_rng(0).uniform(-1, 1, (20, 2)).astype(np.float32):
        env.step(a)
        env.reset()


def test_step_before_reset_raises():
    env = gym.make("BilliardsOneBall-v0").unwrapped
    with pytest.raises(gym.error.ResetNeeded):
        env.step(np.zeros(2, np.float32))
