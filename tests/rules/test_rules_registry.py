"""The rules' list of games is filled by the rulesets themselves: a Ruleset subclass that names its game registers
it (GameState accepts it, ruleset_for and legal_targets know it); a name taken twice or a ruleset without its
legal-target function is refused."""
from __future__ import annotations

import pytest

from billiards_env.rules import RULESETS, TARGETS, GameState, NineBall, RulesError, legal_targets, ruleset_for
from billiards_env.rules import state as S
from billiards_env.rules.nine_ball import nine_ball_targets
from billiards_env.rules.ruleset import Ruleset


def test_the_pool_games_are_registered_by_their_rulesets():
    assert RULESETS["nine_ball"] is NineBall and TARGETS["nine_ball"] is nine_ball_targets
    assert set(S.GAMES) >= {"nine_ball", "eight_ball"} and RULESETS is S.GAMES


def test_a_new_ruleset_registers_its_game_and_its_states_are_valid(monkeypatch):
    monkeypatch.setattr(S, "GAMES", dict(S.GAMES))  # leave the real registry as it was
    monkeypatch.setattr(S, "TARGETS", dict(S.TARGETS))
    with pytest.raises(RulesError, match="unknown game 'ten_ball'"):
        GameState("ten_ball", (1, 2, 10))

    def ten_ball_targets(state: GameState) -> tuple[int, ...]:
        return state.on_table[:1]

    class TenBall(Ruleset):
        game = "ten_ball"
        full_rack = tuple(range(1, 11))
        targets = staticmethod(ten_ball_targets)

        def legal_targets(self, state):  # pragma: no cover - not called
            return ten_ball_targets(state)

        def call(self, state, summary, shot_info=None):  # pragma: no cover - not called
            raise NotImplementedError

    st = GameState("ten_ball", (2, 5, 10))
    assert S.GAMES["ten_ball"] is TenBall and S.TARGETS["ten_ball"](st) == (2,)
    with pytest.raises(RulesError, match="played by TenBall already"):
        S.register_rules("ten_ball", NineBall, nine_ball_targets)


def test_a_ruleset_that_names_a_game_names_its_targets_too():
    with pytest.raises(RulesError, match=r"targets = staticmethod\(f\)"):
        class Broken(Ruleset):  # noqa: F841
            game = "broken_ball"
            full_rack = (1,)


def test_an_unknown_game_is_refused_with_the_registered_ones():
    with pytest.raises(RulesError, match="unknown game 'tenball'; use one of .*nine_ball"):
        ruleset_for("tenball")
    assert legal_targets(GameState("nine_ball", (3, 9), break_shot=False, ball_in_hand=False)) == (3,)
