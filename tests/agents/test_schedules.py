"""Learning-rate schedules that follow the training budget: ``lin_``/``cos_`` values, the clock driving them (wall or
CPU seconds), and the config errors."""
from __future__ import annotations

import math
from types import SimpleNamespace

import pytest
from stable_baselines3.common.utils import FloatSchedule

from agents.callbacks import TrainingClock
from agents.config import Schedule, TrainConfigError, load_train_config, parse_hyperparams, parse_schedule


def test_linear_and_cosine_schedules_run_from_initial_to_final():
    lin = parse_schedule("learning_rate", "lin_1e-3")
    assert lin(1.0) == pytest.approx(1e-3) and lin(0.5) == pytest.approx(5e-4) and lin(0.0) == 0.0
    cos = parse_schedule("learning_rate", "cos_3e-3_1e-5")
    assert cos(1.0) == pytest.approx(3e-3) and cos(0.0) == pytest.approx(1e-5)
    assert cos(0.5) == pytest.approx(1e-5 + 0.5 * (3e-3 - 1e-5))
    # Flat at both ends: the first and last 10% of the run change the rate by under 3% of the span.
    assert cos(1.0) - cos(0.9) < 0.03 * 3e-3 and cos(0.1) - cos(0.0) < 0.03 * 3e-3
    # Progress outside [0, 1] is held at the ends.
    assert cos(1.5) == pytest.approx(3e-3) and cos(-0.2) == pytest.approx(1e-5)


def test_a_schedule_follows_whichever_of_steps_and_clock_is_further_along():
    s = Schedule("lin", 2.0)
    s.clock_remaining = 0.25
    assert s(1.0) == pytest.approx(0.5)      # the clock is further along
    assert s(0.1) == pytest.approx(0.2)      # the steps are


@pytest.mark.parametrize("value", ["exp_1e-3", "lin", "lin_x", "cos_1_2_3"])
def test_bad_schedules_name_the_key_and_the_forms(value):
    with pytest.raises(TrainConfigError, match=r"learning_rate: unknown schedule .*cos_<initial>"):
        parse_schedule("learning_rate", value)


def test_config_values_become_schedules_and_a_bad_clock_is_refused():
    cfg = {"BilliardsOneBall-v0": {"learning_rate": "cos_3e-3", "clip_range": 0.2}, "billiards": {"algo": "sac"}}
    setup = parse_hyperparams(load_train_config(cfg))
    assert isinstance(setup.algo_kwargs["learning_rate"], Schedule)
    assert setup.algo_kwargs["learning_rate"](1.0) == pytest.approx(3e-3)
    with pytest.raises(TrainConfigError, match="budget_clock"):
        load_train_config({"BilliardsOneBall-v0": {}, "billiards": {"budget_clock": "gpu"}})


class _FakeTime:
    def __init__(self) -> None:
        self.t = 100.0

    def __call__(self) -> float:
        return self.t


@pytest.mark.parametrize("clock", ["wall", "cpu"])
def test_the_training_clock_drives_schedules_and_stops_at_the_budget(tmp_path, clock):
    sched = Schedule("cos", 1.0)
    model = SimpleNamespace(lr_schedule=FloatSchedule(sched), num_timesteps=0)
    tc = TrainingClock(tmp_path, max_seconds=60.0, clock=clock)
    tc.now = fake = _FakeTime()
    tc.model = model
    tc._on_training_start()
    assert sched.clock_remaining == 1.0 and model.lr_schedule(1.0) == pytest.approx(1.0)
    fake.t += 30.0
    assert tc._on_step() is True
    assert sched.clock_remaining == pytest.approx(0.5)
    assert model.lr_schedule(1.0) == pytest.approx(0.5 * (1.0 - math.cos(0.5 * math.pi)))
    fake.t += 30.0
    assert tc._on_step() is False and tc.stopped_by_budget
    assert sched.clock_remaining == 0.0 and model.lr_schedule(1.0) == 0.0
    assert tc.summary()["clock"] == clock


def test_the_cpu_clock_counts_this_process_only():
    import time

    tc = TrainingClock(".", clock="cpu")
    assert tc.now is time.process_time
    with pytest.raises(ValueError, match="clock"):
        TrainingClock(".", clock="gpu")


def test_a_model_trained_with_a_schedule_loads_without_the_training_code(tmp_path):
    """SB3 pickles the schedule into the model; it is pickled by value, so ``SAC.load`` works in a process where
    ``agents`` cannot be imported (a user's script anywhere)."""
    import os
    import subprocess
    import sys

    import gymnasium as gym
    from stable_baselines3 import SAC

    import billiards_env  # noqa: F401

    model = SAC("MlpPolicy", gym.make("BilliardsOneBall-v0"), learning_rate=parse_schedule("learning_rate",
                                                                                            "cos_3e-3_1e-5"))
    path = tmp_path / "model.zip"
    model.save(path)
    code = ("import sys; from stable_baselines3 import SAC; m = SAC.load(sys.argv[1]); "
            "assert 'agents' not in sys.modules; print(m.lr_schedule(1.0))")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    out = subprocess.run([sys.executable, "-c", code, str(path)], cwd=tmp_path, env=env, capture_output=True,
                         text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    assert float(out.stdout.strip()) == pytest.approx(3e-3)


def test_billiards_hyperparams_lay_agents_train_values_over_the_zoo_entry():
    """The shipped files keep a value the RL Zoo parses in the env entry (its schedules are lin_ only) and the
    cosine for agents.train under billiards.hyperparams."""
    import yaml

    from agents.config import load_train_config

    for name in ("one_ball_sac", "one_ball_sac_path", "one_ball_sac_candidates"):
        path = f"configs/train/{name}.yaml"
        zoo_entry = yaml.safe_load(open(path))["BilliardsOneBall-v0"]
        assert zoo_entry["learning_rate"] == 3e-3  # what the zoo trains with, verbatim
        assert load_train_config(path).hyperparams["learning_rate"] == "cos_3e-3_3e-5"
    cfg = {"BilliardsOneBall-v0": {"learning_rate": 1e-3}, "billiards": {"hyperparams": {"learning_rate": "lin_2e-3"}}}
    assert load_train_config(cfg).hyperparams["learning_rate"] == "lin_2e-3"
    assert load_train_config(cfg, hyper_overrides={"learning_rate": 5e-4}).hyperparams["learning_rate"] == 5e-4
    with pytest.raises(TrainConfigError, match=r"billiards.hyperparams: expected a mapping"):
        load_train_config({"BilliardsOneBall-v0": {}, "billiards": {"hyperparams": "cos_3e-3"}})
