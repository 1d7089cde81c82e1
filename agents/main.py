"""The main job: train the default agent on the one-ball scene, evaluate it against the baselines, report.

    python -m agents.main                       # what scripts/main.sh runs (about 15 minutes on 2 CPU cores)
    python -m agents.main --seconds 300 --episodes 500
    python -m agents.main --model runs/main/one_ball_sac_path-20250101-120000   # skip training, evaluate a run
    python -m agents.main --three-balls         # also train and evaluate the three-ball scene afterwards
    python -m agents.main --game nine-ball      # the 9-ball job instead: agents/nine_ball.py

Steps: (1) the agent of ``configs/train/one_ball_sac_path.yaml``: when the config has a ``distill:`` section,
behaviour cloning from the search player's shots first (:mod:`agents.distill`: the teacher's labels on its own
tables, in the agent's action type), then ``agents.train`` from the cloned policy under the time budget
(``--seconds``, default the config's ``max_seconds``, in its ``budget_clock``: CPU seconds), run folder
``runs/main/<name>-<timestamp>/``; (2) ``agents.evaluate`` of the trained agent (its best evaluation checkpoint),
the search player acting in the agent's own action type (its teacher), and the ``search``, ``geometric`` and
``random`` baselines on the plain env (absolute aim, the full speed range), all on the same ``--episodes`` tables
(fixed seeds); (3) the agent's decision time (its observation's features and the policy's forward pass); (4) the
table and the targets on stdout, and the files in ``runs/main/``: ``report.md``, ``report.json``,
``learning_curve.png``, ``episodes.gif`` (``runs/main/three_balls/`` likewise).
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from .config import load_train_config
from .evaluate import build_players, evaluate
from .player_spec import PlayerSpec, env_factory
from .train import REPO_ROOT, train

DEFAULT_CONFIG = REPO_ROOT / "configs" / "train" / "one_ball_sac_path.yaml"
THREE_BALLS_CONFIG = REPO_ROOT / "configs" / "train" / "three_balls_sac.yaml"

#: The one-ball targets: the trained policy's pocket rate on the job's tables, its decision time, and
#: the whole job's wall time on 2 cores.
TARGET_RATE = 0.985
TARGET_MS = 1.0
TARGET_JOB_SECONDS = 15 * 60


def train_agent(config: Path, out: Path, seconds: float | None, progress: bool) -> dict[str, Any]:
    """Train the config's agent (after behaviour cloning when the config has a ``distill:`` section; a budget
    below the config's labels that many fewer tables); returns ``{"run_dir", "distill": the distillation report or
    None, "seconds": wall seconds}``."""
    t0 = time.perf_counter()
    overrides: dict[str, Any] = {"run_root": str(out)}
    if seconds is not None:
        overrides["max_seconds"] = seconds
    cfg = load_train_config(config, overrides=overrides)
    d = cfg.extra.get("distill")
    if d:
        from .distill import distill

        states = int(d.get("states", 3000))
        full = float(load_train_config(config).settings.max_seconds or 0.0)
        if seconds is not None and full > 0 and seconds < full:  # a shorter job labels fewer tables too
            states = max(20, round(states * seconds / full))
        rep = distill(cfg, teacher=d.get("teacher", "search"), states=states,
                      bc_epochs=int(d.get("bc_epochs", 40)), rl_seconds=cfg.settings.max_seconds,
                      actor_delay=int(d.get("actor_delay", 20_000)),
                      workers=int(d.get("workers", 0)) or (os.cpu_count() or 1),
                      eval_episodes=int(d.get("eval_episodes", 1000)), eval_seed=cfg.settings.eval_seed)
        return {"run_dir": rep["run_dir"], "distill": rep, "seconds": time.perf_counter() - t0}
    meta = train(cfg, progress_bar=progress)
    return {"run_dir": meta["run_dir"], "distill": None, "seconds": time.perf_counter() - t0}


def teacher_player(model: PlayerSpec, name: str = "search", seed: int = 0) -> PlayerSpec | None:
    """The baseline ``name`` acting in a trained player's own env (its action type and wrappers): the search player
    there is the distillation's teacher. None for a model without a run config."""
    from billiards_env.players import make_player

    if model.run_dir is None or not (model.run_dir / "config.yaml").exists():
        return None
    from .config import parse_hyperparams

    setup = parse_hyperparams(load_train_config(model.run_dir / "config.yaml"))
    player = make_player(name, seed=seed)
    return PlayerSpec(f"{name}, in the agent's action type", "baseline",
                      env_factory(model.env_id, model.env_kwargs, setup.wrapper), player.act, player.reset,
                      env_id=model.env_id, env_kwargs=model.env_kwargs)


