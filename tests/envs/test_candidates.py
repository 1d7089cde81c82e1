"""The 'candidates' action and observation types (choose one of the (ball, pocket) shots, play it for position)
and the games' 'ball_in_hand' opening (run-out practice)."""
from __future__ import annotations

import math
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import billiards_env  # noqa: E402,F401
from billiards_env.envs.actions import PLACE_BACK, PLACE_MAX_CUT
from billiards_env.envs.candidates import candidate_slots
from billiards_env.envs.config import ConfigError
from billiards_env.envs.observations import SLOT_FEATURES
from billiards_env.physics.aim import aim_angle, direction_vector
from billiards_env.physics.layout import head_string_x
from billiards_env.players import make_player, shot_context
from billiards_env.players.geometric import geometric_shot

CAND = {"action_type": "candidates", "observation_type": "candidates"}


def after_break(seed: int = 0, **kw):
    env = gym.make("Billiards9Ball-v0", opening="ball_in_hand", opponent=None, **{**CAND, **kw})
    env.reset(seed=seed)
    return env


def test_ball_in_hand_opening_breaks_for_nobody_and_gives_ball_in_hand_anywhere():
    env = after_break(3)
    u = env.unwrapped
    s = u.task.game_state
    assert s.ball_in_hand == "anywhere" and not s.break_shot and s.shooter == 0 and not s.game_over
    assert u.balls.on_table[9] and u.balls.on_table[0]  # the 9 respotted if it dropped; the cue ball back
    moved = np.hypot(*(u.balls.pos[1:] - gym.make("Billiards9Ball-v0").unwrapped.balls.pos[1:]).T)
    on = u.balls.on_table[1:]
    rack = gym.make("Billiards9Ball-v0", opponent=None)
    rack.reset(seed=3)
    assert np.any(np.hypot(*(u.balls.pos[1:] - rack.unwrapped.balls.pos[1:]).T)[on] > 0.05)  # the rack broke
    assert u.last_shot is None and moved.shape == (9,)
    again = after_break(3)
    assert np.array_equal(again.unwrapped.balls.pos, u.balls.pos)  # seeded
    assert np.array_equal(again.unwrapped.balls.on_table, u.balls.on_table)
    # The two-player env: player_0 (first_shooter 'agent') has ball in hand; 'opponent' gives it to player_1.
    from billiards_env.multi import nine_ball_v0

    aec = nine_ball_v0.env(opening="ball_in_hand", first_shooter="opponent")
    aec.reset(seed=3)
    assert aec.agent_selection == "player_1" and aec.unwrapped.game_state.ball_in_hand == "anywhere"


def test_either_opening_draws_the_break_or_ball_in_hand():
    env = gym.make("Billiards9Ball-v0", opening="either", opponent=None)
    kinds = []
    for seed in range(12):
        env.reset(seed=seed)
        s = env.unwrapped.task.game_state
        kinds.append("break" if s.break_shot else s.ball_in_hand)
        again = gym.make("Billiards9Ball-v0", opening="either", opponent=None)
        again.reset(seed=seed)
        assert again.unwrapped.task.game_state == s  # drawn from the seeded np_random
    assert set(kinds) == {"break", "anywhere"}


def test_opening_is_for_games_only():
    with pytest.raises(ConfigError, match="opening"):
        gym.make("BilliardsOneBall-v0", opening="ball_in_hand")
    with pytest.raises(ConfigError, match="candidate_slots"):
        gym.make("Billiards9Ball-v0", candidate_slots=0)
    with pytest.raises(ConfigError, match="candidate_speed_factor"):
        gym.make("Billiards9Ball-v0", candidate_speed_factor=1.0)


