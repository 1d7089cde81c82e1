"""Evaluation of the baselines on the real envs, the statistics and the report files."""
from __future__ import annotations

import json
import math

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401
from billiards_env.players import SearchSettings, SearchPlayer, make_player, shot_context
from agents.evaluate import baseline_player, evaluate, main, run_player, wilson_interval

ONE = "BilliardsOneBall-v0"
THREE = "BilliardsThreeBalls-v0"


def test_wilson_interval_known_values():
    lo, hi = wilson_interval(5, 10)
    assert math.isclose(lo, 0.2366, abs_tol=1e-4) and math.isclose(hi, 0.7634, abs_tol=1e-4)
    lo, hi = wilson_interval(0, 10)
    assert lo == 0.0 and math.isclose(hi, 0.2775, abs_tol=1e-4)
    lo, hi = wilson_interval(10, 10)
    assert math.isclose(lo, 0.7225, abs_tol=1e-4) and hi == 1.0
    assert wilson_interval(0, 0) == (0.0, 1.0)
    # narrower with more episodes
    assert np.diff(wilson_interval(500, 1000)) < np.diff(wilson_interval(50, 100))


@pytest.mark.parametrize("name,episodes,at_least,at_most", [
    ("random", 40, 0, 8),
    ("geometric", 40, 34, 40),
    ("search", 15, 14, 15),
])
def test_baselines_on_one_ball(name, episodes, at_least, at_most):
    spec = baseline_player(name, ONE, {})
    res, rows = run_player(spec, episodes, seed=500)
    assert res.episodes == episodes and len(rows) == episodes
    assert at_least <= res.successes <= at_most, res
    assert res.shots == episodes  # one shot per episode
    lo, hi = res.success_ci
    assert lo <= res.success_rate <= hi


def test_baselines_are_deterministic_and_work_in_relative_aim():
    a = run_player(baseline_player("geometric", ONE, {}), 20, seed=7)[1]
    b = run_player(baseline_player("geometric", ONE, {"action_type": "relative"}), 20, seed=7)[1]
    assert [r["success"] for r in a] == [r["success"] for r in b]
    r1 = run_player(baseline_player("random", ONE, {}), 10, seed=7)[1]
    r2 = run_player(baseline_player("random", ONE, {}), 10, seed=7)[1]
    assert r1 == r2


def test_geometric_and_search_clear_three_balls():
    for name, n, need in (("geometric", 6, 4), ("search", 3, 3)):
        player = make_player(name) if name == "geometric" else SearchPlayer(
            settings=SearchSettings(n_geometric=4, sweep_angles=24, robust_samples=2, top_k=3))
        spec = baseline_player("geometric", THREE, {})
        spec.act = player.act
        res, rows = run_player(spec, n, seed=11)
        assert res.successes >= need, (name, rows)
        assert all(r["shots"] <= 15 for r in rows)


def test_player_action_round_trip():
    env = gym.make(ONE, action_type="relative")
    env.reset(seed=3)
    player = make_player("geometric")
    action = player.act(env, None)
    angle, speed = env.unwrapped.shot_from_action(action)[:2]
    assert abs((angle - player.last.angle + math.pi) % (2 * math.pi) - math.pi) < 1e-5
    assert abs(speed - player.last.speed) < 1e-4
    ctx = shot_context(env)
    assert ctx.cue == 0 and ctx.targets == [1] and ctx.speed_range == (0.5, 5.0)


def test_evaluate_writes_report(tmp_path):
    players = [baseline_player(n, ONE, {"render_width": 200}) for n in ("random", "geometric")]
    rep = evaluate(players, 12, 123, tmp_path, gif_episodes=1, quiet=True)
    md = (tmp_path / "report.md").read_text()
    js = json.loads((tmp_path / "report.json").read_text())
    assert "pocket rate" in md and "geometric" in md and "random" in md
    assert js["metric"] == "pocket_rate" and len(js["results"]) == 2
    assert js["results"][1]["success_rate"] >= js["results"][0]["success_rate"]
    gif = tmp_path / "episodes.gif"
    assert gif.exists() and gif.stat().st_size > 1000 and rep["gif"]["frames"] > 2


def test_evaluate_cli_three_balls(tmp_path, capsys):
    code = main(["--env", THREE, "--players", "geometric", "--episodes", "3", "--out", str(tmp_path),
                 "--gif-episodes", "0", "--quiet"])
    assert code == 0
    js = json.loads((tmp_path / "report.json").read_text())
    assert js["metric"] == "clear_rate" and js["results"][0]["episodes"] == 3
    assert "report:" in capsys.readouterr().out
