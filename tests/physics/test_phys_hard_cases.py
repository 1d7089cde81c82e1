"""Hard cases: simultaneous contacts, tunnelling, grazing contacts, corners, caps and degenerate inputs."""
from __future__ import annotations

import math

import numpy as np
import pytest

from billiards_env.physics import kinetic_energy, momentum
from billiards_env.physics.layout import rack_balls
from billiards_env.physics.simulate import DEFAULT_DT, DEFAULT_MAX_EVENTS, DEFAULT_MAX_TIME, Simulator
from physics_helpers import (EV_COLLISION, EV_CUSHION, EV_STOP, L, R, W, assert_valid_final_state, balls, carom,
                             collision_velocities, collisions, drag, events_of, frictionless, max_overlap, one_ball,
                             pool, rolling, rolling_time_for_distance, run)

TOL = 1e-9


# --- Newton's cradle ---------------------------------------------------------------------------------------------

def _cradle(n=5, v=1.0):
    x0, y = 1.0, 0.6
    pos = [[0.5, y]] + [[x0 + 2 * R * k, y] for k in range(n)]
    return np.array(pos), balls(pos).strike("cue", 0.0, v)


@pytest.mark.parametrize("friction", ["none", "rolling"])
def test_newtons_cradle_only_last_ball_leaves(friction):
    pos0, b = _cradle()
    v = 1.0
    if friction == "none":
        phys, max_time = frictionless(1.0), 1.0
    else:
        phys, max_time = rolling(e_ball=1.0), 600.0
    res = run(carom(length=7.0), phys, b, max_time=max_time)
    x_hit = pos0[1, 0] - 2 * R
    # Cue stops where it touched the first ball, the four middle balls never move, the last ball leaves.
    np.testing.assert_allclose(res.balls.pos[0], [x_hit, 0.6], rtol=0, atol=TOL)
    np.testing.assert_allclose(res.balls.pos[1:5], pos0[1:5], rtol=0, atol=TOL)
    assert np.all(np.abs(res.balls.vel[:5]) <= TOL)
    if friction == "none":
        assert res.status == "time_cap"
        np.testing.assert_allclose(res.balls.vel[5], [v, 0.0], atol=TOL)
    else:
        assert res.status == "rest"
        a = phys.deceleration
        v_hit = v - a * rolling_time_for_distance(v, pos0[1, 0] - 2 * R - 0.5, a)
        np.testing.assert_allclose(res.balls.pos[5], [pos0[5, 0] + v_hit ** 2 / (2 * a), 0.6], atol=TOL)
    # The impulse goes down the line as a sequence of pairwise hits, all at the same instant.
    cols = collisions(res)
    assert [(i, j) for _, i, j in cols if _ <= cols[0][0]] == [(0, 1), (1, 2), (2, 3), (3, 4), (4, 5)]


@pytest.mark.parametrize("contact", ["lecture", "rewind"])
def test_newtons_cradle_step_solver(contact):
    pos0, b = _cradle()
    dt = 1e-4
    res = run(carom(length=6.0), frictionless(1.0), b, solver="step", dt=dt, contact=contact, max_time=1.0)
    # Up to O(v dt) position errors, the same outcome as the exact one.
    np.testing.assert_allclose(res.balls.pos[1:5], pos0[1:5], rtol=0, atol=2 * dt)
    assert np.all(np.abs(res.balls.vel[:5]) <= 1e-9)
    np.testing.assert_allclose(res.balls.vel[5], [1.0, 0.0], atol=1e-9)
    np.testing.assert_allclose(momentum(res.balls), momentum(b), atol=1e-12)


# --- break shot -------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("table_kind", ["pool", "carom"])
def test_rack_break_at_8_mps_exact(table_kind):
    table = pool() if table_kind == "pool" else carom()
    b = rack_balls(table).strike("cue", 0.0, 8.0)
    assert max_overlap(b.pos, b.radius) <= 1e-12  # the rack is touching, not overlapping
    res = run(table, rolling(), b, record=True)
    assert res.status == "rest"
    assert_valid_final_state(res, table, overlap_tol=1e-9)
    assert np.all(res.balls.vel == 0.0)
    assert len(events_of(res, EV_COLLISION)) >= 15
    # No overlap and no ball off the table at any time along the way either.
    ts = np.linspace(0.0, res.time, 4001)
    pos, on = res.trajectory.sample(ts)
    for q in range(len(ts)):
        p = pos[q][on[q]]
        assert max_overlap(p, b.radius[on[q]]) <= 1e-9, ts[q]
        assert np.all(p >= R - 1e-12) and np.all(p[:, 0] <= L - R + 1e-12) and np.all(p[:, 1] <= W - R + 1e-12)
    # Pocketed balls: the count of on-table flags matches the pocket list.
    assert np.array_equal(res.pocket >= 0, ~res.balls.on_table)


