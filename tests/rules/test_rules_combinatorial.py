"""Pure-data tests: every combination of hand-made shot facts on small tables, random games, and bad input.

Each expectation is the rule's own statement (WPA wording, with the simplifications in docs/rules.md), checked
over all combinations of first contact, rails after contact, balls pocketed (in order) and scratch.
"""
from __future__ import annotations

import itertools
import random
from dataclasses import fields

import pytest

from billiards_env.rules import (ANYWHERE, KITCHEN, EightBall, EightBallOptions, GameState, NineBall,
                                 NineBallOptions, RulesError, ShotInfo, ShotSummary, group_of, legal_targets)
from billiards_env.rules import state as S


def summaries(on_table, rails_choices=((), (0,), (5,), (0, 5, 6, 7))):
    """Every summary on a table holding ``on_table``: first contact (none or any ball), rails after contact,
    any ordered set of up to two pocketed balls (pocket = ball number % 6), scratch or not."""
    pots = [()] + [(a,) for a in on_table] + list(itertools.permutations(on_table, 2))
    for first in (None, *on_table):
        for rails in rails_choices:
            if first is None and rails:
                continue
            for pocketed in pots:
                for cue in (False, True):
                    yield ShotSummary(first, rails, pocketed, tuple(n % 6 for n in pocketed), cue, 0 if cue else -1)


def apply(state, call):
    """The state's table after the call, from the call's own lists."""
    return set(state.on_table) - set(call.pocketed) | set(call.respot)


def common_fouls(s: ShotSummary, targets) -> bool:
    return s.cue_pocketed or s.first_contact not in targets or (not s.pocketed and not s.rail_balls)


# --- 9-ball -------------------------------------------------------------------------------------------------------

NINE_ON = (2, 5, 9)


@pytest.mark.parametrize("fouls_before", [0, 2])
def test_nine_ball_every_shot(fouls_before):
    rules = NineBall()
    state = GameState("nine_ball", NINE_ON, ball_in_hand=False, break_shot=False, shooter=1,
                      fouls_in_a_row=(0, fouls_before))
    n = 0
    for s in summaries(NINE_ON):
        n += 1
        c, nxt = rules.play(state, s)
        foul = common_fouls(s, (2,))
        assert c.foul == foul and c.legal == (not foul) and c.shooter == 1
        lost = foul and fouls_before == 2
        if foul:
            assert c.reason == (S.THREE_FOULS if lost else c.fouls[0]) and set(c.fouls) <= set(S.FOULS)
        won = not foul and 9 in s.pocketed
        assert c.game_over == (lost or won)
        if c.game_over:
            assert c.winner == (1 if won else 0) and c.ball_in_hand is False and c.respot == ()
            assert nxt.game_over and nxt.winner == c.winner
            continue
        assert c.respot == ((9,) if 9 in s.pocketed else ())  # the 9 comes back, everything else stays down
        assert nxt.on_table == tuple(sorted(apply(state, c))) and 9 in nxt.on_table
        if foul:
            assert c.turn_over and nxt.shooter == 0 and nxt.ball_in_hand == ANYWHERE
            assert nxt.fouls_in_a_row == (0, fouls_before + 1)
        else:
            assert c.turn_over == (not s.pocketed) and nxt.ball_in_hand is False
            assert nxt.shooter == (1 if s.pocketed else 0) and nxt.fouls_in_a_row == (0, 0)
    assert n > 200


def test_nine_ball_every_break():
    rules = NineBall()
    state = rules.initial_state(0, NINE_ON)
    for s in summaries(NINE_ON):
        c = rules.call(state, s)
        illegal = not s.pocketed and s.object_balls_to_rail < 4
        foul = s.cue_pocketed or s.first_contact != 2 or illegal
        assert c.foul == foul
        assert (S.ILLEGAL_BREAK in c.fouls) == illegal
        assert c.game_over == (not foul and 9 in s.pocketed)
        if not c.game_over:
            assert c.respot == ((9,) if 9 in s.pocketed else ())
            assert rules.next_state(state, c).push_out_available


