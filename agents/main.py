"""The main job: train the default agent on the one-ball scene, evaluate it against the baselines, report.

    python -m agents.main                       # what scripts/main.sh runs (about 15 minutes on 2 CPU cores)
    python -m agents.main --seconds 300 --episodes 500
    python -m agents.main --model runs/main/one_ball_sac-20250101-120000   # skip training, evaluate a run
    python -m agents.main --three-balls         # also train and evaluate the three-ball scene afterwards
    python -m agents.main --game nine-ball      # the 9-ball job instead: agents/nine_ball.py

Steps: (1) ``agents.train`` with ``configs/train/one_ball_sac.yaml`` under a time budget (``--seconds``,
default 780 CPU seconds of training, the config's ``budget_clock``), run folder
``runs/main/one_ball_sac-<timestamp>/``; (2) ``agents.evaluate`` of the trained agent (its best evaluation
checkpoint), the ``search``, ``geometric`` and ``random`` baselines on the same ``--episodes`` tables (fixed
seeds); (3) the table on stdout and the files in ``runs/main/``:
``report.md``, ``report.json``, ``learning_curve.png``, ``episodes.gif`` (``runs/main/three_balls/`` likewise).
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path
from typing import Any, Sequence

from .config import load_train_config
from .evaluate import build_players, evaluate
from .train import REPO_ROOT, train

DEFAULT_CONFIG = REPO_ROOT / "configs" / "train" / "one_ball_sac.yaml"
THREE_BALLS_CONFIG = REPO_ROOT / "configs" / "train" / "three_balls_sac.yaml"


def train_and_evaluate(config: Path, out: Path, seconds: float | None, episodes: int, seed: int,
                       model: str | None, baselines: Sequence[str], gif_episodes: int, progress: bool,
                       title: str) -> dict[str, Any]:
    t0 = time.perf_counter()
    if model is None:
        overrides: dict[str, Any] = {"run_root": str(out)}
        if seconds is not None:
            overrides["max_seconds"] = seconds
        cfg = load_train_config(config, overrides=overrides)
        meta = train(cfg, progress_bar=progress)
        model = meta["run_dir"]
    t_train = time.perf_counter() - t0
    players = build_players([model, *baselines], None, None)
    players[0].label = f"trained ({players[0].label})"
    report = evaluate(players, episodes, seed, out, gif_episodes=gif_episodes, title=title)
    report["main"] = {"train_wall_seconds": t_train, "eval_wall_seconds": time.perf_counter() - t0 - t_train,
                      "config": str(config), "run_dir": str(model)}
    (out / "report.json").write_text(json.dumps(report, indent=2, default=str))
    return report


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m agents.main", description=__doc__.split("\n\n")[0])
    p.add_argument("--config", default=str(DEFAULT_CONFIG), help="training config of the one-ball agent")
    p.add_argument("--seconds", type=float, default=None,
                   help="training time budget, in the config's budget_clock (default: the config's max_seconds)")
    p.add_argument("--episodes", type=int, default=1000, help="evaluation episodes per player")
    p.add_argument("--seed", type=int, default=100_000, help="evaluation episode k uses reset(seed=seed + k)")
    p.add_argument("--out", default=str(REPO_ROOT / "runs" / "main"), help="report folder (and run root)")
    p.add_argument("--model", help="evaluate this run folder / model instead of training")
    p.add_argument("--baselines", nargs="*", default=["search", "geometric", "random"])
    p.add_argument("--gif-episodes", type=int, default=3)
    p.add_argument("--three-balls", action="store_true", help="also train and evaluate BilliardsThreeBalls-v0")
    p.add_argument("--three-balls-seconds", type=float, default=None)
    p.add_argument("--three-balls-episodes", type=int, default=300)
    p.add_argument("--no-progress", action="store_true")
    p.add_argument("--game", choices=("one-ball", "nine-ball"), default="one-ball",
                   help="nine-ball: the 9-ball job instead (agents/nine_ball.py: curriculum training, league, report "
                        "in runs/main/nine_ball/)")
    from .nine_ball import add_arguments

    add_arguments(p)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if args.game == "nine-ball":
        from .nine_ball import main as nine_ball_main

        return nine_ball_main(args)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    rep = train_and_evaluate(Path(args.config), out, args.seconds, args.episodes, args.seed, args.model,
                             args.baselines, args.gif_episodes, not args.no_progress, "one ball, no noise")
    summaries = [("BilliardsOneBall-v0", out, rep)]
    if args.three_balls:
        out3 = out / "three_balls"
        out3.mkdir(parents=True, exist_ok=True)
        rep3 = train_and_evaluate(THREE_BALLS_CONFIG, out3, args.three_balls_seconds, args.three_balls_episodes,
                                  args.seed, None, args.baselines, 2, not args.no_progress,
                                  "three balls, 15-shot limit")
        summaries.append(("BilliardsThreeBalls-v0", out3, rep3))
    print("=" * 78)
    for env_id, folder, rep in summaries:
        tr = next(iter(rep.get("training", {}).values()), {})
        print(f"{env_id}: {rep['metric'].replace('_', ' ')} over {rep['episodes']} episodes")
        for r in rep["results"]:
            lo, hi = r["success_ci"]
            print(f"  {r['label']:<48} {100 * r['success_rate']:5.1f}%  [{100 * lo:.1f}, {100 * hi:.1f}]")
        if tr:
            clock = "CPU" if tr.get("clock") == "cpu" else "wall"
            print(f"  training: {tr.get('timesteps')} env steps, {tr.get('wall_seconds', 0):.0f} s {clock}, "
                  f"{tr.get('train_steps_per_second', 0):.0f} env steps/s")
        for k, v in rep["files"].items():
            print(f"  {k}: {v}")
    print(f"total {time.perf_counter() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
