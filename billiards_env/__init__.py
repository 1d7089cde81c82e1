"""billiards_env: Gymnasium pool environments on an exact, fast billiards physics engine.

Importing the package registers the environment ids with Gymnasium::

    import gymnasium as gym
    import billiards_env  # noqa: F401

    env = gym.make("BilliardsOneBall-v0")  # also BilliardsThreeBalls-v0, BilliardsRack-v0
"""


def _register_envs() -> None:
    try:
        from gymnasium.envs.registration import register, registry
    except ImportError:  # pragma: no cover - physics-only use without gymnasium
        return
    for env_id, entry_point in (
        ("BilliardsOneBall-v0", "billiards_env.envs.one_ball:OneBallEnv"),
        ("BilliardsThreeBalls-v0", "billiards_env.envs.three_balls:ThreeBallsEnv"),
        ("BilliardsRack-v0", "billiards_env.envs.rack:RackEnv"),
    ):
        if env_id not in registry:
            register(id=env_id, entry_point=entry_point)


_register_envs()
