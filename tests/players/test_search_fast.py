"""The search player on the compiled geometry and the batch API (players/search.py) plays what the Python search it
replaced played (benchmarks/reference_players.py, through its recorded results: the ``golden`` fixture): the same
action on fixed tables of 9-ball and 8-ball games (the cue ball where it lies and in hand), under the spin model with
tip offsets and shot noise, without rules, and with an action type mapped shot by shot. Its parts are checked
against what they replace: what the rules read of a shot from the batch arrays against the event log, the absolute
aim's round trip on arrays against the env's, and the rules' contract that after the break only whether a ball
reached a cushion counts."""
from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401  (registers the ids)
from billiards_env.physics.batch import run_shots
from billiards_env.players import make_player, shot_context
from billiards_env.players.search import (Judge, Playable, SearchPlayer, SearchSettings, _key_from_log,
                                          _simulate_judged, shot_keys)
from billiards_env.rules import STRIPES, SOLIDS, EightBall, GameState, NineBall, ShotInfo, ShotSummary
from golden import reference_players as reference

QUICK = SearchSettings(n_geometric=3, sweep_angles=24, robust_samples=3, top_k=3)


def _decisions(env_id: str, seeds: range, steps: int, **kw):
    """The env at the agent's decisions of seeded games (the agent plays the geometric player's shot, or a seeded
    random action one time in four), breaks skipped."""
    env = gym.make(env_id, **kw)
    env.action_space.seed(seeds.start)
    rng = np.random.default_rng(seeds.start)
    geo = make_player("geometric")
    try:
        for seed in seeds:
            obs, _ = env.reset(seed=seed)
            for _ in range(steps):
                u = env.unwrapped
                if not u.table_state.view.break_shot:
                    yield env, obs, seed
                action = env.action_space.sample() if rng.random() < 0.25 else geo.act(env, obs)
                obs, _, term, trunc, _ = env.step(action)
                if term or trunc:
                    break
    finally:
        env.close()


def _same_as_reference(golden, env_id: str, seeds: range, steps: int, settings: SearchSettings | None = None,
                       **kw) -> tuple[int, int]:
    checked = in_hand = 0
    for env, obs, seed in _decisions(env_id, seeds, steps, **kw):
        new = SearchPlayer(seed=seed, settings=settings)
        got = (new.act(env, obs), (new.last.angle, new.last.speed, new.last.side, new.last.top, new.last.source))

        def want(env=env, obs=obs, seed=seed):
            ref = reference().ReferenceSearchPlayer(seed=seed, settings=settings and reference().SearchSettings(
                **settings.__dict__))
            action = ref.act(env, obs)
            return action, (ref.last.angle, ref.last.speed, ref.last.side, ref.last.top, ref.last.source)

        golden.check(got, want, same=lambda a, b: np.array_equal(a[0], b[0]) and a[1] == b[1])
        checked += 1
        in_hand += shot_context(env).place_area is not None
    return checked, in_hand


@pytest.mark.parametrize("env_id, seeds, steps, settings, kw", [
    ("Billiards9Ball-v0", range(0, 3), 5, None, {}),
    ("Billiards8Ball-v0", range(10, 12), 4, QUICK, {}),
    ("Billiards9Ball-v0", range(20, 22), 4, QUICK, dict(friction="spin", spin_action=True,
                                                        angle_noise=math.radians(0.125), speed_noise=0.0375,
                                                        tip_noise=0.5 / 28.575)),
    ("BilliardsThreeBalls-v0", range(30, 34), 2, QUICK, {}),
    ("BilliardsOneBall-v0", range(40, 44), 1, QUICK, dict(action_type="ghost", speed_max=1.8)),
])
def test_search_plays_what_the_python_search_played(env_id, seeds, steps, settings, kw, golden):
    checked, in_hand = _same_as_reference(golden, env_id, seeds, steps, settings, **kw)
    assert checked >= len(seeds)


@pytest.mark.slow
@pytest.mark.parametrize("env_id, kw", [("Billiards9Ball-v0", {}), ("Billiards8Ball-v0", {}),
                                        ("Billiards9Ball-v0", dict(friction="drag")),
                                        ("Billiards8Ball-v0", dict(friction="spin", spin_action=True))])
