"""The search player simulates its candidates in batches (``physics/batch.py``): every candidate's outcome and
value equal those of its own ``Simulator.run``, so the player chooses what one-by-one simulation would choose."""
from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401
from billiards_env.players.context import shot_context
from billiards_env.players.search import simulate_candidates, candidate_value, search_shot


@pytest.mark.parametrize("env_id,seed", [("BilliardsThreeBalls-v0", 3), ("BilliardsOneBall-v0", 8),
                                         ("Billiards9Ball-v0", 1)])
def test_batch_values_equal_single_runs(env_id, seed):
    env = gym.make(env_id)
    env.reset(seed=seed)
    ctx = shot_context(env)
    rng = np.random.default_rng(seed)
    angles = rng.uniform(-math.pi, math.pi, 40)
    speeds = rng.uniform(*ctx.speed_range, 40)
    pots, scratch, hit, values, res = simulate_candidates(ctx, angles, speeds)
    for k in range(40):
        single = ctx.simulator.run(ctx.balls.strike(ctx.cue, angles[k], speeds[k]), validate=False)
        assert pots[k] == sum(1 for j in ctx.targets if single.pocket[j] >= 0)
        assert scratch[k] == (single.pocket[ctx.cue] >= 0)
        assert hit[k] == (single.first_contact(ctx.cue) >= 0)
        assert np.array_equal(res.pos[k], single.balls.pos)
        if ctx.game is None:
            assert values[k] == candidate_value(pots[k], scratch[k], hit[k])
    assert len(set(values.tolist())) > 1 or ctx.game is not None  # the candidates differ (a break may all foul)
    assert (res.first_contact >= 0).any()


def test_search_is_deterministic_and_plays_a_pot():
    env = gym.make("BilliardsOneBall-v0")
    env.reset(seed=2)
    ctx = shot_context(env)
    a1 = search_shot(ctx, None, np.random.default_rng(0))
    a2 = search_shot(ctx, None, np.random.default_rng(0))
    assert a1[:2] == a2[:2] and a1[2].value == a2[2].value
    _, _, _, info = env.step(env.unwrapped.action_from_shot(a1[0], a1[1]))[1:]
    assert env.unwrapped.info_words(info)["pocketed"] == ("1",)


def test_without_rules_a_miss_earns_no_position_and_never_outranks_a_pot():
    """One ball, no noise: on every table where the geometric player pots, the search's chosen shot pots unperturbed
    (its total counts the pot, not the ease of a next shot after a miss)."""
    from billiards_env.players import make_player

    env = gym.make("BilliardsOneBall-v0", speed_max=1.8)
    search, geometric = make_player("search"), make_player("geometric")
    checked = 0
    for seed in range(40):
        env.reset(seed=seed)
        geo_pots = env.step(geometric.act(env, None))[4]["is_success"]
        env.reset(seed=seed)
        info = env.step(search.act(env, None))[4]
        if geo_pots:
            checked += 1
            assert search.last.pots == 1 and search.last.total >= 1.0, seed
            assert info["is_success"], seed
    assert checked >= 30


def test_search_values_the_shots_a_ghost_action_can_play():
    """With ghost aim (only direct hits within ghost_max_angle), every candidate is mapped to the shot of its
    nearest action, so the shot searched is the shot played."""
    from billiards_env.players import make_player
    from billiards_env.players.search import playable_shots

    env = gym.make("BilliardsOneBall-v0", action_type="ghost", speed_max=1.8)
    player = make_player("search")
    for seed in range(6):
        env.reset(seed=seed)
        action = player.act(env, None)
        played = env.unwrapped.shot_from_action(action)
        assert played.angle == player.last.angle and played.speed == player.last.speed
        play = playable_shots(env.unwrapped.table_state, env.unwrapped.action_type)
        # A kick (cue line missing the object ball) cannot be expressed: it comes back as a direct hit.
        u = env.unwrapped
        cue, obj = u.balls.pos[0], u.balls.pos[1]
        away = math.atan2(cue[1] - obj[1], cue[0] - obj[0])
        (angle, speed, *_), = play([(away, 1.0, 0.0, 0.0, "kick")])
        assert abs(math.remainder(angle - away, 2 * math.pi)) > 1.0


def test_search_values_the_shot_its_float32_action_plays_in_a_game():
    """8-ball practice, absolute aim, no noise: the shot the search chose is the shot its float32 action plays,
    and what drops is what its simulation of that shot says, even for chaotic shots (a 1e-8 rad rounding of the
    cue angle can change which balls drop)."""
    from billiards_env.players import make_player

    env = gym.make("Billiards8Ball-v0", opponent=None)
    player = make_player("search", seed=0)
    checked = 0
    for seed in range(4):
        env.reset(seed=seed)
        for _ in range(4):
            u = env.unwrapped
            action = player.act(env, None)
            played = u.shot_from_action(action)
            expected = None
            if player.last is not None and played.place is None:
                assert (played.angle, played.speed) == (player.last.angle, player.last.speed)
                res = u.simulator.run(u.balls.strike(0, played.angle, played.speed), validate=False)
                expected = {u.balls.ids[i] for i in np.flatnonzero(res.pocket >= 0)}
            _, _, term, trunc, info = env.step(action)
            if expected is not None:
                assert set(u.info_words(info)["pocketed"]) == expected
                checked += 1
            if term or trunc:
                break
    assert checked >= 3
