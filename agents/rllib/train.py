"""Train an RLlib agent (PPO, APPO, IMPALA, SAC) on a billiards env, on this machine or on a Ray cluster.

    python -m agents.rllib --config configs/train/rllib_one_ball_ppo.yaml
    python -m agents.rllib --algo PPO --env Billiards9Ball-v0 --num-env-runners 4 --address auto
    python -m agents.rllib --config configs/train/rllib_nine_ball_selfplay.yaml      # two-player self-play
    python -m agents.rllib --resume runs/rllib_one_ball_ppo-20260101-120000        # continue a run
    python -m agents.rllib --config ... --set training.lr=3e-4 env_runners.num_envs_per_env_runner=32

Without ``--address`` a local Ray starts with this machine's CPUs (env runners are separate processes; Ray has
no local mode); ``--address auto`` joins the cluster of ``ray start`` on this node (``ray://head:10001``: Ray
Client). The run folder ``runs/<name>-<timestamp>/`` is laid out as an SB3 run's, so ``agents.evaluate`` puts
both in one table: ``config.yaml`` (the resolved config: rerun it with ``--config``), ``run.json`` (what ran,
versions, cluster, steps/s, wall time), ``env.json`` (``gym.make(id, **kwargs)``), ``progress.json`` (every
iteration; the evaluations and the time each success level was first reached), ``eval/evaluations.npz``,
``checkpoints/iter_<n>/`` (the newest ``keep_checkpoints``, ``latest.json``), ``best_checkpoint/`` (the best
evaluation) and ``final_checkpoint/``. Every checkpoint is RLlib's own (``Algorithm.save_to_path``):
``Algorithm.from_checkpoint`` restores it, and ``RLModule.from_checkpoint`` its policy.

Evaluations during training (``eval_every`` iterations) run the project's evaluation (:func:`agents.evaluate.run_player`)
in the driver on the same seeded tables every time (``eval_seed``), deterministic actions; a game is scored by
wins against the env's opponent (``Billiards9Ball-v0``: the geometric player unless ``env_kwargs.opponent``).
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import signal
import sys
import time
from dataclasses import asdict
from pathlib import Path
from typing import Any, Sequence

import numpy as np
import yaml

from billiards_env.registration import env_id_arg

from .config import (ALGOS, SELF_PLAY, VECTORIZE_MODES, RLlibConfig, RLlibConfigError, load_rllib_config,
                     parse_assignments)

#: Success levels whose first evaluation is recorded (as for SB3 runs: agents.callbacks.TrainingClock).
MILESTONES = (0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95)


class _Interrupted(Exception):
    pass


def _atomic_write(path: Path, text: str) -> None:
    tmp = path.with_suffix(path.suffix + ".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def env_steps(result: dict[str, Any]) -> int:
    """Env steps sampled so far (all env runners, all sessions) from a ``train()`` result."""
    er = result.get("env_runners") or {}
    for value in (er.get("num_env_steps_sampled_lifetime"), result.get("num_env_steps_sampled_lifetime")):
        if value is not None:
            return int(value)
    return 0


def _mean(value: Any) -> float | None:
    try:
        v = float(value)
    except (TypeError, ValueError):
        return None
    return v if np.isfinite(v) else None


def _versions() -> dict[str, str]:
    import gymnasium
    import ray
    import torch

    return {"python": platform.python_version(), "ray": ray.__version__, "torch": torch.__version__,
            "gymnasium": gymnasium.__version__, "numpy": np.__version__,
            "machine": f"{platform.machine()} {os.cpu_count()} cpu"}


class Progress:
    """Wall clock, evaluations, milestones and per-iteration figures of a run: ``progress.json`` (the format of
    SB3 runs, plus ``iterations``) and ``eval/evaluations.npz`` (timesteps, returns, lengths, successes)."""

    def __init__(self, run_dir: Path, offset_seconds: float = 0.0) -> None:
        self.run_dir = run_dir
        self.offset_seconds = offset_seconds
        self.t0 = time.perf_counter()
        self.excluded = 0.0  #: evaluation and checkpoint seconds (not training)
        self.start_steps: int | None = None
        self.timesteps = 0
        self.evaluations: list[dict[str, Any]] = []
        self.milestones: dict[str, dict[str, float]] = {}
        self.iterations: list[dict[str, Any]] = []
        self.stopped_by_budget = False
        self._npz: dict[str, list[Any]] = {"timesteps": [], "results": [], "ep_lengths": [], "successes": []}

    def load(self) -> None:
        """Continue an earlier session's records (``--resume``)."""
        p = self.run_dir / "progress.json"
        if p.is_file():
            old = json.loads(p.read_text())
            self.evaluations = old.get("evaluations", [])
            self.milestones = old.get("milestones", {})
            self.iterations = old.get("iterations", [])
            self.offset_seconds = float(old.get("wall_seconds", 0.0))
        npz = self.run_dir / "eval" / "evaluations.npz"
        if npz.is_file():
            with np.load(npz) as old_npz:
                self._npz = {k: [np.asarray(r) for r in old_npz[k]] if k != "timesteps" else list(old_npz[k])
                             for k in self._npz}

    def elapsed(self) -> float:
        return self.offset_seconds + time.perf_counter() - self.t0

    def train_seconds(self) -> float:
        return time.perf_counter() - self.t0 - self.excluded

    def steps_per_second(self) -> float:
        t = self.train_seconds()
        done = self.timesteps - (self.start_steps or 0)
        return done / t if t > 0 else 0.0

    def iteration(self, result: dict[str, Any], seconds: float) -> dict[str, Any]:
        steps = env_steps(result)
        if self.start_steps is None:
            self.start_steps = steps - int((result.get("env_runners") or {}).get("num_env_steps_sampled", 0) or 0)
        prev = self.timesteps if self.iterations else (self.start_steps or 0)
        self.timesteps = steps
        er = result.get("env_runners") or {}
        row = {"iteration": int(result.get("training_iteration", len(self.iterations) + 1)), "timesteps": steps,
               "wall_seconds": self.elapsed(), "seconds": seconds,
               "env_steps_per_second": (steps - prev) / seconds if seconds > 0 else 0.0,
               "episode_return_mean": _mean(er.get("episode_return_mean")),
               "episode_len_mean": _mean(er.get("episode_len_mean")),
               "success_rate": _mean(er.get("is_success")),
               "module_returns": {k: _mean(v) for k, v in (er.get("module_episode_returns_mean") or {}).items()}}
        self.iterations.append(row)
        return row

    def evaluation(self, res: Any, rows: list[dict[str, Any]], seconds: float) -> dict[str, Any]:
        entry = {"timesteps": self.timesteps, "wall_seconds": self.elapsed(), "train_seconds": self.train_seconds(),
                 "success_rate": res.success_rate, "mean_reward": res.mean_return, "eval_seconds": seconds}
        self.evaluations.append(entry)
        for level in MILESTONES:
            key = f"{level:.2f}"
            if key not in self.milestones and entry["success_rate"] >= level:
                self.milestones[key] = {"timesteps": entry["timesteps"], "wall_seconds": entry["wall_seconds"]}
        self._npz["timesteps"].append(self.timesteps)
        self._npz["results"].append(np.array([r["return"] for r in rows]))
        self._npz["ep_lengths"].append(np.array([r["shots"] for r in rows]))
        self._npz["successes"].append(np.array([r["success"] for r in rows]))
        (self.run_dir / "eval").mkdir(exist_ok=True)
        np.savez(self.run_dir / "eval" / "evaluations.npz", timesteps=np.array(self._npz["timesteps"]),
                 results=np.array(self._npz["results"]), ep_lengths=np.array(self._npz["ep_lengths"]),
                 successes=np.array(self._npz["successes"]))
        return entry

    def summary(self) -> dict[str, Any]:
        return {"timesteps": self.timesteps, "wall_seconds": self.elapsed(),
                "session_seconds": time.perf_counter() - self.t0, "eval_seconds": self.excluded,
                "train_steps_per_second": self.steps_per_second(), "stopped_by_budget": self.stopped_by_budget,
                "evaluations": self.evaluations, "milestones": self.milestones, "iterations": self.iterations}

    def write(self) -> None:
        _atomic_write(self.run_dir / "progress.json", json.dumps(self.summary(), indent=2))