@pytest.mark.parametrize("contact", ["lecture", "rewind"])
def test_rack_break_at_8_mps_step(contact):
    table = pool()
    b = rack_balls(table).strike("cue", 0.0, 8.0)
    res = run(table, rolling(), b, solver="step", dt=1e-3, contact=contact)
    assert res.status == "rest"
    assert_valid_final_state(res, table, overlap_tol=1e-9)


def test_rack_break_elastic_conserves_energy():
    table = carom(e_c=1.0)
    phys = frictionless(1.0)
    b = rack_balls(table).strike("cue", 0.0, 8.0)
    res = run(table, phys, b, max_time=1.0, record=True)
    assert res.status == "time_cap"
    assert abs(kinetic_energy(res.balls) - kinetic_energy(b)) <= 1e-12 * kinetic_energy(b)
    assert_valid_final_state(res, table, overlap_tol=1e-9)
    assert len(collision_velocities(res, phys)) >= 15


# --- tunnelling -------------------------------------------------------------------------------------------------

def test_fast_ball_never_tunnels_in_exact_but_does_in_step():
    v = 8.0
    b = balls([[0.5, 0.6], [0.6, 0.6]]).strike("cue", 0.0, v)
    t_hit = rolling_time_for_distance(v, 0.1 - 2 * R, rolling().deceleration)
    ex = run(carom(), rolling(), b, max_time=0.1)
    cols = collisions(ex)
    assert cols and cols[0][1:] == (0, 1) and abs(cols[0][0] - t_hit) <= TOL
    for contact in ("lecture", "rewind"):
        st = run(carom(), rolling(), b, solver="step", dt=1 / 30, contact=contact, max_time=0.1)
        # One step moves the cue 0.27 m: it jumps over the object ball, which is counted as tunnelled.
        assert len(events_of(st, EV_COLLISION)) == 0, contact
        assert st.n_tunnelled > 0, contact
        assert np.all(st.balls.vel[1] == 0.0)


def test_fast_ball_against_cushion_exact_and_step():
    v = 8.0
    x0 = L - R - 0.1
    ex = run(carom(), rolling(), one_ball(x0, 0.6, 0.0, v), max_time=0.05)
    q = events_of(ex, EV_CUSHION)
    assert len(q) == 1 and ex.events.other[q[0]] == 1
    assert abs(ex.events.time[q[0]] - rolling_time_for_distance(v, 0.1, rolling().deceleration)) <= TOL
    assert ex.balls.vel[0, 0] < 0
    st = run(carom(), rolling(), one_ball(x0, 0.6, 0.0, v), solver="step", dt=1 / 30, max_time=0.05)
    # The wall cannot be jumped: the step solver's overshoot test still sees it.
    assert len(events_of(st, EV_CUSHION)) == 1 and st.balls.vel[0, 0] < 0
    assert_valid_final_state(st, carom())


# --- grazing contacts -------------------------------------------------------------------------------------------

@pytest.mark.parametrize("phys", [frictionless(1.0), rolling(e_ball=1.0), rolling(e_ball=0.9)],
                         ids=["frictionless", "rolling", "rolling-e0.9"])
def test_exactly_tangent_path(phys):
    # The cue's path passes at exactly 2R from the object ball's centre: at most a zero-impulse touch.
    v = 1.0
    b = balls([[0.5, 0.6], [1.0, 0.6 + 2 * R]]).strike("cue", 0.0, v)
    res = run(carom(), phys, b, max_time=1.0)
    assert np.all(np.isfinite(res.balls.pos)) and np.all(np.isfinite(res.balls.vel))
    assert np.linalg.norm(res.balls.pos[1] - [1.0, 0.6 + 2 * R]) <= 1e-12
    assert np.linalg.norm(res.balls.vel[1]) <= 1e-12
    # The cue ball keeps its straight path.
    assert abs(res.balls.pos[0, 1] - 0.6) <= 1e-12 and res.balls.vel[0, 1] == pytest.approx(0.0, abs=1e-12)
    assert_valid_final_state(res, carom())


