"""The referee's call in words (``games.hud.call_text``): what the panel and the turn log say after a shot."""
from __future__ import annotations

import pytest

from billiards_env.games.hud import call_text
from billiards_env.games.session import Verdict


def _verdict(shooter: int = 0, foul: bool = False, reason: str = "", game_over: bool = False,
             winner: int | None = None) -> Verdict:
    return Verdict(shooter, foul, reason, turn_over=foul or game_over, game_over=game_over, winner=winner, scored=0.0,
                   call=None)


@pytest.mark.parametrize("names, winner, said", [
    (("you", "geometric"), 0, "9 pocketed: you win"),          # the play window speaks to its player
    (("you", "geometric"), 1, "9 pocketed: geometric wins"),
    (("agent", "geometric"), 0, "9 pocketed: agent wins"),
    (("player 1", "player 2"), 1, "9 pocketed: player 2 wins"),
])
def test_a_won_game_names_its_winner_in_plain_english(names, winner, said):
    assert call_text(_verdict(game_over=True, reason="9 pocketed", winner=winner), names, "") == said


def test_a_foul_names_the_shooter_and_a_clean_shot_says_what_it_did():
    assert call_text(_verdict(shooter=1, foul=True, reason="scratch"), ("you", "geometric"), "") == \
        "FOUL: scratch (geometric)"
    assert call_text(_verdict(), ("you", "geometric"), "pocketed 3") == "you: pocketed 3"
    assert call_text(_verdict(game_over=True, reason="drawn"), ("you", "geometric"), "") == "drawn: nobody wins"
