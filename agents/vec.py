"""Stable-Baselines3 on the native vector env: :class:`BilliardsVecEnv` is an SB3 ``VecEnv`` over
``gymnasium.make_vec(id, n)`` (:mod:`billiards_env.envs.vector`), so SB3 steps N tables in one call instead of
N Python envs.

SB3's ``DummyVecEnv`` semantics are kept: a finished episode resets in the same step, its last observation is in
``info["terminal_observation"]``, ``info["TimeLimit.truncated"]`` says whether it was cut by the shot limit, the
infos are one dict per env with the single env's keys; ``seed(s)`` seeds env ``k`` with ``s + k`` at the next
``reset()``. With the same seeds and actions it returns what ``DummyVecEnv`` over ``gym.make(id)`` returns
(``tests/agents/test_vec.py``).

    from agents.vec import BilliardsVecEnv
    from stable_baselines3 import SAC

    env = BilliardsVecEnv("BilliardsOneBall-v0", n_envs=64, env_kwargs={"speed_max": 1.8})
    model = SAC("MlpPolicy", env).learn(10_000)
"""
from __future__ import annotations

from typing import Any, Sequence

import numpy as np
from gymnasium.vector import AutoresetMode
from stable_baselines3.common.vec_env.base_vec_env import VecEnv, VecEnvIndices, VecEnvStepReturn

from billiards_env.games.infos import unstack


class BilliardsVecEnv(VecEnv):
    """``n_envs`` tables of ``env_id`` (with ``env_kwargs``) as one SB3 ``VecEnv``; ``threads``: numba threads of
    the batch physics (None chooses); ``render_mode``/``render_env``: the sub-env that ``render()`` draws."""

    def __init__(self, env_id: str, n_envs: int = 1, env_kwargs: dict[str, Any] | None = None,
                 threads: int | None = None, render_mode: str | None = None, render_env: int = 0) -> None:
        import gymnasium as gym

        import billiards_env  # noqa: F401  (registers the ids)

        self.env_id = env_id
        self.venv = gym.make_vec(env_id, n_envs, vectorization_mode="vector_entry_point",
                                 autoreset_mode=AutoresetMode.SAME_STEP, threads=threads, render_mode=render_mode,
                                 render_env=render_env, **(env_kwargs or {}))
        super().__init__(n_envs, self.venv.single_observation_space, self.venv.single_action_space)
        self.render_mode = render_mode
        self._actions: np.ndarray | None = None

    # --- the VecEnv interface --------------------------------------------------------------------------------
    def reset(self) -> np.ndarray:
        seeds = None if all(s is None for s in self._seeds) else list(self._seeds)
        options = self._options[0] if self._options and self._options[0] else None
        obs, info = self.venv.reset(seed=seeds, options=options)
        self.reset_infos = self._infos(info)
        self._reset_seeds()
        self._reset_options()
        return obs

    def step_async(self, actions: np.ndarray) -> None:
        self._actions = actions

    def step_wait(self) -> VecEnvStepReturn:
        obs, reward, terminated, truncated, info = self.venv.step(self._actions)
        dones = terminated | truncated
        games = self.venv.unwrapped.sub_infos is not None
        infos = self._infos(info)
        if dones.any():
            final_infos = infos if games else _per_env(info.get("final_info", {}), self.num_envs)
            final_obs = info["final_obs"]
            for k in np.flatnonzero(dones).tolist():
                infos[k] = final_infos[k]
                infos[k]["terminal_observation"] = final_obs[k]
                self.reset_infos[k] = {}
        for k, d in enumerate(infos):
            d["TimeLimit.truncated"] = bool(truncated[k] and not terminated[k])
        return obs, reward.astype(np.float32), dones, infos

    def _infos(self, info: dict[str, Any]) -> list[dict[str, Any]]:
        """One info dict per env: the games' own dicts (the vector env's ``sub_infos``, made once), else the stacked
        arrays taken apart."""
        subs = self.venv.unwrapped.sub_infos
        if subs is not None:
            return [dict(d) for d in subs]
        return _per_env(info, self.num_envs)

    def close(self) -> None:
        self.venv.close()

    def render(self, mode: str | None = None) -> np.ndarray | None:
        """The frame of the rendered sub-env (``rgb_array``), as the native vector env draws it."""
        return self.venv.render()

    def get_images(self) -> Sequence[np.ndarray | None]:
        return [self.venv.render()]

    def get_attr(self, attr_name: str, indices: VecEnvIndices = None) -> list[Any]:
        """Attributes of the sub-envs: every table shares the template env's config, spaces and parts."""
        target = self.venv.unwrapped.template
        return [getattr(target, attr_name) for _ in self._get_indices(indices)]

    def set_attr(self, attr_name: str, value: Any, indices: VecEnvIndices = None) -> None:
        raise AttributeError(f"set_attr({attr_name!r}): the native vector env's tables share one config; make a new "
                             "env with the changed env_kwargs")

    def env_method(self, method_name: str, *method_args: Any, indices: VecEnvIndices = None,
                   **method_kwargs: Any) -> list[Any]:
        target = self.venv.unwrapped.template
        return [getattr(target, method_name)(*method_args, **method_kwargs) for _ in self._get_indices(indices)]

    def env_is_wrapped(self, wrapper_class: type, indices: VecEnvIndices = None) -> list[bool]:
        return [False for _ in self._get_indices(indices)]


def _per_env(info: dict[str, Any], n: int) -> list[dict[str, Any]]:
    """Gymnasium's vector info (arrays with ``_key`` masks) as one dict per env, each value in the single env's form
    (:func:`billiards_env.games.infos.unstack`)."""
    out: list[dict[str, Any]] = [{} for _ in range(n)]
    for key, value in info.items():
        if key.startswith("_") or key in ("final_obs", "final_info"):
            continue
        mask = info.get("_" + key)
        rows = np.flatnonzero(mask) if mask is not None else range(n)
        if isinstance(value, dict):
            nested = _per_env(value, n)
            for k in rows:
                out[k][key] = nested[k]
            continue
        items = unstack(value) if isinstance(value, np.ndarray) else list(value)  # the single env's forms
        for k in rows:
            out[k][key] = items[k]
    return out


def native_vec_env_supported(env_id: str, env_kwargs: dict[str, Any] | None, wrapper: Any) -> bool:
    """Whether :class:`BilliardsVecEnv` can replace a ``DummyVecEnv`` of ``gym.make(env_id, **env_kwargs)`` here:
    no per-env wrapper, and a config the native vector env runs as arrays (the pot task on the exact solver; the
    9-ball and 8-ball games with the geometric opponent or none, their own action types or ``candidates``: see
    ``BilliardsVectorEnv.not_native``), not sub-env by sub-env (no faster than ``DummyVecEnv``)."""
    if wrapper is not None:
        return False
    import gymnasium as gym

    import billiards_env  # noqa: F401

    if gym.spec(env_id).vector_entry_point is None:
        return False
    vec = gym.make_vec(env_id, 1, vectorization_mode="vector_entry_point", **(env_kwargs or {}))
    try:
        return bool(vec.unwrapped.native)
    finally:
        vec.close()


__all__ = ["BilliardsVecEnv", "native_vec_env_supported"]
