"""RLlib throughput: env steps per second with 0, 1 and 2 (or more) env runners, in one run.

    .venv-rllib/bin/python -m benchmarks.rllib_throughput                 # ~3 min on 2 cores
    .venv-rllib/bin/python -m benchmarks.rllib_throughput --runners 0 1 2 4 --envs-per-runner 16 --repeats 7
    .venv-rllib/bin/python -m benchmarks.rllib_throughput --env Billiards9Ball-v0 --modes sync
    .venv-rllib/bin/python -m benchmarks.rllib_throughput --address auto --runners 0 8 16 32   # a Ray cluster

Needs the rllib extra (``bash scripts/setup.sh --rllib``). For each number of env runners (0 = the driver samples
itself) and each vectorization mode, the script builds PPO with the agent design of
``configs/train/rllib_one_ball_ppo.yaml`` on a local Ray with this machine's CPUs (or the cluster of
``--address``) and measures two figures, each
the median over ``--repeats`` timed repeats after one warm-up:

- **sampling**: every env runner samples ``--steps`` env steps at once (``EnvRunner.sample``, exploring, in
  parallel across runners), as RLlib does at the start of each iteration; env steps of all runners / wall time.
  This is what env runners scale: on a cluster it grows with the runners until the learner is the bottleneck.
- **training**: full ``algo.train()`` iterations (sample ``train_batch_size_per_learner`` steps, ship them to the
  learner in the driver, update); env steps sampled per iteration / its wall time.

On a machine with C cores, more than C - 1 runners compete with the driver's learner for the CPUs; the figures
say how much a 2-core machine gets, not what a cluster gets. Prints a Markdown table; ``--out FILE`` writes JSON.
"""
from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path
from typing import Any, Sequence

from agents.rllib.algorithm import build_algorithm, init_ray
from agents.rllib.config import VECTORIZE_MODES, load_rllib_config
from billiards_env.registration import env_id_arg

from .common import fmt_rate, load_now, machine_info, machine_markdown, write_json

REPO = Path(__file__).resolve().parents[1]
CONFIG = REPO / "configs" / "train" / "rllib_one_ball_ppo.yaml"


def build(env_id: str, runners: int, envs: int, mode: str, batch: int, local: bool = True) -> Any:
    """PPO with the committed config's env options and network, ``runners`` env runners x ``envs`` envs."""
    base = load_rllib_config(CONFIG)
    kwargs = base.settings.env_kwargs if env_id == base.env_id else {}
    cfg = load_rllib_config(CONFIG, {"env_id": env_id, "env_kwargs": kwargs}, {
        "env_runners": {"num_env_runners": runners, "num_envs_per_env_runner": envs,
                        "gym_env_vectorize_mode": mode},
        "training": {"train_batch_size_per_learner": batch, "minibatch_size": min(512, batch)},
    })
    return build_algorithm(cfg, local=local)


def sample_once(algo: Any, steps: int) -> float:
    """Every env runner samples ``steps`` env steps (remote runners in parallel); env steps per second."""
    group = algo.env_runner_group

    def count(runner: Any) -> int:
        return sum(len(e) for e in runner.sample(num_timesteps=steps, explore=True))

    t0 = time.perf_counter()
    if group.num_remote_env_runners() == 0:
        done = [count(group.local_env_runner)]
    else:
        done = group.foreach_env_runner(count, local_env_runner=False)
    return sum(done) / (time.perf_counter() - t0)


def train_once(algo: Any) -> float:
    """One training iteration; env steps sampled in it per second of its wall time."""
    t0 = time.perf_counter()
    result = algo.train()
    seconds = time.perf_counter() - t0
    return float(result["env_runners"]["num_env_steps_sampled"]) / seconds


def measure(env_id: str, runners: int, envs: int, mode: str, steps: int, batch: int, repeats: int,
            local: bool = True) -> dict[str, Any]:
    algo = build(env_id, runners, envs, mode, batch, local)
    try:
        sample_once(algo, steps)  # warm-up (first episodes, numba in the runners)
        sampling = [sample_once(algo, steps) for _ in range(repeats)]
        train_once(algo)
        training = [train_once(algo) for _ in range(repeats)]
    finally:
        algo.stop()
    return {"env_runners": runners, "envs_per_runner": envs, "vectorize_mode": mode,
            "sampling_steps_per_s": statistics.median(sampling), "sampling_runs": sampling,
            "training_steps_per_s": statistics.median(training), "training_runs": training}


def markdown(rows: list[dict[str, Any]], env_id: str, args: argparse.Namespace, info: dict[str, Any],
             end_load: list[float] | None) -> str:
    lines = [f"RLlib PPO on {env_id}: env steps per second (median of {args.repeats} after a warm-up); sampling: "
             f"{args.steps} steps per runner per repeat; training: batch {args.batch} per iteration.", "",
             "| env runners | envs per runner | vectorize mode | sampling steps/s | training steps/s |",
             "|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['env_runners']} | {r['envs_per_runner']} | {r['vectorize_mode']} | "
                     f"{fmt_rate(r['sampling_steps_per_s'])} | {fmt_rate(r['training_steps_per_s'])} |")
    lines += ["", machine_markdown(info, end_load)]
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks.rllib_throughput", description=__doc__.split("\n\n")[0])
    p.add_argument("--env", default="BilliardsOneBall-v0", type=env_id_arg)
    p.add_argument("--runners", type=int, nargs="+", default=[0, 1, 2], help="numbers of env runners to measure")
    p.add_argument("--envs-per-runner", type=int, default=16)
    p.add_argument("--modes", nargs="+", choices=VECTORIZE_MODES, default=["vector_entry_point"],
                   help="gym_env_vectorize_mode values to measure")
    p.add_argument("--steps", type=int, default=2048, help="env steps each runner samples per sampling repeat")
    p.add_argument("--batch", type=int, default=4096, help="train_batch_size_per_learner of the training figure")
    p.add_argument("--repeats", type=int, default=5)
    p.add_argument("--address", help="Ray cluster to measure (auto, ray://head:10001); default a local Ray")
    p.add_argument("--out", help="write the figures as JSON here")
    args = p.parse_args(argv)
    info = machine_info()
    import torch

    torch.set_num_threads(1)  # the driver's learner on one thread, as agents.rllib runs it (billiards.torch_threads)
    started = init_ray(args.address, quiet=True)
    rows = []
    try:
        for mode in args.modes:
            for n in args.runners:
                row = measure(args.env, n, args.envs_per_runner, mode, args.steps, args.batch, args.repeats,
                              local=not args.address)
                rows.append(row)
                print(f"{n} env runners x {args.envs_per_runner} envs ({mode}): sampling "
                      f"{fmt_rate(row['sampling_steps_per_s'])} steps/s, training "
                      f"{fmt_rate(row['training_steps_per_s'])} steps/s", flush=True)
    finally:
        if started:
            import ray

            ray.shutdown()
    end_load = load_now()
    print()
    print(markdown(rows, args.env, args, info, end_load))
    if args.out:
        write_json(Path(args.out), {"env_id": args.env, "settings": vars(args), "machine": info,
                                    "end_load": end_load, "rows": rows})
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