class Checkpoints:
    """``checkpoints/iter_<n>/`` every ``every`` iterations or ``seconds`` wall seconds (the newest ``keep``),
    ``checkpoints/latest.json`` naming the newest; ``best_checkpoint/`` and ``final_checkpoint/``."""

    def __init__(self, run_dir: Path, every: int, seconds: float, keep: int) -> None:
        self.dir = run_dir / "checkpoints"
        self.run_dir = run_dir
        self.every, self.seconds, self.keep = int(every), float(seconds), max(int(keep), 1)
        self.last_time = time.perf_counter()

    def due(self, iteration: int) -> bool:
        return (self.every > 0 and iteration % self.every == 0) or \
            (self.seconds > 0 and time.perf_counter() - self.last_time >= self.seconds)

    def save(self, algo: Any, iteration: int, timesteps: int, wall: float) -> Path:
        self.dir.mkdir(parents=True, exist_ok=True)
        path = self.dir / f"iter_{iteration:06d}"
        algo.save_to_path(str(path))
        _atomic_write(self.dir / "latest.json", json.dumps(
            {"checkpoint": path.name, "iteration": iteration, "timesteps": timesteps, "wall_seconds": wall}, indent=2))
        for old in sorted(self.dir.glob("iter_*"))[: -self.keep]:
            shutil.rmtree(old, ignore_errors=True)
        self.last_time = time.perf_counter()
        return path

    def save_as(self, algo: Any, name: str) -> Path:
        """Save to ``<run>/<name>/`` (replacing it only once the new one is complete)."""
        final, tmp = self.run_dir / name, self.run_dir / f".{name}.tmp"
        shutil.rmtree(tmp, ignore_errors=True)
        algo.save_to_path(str(tmp))
        shutil.rmtree(final, ignore_errors=True)
        os.replace(tmp, final)
        return final


