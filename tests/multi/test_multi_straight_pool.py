"""straight_pool_v0: PettingZoo's AEC API test on a short game, and a match between the built-in players (the
parallel API, seed, max-cycles and render tests run over every registered game in test_multi_parallel.py and
test_multi_api.py)."""
from __future__ import annotations

import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import pytest  # noqa: E402

pytest.importorskip("pettingzoo")
from pettingzoo.test import api_test  # noqa: E402

from billiards_env.multi import play_match, straight_pool_v0  # noqa: E402
from billiards_env.players import make_player  # noqa: E402


def test_pettingzoo_api_test_passes_on_a_game_to_ten_points():
    # api_test resets with options={"options": 1}: ignored with a warning naming the key.
    with pytest.warns(UserWarning, match=r"unknown key\(s\) \['options'\] ignored"):
        api_test(straight_pool_v0.env(rules={"target": 10}, max_shots=80), num_cycles=200)


def test_a_match_of_the_built_in_players_ends_with_a_winner_at_the_target():
    players = [make_player("geometric", seed=0, game="straight_pool"), make_player("random", seed=0)]
    result = play_match(straight_pool_v0.env(rules={"target": 8}, max_shots=300), players, n_games=2, seed=0)
    assert len(result.winners) == 2 and set(result.winners) <= {0, 1}
    assert result.wins[0] == 2  # the geometric player beats random actions to 8 points
