"""The ``step`` solver converges to ``exact`` as the time step shrinks (first order), for both contact treatments."""
from __future__ import annotations

import math

import numpy as np
import pytest

from physics_helpers import EV_COLLISION, EV_CUSHION, balls, carom, drag, events_of, one_ball, rolling, run

DTS = (1e-2, 1e-3, 1e-4)


def _errors(table, phys, b, contact):
    ref = run(table, phys, b)
    assert ref.status == "rest"
    errs = []
    for dt in DTS:
        st = run(table, phys, b, solver="step", dt=dt, contact=contact)
        assert st.status == "rest"
        errs.append(float(np.abs(st.balls.pos - ref.balls.pos).max()))
    return ref, errs


@pytest.mark.parametrize("law", ["rolling", "drag"])
@pytest.mark.parametrize("contact", ["lecture", "rewind"])
def test_single_ball_with_cushion_bounce_converges_first_order(contact, law):
    table = carom()
    b = one_ball(0.7, 0.4, 0.35, 1.6)
    ref, errs = _errors(table, rolling() if law == "rolling" else drag(0.5, 0.01), b, contact)
    assert len(events_of(ref, EV_CUSHION)) >= 1
    assert errs[-1] < 1e-3
    ratios = [errs[k] / errs[k + 1] for k in range(len(errs) - 1)]
    # Error ~ C dt: each tenfold smaller step gives a roughly tenfold smaller error.
    for r in ratios:
        assert 4.0 <= r <= 25.0, (errs, ratios)


@pytest.mark.parametrize("contact", ["lecture", "rewind"])
def test_two_ball_shot_converges(contact):
    table = carom()
    b = balls([[0.6, 0.5], [1.5, 0.75]]).strike("cue", math.atan2(0.25 - 0.03, 0.9), 2.0)
    ref, errs = _errors(table, rolling(), b, contact)
    assert len(events_of(ref, EV_COLLISION)) >= 1
    assert errs[2] < 0.05 * errs[0], errs


@pytest.mark.parametrize("contact", ["lecture", "rewind"])
def test_step_stop_time_and_distance_converge(contact):
    # No collisions: the step solver's stop time and distance approach v/(mu g) and v^2/(2 mu g) as dt -> 0.
    v = 1.0
    a = rolling().deceleration
    table = carom(length=12.0)  # 5.1 m of travel: a long table
    b = one_ball(0.5, 0.635, 0.0, v)
    for dt in DTS:
        st = run(table, rolling(), b, solver="step", dt=dt, contact=contact)
        assert abs(st.time - v / a) <= 2 * dt
        assert abs(st.balls.pos[0, 0] - (0.5 + v * v / (2 * a))) <= 2 * v * dt