def test_neutral_action_plays_the_geometric_players_shot():
    env = gym.make("Billiards9Ball-v0", opponent=None, **CAND)
    for seed in range(6):
        env.reset(seed=seed)
        env.step(env.unwrapped.action_from_shot(0.0, 8.0, place=(0.5, 0.64)))  # break
        u = env.unwrapped
        if u.task.game_state.ball_in_hand or u.task.game_state.game_over:
            continue
        angle, speed, cand = geometric_shot(shot_context(env))
        shot = u.shot_from_action(np.zeros(env.action_space.shape))
        if cand is None:
            continue
        assert (shot.angle, shot.speed) == (angle, speed)
        # a[1] scales the shot's speed by candidate_speed_factor ** a[1] (clipped to the speed range)
        a = np.zeros(env.action_space.shape)
        a[1] = 0.5
        assert u.shot_from_action(a).speed == pytest.approx(min(speed * math.sqrt(3.0), 8.0))
        return
    pytest.fail("no table after the break with a candidate shot")


def test_slots_are_chosen_by_the_aim_dim_and_round_trip():
    env = after_break(1)
    u = env.unwrapped
    u.task.game_state = type(u.task.game_state)("nine_ball", u.task.game_state.on_table, shooter=0, ball_in_hand=False,
                                      break_shot=False)  # play from where it lies
    cands = candidate_slots(u.table_state, 4)
    assert not cands.in_hand and 1 <= len(cands.slots) <= 3  # the last of the 4 slots is the kick's
    for k, slot in enumerate(cands.slots):
        a = np.zeros(env.action_space.shape)
        a[0] = (k + 0.5) / 4 * (-1 if k % 2 else 1)  # |a| picks the slot; the sign does not matter
        shot = u.shot_from_action(a)
        assert shot.angle == slot.shot.angle and shot.speed == slot.shot.speed
        back = u.action_from_shot(slot.shot.angle, slot.shot.speed * 2.0)
        again = u.shot_from_action(back)
        assert again.angle == slot.shot.angle and again.speed == pytest.approx(slot.shot.speed * 2.0)
    a = np.zeros(env.action_space.shape)
    a[0] = 0.7  # past the end of a short list: its last slot
    assert u.shot_from_action(a).angle == cands.slots[min(2, len(cands.slots) - 1)].shot.angle
    a[0] = 1.0  # the kick slot: the kick if there is one, else the easiest pot
    want = cands.kick.shot.angle if cands.kick is not None else cands.slots[0].shot.angle
    assert u.shot_from_action(a).angle == want


def test_a_blocked_ball_is_kicked_at_off_a_cushion():
    env = gym.make("Billiards9Ball-v0", opponent=None, friction="spin", spin_action=True, **CAND)
    pos = np.array([[0.5, 0.35], [1.5, 0.35], [1.0, 0.35]] + [[0.3 + 0.1 * k, 1.2] for k in range(7)])
    off = np.array([False, False, False] + [True] * 7)
    env.reset(seed=0, options={"positions": pos, "pocketed": off})
    u = env.unwrapped
    cands = candidate_slots(u.table_state, 4)
    assert cands.kick is not None and cands.kick.target == 1 and cands.kick.pocket == -1
    assert all(not s.shot.clear for s in cands.slots)  # every pot goes through the 2
    obs = u.observe()
    kick_row = obs[30 + 3 * SLOT_FEATURES:30 + 4 * SLOT_FEATURES]
    assert kick_row[0] == 1.0 and kick_row[2] == kick_row[3] == -1.0
    a = np.zeros(env.action_space.shape)
    a[0] = -1.0
    a[1], a[2], a[3] = 0.8, 0.9, -0.9  # the kick is played as verified: power and tip ignored
    shot = u.shot_from_action(a)
    assert (shot.angle, shot.speed, shot.side, shot.top) == (cands.kick.shot.angle, cands.kick.shot.speed, 0.0, 0.0)
    _, _, _, _, info = env.step(a)
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert w["first_contact"] == "1" and w["foul_reason"] != "wrong ball first"
    # A pot instead hits the 2 first.
    env.reset(seed=0, options={"positions": pos, "pocketed": off})
    _, _, _, _, info = env.step(np.zeros(env.action_space.shape))
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert w["first_contact"] == "2" and w["foul_reason"] == "wrong ball first"


