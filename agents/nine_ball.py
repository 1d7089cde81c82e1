"""The 9-ball job (``python -m agents.main --game nine-ball``): train the 9-ball agent, play the league, report.

    python -m agents.main --game nine-ball                      # the whole job (see the config and the league)
    python -m agents.main --game nine-ball --seconds 600 --games 100 --search-games 20 --runouts 40   # shorter
    python -m agents.main --game nine-ball --model runs/main/nine_ball/<run>          # skip training
    python -m agents.main --game nine-ball --curriculum         # the earlier agent: RL only, practice then games

Steps:

1. Training, in one run folder ``<out>/<name>-distill-<stamp>/``: distillation of the search player
   (``configs/train/nine_ball_distill.yaml`` and its ``distill:`` section; :mod:`agents.distill`): the search
   player's shots in the agent's action type on the states of games against the geometric player, behaviour
   cloning, DAgger rounds played by the student, then SAC against the geometric player from the cloned policy for the
   config's budget (CPU seconds). Spin model, FastFiz's level-1 noise (``noise: olympiad``), the ``candidates``
   action type and the ``candidates_position`` observation. Then, when the ``distill:`` section asks for it
   (``scorer_games``), the option scorer (:func:`train_scorer`, :mod:`agents.scorer`): more games labelled by the
   teacher (its place with ball in hand too), a DAgger round played by a first scorer, the SAC clone of all the
   labels (its fallback where no place has a pot) and an ensemble of fits, in ``<run>/scorer.pt``.
   ``--curriculum``: the earlier RL-only agent (run-out practice, then games).
2. The league (:mod:`agents.league`, on every core) of random, geometric, search, the trained policy (the option
   scorer when the run has one, else the SAC agent's best evaluation checkpoint) and the search player with the
   trained policy as its prior (:mod:`agents.prior_search`), under the
   spin model, without noise and with ``noise="olympiad"``: head-to-head win rates with Wilson intervals, Elo,
   break-and-run, balls per inning, run-outs from ball in hand, decision times.
3. Files in ``<out>`` (default ``runs/main/nine_ball``): ``report.md`` / ``report.json`` (every target with its
   figure and, where missed, what limits it), ``league_no_noise.md/json``, ``league_olympiad.md/json``,
   ``learning_curve.png`` and ``game.gif`` (the trained agent playing a rack against the geometric player).
"""
from __future__ import annotations

import json
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

from .evaluate import wilson_interval
from .train import REPO_ROOT

PRACTICE_CONFIG = REPO_ROOT / "configs" / "train" / "nine_ball_sac.yaml"
MATCH_CONFIG = REPO_ROOT / "configs" / "train" / "nine_ball_sac_vs_geometric.yaml"
DISTILL_CONFIG = REPO_ROOT / "configs" / "train" / "nine_ball_distill.yaml"
#: Training budget of the curriculum (``--curriculum``): CPU seconds of the training process, both phases (the
#: configs' budget_clock; wall seconds on an idle machine, where torch and numba run on one thread). The
#: distillation's RL budget is its config's ``max_seconds``.
DEFAULT_SECONDS = 1800.0
BASELINES = ("random", "geometric", "search")
SETTINGS = (("no_noise", "0"), ("olympiad", "olympiad"))
#: The 9-ball targets: the trained policy alone against the geometric player, the search with the
#: learned prior against the search player, the job's wall time on 2 cores.
TARGET_VS_GEOMETRIC = 0.60
TARGET_PRIOR_VS_SEARCH = 0.55
TARGET_JOB_SECONDS = 60 * 60


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


def train_distilled(out: Path, seconds: float | None, config: Path = DISTILL_CONFIG,
                    workers: int | None = None) -> dict[str, Any]:
    """Distillation then RL (:mod:`agents.distill`, the config's ``distill:`` section); ``seconds`` overrides the RL
    budget. Returns the distillation report (``run_dir``, ``stages``)."""
    import os

    from .config import load_train_config
    from .distill import distill

    overrides: dict[str, Any] = {"run_root": str(out)}
    if seconds is not None:
        overrides["max_seconds"] = seconds
    cfg = load_train_config(config, overrides=overrides)
    d = cfg.extra.get("distill") or {}
    workers = workers or os.cpu_count() or 1
    rep = distill(cfg, teacher=d.get("teacher", "search"), states=int(d.get("states", 240)),
                  dagger_rounds=int(d.get("dagger_rounds", 1)), beta=float(d.get("beta", 0.0)),
                  bc_epochs=int(d.get("bc_epochs", 60)), rl_seconds=cfg.settings.max_seconds,
                  actor_delay=int(d.get("actor_delay", 20_000)), workers=workers,
                  eval_episodes=int(d.get("eval_episodes", 100)), eval_seed=cfg.settings.eval_seed)
    if int(d.get("scorer_games", 0)) > 0:
        rep["scorer"] = train_scorer(config, Path(rep["run_dir"]), d, workers)
        (Path(rep["run_dir"]) / "distill.json").write_text(json.dumps(rep, indent=2, default=str))
    return rep


