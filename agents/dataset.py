"""Expert games as a Minari dataset (the Farama offline-RL format)::

    python -m agents.dataset --env Billiards9Ball-v0 --expert search --episodes 200 --workers 2
    python -m agents.dataset --env BilliardsOneBall-v0 --expert search --episodes 5000 --env-kwargs '{"noise": "olympiad"}'

An expert (a baseline player, ``search`` by default, or a trained run folder) plays whole episodes of a registered
id with its env kwargs; each episode's observations, actions, rewards, terminations and truncations go into a
dataset that ``minari.load_dataset(dataset_id)`` reads, with the env spec (``dataset.recover_environment()`` makes
the same env again). Episodes are played in parallel: local processes (``--workers``), or Ray workers on a cluster
(``--address``; needs the ``rllib`` extra, the ``.venv-rllib`` of ``scripts/setup.sh --rllib``). Episode ``k`` is
reset with seed ``seed + k`` and the expert is reset with the same seed, so a dataset is the same whatever the
number of workers.

Datasets go where Minari keeps them (``~/.minari/datasets``, or ``$MINARI_DATASETS_PATH``; ``--root`` sets it for
this run). The default id is ``billiards/<env>/<expert>-v0``.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
from typing import Any

import numpy as np

from billiards_env.registration import env_id_arg

from .processes import process_pool

DEFAULT_EPISODES = 100


def _expert(name: str, seed: int) -> Any:
    """A player by name (``random``, ``geometric``, ``search``) or a trained run folder / model zip."""
    from billiards_env.players import PLAYERS, make_player

    if name in PLAYERS:
        return make_player(name, seed=seed)
    from .evaluate import model_player

    spec = model_player(name)

    class _Trained:
        name = spec.label

        def reset(self, seed: int | None = None) -> None:
            spec.reset(seed or 0)

        def act(self, source: Any, obs: Any, codec: Any = None) -> np.ndarray:
            """The model's action on ``obs`` (in its own env's action type; it reads no table state)."""
            return spec.act(None, obs)

    return _Trained()


def play_episodes(env_id: str, env_kwargs: dict[str, Any], expert: str, seeds: list[int]) -> list[dict[str, Any]]:
    """Play one episode per seed with the expert; each as a dict of arrays (``observations`` with the final one,
    ``actions``, ``rewards``, ``terminations``, ``truncations``), its ``seed``, and whether it succeeded."""
    import gymnasium as gym

    import billiards_env  # noqa: F401  (registers the ids)

    env = gym.make(env_id, **env_kwargs)
    player = _expert(expert, seeds[0] if seeds else 0)
    out = []
    for seed in seeds:
        obs, info = env.reset(seed=seed)
        player.reset(seed)
        observations, actions, rewards, terms, truncs = [obs], [], [], [], []
        done = False
        while not done:
            action = np.asarray(player.act(env, obs), dtype=np.float32)
            obs, reward, term, trunc, info = env.step(action)
            observations.append(obs)
            actions.append(action)
            rewards.append(float(reward))
            terms.append(bool(term))
            truncs.append(bool(trunc))
            done = term or trunc
        out.append({"seed": seed, "observations": np.asarray(observations), "actions": np.asarray(actions),
                    "rewards": np.asarray(rewards), "terminations": np.asarray(terms),
                    "truncations": np.asarray(truncs), "success": bool(info.get("is_success", False))})
    env.close()
    return out


def collect(env_id: str, env_kwargs: dict[str, Any], expert: str, episodes: int, seed: int = 0, workers: int = 1,
            address: str | None = None) -> list[dict[str, Any]]:
    """Episodes ``seed .. seed + episodes - 1`` played by the expert, in seed order, on ``workers`` local processes
    or on the Ray cluster at ``address``."""
    seeds = list(range(seed, seed + episodes))
    n_chunks = max(1, min(episodes, 4 * max(workers, 1)))
    chunks = [c.tolist() for c in np.array_split(np.array(seeds, dtype=np.int64), n_chunks) if len(c)]
    if address:
        import ray

        ray.init(address=address, ignore_reinit_error=True, log_to_driver=False)
        remote = ray.remote(play_episodes)
        parts = ray.get([remote.remote(env_id, env_kwargs, expert, c) for c in chunks])
    elif workers > 1:
        with process_pool(workers) as pool:
            parts = list(pool.map(play_episodes, [env_id] * len(chunks), [env_kwargs] * len(chunks),
                                  [expert] * len(chunks), chunks))
    else:
        parts = [play_episodes(env_id, env_kwargs, expert, c) for c in chunks]
    return [ep for part in parts for ep in part]


def write_dataset(dataset_id: str, episodes: list[dict[str, Any]], env_id: str, env_kwargs: dict[str, Any],
                  expert: str, description: str | None = None) -> Any:
    """The episodes as the Minari dataset ``dataset_id`` (its env spec: ``env_id`` with ``env_kwargs``)."""
    import gymnasium as gym
    import minari
    from minari.data_collector import EpisodeBuffer

    import billiards_env  # noqa: F401

    env = gym.make(env_id, **env_kwargs)
    buffers = [EpisodeBuffer(id=k, seed=ep["seed"], observations=list(ep["observations"]),
                             actions=list(ep["actions"]), rewards=list(ep["rewards"]),
                             terminations=list(ep["terminations"]), truncations=list(ep["truncations"]))
               for k, ep in enumerate(episodes)]
    wins = sum(ep["success"] for ep in episodes)
    text = description or (f"{len(episodes)} episodes of {env_id} ({env_kwargs or 'default kwargs'}) played by the "
                           f"{expert} player of billiards_env; success in {wins} of them.")
    import warnings

    with warnings.catch_warnings():  # no eval env and no reference scores: both expected here
        warnings.simplefilter("ignore", UserWarning)
        ds = minari.create_dataset_from_buffers(dataset_id, buffers, env=env, algorithm_name=expert,
                                                code_permalink="https://github.com/billiards_env (agents/dataset.py)",
                                                author="billiards_env agents.dataset", description=text)
    env.close()
    return ds


def default_dataset_id(env_id: str, expert: str) -> str:
    """``billiards/<env name>/<expert>-v0`` (the expert's name reduced to letters, digits and dashes)."""
    name = env_id.split("-v")[0]
    who = "".join(ch if ch.isalnum() else "-" for ch in os.path.basename(os.path.normpath(expert))).strip("-")
    return f"billiards/{name}/{who or 'expert'}-v0"


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m agents.dataset", description=__doc__.split("\n\n")[0])
    p.add_argument("--env", default="Billiards9Ball-v0", type=env_id_arg,
                   help="registered id (default Billiards9Ball-v0)")
    p.add_argument("--env-kwargs", default="{}", help="JSON of env kwargs, e.g. '{\"noise\": \"olympiad\"}'")
    p.add_argument("--expert", default="search", help="random, geometric, search, or a trained run folder")
    p.add_argument("--episodes", type=int, default=DEFAULT_EPISODES)
    p.add_argument("--seed", type=int, default=0, help="episode k is reset with seed + k")
    p.add_argument("--workers", type=int, default=os.cpu_count() or 1, help="local processes (default: every core)")
    p.add_argument("--address", default=None, help="a Ray cluster's address (e.g. auto) instead of local processes")
    p.add_argument("--dataset-id", default=None, help="default billiards/<env>/<expert>-v0")
    p.add_argument("--root", default=None, help="where Minari keeps datasets (sets MINARI_DATASETS_PATH)")
    p.add_argument("--overwrite", action="store_true", help="replace a dataset of the same id")
    args = p.parse_args(argv)
    if args.episodes < 1 or args.workers < 1:
        p.error("--episodes and --workers must be >= 1")
    try:
        env_kwargs = json.loads(args.env_kwargs)
    except json.JSONDecodeError as exc:
        p.error(f"--env-kwargs: not JSON ({exc}); e.g. '{{\"noise\": \"olympiad\"}}'")
    if not isinstance(env_kwargs, dict):
        p.error("--env-kwargs: expected a JSON object of env kwargs")
    if args.root:
        os.environ["MINARI_DATASETS_PATH"] = os.path.abspath(args.root)
    dataset_id = args.dataset_id or default_dataset_id(args.env, args.expert)
    import minari

    if dataset_id in minari.list_local_datasets():
        if not args.overwrite:
            p.error(f"dataset {dataset_id!r} exists already; give --overwrite or another --dataset-id")
        minari.delete_dataset(dataset_id)
    import gymnasium as gym

    import billiards_env  # noqa: F401

    gym.make(args.env, **env_kwargs).close()  # a bad id or kwarg fails here, with the env's own message
    t0 = time.perf_counter()
    episodes = collect(args.env, env_kwargs, args.expert, args.episodes, args.seed, args.workers, args.address)
    played = time.perf_counter() - t0
    write_dataset(dataset_id, episodes, args.env, env_kwargs, args.expert)
    steps = sum(len(ep["actions"]) for ep in episodes)
    wins = sum(ep["success"] for ep in episodes)
    print(f"{dataset_id}: {len(episodes)} episodes, {steps} steps, success {wins}/{len(episodes)} "
          f"({100.0 * wins / len(episodes):.1f}%), played in {played:.1f} s on "
          f"{'Ray at ' + args.address if args.address else f'{args.workers} process(es)'}; "
          f"load it with minari.load_dataset({dataset_id!r})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