@pytest.mark.parametrize("phys", [frictionless(1.0), rolling(e_ball=1.0), drag(0.5, 1e-6, e_ball=0.9)],
                         ids=["frictionless", "rolling", "drag-e0.9"])
def test_a_hair_inside_tangent(phys):
    # Offset 2R - 1e-9: a real but extremely thin cut. The object ball gets the normal component of the impact,
    # v_n = v_hit sqrt(1 - (b / 2R)^2), times (1 + e) / 2, along the line of centres.
    v, eps = 1.0, 1e-9
    y1 = 0.6 + 2 * R - eps
    b = balls([[0.5, 0.6], [1.0, y1]]).strike("cue", 0.0, v)
    res = run(carom(), phys, b, max_time=1.0, record=True)
    cols = collisions(res)
    assert len(cols) == 1
    assert np.all(np.isfinite(res.balls.pos)) and np.all(np.isfinite(res.balls.vel))
    off = y1 - 0.6  # the offset as actually represented
    (_, i, j, vi0, vj0, vi1, vj1), = collision_velocities(res, phys)
    v_hit = vi0[0]
    vn_expected = v_hit * math.sqrt(1 - (off / (2 * R)) ** 2) * (1 + phys.ball_restitution) / 2
    assert np.linalg.norm(vj1) == pytest.approx(vn_expected, rel=1e-4)
    assert vn_expected < 1e-3 * v  # a tiny bit...
    assert vj1[1] > 0  # ...pushed away from the cue's path
    np.testing.assert_allclose(vi1 + vj1, vi0 + vj0, atol=1e-15)
    assert_valid_final_state(res, carom())


def test_a_hair_outside_tangent_no_collision():
    b = balls([[0.5, 0.6], [1.0, 0.6 + 2 * R + 1e-9]]).strike("cue", 0.0, 1.0)
    for phys in (frictionless(1.0), rolling()):
        res = run(carom(), phys, b, max_time=1.0)
        assert collisions(res) == []
        assert np.all(res.balls.vel[1] == 0.0) and np.array_equal(res.balls.pos[1], b.pos[1])


# --- corner (double cushion) ------------------------------------------------------------------------------------

@pytest.mark.parametrize("e_c", [0.85, 0.6])
@pytest.mark.parametrize("corner", [(1, 3), (0, 2), (1, 2), (0, 3)])
def test_ball_driven_into_corner_comes_back_reversed(e_c, corner):
    # Aimed exactly at the corner point (R or L-R, R or W-R): both cushions at the same instant.
    cx, cy = corner
    tx = L - R if cx == 1 else R
    ty = W - R if cy == 3 else R
    d = 0.4
    sx = -1 if cx == 1 else 1
    sy = -1 if cy == 3 else 1
    start = (tx + sx * d, ty + sy * d)
    ang = math.atan2(-sy, -sx)
    v = 1.0
    table = carom(e_c=e_c)
    t_hit = d * math.sqrt(2) / v
    res = run(table, frictionless(), one_ball(*start, ang, v), max_time=t_hit + 0.3)
    assert sorted(res.events.other.tolist()) == sorted(corner)
    assert np.all(res.events.kind == EV_CUSHION)
    np.testing.assert_allclose(res.events.time, [t_hit, t_hit], atol=TOL)
    vin = np.array([math.cos(ang), math.sin(ang)]) * v
    np.testing.assert_allclose(res.balls.vel[0], -e_c * vin, atol=TOL)
    np.testing.assert_allclose(res.balls.pos[0], [tx, ty] - e_c * vin * 0.3, atol=TOL)


def test_ball_into_corner_with_rolling_friction():
    e_c = 0.85
    table = carom(e_c=e_c)
    a = rolling().deceleration
    d = 0.5
    start = (L - R - d, W - R - d)
    v = 0.6  # slow enough to stop before reaching another cushion on the way back
    res = run(table, rolling(), one_ball(*start, math.pi / 4, v), record=True)
    assert res.status == "rest"
    t_hit = rolling_time_for_distance(v, d * math.sqrt(2), a)
    cush = events_of(res, EV_CUSHION)
    assert len(cush) == 2 and sorted(res.events.other[cush].tolist()) == [1, 3]
    np.testing.assert_allclose(res.events.time[cush], t_hit, atol=TOL)
    # Back along the diagonal with speed e_c v_hit, then rolls to rest.
    v_back = e_c * (v - a * t_hit)
    back = v_back ** 2 / (2 * a)
    np.testing.assert_allclose(res.balls.pos[0], np.array([L - R, W - R]) - back / math.sqrt(2), atol=TOL)


