"""Where the cue ball comes to rest after a ghost-ball shot (physics/cue_rest.py): the 2/7 law's closed forms
(stun, follow, draw on a straight shot) and the engine's own simulation of the same shots (straight, cut, off
cushions, a scratch)."""
from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401
from billiards_env.physics.batch import run_shots
from billiards_env.physics.codes import ROLLING, SPIN
from billiards_env.physics.cue_rest import MAX_BOUNCES, cue_rest, speed_spin_at


@pytest.fixture(scope="module")
def table():
    env = gym.make("BilliardsOneBall-v0", physics={"friction": "spin"}, spin_action=True)
    env.reset(seed=0)
    return env.unwrapped


def _rest(u, cue, obj, direction, speed, top):
    """cue_rest of the shot sending ``obj`` along ``direction`` from ``cue``, and the ghost point."""
    b, t, ph = u.balls, u.table, u.physics
    law, a, k = ph.path_args
    contact = float(b.radius[0] + b.radius[1])
    gx, gy = obj[0] - contact * math.cos(direction), obj[1] - contact * math.sin(direction)
    out = cue_rest(cue[0], cue[1], gx, gy, direction, 0.3, speed, top, float(b.radius[0]), float(b.mass[0]),
                   float(b.mass[1]), t.length, t.width, t.cushion_restitution,
                   ph.ball_restitution, np.ascontiguousarray(t.pocket_xy),
                   np.ascontiguousarray(t.pocket_radius), law, a, k, ph.min_speed, u.simulator._params, MAX_BOUNCES)
    return out, (gx, gy)


def _engine(u, cue, obj, direction, speed, top):
    b = u.balls
    b.pos[0] = cue
    b.pos[1] = obj
    contact = float(b.radius[0] + b.radius[1])
    gx, gy = obj[0] - contact * math.cos(direction), obj[1] - contact * math.sin(direction)
    res = run_shots(u.simulator, b, [math.atan2(gy - cue[1], gx - cue[0])], [speed], top=[top], events=True)
    collisions = sum(e["kind"] == "collision" for e in res.events.row(0).as_dicts(b.ids))
    return res.pos[0, 0], res.pocket[0, 0], collisions


def test_sliding_then_rolling_to_the_contact_follows_the_spin_law():
    f_slide, f_roll = 0.2 * 9.81, 0.01 * 9.81
    # stun at launch: slides until 5/7 of the speed is left, then rolls
    s = 2.0
    tau = 2.0 * s / (7.0 * f_slide)
    d_slide = s * tau - 0.5 * f_slide * tau * tau
    v, w, reached, _ = speed_spin_at(s, 0.0, d_slide + 0.5, SPIN, f_roll, f_slide, 0.0)
    assert reached and v == pytest.approx(math.sqrt((5 * s / 7) ** 2 - 2 * f_roll * 0.5)) and w == v
    # a rolling launch only rolls
    v, w, reached, _ = speed_spin_at(s, s, 1.0, SPIN, f_roll, f_slide, 0.0)
    assert v == pytest.approx(math.sqrt(s * s - 2 * f_roll * 1.0)) and w == v
    # too soft: stops before the contact, after the stop distance
    v, w, reached, travelled = speed_spin_at(0.2, 0.2, 5.0, SPIN, f_roll, f_slide, 0.0)
    assert not reached and travelled == pytest.approx(0.04 / (2 * f_roll))
    # without spin (rolling law) the tip offset is ignored
    assert speed_spin_at(1.0, -1.0, 0.5, ROLLING, f_roll, 0.0, 0.0)[:2] == pytest.approx(
        (math.sqrt(1.0 - 2 * f_roll * 0.5),) * 2)


