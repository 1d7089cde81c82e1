"""The game envs (Billiards9Ball-v0, Billiards8Ball-v0): scripted tables played through env.step, checked
against the rules' calls; ball in hand; the called 8; the players following the rules."""
from __future__ import annotations

import math
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import billiards_env  # noqa: E402,F401
from billiards_env.physics.layout import foot_spot, head_string_x  # noqa: E402
from billiards_env.players import make_player  # noqa: E402

L, W, R = 2.54, 1.27, 0.028575
PARKED = [(0.3 + 0.1 * k, 0.1) for k in range(15)]  # out of the way along the bottom cushion
TOP_RIGHT = 5  # pocket index (L, W)


def table(n_balls: int, cue: tuple[float, float], placed: dict[int, tuple[float, float]]):
    """Positions (rows cue, 1..n) and pocketed flags: the balls in ``placed`` where given, the others pocketed."""
    pos = np.array([cue] + PARKED[:n_balls], dtype=float)
    off = np.ones(n_balls + 1, dtype=bool)
    off[0] = False
    for number, xy in placed.items():
        pos[number] = xy
        off[number] = False
    return pos, off


def corner_pot(env, number: int, speed: float = 1.2):
    """Ball ``number`` 0.2 m from the top-right pocket on the diagonal, the cue 0.4 m behind it: the action that
    pots it straight (a stun-like stop of the cue ball)."""
    return env.unwrapped.action_from_shot(math.pi / 4, speed)


DIAG_BALL = (L - 0.25, W - 0.25)
DIAG_CUE = (L - 0.65, W - 0.65)


def test_nine_ball_legal_pot_keeps_the_turn_and_the_nine_wins():
    env = gym.make("Billiards9Ball-v0", opponent="geometric")
    pos, off = table(9, DIAG_CUE, {1: DIAG_BALL, 9: (0.6, 0.7)})
    env.reset(seed=0, options={"positions": pos, "pocketed": off})
    obs, reward, terminated, truncated, info = env.step(corner_pot(env, 1))
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert w["pocketed"] == ("1",) and not info["foul"] and not info["turn_over"]
    assert info["opponent_shots"] == 0 and info["shooter"] == 0 and w["legal_targets"] == ("9",)
    assert np.flatnonzero(info["legal_targets"]).tolist() == [9]  # a mask over the rows
    assert (reward, terminated) == (0.0, False)
    # Now the 9 alone: put it on the diagonal and pot it legally -> the agent wins.
    pos2 = env.unwrapped.balls.pos.copy()
    pos2[0], pos2[9] = DIAG_CUE, DIAG_BALL
    env.unwrapped.balls.pos[...] = pos2
    obs, reward, terminated, truncated, info = env.step(corner_pot(env, 9))
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert terminated and info["winner"] == 0 and info["is_success"] and w["call"] == "9 pocketed"
    assert reward == pytest.approx(1.0)
    with pytest.raises(gym.error.ResetNeeded):
        env.step(env.action_space.sample())


def test_nine_ball_wrong_ball_first_is_a_foul_with_ball_in_hand_for_the_opponent():
    env = gym.make("Billiards9Ball-v0", opponent=None)  # alone: the episode ends at the first foul
    pos, off = table(9, DIAG_CUE, {1: (0.5, 0.3), 2: DIAG_BALL, 9: (0.6, 0.9)})
    env.reset(seed=0, options={"positions": pos, "pocketed": off})
    obs, reward, terminated, truncated, info = env.step(corner_pot(env, 2))
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert w["first_contact"] == "2" and info["foul"] and w["foul_reason"] == "wrong ball first"
    assert terminated and info["winner"] == -1 and reward == 0.0
    assert w["ball_in_hand"] == "anywhere" and info["shooter"] == 1
    assert not env.unwrapped.balls.on_table[2]  # balls pocketed on a foul stay down (all but the 9)


def test_the_nine_pocketed_on_a_foul_is_respotted_on_the_foot_spot():
    env = gym.make("Billiards9Ball-v0", opponent=None)
    pos, off = table(9, DIAG_CUE, {3: (0.4, 1.0), 9: DIAG_BALL})
    env.reset(seed=0, options={"positions": pos, "pocketed": off})
    obs, reward, terminated, truncated, info = env.step(corner_pot(env, 9))
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert w["pocketed"] == ("9",) and w["foul_reason"] == "wrong ball first"
    u = env.unwrapped
    assert u.balls.on_table[9] and np.allclose(u.balls.pos[9], foot_spot(u.table))