def test_search_plays_what_the_python_search_played_on_many_tables(env_id, kw, golden):
    checked, in_hand = _same_as_reference(golden, env_id, range(500, 536), 12, None, **kw)
    assert checked >= 30 and in_hand >= 3


def test_shot_keys_read_from_the_batch_arrays_equal_the_event_log():
    # Hard shots into the rack and through a broken table: many pockets, cushions, first contacts.
    env = gym.make("Billiards9Ball-v0", opponent=None)
    checked = potted = 0
    for seed in range(3):
        env.reset(seed=seed)
        ctx = shot_context(env)
        rng = np.random.default_rng(seed)
        angles = rng.uniform(-math.pi, math.pi, 200)
        speeds = rng.uniform(0.5, 5.0, 200)
        res = run_shots(ctx.simulator, ctx.balls, angles, speeds, validate=False, events=True)
        numbers = np.asarray(ctx.game.numbers, dtype=np.int64)
        for detail in (True, False):
            keys, masks, ties = shot_keys(res.first_contact, res.rail_after_contact, res.pocket, res.pocketed_at,
                                          numbers, 0, detail)
            ev = res.events
            table = np.stack([ev.kind, ev.ball, ev.other], axis=1)
            for k in range(len(angles)):
                key, mask = _key_from_log(table[ev.offsets[k]:ev.offsets[k + 1]], res.pocket[k], numbers, 0, detail)
                if not ties[k]:
                    assert np.array_equal(keys[k], key) and masks[k] == mask
                    checked += 1
                    potted += int(key[3]) >= 2
        env.step(env.unwrapped.action_from_shot(angles[0], 5.0))  # a broken table next
    assert checked >= 1000 and potted >= 5


def test_after_the_break_the_rules_read_only_whether_a_ball_reached_a_cushion():
    """The search judges shots that differ only in which balls reached a cushion after the first contact once
    (Judge): the rules' call must not depend on more than whether one did."""
    rng = np.random.default_rng(7)
    checked = 0
    for env_id in ("Billiards9Ball-v0", "Billiards8Ball-v0"):
        for env, _, _ in _decisions(env_id, range(60, 64), 6):
            game = shot_context(env).game
            on = list(game.game_state.on_table)
            for _ in range(20):
                first = int(rng.choice(on)) if rng.random() < 0.9 else None
                pocketed = tuple(int(n) for n in rng.permutation(on)[:int(rng.integers(0, 3))])
                pockets = tuple(int(p) for p in rng.integers(0, 6, len(pocketed)))
                cue = int(rng.integers(-1, 6)) if rng.random() < 0.2 else -1
                called = ShotInfo(called_pocket=int(rng.integers(0, 6)))
                calls = set()
                for rails in ((0,), tuple(sorted(rng.permutation([0] + on)[:3].tolist())), tuple(sorted(on))):
                    summary = ShotSummary(first, tuple(int(n) for n in rails), pocketed, pockets, cue >= 0, cue)
                    calls.add(game.rules.call(game.game_state, summary, called))
                assert len(calls) == 1
                checked += 1
    assert checked >= 100


def test_compiled_verdicts_equal_the_python_rules():
    """The search's 9-ball and 8-ball verdicts come from the compiled rules (``judge_rows``): the same value, next
    shooter and legal balls after, shot for shot, as the Python rules give (``Judge._judge``), on random shots from
    the positions of seeded games (breaks included, ball in hand, fouls, wins)."""
    rng = np.random.default_rng(9)
    checked = set()
    for env_id in ("Billiards9Ball-v0", "Billiards8Ball-v0"):
        env = gym.make(env_id)
        env.action_space.seed(9)
        try:
            for seed in range(90, 94):
                env.reset(seed=seed)
                for _ in range(6):
                    ctx = shot_context(env)
                    n = 120
                    angles, speeds = rng.uniform(0, 2 * math.pi, n), rng.uniform(0.3, 6.0, n)
                    fast, slow = Judge(ctx), Judge(ctx)
                    assert fast._compiled is not None
                    slow._compiled = None
                    a = _simulate_judged(ctx, angles, speeds, judge=fast)
                    b = _simulate_judged(ctx, angles, speeds, judge=slow)
                    assert np.array_equal(a.values, b.values) and np.array_equal(a.next, b.next)
                    for k in range(n):
                        assert np.array_equal(a.t_flat[a.t_off[a.group[k]]:a.t_off[a.group[k] + 1]],
                                              b.t_flat[b.t_off[b.group[k]]:b.t_off[b.group[k] + 1]])
                    checked |= set(zip(a.values.tolist(), a.next.tolist()))
                    _, _, term, trunc, _ = env.step(env.action_space.sample())
                    if term or trunc:
                        break
        finally:
            env.close()
    # wins, fouls, turns kept and lost all judged
    assert {v for v, _ in checked} >= {-3.0, 0.0} and any(v >= 1.0 for v, _ in checked), checked


