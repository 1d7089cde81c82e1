"""The 9-ball job (``python -m agents.main --game nine-ball``): train the 9-ball agent, play the league, report.

    python -m agents.main --game nine-ball                      # the whole job (see DEFAULT_SECONDS and the league)
    python -m agents.main --game nine-ball --seconds 600 --games 40 --runouts 40      # shorter
    python -m agents.main --game nine-ball --model runs/main/nine_ball/<run>          # skip training

Steps:

1. Training (SB3 SAC, ``agents.train``), a curriculum in one run folder ``<out>/nine_ball_sac-<stamp>/``: run-out
   practice (``configs/train/nine_ball_sac.yaml``: ``opponent=None``, the ``ball_in_hand`` opening, shaping for
   pots, fouls and position) for ``practice_fraction`` of the budget, then games against the geometric player
   (``configs/train/nine_ball_sac_vs_geometric.yaml``, resumed from the practice model) for the rest. Both under
   the spin model with the FastFiz-like shot noise, in the ``candidates`` action and observation types.
2. The neutral policy (action 0: the geometric player's own choice in that action type) on the same evaluation
   episodes, for the learning curve's reference lines.
3. The league (:mod:`agents.league`) of random, geometric, search and the trained agent (its best evaluation
   checkpoint: :func:`_league_model`), under the spin model, without noise and with the FastFiz-like noise:
   head-to-head win rates with Wilson intervals, Elo, break-and-run and run-out-from-ball-in-hand rates, decision
   times.
4. Files in ``<out>`` (default ``runs/main/nine_ball``): ``report.md`` / ``report.json`` (the targets, each with its
   figure), ``league_no_noise.md/json``, ``league_fastfiz.md/json``, ``learning_curve.png`` and ``game.gif`` (the
   trained agent playing a rack against the geometric player, with the game panel).
"""
from __future__ import annotations

import json
import sys
import time
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from .evaluate import wilson_interval
from .train import REPO_ROOT

PRACTICE_CONFIG = REPO_ROOT / "configs" / "train" / "nine_ball_sac.yaml"
MATCH_CONFIG = REPO_ROOT / "configs" / "train" / "nine_ball_sac_vs_geometric.yaml"
#: Training budget of the default job: CPU seconds of the training process, both phases (the configs' budget_clock;
#: wall seconds on an idle machine, where torch and numba run on one thread).
DEFAULT_SECONDS = 1800.0
BASELINES = ("random", "geometric", "search")
SETTINGS = (("no_noise", "0"), ("fastfiz", "fastfiz"))


def train_curriculum(out: Path, seconds: float, practice_fraction: float, progress: bool) -> dict[str, Any]:
    """Phase 1 (run-out practice) then phase 2 (against the geometric player) in one run folder; the run summary."""
    from .config import load_train_config
    from .train import train

    t1 = seconds * practice_fraction
    cfg1 = load_train_config(PRACTICE_CONFIG, overrides={"run_root": str(out), "max_seconds": t1})
    meta1 = train(cfg1, progress_bar=progress)
    run_dir = Path(meta1["run_dir"])
    cfg2 = load_train_config(MATCH_CONFIG, overrides={"run_root": str(out), "max_seconds": seconds})
    meta2 = train(cfg2, resume=run_dir, progress_bar=progress)
    phases = {"practice": {k: meta1.get(k) for k in ("timesteps", "wall_seconds", "train_steps_per_second")},
              "vs_geometric": {k: meta2.get(k) for k in ("timesteps", "wall_seconds", "train_steps_per_second")}}
    (run_dir / "curriculum.json").write_text(json.dumps({"phases": phases, "switch_step": meta1["timesteps"],
                                                          "switch_seconds": meta1["wall_seconds"]}, indent=2))
    return {"run_dir": str(run_dir), "phases": phases, "switch_step": meta1["timesteps"]}


def neutral_baseline(config: Path, episodes: int) -> dict[str, float]:
    """The neutral policy (action 0: the geometric player's shot, placement and break in the candidates types) on
    the evaluation episodes of ``config`` (its eval seeds): mean return and success rate."""
    import gymnasium as gym

    import billiards_env  # noqa: F401

    from .config import load_train_config

    cfg = load_train_config(config)
    env = gym.make(cfg.env_id, **cfg.env_kwargs)
    rets, wins = [], 0
    for k in range(episodes):
        env.reset(seed=cfg.settings.eval_seed + k)
        done, ret = False, 0.0
        while not done:
            _, r, term, trunc, info = env.step(np.zeros(env.action_space.shape, np.float32))
            ret += r
            done = term or trunc
        rets.append(ret)
        wins += bool(info.get("is_success"))
    env.close()
    return {"mean_reward": float(np.mean(rets)), "success_rate": wins / max(episodes, 1)}