def test_ball_in_hand_placement_moves_to_the_nearest_legal_point():
    env = gym.make("Billiards9Ball-v0", opponent=None)
    pos, off = table(9, (0.5, 0.5), {1: (1.5, 0.6), 9: (2.0, 0.9)})
    env.reset(seed=0, options={"positions": pos, "pocketed": off, "ball_in_hand": "anywhere"})
    u = env.unwrapped
    target = (1.5 + 0.01, 0.6)  # on top of the 1
    action = u.action_from_shot(0.0, 1.0, place=target)
    shot = u.shot_from_action(action)
    d = math.dist(shot.place, (1.5, 0.6))
    assert d >= 2 * R and d == pytest.approx(2 * R, abs=1e-5)  # just off the ball, on the side asked for
    assert shot.place[0] > 1.5
    # A programmer's place off the table is refused with the area.
    with pytest.raises(ValueError, match="outside the ball-in-hand area"):
        u.action_from_shot(0.0, 1.0, place=(5.0, -1.0))
    # A policy's placement dims beyond the box are clipped to the area's corner (L - R, R). On the jaw table (the
    # game's) that point is on the table, clear of the jaws and of the pocket circle behind the mouth: kept.
    assert u.table.has_jaws
    shot = u.shot_from_action(np.array([0.0, 0.0, 3.0, -3.0], np.float32))
    assert shot.place == pytest.approx((L - R, R), abs=1e-12)
    # On a capture table it lies inside the corner's capture circle, so the cue ball goes on to the nearest point
    # just outside the circle (radially out from the pocket).
    env = gym.make("Billiards9Ball-v0", opponent=None, table={"preset": "pool"})
    env.reset(seed=0, options={"positions": pos, "pocketed": off, "ball_in_hand": "anywhere"})
    u = env.unwrapped
    shot = u.shot_from_action(np.array([0.0, 0.0, 3.0, -3.0], np.float32))
    x, y = shot.place
    corner = int(np.argmin(np.hypot(u.table.pocket_xy[:, 0] - L, u.table.pocket_xy[:, 1])))
    gap = math.dist((x, y), u.table.pocket_xy[corner]) - u.table.pocket_radius[corner]
    assert 0.0 < gap < 1e-5
    px, py = u.table.pocket_xy[corner]
    assert math.atan2(y - py, x - px) == pytest.approx(math.atan2(R - py, L - R - px), abs=1e-9)
    assert R <= y and x <= L - R


def test_break_ball_in_hand_is_behind_the_head_string():
    env = gym.make("Billiards9Ball-v0")
    env.reset(seed=3)
    u = env.unwrapped
    assert u.task.game_state.break_shot and u.table_state.view.place_area[1] == pytest.approx(head_string_x(u.table))
    shot = u.shot_from_action(np.array([0.0, 1.0, 1.0, 0.0], dtype=np.float32))  # place_x = +1: the far edge
    assert shot.place[0] <= head_string_x(u.table) + 1e-12


def test_action_round_trip_with_placement_and_called_pocket():
    env = gym.make("Billiards8Ball-v0", opponent=None)
    env.reset(seed=1)
    u = env.unwrapped
    place = (0.4, 0.5)
    for pocket in range(6):
        shot = u.shot_from_action(u.action_from_shot(0.7, 3.0, place=place, pocket=pocket))
        assert shot.call("pocket") == pocket and shot.place == pytest.approx(place, abs=1e-6)
        assert math.cos(shot.angle - 0.7) == pytest.approx(1.0, abs=1e-8) and shot.speed == pytest.approx(3.0)


@pytest.mark.parametrize("called, wins", [(TOP_RIGHT, True), (0, False)])
def test_eight_ball_called_pocket_decides_the_game(called, wins):
    env = gym.make("Billiards8Ball-v0", opponent="geometric")
    pos, off = table(15, DIAG_CUE, {8: DIAG_BALL, 9: (0.6, 0.7)})
    env.reset(seed=0, options={"positions": pos, "pocketed": off, "groups": ("solids", "stripes")})
    u = env.unwrapped
    assert u.table_state.view.call_pocket  # solids cleared: on the 8
    obs, reward, terminated, truncated, info = env.step(u.action_from_shot(math.pi / 4, 1.2, pocket=called))
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert terminated and w["pocketed"] == ("8",)
    assert info["winner"] == (0 if wins else 1)
    assert reward == pytest.approx(1.0 if wins else -1.0)
    assert w["call"] == ("8 pocketed" if wins else "8 in an uncalled pocket")