def test_nine_ball_every_push_out():
    rules = NineBall()
    state = GameState("nine_ball", NINE_ON, ball_in_hand=False, break_shot=False, push_out_available=True)
    for s in summaries(NINE_ON):
        c, nxt = rules.play(state, s, ShotInfo(push_out=True))
        assert c.foul == s.cue_pocketed and not c.game_over and c.turn_over
        assert c.respot == ((9,) if 9 in s.pocketed else ())
        assert nxt.push_out_pending == (not c.foul) and not nxt.push_out_available


# --- 8-ball -------------------------------------------------------------------------------------------------------

EIGHT_ON = (2, 8, 10)

EIGHT_STATES = {
    "open": dict(groups=None),
    "solids": dict(groups=("solids", "stripes")),
    "stripes": dict(groups=("stripes", "solids")),
}


@pytest.mark.parametrize("groups", list(EIGHT_STATES))
@pytest.mark.parametrize("on", [EIGHT_ON, (8, 10), (2, 8)], ids=["both", "no-solid", "no-stripe"])
@pytest.mark.parametrize("call_eight", [True, False])
def test_eight_ball_every_shot(groups, on, call_eight):
    rules = EightBall(EightBallOptions(call_eight=call_eight))
    state = GameState("eight_ball", on, ball_in_hand=False, break_shot=False, **EIGHT_STATES[groups])
    targets = legal_targets(state)
    on_eight = targets == (8,)
    for s in summaries(on):
        for called in (None, 0, 2):
            c, nxt = rules.play(state, s, ShotInfo(called_pocket=called))
            foul = common_fouls(s, targets)
            assert c.foul == foul
            if 8 in s.pocketed:  # the 8 always ends the game
                good_pocket = not call_eight or s.pocket_of(8) == called
                win = on_eight and not foul and good_pocket
                assert c.game_over and c.winner == (0 if win else 1) and c.legal == win
                continue
            assert not c.game_over and c.respot == ()
            assert nxt.on_table == tuple(sorted(apply(state, c)))
            if foul:
                assert c.turn_over and nxt.ball_in_hand == ANYWHERE and nxt.groups == state.groups
                continue
            if state.groups is None:
                if s.pocketed:
                    g = group_of(s.pocketed[0])
                    assert c.groups[0] == g and c.groups[1] != g and not c.turn_over
                else:
                    assert c.groups is None and c.turn_over
            else:
                assert c.groups == state.groups
                mine = state.groups[0]
                assert c.turn_over == (not any(group_of(n) == mine for n in s.pocketed))


@pytest.mark.parametrize("eight_on_break", ["respot", "win"])
def test_eight_ball_every_break(eight_on_break):
    rules = EightBall(EightBallOptions(eight_on_break=eight_on_break))
    state = rules.initial_state(0, EIGHT_ON)
    for s in summaries(EIGHT_ON):
        c = rules.call(state, s)
        illegal = not s.pocketed and s.object_balls_to_rail < 4
        foul = s.cue_pocketed or s.first_contact is None or illegal
        assert c.foul == foul and c.groups is None
        if 8 in s.pocketed and not foul and eight_on_break == "win":
            assert c.game_over and c.winner == 0
            continue
        assert not c.game_over and c.respot == ((8,) if 8 in s.pocketed else ())
        if foul:
            assert c.ball_in_hand == (KITCHEN if s.cue_pocketed else ANYWHERE) and c.turn_over
        else:
            assert c.turn_over == (not s.pocketed)


# --- random games -------------------------------------------------------------------------------------------------

def random_shot(rng: random.Random, state: GameState) -> ShotSummary:
    """A random summary consistent with ``state`` (only balls on the table take part)."""
    on = list(state.on_table)
    first = rng.choice([None] + on)
    rails = () if first is None else tuple(sorted(set(rng.sample([0] + on, rng.randint(0, min(3, len(on)))))))
    pocketed = tuple(rng.sample(on, rng.choice([0, 0, 1, 1, 2, 3][:len(on) + 3])))
    cue = rng.random() < 0.25
    pockets = tuple(rng.randint(0, 5) for _ in pocketed)
    return ShotSummary(first, rails, pocketed, pockets, cue, 2 if cue else -1)


