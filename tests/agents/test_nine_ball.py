"""The 9-ball job (agents/nine_ball.py, python -m agents.main --game nine-ball): its report pieces, and (slow) the
whole job on a tiny budget."""
from __future__ import annotations

import json
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import pytest  # noqa: E402

from agents.main import build_parser  # noqa: E402
from agents.nine_ball import plot_learning_curve, prior_limits, target_lines  # noqa: E402


def league(pairs):
    return {"pairs": [{"a": a, "b": b, "wins_a": wa, "wins_b": wb, "games": wa + wb} for a, b, wa, wb in pairs]}


def test_targets_name_each_figure_and_verdict():
    leagues = {"no_noise": league([("geometric", "search", 10, 30), ("geometric", "agent", 45, 55),
                                   ("search", "prior", 18, 22)]),
               "olympiad": league([("search", "geometric", 20, 20), ("agent", "geometric", 70, 30),
                                   ("prior", "search", 30, 10)])}
    search, agent, prior, ms, job = target_lines(leagues, "agent", "prior", job_seconds=3000, decision_ms=0.7)
    assert "search player beats" in search and "30/40 = **75%**" in search and "20/40 = **50%**" in search
    assert "**missed**" in search
    assert "55/100 = **55%**" in agent and "70/100 = **70%**" in agent
    assert "| **missed**, met |" in agent  # 55% < 60%; 70% [60.4, 78] clears 60%
    assert "22/40 = **55%**" in prior and "30/40 = **75%**" in prior
    assert "met (interval includes the target), met" in prior  # 55% [40, 69]; 75% [60, 86]
    assert ms.endswith("| met |") and "50 min wall | met |" in job


def test_the_prior_limits_are_the_pairs_games():
    pair = {"a": "search", "b": "prior", "wins_a": 45, "wins_b": 55, "games": 100, "innings": (80, 75),
            "shots": (700, 650), "no_return": 60}
    lines = prior_limits({"no_noise": {"pairs": [pair]}, "olympiad": {"pairs": []}}, "prior")
    assert len(lines) == 1  # the setting without the pair says nothing
    # 60 of 100 games over before a return; the search's 80 innings, 45 of them won: 35 ended without the game
    assert "no noise: 60 of 100 games (60%)" in lines[0] and "35 times in 700 shots (one shot in 20" in lines[0]


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
@pytest.mark.parametrize("curriculum", [False, True])
def test_the_whole_job_on_a_tiny_budget(tmp_path, monkeypatch, curriculum):
    import yaml

    import agents.nine_ball as nb
    from agents.config import load_train_config

    small = {"n_eval_episodes": 4, "eval_freq": 200, "n_eval_envs": 2}
    real = load_train_config

    def tiny(path, env_id=None, overrides=None, hyper_overrides=None):
        return real(path, env_id, {**(overrides or {}), **small},
                    {**(hyper_overrides or {}), "learning_starts": 50, "batch_size": 32, "n_envs": 2})

    monkeypatch.setattr("agents.config.load_train_config", tiny)
    cfg = yaml.safe_load(nb.DISTILL_CONFIG.read_text())
    cfg["distill"].update(states=4, dagger_rounds=1, bc_epochs=2, eval_episodes=2, scorer_games=3,
                          scorer_dagger_games=2, scorer_ensemble=2, scorer_epochs=2)
    cfg["billiards"]["max_seconds"] = 20
    (tmp_path / "distill.yaml").write_text(yaml.safe_dump(cfg))
    rep = nb.run(tmp_path / "out", 20.0, 0.6, 2, 2, 2, 0, None, 3, False, "test", curriculum=curriculum, workers=2,
                 config=tmp_path / "distill.yaml")
    out = tmp_path / "out"
    for name in ("report.md", "report.json", "league_no_noise.md", "league_olympiad.md", "learning_curve.png",
                 "game.gif"):
        assert (out / name).exists(), name
    md = (out / "report.md").read_text()
    assert "the search player beats the geometric player" in md and "the trained policy alone wins" in md
    assert "search with the learned prior" in md and "the 9-ball job <= 60 min" in md
    if curriculum:
        assert rep["training"]["phases"]["vs_geometric"]["timesteps"] >= rep["training"]["switch_step"]
    else:
        assert [s["stage"] for s in rep["training"]["stages"]] == ["bc", "dagger round 1", "rl fine-tuning"]
        assert "What limits the trained agent" in md
        scorer = rep["training"]["scorer"]  # the option scorer is the league's trained policy
        assert scorer["ensemble"] == 2 and scorer["labels"] > 0
        assert any(n.startswith("scorer(") for n in rep["leagues"]["no_noise"]["elo"])
