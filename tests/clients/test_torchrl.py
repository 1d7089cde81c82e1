"""TorchRL: ``GymEnv(env_id)`` passes ``check_env_specs`` and rolls out across resets (TorchRL's docs' first steps);
and with the infos read into the rollout (``auto_register_info_dict``: it needs one fixed schema per id)."""
from __future__ import annotations

import pytest

from clients import ENV_IDS, require


def _gym_env(env_id: str, infos: bool):
    require("torchrl")
    import billiards_env  # noqa: F401  (registers the ids)
    from torchrl.envs import GymEnv

    env = GymEnv(env_id)
    if infos:
        env.auto_register_info_dict()
    env.set_seed(0)
    return env


@pytest.mark.parametrize("env_id", ENV_IDS)
def test_gymenv_specs_and_rollout(env_id):
    require("torchrl")
    from torchrl.envs.utils import check_env_specs

    env = _gym_env(env_id, infos=False)
    check_env_specs(env)
    rollout = env.rollout(12, break_when_any_done=False)  # one-shot episodes: resets inside the rollout
    assert rollout.batch_size == (12,)
    obs = rollout["observation"]
    assert obs.shape == (12, *env.observation_spec["observation"].shape)
    assert float(obs.min()) >= 0.0 and float(obs.max()) <= 1.0
    if env_id == "BilliardsOneBall-v0":
        assert bool(rollout["next", "done"].all())  # every shot ends the episode
    env.close()


@pytest.mark.parametrize("env_id", ENV_IDS)
def test_gymenv_reads_the_infos(env_id):
    require("torchrl")
    from torchrl.envs.utils import check_env_specs

    env = _gym_env(env_id, infos=True)
    check_env_specs(env)
    rollout = env.rollout(6, break_when_any_done=False)
    assert rollout["next", "is_success"].shape[0] == 6  # an info key, read at every step
    assert rollout["next", "pocketed"].shape[0] == 6
    env.close()