#: Seeds of the scorer's extra labelling games (apart from the distillation's, 1,000,000 on, and the evaluations').
SCORER_LABEL_SEED = 1_500_000


def train_scorer(config: Path, run_dir: Path, d: dict[str, Any], workers: int) -> dict[str, Any]:
    """The option scorer (:mod:`agents.scorer`) from the distillation's labels and more: the teacher labels
    ``scorer_games`` more games it plays, a first scorer is fitted, it plays ``scorer_dagger_games`` games labelled by
    the teacher (DAgger), the SAC clone of all the labels is made (the scorer's fallback for ball in hand, in
    ``<run>/clone``) and ``scorer_ensemble`` fits on all the labels are summed into ``<run>/scorer.pt``. Returns its
    path, the labels and the fits' agreement with the teacher."""
    import time as _time

    import numpy as np

    from .config import load_train_config, parse_hyperparams
    from .distill import collect_labels, distill
    from .option_policies import Scorer, fit

    cfg = load_train_config(config, overrides={"run_root": str(run_dir)})
    setup = parse_hyperparams(cfg)
    teacher = d.get("teacher", "search")
    t0 = _time.perf_counter()
    with np.load(run_dir / "labels.npz") as f:
        parts = [{k: f[k] for k in f.files}]
    n_games = int(d.get("scorer_games", 0))
    seeds = range(SCORER_LABEL_SEED, SCORER_LABEL_SEED + n_games)
    parts.append(collect_labels(cfg.env_id, setup.env_kwargs, None, teacher, seeds, workers=workers))
    ensemble = max(int(d.get("scorer_ensemble", 3)), 1)
    epochs = int(d.get("scorer_epochs", 60))

    def merged() -> dict[str, Any]:  # the keys every part has (ball-in-hand labels: agents.distill.label_episodes)
        return {k: np.concatenate([p[k] for p in parts]) for k in parts[0] if all(k in p for p in parts)}

    def fit_all(data: dict[str, Any], seed: int) -> tuple[Any, dict[str, Any]]:
        return fit(data["obs"], data["actions"], epochs, seed=seed, hand_obs=data.get("hand_obs"),
                   hand_target=data.get("hand_target"))

    n_dagger = int(d.get("scorer_dagger_games", 0))
    if n_dagger > 0:
        data = merged()
        first = run_dir / "scorer_round0.pt"
        Scorer([fit_all(data, 0)[0]]).save(first)
        seeds = range(SCORER_LABEL_SEED + n_games, SCORER_LABEL_SEED + n_games + n_dagger)
        parts.append(collect_labels(cfg.env_id, setup.env_kwargs, None, teacher, seeds, student=f"scorer:{first}",
                                    workers=workers))
    data = merged()
    labels = run_dir / "scorer_labels.npz"
    np.savez_compressed(labels, **data)
    clone = distill(cfg, teacher=teacher, dagger_rounds=0, bc_epochs=int(d.get("bc_epochs", 60)), rl_seconds=0.0,
                    workers=1, eval_episodes=0, run_dir=run_dir / "clone", quiet=True, labels=labels)
    nets, agreement, hand_agreement = [], [], []
    for k in range(ensemble):
        net, info = fit_all(data, k)
        nets.append(net)
        agreement.append(info["holdout_agreement"])
        hand_agreement.append(info.get("hand_holdout_agreement", float("nan")))
    path = run_dir / "scorer.pt"
    Scorer(nets, Path(clone["run_dir"]) / "bc_model.zip").save(path)
    return {"path": str(path), "labels": int(len(data["obs"])), "extra_games": n_games, "dagger_games": n_dagger,
            "ensemble": ensemble, "holdout_agreement": agreement, "hand_labels": int(len(data.get("hand_target", []))),
            "hand_holdout_agreement": hand_agreement, "wall_seconds": _time.perf_counter() - t0}


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
        phases = ((("run-out practice", ts <= switch, "tab:blue"), ("vs geometric", ts > switch, "tab:red"))
                  if switch is not None else (("vs geometric", ts >= 0, "tab:red"),))
        for phase, mask, color in phases:
            if mask.any():
                ax.plot(ts[mask], y[mask], "o-", color=color, lw=2, ms=3, label=f"agent, {phase}")
        for name, color, (lo, hi) in (("practice", "tab:blue", (0, switch)), ("vs_geometric", "tab:red",
                                                                                (switch or 0, None))):
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
    axes[0].set_title("9-ball SAC: run-out practice (success = run-out), then games vs geometric (success = win)"
                      if switch is not None else "9-ball SAC from the cloned policy: games vs geometric (success = win)",
                      fontsize=9)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path)
    plt.close(fig)
    return path