# --- touching balls at the start --------------------------------------------------------------------------------

def test_touching_balls_at_start_transfer_immediately():
    b = balls([[1.0, 0.6], [1.0 + 2 * R, 0.6]]).strike("cue", 0.0, 1.0)
    res = run(carom(), frictionless(1.0), b, max_time=0.5)
    cols = collisions(res)
    assert cols[0] == (0.0, 0, 1)
    np.testing.assert_allclose(res.balls.vel, [[0, 0], [1, 0]], atol=TOL)
    np.testing.assert_allclose(res.balls.pos[0], [1.0, 0.6], atol=TOL)
    np.testing.assert_allclose(res.balls.pos[1], [1.0 + 2 * R + 0.5, 0.6], atol=TOL)


def test_touching_balls_struck_apart_do_not_collide():
    b = balls([[1.0, 0.6], [1.0 + 2 * R, 0.6]]).strike("cue", math.pi, 1.0)
    res = run(carom(), rolling(), b, max_time=0.9)  # before the cue comes back from the left cushion
    assert collisions(res) == []
    np.testing.assert_array_equal(res.balls.pos[1], b.pos[1])


def test_touching_rack_is_a_valid_scene():
    from billiards_env.physics import validate_balls
    validate_balls(rack_balls(pool()), pool())  # does not raise


# --- caps -------------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("solver", ["exact", "step"])
def test_zero_friction_hits_time_cap(solver):
    res = run(carom(), frictionless(), one_ball(1.0, 0.6, 0.3, 1.0), solver=solver, max_time=20.0)
    assert res.status == "time_cap"
    assert res.time == pytest.approx(20.0, abs=1e-9)
    assert np.linalg.norm(res.balls.vel[0]) > 0
    assert_valid_final_state(res, carom())


def test_zero_friction_default_cap_is_reported():
    res = run(carom(), frictionless(), one_ball(1.0, 0.6, 0.3, 1.0))
    assert res.status == "time_cap" and res.time == 600.0


def _assert_bounded_work(res) -> None:
    """A shot ends within its caps: at most max_events events (exact), at most max_time / dt steps (step)."""
    if res.solver == "exact":
        assert res.n_events <= DEFAULT_MAX_EVENTS
    else:
        assert res.n_steps <= round(DEFAULT_MAX_TIME / DEFAULT_DT) + 1


def _unchecked(table, physics, b, solver):
    """Run past the input checks (speeds above MAX_BALL_SPEED are refused there): the kernels themselves must
    still end such a shot within their caps."""
    return Simulator(table, physics, solver=solver).run(b, validate=False)


def _fast(b, row: int, angle: float, speed: float):
    """``b`` with ball ``row`` moving at ``speed`` (set directly: ``strike`` refuses speeds beyond the bound)."""
    out = b.copy()
    out.vel[row] = (speed * math.cos(angle), speed * math.sin(angle))
    return out


@pytest.mark.parametrize("solver", ["exact", "step"])
def test_absurd_speed_terminates_with_a_cap(solver):
    # e_c = 1: nothing can stop a 1e6 m/s ball within 600 s (rolling needs 1e6 / 0.098 s), so a cap must report.
    table = carom(e_c=1.0)
    res = _unchecked(table, rolling(), _fast(balls([[1.0, 0.6]]), 0, 0.3, 1e6), solver)
    _assert_bounded_work(res)
    assert res.status in ("time_cap", "event_cap")
    assert_valid_final_state(res, table)
    # Speed is only ever lost to friction: at most a * t.
    assert np.linalg.norm(res.balls.vel[0]) >= 1e6 - rolling().deceleration * res.time - 1e-3


@pytest.mark.parametrize("solver", ["exact", "step"])
def test_absurd_speed_break_terminates(solver):
    table = pool()
    res = _unchecked(table, rolling(), _fast(rack_balls(table), 0, 0.0, 1e6), solver)
    _assert_bounded_work(res)
    assert res.status in ("rest", "time_cap", "event_cap")
    assert_valid_final_state(res, table, overlap_tol=1e-9 if solver == "exact" else 1e-6)


