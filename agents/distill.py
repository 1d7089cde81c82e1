"""Distillation: a teacher's shots -> behaviour cloning into an SB3 policy -> RL fine-tuning, with DAgger rounds.

    python -m agents.distill --config configs/train/one_ball_sac_path.yaml --teacher search --states 4000 \\
        --rl-seconds 300
    python -m agents.distill --config configs/train/nine_ball_sac.yaml --teacher search --states 3000 \\
        --dagger-rounds 2 --rl-seconds 0 --workers 2

1. **Labels.** Episodes of the config's env (its kwargs and wrappers) are played on seeds ``seed .. seed + n``; at
   every shot of the agent the teacher (a baseline player by name, ``search`` by default, from
   :func:`billiards_env.players.make_player` for the env's game) is asked for its action *in the env's own action
   type*: the search player then searches the shots that type can play (it values each candidate through the type's
   ``action`` and ``shot``, :func:`billiards_env.players.search.playable_shots`), so the label is a shot the student
   can express. Which shot is then played: round 0 the teacher's; DAgger round ``k`` the student's of round ``k-1``
   (with probability ``--beta`` the teacher's), so the states labelled are the ones the student reaches
   (Ross et al. 2011). Episodes run on ``--workers`` local processes or Ray workers (``--address``); episode ``k``
   is reset with seed ``seed + k`` and the teacher with the same seed, so the labels do not depend on the workers.
2. **Behaviour cloning** (:func:`behaviour_clone`): the policy of the config's algorithm is fitted to the labels by
   maximum likelihood (SAC: the squashed Gaussian's log-probability of the label; TD3/DDPG: the squared error of
   the deterministic action; PPO/A2C: the Gaussian's log-probability), all labels so far (DAgger aggregates).
3. **RL fine-tuning** (``--rl-seconds``, in the config's budget clock): ``agents.train`` on the config, starting
   from the cloned policy; the actor is held still for the first ``--actor-delay`` env steps while the critic learns
   the values of its shots (a cold critic would otherwise drag a good actor off its teacher's shots).

The run folder (``runs/<name>-distill-<stamp>/``) holds ``bc_model.zip`` (the cloned policy, loadable as any run:
``python -m agents.evaluate --players runs/<run>/bc_model.zip``), ``distill.json`` (labels, teacher's success on
the states it played, BC losses, each stage's evaluation and its CPU seconds) and, after fine-tuning, the usual
training files (``best_model.zip``...).
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
import yaml

from .processes import process_pool
from .config import TrainConfig, load_train_config, parse_hyperparams, wrapper_factory
from .train import REPO_ROOT, algo_class, env_spec, make_vec_envs, new_run_dir, train

#: Labels are clipped to this inside ``[-1, 1]`` for the squashed Gaussian's log-probability (atanh is finite).
LABEL_CLIP = 0.995


# --- labels ---------------------------------------------------------------------------------------------------

def _teacher(name: str, env: Any, seed: int) -> Any:
    """The baseline player ``name`` of the env's game (or of the pot scenes), or ``position_rule``
    (:class:`agents.option_policies.PositionRulePlayer`: the hand-written rule on the ``candidates_position``
    observation)."""
    from billiards_env.players import make_player

    if name == "position_rule":
        from .option_policies import PositionRulePlayer

        return PositionRulePlayer()

    game = _game_of(env)
    return make_player(name, seed=seed, game=game) if game else make_player(name, seed=seed)


def _game_of(env: Any) -> str | None:
    """The registered game of an env (None for the pot scenes)."""
    from billiards_env.games import GAMES

    spec_id = getattr(getattr(env, "spec", None), "id", None)
    return next((g.name for g in GAMES.values() if g.env_id == spec_id), None)


def label_episodes(env_id: str, env_kwargs: dict[str, Any], wrapper: Any, teacher: str, seeds: Sequence[int],
                   student: str | None = None, beta: float = 0.0) -> dict[str, Any]:
    """Play one episode per seed; at every agent shot record the observation and the teacher's action in the env's
    action type. The shot played is the teacher's, or with ``student`` (a model zip) the student's except with
    probability ``beta``. Returns ``obs`` (N, d), ``actions`` (N, a), ``rewards`` of the shots played, the
    episodes' ``success`` and ``teacher_played`` (shots where the teacher's action was played, and how many of
    those episodes it won). On 9-ball's ``candidates_position`` observation also the option scorer's ball-in-hand
    labels (:func:`agents.option_policies.hand_label`): ``hand_obs`` (M, HAND_PLACES, d), ``hand_target`` (M,)."""
    import gymnasium as gym

    import billiards_env  # noqa: F401

    wrap = wrapper_factory(wrapper)
    env = gym.make(env_id, **env_kwargs)
    if wrap is not None:
        env = wrap(env)
    model = None
    if student is not None and student.startswith("scorer:"):  # an agents.scorer policy (DAgger on its states)
        from .option_policies import Scorer

        model = Scorer.load(Path(student[len("scorer:"):]))
    elif student is not None:
        from .evaluate import model_player

        spec = model_player(student)
        model = spec
    obs_l, act_l, rew_l, succ = [], [], [], []
    hand_obs, hand_target = [], []  # ball-in-hand labels of the option scorer (candidates_position only)
    u = env.unwrapped
    hand = _game_of(env) == "nine_ball" and u.config.observation_type == "candidates_position"
    for seed in seeds:
        rng = np.random.default_rng([int(seed), 17])
        obs, info = env.reset(seed=int(seed))
        player = _teacher(teacher, env, int(seed))
        done = False
        while not done:
            label = np.asarray(player.act(env, obs), dtype=np.float32).reshape(-1)
            obs_l.append(np.asarray(obs, dtype=np.float32))
            act_l.append(label)
            view = u.table_state.view
            if hand and view.place_area is not None and not view.break_shot:
                from .option_policies import hand_label

                o_p, t = hand_label(u.table_state, u.observation_type, u.action_type, label)
                hand_obs.append(o_p)
                hand_target.append(t)
            played = label
            if model is not None and rng.random() >= beta:
                played = np.asarray(model.act(env, obs), dtype=np.float32).reshape(-1)
            obs, r, term, trunc, info = env.step(played)
            rew_l.append(float(r))
            done = term or trunc
        succ.append(bool(info.get("is_success", False)))
    env.close()
    out = {"obs": np.asarray(obs_l, dtype=np.float32), "actions": np.asarray(act_l, dtype=np.float32),
           "rewards": np.asarray(rew_l, dtype=np.float32), "success": np.asarray(succ, dtype=bool)}
    if hand:
        from .option_policies import HAND_PLACES

        d = int(env.observation_space.shape[0])
        out["hand_obs"] = np.asarray(hand_obs, dtype=np.float32).reshape(-1, HAND_PLACES, d)
        out["hand_target"] = np.asarray(hand_target, dtype=np.int64)
    return out


def collect_labels(env_id: str, env_kwargs: dict[str, Any], wrapper: Any, teacher: str, seeds: Sequence[int],
                   student: str | None = None, beta: float = 0.0, workers: int = 1,
                   address: str | None = None) -> dict[str, Any]:
    """:func:`label_episodes` on ``workers`` local processes (or the Ray cluster at ``address``), in seed order."""
    seeds = [int(s) for s in seeds]
    n_chunks = max(1, min(len(seeds), 4 * max(workers, 1)))
    chunks = [c.tolist() for c in np.array_split(np.array(seeds, dtype=np.int64), n_chunks) if len(c)]
    args = [(env_id, env_kwargs, wrapper, teacher, c, student, beta) for c in chunks]
    if address:
        import ray

        ray.init(address=address, ignore_reinit_error=True, log_to_driver=False)
        remote = ray.remote(label_episodes)
        parts = ray.get([remote.remote(*a) for a in args])
    elif workers > 1:
        with process_pool(workers) as pool:
            parts = list(pool.map(label_episodes, *zip(*args)))
    else:
        parts = [label_episodes(*a) for a in args]
    return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}


# --- behaviour cloning ------------------------------------------------------------------------------------------

def _log_likelihood(model: Any, obs: Any, actions: Any) -> Any:
    """Per-sample log-probability of ``actions`` under ``model``'s policy (SAC: squashed Gaussian; PPO/A2C:
    Gaussian), or minus the squared error of the deterministic action (TD3/DDPG)."""
    policy = model.policy
    if hasattr(policy, "actor") and hasattr(policy.actor, "get_action_dist_params"):  # SAC
        mean, log_std, kw = policy.actor.get_action_dist_params(obs)
        dist = policy.actor.action_dist.proba_distribution(mean, log_std, **kw)
        return dist.log_prob(actions)
    if hasattr(policy, "actor"):  # TD3 / DDPG
        return -((policy.actor(obs) - actions) ** 2).sum(dim=1)
    return policy.get_distribution(obs).log_prob(actions)  # PPO / A2C (summed over the action dims)


def _deterministic_action(model: Any, obs: Any) -> Any:
    """The policy's deterministic action for a batch of observation tensors, through its public modules (what SB3's
    ``policy.predict`` computes, without its numpy round trip, so that the gradient flows)."""
    policy = model.policy
    if hasattr(policy, "actor") and hasattr(policy.actor, "get_action_dist_params"):  # SAC
        return policy.actor(obs, deterministic=True)
    if hasattr(policy, "actor"):  # TD3 / DDPG
        return policy.actor(obs)
    return policy.get_distribution(obs).get_actions(deterministic=True)  # PPO / A2C


def _bc_parameters(model: Any) -> list[Any]:
    policy = model.policy
    if hasattr(policy, "actor"):
        return list(policy.actor.parameters())
    return list(policy.parameters())


def behaviour_clone(model: Any, obs: np.ndarray, actions: np.ndarray, epochs: int = 30, batch_size: int = 256,
                    lr: float = 1e-3, seed: int = 0, holdout: float = 0.1, mse_weight: float = 10.0
                    ) -> dict[str, Any]:
    """Fit ``model``'s policy to ``(obs, actions)`` by maximum likelihood (see :func:`_log_likelihood`) plus
    ``mse_weight`` times the squared error of its deterministic action (the likelihood alone spends its first
    steps on the spread), Adam, ``epochs`` passes; a ``holdout`` fraction is kept out to report the fit. Returns
    the losses per epoch. The target network of an off-policy actor (TD3/DDPG) is copied from the fitted actor."""
    import torch

    rng = np.random.default_rng(seed)
    n = len(obs)
    order = rng.permutation(n)
    n_val = int(holdout * n) if n >= 50 else 0
    val, fit = order[:n_val], order[n_val:]
    dev = model.device
    o = torch.as_tensor(obs, dtype=torch.float32, device=dev)
    a = torch.as_tensor(np.clip(actions, -LABEL_CLIP, LABEL_CLIP), dtype=torch.float32, device=dev)
    params = _bc_parameters(model)
    opt = torch.optim.Adam(params, lr=lr)
    model.policy.set_training_mode(True)
    history = []
    for epoch in range(int(epochs)):
        perm = fit[rng.permutation(len(fit))]
        total = 0.0
        for start in range(0, len(perm), batch_size):
            idx = torch.as_tensor(perm[start:start + batch_size], device=dev)
            loss = -_log_likelihood(model, o[idx], a[idx]).mean()
            if mse_weight:
                det = _deterministic_action(model, o[idx])
                loss = loss + mse_weight * ((det - a[idx]) ** 2).sum(dim=1).mean()
            opt.zero_grad()
            loss.backward()
            opt.step()
            total += float(loss.detach()) * len(idx)
        entry = {"epoch": epoch + 1, "train_loss": total / max(len(fit), 1)}
        if n_val:
            with torch.no_grad():
                vi = torch.as_tensor(val, device=dev)
                entry["holdout_nll"] = float(-_log_likelihood(model, o[vi], a[vi]).mean())
                pred = _deterministic_action(model, o[vi])
                entry["holdout_mae"] = float((pred - a[vi]).abs().mean())
        history.append(entry)
    model.policy.set_training_mode(False)
    policy = model.policy
    if hasattr(policy, "actor_target"):
        policy.actor_target.load_state_dict(policy.actor.state_dict())
    return {"epochs": history, "samples": n, "holdout": int(n_val)}


def hold_actor(model: Any, steps: int) -> None:
    """Keep ``model``'s actor still (zero gradients) until it has taken ``steps`` env steps, so that the critic
    learns the values of the cloned policy's shots first. Gradient hooks: nothing is saved with the model."""
    policy = model.policy
    if steps <= 0 or not hasattr(policy, "actor"):
        return

    def hook(grad: Any) -> Any:
        return grad * 0.0 if model.num_timesteps < steps else grad

    for p in policy.actor.parameters():
        p.register_hook(hook)


