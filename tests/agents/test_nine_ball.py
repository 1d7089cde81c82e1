"""The 9-ball job (agents/nine_ball.py, python -m agents.main --game nine-ball): its report pieces, and (slow) the
whole job on a tiny budget."""
from __future__ import annotations

import json
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import pytest  # noqa: E402

from agents.main import build_parser  # noqa: E402
from agents.nine_ball import plot_learning_curve, target_lines  # noqa: E402


def league(pairs):
    return {"pairs": [{"a": a, "b": b, "wins_a": wa, "wins_b": wb, "games": wa + wb} for a, b, wa, wb in pairs]}


def test_targets_name_each_figure_and_verdict():
    leagues = {"no_noise": league([("geometric", "search", 10, 30), ("geometric", "agent", 45, 55)]),
               "fastfiz": league([("search", "geometric", 20, 20), ("agent", "geometric", 70, 30)])}
    search, agent = target_lines(leagues, "agent")
    assert "search player beats" in search and "30/40 = **75%**" in search and "20/40 = **50%**" in search
    assert search.endswith("pass (interval includes 50%), **miss** |") or "**miss**" in search
    assert "55/100 = **55%**" in agent and "70/100 = **70%**" in agent
    assert "pass (interval includes 50%), pass |" in agent  # 55% [45, 65]; 70% [60, 78]


def test_learning_curve_marks_the_two_phases(tmp_path):
    evals = [{"timesteps": t, "mean_reward": r, "success_rate": s, "wall_seconds": t / 10}
             for t, r, s in ((100, 1.0, 0.0), (200, 1.5, 0.1), (300, 0.2, 0.4), (400, 0.4, 0.5))]
    (tmp_path / "progress.json").write_text(json.dumps({"evaluations": evals}))
    (tmp_path / "curriculum.json").write_text(json.dumps({"switch_step": 250}))
    neutral = {"practice": {"mean_reward": 1.2, "success_rate": 0.05},
               "vs_geometric": {"mean_reward": 0.0, "success_rate": 0.45}}
    path = plot_learning_curve(tmp_path, tmp_path / "curve.png", neutral)
    assert path is not None and path.stat().st_size > 10_000
    assert plot_learning_curve(tmp_path / "missing", tmp_path / "none.png", neutral) is None


def test_main_takes_the_game_option():
    args = build_parser().parse_args(["--game", "nine-ball", "--games", "4", "--runouts", "2", "--seconds", "30"])
    assert (args.game, args.games, args.runouts, args.seconds) == ("nine-ball", 4, 2, 30.0)
    assert build_parser().parse_args([]).game == "one-ball"  # the default job is unchanged


@pytest.mark.slow
def test_the_whole_job_on_a_tiny_budget(tmp_path, monkeypatch):
    import agents.nine_ball as nb
    from agents.config import load_train_config

    small = {"n_eval_episodes": 4, "eval_freq": 200, "n_eval_envs": 2}
    real = load_train_config

    def tiny(path, env_id=None, overrides=None, hyper_overrides=None):
        return real(path, env_id, {**(overrides or {}), **small},
                    {**(hyper_overrides or {}), "learning_starts": 50, "batch_size": 32, "n_envs": 2})

    monkeypatch.setattr("agents.config.load_train_config", tiny)
    rep = nb.run(tmp_path, 40.0, 0.6, 2, 2, 2, 0, None, 3, False, "test")
    for name in ("report.md", "report.json", "league_no_noise.md", "league_fastfiz.md", "learning_curve.png",
                 "game.gif"):
        assert (tmp_path / name).exists(), name
    md = (tmp_path / "report.md").read_text()
    assert "the search player beats the geometric player" in md and "a trained agent beats" in md
    assert rep["training"]["phases"]["vs_geometric"]["timesteps"] >= rep["training"]["switch_step"]
