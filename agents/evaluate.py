"""Evaluate players side by side on the same episodes and write a report (Markdown + JSON, plot, GIF).

    python -m agents.evaluate --env BilliardsOneBall-v0 --players random geometric search runs/one_ball_sac-*/
    python -m agents.evaluate --players runs/main/train --episodes 1000 --out runs/main/eval
    python -m agents.evaluate --env BilliardsThreeBalls-v0 --players geometric search --episodes 300

A player is a baseline name (``random``, ``geometric``, ``search``: see :mod:`billiards_env.players`) or a trained
model: a run folder (its ``best_model.zip``, else ``final_model.zip``) or a model ``.zip`` inside one; an RLlib
run folder of ``agents.rllib`` or any RLlib checkpoint (:mod:`agents.rllib.player`; needs the ``rllib`` extra). A
model is played with its run's env kwargs and wrappers (from the run's ``config.yaml``) and deterministic
actions; baselines play the same scene (the first model's env kwargs unless ``--env-kwargs`` is given).
Episode ``k`` of every player starts from ``reset(seed=seed + k)``: the same tables, the same shot noise.

Reported per player: success rate (one-shot scenes: the *pocket rate*, object ball pocketed without a
scratch; multi-shot scenes: the *clear rate*, table cleared within the shot limit) with a 95% Wilson
interval, the rate of pocketing regardless of scratches, shots per clear, scratches per episode, balls
pocketed per shot, mean return and decision time per shot. Files in ``--out``: ``report.md``,
``report.json``, ``learning_curve.png`` (trained runs: EvalCallback's evaluations and the training
episodes' success from the Monitor logs, baselines as horizontal lines) and ``episodes.gif``.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any, Callable, Sequence

import numpy as np

from billiards_env.players import BASELINES, make_player
from billiards_env.registration import env_id_arg

from .config import ALGOS
from .player_spec import PlayerSpec, env_factory

# --- statistics ---------------------------------------------------------------------------------------------

def wilson_interval(successes: int, n: int, z: float = 1.959963984540054) -> tuple[float, float]:
    """Wilson score interval for a binomial proportion (95% by default); (0, 1) when n = 0."""
    if n <= 0:
        return 0.0, 1.0
    p = successes / n
    denom = 1.0 + z * z / n
    centre = (p + z * z / (2 * n)) / denom
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom
    lo = 0.0 if successes <= 0 else max(0.0, centre - half)
    hi = 1.0 if successes >= n else min(1.0, centre + half)
    return lo, hi


# --- players ------------------------------------------------------------------------------------------------

def resolve_model(path: str | Path) -> tuple[Path, Path | None]:
    """``(model_zip, run_dir)`` for a run folder or a model zip."""
    p = Path(path)
    if p.is_dir():
        for name in ("best_model.zip", "final_model.zip"):
            if (p / name).exists():
                return p / name, p
        latest = p / "checkpoints" / "latest.json"
        if latest.exists():
            return p / "checkpoints" / json.loads(latest.read_text())["model"], p
        raise FileNotFoundError(f"{p}: no best_model.zip, final_model.zip or checkpoint in this run folder")
    if p.is_file():
        for d in (p.parent, p.parent.parent):
            if (d / "config.yaml").exists():
                return p, d
        return p, None
    raise FileNotFoundError(f"{p}: no such model file or run folder")


def model_player(path: str | Path, env_id: str | None = None, label: str | None = None) -> PlayerSpec:
    """A trained SB3 model as a player (its run's env kwargs, wrappers and VecNormalize statistics), or an RLlib
    checkpoint / ``agents.rllib`` run folder (:func:`agents.rllib.player.rllib_player`)."""
    from .rllib.player import is_rllib_path, rllib_player  # imports no Ray until it restores

    if is_rllib_path(path):
        return rllib_player(path, env_id, label)
    from .config import load_train_config, parse_hyperparams
    from .train import algo_class
    from .zoo import is_zoo_run, read_zoo_run

    env_kwargs: dict[str, Any] = {}
    wrapper = None
    algo = None
    zoo_norm = None
    if is_zoo_run(path):  # an RL Zoo run folder (logs/<algo>/<env_id>_<k>): its config.yml says what it trained on
        zoo = read_zoo_run(path)
        model_zip, run_dir = zoo.model_zip, zoo.run_dir
        env_id, env_kwargs, algo, zoo_norm = env_id or zoo.env_id, zoo.env_kwargs, zoo.algo, zoo.vecnormalize
    else:
        model_zip, run_dir = resolve_model(path)
    if run_dir is not None and (run_dir / "config.yaml").exists():
        cfg = load_train_config(run_dir / "config.yaml")
        setup = parse_hyperparams(cfg)
        env_id = env_id or cfg.env_id
        env_kwargs, wrapper, algo = setup.env_kwargs, setup.wrapper, cfg.algo
    if env_id is None:
        raise ValueError(f"{path}: no run config found; give --env")
    if algo is None:
        import zipfile

        with zipfile.ZipFile(model_zip) as z:
            data = json.loads(z.read("data"))
        algo = next((a for a in ALGOS
                     if a.upper() in str(data.get("policy_class", {}).get(":serialized:", ""))
                     or a in str(model_zip).lower()), "sac")
    model = algo_class(algo).load(str(model_zip), device="cpu")
    norm = None
    candidates = [run_dir / "vecnormalize.pkl", run_dir / "checkpoints" / "vecnormalize.pkl"] if run_dir else []
    for cand in ([zoo_norm] if zoo_norm else []) + candidates:
        if cand.exists():
            import pickle

            with open(cand, "rb") as f:
                norm = pickle.load(f)
            break

    def act(env: Any, obs: Any) -> np.ndarray:
        o = np.asarray(obs, dtype=np.float32)
        if norm is not None:
            o = norm.normalize_obs(o)
        action, _ = model.predict(o, deterministic=True)
        return action

    name = label or (run_dir.name if run_dir is not None else model_zip.stem)
    return PlayerSpec(name, "model", env_factory(env_id, env_kwargs, wrapper), act, run_dir=run_dir,
                      model_path=model_zip, env_id=env_id, env_kwargs=env_kwargs)


def baseline_player(name: str, env_id: str, env_kwargs: dict[str, Any], seed: int = 0) -> PlayerSpec:
    player = make_player(name, seed=seed)
    return PlayerSpec(name, "baseline", env_factory(env_id, env_kwargs), player.act, player.reset,
                      env_id=env_id, env_kwargs=env_kwargs)


def build_players(specs: Sequence[str], env_id: str | None, env_kwargs: dict[str, Any] | None,
                  seed: int = 0) -> list[PlayerSpec]:
    """Players from names/paths; models first resolve the env id and scene for the baselines."""
    models = {s: model_player(s, env_id) for s in specs if s not in BASELINES}
    first = next(iter(models.values()), None)
    eid = env_id or (first.env_id if first else None) or "BilliardsOneBall-v0"
    kwargs = dict(env_kwargs) if env_kwargs is not None else (dict(first.env_kwargs) if first else {})
    out = []
    for s in specs:
        out.append(models[s] if s in models else baseline_player(s, eid, kwargs, seed))
    return out


# --- running ------------------------------------------------------------------------------------------------

@dataclass
class PlayerResult:
    label: str
    kind: str
    episodes: int
    successes: int
    success_rate: float
    success_ci: tuple[float, float]
    pocketed_any: int  #: episodes in which at least one object ball was pocketed
    all_potted: int  #: episodes in which every object ball was pocketed (scratch or not)
    shots: int
    scratches: int
    balls_potted: int
    scratch_episodes: int
    mean_return: float
    shots_per_episode: float
    shots_per_clear: float | None
    scratches_per_episode: float
    pots_per_shot: float
    ms_per_shot: float
    seconds: float
    model_path: str | None = None
    run_dir: str | None = None


def run_player(spec: PlayerSpec, episodes: int, seed: int, progress: Callable[[int], None] | None = None
               ) -> tuple[PlayerResult, list[dict[str, Any]]]:
    """Play ``episodes`` episodes (seeds ``seed + k``) and gather the statistics."""
    env = spec.make_env()
    rows: list[dict[str, Any]] = []
    t_decide = 0.0
    t0 = time.perf_counter()
    try:
        for k in range(episodes):
            spec.reset(seed + k)
            obs, _ = env.reset(seed=seed + k)
            n_obj = env.unwrapped.n_balls - 1
            shots = scratches = pots = 0
            ret = 0.0
            done = False
            info: dict[str, Any] = {}
            while not done:
                t1 = time.perf_counter()
                action = spec.act(env, obs)
                t_decide += time.perf_counter() - t1
                obs, r, term, trunc, info = env.step(action)
                shots += 1
                ret += float(r)
                scratches += int(bool(info.get("scratch")))
                pots += int(np.count_nonzero(info["pocketed"][1:]))  # a mask over the rows; row 0 the cue ball
                done = term or trunc
            rows.append({"seed": seed + k, "success": bool(info.get("is_success")), "shots": shots,
                         "scratches": scratches, "pots": pots, "return": ret, "all_potted": pots >= n_obj})
            if progress:
                progress(k + 1)
    finally:
        env.close()
    secs = time.perf_counter() - t0
    n = len(rows)
    succ = sum(r["success"] for r in rows)
    shots_total = sum(r["shots"] for r in rows)
    clears = [r["shots"] for r in rows if r["success"]]
    res = PlayerResult(
        label=spec.label, kind=spec.kind, episodes=n, successes=succ, success_rate=succ / n if n else 0.0,
        success_ci=wilson_interval(succ, n), pocketed_any=sum(r["pots"] > 0 for r in rows),
        all_potted=sum(r["all_potted"] for r in rows), shots=shots_total,
        scratches=sum(r["scratches"] for r in rows), balls_potted=sum(r["pots"] for r in rows),
        scratch_episodes=sum(r["scratches"] > 0 for r in rows),
        mean_return=float(np.mean([r["return"] for r in rows])) if rows else 0.0,
        shots_per_episode=shots_total / n if n else 0.0,
        shots_per_clear=float(np.mean(clears)) if clears else None,
        scratches_per_episode=sum(r["scratches"] for r in rows) / n if n else 0.0,
        pots_per_shot=sum(r["pots"] for r in rows) / shots_total if shots_total else 0.0,
        ms_per_shot=1000.0 * t_decide / shots_total if shots_total else 0.0, seconds=secs,
        model_path=str(spec.model_path) if spec.model_path else None,
        run_dir=str(spec.run_dir) if spec.run_dir else None)
    return res, rows


# --- outputs ------------------------------------------------------------------------------------------------

def _pct(x: float) -> str:
    return f"{100 * x:.1f}%"


def markdown_report(results: list[PlayerResult], env_id: str, env_kwargs: dict[str, Any], seed: int,
                    single_shot: bool, extra: dict[str, Any] | None = None) -> str:
    game = env_id in ("Billiards9Ball-v0", "Billiards8Ball-v0")
    rate = "win rate" if game else ("pocket rate" if single_shot else "clear rate")
    lines = [f"# Evaluation on {env_id}", "",
             f"{results[0].episodes if results else 0} episodes per player, seeds {seed}..{seed + (results[0].episodes if results else 1) - 1} "
             f"(the same tables for every player); env kwargs: `{json.dumps(env_kwargs)}`.", "",
             f"| player | {rate} [95% CI] | pocketed (any) | shots/clear | scratches/episode | pots/shot | "
             "mean return | ms/shot |",
             "|---|---|---|---|---|---|---|---|"]
    for r in results:
        lo, hi = r.success_ci
        spc = f"{r.shots_per_clear:.2f}" if r.shots_per_clear is not None else "-"
        lines.append(f"| {r.label} | **{_pct(r.success_rate)}** [{_pct(lo)}, {_pct(hi)}] | "
                     f"{_pct(r.pocketed_any / r.episodes if r.episodes else 0)} | {spc} | "
                     f"{r.scratches_per_episode:.3f} | {r.pots_per_shot:.3f} | {r.mean_return:.3f} | "
                     f"{r.ms_per_shot:.2f} |")
    meaning = ("games won against the env's opponent (or run-outs without one)." if game else
               "object ball pocketed and cue ball not (one shot)." if single_shot else
               "every object ball pocketed within the shot limit, no scratch on the last shot.")
    lines += ["", f"*{rate}*: " + meaning,
              "CI: Wilson score interval. *pocketed (any)*: episodes with at least one object ball pocketed."]
    if extra:
        for title, body in extra.items():
            lines += ["", f"## {title}", "", body]
    return "\n".join(lines) + "\n"


def _monitor_success(run_dir: Path) -> tuple[np.ndarray, np.ndarray] | None:
    """Training episodes' success from the Monitor CSVs: (cumulative timesteps, rolling success rate)."""
    import csv

    rows: list[tuple[float, int, float]] = []
    for sess in sorted((run_dir / "monitor").glob("session*")):
        sess_rows = []
        for f in sorted(sess.glob("*.monitor.csv")):
            with open(f) as fh:
                first = fh.readline()
                t_start = json.loads(first[1:]).get("t_start", 0.0) if first.startswith("#") else 0.0
                for rec in csv.DictReader(fh):
                    if "is_success" not in rec or rec["is_success"] in ("", None):
                        continue
                    sess_rows.append((t_start + float(rec["t"]), int(float(rec["l"])),
                                      1.0 if rec["is_success"] in ("True", "1", "1.0") else 0.0))
        rows += sorted(sess_rows)
    if not rows:
        return None
    lengths = np.array([r[1] for r in rows], dtype=float)
    succ = np.array([r[2] for r in rows])
    steps = np.cumsum(lengths)
    w = max(1, min(2000, len(succ) // 20))
    kernel = np.ones(w) / w
    roll = np.convolve(succ, kernel, mode="valid")
    return steps[w - 1:], roll


def _clock_name(run_dir: Path, meta: dict[str, Any] | None = None) -> str:
    """What a run's ``wall_seconds`` count: ``wall`` or ``CPU`` (its ``billiards.budget_clock``)."""
    clock = (meta or {}).get("clock")
    prog = Path(run_dir) / "progress.json"
    if clock is None and prog.exists():
        clock = json.loads(prog.read_text()).get("clock")
    return "CPU" if clock == "cpu" else "wall"


def learning_curve(run_dir: Path, path: Path, baselines: dict[str, float] | None = None,
                   title: str | None = None) -> Path | None:
    """Plot success rate against env steps (and wall time on a top axis) for a training run."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ev_file = run_dir / "eval" / "evaluations.npz"
    mon = _monitor_success(run_dir)
    if not ev_file.exists() and mon is None:
        return None
    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=100)
    if mon is not None:
        ax.plot(mon[0], mon[1], color="tab:gray", alpha=0.7, lw=1, label="training episodes (rolling, stochastic)")
    wall = None
    if ev_file.exists():
        ev = np.load(ev_file)
        ts = ev["timesteps"]
        if "successes" in ev.files:
            y = np.array([np.mean(s) for s in ev["successes"]])
            ax.plot(ts, y, "o-", color="tab:blue", lw=2, ms=3, label="evaluation (deterministic, fixed seeds)")
        prog = run_dir / "progress.json"
        if prog.exists():
            evals = json.loads(prog.read_text()).get("evaluations", [])
            if evals:
                wall = (np.array([e["timesteps"] for e in evals]), np.array([e["wall_seconds"] for e in evals]))
    for k, (name, v) in enumerate((baselines or {}).items()):
        ax.axhline(v, ls="--", lw=1, color=f"C{k + 2}", label=f"{name} baseline")
    ax.set_xlabel("environment steps")
    ax.set_ylabel("success rate")
    ax.set_ylim(0, 1.02)
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=8)
    if wall is not None and len(wall[0]) > 1:
        sec = ax.secondary_xaxis("top", functions=(lambda x: np.interp(x, wall[0], wall[1]),
                                                   lambda s: np.interp(s, wall[1], wall[0])))
        sec.set_xlabel(f"{_clock_name(run_dir)} seconds (incl. evaluation)")
    ax.set_title(title or run_dir.name, fontsize=10)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path)
    plt.close(fig)
    return path


def record_gif(spec: PlayerSpec, path: Path, seeds: Sequence[int], **options: Any) -> dict[str, Any]:
    """Play ``seeds`` episodes with ``spec`` and write them as one GIF, with the recorder of billiards_env
    (:func:`billiards_env.envs.recording.record_gif`: its render settings and per-shot frame cap; ``options``
    go to it). Returns its summary (frames, shots, returns, successes per episode) with the path as a string."""
    from billiards_env.envs.recording import GIF_RENDER
    from billiards_env.envs.recording import record_gif as record

    env = spec.make_env(render_mode="rgb_array_list", **GIF_RENDER)
    try:
        out = record(env, lambda obs: spec.act(env, obs), path, list(seeds), reset_policy=spec.reset, **options)
    finally:
        env.close()
    return {**out, "path": str(out["path"])}


def evaluate(players: list[PlayerSpec], episodes: int, seed: int, out_dir: Path | None,
             gif_episodes: int = 3, gif_player: str | None = None, quiet: bool = False,
             title: str | None = None) -> dict[str, Any]:
    """Run every player, print the table, write the report files; returns the JSON report."""
    say = (lambda *a: None) if quiet else (lambda *a: print(*a, flush=True))
    results: list[PlayerResult] = []
    per_episode: dict[str, list[dict[str, Any]]] = {}
    probe = players[0].make_env()
    cfg = probe.unwrapped.config
    single_shot = bool(cfg.single_shot or cfg.max_shots == 1)
    env_id = players[0].env_id or probe.spec.id
    env_kwargs = players[0].env_kwargs
    probe.close()
    for spec in players:
        say(f"evaluating {spec.label} on {episodes} episodes ...")
        res, rows = run_player(spec, episodes, seed)
        results.append(res)
        per_episode[spec.label] = rows
        lo, hi = res.success_ci
        say(f"  {spec.label}: {_pct(res.success_rate)} [{_pct(lo)}, {_pct(hi)}] in {res.seconds:.1f} s")
    report: dict[str, Any] = {
        "env_id": env_id, "env_kwargs": env_kwargs, "episodes": episodes, "seed": seed,
        "metric": "pocket_rate" if single_shot else "clear_rate",
        "results": [asdict(r) for r in results], "files": {},
    }
    extra: dict[str, str] = {}
    for spec in players:
        if spec.run_dir is not None and (spec.run_dir / "run.json").exists():
            meta = json.loads((spec.run_dir / "run.json").read_text())
            ms = meta.get("milestones") or {}
            clock = _clock_name(spec.run_dir, meta)
            txt = (f"`{spec.run_dir}`: {meta.get('algo', '?').upper()}, {meta.get('timesteps', '?')} env steps in "
                   f"{meta.get('wall_seconds', 0):.0f} s {clock} ({meta.get('train_steps_per_second', 0):.0f} env "
                   f"steps/s excluding evaluation), model `{spec.model_path}`.")
            if ms:
                txt += ("\n\nFirst evaluation reaching each success level:\n\n"
                        f"| level | env steps | {clock} s |\n|---|---|---|\n")
                txt += "\n".join(f"| {k} | {v['timesteps']} | {v['wall_seconds']:.0f} |" for k, v in sorted(ms.items()))
            extra[f"Training: {spec.label}"] = txt
            report.setdefault("training", {})[spec.label] = {k: meta.get(k) for k in (
                "algo", "timesteps", "wall_seconds", "clock", "train_steps_per_second", "milestones", "best_eval",
                "env_kwargs", "env_wrapper", "config_source")}
    if out_dir is not None:
        out_dir = Path(out_dir)
        out_dir.mkdir(parents=True, exist_ok=True)
        base_rates = {r.label: r.success_rate for r in results if r.kind == "baseline" and r.label != "random"}
        for spec in players:
            if spec.run_dir is not None:
                name = "learning_curve.png" if sum(p.run_dir is not None for p in players) == 1 else \
                    f"learning_curve_{spec.label}.png"
                try:
                    png = learning_curve(spec.run_dir, out_dir / name, base_rates, title or f"{spec.label} on {env_id}")
                except Exception as exc:  # noqa: BLE001 - a plot failure must not lose the report
                    say(f"learning curve failed: {exc}")
                    png = None
                if png:
                    report["files"].setdefault("learning_curves", []).append(str(png))
        if gif_episodes > 0:
            target = next((p for p in players if p.label == gif_player), None) or \
                next((p for p in players if p.kind == "model"), None) or players[-1]
            try:
                gif = record_gif(target, out_dir / "episodes.gif", [seed + k for k in range(gif_episodes)])
                report["files"]["gif"] = gif["path"]
                report["gif"] = {**gif, "player": target.label}
            except Exception as exc:  # noqa: BLE001 - rendering is optional (headless machines)
                say(f"GIF failed: {exc}")
        md = markdown_report(results, env_id, env_kwargs, seed, single_shot, extra)
        if report["files"]:
            md += "\n## Files\n\n" + "\n".join(f"- {k}: `{v}`" for k, v in report["files"].items()) + "\n"
        (out_dir / "report.md").write_text(md)
        report["files"]["report_md"] = str(out_dir / "report.md")
        report["files"]["report_json"] = str(out_dir / "report.json")
        (out_dir / "report.json").write_text(json.dumps(report, indent=2, default=str))
        (out_dir / "episodes.json").write_text(json.dumps(per_episode, default=str))
    say("")
    say(markdown_report(results, env_id, env_kwargs, seed, single_shot))
    return report


def _pairs(items: Sequence[str] | None) -> dict[str, Any]:
    import yaml

    out: dict[str, Any] = {}
    for item in items or []:
        k, sep, v = item.partition("=")
        if not sep:
            raise ValueError(f"--env-kwargs: expected key=value, got {item!r}")
        out[k] = yaml.safe_load(v)
    return out


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m agents.evaluate", description=__doc__.split("\n\n")[0])
    p.add_argument("--players", nargs="+", default=list(BASELINES),
                   help="baseline names (random, geometric, search) and/or run folders / model .zip files / RLlib "
                        "checkpoints")
    p.add_argument("--env", type=env_id_arg, help="env id (default: the first model's, else BilliardsOneBall-v0)")
    p.add_argument("--env-kwargs", nargs="*", metavar="KEY=VALUE", help="scene overrides for the baselines")
    p.add_argument("--episodes", type=int, default=500)
    p.add_argument("--seed", type=int, default=100_000, help="episode k uses reset(seed=seed + k)")
    p.add_argument("--out", help="report folder (default runs/eval-<timestamp>)")
    p.add_argument("--gif-episodes", type=int, default=3, help="episodes in episodes.gif (0: no GIF)")
    p.add_argument("--gif-player", help="player shown in the GIF (default: the first model)")
    p.add_argument("--quiet", action="store_true")
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        players = build_players(args.players, args.env, _pairs(args.env_kwargs) if args.env_kwargs else None)
    except (FileNotFoundError, ValueError) as exc:
        print(f"agents.evaluate: error: {exc}", file=sys.stderr)
        return 2
    out = Path(args.out) if args.out else Path("runs") / f"eval-{time.strftime('%Y%m%d-%H%M%S')}"
    report = evaluate(players, args.episodes, args.seed, out, args.gif_episodes, args.gif_player, args.quiet)
    print(f"report: {report['files'].get('report_md')}  json: {report['files'].get('report_json')}")
    for k in ("learning_curves", "gif"):
        if k in report["files"]:
            print(f"{k}: {report['files'][k]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