def test_without_a_called_pocket_the_rules_read_no_pocket():
    """The search judges shots that differ only in the pockets their balls dropped into once when
    ``reads_pockets`` says the rules read none (9-ball; 8-ball off the 8): the call must not depend on them then.
    On the 8 with calls on, it does (the called pocket), and ``reads_pockets`` says so."""
    rng = np.random.default_rng(8)
    checked = 0
    for env_id in ("Billiards9Ball-v0", "Billiards8Ball-v0"):
        for env, _, _ in _decisions(env_id, range(70, 76), 8):
            game = shot_context(env).game
            state = game.game_state
            on = list(state.on_table)
            for _ in range(20):
                first = int(rng.choice(on)) if rng.random() < 0.9 else None
                pocketed = tuple(int(n) for n in rng.permutation(on)[:int(rng.integers(1, 3))])
                if rng.random() < 0.3 and 8 in on and 8 not in pocketed:
                    pocketed = pocketed + (8,)
                rails = tuple(sorted(rng.permutation(on)[:2].tolist()))
                scratch = rng.random() < 0.3
                calls = set()
                for _ in range(4):
                    pockets = tuple(int(p) for p in rng.integers(0, 6, len(pocketed)))
                    cue = int(rng.integers(0, 6)) if scratch else -1
                    summary = ShotSummary(first, rails, pocketed, pockets, scratch, cue)
                    calls.add(game.rules.call(state, summary, game.declared_for(summary)))
                if not game.rules.reads_pockets(state):
                    assert len(calls) == 1, (state, calls)
                    checked += 1
    assert checked >= 200
    # On the 8 with calls on: the 8 into the called pocket wins, into another loses.
    rules = EightBall()
    on_8 = GameState("eight_ball", (3, 8), shooter=0, ball_in_hand=False, groups=(STRIPES, SOLIDS), break_shot=False)
    assert rules.reads_pockets(on_8) and not NineBall().reads_pockets(NineBall().initial_state(0))
    calls = {rules.call(on_8, ShotSummary(8, (8,), (8,), (p,), False, -1), ShotInfo(called_pocket=2)).winner
             for p in (2, 4)}
    assert calls == {0, 1}


@pytest.mark.parametrize("kw", [dict(), dict(friction="spin", spin_action=True)])
def test_absolute_round_trip_on_arrays_equals_the_envs(kw):
    env = gym.make("Billiards8Ball-v0", opponent=None, **kw)
    env.reset(seed=3)
    rng = np.random.default_rng(1)
    n = 400
    angles = np.concatenate([rng.uniform(-7.0, 7.0, n - 4), [math.pi, -math.pi, 0.0, 1e-12]])
    speeds = np.concatenate([rng.uniform(0.0, 6.0, n - 4), [0.5, 5.0, 0.3, 7.0]])
    tips = [(0.0, 0.0), (0.0, -0.35), (0.0, 0.35), (-0.3, 0.0), (0.3, 0.0)]
    sides = np.array([tips[k % 5][0] for k in range(n)])
    tops = np.array([tips[k % 5][1] for k in range(n)])
    for place in (None, (0.5, 0.6)):
        u = env.unwrapped
        fast, slow = Playable(u.table_state, u.action_type, place), Playable(u.table_state, u.action_type, place)
        assert fast._fast
        slow._fast = False
        got, expected = fast.arrays(angles, speeds, sides, tops), slow.arrays(angles, speeds, sides, tops)
        for a, b in zip(got, expected):
            assert np.array_equal(a, b)
        for k in range(0, n, 37):
            shot = tuple(float(x[k]) for x in got)
            dims = 4 if kw else 2
            assert np.array_equal(fast.action_for(*shot)[:dims], slow.action_for(*shot)[:dims])