def test_absurd_speeds_are_refused_at_the_input():
    """What the kernels survive is not what a scene may ask for: a strike beyond MAX_BALL_SPEED is refused with it."""
    from billiards_env.physics import MAX_BALL_SPEED, SceneError

    with pytest.raises(SceneError, match=rf"shot.speed: 1e\+06 m/s .*at most {MAX_BALL_SPEED:g} m/s"):
        one_ball(1.0, 0.6, 0.3, 1e6)
    assert np.linalg.norm(one_ball(1.0, 0.6, 0.3, MAX_BALL_SPEED).vel[0]) == pytest.approx(MAX_BALL_SPEED)


def test_event_cap_is_reported():
    res = run(carom(e_c=1.0), frictionless(), one_ball(1.0, 0.6, 0.3, 1.0), max_events=7)
    assert res.status == "event_cap" and res.n_events == 7 and len(res.events) == 7


# --- no phantom collisions --------------------------------------------------------------------------------------

@pytest.mark.parametrize("case", ["touching", "gap", "oblique", "both-away", "chase-slower", "both-away-skew"])
def test_ball_rolling_away_never_collides(case):
    # A decelerating ball's parabola in time turns back after its stop: that second root is not an event.
    x, y = 1.0, 0.6
    if case == "touching":
        b = balls([[x, y], [x + 2 * R, y]], velocities=[[0, 0], [0.05, 0]])
    elif case == "gap":
        b = balls([[x, y], [x + 2 * R + 1e-6, y]], velocities=[[0, 0], [0.05, 0]])
    elif case == "oblique":
        b = balls([[x, y], [x + 2 * R * math.cos(0.5), y + 2 * R * math.sin(0.5)]],
                  velocities=[[0, 0], [0.04 * math.cos(0.5), 0.04 * math.sin(0.5)]])
    elif case == "both-away":
        b = balls([[x, y], [x + 2 * R, y]], velocities=[[-0.03, 0], [0.03, 0]])
    elif case == "chase-slower":  # the rear ball follows, slower: it stops first, never catching up
        b = balls([[x, y], [x + 2 * R + 1e-3, y]], velocities=[[0.02, 0], [0.05, 0]])
    else:
        b = balls([[x, y], [x + 2 * R, y]],
                  velocities=[[0.02 * math.cos(math.pi + 0.3), 0.02 * math.sin(math.pi + 0.3)],
                              [0.05 * math.cos(0.2), 0.05 * math.sin(0.2)]])
    for solver in ("exact", "step"):
        res = run(carom(), rolling(), b, solver=solver)
        assert res.status == "rest"
        assert len(events_of(res, EV_COLLISION)) == 0, (solver, collisions(res))
        assert max_overlap(res.balls.pos, res.balls.radius) <= 1e-12


def test_stop_events_only_for_moving_balls():
    b = balls([[0.5, 0.6], [1.5, 0.9]]).strike("cue", 0.0, 0.4)
    res = run(carom(), rolling(), b)
    assert list(res.events.kind) == [EV_STOP] and res.events.ball[0] == 0
    np.testing.assert_array_equal(res.balls.pos[1], b.pos[1])


def test_double_newtons_cradle_symmetric():
    # Two cue balls hit a touching row of three from both ends at the same instant (e = 1, no friction):
    # both bounce straight back at their own speed, the row stays put.
    x = [0.7, 1.0, 1.0 + 2 * R, 1.0 + 4 * R, 1.3 + 4 * R]
    v = 1.0
    b = balls([[xx, 0.6] for xx in x], velocities=[[v, 0], [0, 0], [0, 0], [0, 0], [-v, 0]])
    t_hit = (0.3 - 2 * R) / v
    res = run(carom(), frictionless(1.0), b, max_time=t_hit + 0.1)
    np.testing.assert_allclose(res.balls.vel, [[-v, 0], [0, 0], [0, 0], [0, 0], [v, 0]], atol=TOL)
    np.testing.assert_allclose(res.balls.pos[1:4, 0], x[1:4], atol=TOL)
    np.testing.assert_allclose(res.balls.pos[[0, 4], 0], [x[0] + v * t_hit - 0.1 * v, x[4] - v * t_hit + 0.1 * v],
                               atol=TOL)
    assert all(abs(t - t_hit) <= TOL for t, _, _ in collisions(res))