def evaluate_policy(algo: Any, cfg: RLlibConfig, episodes: int, seed: int) -> tuple[Any, list[dict[str, Any]]]:
    """The project's evaluation of the algorithm's current policy (deterministic, seeds ``seed + k``)."""
    from ..evaluate import run_player
    from ..player_spec import PlayerSpec, env_factory
    from .player import RLlibPolicy, single_env_kwargs

    s = cfg.settings
    policy = RLlibPolicy.from_algorithm(algo)
    kwargs = single_env_kwargs(s.env_kwargs)
    spec = PlayerSpec("current", "model", env_factory(s.env_id, kwargs), lambda env, obs: policy(obs),
                      env_id=s.env_id, env_kwargs=kwargs)
    return run_player(spec, episodes, seed)


def train(cfg: RLlibConfig, run_dir: Path | None = None, resume: Path | None = None,
          quiet: bool = False) -> dict[str, Any]:
    """Train from a resolved config; returns the run summary (also written to ``run.json``)."""
    import torch

    from .algorithm import init_ray
    from .player import resume_checkpoint

    s = cfg.settings
    say = (lambda *a: None) if quiet else (lambda *a: print(*a, flush=True))
    torch.set_num_threads(max(int(s.torch_threads), 1))
    if not (s.timesteps or s.iterations or s.max_seconds):
        raise RLlibConfigError("no stopping rule: set billiards.timesteps, iterations or max_seconds "
                               "(--timesteps / --iterations / --seconds)")
    ckpt = None
    if resume is not None:
        ckpt, run_dir = resume_checkpoint(resume)
        if run_dir is None:
            raise RLlibConfigError(f"--resume: {resume} is not inside an agents.rllib run folder")
    import ray

    started = init_ray(s.address, quiet)  # first: a cluster that is not there leaves no run folder behind
    try:
        return _train(cfg, run_dir, resume, ckpt, started, say)
    except BaseException:
        if started:
            ray.shutdown()
        raise