def decision_ms(spec: PlayerSpec, tables: int, seed: int) -> dict[str, float]:
    """A trained player's decision time on ``tables`` tables (median over them, ms of the deciding thread's CPU
    time, so that other work on the machine does not count; torch runs on this thread): its observation's features
    computed from the table state from scratch (the observation type's ``observe``, nothing of the table cached) and
    the policy's forward pass."""
    import torch

    threads = torch.get_num_threads()
    torch.set_num_threads(1)  # the policy on this thread: its CPU time is the thread's
    env = spec.make_env()
    u = env.unwrapped
    feats, policy = [], []
    try:
        for k in range(tables):
            env.reset(seed=seed + k)
            memo = getattr(getattr(u.table_state, "view", None), "memo", None)
            if memo is not None:  # what reset computed of this table (the candidate shots) is computed again
                memo.clear()
            t0 = time.thread_time()
            obs = u.observation_type.observe(u.table_state)
            t1 = time.thread_time()
            spec.act(env, obs)
            t2 = time.thread_time()
            feats.append(t1 - t0)
            policy.append(t2 - t1)
    finally:
        env.close()
        torch.set_num_threads(threads)
    f, p = 1000 * float(np.median(feats)), 1000 * float(np.median(policy))
    return {"features_ms": f, "policy_ms": p, "decision_ms": f + p, "tables": tables}


def train_and_evaluate(config: Path, out: Path, seconds: float | None, episodes: int, seed: int,
                       model: str | None, baselines: Sequence[str], gif_episodes: int, progress: bool,
                       title: str, baseline_kwargs: dict[str, Any] | None = None,
                       teacher: bool = False) -> dict[str, Any]:
    """Train (unless ``model``), evaluate beside the baselines (on ``baseline_kwargs``: None plays them on the
    model's env kwargs) and, with ``teacher``, the search player in the agent's own action type."""
    t0 = time.perf_counter()
    trained: dict[str, Any] = {"run_dir": model, "distill": None, "seconds": 0.0}
    if model is None:
        trained = train_agent(config, out, seconds, progress)
        model = trained["run_dir"]
    t_train = time.perf_counter() - t0
    players = build_players([model, *baselines], None, baseline_kwargs)
    players[0].label = f"trained ({players[0].label})"
    if baseline_kwargs is not None:
        where = "plain env" if not baseline_kwargs else json.dumps(baseline_kwargs)
        for p in players[1:]:
            p.label = f"{p.label} ({where})"
    if teacher and "search" in baselines:
        t = teacher_player(players[0])
        if t is not None:
            players.insert(1, t)
    report = evaluate(players, episodes, seed, out, gif_episodes=gif_episodes, title=title)
    timing = decision_ms(players[0], min(episodes, 300), seed)
    report["decision"] = timing
    report["main"] = {"train_wall_seconds": t_train, "eval_wall_seconds": time.perf_counter() - t0 - t_train,
                      "config": str(config), "run_dir": str(model), "distill": trained["distill"]}
    (out / "report.json").write_text(json.dumps(report, indent=2, default=str))
    return report