def test_ball_in_hand_places_the_cue_ball_behind_the_chosen_ghost_ball():
    env = after_break(2)
    u = env.unwrapped
    cands = candidate_slots(u.table_state, 4)
    assert cands.in_hand and cands.slots
    slot = cands.slots[0]
    ghost = slot.ghost(2 * u.config.ball_radius, u.balls.pos)
    for px, py in ((0.0, 0.0), (-1.0, 0.5), (0.6, -0.3)):
        a = np.zeros(env.action_space.shape)
        a[2], a[3] = px, py
        shot = u.shot_from_action(a)
        back = PLACE_BACK[0] + (px + 1) / 2 * (PLACE_BACK[1] - PLACE_BACK[0])
        want = ghost - back * direction_vector(slot.obj_angle + py * PLACE_MAX_CUT)
        want = u.legal_cue_position(*want)
        assert shot.place == pytest.approx(want)
        assert shot.angle == pytest.approx(aim_angle(np.asarray(shot.place), ghost), abs=1e-9)
    # The window ranking: widest first among clear paths.
    halves = [s.half for s in cands.slots if s.clear_obj]
    assert halves == sorted(halves, reverse=True)


def test_the_break_is_a_full_hit_and_neutral_is_the_geometric_break():
    env = gym.make("Billiards9Ball-v0", opponent=None, **CAND)
    env.reset(seed=0)
    u = env.unwrapped
    shot = u.shot_from_action(np.zeros(env.action_space.shape))
    from billiards_env.players.geometric import break_shot

    place, angle, speed = break_shot(shot_context(env))
    assert shot.place == pytest.approx(place) and shot.angle == pytest.approx(angle) and shot.speed == speed
    a = np.zeros(env.action_space.shape)
    a[1], a[2], a[3] = -1.0, -1.0, 0.5
    shot = u.shot_from_action(a)
    assert shot.speed == pytest.approx(u.config.speed_max / 3.0) and shot.place[0] < head_string_x(u.table) - 0.3
    assert shot.angle == pytest.approx(aim_angle(np.asarray(shot.place), u.balls.pos[1]))
    back = u.shot_from_action(u.action_from_shot(shot.angle, shot.speed, place=shot.place))
    assert back.place == pytest.approx(shot.place) and back.speed == pytest.approx(shot.speed)


def test_observation_describes_the_slots():
    env = after_break(4, candidate_slots=3)
    u = env.unwrapped
    obs = u.observe()
    assert env.observation_space.shape == (30 + 3 * SLOT_FEATURES + 11,) and env.observation_space.contains(obs)
    slots = obs[30:30 + 3 * SLOT_FEATURES].reshape(3, SLOT_FEATURES)
    cands = candidate_slots(u.table_state, 3)
    assert slots[:, 0].tolist() == [1.0 if k < len(cands.slots) else 0.0 for k in range(3)]
    s0 = cands.slots[0]
    assert slots[0, 1] == pytest.approx(s0.target / 15) and slots[0, 2] == pytest.approx(
        u.table.pocket_xy[s0.pocket, 0] / u.table.length)
    assert slots[0, 4] == 0.0 and slots[0, 11] == 0.0  # in hand: no cue-dependent values


def test_a_player_opponent_plays_its_own_shots_against_a_candidates_agent():
    class Spy:
        name = "spy"

        def __init__(self):
            self.inner = make_player("geometric")
            self.asked = []

        def reset(self, seed=None):
            self.inner.reset(seed)

        def shot(self, state, obs=None, codec=None):
            s = self.inner.shot(state, obs, codec)
            self.asked.append(s)
            return s

    env = gym.make("Billiards9Ball-v0", opponent=None, first_shooter="opponent", **CAND)
    spy = Spy()
    env.unwrapped.set_opponent(spy)
    env.reset(seed=5)
    assert spy.asked  # it broke
    played = env.unwrapped.last_shot
    assert played is not None and played[2] == pytest.approx(spy.asked[-1].angle)
    assert played[3] == pytest.approx(spy.asked[-1].speed)


