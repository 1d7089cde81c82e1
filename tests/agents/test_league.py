"""The league: Elo fitted to head-to-head results, and a short real match."""
from __future__ import annotations

import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import pytest  # noqa: E402

from agents.league import (PairResult, fit_elo, league_env_kwargs, load_player, main, play_pair,  # noqa: E402
                           player_stats, run_outs)


def pair(a, b, wa, wb, unfinished=0):
    return PairResult(a, b, wa + wb + unfinished, wa, wb, unfinished, 0, 0.0)


def test_even_results_give_equal_ratings_and_the_anchor_sits_at_1000():
    elo = fit_elo(["random", "x"], [pair("random", "x", 10, 10)])
    assert elo["random"] == pytest.approx(1000.0) and elo["x"] == pytest.approx(1000.0, abs=1e-6)


def test_ratings_follow_the_bradley_terry_odds():
    # 3:1 odds with one virtual draw added (regularisation): (30.5 / 10.5) -> 400 log10(30.5 / 10.5) points.
    elo = fit_elo(["a", "b"], [pair("a", "b", 30, 10)], anchor=None)
    import math

    assert elo["a"] - elo["b"] == pytest.approx(400 * math.log10(30.5 / 10.5), rel=1e-6)
    assert (elo["a"] + elo["b"]) / 2 == pytest.approx(1500.0)


def test_transitive_results_order_the_players():
    names = ["random", "geometric", "search"]
    pairs = [pair("random", "geometric", 2, 18), pair("random", "search", 1, 19), pair("geometric", "search", 8, 12)]
    elo = fit_elo(names, pairs)
    assert elo["search"] > elo["geometric"] > elo["random"] == pytest.approx(1000.0)


def test_a_short_match_between_baselines():
    res = play_pair("nine_ball", load_player("random"), load_player("geometric"), 4, seed=3, env_kwargs={})
    assert res.wins_a + res.wins_b + res.unfinished == 4
    assert sum(res.reasons.values()) == 4 and res.break_and_runs <= res.wins_a + res.wins_b
    again = play_pair("nine_ball", load_player("random"), load_player("geometric"), 4, seed=3, env_kwargs={})
    assert (again.wins_a, again.wins_b, again.reasons) == (res.wins_a, res.wins_b, res.reasons)  # seeded


def test_cli_writes_the_report(tmp_path):
    assert main(["--game", "eight_ball", "--players", "random", "geometric", "--games", "2", "--out",
                 str(tmp_path)]) == 0
    md = (tmp_path / "league.md").read_text()
    assert "| random | geometric |" in md and "| player | Elo |" in md
    assert main(["--players", "random"]) == 2


def test_run_outs_from_ball_in_hand_count_turns_that_win():
    res = run_outs("nine_ball", load_player("geometric"), 3, seed=11, env_kwargs={})
    assert res.racks == 3 and 0 <= res.run_outs <= 3 and res.balls >= res.run_outs  # a win pockets the 9 at least
    again = run_outs("nine_ball", load_player("geometric"), 3, seed=11, env_kwargs={})
    assert (again.run_outs, again.balls) == (res.run_outs, res.balls)  # the same layouts and play
    rnd = run_outs("nine_ball", load_player("random"), 3, seed=11, env_kwargs={})
    assert rnd.run_outs == 0 and res.ms_per_decision > 0


def test_player_stats_count_breaks_and_decision_times():
    p = PairResult("a", "b", 5, 3, 2, 0, 2, 0.0, {}, (2.0, 4.0), (2, 0))
    st = player_stats([p])
    assert (st["a"]["breaks"], st["b"]["breaks"]) == (3, 2)  # seats alternate, a breaks games 0, 2, 4
    assert (st["a"]["break_and_runs"], st["a"]["wins"], st["b"]["ms"]) == (2, 3, 4.0)


def test_league_settings_noise_and_physics():
    kw = league_env_kwargs([("geometric", None)], spin=True, noise="fastfiz")
    assert kw["friction"] == "spin" and kw["spin_action"] and kw["tip_noise"] == pytest.approx(0.5 / 28.575)
    kw = league_env_kwargs([("geometric", None)], spin=True, noise="olympiad")
    assert kw["speed_noise"] == 0.075 and kw["speed_noise_mode"] == "absolute"
    kw = league_env_kwargs([("geometric", None)], spin=False, noise="fastfiz")
    assert "tip_noise" not in kw and kw["angle_noise"] == pytest.approx(0.0021817, rel=1e-4)
    assert league_env_kwargs([], spin=False, noise="0.005") == {"angle_noise": 0.005, "speed_noise": 0.015}
    with pytest.raises(ValueError, match="noise"):
        league_env_kwargs([], spin=False, noise="loud")


def test_a_trained_player_acts_in_its_own_types_on_the_league_env():
    """A policy trained on the candidates types plays the league's absolute-type env: the shot it means there is
    the shot its own env would play for the same action."""
    import gymnasium as gym
    import numpy as np

    from agents.games import TrainedPlayer
    from billiards_env.multi import nine_ball_v0

    kw = {"action_type": "candidates", "observation_type": "candidates", "friction": "spin", "spin_action": True}
    seen = []

    def predict(obs):
        seen.append(obs)
        a = np.zeros(6, np.float32)
        a[1], a[2], a[3] = 0.3, 0.2, -0.4
        return a

    player = TrainedPlayer("t", predict, kw)
    league = nine_ball_v0.env(friction="spin", spin_action=True, opening="ball_in_hand")
    league.reset(seed=4)
    game = league.unwrapped.game_env
    action = player.act(game, None)
    own = gym.make("Billiards9Ball-v0", opponent=None, opening="ball_in_hand", **kw)
    obs, _ = own.reset(seed=4)
    assert np.array_equal(seen[0], obs)  # it observes the league's table as its own env would
    want = own.unwrapped.shot_from_action(predict(obs))
    got = game.shot_from_action(action)
    assert got.place == pytest.approx(want.place) and got.angle == pytest.approx(want.angle, abs=1e-6)
    assert (got.speed, got.side, got.top) == pytest.approx((want.speed, want.side, want.top), abs=1e-5)
    rolling = nine_ball_v0.env()
    rolling.reset(seed=4)
    with pytest.raises(ValueError, match="physics"):
        player.act(rolling.unwrapped.game_env, None)