@pytest.mark.parametrize("game", ["nine_ball", "eight_ball"])
def test_random_games_keep_their_invariants(game):
    rules = NineBall() if game == "nine_ball" else EightBall()
    rng = random.Random(7)
    ended = 0
    for _ in range(300):
        state = rules.initial_state(rng.randint(0, 1))
        for _ in range(80):
            if state.game_over:
                ended += 1
                break
            if state.push_out_pending and rng.random() < 0.5:
                state = rules.pass_back(state)
            info = ShotInfo(push_out=state.push_out_available and rng.random() < 0.5,
                            called_pocket=rng.choice([None, 0, 1, 2, 3, 4, 5]))
            s = random_shot(rng, state)
            c, nxt = rules.play(state, s, info)
            assert c.shooter == state.shooter
            assert c.next_shooter == (state.opponent if c.turn_over else state.shooter)
            assert set(c.respot) <= set(s.pocketed) and set(nxt.on_table) <= set(state.on_table)
            assert c.foul == bool(c.fouls) and not (c.legal and c.foul)
            if c.foul and not c.game_over:
                assert c.turn_over and c.ball_in_hand in (ANYWHERE, KITCHEN)
            if not c.foul:
                assert c.ball_in_hand is False
            if game == "nine_ball" and not nxt.game_over:
                assert max(nxt.fouls_in_a_row) <= 2 and 9 in nxt.on_table  # the 9 leaves only to end the game
            if game == "eight_ball" and not nxt.game_over:
                assert 8 in nxt.on_table
            if state.groups is not None:
                assert nxt.groups == state.groups  # groups never change once decided
            assert nxt.game_over == c.game_over and nxt.winner == c.winner
            assert nxt.shot_number == state.shot_number + 1
            assert GameState(*(getattr(nxt, f.name) for f in fields(GameState))) == nxt  # passes the checks
            state = nxt
    assert ended > 100


# --- bad input ----------------------------------------------------------------------------------------------------

def test_state_and_declarations_are_checked():
    for kw, what in ((dict(game="snooker", on_table=(1,)), "game"),
                     (dict(game="nine_ball", on_table=(1, 1)), "on_table"),
                     (dict(game="nine_ball", on_table=(16,)), "on_table"),
                     (dict(game="nine_ball", on_table=(1,), shooter=2), "shooter"),
                     (dict(game="nine_ball", on_table=(1,), ball_in_hand="behind"), "ball_in_hand"),
                     (dict(game="nine_ball", on_table=(1,), groups=("solids", "stripes")), "groups"),
                     (dict(game="eight_ball", on_table=(8,), groups=("solids", "solids")), "groups"),
                     (dict(game="nine_ball", on_table=(1,), fouls_in_a_row=(0, -1)), "fouls_in_a_row"),
                     (dict(game="nine_ball", on_table=(1,), winner=0), "winner")):
        with pytest.raises(RulesError, match=what):
            GameState(**kw)
    with pytest.raises(RulesError, match="called_pocket"):
        ShotInfo(called_pocket=-1)
    with pytest.raises(RulesError, match="push_out"):
        ShotInfo(push_out=1)
    with pytest.raises(RulesError, match="eight_on_break"):
        EightBallOptions(eight_on_break="lose")
    with pytest.raises(RulesError, match="break_scratch_ball_in_hand"):
        EightBallOptions(break_scratch_ball_in_hand="behind")
    with pytest.raises(RulesError, match="break_rail_balls"):
        NineBallOptions(break_rail_balls=-1)
    with pytest.raises(RulesError, match="three_foul_rule"):
        NineBallOptions(three_foul_rule="yes")
    with pytest.raises(RulesError, match="not part of"):
        NineBall().initial_state(0, (1, 10))


def test_summary_must_fit_the_state():
    rules = NineBall()
    state = GameState("nine_ball", (1, 9), ball_in_hand=False, break_shot=False)
    with pytest.raises(RulesError, match="first_contact"):
        rules.call(state, ShotSummary(first_contact=3))
    with pytest.raises(RulesError, match="pocketed"):
        rules.call(state, ShotSummary(first_contact=1, pocketed=(4,), pockets=(0,)))
    with pytest.raises(RulesError, match="ruleset"):
        EightBall().call(state, ShotSummary())
    c = rules.call(state, ShotSummary(first_contact=1, rail_balls=(1,)))
    with pytest.raises(RulesError, match="shooter"):
        rules.next_state(GameState("nine_ball", (1, 9), shooter=1, break_shot=False), c)
