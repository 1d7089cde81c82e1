"""Train an SB3 agent (SAC, TD3, PPO, A2C, DDPG) on a billiards env from a config file.

    python -m agents.train --config configs/train/one_ball_sac.yaml
    python -m agents.train --config configs/train/one_ball_sac.yaml --seconds 120 --name quick
    python -m agents.train --resume runs/one_ball_sac-20250101-120000      # continue an interrupted run
    python -m agents.train --config configs/train/three_balls_sac.yaml --set seed=3 --hp batch_size=512

A run folder ``runs/<name>-<timestamp>/`` holds: ``config.yaml`` (the resolved config: rerun it with
``--config``), ``run.json`` (what ran, versions, steps/s, wall time, final figures), ``progress.json``
(evaluations and the time each success level was first reached), ``best_model.zip`` (EvalCallback's best),
``final_model.zip``, ``checkpoints/`` (model every ``checkpoint_freq`` steps / ``checkpoint_seconds`` s, the
replay buffer, ``latest.json``), ``eval/evaluations.npz``, ``monitor/`` (per-env Monitor CSVs with
``is_success``) and ``tb/`` (TensorBoard: ``tensorboard --logdir runs``).

``--resume`` takes a run folder (or a checkpoint ``.zip`` inside one): the latest checkpoint's model and
replay buffer are loaded and training goes on in the same folder up to ``n_timesteps`` and the time budget
``max_seconds``, both totals of the run (``--timesteps`` and ``--seconds`` override them as totals too; a run that
has spent either is refused with the command that trains on). The budget counts the seconds of
``budget_clock``: ``wall`` or the training process's ``cpu`` seconds (the committed configs). Ctrl-C or SIGTERM saves a checkpoint before exiting, so an interruption loses at most one
checkpoint interval even if the process is killed harder.
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import signal
import sys
import time
from dataclasses import asdict
from pathlib import Path
from typing import Any, Callable, Sequence

import numpy as np
import yaml

from .config import (ALGOS, OFF_POLICY, AlgoSetup, TrainConfig, TrainConfigError, load_train_config,
                     parse_hyperparams)

REPO_ROOT = Path(__file__).resolve().parent.parent


def algo_class(name: str) -> Any:
    import stable_baselines3 as sb3

    if name not in ALGOS:
        raise TrainConfigError(f"algo: unknown algorithm {name!r}; use one of {', '.join(ALGOS)}")
    return getattr(sb3, name.upper())  # the class of each name in ALGOS (config.py: the one list)


def make_env_fn(env_id: str, env_kwargs: dict[str, Any], wrapper: Any = None, render_mode: str | None = None):
    """A no-argument env factory (registers the billiards ids first)."""

    def _make() -> Any:
        import gymnasium as gym

        import billiards_env  # noqa: F401  (registers the ids)

        env = gym.make(env_id, render_mode=render_mode, **env_kwargs) if render_mode else \
            gym.make(env_id, **env_kwargs)
        return wrapper(env) if wrapper is not None else env

    return _make


#: Which SB3 VecEnv trains: "auto" (the native vector env where it applies, else DummyVecEnv), "native", "dummy".
VEC_ENVS = ("auto", "native", "dummy")


def use_native(cfg: TrainConfig, setup: AlgoSetup, vec_env: str = "auto") -> bool:
    """Whether to train on :class:`agents.vec.BilliardsVecEnv` (N tables in one call; the same transitions as
    DummyVecEnv with the same seeds) rather than a DummyVecEnv of single envs: ``auto`` uses it where it applies
    (no env wrapper; a config the native vector env runs as arrays: the pot task on the exact solver, 9-ball and
    8-ball against the geometric player or none), ``native`` insists."""
    from .vec import native_vec_env_supported

    if vec_env not in VEC_ENVS:
        raise TrainConfigError(f"vec_env: unknown {vec_env!r}; use one of {', '.join(VEC_ENVS)}")
    if vec_env == "dummy":
        return False
    ok = native_vec_env_supported(cfg.env_id, setup.env_kwargs, setup.wrapper)
    if vec_env == "native" and not ok:
        raise TrainConfigError(f"vec_env: 'native' needs no env_wrapper and a config the native vector env runs as "
                               f"arrays ({cfg.env_id} with these env_kwargs does not qualify: see "
                               "BilliardsVectorEnv.not_native); use 'auto' or 'dummy'")
    return ok


def make_vec_envs(cfg: TrainConfig, setup: AlgoSetup, n_envs: int, seed: int, monitor_dir: Path | None,
                  vecnormalize_path: Path | None = None, training: bool = True, vec_env: str = "auto") -> Any:
    """The training (or evaluation) VecEnv of ``n_envs`` envs, seeded with ``seed``: the native vector env under
    a VecMonitor where it applies (:func:`use_native`), else a DummyVecEnv of Monitor-wrapped envs. Both log
    ``*.monitor.csv`` files with ``is_success`` in ``monitor_dir``."""
    from stable_baselines3.common.env_util import make_vec_env
    from stable_baselines3.common.vec_env import DummyVecEnv, VecMonitor, VecNormalize

    import billiards_env  # noqa: F401

    monitor_kwargs = {"info_keywords": ("is_success",), **setup.monitor_kwargs}
    if use_native(cfg, setup, vec_env):
        from .vec import BilliardsVecEnv

        if monitor_dir is not None:
            monitor_dir.mkdir(parents=True, exist_ok=True)
        env = BilliardsVecEnv(cfg.env_id, n_envs, setup.env_kwargs, threads=1)
        env.seed(seed)
        env = VecMonitor(env, str(monitor_dir / "vec") if monitor_dir else None, **monitor_kwargs)
    else:
        env = make_vec_env(make_env_fn(cfg.env_id, setup.env_kwargs), n_envs=n_envs, seed=seed,
                           monitor_dir=str(monitor_dir) if monitor_dir else None, wrapper_class=setup.wrapper,
                           vec_env_cls=DummyVecEnv, monitor_kwargs=monitor_kwargs)
    if setup.normalize is not None:
        if vecnormalize_path is not None and vecnormalize_path.exists():
            env = VecNormalize.load(str(vecnormalize_path), env)
        else:
            env = VecNormalize(env, **setup.normalize)
        if not training:
            env.training = False
            env.norm_reward = False
    return env


def env_spec(cfg: TrainConfig, setup: AlgoSetup) -> dict[str, Any]:
    """What ``env.json`` holds: the env id and kwargs (``gym.make(spec["id"], **spec["kwargs"])`` makes the env a
    model was trained on) and, for a config that wraps the env, the wrapper (``env_wrapper``, as in the config)."""
    out: dict[str, Any] = {"id": cfg.env_id, "kwargs": setup.env_kwargs}
    if cfg.hyperparams.get("env_wrapper"):
        out["wrapper"] = cfg.hyperparams["env_wrapper"]
    return out


def _action_noise(setup: AlgoSetup, env: Any) -> Any:
    if setup.noise is None:
        return None
    from stable_baselines3.common.noise import NormalActionNoise, OrnsteinUhlenbeckActionNoise

    kind, std = setup.noise
    n = env.action_space.shape[0]
    if "normal" in kind:
        return NormalActionNoise(np.zeros(n), std * np.ones(n))
    if "ornstein-uhlenbeck" in kind:
        return OrnsteinUhlenbeckActionNoise(np.zeros(n), std * np.ones(n))
    raise TrainConfigError(f"noise_type: unknown {kind!r}; use 'normal' or 'ornstein-uhlenbeck'")


def _versions() -> dict[str, str]:
    import gymnasium
    import stable_baselines3
    import torch

    return {"python": platform.python_version(), "torch": torch.__version__, "stable_baselines3":
            stable_baselines3.__version__, "gymnasium": gymnasium.__version__, "numpy": np.__version__,
            "machine": f"{platform.machine()} {os.cpu_count()} cpu"}


def git_commit() -> str | None:
    """The repository's commit (read from ``.git``, no subprocess), None outside a checkout (the RLlib runs write it
    too)."""
    head = REPO_ROOT / ".git" / "HEAD"
    try:
        ref = head.read_text().strip()
        if ref.startswith("ref: "):
            return (REPO_ROOT / ".git" / ref[5:]).read_text().strip()
        return ref
    except OSError:
        return None


def new_run_dir(root: Path, name: str) -> Path:
    stamp = time.strftime("%Y%m%d-%H%M%S")
    d = root / f"{name}-{stamp}"
    k = 1
    while d.exists():
        k += 1
        d = root / f"{name}-{stamp}-{k}"
    d.mkdir(parents=True)
    return d


def find_checkpoint(path: Path) -> tuple[Path, Path, dict[str, Any]]:
    """``(run_dir, model_zip, latest_meta)`` for a run folder or a checkpoint zip inside one."""
    path = Path(path)
    if path.is_file() and path.suffix == ".zip":
        run_dir = path.parent.parent if path.parent.name == "checkpoints" else path.parent
        meta: dict[str, Any] = {}
        latest = run_dir / "checkpoints" / "latest.json"
        if latest.exists():
            meta = json.loads(latest.read_text())
            if meta.get("model") != path.name:
                meta = {k: v for k, v in meta.items() if k in ("replay_buffer", "vecnormalize")}
        return run_dir, path, meta
    if not path.is_dir():
        raise TrainConfigError(f"--resume: {path} is neither a run folder nor a checkpoint .zip")
    latest = path / "checkpoints" / "latest.json"
    if latest.exists():
        meta = json.loads(latest.read_text())
        return path, path / "checkpoints" / meta["model"], meta
    for name in ("final_model.zip", "best_model.zip"):
        if (path / name).exists():
            return path, path / name, {}
    raise TrainConfigError(f"--resume: no checkpoint in {path} (expected checkpoints/latest.json)")


class _Interrupted(Exception):
    pass


def _spent_budget(max_seconds: float, clock: str, seconds: float, steps: int, n_timesteps: int) -> str | None:
    """What a resumed run has already used up, as the end of an error message, or None if it can train on: both
    limits are the run's totals (``max_seconds`` in the budget's clock, ``n_timesteps``), counting earlier
    sessions."""
    unit = "CPU s" if clock == "cpu" else "s"
    if max_seconds and seconds >= max_seconds:
        return (f"has spent its time budget ({seconds:.0f} of {max_seconds:.0f} {unit}, max_seconds counts the "
                f"run's total {clock} seconds): nothing to train. To train on, raise the total, e.g. "
                f"--seconds {seconds + 300:.0f} for 300 {unit} more")
    if steps >= n_timesteps:
        return (f"has reached n_timesteps ({steps} of {n_timesteps} steps, the run's total): nothing to train. To "
                f"train on, raise the total, e.g. --timesteps {steps + 100_000}")
    return None


def train(cfg: TrainConfig, run_dir: Path | None = None, resume: Path | None = None,
          progress_bar: bool | None = None, quiet: bool = False, vec_env: str = "auto",
          init: Callable[[Any], None] | None = None) -> dict[str, Any]:
    """Train from a resolved config; returns the run summary (also written to ``run.json``). ``vec_env``: see
    :func:`use_native`. ``init(model)`` is called on a new model before it learns (e.g. to start from a
    behaviour-cloned policy: :mod:`agents.distill`); not on a resumed one."""
    import torch
    from stable_baselines3.common.callbacks import CallbackList

    from .callbacks import BudgetProgressBar, RunCheckpoint, SeededEvalCallback, TrainingClock

    s = cfg.settings
    torch.set_num_threads(max(int(s.torch_threads), 1))
    setup = parse_hyperparams(cfg)
    algo = algo_class(s.algo)
    say = (lambda *a: None) if quiet else (lambda *a: print(*a, flush=True))

    offset_seconds, offset_steps, resumed_from = 0.0, 0, None
    ckpt_meta: dict[str, Any] = {}
    model_zip: Path | None = None
    prior_best = -np.inf
    if resume is not None:
        run_dir, model_zip, ckpt_meta = find_checkpoint(resume)
        resumed_from = str(model_zip)
        prog = run_dir / "progress.json"
        if prog.exists():
            p = json.loads(prog.read_text())
            offset_seconds = float(ckpt_meta.get("wall_seconds") or p.get("wall_seconds", 0.0))
            rewards = [e["mean_reward"] for e in p.get("evaluations", [])]
            prior_best = max(rewards) if rewards else -np.inf
        spent = _spent_budget(s.max_seconds, s.budget_clock, offset_seconds, int(ckpt_meta.get("timesteps") or 0),
                              setup.n_timesteps)
        if spent is not None:  # before loading the model and its replay buffer
            raise TrainConfigError(f"--resume: {run_dir} {spent}")
    elif run_dir is None:
        name = s.name or (Path(cfg.source).stem if cfg.source != "<dict>" else f"{cfg.env_id}-{s.algo}")
        run_dir = new_run_dir(REPO_ROOT / s.run_root if not Path(s.run_root).is_absolute() else Path(s.run_root),
                              name)
    run_dir = Path(run_dir)
    run_dir.mkdir(parents=True, exist_ok=True)
    if resume is None:
        (run_dir / "config.yaml").write_text(
            f"# Resolved config of this run (from {cfg.source}); rerun with --config {run_dir / 'config.yaml'}\n"
            + yaml.safe_dump(cfg.to_yaml_dict(), sort_keys=False))

    monitor_dir = run_dir / "monitor"
    monitor_dir.mkdir(exist_ok=True)
    session = len(list(monitor_dir.glob("session*"))) if resume else 0
    mon = monitor_dir / f"session{session}"
    vn_path = run_dir / "checkpoints" / ckpt_meta["vecnormalize"] if ckpt_meta.get("vecnormalize") else None
    env = make_vec_envs(cfg, setup, setup.n_envs, s.seed + 1000 * session, mon, vn_path, vec_env=vec_env)

    if model_zip is not None:
        say(f"resuming from {model_zip}")
        model = algo.load(str(model_zip), env=env, device=s.device, tensorboard_log=str(run_dir / "tb"))
        rb = ckpt_meta.get("replay_buffer")
        if s.algo in OFF_POLICY and rb and (run_dir / "checkpoints" / rb).exists():
            model.load_replay_buffer(str(run_dir / "checkpoints" / rb))
            say(f"replay buffer restored: {model.replay_buffer.size()} transitions")
        offset_steps = int(model.num_timesteps)
        spent = _spent_budget(s.max_seconds, s.budget_clock, offset_seconds, offset_steps, setup.n_timesteps)
        if spent is not None:
            env.close()
            raise TrainConfigError(f"--resume: {run_dir} {spent}")
    else:
        kwargs = dict(setup.algo_kwargs)
        noise = _action_noise(setup, env)
        if noise is not None:
            kwargs["action_noise"] = noise
        try:
            model = algo(setup.policy, env, seed=s.seed, device=s.device, verbose=s.verbose,
                         tensorboard_log=str(run_dir / "tb"), **kwargs)
        except TypeError as exc:
            raise TrainConfigError(f"{cfg.source}: {s.algo.upper()} does not accept these hyperparameters "
                                   f"({exc}); check the '{cfg.env_id}:' entry") from None
        if init is not None:
            init(model)

    clock = TrainingClock(run_dir, s.max_seconds, offset_seconds, offset_steps, verbose=1 if not quiet else 0,
                          clock=s.budget_clock)
    ckpt = RunCheckpoint(run_dir, s.checkpoint_freq, s.checkpoint_seconds, s.keep_checkpoints,
                         s.save_replay_buffer, clock, verbose=0)
    callbacks: list[Any] = [clock, ckpt]
    eval_cb = None
    if s.eval_freq > 0 and s.n_eval_episodes > 0:
        eval_env = make_vec_envs(cfg, setup, min(s.n_eval_envs, s.n_eval_episodes), s.eval_seed, None, vn_path,
                                 training=False, vec_env=vec_env)
        (run_dir / "eval").mkdir(exist_ok=True)
        eval_cb = SeededEvalCallback(
            eval_env, eval_seed=s.eval_seed, clock=clock, stop_at_success=s.stop_at_success,
            n_eval_episodes=s.n_eval_episodes, eval_freq=max(s.eval_freq // setup.n_envs, 1),
            best_model_save_path=str(run_dir), log_path=str(run_dir / "eval"), deterministic=True,
            verbose=0, warn=False)
        eval_cb.print_progress = not quiet
        eval_cb.best_mean_reward = prior_best
        if resume is not None and (run_dir / "eval" / "evaluations.npz").exists():
            old = np.load(run_dir / "eval" / "evaluations.npz")
            eval_cb.evaluations_timesteps = list(old["timesteps"])
            eval_cb.evaluations_results = [list(r) for r in old["results"]]
            eval_cb.evaluations_length = [list(r) for r in old["ep_lengths"]]
            if "successes" in old:
                eval_cb.evaluations_successes = [list(r) for r in old["successes"]]
        if resume is not None and (run_dir / "progress.json").exists():
            clock.evals = json.loads((run_dir / "progress.json").read_text()).get("evaluations", [])
            clock.milestones = json.loads((run_dir / "progress.json").read_text()).get("milestones", {})
        callbacks.append(eval_cb)

    total = setup.n_timesteps
    remaining = max(total - offset_steps, 0)
    meta: dict[str, Any] = {
        "env_id": cfg.env_id, "algo": s.algo, "config_source": cfg.source, "run_dir": str(run_dir),
        "n_envs": setup.n_envs, "vec_env": "native" if use_native(cfg, setup, vec_env) else "dummy",
        "n_timesteps": total, "env_kwargs": setup.env_kwargs,
        "env_wrapper": cfg.hyperparams.get("env_wrapper"), "seed": s.seed, "settings": asdict(s),
        "versions": _versions(), "git_commit": git_commit(), "resumed_from": resumed_from,
        "started": time.strftime("%Y-%m-%dT%H:%M:%S"), "command": " ".join(sys.argv),
    }
    (run_dir / "run.json").write_text(json.dumps(meta, indent=2, default=str))
    # What the model was trained on: gym.make(env["id"], **env["kwargs"]) gives that env (see the README).
    (run_dir / "env.json").write_text(json.dumps(env_spec(cfg, setup), indent=2))
    say(f"run folder: {run_dir}")
    say(f"training {s.algo.upper()} on {cfg.env_id} ({setup.n_envs} envs) for {remaining} steps"
        + (f" (budget {s.max_seconds:.0f} s)" if s.max_seconds else ""))

    def _on_term(signum: int, frame: Any) -> None:
        raise _Interrupted()

    old_handler = signal.signal(signal.SIGTERM, _on_term) if hasattr(signal, "SIGTERM") else None
    interrupted = False
    use_bar = s.progress_bar if progress_bar is None else progress_bar
    if use_bar:
        callbacks.append(BudgetProgressBar(clock, remaining))
    try:
        if remaining > 0 and not (s.max_seconds and offset_seconds >= s.max_seconds):
            model.learn(remaining, callback=CallbackList(callbacks), progress_bar=False,
                        reset_num_timesteps=resume is None, tb_log_name="run",
                        log_interval=s.log_interval if s.log_interval > 0 else 10**9)
    except (KeyboardInterrupt, _Interrupted):
        interrupted = True
        say("interrupted: saving a checkpoint")
    finally:
        if old_handler is not None:
            signal.signal(signal.SIGTERM, old_handler)
        if getattr(ckpt, "model", None) is None:  # learn() never ran (SB3 sets .model in init_callback)
            ckpt.init_callback(model)
        ckpt.save_now()
    final = run_dir / "final_model.zip"
    model.save(final)
    if model.get_vec_normalize_env() is not None:
        model.get_vec_normalize_env().save(str(run_dir / "vecnormalize.pkl"))
    if getattr(clock, "model", None) is None:
        clock.init_callback(model)
    summary = clock.summary()
    summary["interrupted"] = interrupted
    clock.write()
    best = run_dir / "best_model.zip"
    meta.update({
        "finished": time.strftime("%Y-%m-%dT%H:%M:%S"),
        "timesteps": int(model.num_timesteps),
        "wall_seconds": summary["wall_seconds"],
        "clock": summary["clock"],  # what wall_seconds counts: "wall" or "cpu" (billiards.budget_clock)
        "train_steps_per_second": summary["train_steps_per_second"],
        "eval_seconds": summary["eval_seconds"],
        "stopped_by_budget": summary["stopped_by_budget"],
        "interrupted": interrupted,
        "final_model": str(final),
        "best_model": str(best) if best.exists() else None,
        "best_eval": max(summary["evaluations"], key=lambda e: e["mean_reward"]) if summary["evaluations"] else None,
        "milestones": summary["milestones"],
    })
    (run_dir / "run.json").write_text(json.dumps(meta, indent=2, default=str))
    # What the model was trained on: gym.make(env["id"], **env["kwargs"]) gives that env (see the README).
    (run_dir / "env.json").write_text(json.dumps(env_spec(cfg, setup), indent=2))
    say(f"done: {meta['timesteps']} steps in {meta['wall_seconds']:.0f} s "
        f"({meta['train_steps_per_second']:.0f} env steps/s excluding evaluation); run folder {run_dir}")
    env.close()
    return meta


def _parse_value(text: str) -> Any:
    return yaml.safe_load(text)


def _pairs(items: Sequence[str] | None, flag: str) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for item in items or []:
        key, sep, value = item.partition("=")
        if not sep or not key:
            raise TrainConfigError(f"{flag}: expected key=value, got {item!r}")
        out[key.strip()] = _parse_value(value)
    return out


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m agents.train", description="Train an SB3 agent on a billiards env.",
                                epilog="Config format: see agents/config.py and configs/train/*.yaml.")
    p.add_argument("--config", help="training config YAML (RL Zoo entry + 'billiards:' section)")
    p.add_argument("--resume", help="run folder or checkpoint .zip to continue")
    p.add_argument("--env-id", help="env entry of the config to train (default: billiards.env_id)")
    p.add_argument("--algo", help="override billiards.algo (sac, td3, ppo, a2c, ddpg)")
    p.add_argument("--timesteps", type=float,
                   help="override n_timesteps: the run's total env steps (with --resume, counting those done)")
    p.add_argument("--seconds", type=float,
                   help="override billiards.max_seconds: the run's total training budget in the config's clock "
                        "(billiards.budget_clock: 'cpu' = CPU seconds of the training process, as the committed "
                        "configs count; 'wall' = elapsed seconds); with --resume, counting the seconds already "
                        "spent, so give more than the run has used to train on")
    p.add_argument("--seed", type=int, help="override billiards.seed")
    p.add_argument("--n-envs", type=int, help="override n_envs")
    p.add_argument("--name", help="run name (folder runs/<name>-<timestamp>)")
    p.add_argument("--run-root", help="parent folder of run folders (default runs)")
    p.add_argument("--run-dir", help="exact run folder to create/use (instead of runs/<name>-<timestamp>)")
    p.add_argument("--set", nargs="*", metavar="KEY=VALUE", help="override billiards: settings")
    p.add_argument("--hp", nargs="*", metavar="KEY=VALUE", help="override hyperparameters of the env entry")
    p.add_argument("--env-kwargs", nargs="*", metavar="KEY=VALUE", help="override env kwargs")
    p.add_argument("--vec-env", choices=VEC_ENVS, default="auto",
                   help="auto (default): the native vector env where it applies, else DummyVecEnv")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.add_argument("--quiet", action="store_true")
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        overrides = _pairs(args.set, "--set")
        for key, val in (("algo", args.algo), ("max_seconds", args.seconds), ("seed", args.seed),
                         ("name", args.name), ("run_root", args.run_root)):
            if val is not None:
                overrides[key] = val
        hyper = _pairs(args.hp, "--hp")
        if args.timesteps is not None:
            hyper["n_timesteps"] = int(args.timesteps)
        if args.n_envs is not None:
            hyper["n_envs"] = args.n_envs
        if args.env_kwargs:
            hyper["env_kwargs"] = _pairs(args.env_kwargs, "--env-kwargs")
        resume = Path(args.resume) if args.resume else None
        if resume is not None:
            run_dir = find_checkpoint(resume)[0]
            cfg = load_train_config(args.config or run_dir / "config.yaml", args.env_id, overrides, hyper)
        elif args.config:
            cfg = load_train_config(args.config, args.env_id, overrides, hyper)
        else:
            raise TrainConfigError("give --config FILE (see configs/train/) or --resume RUN_DIR")
        train(cfg, Path(args.run_dir) if args.run_dir else None, resume,
              progress_bar=False if args.no_progress else None, quiet=args.quiet, vec_env=args.vec_env)
    except TrainConfigError as exc:
        print(f"agents.train: error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
