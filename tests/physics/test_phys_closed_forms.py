"""The ``exact`` solver against closed-form results of the spec's models (to 1e-9 or better).

Every expected value is computed here from the physics (kinematics, the 1-D restitution law, conservation
laws), never taken from a previous run.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from billiards_env.physics import G, kinetic_energy, momentum
from billiards_env.physics.layout import rack_balls
from physics_helpers import (EV_CUSHION, EV_POCKET, EV_STOP, L, R, W, balls, carom, collision_velocities,
                             collisions, drag, events_of, frictionless, one_ball, polar, pool, rolling,
                             rolling_time_for_distance, run)

TOL = 1e-9


# --- motion between collisions ---------------------------------------------------------------------------------

@pytest.mark.parametrize("v", [0.3, 1.0, 2.5])
@pytest.mark.parametrize("mu", [0.01, 0.2])
@pytest.mark.parametrize("angle", [0.0, 0.7, 2.5, -1.9])
def test_rolling_stop_distance_and_time(v, mu, angle):
    a = mu * G
    d = v * v / (2 * a)
    size = 2 * d + 1.0  # the ball, starting at the centre, cannot reach a cushion
    table = carom(length=size, width=size)
    x0 = y0 = size / 2
    res = run(table, rolling(mu=mu), one_ball(x0, y0, angle, v), record=True)
    assert res.status == "rest"
    assert abs(res.time - v / a) <= TOL
    u = np.array([math.cos(angle), math.sin(angle)])
    np.testing.assert_allclose(res.balls.pos[0], [x0, y0] + d * u, rtol=0, atol=TOL)
    assert np.all(res.balls.vel == 0.0)
    # The only event is the stop, at v / (mu g).
    assert list(res.events.kind) == [EV_STOP]
    assert abs(res.events.time[0] - v / a) <= TOL
    # Along the way: s(t) = v t - a t^2 / 2.
    ts = np.linspace(0.0, v / a, 7)
    pos, on = res.trajectory.sample(ts)
    assert on.all()
    s = v * ts - 0.5 * a * ts ** 2
    np.testing.assert_allclose(pos[:, 0, :], np.array([x0, y0]) + s[:, None] * u, rtol=0, atol=TOL)


@pytest.mark.parametrize("v,vmin", [(1.0, 0.2), (2.0, 0.5)])
def test_rolling_with_min_speed_stops_at_min_speed(v, vmin):
    a = 0.05 * G
    res = run(carom(length=8.0), rolling(mu=0.05, min_speed=vmin), one_ball(0.4, 0.635, 0.0, v))
    assert res.status == "rest"
    assert abs(res.time - (v - vmin) / a) <= TOL
    assert abs(res.balls.pos[0, 0] - (0.4 + (v * v - vmin * vmin) / (2 * a))) <= TOL


@pytest.mark.parametrize("k,v,vmin,angle", [(0.8, 1.0, 0.01, 0.0), (2.0, 2.0, 0.05, 1.1), (1.3, 0.5, 0.2, -2.9)])
def test_drag_stop_time_and_distance(k, v, vmin, angle):
    d = (v - vmin) / k
    size = 2 * d + 1.0
    table = carom(length=size, width=size)
    x0 = y0 = size / 2
    res = run(table, drag(k, vmin), one_ball(x0, y0, angle, v), record=True)
    assert res.status == "rest"
    assert abs(res.time - math.log(v / vmin) / k) <= TOL
    u = np.array([math.cos(angle), math.sin(angle)])
    np.testing.assert_allclose(res.balls.pos[0], [x0, y0] + d * u, rtol=0, atol=TOL)
    # x(t) = x0 + v (1 - e^{-kt}) / k
    ts = np.linspace(0.0, math.log(v / vmin) / k, 6)
    pos, _ = res.trajectory.sample(ts)
    s = v * (1 - np.exp(-k * ts)) / k
    np.testing.assert_allclose(pos[:, 0, :], np.array([x0, y0]) + s[:, None] * u, rtol=0, atol=TOL)


def test_drag_from_lecture_friction_factor():
    # The lecture's factor f per frame of dt0 is the drag rate k = -ln(f) / dt0: speed after n frames is v f^n.
    from billiards_env.physics import Physics
    f, dt0 = 0.99, 1 / 30
    k = Physics.drag_k_from_factor(f, dt0)
    assert abs(k - (-math.log(f) / dt0)) <= 1e-15
    v, vmin = 1.0, 0.1
    res = run(carom(length=10, width=10), drag(k, vmin), one_ball(3, 5, 0.0, v))
    n_frames = math.log(vmin / v) / math.log(f)  # v f^n = vmin
    assert abs(res.time - n_frames * dt0) <= TOL


# --- ball-ball collisions ----------------------------------------------------------------------------------------

def test_head_on_equal_masses_exchange_velocities_frictionless():
    v = 1.3
    b = balls([[0.5, 0.6], [1.0, 0.6]]).strike("cue", 0.0, v)
    t_hit = (0.5 - 2 * R) / v
    res = run(carom(), frictionless(1.0), b, max_time=t_hit + 0.3)
    assert res.status == "time_cap"
    assert collisions(res) == [pytest.approx((t_hit, 0, 1), abs=TOL)]
    np.testing.assert_allclose(res.balls.vel, [[0, 0], [v, 0]], rtol=0, atol=TOL)
    # The cue stops where it touched the object ball; the object ball carries on at v.
    np.testing.assert_allclose(res.balls.pos[0], [1.0 - 2 * R, 0.6], rtol=0, atol=TOL)
    np.testing.assert_allclose(res.balls.pos[1], [1.0 + 0.3 * v, 0.6], rtol=0, atol=TOL)


def test_head_on_equal_masses_exchange_velocities_rolling():
    # Long table so the object ball never reaches a cushion.
    v, mu = 1.0, 0.01
    a = mu * G
    b = balls([[0.5, 0.6], [1.0, 0.6]]).strike("cue", 0.0, v)
    res = run(carom(length=8.0), rolling(mu=mu, e_ball=1.0), b, record=True)
    assert res.status == "rest"
    gap = 0.5 - 2 * R
    t_hit = rolling_time_for_distance(v, gap, a)
    v_hit = v - a * t_hit
    cols = collisions(res)
    assert len(cols) == 1
    assert abs(cols[0][0] - t_hit) <= TOL and cols[0][1:] == (0, 1)
    # Velocities exchanged at the hit: cue at rest, object ball at the cue's speed.
    (_, i, j, vi0, vj0, vi1, vj1), = collision_velocities(res, rolling(mu=mu, e_ball=1.0))
    np.testing.assert_allclose(vi0, [v_hit, 0], atol=TOL)
    np.testing.assert_allclose(vj0, [0, 0], atol=TOL)
    np.testing.assert_allclose(vi1, [0, 0], atol=TOL)
    np.testing.assert_allclose(vj1, [v_hit, 0], atol=TOL)
    # Final positions: cue where it hit, object ball rolled v_hit^2 / 2a further.
    np.testing.assert_allclose(res.balls.pos[0], [1.0 - 2 * R, 0.6], atol=TOL)
    np.testing.assert_allclose(res.balls.pos[1], [1.0 + v_hit ** 2 / (2 * a), 0.6], atol=TOL)


def test_head_on_drag_collision_time():
    k, v = 0.8, 1.0
    b = balls([[0.5, 0.6], [1.0, 0.6]]).strike("cue", 0.0, v)
    res = run(carom(length=6.0), drag(k, 0.01, e_ball=1.0), b)
    gap = 0.5 - 2 * R
    t_hit = -math.log(1 - k * gap / v) / k  # v (1 - e^{-kt}) / k = gap
    cols = collisions(res)
    assert len(cols) == 1 and abs(cols[0][0] - t_hit) <= TOL
    v_hit = v * math.exp(-k * t_hit)
    # Cue stops at the contact point; the object ball then drags from v_hit down to min_speed.
    np.testing.assert_allclose(res.balls.pos[0], [1.0 - 2 * R, 0.6], atol=TOL)
    np.testing.assert_allclose(res.balls.pos[1], [1.0 + (v_hit - 0.01) / k, 0.6], atol=TOL)


@pytest.mark.parametrize("offset_in_radii", [0.2, 1.0, 1.5, 1.9])
def test_cut_shot_ninety_degree_rule(offset_in_radii):
    v = 1.0
    b_off = offset_in_radii * R
    b = balls([[0.5, 0.6], [1.0, 0.6 + b_off]]).strike("cue", 0.0, v)
    res = run(carom(), frictionless(1.0), b, max_time=0.6)
    cols = collisions(res)
    assert len(cols) == 1 and len(events_of(res, EV_CUSHION)) == 0
    v_cue, v_obj = res.balls.vel
    sin_cut = b_off / (2 * R)
    cos_cut = math.sqrt(1 - sin_cut ** 2)
    # 90-degree rule: outgoing directions perpendicular, speeds v sin and v cos of the cut angle.
    assert abs(np.dot(v_cue, v_obj)) <= 1e-12
    assert abs(np.linalg.norm(v_obj) - v * cos_cut) <= TOL
    assert abs(np.linalg.norm(v_cue) - v * sin_cut) <= TOL
    # The object ball leaves along the line of centres at contact, away from the cue ball.
    t_hit = cols[0][0]
    contact_cue = np.array([0.5 + v * t_hit, 0.6])
    n = np.array([1.0, 0.6 + b_off]) - contact_cue
    assert abs(np.linalg.norm(n) - 2 * R) <= TOL
    np.testing.assert_allclose(v_obj, v * cos_cut * n / np.linalg.norm(n), atol=TOL)
    np.testing.assert_allclose(v_cue + v_obj, [v, 0.0], atol=TOL)


def test_ninety_degree_rule_holds_at_impact_with_rolling_friction():
    phys = rolling(e_ball=1.0)
    b = balls([[0.5, 0.6], [1.2, 0.62]]).strike("cue", 0.0, 1.5)
    res = run(carom(), phys, b, record=True)
    cv = collision_velocities(res, phys)
    assert cv, "the cut shot must hit"
    _, i, j, vi0, vj0, vi1, vj1 = cv[0]
    assert abs(np.dot(vi1, vj1)) <= 1e-12
    np.testing.assert_allclose(vi1 + vj1, vi0 + vj0, atol=1e-12)


@pytest.mark.parametrize("e_c", [0.85, 0.5, 1.0])
@pytest.mark.parametrize("wall", ["left", "right", "bottom", "top"])
def test_cushion_reflection(e_c, wall):
    v = 1.0
    # Start 0.3 m from the wall, hit at 50 degrees of incidence, stop well before any other cushion.
    start, ang = {
        "left": ((0.3 + R, 0.6), math.pi + 0.7),
        "right": ((L - 0.3 - R, 0.6), 0.7),
        "bottom": ((1.2, 0.3 + R), -0.8),
        "top": ((1.2, W - 0.3 - R), 0.8),
    }[wall]
    cush = {"left": 0, "right": 1, "bottom": 2, "top": 3}[wall]
    axis = 0 if cush < 2 else 1
    vin = np.array(polar(ang, v))
    t_hit = 0.3 / abs(vin[axis])
    t_end = t_hit + 0.25
    res = run(carom(e_c=e_c), frictionless(), one_ball(*start, ang, v), max_time=t_end)
    assert list(res.events.kind) == [EV_CUSHION]
    assert res.events.other[0] == cush
    assert abs(res.events.time[0] - t_hit) <= TOL
    assert abs(res.events.speed[0] - abs(vin[axis])) <= TOL
    vout = vin.copy()
    vout[axis] = -e_c * vin[axis]
    np.testing.assert_allclose(res.balls.vel[0], vout, atol=TOL)
    hit = np.array(start) + vin * t_hit
    np.testing.assert_allclose(res.balls.pos[0], hit + vout * (t_end - t_hit), atol=TOL)


def test_cushion_hit_time_under_rolling_friction():
    a = 0.01 * G
    v, ang = 1.2, -0.9
    y0 = 0.5
    res = run(carom(), rolling(), one_ball(1.0, y0, ang, v))
    d = (y0 - R) / math.sin(-ang)  # path length to the bottom cushion
    t_hit = rolling_time_for_distance(v, d, a)
    q = events_of(res, EV_CUSHION)[0]
    assert res.events.other[q] == 2
    assert abs(res.events.time[q] - t_hit) <= TOL
    assert abs(res.events.speed[q] - (v - a * t_hit) * math.sin(-ang)) <= TOL


# --- pockets -----------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("start,pocket", [
    ((L / 2, 0.6), 1),  # straight down into the bottom side pocket
    ((L / 2, 0.7), 4),  # straight up into the top side pocket
    ((0.6, 0.6), 0),  # 45 degrees into the bottom-left corner
    ((L - 0.5, W - 0.5), 5),  # 45 degrees into the top-right corner
])
@pytest.mark.parametrize("v", [1.2, 2.0])
def test_time_to_reach_pocket(start, pocket, v):
    table = pool()
    a = 0.01 * G
    centre = table.pocket_xy[pocket]
    cap = table.pocket_radius[pocket]
    delta = centre - np.array(start)
    dist = float(np.linalg.norm(delta))
    ang = math.atan2(delta[1], delta[0])
    res = run(table, rolling(), one_ball(*start, ang, v))
    t_in = rolling_time_for_distance(v, dist - cap, a)
    assert res.pocket[0] == pocket
    assert abs(res.pocketed_at[0] - t_in) <= TOL
    assert not res.balls.on_table[0]
    assert list(res.events.kind) == [EV_POCKET]
    assert abs(res.events.speed[0] - (v - a * t_in)) <= TOL
    # Pocketed where its centre first touched the capture circle.
    assert abs(np.linalg.norm(res.balls.pos[0] - centre) - cap) <= TOL


# --- conservation laws -------------------------------------------------------------------------------------------

def test_momentum_and_energy_conserved_in_every_collision_elastic_frictionless():
    table = carom(e_c=1.0)
    phys = frictionless(1.0)
    b = rack_balls(table, gap=0.002).strike("cue", 0.03, 4.0)
    res = run(table, phys, b, max_time=3.0, record=True)
    cv = collision_velocities(res, phys)
    assert len(cv) >= 30
    m = b.mass
    for q, i, j, vi0, vj0, vi1, vj1 in cv:
        p0 = m[i] * vi0 + m[j] * vj0
        p1 = m[i] * vi1 + m[j] * vj1
        np.testing.assert_allclose(p1, p0, rtol=0, atol=1e-12 * (1 + np.abs(p0).max()))
        e0 = 0.5 * (m[i] * vi0 @ vi0 + m[j] * vj0 @ vj0)
        e1 = 0.5 * (m[i] * vi1 @ vi1 + m[j] * vj1 @ vj1)
        assert abs(e1 - e0) <= 1e-12 * max(e0, 1e-30), (q, e0, e1)
    # Walls with e_c = 1 and no friction: total kinetic energy is conserved over the whole shot.
    assert abs(kinetic_energy(res.balls) - kinetic_energy(b)) <= 1e-12 * kinetic_energy(b)


@pytest.mark.parametrize("e", [0.95, 0.5, 0.0])
def test_momentum_conserved_and_energy_loss_law_rolling(e):
    table = carom()
    phys = rolling(e_ball=e)
    b = rack_balls(table).strike("cue", 0.0, 5.0)
    res = run(table, phys, b, record=True)
    assert res.status == "rest"
    cv = collision_velocities(res, phys)
    assert len(cv) >= 15
    m = b.mass
    for q, i, j, vi0, vj0, vi1, vj1 in cv:
        p0 = m[i] * vi0 + m[j] * vj0
        p1 = m[i] * vi1 + m[j] * vj1
        np.testing.assert_allclose(p1, p0, rtol=0, atol=1e-12 * (1 + np.abs(p0).max()))
        e0 = 0.5 * (m[i] * vi0 @ vi0 + m[j] * vj0 @ vj0)
        e1 = 0.5 * (m[i] * vi1 @ vi1 + m[j] * vj1 @ vj1)
        assert e1 <= e0 * (1 + 1e-12) + 1e-18, (q, e0, e1)  # never gains energy
        v_close = res.events.speed[q]
        mu = m[i] * m[j] / (m[i] + m[j])
        if e * v_close > 1e-2:  # well above the documented low-speed collapse guard (1e-3 m/s)
            loss = 0.5 * mu * (1 - e * e) * v_close ** 2
            assert abs((e0 - e1) - loss) <= 1e-9 * e0 + 1e-15, (q, e0 - e1, loss)


def test_momentum_helper_matches_definition():
    b = balls([[0.5, 0.5], [1.0, 0.7]], velocities=[[1.0, -2.0], [0.5, 0.25]], mass=[0.17, 0.3])
    np.testing.assert_allclose(momentum(b), [0.17 * 1.0 + 0.3 * 0.5, 0.17 * -2.0 + 0.3 * 0.25], atol=1e-15)
    assert abs(kinetic_energy(b) - (0.5 * 0.17 * 5.0 + 0.5 * 0.3 * 0.3125)) <= 1e-15


@pytest.mark.parametrize("m1,m2,v1,v2,e", [
    (0.17, 0.34, 1.0, 0.0, 1.0),
    (0.34, 0.17, 1.0, 0.0, 1.0),
    (0.17, 0.50, 1.5, -0.5, 0.8),
    (0.30, 0.10, 0.7, -1.2, 0.3),
    (0.17, 0.17, 1.0, -0.5, 1.0),  # equal masses, e = 1: the velocities swap
    (0.20, 0.25, 1.0, 0.2, 0.0),  # perfectly inelastic: common velocity
])
def test_unequal_masses_one_dimensional_restitution_law(m1, m2, v1, v2, e):
    x1, x2, y = 2.0, 2.3, 0.6
    b = balls([[x1, y], [x2, y]], velocities=[[v1, 0.0], [v2, 0.0]], mass=[m1, m2])
    t_hit = (x2 - x1 - 2 * R) / (v1 - v2)
    res = run(carom(length=5.0), frictionless(e), b, max_time=t_hit + 0.05)
    cols = collisions(res)
    assert len(cols) == 1 and abs(cols[0][0] - t_hit) <= TOL
    v1p = (m1 * v1 + m2 * v2 + m2 * e * (v2 - v1)) / (m1 + m2)
    v2p = (m1 * v1 + m2 * v2 + m1 * e * (v1 - v2)) / (m1 + m2)
    np.testing.assert_allclose(res.balls.vel, [[v1p, 0.0], [v2p, 0.0]], rtol=0, atol=TOL)
    np.testing.assert_allclose(momentum(res.balls), momentum(b), rtol=0, atol=1e-12)
    if e == 1.0:
        assert abs(kinetic_energy(res.balls) - kinetic_energy(b)) <= 1e-12 * kinetic_energy(b)


@pytest.mark.parametrize("e", [0.5, 0.9])
@pytest.mark.parametrize("v", [1.0, 1e-3])
def test_oblique_restitution_law_without_friction_at_any_speed(e, v):
    # With no friction at all nothing can make two separating balls close again, so the restitution law must
    # hold at any impact speed: the object ball of a cut at angle theta leaves at (1 + e)/2 v cos(theta).
    off = R  # cut angle 30 degrees
    b = balls([[0.5, 0.6], [0.6, 0.6 + off]]).strike("cue", 0.0, v)
    res = run(carom(), frictionless(e), b, max_time=0.07 / v)
    assert len(collisions(res)) == 1
    cos_cut = math.sqrt(1 - (off / (2 * R)) ** 2)
    assert np.linalg.norm(res.balls.vel[1]) == pytest.approx((1 + e) / 2 * v * cos_cut, rel=1e-9)
    np.testing.assert_allclose(momentum(res.balls), momentum(b), rtol=0, atol=1e-15)