# --- evaluation ----------------------------------------------------------------------------------------------

def success_rate(model_zip: Path, episodes: int, seed: int) -> dict[str, Any]:
    """The success rate of a saved model on ``episodes`` episodes (seeds ``seed + k``), with its Wilson interval."""
    from .evaluate import model_player, run_player

    res, _ = run_player(model_player(model_zip), episodes, seed)
    return {"success_rate": res.success_rate, "ci": list(res.success_ci), "episodes": episodes,
            "ms_per_shot": res.ms_per_shot}


# --- the pipeline ----------------------------------------------------------------------------------------------

def distill(cfg: TrainConfig, teacher: str = "search", states: int = 4000, dagger_rounds: int = 0,
            beta: float = 0.0, bc_epochs: int = 30, bc_lr: float = 1e-3, rl_seconds: float = 0.0,
            actor_delay: int = 20_000, workers: int = 1, address: str | None = None, label_seed: int = 1_000_000,
            eval_episodes: int = 500, eval_seed: int = 10_000, run_dir: Path | None = None,
            quiet: bool = False, labels: Path | None = None, mse_weight: float = 10.0) -> dict[str, Any]:
    """The pipeline of the module docstring; returns (and writes to ``distill.json``) what each stage bought.
    ``labels``: a ``labels.npz`` of an earlier run, cloned again instead of the first round's labelling."""
    import torch

    say = (lambda *a: None) if quiet else (lambda *a: print(*a, flush=True))
    s = cfg.settings
    torch.set_num_threads(max(int(s.torch_threads), 1))
    setup = parse_hyperparams(cfg)
    wrapper_spec = cfg.hyperparams.get("env_wrapper")
    if run_dir is None:
        root = Path(s.run_root) if Path(s.run_root).is_absolute() else REPO_ROOT / s.run_root
        run_dir = new_run_dir(root, f"{s.name or Path(cfg.source).stem}-distill")
    run_dir = Path(run_dir)
    run_dir.mkdir(parents=True, exist_ok=True)
    # what a model of this folder plays (agents.evaluate reads it): as agents.train writes it
    (run_dir / "config.yaml").write_text(f"# Resolved config of this run (from {cfg.source})\n"
                                         + yaml.safe_dump(cfg.to_yaml_dict(), sort_keys=False))
    (run_dir / "env.json").write_text(json.dumps(env_spec(cfg, setup), indent=2))
    report: dict[str, Any] = {"teacher": teacher, "env_id": cfg.env_id, "env_kwargs": setup.env_kwargs,
                              "env_wrapper": wrapper_spec, "config": cfg.source, "stages": []}

    def cpu() -> float:
        t = os.times()
        return t.user + t.system + t.children_user + t.children_system

    env = make_vec_envs(cfg, setup, 1, s.seed, None)
    model = algo_class(s.algo)(setup.policy, env, seed=s.seed, device=s.device,
                               **{k: v for k, v in setup.algo_kwargs.items()})
    data: dict[str, Any] | None = None
    student: str | None = None
    per_round = max(1, states // (dagger_rounds + 1))
    for rnd in range(dagger_rounds + 1):
        c0, w0 = cpu(), time.perf_counter()
        seeds = range(label_seed + rnd * per_round, label_seed + (rnd + 1) * per_round)
        if rnd == 0 and labels is not None:
            with np.load(labels) as f:
                new = {k: f[k] for k in ("obs", "actions", "rewards", "success")}
        else:
            new = collect_labels(cfg.env_id, setup.env_kwargs, wrapper_spec, teacher, seeds,
                                 student if rnd > 0 else None, beta if rnd > 0 else 1.0, workers, address)
        data = new if data is None else {k: np.concatenate([data[k], new[k]]) for k in new}
        np.savez_compressed(run_dir / "labels.npz", **data)
        c1, w1 = cpu(), time.perf_counter()
        fit = behaviour_clone(model, data["obs"], data["actions"], bc_epochs, lr=bc_lr, seed=s.seed + rnd,
                              mse_weight=mse_weight)
        path = run_dir / ("bc_model.zip" if rnd == dagger_rounds else f"bc_model_round{rnd}.zip")
        model.save(path)
        c2 = cpu()
        ev = success_rate(path, eval_episodes, eval_seed) if eval_episodes else {}
        loaded = rnd == 0 and labels is not None
        stage = {"stage": "bc" if rnd == 0 else f"dagger round {rnd}", "episodes_labelled": len(new["success"]),
                 "labels": int(len(new["obs"])), "labels_total": int(len(data["obs"])),
                 "labels_from": str(labels) if loaded else None,
                 "played_success": float(new["success"].mean()) if len(new["success"]) and not loaded else None,
                 "label_cpu_seconds": c1 - c0, "label_wall_seconds": w1 - w0, "bc_cpu_seconds": c2 - c1,
                 "bc_last_epoch": fit["epochs"][-1] if fit["epochs"] else None, "model": str(path), **ev}
        report["stages"].append(stage)
        say(f"{stage['stage']}: {stage['labels']} labels ({stage['labels_total']} in all) in "
            f"{stage['label_wall_seconds']:.0f} s, cloned in {stage['bc_cpu_seconds']:.0f} CPU s"
            + (f"; success {100 * ev['success_rate']:.1f}% on {eval_episodes} episodes" if ev else ""))
        (run_dir / "distill.json").write_text(json.dumps(report, indent=2, default=str))
        student = str(path)
    env.close()
    if rl_seconds > 0:
        cfg.settings.max_seconds = float(rl_seconds)
        bc_path = run_dir / "bc_model.zip"

        def init(m: Any) -> None:
            m.set_parameters(str(bc_path), exact_match=False, device=m.device)
            hold_actor(m, actor_delay)

        meta = train(cfg, run_dir=run_dir, init=init, quiet=quiet, progress_bar=False)
        best = Path(meta["best_model"] or meta["final_model"])
        ev = success_rate(best, eval_episodes, eval_seed) if eval_episodes else {}
        report["stages"].append({"stage": "rl fine-tuning", "cpu_seconds": meta["wall_seconds"],
                                 "clock": meta["clock"], "timesteps": meta["timesteps"], "model": str(best),
                                 "actor_delay": actor_delay, **ev})
        say(f"rl fine-tuning: {meta['timesteps']} steps" + (f"; success {100 * ev['success_rate']:.1f}%" if ev else ""))
    report["run_dir"] = str(run_dir)
    (run_dir / "distill.json").write_text(json.dumps(report, indent=2, default=str))
    return report


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m agents.distill", description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog=__doc__.split("\n\n", 1)[1])
    p.add_argument("--config", required=True, help="training config (its env, kwargs, wrappers, algorithm)")
    p.add_argument("--teacher", default="search", help="a baseline player's name (default search), or "
                   "position_rule (agents.position_rule, on the candidates_position observation)")
    p.add_argument("--states", type=int, default=4000, help="episodes labelled in all (split over the rounds)")
    p.add_argument("--dagger-rounds", type=int, default=0, help="rounds played by the student after the first")
    p.add_argument("--beta", type=float, default=0.0, help="DAgger: chance the teacher's shot is played")
    p.add_argument("--bc-epochs", type=int, default=30)
    p.add_argument("--bc-lr", type=float, default=1e-3)
    p.add_argument("--rl-seconds", type=float, default=0.0, help="RL fine-tuning budget (the config's clock)")
    p.add_argument("--actor-delay", type=int, default=20_000, help="env steps the actor is held still at first")
    p.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    p.add_argument("--address", default=None, help="a Ray cluster's address: label there")
    p.add_argument("--mse-weight", type=float, default=10.0, help="weight of the squared error in the BC loss")
    p.add_argument("--labels", type=Path, default=None, help="labels.npz of an earlier run: clone from it")
    p.add_argument("--eval-episodes", type=int, default=500)
    p.add_argument("--run-root", default=None)
    p.add_argument("--seed", type=int, default=None)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    overrides: dict[str, Any] = {}
    if args.run_root:
        overrides["run_root"] = args.run_root
    if args.seed is not None:
        overrides["seed"] = args.seed
    cfg = load_train_config(args.config, overrides=overrides)
    rep = distill(cfg, args.teacher, args.states, args.dagger_rounds, args.beta, args.bc_epochs, args.bc_lr,
                  args.rl_seconds, args.actor_delay, args.workers, args.address,
                  eval_episodes=args.eval_episodes, eval_seed=cfg.settings.eval_seed, labels=args.labels,
                  mse_weight=args.mse_weight)
    print(f"run folder: {rep['run_dir']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