def _train(cfg: RLlibConfig, run_dir: Path | None, resume: Path | None, ckpt: Path | None, started: bool,
           say: Any) -> dict[str, Any]:
    """:func:`train` once Ray is up. A new run's folder that fails before its first iteration is removed, so that
    failed starts leave no stub folders for ``runs/<name>-*`` globs to match."""
    from ..train import REPO_ROOT, new_run_dir

    s = cfg.settings
    if resume is None and run_dir is None:
        root = Path(s.run_root) if Path(s.run_root).is_absolute() else REPO_ROOT / s.run_root
        run_dir = new_run_dir(root, s.name or f"rllib_{s.env_id.split('-')[0].lower()}_{s.algo.lower()}")
    run_dir = Path(run_dir)
    new_folder = resume is None and not (run_dir.exists() and any(run_dir.iterdir()))
    run_dir.mkdir(parents=True, exist_ok=True)

    def drop_stub() -> None:
        if new_folder and not (run_dir / "progress.json").exists() and not (run_dir / "checkpoints").exists():
            shutil.rmtree(run_dir, ignore_errors=True)  # nothing trained: no stub folder

    try:
        result = _train_in(cfg, run_dir, resume, ckpt, started, say)
    except BaseException:
        drop_stub()
        raise
    drop_stub()  # interrupted before the first iteration
    return result