def test_candidates_on_the_pot_task_take_the_python_path():
    env = gym.make("BilliardsThreeBalls-v0", **CAND)
    obs, _ = env.reset(seed=0)
    assert env.unwrapped._pot_fast is None and env.observation_space.contains(obs)
    total = 0.0
    for _ in range(5):
        obs, r, term, trunc, info = env.step(np.zeros(2))
        total += r
        if term or trunc:
            break
    assert total >= 1.0  # the easiest shots pot on an open table
    vec = gym.make_vec("BilliardsThreeBalls-v0", num_envs=2, **CAND)
    assert not vec.native
    vec.reset(seed=0)
    vec.step(np.zeros((2, 2)))


def test_position_reward_pays_for_the_next_shot_after_a_kept_turn():
    from billiards_env.envs.candidates import next_shot_ease

    kw = dict(opponent=None, opening="ball_in_hand", pot_reward=1.0, foul_penalty=0.5, **CAND)
    plain = gym.make("Billiards9Ball-v0", **kw)
    shaped = gym.make("Billiards9Ball-v0", position_reward=2.0, **kw)
    seen = set()
    for seed in range(12):
        plain.reset(seed=seed)
        shaped.reset(seed=seed)
        for _ in range(4):
            a = np.zeros(plain.action_space.shape)
            _, r0, t0, _, info = plain.step(a)
            _, r1, t1, _, _ = shaped.step(a)
            kept = not info["turn_over"] and not t0
            if kept:
                ease = next_shot_ease(shaped.unwrapped.table_state, shaped.unwrapped.config.candidate_slots)
                assert 0.0 <= ease <= 1.0 and r1 == pytest.approx(r0 + 2.0 * ease)
                seen.add("kept")
            else:
                assert r1 == r0  # a miss, a foul or the end: no position term
                seen.add("lost")
            if t0:
                break
    assert seen == {"kept", "lost"}


@pytest.mark.parametrize("env_id", ["Billiards9Ball-v0", "Billiards8Ball-v0"])
def test_observation_values_equal_the_python_loop(env_id, golden):
    """The compiled slot values (envs/candidates.py ``slot_features``) equal the Python loop they replaced
    (``benchmarks/reference_players.py``, through its recorded results: the ``golden`` fixture), bit for bit: the
    cue ball where it lies, in hand, the break, kicks (a hidden ball), 1 to 6 slots."""
    from golden import reference_players

    from billiards_env.envs.candidates import slot_features

    env = gym.make(env_id, opening="either", opponent="geometric", **CAND)
    u = env.unwrapped
    rng = np.random.default_rng(4)
    seen = {"hand": 0, "kick": 0, "pots": 0, "break": 0}
    for seed in range(8):
        obs, _ = env.reset(seed=seed)
        for _ in range(6):
            for n in (1, 4, 6):
                cands = candidate_slots(u.table_state, n, u.action_type.speed_range)
                got = slot_features(u.table_state, cands, n, u.config.speed_max)
                golden.check(got, lambda: reference_players().reference_slot_values(u.table_state, cands, n,
                                                                                      u.config.speed_max),
                             same=lambda a, b: a.dtype == b.dtype and np.array_equal(a, b))
                seen["break" if cands.break_shot else "hand" if cands.in_hand else "pots"] += 1
                seen["kick"] += cands.kick is not None
            obs, _, term, trunc, _ = env.step(rng.uniform(-1, 1, env.action_space.shape).astype(np.float32))
            if term or trunc:
                break
    # A hidden 1 (every pot goes through the 2): the kick's values.
    env9 = gym.make("Billiards9Ball-v0", opponent=None, **CAND)
    pos = np.array([[0.5, 0.35], [1.5, 0.35], [1.0, 0.35]] + [[0.3 + 0.1 * k, 1.2] for k in range(7)])
    env9.reset(seed=0, options={"positions": pos, "pocketed": np.array([False] * 3 + [True] * 7)})
    cands = candidate_slots(env9.unwrapped.table_state, 4)
    assert cands.kick is not None
    golden.check(slot_features(env9.unwrapped.table_state, cands, 4, 5.0),
                 lambda: reference_players().reference_slot_values(env9.unwrapped.table_state, cands, 4, 5.0),
                 same=lambda a, b: a.dtype == b.dtype and np.array_equal(a, b))
    assert seen["hand"] and seen["pots"] and seen["break"], seen