def cpu_seconds() -> float:
    """CPU seconds of this process and of its finished children (the labelling workers)."""
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


def target_lines(rep: dict[str, Any], job_seconds: float, job_cpu: float | None = None) -> list[str]:
    """The one-ball targets with the job's figures (met / missed). The job's time: wall seconds, and the CPU seconds
    of its processes (what it costs a machine that others share, where the wall time is not its own)."""
    r = rep["results"][0]
    lo, hi = r["success_ci"]
    d = rep["decision"]
    ok = lambda b: "met" if b else "MISSED"  # noqa: E731
    return [
        f"  pocket rate >= {100 * TARGET_RATE:.1f}% on {r['episodes']} tables: {100 * r['success_rate']:.1f}% "
        f"[{100 * lo:.1f}, {100 * hi:.1f}]  {ok(r['success_rate'] >= TARGET_RATE)}",
        f"  decision <= {TARGET_MS:.0f} ms: {d['decision_ms']:.2f} ms (features {d['features_ms']:.2f} + policy "
        f"{d['policy_ms']:.2f}, median of {d['tables']} tables)  {ok(d['decision_ms'] <= TARGET_MS)}",
        f"  job <= {TARGET_JOB_SECONDS // 60} min on 2 cores: {job_seconds / 60:.1f} min wall"
        + (f", {job_cpu / 60:.1f} min of CPU (load average at the end {os.getloadavg()[0]:.1f})"
           if job_cpu is not None else "")
        + f"  {ok(job_seconds <= TARGET_JOB_SECONDS or (job_cpu is not None and job_cpu <= TARGET_JOB_SECONDS))}",
    ]


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
    c0 = cpu_seconds()
    rep = train_and_evaluate(Path(args.config), out, args.seconds, args.episodes, args.seed, args.model,
                             args.baselines, args.gif_episodes, not args.no_progress, "one ball, no noise",
                             baseline_kwargs={}, teacher=True)
    summaries = [("BilliardsOneBall-v0", out, rep)]
    if args.three_balls:
        out3 = out / "three_balls"
        out3.mkdir(parents=True, exist_ok=True)
        rep3 = train_and_evaluate(THREE_BALLS_CONFIG, out3, args.three_balls_seconds, args.three_balls_episodes,
                                  args.seed, None, args.baselines, 2, not args.no_progress,
                                  "three balls, 15-shot limit")
        summaries.append(("BilliardsThreeBalls-v0", out3, rep3))
    print("=" * 78)
    for env_id, folder, r_env in summaries:
        tr = next(iter(r_env.get("training", {}).values()), {})
        print(f"{env_id}: {r_env['metric'].replace('_', ' ')} over {r_env['episodes']} episodes")
        for r in r_env["results"]:
            lo, hi = r["success_ci"]
            print(f"  {r['label']:<48} {100 * r['success_rate']:5.1f}%  [{100 * lo:.1f}, {100 * hi:.1f}]")
        if tr:
            clock = "CPU" if tr.get("clock") == "cpu" else "wall"
            print(f"  training: {tr.get('timesteps')} env steps, {tr.get('wall_seconds', 0):.0f} s {clock}, "
                  f"{tr.get('train_steps_per_second', 0):.0f} env steps/s")
        for k, v in r_env["files"].items():
            print(f"  {k}: {v}")
    total = time.perf_counter() - t0
    cpu = cpu_seconds() - c0
    dist = rep["main"].get("distill")
    if dist:
        print("distillation (one ball, evaluation tables of the training run):")
        for st in dist["stages"]:
            if "success_rate" in st:
                print(f"  {st['stage']:<16} {100 * st['success_rate']:5.1f}% on {st['episodes']} tables")
    print("targets (one ball):")
    lines = target_lines(rep, total, cpu)
    for line in lines:
        print(line)
    (out / "targets.txt").write_text("\n".join(lines) + "\n")
    print(f"total {total:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
