"""TorchRL: ``GymEnv(env_id)`` passes ``check_env_specs`` and rolls out across resets (TorchRL's docs' first steps)."""
from __future__ import annotations

import pytest

from clients import ENV_IDS, require


@pytest.mark.parametrize("env_id", ENV_IDS)
def test_gymenv_specs_and_rollout(env_id):
    require("torchrl")
    import billiards_env  # noqa: F401  (registers the ids)
    from torchrl.envs import GymEnv
    from torchrl.envs.utils import check_env_specs

    env = GymEnv(env_id)
    env.set_seed(0)
    check_env_specs(env)
    rollout = env.rollout(12, break_when_any_done=False)  # one-shot episodes: resets inside the rollout
    assert rollout.batch_size == (12,)
    obs = rollout["observation"]
    assert obs.shape == (12, *env.observation_spec["observation"].shape)
    assert float(obs.min()) >= 0.0 and float(obs.max()) <= 1.0
    done = rollout["next", "done"]
    if env_id == "BilliardsOneBall-v0":
        assert bool(done.all())  # every shot ends the episode
    env.close()