def record_game(model_path: str, path: Path, seed: int) -> dict[str, Any]:
    """A GIF of the trained agent (an SB3 model, or ``scorer:<file>``: an option scorer) playing a rack (it breaks)
    against the geometric player, with the game panel."""
    import gymnasium as gym

    import billiards_env  # noqa: F401
    from billiards_env.envs.recording import GIF_RENDER, record_gif

    from .evaluate import model_player

    if model_path.startswith("scorer:"):
        from .option_policies import RULE_KWARGS, Scorer

        policy: Any = Scorer.load(Path(model_path[len("scorer:"):]))
        env_id, env_kwargs = "Billiards9Ball-v0", RULE_KWARGS
    else:
        policy = model_player(model_path)
        env_id, env_kwargs = policy.env_id, policy.env_kwargs
    kw = {k: v for k, v in env_kwargs.items() if k not in ("opponent", "opening", "first_shooter")}
    env = gym.make(env_id, render_mode="rgb_array_list", **{**GIF_RENDER, **kw, "opponent": "geometric",
                                                            "opening": "break", "first_shooter": "agent"})
    try:
        return record_gif(env, lambda obs: policy.act(env, obs), path, [seed], max_shots=40)
    finally:
        env.close()


def _pair(report: dict[str, Any], a: str, b: str) -> tuple[int, int, int] | None:
    for p in report["pairs"]:
        if (p["a"], p["b"]) == (a, b):
            return p["wins_a"], p["games"], p["wins_b"]
        if (p["a"], p["b"]) == (b, a):
            return p["wins_b"], p["games"], p["wins_a"]
    return None


def _verdict(w: int, n: int, target: float) -> str:
    lo, _ = wilson_interval(w, n)
    if n and w / n >= target:
        return "met" if lo >= target else "met (interval includes the target)"
    return "**missed**"


def target_lines(leagues: dict[str, dict[str, Any]], trained: str, prior: str | None = None,
                 job_seconds: float | None = None, decision_ms: float | None = None) -> list[str]:
    """The targets' table rows: ``| target | figure | verdict |``."""
    lines = []
    rows = [("the search player beats the geometric player", "search", "geometric", 0.5),
            (f"the trained policy alone wins >= {100 * TARGET_VS_GEOMETRIC:.0f}% against the geometric player "
             "(400 games a setting)", trained, "geometric", TARGET_VS_GEOMETRIC)]
    if prior is not None:
        rows.append((f"search with the learned prior wins >= {100 * TARGET_PRIOR_VS_SEARCH:.0f}% against the search "
                     "player, equal simulation budget", prior, "search", TARGET_PRIOR_VS_SEARCH))
    for title, a, b, target in rows:
        figures, verdicts = [], []
        for setting, rep in leagues.items():
            r = _pair(rep, a, b)
            if r is None:
                continue
            w, n, _ = r
            lo, hi = wilson_interval(w, n)
            figures.append(f"{setting.replace('_', ' ')}: {w}/{n} = **{100 * w / n:.0f}%** [{100 * lo:.0f}, "
                           f"{100 * hi:.0f}]")
            verdicts.append(_verdict(w, n, target) if target != 0.5 else
                            ("met" if w / n > 0.5 and lo > 0.5 else ("met (interval includes 50%)" if w / n > 0.5
                                                                     else "**missed**")))
        lines.append(f"| {title} | {'; '.join(figures)} | {', '.join(verdicts)} |")
    if decision_ms is not None:
        lines.append(f"| the trained policy decides in <= 1 ms | {decision_ms:.2f} ms a decision (league mean of the slower "
                     f"setting, its own observations included) | {'met' if decision_ms <= 1.0 else '**missed**'} |")
    if job_seconds is not None:
        lines.append(f"| the 9-ball job <= {TARGET_JOB_SECONDS // 60} min on 2 cores | {job_seconds / 60:.0f} min wall | "
                     f"{'met' if job_seconds <= TARGET_JOB_SECONDS else '**missed**'} |")
    return lines


