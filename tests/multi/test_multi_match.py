"""play_match: games between two policies (players, models, callables) in the two-player envs."""
from __future__ import annotations

import math
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from billiards_env.multi import GameRecord, MatchResult, eight_ball_v0, nine_ball_v0, play_match  # noqa: E402
from billiards_env.players import make_player  # noqa: E402


class Recorder:
    """A callable policy ``obs -> action`` that records what it saw (always a soft shot to the left)."""

    def __init__(self, n: int) -> None:
        self.n, self.seen = n, []

    def __call__(self, obs):
        self.seen.append(obs.copy())
        return np.array([1.0, -1.0] + [0.0] * (self.n - 2), dtype=np.float32)


class Model:
    """An SB3-style model: ``predict(obs, deterministic)`` -> (action, state)."""

    def __init__(self, n: int) -> None:
        self.n, self.calls = n, 0

    def predict(self, obs, deterministic=False):
        self.calls += 1
        return np.array([1.0, -1.0] + [0.0] * (self.n - 2), dtype=np.float32), None


def test_match_is_deterministic_and_alternates_seats():
    def match():
        return play_match(lambda: nine_ball_v0.env(angle_noise=0.005),
                          [make_player("geometric"), make_player("random")], n_games=4, seed=11)

    r1, r2 = match(), match()
    assert isinstance(r1, MatchResult) and all(isinstance(g, GameRecord) for g in r1.games)
    assert r1 == r2  # same seed: same games, shot for shot
    assert [g.seats for g in r1.games] == [(0, 1), (1, 0), (0, 1), (1, 0)]
    assert [g.seed for g in r1.games] == [11, 12, 13, 14]
    assert all(w in (-1, 0, 1) for w in r1.winners) and sum(r1.wins) + r1.unfinished == 4
    for g in r1.games:
        assert (g.winner == -1) == (g.reason == "max_shots") and min(g.shots) >= 0 and sum(g.shots) >= 1
    # The geometric player beats one that shoots at random (three fouls in a row lose).
    assert r1.wins[0] > r1.wins[1]


def test_players_act_on_the_single_agent_env_and_follow_the_rules():
    """A player gets the underlying game env: it hits a legal ball first and places ball in hand in the area."""
    env = eight_ball_v0.env()
    raw = env.unwrapped
    game = raw.game_env
    player = make_player("geometric")
    env.reset(seed=2)
    wrong = 0
    for agent in env.agent_iter(12):
        obs, _, terminated, truncated, _ = env.last()
        if terminated or truncated:
            env.step(None)
            continue
        legal = {str(n) for n in game.task.rules.legal_targets(game.task.game_state)}
        area = game.table_state.view.place_area
        action = player.act(game, obs)
        assert env.action_space(agent).contains(action)
        if area is not None:
            x0, x1, y0, y1 = area
            place = game.shot_from_action(action).place
            assert x0 <= place[0] <= x1 and y0 <= place[1] <= y1
        env.step(action)
        first = game.info_words(env.infos[agent])["first_contact"]
        wrong += first is not None and first not in legal
    assert wrong == 0


def test_callables_and_models_get_their_own_view():
    n = nine_ball_v0.raw_env().action_space("player_0").shape[0]
    rec, model = Recorder(n), Model(n)
    result = play_match(nine_ball_v0.env(), [rec, model], n_games=2, seed=0)
    assert len(result.games) == 2 and model.calls >= 1 and rec.seen
    # Both shoot soft misses: a foul each time, so every observation a policy gets is on its own turn.
    assert all(obs[-1] == 1.0 for obs in rec.seen)  # the "my turn" feature
    assert all(g.reason == "three fouls" for g in result.games)


def test_self_play_with_one_policy_in_both_seats():
    player = make_player("geometric")
    result = play_match(eight_ball_v0.env, [player, player], n_games=1, seed=3)
    assert len(result.winners) == 1


def test_bad_arguments():
    with pytest.raises(ValueError, match="two"):
        play_match(nine_ball_v0.env, [make_player("random")], n_games=1)
    with pytest.raises(ValueError, match="n_games"):
        play_match(nine_ball_v0.env, [make_player("random")] * 2, n_games=0)
    with pytest.raises(TypeError, match="opponent|expected a player"):
        play_match(nine_ball_v0.env, [make_player("random"), math.pi], n_games=1)