def test_chunked_games_are_the_matchs_games():
    """play_games on any cut of the game indices plays play_match's games (seeds, seats, players' reseeding)."""
    from billiards_env.multi import nine_ball_v0, play_match

    from agents.league import play_games

    a, b = load_player("random", 0), load_player("geometric", 0)
    ref = play_match(nine_ball_v0.env, [a[1], b[1]], 4, seed=7)
    parts = play_games("nine_ball", [a[1], b[1]], [2, 3], 7, {}) + play_games("nine_ball", [a[1], b[1]], [0, 1], 7, {})
    parts.sort(key=lambda g: g.k)
    assert [(g.seats, g.winner, g.reason, g.shots) for g in parts] == \
        [(r.seats, r.winner, r.reason, r.shots) for r in ref.games]
    for g in parts:  # innings: each player's visits; what they scored: balls kept down (9-ball)
        assert all(0 <= g.innings[j] <= g.shots[j] for j in (0, 1)) and g.innings[g.seats[0]] >= 1
        assert 0 <= sum(g.scored) <= 9


def test_a_league_on_two_processes_is_the_league_on_one(tmp_path):
    from agents.league import run_league

    args = ("nine_ball", ["random", "geometric"], 4, 1, "0", None)
    one = run_league(*args, quiet=True, runouts=2, workers=1)
    two = run_league(*args, quiet=True, runouts=2, workers=2)
    keys = ("wins_a", "wins_b", "unfinished", "break_and_runs", "innings", "scored", "reasons")
    assert [{k: p[k] for k in keys} for p in one["pairs"]] == [{k: p[k] for k in keys} for p in two["pairs"]]
    assert [(r["run_outs"], r["balls"]) for r in one["run_outs"]] == [(r["run_outs"], r["balls"])
                                                                      for r in two["run_outs"]]
    assert one["players"]["geometric"]["per_inning"] > one["players"]["random"]["per_inning"]


@pytest.mark.parametrize("game, extra", [("three_cushion", ["--rules", '{"target_points": 1}']),
                                         ("snooker", ["--max-shots", "30"])])
def test_every_game_has_a_league(tmp_path, game, extra):
    assert main(["--game", game, "--players", "random", "geometric", "--games", "2", "--runouts", "2",
                 "--out", str(tmp_path), *extra]) == 0
    md = (tmp_path / "league.md").read_text()
    assert "points per inning" in md and "| random | geometric |" in md
    assert "run-out" in md  # the column, empty: these games have no ball-in-hand opening
    assert main(["--game", game, "--players", "random", "geometric", "--rules", "{oops"]) == 2


def test_the_setting_is_the_games_resolved_physics_and_noise():
    """The report says what the games were played under: a game's own default physics where the league gives
    none (three-cushion: the spin model with tip offsets), and the noise the option resolves to."""
    from agents.league import setting_text

    assert setting_text("three_cushion", {}).startswith("physics: spin, tip offsets in the action; shot noise: none")
    assert setting_text("nine_ball", {}) == "physics: rolling; shot noise: none"
    assert "angle_noise 0.01" in setting_text("nine_ball", {"angle_noise": 0.01})


def test_a_pair_counts_the_games_nobody_came_back_to_the_table():
    """Games over within two innings (a break-and-run, or the run-out of the player after the breaker) count as
    ``no_return``; a game with a third inning, or unfinished, does not. Shots are summed per player."""
    from agents.league import GameStats, pair_result

    def game(k, winner, innings, shots):
        return GameStats(k, (0, 1), winner, "9 pocketed", shots, innings, (0.0, 0.0), shots, (0.0, 0.0))

    games = [game(0, 0, (1, 0), (5, 0)),  # a breaks and runs out
             game(1, 1, (1, 1), (1, 7)),  # a's break misses, b runs out
             game(2, 0, (2, 1), (6, 2)),  # a comes back to the table: a third inning
             game(3, -1, (1, 1), (1, 3))]  # unfinished
    res = pair_result("a", "b", games)
    assert res.no_return == 2 and res.shots == (13, 12) and res.innings == (5, 3)


def test_no_games_is_refused_with_a_clear_message(capsys):
    """``--games 0`` (or ``--search-games 0``): argparse's one-line error and exit 2, not a ZeroDivisionError."""
    for flag in ("--games", "--search-games"):
        with pytest.raises(SystemExit) as exit_:
            main(["--game", "snooker", "--players", "random", "geometric", flag, "0"])
        assert exit_.value.code == 2
        err = capsys.readouterr().err
        assert f"argument {flag}: must be at least 1, got 0" in err and "Traceback" not in err
    from agents.league import run_league

    with pytest.raises(ValueError, match="games per pair must be at least 1, got 0"):
        run_league("snooker", ["random", "geometric"], 0, 0, "0", None, quiet=True)


def test_a_rules_typo_in_snooker_gives_the_did_you_mean(capsys):
    assert main(["--game", "snooker", "--players", "random", "geometric", "--games", "1",
                 "--rules", '{"target_pionts": 5}']) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("league: error: ") and "unknown option 'target_pionts'" in err
    assert "valid options:" in err and "\n" not in err
