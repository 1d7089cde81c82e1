"""The compiled 9-ball and 8-ball judge (rules/pool_judge.py) calls every shot as the Python rules do: on many random
states, options, shot summaries and declarations, the same call (every field) and the same next state; and the
legal targets and the called-pocket need agree."""
from __future__ import annotations

import random

import numpy as np
import pytest

from billiards_env.rules import (ANYWHERE, KITCHEN, SOLIDS, STRIPES, EightBall, EightBallOptions, GameState, NineBall,
                                 NineBallOptions, ShotInfo, ShotSummary, legal_targets)
from billiards_env.rules import pool_judge as pj


def _rules(rng: random.Random, game: str):
    if game == "nine_ball":
        return NineBall(NineBallOptions(push_out=rng.random() < 0.5, three_foul_rule=rng.random() < 0.7,
                                        break_rail_balls=rng.choice([0, 2, 4, 9])))
    return EightBall(EightBallOptions(call_eight=rng.random() < 0.7, eight_on_break=rng.choice(["respot", "win"]),
                                      break_scratch_ball_in_hand=rng.choice([KITCHEN, ANYWHERE]),
                                      illegal_break_ball_in_hand=rng.choice([KITCHEN, ANYWHERE]),
                                      break_rail_balls=rng.choice([0, 3, 4, 15]), three_foul_rule=rng.random() < 0.3))


def _state(rng: random.Random, game: str) -> GameState:
    full = list(range(1, 10)) if game == "nine_ball" else list(range(1, 16))
    n = rng.choice([1, 2, 3, len(full) // 2, len(full)])
    on = sorted(rng.sample(full, n))
    if game == "eight_ball" and 8 not in on and rng.random() < 0.9:
        on = sorted(on[1:] + [8]) if len(on) > 1 else [8]
    brk = rng.random() < 0.25
    groups = None
    if game == "eight_ball" and not brk and rng.random() < 0.6:
        groups = rng.choice([(SOLIDS, STRIPES), (STRIPES, SOLIDS)])
    return GameState(game, tuple(on), shooter=rng.randrange(2), ball_in_hand=rng.choice([False, ANYWHERE, KITCHEN]),
                     groups=groups, fouls_in_a_row=(rng.randrange(3), rng.randrange(3)), break_shot=brk,
                     push_out_available=game == "nine_ball" and not brk and rng.random() < 0.3,
                     shot_number=rng.randrange(20))


def _summary(rng: random.Random, state: GameState) -> ShotSummary:
    on = list(state.on_table)
    targets = legal_targets(state)
    first = None if rng.random() < 0.1 else (rng.choice(targets) if targets and rng.random() < 0.6 else rng.choice(on))
    rails: tuple[int, ...] = ()
    if first is not None and rng.random() < 0.7:
        rails = tuple(sorted(rng.sample([0] + on, rng.randrange(min(len(on) + 1, 6)))))
    pocketed = tuple(rng.sample(on, rng.choice([0, 0, 1, 1, 2, 3][:len(on) + 1])))
    if 8 in on and rng.random() < 0.15 and 8 not in pocketed:
        pocketed = pocketed + (8,)
    cue = rng.random() < 0.2
    return ShotSummary(first, rails, pocketed, tuple(rng.randrange(6) for _ in pocketed), cue,
                       rng.randrange(6) if cue else -1)


@pytest.mark.parametrize("game", ["nine_ball", "eight_ball"])
def test_compiled_calls_equal_the_rules(game):
    rng = random.Random({"nine_ball": 1, "eight_ball": 2}[game])
    call = np.zeros((), pj.CALL_ROW)[()]  # records the compiled rules write into
    after = np.zeros((), pj.GAME_STATE_ROW)[()]
    reasons: set[str] = set()
    for _ in range(6000):
        rules = _rules(rng, game)
        state = _state(rng, game)
        summary = _summary(rng, state)
        push = state.push_out_available and rng.random() < 0.5
        called = rng.choice([None, 0, 1, 2, 3, 4, 5])
        want_call, want_next = rules.play(state, summary, ShotInfo(push_out=push, called_pocket=called))
        row, opts = pj.state_row(state), pj.options_row(rules)
        assert pj.game_state(row) == state
        assert pj.legal_mask(row) == pj.mask_of(rules.legal_targets(state))
        assert pj.needs_called_pocket(row, opts) == rules.needs_called_pocket(state)
        pocketed = np.array(summary.pocketed + (0,) * 16, np.int64)
        pockets = np.array(summary.pockets + (0,) * 16, np.int64)
        pj.play(row, opts, -1 if summary.first_contact is None else summary.first_contact,
                pj.mask_of(summary.rail_balls), pocketed, pockets, len(summary.pocketed), summary.cue_pocketed, push,
                -1 if called is None else called, call, after)
        assert pj.call_of(call, summary.pocketed) == want_call, (state, summary, push, called)
        assert pj.game_state(after) == want_next, (state, summary, push, called)
        reasons.add(want_call.reason)
    expected = {"legal", "scratch", "no contact", "wrong ball first", "no rail", "illegal break", "three fouls"}
    expected |= {"push-out", "9 pocketed"} if game == "nine_ball" else \
        {"8 pocketed", "8 on the break", "8 pocketed early", "8 pocketed on a foul", "8 in an uncalled pocket",
         "8 not called"}
    assert reasons >= expected, expected - reasons


def test_state_rows_round_trip_the_envs_states():
    for state in (NineBall().initial_state(1), EightBall().initial_state(0, on_table=(1, 8, 12)),
                  GameState("eight_ball", (3, 8), shooter=1, ball_in_hand=False, groups=(STRIPES, SOLIDS),
                            fouls_in_a_row=(2, 1), break_shot=False, shot_number=7)):
        assert pj.game_state(pj.state_row(state)) == state
    assert pj.numbers_of(pj.mask_of((1, 9, 15))) == (1, 9, 15)
