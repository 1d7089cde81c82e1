"""The nasty cases of a billiards engine, by name. Every shot also passes the shared invariant checks of
:func:`billiards_env.physics.invariants.check_shot` (bounds, overlap, finite, per-collision energy and momentum,
contact, continuity, pocketed-stays-pocketed, status, no Zeno bursts).

Tolerances: as in ``billiards_env.physics.invariants`` (exact overlap 1e-9 m; step ``2 * speed * dt + 1e-9`` m);
velocities compared with ``VEL_TOL`` relative where the exact answer is known in closed form.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from billiards_env.physics.codes import EV_COLLISION, EV_CUSHION, EV_POCKET
from billiards_env.physics.layout import rack_balls, triangle_positions

from .helpers import L, R, W, assert_invariants, scene_dict

VEL_TOL = 1e-12
S30, C30 = 0.5, math.sqrt(3.0) / 2.0
SOLVERS = [("exact", None, None), ("step", 1e-3, "lecture"), ("step", 1e-3, "rewind")]
SOLVER_IDS = ["exact", "step-lecture", "step-rewind"]


def _solver_kw(solver, dt, contact):
    return {"solver": solver} if solver == "exact" else {"solver": solver, "dt": dt, "contact": contact}


def _events(res, kind=None):
    ev = res.events
    rows = range(len(ev)) if kind is None else np.flatnonzero(ev.kind == kind)
    return [(float(ev.time[q]), int(ev.kind[q]), int(ev.ball[q]), int(ev.other[q])) for q in rows]


# ------------------------------------------------------------------------------------------- the touching rack
RACK = rack_balls().pos  # cue at the head spot, 15 touching balls at the foot spot
RACK_NEAR = rack_balls(cue_xy=(0.75 * L - 0.3, 0.5 * W)).pos  # cue 0.3 m from the apex


@pytest.mark.parametrize("solver,dt,contact", SOLVERS, ids=SOLVER_IDS)
@pytest.mark.parametrize("speed", [0.3, 1.0, 3.0, 8.0, 12.0])
@pytest.mark.parametrize("e_ball", [0.0, 0.95, 1.0])
def test_touching_rack_break(solver, dt, contact, speed, e_ball):
    d = scene_dict(RACK_NEAR, shot=(0.0, speed), e_ball=e_ball, max_time=60.0 if solver == "exact" else 30.0,
                   **_solver_kw(solver, dt, contact))
    rep, res = assert_invariants(d)
    assert res.status == "rest"
    if solver == "exact":
        assert rep.n_events < 5000
        assert res.first_contact(0) == 1  # the apex ball


@pytest.mark.parametrize("solver,dt,contact", SOLVERS, ids=SOLVER_IDS)
def test_touching_rack_at_rest_stays_put(solver, dt, contact):
    """Touching balls at rest (the rack) with a slow cue far away: nothing moves but the cue, no events among them."""
    d = scene_dict(RACK, shot=(math.pi, 0.01), max_time=10.0, **_solver_kw(solver, dt, contact))
    rep, res = assert_invariants(d)
    assert np.array_equal(res.balls.pos[1:], RACK[1:])
    assert not [e for e in _events(res) if e[1] == EV_COLLISION]


@pytest.mark.parametrize("n", [2, 3, 5, 8])
def test_newtons_cradle(n):
    """A line of touching balls hit head-on, e = 1, no friction: the last ball leaves with the cue's speed,
    every other ball is left exactly at rest (the documented sequential resolution)."""
    x0 = 1.0
    balls = [(x0 - 0.5, 0.635)] + [(x0 + k * 2 * R, 0.635) for k in range(n)]
    d = scene_dict(balls, shot=(0.0, 1.0), mu_roll=0.0, e_ball=1.0, pockets=[], max_time=0.6)
    rep, res = assert_invariants(d)
    v = res.balls.vel
    assert np.all(v[:-1] == 0.0)
    assert abs(v[-1, 0] - 1.0) <= VEL_TOL and v[-1, 1] == 0.0


# ------------------------------------------------------------------------------------------- wedged balls
def _wedge_layouts():
    x = 1.0
    # V: B on the bottom cushion, A and C resting on it from above-left/right; the cue comes down onto A and C.
    yield "V", [(x, 0.6), (x, R), (x - 2 * R * C30, R + 2 * R * S30), (x + 2 * R * C30, R + 2 * R * S30)], -math.pi / 2
    # three in a row along the cushion, the cue hits the middle one into the cushion
    yield "row", [(x, 0.6), (x, R), (x - 2 * R, R), (x + 2 * R, R)], -math.pi / 2
    # the cue itself wedged between two balls on the cushion, struck (obliquely) into the cushion
    yield "cue_wedged", [(x, R), (x - 2 * R, R), (x + 2 * R, R)], -math.pi / 2 + 0.3
    # cushion - B - A stacked, the cue drives A into B into the cushion, head-on and obliquely
    yield "stack", [(x, 0.6), (x, R), (x, 3 * R)], -math.pi / 2
    yield "stack_oblique", [(x + 0.3, 0.6), (x, R), (x, 3 * R)], math.atan2(3 * R - 0.6, -0.3)


WEDGES = list(_wedge_layouts())


@pytest.mark.parametrize("layout", WEDGES, ids=[w[0] for w in WEDGES])
@pytest.mark.parametrize("friction,min_speed", [("rolling", 0.0), ("rolling", 0.02), ("drag", 0.01), ("drag", 0.02)])
@pytest.mark.parametrize("e_ball", [0.0, 0.3, 0.8, 0.95])
@pytest.mark.parametrize("e_cushion", [0.0, 0.5, 0.85])
def test_wedged_ball_inelastic_collapse_terminates(layout, friction, min_speed, e_ball, e_cushion):
    """A ball wedged between balls and a cushion, restitution < 1 (including 0): no endless micro-collisions, no
    Zeno hang; the shot comes to rest within a modest event count."""
    name, balls, angle = layout
    for speed in (0.05, 1.0, 5.0):
        d = scene_dict(balls, shot=(angle, speed), friction=friction, drag_k=0.5, min_speed=min_speed,
                       e_ball=e_ball, e_cushion=e_cushion, pockets=[], max_events=20_000)
        rep, res = assert_invariants(d)
        assert res.status == "rest", (name, speed, res.status)
        assert rep.n_events <= 2000, (name, speed, rep.n_events)


@pytest.mark.parametrize("layout", WEDGES, ids=[w[0] for w in WEDGES])
@pytest.mark.parametrize("e_ball", [0.0, 0.3, 0.8])
@pytest.mark.parametrize("e_cushion", [0.0, 0.5])
def test_wedged_ball_without_friction_no_zeno(layout, e_ball, e_cushion):
    """Without friction the balls never come to rest (time cap), but the wedge must still resolve in a modest
    number of events at any one instant."""
    name, balls, angle = layout
    for speed in (0.05, 1.0, 5.0):
        d = scene_dict(balls, shot=(angle, speed), mu_roll=0.0, e_ball=e_ball, e_cushion=e_cushion, pockets=[],
                       max_time=20.0, max_events=20_000)
        rep, res = assert_invariants(d)
        assert rep.max_burst <= 2000, (name, speed, rep.max_burst)


@pytest.mark.parametrize("solver,dt,contact", SOLVERS[1:], ids=SOLVER_IDS[1:])
@pytest.mark.parametrize("layout", WEDGES, ids=[w[0] for w in WEDGES])
def test_wedged_ball_step_solver(solver, dt, contact, layout):
    name, balls, angle = layout
    for e_ball in (0.0, 0.8):
        d = scene_dict(balls, shot=(angle, 2.0), e_ball=e_ball, e_cushion=0.5, pockets=[], max_time=30.0,
                       **_solver_kw(solver, dt, contact))
        rep, res = assert_invariants(d)
        assert res.status == "rest"


# ------------------------------------------------------------------------------------------- simultaneous contacts
def test_three_balls_meet_head_on_at_one_instant():
    """Two balls hit a resting ball from opposite sides at the same instant (e = 1, no friction): they bounce back
    with their speeds and the middle ball is left at rest, as the simultaneous answer says."""
    c = (1.25, 0.625)  # exactly representable offsets: both arrive at the same float time
    balls = [(c[0] - 0.5, c[1]), (c[0] + 0.5, c[1]), c]
    d = scene_dict(balls, velocities=[(1.0, 0.0), (-1.0, 0.0), (0.0, 0.0)], mu_roll=0.0, e_ball=1.0, pockets=[],
                   max_time=0.6)
    rep, res = assert_invariants(d)
    col = _events(res, EV_COLLISION)
    assert len(col) >= 2 and max(t for t, *_ in col) - min(t for t, *_ in col) <= 1e-12  # one instant (rounding)
    v = res.balls.vel
    assert abs(v[0, 0] + 1.0) <= VEL_TOL and abs(v[1, 0] - 1.0) <= VEL_TOL
    assert np.all(np.abs(v[2]) <= VEL_TOL) and np.all(v[:, 1] == 0.0)


@pytest.mark.parametrize("e_ball", [0.0, 0.5, 1.0])
@pytest.mark.parametrize("friction", ["rolling", "drag"])
def test_three_balls_converge_at_120_degrees(e_ball, friction):
    """Three balls moving towards one point at 120 degrees touch pairwise at the same instant: total momentum (zero)
    is conserved through the burst and energy does not rise."""
    c = np.array([1.27, 0.635])
    dirs = np.array([[math.cos(a), math.sin(a)] for a in (0.0, 2 * math.pi / 3, 4 * math.pi / 3)])
    contact = 2 * R / math.sqrt(3.0)  # centre distance from the meeting point when all three touch
    pos = c - dirs * (contact + 0.2)
    d = scene_dict(pos, velocities=dirs * 1.0, friction=friction, mu_roll=0.0, drag_k=0.0, e_ball=e_ball,
                   pockets=[], max_time=0.3)
    rep, res = assert_invariants(d)
    assert res.n_events >= 3
    p = res.balls.vel.sum(axis=0) * 0.17
    assert np.all(np.abs(p) <= 1e-12)


@pytest.mark.parametrize("e_ball", [0.0, 0.95, 1.0])
def test_cue_hits_two_touching_balls_at_once(e_ball):
    """The cue aimed at the contact point of two touching balls meets both at one instant."""
    a = (1.5, 0.635 - R)
    b = (1.5, 0.635 + R)
    cue = (1.5 - 2 * R * C30 - 0.7, 0.635)
    d = scene_dict([cue, a, b], shot=(0.0, 2.0), e_ball=e_ball, pockets=[])
    rep, res = assert_invariants(d)
    assert res.status == "rest"
    first = _events(res, EV_COLLISION)[:2]
    assert {first[0][3], first[1][3]} == {1, 2} and abs(first[0][0] - first[1][0]) <= 1e-12


# ------------------------------------------------------------------------------------------- grazing contacts
@pytest.mark.parametrize("delta", [-1e-3, -1e-6, -1e-9, -1e-11, 1e-11, 1e-9, 1e-6, 1e-3])
@pytest.mark.parametrize("friction", ["none", "rolling", "drag"])
def test_grazing_contact_just_inside_and_outside_2R(delta, friction):
    """The cue passes a resting ball with its centre line at 2R + delta: a collision exactly when delta < 0."""
    y0 = 0.5
    b = 2 * R + delta
    kw = {"none": dict(mu_roll=0.0), "rolling": dict(mu_roll=0.01), "drag": dict(friction="drag", drag_k=0.3,
                                                                                  min_speed=0.01)}[friction]
    d = scene_dict([(0.5, y0 + b), (1.2, y0)], shot=(0.0, 1.0), e_cushion=0.0, pockets=[], max_time=1.2, **kw)
    rep, res = assert_invariants(d)
    hit = res.first_contact(0) == 1
    assert hit == (delta < 0), (delta, friction, _events(res))


@pytest.mark.parametrize("delta", [-1e-6, 1e-6, 1e-3])
@pytest.mark.parametrize("solver,dt,contact", SOLVERS[1:], ids=SOLVER_IDS[1:])
def test_grazing_contact_step_solver(delta, solver, dt, contact):
    d = scene_dict([(0.5, 0.5 + 2 * R + delta), (1.2, 0.5)], shot=(0.0, 1.0), pockets=[], max_time=20.0,
                   **_solver_kw(solver, dt, contact))
    assert_invariants(d)


# ------------------------------------------------------------------------------------------- balls a hair apart
@pytest.mark.parametrize("gap", [0.0, 1e-12, 1e-10, 1e-9, 1e-6, 1e-3])
def test_balls_a_hair_apart_cradle(gap):
    """cue -> 1 -> 2 head-on with 1 and 2 a hair apart (e = 1, no friction): 2 leaves with the cue's speed, the
    others are at rest; with a gap the two hits are separate events in time order."""
    balls = [(0.6, 0.635), (1.2, 0.635), (1.2 + 2 * R + gap, 0.635)]
    d = scene_dict(balls, shot=(0.0, 1.0), mu_roll=0.0, e_ball=1.0, pockets=[], max_time=0.8)
    rep, res = assert_invariants(d)
    col = _events(res, EV_COLLISION)
    assert [(c[2], c[3]) for c in col] == [(0, 1), (1, 2)]
    assert col[1][0] >= col[0][0]
    v = res.balls.vel
    assert np.all(v[:2] == 0.0) and abs(v[2, 0] - 1.0) <= VEL_TOL


@pytest.mark.parametrize("gap", [1e-12, 1e-10, 1e-9, 1e-6, 1e-3])
@pytest.mark.parametrize("solver,dt,contact", SOLVERS, ids=SOLVER_IDS)
def test_rack_with_hair_gaps(gap, solver, dt, contact):
    pos = np.vstack([[0.635, 0.635], triangle_positions((0.75 * L, 0.5 * W), R, gap=gap)])
    d = scene_dict(pos, shot=(0.0, 6.0), max_time=60.0 if solver == "exact" else 30.0, **_solver_kw(solver, dt, contact))
    rep, res = assert_invariants(d)
    assert res.status == "rest"


@pytest.mark.parametrize("gap", [0.0, 1e-12, 1e-9, 1e-6, 1e-3])
@pytest.mark.parametrize("speed", [1e-6, 1e-3, 1.0])
def test_ball_a_hair_from_the_cushion(gap, speed):
    d = scene_dict([(R + gap, 0.635), (1.0, 0.635)], shot=(math.pi, speed), e_cushion=0.85, pockets=[])
    rep, res = assert_invariants(d)
    cush = _events(res, EV_CUSHION)
    reaches = speed * speed / (2 * 0.01 * 9.81) > gap  # rolling distance before the stop
    assert bool(cush) == reaches
    if reaches:
        assert cush[0][3] == 0  # the left cushion


# ------------------------------------------------------------------------------------------- pocket capture radius
PK = (1.0, 0.0, 0.125)  # a pocket whose capture circle has an exactly representable radius


@pytest.mark.parametrize("angle", [math.pi / 2, -math.pi / 2, 0.0, math.pi])
def test_ball_exactly_at_capture_radius_is_pocketed_at_once(angle):
    """A moving ball whose centre is exactly at the capture radius is within it: pocketed at t = 0, whatever its
    direction (the spec: at the first instant its centre is within the capture radius)."""
    d = scene_dict([(1.0, 0.125)], shot=(angle, 0.1), pockets=[PK], e_cushion=0.0)
    rep, res = assert_invariants(d)
    assert res.pocket[0] == 0 and res.pocketed_at[0] == 0.0


def test_ball_just_outside_capture_radius():
    eps = 2.0 ** -40
    away = scene_dict([(1.0, 0.125 + eps)], shot=(math.pi / 2, 0.1), pockets=[PK], mu_roll=0.05)
    rep, res = assert_invariants(away)
    assert res.pocket[0] == -1
    towards = scene_dict([(1.0, 0.125 + eps)], shot=(-math.pi / 2, 0.1), pockets=[PK], mu_roll=0.05)
    rep, res = assert_invariants(towards)
    assert res.pocket[0] == 0 and 0.0 < res.pocketed_at[0] < 1e-9


def test_resting_ball_at_capture_radius_is_pocketed_at_once():
    """A resting ball exactly at the capture radius is within it: pocketed at t = 0, before anything hits it
    (the cue ball then rolls through where it stood)."""
    d = scene_dict([(0.6, 0.125), (1.0, 0.125)], shot=(0.0, 1.0), pockets=[PK], e_ball=0.5)
    rep, res = assert_invariants(d)
    pk = _events(res, EV_POCKET)
    assert pk and pk[0][2] == 1 and pk[0][0] == 0.0
    assert not _events(res, EV_COLLISION)


@pytest.mark.parametrize("solver,dt,contact", SOLVERS, ids=SOLVER_IDS)
def test_ball_at_capture_radius_all_solvers_invariants(solver, dt, contact):
    for angle in (0.0, math.pi / 2, -math.pi / 2):
        d = scene_dict([(1.0, 0.125), (1.3, 0.125)], shot=(angle, 0.3), pockets=[PK], **_solver_kw(solver, dt, contact))
        assert_invariants(d)


def test_resting_ball_inside_capture_circle_same_fate_in_both_solvers():
    """A ball at rest inside a capture circle (legal input: validate_balls accepts it, e.g. any ball touching both
    cushions near a corner) while another ball moves elsewhere: both solvers must agree whether it is pocketed."""
    balls = [(R, R), (1.2, 0.635)]  # (R, R) is 0.0404 m from the corner pocket (capture radius 0.06)
    fates = []
    for kw in ({"solver": "exact"}, {"solver": "step", "dt": 1e-3, "contact": "lecture"}):
        d = scene_dict(balls, velocities=[(0.0, 0.0), (0.5, 0.0)], max_time=20.0, **kw)
        rep, res = assert_invariants(d)
        fates.append(int(res.pocket[0]))
    assert fates[0] == fates[1], f"exact: pocket {fates[0]}, step: pocket {fates[1]}"


# ------------------------------------------------------------------------------------------- corner double cushion
@pytest.mark.parametrize("e_cushion", [0.0, 0.5, 0.85, 1.0])
@pytest.mark.parametrize("friction", ["rolling", "drag"])
def test_corner_double_cushion(e_cushion, friction):
    """A ball sent exactly into a corner of a pocketless table (both cushions at the same instant) comes back
    along its own line with both components scaled by the cushion restitution."""
    s = 0.5
    start = (L - R - s, W - R - s)
    d = scene_dict([start], velocities=[(1.0, 1.0)], friction=friction, mu_roll=0.0, drag_k=0.0, min_speed=0.0,
                   e_cushion=e_cushion, pockets=[], max_time=0.9)
    rep, res = assert_invariants(d)
    cush = _events(res, EV_CUSHION)
    assert sorted(c[3] for c in cush[:2]) == [1, 3] and cush[0][0] == cush[1][0]
    v = res.balls.vel[0]
    assert v[0] == v[1] == -e_cushion * 1.0
    x, y = res.balls.pos[0]
    assert abs((x - y) - (start[0] - start[1])) <= 1e-12


@pytest.mark.parametrize("solver,dt,contact", SOLVERS, ids=SOLVER_IDS)
@pytest.mark.parametrize("angle", [math.pi / 4, math.pi / 4 + 1e-12, math.atan2(W, L)])
def test_corner_shots(solver, dt, contact, angle):
    """From touching both cushions at a corner, and from afar into the corner: invariants hold."""
    for start in ((L - R, W - R), (L / 2, W / 2)):
        a = angle if start[0] < L - R else angle + 0.0  # into the corner from the corner itself
        d = scene_dict([start], shot=(a, 2.0), pockets=[], max_time=20.0, **_solver_kw(solver, dt, contact))
        rep, res = assert_invariants(d)
        assert res.status == "rest"


# ------------------------------------------------------------------------------------------- slow balls, stop threshold
@pytest.mark.parametrize("speed", [1e-9, 1e-6, 1e-3, 0.1])
def test_slow_ball_rolls_to_its_closed_form_stop(speed):
    d = scene_dict([(1.0, 0.6)], shot=(0.0, speed), mu_roll=0.01, pockets=[])
    rep, res = assert_invariants(d)
    a = 0.01 * 9.81
    assert res.status == "rest"
    assert abs(res.balls.pos[0, 0] - (1.0 + speed * speed / (2 * a))) <= 1e-15 + 1e-12 * speed * speed / a
    assert abs(res.time - speed / a) <= 1e-12 * max(res.time, 1e-12)


@pytest.mark.parametrize("friction", ["rolling", "drag"])
@pytest.mark.parametrize("rel", [-1e-12, 0.0, 1e-15, 1e-12, 1e-6])
def test_speed_at_the_min_speed_threshold(friction, rel):
    """A ball struck at min_speed * (1 + rel): at or below the threshold it does not move; just above it moves a
    little and stops; into a touching ball it may stop that ball at once (momentum allowance m * min_speed)."""
    v_min = 0.01
    speed = v_min * (1.0 + rel)
    for balls in ([(1.0, 0.6)], [(1.0, 0.6), (1.0 + 2 * R, 0.6)], [(1.0, 0.6), (1.0 + 2 * R + 1e-12, 0.6)]):
        d = scene_dict(balls, shot=(0.0, speed), friction=friction, mu_roll=0.01, drag_k=0.5, min_speed=v_min,
                       e_ball=0.9, pockets=[])
        rep, res = assert_invariants(d)
        assert res.status == "rest"
        if speed <= v_min:
            assert np.array_equal(res.balls.pos, np.asarray(balls))


@pytest.mark.parametrize("solver,dt,contact", SOLVERS, ids=SOLVER_IDS)
@pytest.mark.parametrize("speed", [1e-6, 1e-4, 0.0101, 0.02])
def test_slow_cue_into_touching_cluster(solver, dt, contact, speed):
    pos = np.vstack([[0.75 * L - 2 * R, 0.5 * W], triangle_positions((0.75 * L, 0.5 * W), R, rows=3)])
    d = scene_dict(pos, shot=(0.0, speed), min_speed=0.01, e_ball=0.9, max_time=30.0,
                   **_solver_kw(solver, dt, contact))
    rep, res = assert_invariants(d)
    assert res.status == "rest"


# ------------------------------------------------------------------------------------------- speed range
#: Up to MAX_BALL_SPEED (50 m/s), the fastest a scene may ask for; the kernels beyond it: tests/physics
#: test_phys_hard_cases.py (1e6 m/s, past the input checks).
SPEEDS = [1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1, 1.0, 10.0, 50.0]


@pytest.mark.parametrize("speed", SPEEDS)
@pytest.mark.parametrize("friction", ["rolling", "drag"])
def test_speed_range_exact(speed, friction):
    """Speeds from 1e-6 to 50 m/s (the bound) into a touching rack: invariants hold (the fastest shot ends at the
    time cap or the event cap, and says so)."""
    d = scene_dict(RACK, shot=(0.02, speed), friction=friction, drag_k=1.0, min_speed=1e-7, e_ball=0.95,
                   max_time=2.0 if speed >= 50 else 60.0, max_events=20_000)
    rep, res = assert_invariants(d)
    if speed < 50:
        assert res.status == "rest"


@pytest.mark.parametrize("speed", [100.0, 1e3, 1e300])
def test_speeds_beyond_the_bound_are_refused_by_the_scene(speed):
    from billiards_env.physics import SceneError
    from billiards_env.physics.scene import Scene

    with pytest.raises(SceneError, match=r"shot.speed: .* m/s is faster than any ball can move here \(at most 50"):
        Scene.from_dict(scene_dict(RACK, shot=(0.02, speed)))


@pytest.mark.parametrize("speed", SPEEDS)
@pytest.mark.parametrize("solver,dt,contact", SOLVERS[1:], ids=SOLVER_IDS[1:])
def test_speed_range_step(speed, solver, dt, contact):
    d = scene_dict(RACK, shot=(0.02, speed), friction="drag", drag_k=1.0, min_speed=1e-7, e_ball=0.95,
                   max_time=5.0, **_solver_kw(solver, dt, contact))
    assert_invariants(d)
