"""The behaviour fingerprint: hashes of what the envs, vector envs, two-player envs and players return for fixed
seeds and actions, on every id, action type, observation type, solver and friction law.

A refactoring keeps behaviour: ``tests/envs/test_fingerprint.py`` recomputes every case and compares it with
``fingerprint.json``. A deliberate change of behaviour regenerates the file, and the commit says why::

    python tests/envs/fingerprint_cases.py --write        # from the repository root
    python tests/envs/fingerprint_cases.py --only games   # print the cases whose name contains "games"

Info keys added after the fingerprint was taken (``ADDED_INFO_KEYS``) are left out of the hash, so adding a key
to ``info`` does not hide a change of the others.
"""
from __future__ import annotations

import hashlib
import json
import math
import os
import sys
from pathlib import Path
from typing import Any, Callable, Iterator

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402

import billiards_env  # noqa: E402,F401

FILE = Path(__file__).with_name("fingerprint.json")
#: Keys of ``info`` added after the fingerprint was taken: not hashed.
ADDED_INFO_KEYS: frozenset[str] = frozenset()

POT = ("BilliardsOneBall-v0", "BilliardsThreeBalls-v0", "BilliardsRack-v0")
GAMES = ("Billiards9Ball-v0", "Billiards8Ball-v0")


def canon(x: Any) -> Any:
    """A JSON-able canonical form of ``x`` with floats written exactly (``float.hex``)."""
    if isinstance(x, dict):
        return {str(k): canon(v) for k, v in sorted(x.items(), key=lambda kv: str(kv[0]))
                if str(k).lstrip("_") not in ADDED_INFO_KEYS}
    if isinstance(x, np.ndarray):
        if x.ndim == 0 and x.dtype != object:  # a flag of the infos: its value, as a scalar of the dtype
            return canon(x[()])
        if x.dtype == object:
            return [canon(v) for v in x.tolist()]
        return [str(x.dtype), list(x.shape), hashlib.sha256(np.ascontiguousarray(x).tobytes()).hexdigest()]
    if isinstance(x, (list, tuple)):
        return [canon(v) for v in x]
    if isinstance(x, (bool, np.bool_)):
        return bool(x)
    if isinstance(x, (int, np.integer)):
        return int(x)
    if isinstance(x, (float, np.floating)):
        return float(x).hex() if math.isfinite(float(x)) else repr(float(x))
    if x is None or isinstance(x, str):
        return x
    return repr(x)


class Digest:
    def __init__(self) -> None:
        self.h = hashlib.sha256()

    def add(self, *items: Any) -> None:
        self.h.update(json.dumps(canon(list(items)), sort_keys=True).encode())

    def hex(self) -> str:
        return self.h.hexdigest()[:24]


def run_single(env_id: str, steps: int, seed: int, **kwargs: Any) -> str:
    """reset(seed) then ``steps`` uniform random actions (a generator of its own), resetting when an episode ends."""
    env = gym.make(env_id, **kwargs)
    d = Digest()
    rng = np.random.default_rng(seed + 1000)
    obs, info = env.reset(seed=seed)
    d.add(obs, info)
    for _ in range(steps):
        a = rng.uniform(-1.0, 1.0, env.action_space.shape).astype(np.float32)
        obs, r, term, trunc, info = env.step(a)
        d.add(obs, r, term, trunc, info)
        if term or trunc:
            obs, info = env.reset()
            d.add(obs, info)
    env.close()
    return d.hex()


def run_player(env_id: str, player: str, steps: int, seed: int, **kwargs: Any) -> str:
    """A player's actions and the env's answers: the player's choices are part of the hash."""
    from billiards_env.players import make_player

    from billiards_env.games import game_of_env

    env = gym.make(env_id, **kwargs)
    game = game_of_env(env_id)
    p = make_player(player, seed=seed, game=game.name if game is not None else None)
    d = Digest()
    obs, info = env.reset(seed=seed)
    p.reset(seed)
    d.add(obs, info)
    for _ in range(steps):
        a = p.act(env, obs)
        obs, r, term, trunc, info = env.step(a)
        d.add(a, obs, r, term, trunc, info)
        if term or trunc:
            obs, info = env.reset()
            d.add(obs, info)
    env.close()
    return d.hex()


def run_vector(env_id: str, n: int, steps: int, seed: int, **kwargs: Any) -> str:
    envs = gym.make_vec(env_id, n, vectorization_mode="vector_entry_point", **kwargs)
    d = Digest()
    rng = np.random.default_rng(seed + 2000)
    obs, info = envs.reset(seed=seed)
    d.add(obs, info)
    for _ in range(steps):
        a = rng.uniform(-1.0, 1.0, envs.action_space.shape).astype(np.float32)
        d.add(*envs.step(a))
    envs.close()
    return d.hex()