def test_straight_stun_follow_and_draw_in_closed_form(table):
    """Full-ball hit (restitution e, equal masses: the cue ball keeps (1 - e) / 2 of its speed v, the spin passes
    unchanged): arriving without spin (stun) it slides on by the little it kept and stops almost at the ghost ball
    (exactly there at e = 1); arriving rolling it follows through: the slip -(1 + e) v / 2 closes and it leaves the
    slide at (1 - e) v / 2 + (1 + e) v / 7 (2/7 v at e = 1), then rolls that speed's stop distance; arriving with
    backspin it comes back."""
    u = table
    f_slide, f_roll = u.physics.mu_slide * 9.81, u.physics.mu_roll * 9.81
    e = u.physics.ball_restitution
    cue, obj = (0.5, 0.6), (0.8, 0.6)
    d = 0.3 - 2 * float(u.balls.radius[0])
    s = 1.5
    # stun at contact: launched with the backspin that the slide brings to 0 exactly at the contact
    # (R w = 2.5 top s grows at 5/2 f_slide while v falls at f_slide: w(t_c) = 0 where s t - f t^2 / 2 = d)
    t_c = (s - math.sqrt(s * s - 2 * f_slide * d)) / f_slide
    top = -t_c * f_slide / s
    (x, y, pocket, _), (gx, gy) = _rest(u, cue, obj, 0.0, s, top)
    v = s - f_slide * t_c
    v0 = (1 - e) / 2 * v
    tau = 2 * v0 / (7 * f_slide)
    expect = v0 * tau - 0.5 * f_slide * tau * tau + (5 * v0 / 7) ** 2 / (2 * f_roll)
    assert pocket == -1 and y == pytest.approx(gy, abs=1e-12)
    assert x - gx == pytest.approx(expect, rel=1e-6) and x - gx < 0.01
    # follow: rolling at contact (launched with natural roll: 2.5 * 0.4 = 1)
    (x, y, pocket, _), (gx, gy) = _rest(u, cue, obj, 0.0, s, 0.4)
    v = math.sqrt(s * s - 2 * f_roll * d)
    v0 = (1 - e) / 2 * v
    slip = (1 + e) / 2 * v  # backwards: friction pushes the ball forwards
    tau = 2 * slip / (7 * f_slide)
    v1 = v0 + 2.0 / 7.0 * slip
    expect = v0 * tau + 0.5 * f_slide * tau * tau + v1 * v1 / (2 * f_roll)
    assert pocket == -1 and y == pytest.approx(gy, abs=1e-12)
    assert x - gx == pytest.approx(expect, rel=1e-6)
    # draw: arrives with backspin R w, keeps (1 - e) v / 2 and leaves the slide at that minus 2/7 of the slip:
    # backwards, and rolls back its stop distance behind the ghost ball
    cue = (0.6, 0.6)
    d = 0.2 - 2 * float(u.balls.radius[0])
    s, top = 1.2, -0.5
    (x, y, pocket, _), (gx, gy) = _rest(u, cue, obj, 0.0, s, top)
    t_c = (s - math.sqrt(s * s - 2 * f_slide * d)) / f_slide
    v, w = s - f_slide * t_c, 2.5 * top * s + 2.5 * f_slide * t_c
    assert w < 0.0  # still backspin at the contact
    v0 = (1 - e) / 2 * v
    slip = v0 - w
    tau = 2 * slip / (7 * f_slide)
    v1 = v0 - 2.0 / 7.0 * slip
    assert v1 < 0.0
    expect = v0 * tau - 0.5 * f_slide * tau * tau - v1 * v1 / (2 * f_roll)
    assert pocket == -1 and x - gx == pytest.approx(expect, rel=1e-6) and x < gx - 0.1


@pytest.mark.parametrize("direction_deg,speed,top", [(0.0, 1.0, -0.5), (0.0, 1.2, 0.0), (0.0, 1.0, 0.5),
                                                     (30.0, 2.5, -0.5), (30.0, 2.5, 0.0), (30.0, 2.5, 0.5),
                                                     (-50.0, 3.0, 0.3)])
def test_rest_point_equals_the_engines_when_the_balls_meet_once(table, direction_deg, speed, top):
    """The engine's simulation of the same shot (its strike, collision and cushion laws): the same rest point when
    the two balls meet once (cushions on the way included)."""
    u = table
    cue = (0.6, 0.6 if direction_deg == 0.0 else 0.5)
    obj = (1.2, 0.6)
    pos, pocket, collisions = _engine(u, cue, obj, math.radians(direction_deg), speed, top)
    assert collisions == 1
    (x, y, p, _), _ = _rest(u, cue, obj, math.radians(direction_deg), speed, top)
    assert p == pocket == -1
    assert x == pytest.approx(pos[0], abs=1e-6) and y == pytest.approx(pos[1], abs=1e-6)


def test_a_scratch_is_flagged_with_its_pocket(table):
    """A cut that sends the cue ball into the bottom-right corner pocket (the engine drops it there too), and a
    fuller hit on the same ball that leaves it on the table (the engine too)."""
    u = table
    corner = 2  # (length, 0)
    cue, obj = (1.4, 0.8), (2.0, 0.45)
    (x, y, p, _), _ = _rest(u, cue, obj, math.radians(56.0), 2.5, 0.0)
    pos, pocket, collisions = _engine(u, cue, obj, math.radians(56.0), 2.5, 0.0)
    assert p == pocket == corner and collisions == 1
    assert math.hypot(x - u.table.pocket_xy[corner, 0], y - u.table.pocket_xy[corner, 1]) == pytest.approx(
        u.table.pocket_radius[corner])
    (x, y, p, _), _ = _rest(u, cue, obj, math.radians(20.0), 1.5, 0.0)
    pos, pocket, collisions = _engine(u, cue, obj, math.radians(20.0), 1.5, 0.0)
    assert p == pocket == -1 and collisions == 1
    assert x == pytest.approx(pos[0], abs=1e-6) and y == pytest.approx(pos[1], abs=1e-6)