def plot_learning_curve(run_dir: Path, path: Path, neutral: dict[str, dict[str, float]]) -> Path | None:
    """Evaluation return and success against env steps (both phases), with the neutral policy's levels."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    prog = run_dir / "progress.json"
    if not prog.exists():
        return None
    evals = json.loads(prog.read_text()).get("evaluations", [])
    if not evals:
        return None
    cur = run_dir / "curriculum.json"
    switch = json.loads(cur.read_text())["switch_step"] if cur.exists() else None
    ts = np.array([e["timesteps"] for e in evals])
    fig, axes = plt.subplots(2, 1, figsize=(8, 6.5), dpi=100, sharex=True)
    for ax, key, label in ((axes[0], "mean_reward", "evaluation return (deterministic)"),
                           (axes[1], "success_rate", "evaluation success")):
        y = np.array([e.get(key, np.nan) for e in evals], dtype=float)
        for phase, mask, color in (("run-out practice", ts <= (switch if switch is not None else np.inf),
                                    "tab:blue"),
                                   ("vs geometric", ts > (switch if switch is not None else np.inf), "tab:red")):
            if mask.any():
                ax.plot(ts[mask], y[mask], "o-", color=color, lw=2, ms=3, label=f"agent, {phase}")
        for name, color, (lo, hi) in (("practice", "tab:blue", (0, switch)), ("vs_geometric", "tab:red",
                                                                                (switch, None))):
            if name in neutral and lo is not None:
                ax.hlines(neutral[name][key], lo, hi if hi is not None else ts.max(), colors=color, linestyles="--",
                          lw=1, label=f"neutral action (the geometric player's choice), {name.replace('_', ' ')}")
        if switch is not None:
            ax.axvline(switch, color="gray", lw=1, ls=":")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[1].set_ylim(-0.02, 1.02)
    axes[1].set_xlabel("environment steps (agent shots)")
    axes[0].legend(fontsize=7, loc="best")
    axes[0].set_title("9-ball SAC: run-out practice (success = run-out), then games vs geometric (success = win)",
                      fontsize=9)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path)
    plt.close(fig)
    return path


def record_game(model_path: str, path: Path, seed: int) -> dict[str, Any]:
    """A GIF of the trained agent playing a rack (it breaks) against the geometric player, with the game panel."""
    import gymnasium as gym

    import billiards_env  # noqa: F401
    from billiards_env.envs.recording import GIF_RENDER, record_gif

    from .evaluate import model_player

    spec = model_player(model_path)
    kw = {k: v for k, v in spec.env_kwargs.items() if k not in ("opponent", "opening", "first_shooter")}
    env = gym.make(spec.env_id, render_mode="rgb_array_list", **{**GIF_RENDER, **kw, "opponent": "geometric",
                                                                  "opening": "break", "first_shooter": "agent"})
    try:
        return record_gif(env, lambda obs: spec.act(env, obs), path, [seed], max_shots=40)
    finally:
        env.close()


def _pair(report: dict[str, Any], a: str, b: str) -> tuple[int, int, int] | None:
    for p in report["pairs"]:
        if (p["a"], p["b"]) == (a, b):
            return p["wins_a"], p["games"], p["wins_b"]
        if (p["a"], p["b"]) == (b, a):
            return p["wins_b"], p["games"], p["wins_a"]
    return None


def target_lines(leagues: dict[str, dict[str, Any]], trained: str) -> list[str]:
    lines = []
    for title, a in (("the search player beats the geometric player", "search"),
                     ("a trained agent beats the geometric player head-to-head (> 50% of games)", trained)):
        figures = []
        verdicts = []
        for setting, rep in leagues.items():
            r = _pair(rep, a, "geometric")
            if r is None:
                continue
            w, n, _ = r
            lo, hi = wilson_interval(w, n)
            figures.append(f"{setting.replace('_', ' ')}: {w}/{n} = **{100 * w / n:.0f}%** [{100 * lo:.0f}, "
                           f"{100 * hi:.0f}]")
            verdicts.append("pass" if w / n > 0.5 and lo > 0.5 else ("pass (interval includes 50%)"
                                                                      if w / n > 0.5 else "**miss**"))
        lines.append(f"| {title} | {'; '.join(figures)} | {', '.join(verdicts)} |")
    return lines


def _league_model(run_dir: Path) -> Path:
    """The model a run plays the league with: its best evaluation checkpoint (EvalCallback's, on the evaluation
    games against the geometric player: seeds apart from the league's racks), as the one-ball job plays; else the
    final model; else the folder itself (an RLlib run)."""
    for name in ("best_model.zip", "final_model.zip"):
        if (run_dir / name).exists():
            return run_dir / name
    return run_dir


def run(out: Path, seconds: float, practice_fraction: float, games: int, search_games: int, runouts: int,
        seed: int, model: str | None, gif_seed: int, progress: bool, command: str) -> dict[str, Any]:
    from .league import run_league

    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    train_info: dict[str, Any] = {}
    if model is None:
        train_info = train_curriculum(out, seconds, practice_fraction, progress)
        run_dir = Path(train_info["run_dir"])
        model = str(_league_model(run_dir))
    else:
        p = Path(model)
        run_dir = p if p.is_dir() else p.parent
        if p.is_dir():
            model = str(_league_model(p))
    t_train = time.perf_counter() - t0
    print("neutral policy on the evaluation episodes...", flush=True)
    neutral = {"practice": neutral_baseline(PRACTICE_CONFIG, 100),
               "vs_geometric": neutral_baseline(MATCH_CONFIG, 100)}
    curve = plot_learning_curve(run_dir, out / "learning_curve.png", neutral)
    leagues = {}
    for name, noise in SETTINGS:
        rep = run_league("nine_ball", [*BASELINES, model], games, seed, noise, out / f"league_{name}",
                         runouts=runouts, command=f"{command} (league {name})",
                         pair_games={"search": search_games})
        for ext in ("md", "json"):
            (out / f"league_{name}.{ext}").write_text((out / f"league_{name}" / f"league.{ext}").read_text())
        leagues[name] = rep
    trained = next(n for n in leagues[SETTINGS[0][0]]["elo"] if n not in BASELINES)
    gif = record_game(model, out / "game.gif", gif_seed)
    total = time.perf_counter() - t0
    report = {"command": command, "model": model, "run_dir": str(run_dir), "training": train_info,
              "train_wall_seconds": t_train, "total_wall_seconds": total, "neutral": neutral,
              "leagues": {k: {"elo": v["elo"], "pairs": v["pairs"], "run_outs": v["run_outs"],
                              "info": v["info"]} for k, v in leagues.items()},
              "files": {"learning_curve": str(curve) if curve else None, "gif": gif["path"],
                        **{f"league_{k}": str(out / f"league_{k}.md") for k, _ in SETTINGS}}}
    (out / "report.json").write_text(json.dumps(report, indent=2, default=str))
    (out / "report.md").write_text(markdown(report, leagues, trained))
    return report


def markdown(report: dict[str, Any], leagues: dict[str, dict[str, Any]], trained: str) -> str:
    tr = report.get("training") or {}
    lines = ["# 9-ball: agents, league, targets", "",
             f"Command: `{report['command']}`; total {report['total_wall_seconds']:.0f} s wall "
             f"(training {report['train_wall_seconds']:.0f} s). Trained agent: `{report['model']}`.", ""]
    if tr:
        ph = tr["phases"]
        lines += [f"Training (SB3 SAC, candidates action/observation types, spin model, FastFiz-like noise): run-out "
                  f"practice {ph['practice']['timesteps']} shots in {ph['practice']['wall_seconds']:.0f} CPU s, then "
                  f"games against the geometric player up to {ph['vs_geometric']['timesteps']} shots, "
                  f"{ph['vs_geometric']['wall_seconds']:.0f} CPU s in all.", ""]
    lines += ["## Targets", "", "| target | figure (win rate against geometric [95% Wilson interval]) | verdict |",
              "|---|---|---|", *target_lines(leagues, trained), ""]
    n = report["neutral"]
    lines += [f"Reference (learning curve): the neutral action (the geometric player's own choice in the agent's "
              f"action type) scores {n['practice']['mean_reward']:.2f} return / {100 * n['practice']['success_rate']:.0f}% "
              f"run-outs in practice and {n['vs_geometric']['mean_reward']:.2f} / "
              f"{100 * n['vs_geometric']['success_rate']:.0f}% wins against geometric, on the evaluation episodes.",
              ""]
    for name, _ in SETTINGS:
        lines += [f"## League, {name.replace('_', ' ')}", "",
                  (Path(report["files"][f"league_{name}"]).read_text().split("\n", 2)[2]), ""]
    lines += ["## Files", ""] + [f"- {k}: `{v}`" for k, v in report["files"].items() if v]
    return "\n".join(lines) + "\n"


def add_arguments(p: Any) -> None:
    g = p.add_argument_group("--game nine-ball")
    g.add_argument("--practice-fraction", type=float, default=0.7,
                   help="nine-ball: share of the training budget spent on run-out practice (the rest: games vs "
                        "geometric)")
    g.add_argument("--games", type=int, default=100, help="nine-ball: league games per pair and setting")
    g.add_argument("--search-games", type=int, default=60, help="nine-ball: games of the pairs with the search "
                                                                "player (slower)")
    g.add_argument("--runouts", type=int, default=100, help="nine-ball: racks of the run-out test per player")
    g.add_argument("--gif-seed", type=int, default=3)


def main(args: Any) -> int:
    out = Path(args.out) if args.out != str(REPO_ROOT / "runs" / "main") else REPO_ROOT / "runs" / "main" / "nine_ball"
    seconds = args.seconds if args.seconds is not None else DEFAULT_SECONDS
    command = "python -m agents.main " + " ".join(sys.argv[1:])
    rep = run(out, seconds, args.practice_fraction, args.games, args.search_games, args.runouts, 0, args.model,
              args.gif_seed, not args.no_progress, command)
    print((out / "report.md").read_text())
    print(f"total {rep['total_wall_seconds']:.0f} s; files in {out}")
    return 0


__all__ = ["run", "train_curriculum", "neutral_baseline", "plot_learning_curve", "record_game", "main",
           "add_arguments", "DEFAULT_SECONDS"]