def limits_text(report: dict[str, Any], leagues: dict[str, dict[str, Any]], trained: str) -> list[str]:
    """What limits the trained agent, from the job's own figures: the teacher's level on the states it labelled, what
    each stage of the distillation reached, the league's games."""
    out = []
    stages = (report.get("training") or {}).get("stages") or []
    if stages:
        first = stages[0]
        if first.get("labels_from"):
            out.append(f"- The labels were those of an earlier run (`{first['labels_from']}`): its `distill.json` has the "
                       "teacher's own games.")
        if first.get("played_success") is not None:
            out.append(f"- The teacher (the search player acting in the agent's action type) won "
                       f"{100 * first['played_success']:.0f}% of the {first['episodes_labelled']} games it played "
                       "against the geometric player while labelling (olympiad noise): a student that copies it is "
                       "capped near there, and a copy is never exact.")
        for st in stages:
            if "success_rate" in st:
                lo, hi = st.get("ci", (0, 1))
                out.append(f"- {st['stage']}: {100 * st['success_rate']:.0f}% [{100 * lo:.0f}, {100 * hi:.0f}] of "
                           f"{st['episodes']} evaluation games against the geometric player"
                           + (f" ({st['labels_total']} labels)" if "labels_total" in st else "")
                           + (f", {st.get('timesteps')} RL steps" if st["stage"] == "rl fine-tuning" else "") + ".")
    return out


def prior_limits(leagues: dict[str, dict[str, Any]], prior: str) -> list[str]:
    """What bounds the search with the learned prior against the search player, per setting, from the pair's
    games: how many were over before either player came back to the table (the game then goes to whoever holds
    the table after the break, and both break the same way), and how often the search player's innings ended
    without winning (the misses an opponent can profit from)."""
    out = []
    for setting, rep in leagues.items():
        pair = next((p for p in rep["pairs"] if {p["a"], p["b"]} == {prior, "search"}), None)
        if pair is None or "no_return" not in pair:
            continue
        k = 0 if pair["a"] == "search" else 1
        wins = pair["wins_a"] if k == 0 else pair["wins_b"]
        failed = pair["innings"][k] - wins
        shots = pair["shots"][k]
        out.append(f"- {setting.replace('_', ' ')}: {pair['no_return']} of {pair['games']} games "
                   f"({100 * pair['no_return'] / max(pair['games'], 1):.0f}%) were over before either player came "
                   f"back to the table; the search player's innings ended without the game {failed} times in "
                   f"{shots} shots (one shot in {shots / max(failed, 1):.0f}, its break included).")
    return out


def _league_model(run_dir: Path) -> Path:
    """The model a run plays the league with: its best evaluation checkpoint (EvalCallback's, on the evaluation
    games against the geometric player: seeds apart from the league's racks), as the one-ball job plays; else the
    final model; else the folder itself (an RLlib run)."""
    for name in ("best_model.zip", "final_model.zip"):
        if (run_dir / name).exists():
            return run_dir / name
    return run_dir


