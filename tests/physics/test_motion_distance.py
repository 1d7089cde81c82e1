"""The distance-domain motion law (physics/motion.py: stop_distance, speed_after_distance, launch_speed) for each
friction law, against the simulator and against each other."""
from __future__ import annotations

import math

import numpy as np
import pytest

from billiards_env.physics import Balls, Physics, Simulator, Table
from billiards_env.physics.motion import launch_speed, speed_after_distance, stop_distance

BIG = Table(length=100.0, width=10.0).without_pockets()  # no cushion or pocket in reach
LAWS = [Physics(), Physics(friction="drag", drag_k=0.3, min_speed=0.01), Physics(friction="spin")]


@pytest.mark.parametrize("physics", LAWS, ids=lambda p: p.friction)
@pytest.mark.parametrize("v0", [0.3, 1.0, 2.5])
def test_stop_distance_is_where_a_lone_ball_stops(physics, v0):
    """A ball set moving without spin (the spin model: a stun strike) stops where stop_distance says."""
    b = Balls.from_positions([[5.0, 5.0]]).strike(0, 0.0, v0)
    res = Simulator(BIG, physics).run(b)
    travelled = res.balls.pos[0, 0] - 5.0
    assert travelled == pytest.approx(stop_distance(v0, *physics.path_args, physics.min_speed), rel=1e-9)


@pytest.mark.parametrize("physics", LAWS, ids=lambda p: p.friction)
def test_speed_after_distance_matches_the_simulated_speed(physics):
    v0 = 2.0
    b = Balls.from_positions([[5.0, 5.0]]).strike(0, 0.0, v0)
    traj = Simulator(BIG, physics).run(b, record=True).trajectory

    times = np.linspace(0.05, 0.9 * traj.duration, 7)
    states = traj.sample_states(times)[0]  # (T, N, 7): x, y, vx, vy, wx, wy, wz
    for k in range(len(times)):
        d = float(states[k, 0, 0] - 5.0)
        speed = float(np.hypot(states[k, 0, 2], states[k, 0, 3]))
        assert speed_after_distance(v0, d, *physics.path_args) == pytest.approx(speed, rel=1e-7, abs=1e-9)


@pytest.mark.parametrize("physics", LAWS, ids=lambda p: p.friction)
@pytest.mark.parametrize("d, v_end", [(0.05, 0.5), (0.4, 0.3), (1.5, 0.8), (3.0, 0.05)])
def test_launch_speed_inverts_speed_after_distance(physics, d, v_end):
    v0 = launch_speed(d, v_end, *physics.path_args)
    assert speed_after_distance(v0, d, *physics.path_args) == pytest.approx(v_end, rel=1e-12)
    assert v0 > v_end


def test_a_stunned_ball_slides_24_49_of_its_energy_away_before_rolling():
    """Spin model closed form: the slide of a ball struck without spin ends at 5/7 of its speed, after
    24/49 v0^2 / (2 mu_slide g) metres."""
    p = Physics(friction="spin")
    law, a, k = p.path_args
    v0 = 2.0
    d_slide = 24.0 / 49.0 * v0 * v0 / (2.0 * k)
    assert d_slide == pytest.approx(0.4993, abs=1e-4)  # the stun shot: 0.4993 m of sliding
    assert speed_after_distance(v0, d_slide, law, a, k) == pytest.approx(5.0 / 7.0 * v0, rel=1e-12)
    assert math.isclose(stop_distance(v0, law, a, k, 0.0), d_slide + (5 / 7 * v0) ** 2 / (2 * a), rel_tol=1e-12)