def test_opponent_replies_inside_step_and_game_features_follow_the_state():
    env = gym.make("Billiards9Ball-v0", opponent="geometric")
    pos, off = table(9, (0.3, 0.2), {1: (1.3, 1.1), 9: (2.0, 0.4)})
    obs, _ = env.reset(seed=0, options={"positions": pos, "pocketed": off})
    u = env.unwrapped
    # A miss that touches nothing: a foul, the opponent replies with ball in hand and shoots until it misses or wins.
    obs, reward, terminated, truncated, info = env.step(u.action_from_shot(-math.pi / 2, 0.6))
    w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
    assert w["foul_reason"] == "no contact" and info["opponent_shots"] >= 1
    assert terminated == (info["winner"] != -1)
    if not terminated:
        feats = obs[-11:]
        assert feats[10] == 1.0  # the agent's turn
        assert feats[3] == pytest.approx(min(u.task.game_state.on_table) / 15.0)


@pytest.mark.parametrize("game", ["Billiards9Ball-v0", "Billiards8Ball-v0"])
@pytest.mark.parametrize("player", ["geometric", "search"])
def test_players_follow_the_rules(game, player):
    """The baselines hit a legal ball first (the geometric player: with its clear shots), place ball in hand legally,
    and break from the kitchen."""
    env = gym.make(game, opponent="geometric", first_shooter="agent")
    p = make_player(player, seed=0)
    u = env.unwrapped
    fouls = wrong = placed = 0
    for seed in range(2 if player == "search" else 4):
        obs, _ = env.reset(seed=seed)
        for _ in range(4):
            legal = {str(n) for n in u.task.rules.legal_targets(u.task.game_state)}
            area = u.table_state.view.place_area
            action = p.act(env, obs)
            if area is not None:
                place = u.shot_from_action(action).place
                x0, x1, y0, y1 = area
                assert x0 <= place[0] <= x1 and y0 <= place[1] <= y1
                others = [u.balls.pos[i] for i in range(1, u.n_balls) if u.balls.on_table[i]]
                assert all(math.dist(place, q) >= 2 * R for q in others)
                placed += 1
            # The geometric player plays a shot whose path another ball blocks (scored down) when no clear one is
            # left, or its fallback full-ball hit when nothing pots, and a ball in the way may take those first (it
            # does not kick); its clear shots, and every search shot, hit a legal ball first.
            fallback = player == "geometric" and (p.last is None or not p.last.clear)
            obs, reward, terminated, truncated, info = env.step(action)
            fouls += info["foul"]
            w = env.unwrapped.info_words(info)  # the balls as ids, the codes as names
            wrong += w["first_contact"] is not None and w["first_contact"] not in legal and not fallback
            if terminated or truncated:
                break
    assert placed >= 1  # every game starts with ball in hand in the kitchen
    assert wrong == 0


def test_ball_in_hand_never_places_the_cue_ball_where_it_drops_at_once():
    """A placement inside a pocket's capture circle (a corner of the kitchen) moves to the nearest point outside it
    (a random policy's placement once scratched at t = 0), still inside the area and off the other balls."""
    env = gym.make("Billiards9Ball-v0")
    env.reset(seed=3)
    u = env.unwrapped
    t = u.table
    x0, x1, y0, y1 = u.table_state.view.place_area
    for px, py in ((0.0, 0.0), (0.0, W), (x0, y0 + 1e-3)):
        x, y = u.legal_cue_position(px, py)
        assert x0 <= x <= x1 and y0 <= y <= y1
        gaps = np.hypot(t.pocket_xy[:, 0] - x, t.pocket_xy[:, 1] - y) - t.pocket_radius
        assert gaps.min() > 0.0
        assert np.hypot(x - px, y - py) < 0.1  # moved just out of the circle, not far away
    action = u.action_from_shot(0.0, 2.0, place=(x0, y0))  # the area's corner: in the pocket's circle
    info = env.step(action)[4]
    assert info["sim_time"] > 0.0 and info["n_events"] >= 1  # the shot is played, not a drop at t = 0