def run(out: Path, seconds: float | None, practice_fraction: float, games: int, search_games: int, runouts: int,
        seed: int, model: str | None, gif_seed: int, progress: bool, command: str, curriculum: bool = False,
        workers: int | None = None, prior: bool = True, config: Path = DISTILL_CONFIG) -> dict[str, Any]:
    import os

    from .league import run_league

    out.mkdir(parents=True, exist_ok=True)
    workers = workers or os.cpu_count() or 1
    t0 = time.perf_counter()
    train_info: dict[str, Any] = {}
    if model is None:
        if curriculum:
            train_info = train_curriculum(out, seconds if seconds is not None else DEFAULT_SECONDS,
                                          practice_fraction, progress)
        else:
            train_info = train_distilled(out, seconds, config, workers)
        run_dir = Path(train_info["run_dir"])
        model = str(_league_model(run_dir))
    else:
        p = Path(model)
        run_dir = p if p.is_dir() else p.parent
        if p.is_dir():
            model = str(_league_model(p))
        if (run_dir / "distill.json").exists():  # a distilled run: its stages go into the report
            train_info = json.loads((run_dir / "distill.json").read_text())
    t_train = time.perf_counter() - t0
    print("neutral policy on the evaluation episodes...", flush=True)
    neutral = {"vs_geometric": neutral_baseline(MATCH_CONFIG if curriculum else config, 100)}
    if curriculum:
        neutral["practice"] = neutral_baseline(PRACTICE_CONFIG, 100)
    curve = plot_learning_curve(run_dir, out / "learning_curve.png", neutral)
    scorer = (train_info.get("scorer") or {}).get("path")
    if scorer is None and (run_dir / "scorer.pt").exists():
        scorer = str(run_dir / "scorer.pt")
    # the trained policy of the league: the option scorer when the run has one (agents.scorer), else the SAC model
    # the search's prior: the same trained policy
    trained_spec = f"scorer:{scorer}" if scorer else model
    players = [*BASELINES, trained_spec] + ([f"prior:{trained_spec}"] if prior else [])
    leagues = {}
    for name, noise in SETTINGS:
        limits = {"search": search_games, "prior:": search_games}  # the slow players' pairs
        rep = run_league("nine_ball", players, games, seed, noise, out / f"league_{name}",
                         runouts=runouts, command=f"{command} (league {name})", pair_games=limits, workers=workers)
        for ext in ("md", "json"):
            (out / f"league_{name}.{ext}").write_text((out / f"league_{name}" / f"league.{ext}").read_text())
        leagues[name] = rep
    names = list(leagues[SETTINGS[0][0]]["elo"])
    trained = next(n for n in names if n not in BASELINES and not n.startswith("search+prior"))
    prior_name = next((n for n in names if n.startswith("search+prior")), None)
    gif = record_game(f"scorer:{scorer}" if scorer else model, out / "game.gif", gif_seed)
    total = time.perf_counter() - t0
    ms = max(rep["players"][trained]["ms"] for rep in leagues.values())  # the slower setting (more ball in hand)
    report = {"command": command, "model": model, "run_dir": str(run_dir), "training": train_info,
              "train_wall_seconds": t_train, "total_wall_seconds": total, "neutral": neutral,
              "workers": workers, "trained_ms_per_decision": ms,
              "leagues": {k: {"elo": v["elo"], "pairs": v["pairs"], "run_outs": v["run_outs"], "players": v["players"],
                              "info": v["info"]} for k, v in leagues.items()},
              "files": {"learning_curve": str(curve) if curve else None, "gif": gif["path"],
                        **{f"league_{k}": str(out / f"league_{k}.md") for k, _ in SETTINGS}}}
    report["targets"] = target_lines(leagues, trained, prior_name, total, ms)
    (out / "report.json").write_text(json.dumps(report, indent=2, default=str))
    (out / "report.md").write_text(markdown(report, leagues, trained, prior_name))
    return report