def run_aec(module: str, steps: int, seed: int, players: tuple[str, str] | None = None, **kwargs: Any) -> str:
    import importlib

    from billiards_env.players import make_player

    env = importlib.import_module(f"billiards_env.multi.{module}").env(**kwargs)
    env.reset(seed=seed)
    rng = np.random.default_rng(seed + 3000)
    game = env.unwrapped.task.name
    pl = None if players is None else {a: make_player(p, seed=seed, game=game)
                                       for a, p in zip(env.possible_agents, players)}
    d = Digest()
    n = 0
    for agent in env.agent_iter():
        obs, r, term, trunc, info = env.last()
        d.add(agent, obs, r, term, trunc, info)
        if term or trunc:
            action = None
        elif pl is None:
            action = rng.uniform(-1.0, 1.0, env.action_space(agent).shape).astype(np.float32)
        else:
            action = pl[agent].act(env.unwrapped.game_env, obs)
        d.add(action)
        env.step(action)
        n += 1
        if n >= steps:
            break
    env.close()
    return d.hex()


def cases() -> Iterator[tuple[str, Callable[[], str]]]:
    """Every case: a name and the function computing its hash."""
    def c(name: str, fn: Callable[..., str], *args: Any, **kw: Any) -> tuple[str, Callable[[], str]]:
        return name, lambda: fn(*args, **kw)

    # Pot scenes: every action type x observation type on the default (rolling, exact) physics.
    for env_id in POT:
        steps = 12 if env_id != "BilliardsRack-v0" else 6
        for at in ("absolute", "relative", "ghost", "candidates"):
            for ot in ("positions", "features", "candidates"):
                yield c(f"pot/{env_id}/{at}/{ot}", run_single, env_id, steps, 3, action_type=at, observation_type=ot)
        # Laws, solvers, noise, spin.
        yield c(f"pot/{env_id}/drag", run_single, env_id, steps, 4, friction="drag")
        yield c(f"pot/{env_id}/noise", run_single, env_id, steps, 5, angle_noise=0.01, speed_noise=0.05)
        yield c(f"pot/{env_id}/spin", run_single, env_id, steps, 6, friction="spin", spin_action=True,
                tip_noise=0.02, angle_noise=0.003)
        yield c(f"pot/{env_id}/spin-ghost-features", run_single, env_id, steps, 6, friction="spin",
                action_type="ghost", observation_type="features")
        yield c(f"pot/{env_id}/step", run_single, env_id, 3, 7, solver={"name": "step", "dt": 2e-3})
        yield c(f"pot/{env_id}/step-spin", run_single, env_id, 3, 7, solver={"name": "step", "dt": 2e-3},
                friction="spin", spin_action=True)
    yield c("pot/BilliardsOneBall-v0/single_shot-penalties", run_single, "BilliardsOneBall-v0", 12, 8,
            miss_penalty=0.5, step_penalty=0.1, scratch_penalty=2.0)
    yield c("pot/BilliardsOneBall-v0/candidates_aim/candidates_path", run_single, "BilliardsOneBall-v0", 12, 22,
            action_type="candidates_aim", observation_type="candidates_path", candidate_slots=7,
            candidate_speed_factor=3.0)
    yield c("games/Billiards9Ball-v0/candidates_aim/candidates_path", run_single, "Billiards9Ball-v0", 4, 23,
            action_type="candidates_aim", observation_type="candidates_path")
    yield c("games/Billiards9Ball-v0/candidates/candidates_position", run_single, "Billiards9Ball-v0", 6, 24,
            action_type="candidates", observation_type="candidates_position")
    yield c("games/Billiards9Ball-v0/candidates/candidates_position-spin", run_single, "Billiards9Ball-v0", 6, 25,
            action_type="candidates", observation_type="candidates_position", friction="spin", spin_action=True,
            noise="olympiad")
    # Games: against the default opponent, alone, and the other action / observation types.
    for env_id in GAMES:
        yield c(f"games/{env_id}/default", run_single, env_id, 4, 11)
        yield c(f"games/{env_id}/alone", run_single, env_id, 8, 12, opponent=None)
        yield c(f"games/{env_id}/alone-bih-features", run_single, env_id, 8, 13, opponent=None,
                opening="ball_in_hand", action_type="ghost", observation_type="features")
        yield c(f"games/{env_id}/candidates", run_single, env_id, 4, 14, action_type="candidates",
                observation_type="candidates")
        yield c(f"games/{env_id}/candidates-alone", run_single, env_id, 8, 15, action_type="candidates",
                observation_type="candidates", opponent=None, opening="either")
        yield c(f"games/{env_id}/relative-random-opp", run_single, env_id, 4, 16, action_type="relative",
                opponent="random", first_shooter="random")
        yield c(f"games/{env_id}/spin-noise", run_single, env_id, 3, 17, friction="spin", spin_action=True,
                angle_noise=0.005, speed_noise=0.02, tip_noise=0.02)
        yield c(f"games/{env_id}/shaping", run_single, env_id, 6, 18, opponent=None, pot_reward=0.1,
                foul_penalty=0.2, position_reward=0.5, opening="ball_in_hand")
    yield c("games/Billiards9Ball-v0/push-out", run_single, "Billiards9Ball-v0", 4, 19, rules={"push_out": True})
    yield c("games/Billiards8Ball-v0/no-call", run_single, "Billiards8Ball-v0", 4, 20, rules={"call_eight": False})
    yield c("games/Billiards9Ball-v0/step", run_single, "Billiards9Ball-v0", 2, 21, opponent=None,
            solver={"name": "step", "dt": 2e-3})
    # Players: their choices.
    for env_id in ("BilliardsOneBall-v0", "BilliardsThreeBalls-v0"):
        for player in ("random", "geometric", "search"):
            yield c(f"players/{env_id}/{player}", run_player, env_id, player, 6, 31)
    yield c("players/BilliardsThreeBalls-v0/geometric-ghost", run_player, "BilliardsThreeBalls-v0", "geometric", 6,
            32, action_type="ghost")
    yield c("players/BilliardsThreeBalls-v0/search-noise", run_player, "BilliardsThreeBalls-v0", "search", 4, 33,
            angle_noise=0.01)
    for env_id in GAMES:
        yield c(f"players/{env_id}/geometric", run_player, env_id, "geometric", 4, 34, opponent=None)
        yield c(f"players/{env_id}/geometric-bih", run_player, env_id, "geometric", 4, 35, opponent=None,
                opening="ball_in_hand")
        yield c(f"players/{env_id}/search", run_player, env_id, "search", 2, 36, opponent=None,
                opening="ball_in_hand")
        yield c(f"players/{env_id}/geometric-candidates", run_player, env_id, "geometric", 3, 37,
                action_type="candidates", observation_type="candidates")
        yield c(f"players/{env_id}/search-opponent", run_single, env_id, 2, 38, opponent="search")
    yield c("players/Billiards9Ball-v0/geometric-spin", run_player, "Billiards9Ball-v0", "geometric", 3, 39,
            friction="spin", spin_action=True, opponent=None, opening="ball_in_hand")
    # Snooker and three-cushion (added with the games).
    for env_id in ("BilliardsSnooker-v0", "BilliardsThreeCushion-v0"):
        yield c(f"games/{env_id}/default", run_single, env_id, 3, 61)
        yield c(f"games/{env_id}/alone-noise", run_single, env_id, 6, 62, opponent=None, noise="olympiad")
        yield c(f"players/{env_id}/geometric", run_player, env_id, "geometric", 3, 63, opponent=None)
    yield c("players/BilliardsSnooker-v0/search", run_player, "BilliardsSnooker-v0", "search", 2, 64, opponent=None)
    # Vector envs (native and one-by-one).
    for env_id in POT:
        yield c(f"vector/{env_id}", run_vector, env_id, 8, 6, 41)
        yield c(f"vector/{env_id}/spin-noise", run_vector, env_id, 8, 6, 42, friction="spin", spin_action=True,
                angle_noise=0.01, tip_noise=0.02)
        yield c(f"vector/{env_id}/ghost-features", run_vector, env_id, 4, 4, 43, action_type="ghost",
                observation_type="features")
    for env_id in GAMES:
        yield c(f"vector/{env_id}", run_vector, env_id, 3, 2, 44, opponent="random")
    # Two players.
    for module in ("nine_ball_v0", "eight_ball_v0", "snooker_v0", "three_cushion_v0"):
        yield c(f"aec/{module}/random", run_aec, module, 12, 51)
        yield c(f"aec/{module}/geometric", run_aec, module, 8, 52, players=("geometric", "search"))


def compute(only: str | None = None) -> dict[str, str]:
    return {name: fn() for name, fn in cases() if only is None or only in name}


def main(argv: list[str]) -> int:
    import argparse
    import time

    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--write", action="store_true", help=f"write {FILE.name}")
    p.add_argument("--only", default=None, help="cases whose name contains this")
    args = p.parse_args(argv)
    t0 = time.perf_counter()
    got = compute(args.only)
    old = json.loads(FILE.read_text()) if FILE.exists() else {}
    changed = [k for k in got if k in old and old[k] != got[k]]
    for k, v in got.items():
        mark = "" if k not in old else ("  ok" if old[k] == v else "  CHANGED")
        print(f"{k:<70} {v}{mark}")
    print(f"{len(got)} cases in {time.perf_counter() - t0:.1f} s; {len(changed)} changed")
    if args.write:
        FILE.write_text(json.dumps({**old, **got}, indent=1, sort_keys=True) + "\n")
        print(f"wrote {FILE}")
    return 1 if changed and not args.write else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