def _train_in(cfg: RLlibConfig, run_dir: Path, resume: Path | None, ckpt: Path | None, started: bool,
              say: Any) -> dict[str, Any]:
    import ray

    from ..train import git_commit
    from .algorithm import build_algorithm, cpus_needed

    s = cfg.settings
    progress = Progress(run_dir)
    if resume is not None:
        progress.load()
    else:
        (run_dir / "config.yaml").write_text(
            f"# Resolved config of this run (from {cfg.source}); rerun with --config {run_dir / 'config.yaml'}\n"
            + yaml.safe_dump(cfg.to_yaml_dict(), sort_keys=False))
    from .player import single_env_kwargs

    # What the checkpoint plays: gym.make(env["id"], **env["kwargs"]) (the evaluation's env).
    (run_dir / "env.json").write_text(json.dumps({"id": s.env_id, "kwargs": single_env_kwargs(s.env_kwargs)},
                                                 indent=2))

    algo = None
    interrupted = False
    old_handler = None
    try:
        algo = build_algorithm(cfg, local=not s.address)
        if ckpt is not None:
            say(f"resuming from {ckpt}")
            algo.restore_from_path(str(ckpt))
        setup_seconds = time.perf_counter() - progress.t0
        progress.t0 = time.perf_counter()  # the clock (and steps/s) starts with training, as for SB3 runs
        c = algo.config
        cluster = {k: float(v) for k, v in ray.cluster_resources().items() if k in ("CPU", "GPU", "memory")}
        meta: dict[str, Any] = {
            "framework": "rllib", "env_id": s.env_id, "algo": s.algo, "config_source": cfg.source,
            "run_dir": str(run_dir), "env_kwargs": s.env_kwargs, "env_wrapper": None, "self_play": s.self_play,
            "seed": s.seed, "settings": asdict(s), "rllib": {
                "num_env_runners": c.num_env_runners, "num_envs_per_env_runner": c.num_envs_per_env_runner,
                "gym_env_vectorize_mode": str(getattr(c.gym_env_vectorize_mode, "value", c.gym_env_vectorize_mode)),
                "num_learners": c.num_learners, "cpus_reserved": cpus_needed(c), "address": s.address,
                "cluster_resources": cluster, "nodes": len(ray.nodes())},
            "setup_seconds": setup_seconds,
            "versions": _versions(), "git_commit": git_commit(), "resumed_from": str(ckpt) if ckpt else None,
            "started": time.strftime("%Y-%m-%dT%H:%M:%S"), "command": " ".join(sys.argv),
        }
        _atomic_write(run_dir / "run.json", json.dumps(meta, indent=2, default=str))
        say(f"run folder: {run_dir}")
        say(f"training {s.algo} (RLlib) on {s.env_id}{' self-play (' + s.self_play + ')' if s.self_play else ''}: "
            f"{c.num_env_runners} env runners x {c.num_envs_per_env_runner} envs "
            f"({meta['rllib']['gym_env_vectorize_mode']}), {c.num_learners} learner actors, "
            f"Ray {'at ' + s.address if s.address else 'local'} with {cluster.get('CPU', 0):g} CPUs")

        def _on_term(signum: int, frame: Any) -> None:
            raise _Interrupted()

        old_handler = signal.signal(signal.SIGTERM, _on_term)
        checkpoints = Checkpoints(run_dir, s.checkpoint_every, s.checkpoint_seconds, s.keep_checkpoints)
        best = max((e["mean_reward"] for e in progress.evaluations), default=-np.inf)
        it = 0
        while True:
            t_it = time.perf_counter()
            result = algo.train()
            row = progress.iteration(result, time.perf_counter() - t_it)
            it = row["iteration"]
            msg = (f"iter {it}: {row['timesteps']} env steps ({row['env_steps_per_second']:.0f}/s), "
                   f"{row['wall_seconds']:.0f} s")
            if row["episode_return_mean"] is not None:
                msg += f", return {row['episode_return_mean']:.3f}"
            if row["success_rate"] is not None:
                msg += f", success {row['success_rate']:.3f}"
            if s.eval_every and it % s.eval_every == 0 and s.eval_episodes:
                t_ev = time.perf_counter()
                res, rows = evaluate_policy(algo, cfg, s.eval_episodes, s.eval_seed)
                entry = progress.evaluation(res, rows, time.perf_counter() - t_ev)
                msg += f" | eval: success {entry['success_rate']:.3f}, return {entry['mean_reward']:.3f}"
                if entry["mean_reward"] > best:
                    best = entry["mean_reward"]
                    checkpoints.save_as(algo, "best_checkpoint")
                progress.excluded += time.perf_counter() - t_ev
            t_ck = time.perf_counter()
            if checkpoints.due(it):
                checkpoints.save(algo, it, row["timesteps"], row["wall_seconds"])
            progress.excluded += time.perf_counter() - t_ck
            say(msg)
            progress.write()
            if s.timesteps and row["timesteps"] >= s.timesteps:
                break
            if s.iterations and it >= s.iterations:
                break
            if s.max_seconds and progress.elapsed() >= s.max_seconds:
                progress.stopped_by_budget = True
                say(f"wall-clock budget of {s.max_seconds:.0f} s reached")
                break
            if s.stop_at_success and progress.evaluations and \
                    progress.evaluations[-1]["success_rate"] >= s.stop_at_success:
                say(f"evaluation success >= stop_at_success {s.stop_at_success}: stopping")
                break
    except (KeyboardInterrupt, _Interrupted):
        interrupted = True
        say("interrupted: saving a checkpoint")
    finally:
        if old_handler is not None:
            signal.signal(signal.SIGTERM, old_handler)
        try:
            if algo is not None and progress.iterations:
                last = progress.iterations[-1]
                checkpoints.save(algo, last["iteration"], last["timesteps"], last["wall_seconds"])
                final = checkpoints.save_as(algo, "final_checkpoint")
                summary = progress.summary()
                progress.write()
                best_dir = run_dir / "best_checkpoint"
                meta.update({
                    "finished": time.strftime("%Y-%m-%dT%H:%M:%S"), "timesteps": summary["timesteps"],
                    "iterations": last["iteration"], "wall_seconds": summary["wall_seconds"],
                    "train_steps_per_second": summary["train_steps_per_second"],
                    "eval_seconds": summary["eval_seconds"], "stopped_by_budget": summary["stopped_by_budget"],
                    "interrupted": interrupted, "final_checkpoint": str(final),
                    "best_checkpoint": str(best_dir) if best_dir.is_dir() else None,
                    "best_eval": max(summary["evaluations"], key=lambda e: e["mean_reward"])
                    if summary["evaluations"] else None,
                    "milestones": summary["milestones"],
                })
                _atomic_write(run_dir / "run.json", json.dumps(meta, indent=2, default=str))
                say(f"done: {meta['timesteps']} env steps in {meta['wall_seconds']:.0f} s "
                    f"({meta['train_steps_per_second']:.0f} env steps/s excluding evaluation); run folder {run_dir}")
        finally:
            if algo is not None:
                algo.stop()
            if started:
                ray.shutdown()
    return meta if algo is not None and progress.iterations else {"run_dir": str(run_dir), "interrupted": interrupted}