def markdown(report: dict[str, Any], leagues: dict[str, dict[str, Any]], trained: str,
             prior: str | None = None) -> str:
    tr = report.get("training") or {}
    lines = ["# 9-ball: agents, league, targets", "",
             f"Command: `{report['command']}`; total {report['total_wall_seconds']:.0f} s wall "
             f"(training {report['train_wall_seconds']:.0f} s) on {report.get('workers', 1)} process(es). Trained "
             f"agent: `{report['model']}`.", ""]
    if tr.get("phases"):
        ph = tr["phases"]
        lines += [f"Training (SB3 SAC, candidates action/observation types, spin model, FastFiz-like noise): run-out "
                  f"practice {ph['practice']['timesteps']} shots in {ph['practice']['wall_seconds']:.0f} CPU s, then "
                  f"games against the geometric player up to {ph['vs_geometric']['timesteps']} shots, "
                  f"{ph['vs_geometric']['wall_seconds']:.0f} CPU s in all.", ""]
    elif tr.get("stages"):
        lines += ["Training (agents.distill: the search player's shots in the agent's action type, behaviour cloning, "
                  "DAgger, then SB3 SAC against the geometric player; spin model, olympiad noise):", "",
                  "| stage | labels | evaluation games won [95% CI] | seconds |", "|---|---|---|---|"]
        for st in tr["stages"]:
            lo, hi = st.get("ci", (0.0, 1.0))
            rate = f"{100 * st['success_rate']:.0f}% [{100 * lo:.0f}, {100 * hi:.0f}] of {st['episodes']}" \
                if "success_rate" in st else "-"
            secs = (f"labels {st['label_wall_seconds']:.0f} s wall, cloning {st['bc_cpu_seconds']:.0f} CPU s"
                    if "label_wall_seconds" in st else f"{st.get('cpu_seconds', 0):.0f} CPU s")
            lines.append(f"| {st['stage']} | {st.get('labels_total', '-')} | {rate} | {secs} |")
        lines.append("")
        sc = tr.get("scorer")
        if sc:
            from .option_policies import HAND_PLACES

            agree = ", ".join(f"{100 * a:.0f}%" for a in sc.get("holdout_agreement", []))
            hand = ", ".join(f"{100 * a:.0f}%" for a in sc.get("hand_holdout_agreement", []))
            lines += [f"The league's trained policy is the option scorer `{sc['path']}` (agents.scorer): "
                      f"{sc['labels']} labels (the distillation's, {sc['extra_games']} more teacher games, "
                      f"{sc['dagger_games']} games played by a first scorer) and {sc.get('hand_labels', 0)} "
                      f"ball-in-hand labels (the teacher's place among its {HAND_PLACES} places), {sc['ensemble']} fits "
                      f"(agreement with the teacher on held-out labels {agree}; on ball-in-hand labels {hand or '-'}), "
                      f"the SAC clone of the labels where no place has a pot; {sc['wall_seconds']:.0f} s wall. It is "
                      "also the prior of the search with the learned prior.", ""]
    lines += ["## Targets", "", "| target | figure (win rate [95% Wilson interval]) | verdict |", "|---|---|---|",
              *report.get("targets", target_lines(leagues, trained, prior)), ""]
    lim = limits_text(report, leagues, trained)
    if lim:
        lines += ["What limits the trained agent (figures of this run):", "", *lim, ""]
    if prior is not None:
        lines += ["What limits the search with the learned prior: without noise the search player runs out from "
                  "nearly every table it gets, so the game goes to whoever holds the table after the break, which "
                  "every player plays the same (the geometric break): no opponent can win much more than half of "
                  "the games against it, however it plays after the break. Its proposals are shots of the same "
                  "ghost-ball pots the search already simulates at the same speeds and tips; under noise the "
                  "simulations the prior frees from the sweep re-run the best shots more often (a surer estimate of "
                  "each one's chance), which is where it gains (agents/prior_search.py). This run's games:", "",
                  *prior_limits(leagues, prior), ""]
    n = report["neutral"]
    if "vs_geometric" in n:
        lines += [f"Reference (learning curve): the neutral action (the geometric player's own choice in the agent's "
                  f"action type) scores {n['vs_geometric']['mean_reward']:.2f} return / "
                  f"{100 * n['vs_geometric']['success_rate']:.0f}% wins against geometric on the evaluation games.",
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
    g.add_argument("--games", type=int, default=400, help="nine-ball: league games per pair and setting")
    g.add_argument("--search-games", type=int, default=400, help="nine-ball: games of the pairs with the search "
                                                                "player or the search with the prior (slower)")
    g.add_argument("--runouts", type=int, default=100, help="nine-ball: racks of the run-out test per player")
    g.add_argument("--curriculum", action="store_true", help="nine-ball: the earlier RL-only agent (run-out practice, "
                                                             "then games) instead of the distillation")
    g.add_argument("--no-prior", action="store_true", help="nine-ball: leave the search with the learned prior out "
                                                           "of the league")
    g.add_argument("--workers", type=int, default=None, help="nine-ball: processes of the league and the labelling "
                                                             "(default: every core)")
    g.add_argument("--gif-seed", type=int, default=3)


def main(args: Any) -> int:
    out = Path(args.out) if args.out != str(REPO_ROOT / "runs" / "main") else REPO_ROOT / "runs" / "main" / "nine_ball"
    command = "python -m agents.main " + " ".join(sys.argv[1:])
    rep = run(out, args.seconds, args.practice_fraction, args.games, args.search_games, args.runouts, 0, args.model,
              args.gif_seed, not args.no_progress, command, curriculum=args.curriculum, workers=args.workers,
              prior=not args.no_prior)
    print((out / "report.md").read_text())
    print(f"total {rep['total_wall_seconds']:.0f} s; files in {out}")
    return 0


__all__ = ["run", "train_curriculum", "neutral_baseline", "plot_learning_curve", "record_game", "main",
           "add_arguments", "DEFAULT_SECONDS"]