def _pairs(items: Sequence[str] | None, flag: str) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for item in items or []:
        key, sep, value = item.partition("=")
        if not sep or not key:
            raise RLlibConfigError(f"{flag}: expected key=value, got {item!r}")
        out[key.strip()] = yaml.safe_load(value)
    return out


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m agents.rllib", description=__doc__.split("\n\n")[0],
                                epilog="Config format: agents/rllib/config.py and configs/train/rllib_*.yaml.")
    p.add_argument("--config", help="RLlib training config YAML ('rllib:' AlgorithmConfig sections + 'billiards:')")
    p.add_argument("--resume", help="run folder (or checkpoint inside one) to continue")
    p.add_argument("--algo", help=f"algorithm: {', '.join(ALGOS)} (default PPO)")
    p.add_argument("--env", type=env_id_arg, help="registered env id (default BilliardsOneBall-v0)")
    p.add_argument("--env-kwargs", nargs="*", metavar="KEY=VALUE", help="env options (merged over the config's)")
    p.add_argument("--self-play", choices=SELF_PLAY, help="games: both seats learn, one shared policy or one each")
    p.add_argument("--num-env-runners", type=int, help="sampling actors (0: sample in this process)")
    p.add_argument("--num-envs-per-env-runner", type=int, help="envs stepped together in each env runner")
    p.add_argument("--num-learners", type=int, help="learner actors (0: learn in this process)")
    p.add_argument("--vectorize-mode", choices=VECTORIZE_MODES,
                   help="gym_env_vectorize_mode (default vector_entry_point: the native vector env)")
    p.add_argument("--address", help="Ray cluster to join: auto (ray start on this node), ray://head:10001")
    p.add_argument("--timesteps", type=float, help="stop after this many env steps")
    p.add_argument("--iterations", type=int, help="stop after this many training iterations")
    p.add_argument("--seconds", type=float, help="wall-clock budget")
    p.add_argument("--seed", type=int)
    p.add_argument("--name", help="run name (folder runs/<name>-<timestamp>)")
    p.add_argument("--run-root", help="parent folder of run folders (default runs)")
    p.add_argument("--run-dir", help="exact run folder to create")
    p.add_argument("--eval-every", type=int, help="iterations between evaluations (0: none)")
    p.add_argument("--eval-episodes", type=int, help="episodes per evaluation")
    p.add_argument("--set", nargs="*", metavar="SECTION.KEY=VALUE",
                   help="AlgorithmConfig overrides, e.g. training.lr=3e-4 env_runners.rollout_fragment_length=64")
    p.add_argument("--quiet", action="store_true")
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        overrides: dict[str, Any] = {}
        for key, val in (("algo", args.algo), ("env_id", args.env), ("self_play", args.self_play),
                         ("address", args.address), ("timesteps", args.timesteps), ("iterations", args.iterations),
                         ("max_seconds", args.seconds), ("seed", args.seed), ("name", args.name),
                         ("run_root", args.run_root), ("eval_every", args.eval_every),
                         ("eval_episodes", args.eval_episodes)):
            if val is not None:
                overrides[key] = val
        sections = parse_assignments(args.set, "--set")
        runners = sections.setdefault("env_runners", {})
        for key, val in (("num_env_runners", args.num_env_runners),
                         ("num_envs_per_env_runner", args.num_envs_per_env_runner),
                         ("gym_env_vectorize_mode", args.vectorize_mode)):
            if val is not None:
                runners[key] = val
        if args.num_learners is not None:
            sections.setdefault("learners", {})["num_learners"] = args.num_learners
        sections = {k: v for k, v in sections.items() if v}
        resume = Path(args.resume) if args.resume else None
        source: Any = args.config
        if resume is not None and source is None:
            from .player import resume_checkpoint

            run_dir = resume_checkpoint(resume)[1]
            if run_dir is None:
                raise RLlibConfigError(f"--resume: {resume} is not inside an agents.rllib run folder")
            source = run_dir / "config.yaml"
        base = load_rllib_config(source)
        if args.env_kwargs:
            overrides["env_kwargs"] = {**base.settings.env_kwargs, **_pairs(args.env_kwargs, "--env-kwargs")}
        cfg = load_rllib_config(source, overrides, sections)
        if args.config is None and resume is None and not (cfg.settings.timesteps or cfg.settings.iterations
                                                           or cfg.settings.max_seconds):
            cfg.settings.timesteps = 1e6  # the command line alone: a default stopping rule
        train(cfg, Path(args.run_dir) if args.run_dir else None, resume, quiet=args.quiet)
    except (RLlibConfigError, FileNotFoundError) as exc:
        print(f"agents.rllib: error: {exc}", file=sys.stderr)
        return 2
    except ValueError as exc:  # the env's ConfigError (a bad env option) names the key and the fix
        print(f"agents.rllib: error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
