"""Aiming geometry (billiards_env.physics.aim): closed-form checks, and cross-checks against the exact solver."""
from __future__ import annotations

import math

import numpy as np
import pytest
from numba import njit

from billiards_env.physics import Balls, Physics, Simulator, Table, aim
from billiards_env.physics.codes import EV_COLLISION, EV_CUSHION
from physics_helpers import L, M, R, W, frictionless

TABLE = Table()
BOTTOM_SIDE, TOP_RIGHT = 1, 5  # pocket order: bottom-left, bottom-side, bottom-right, top-left, top-side, top-right


def _unit(deg: float) -> np.ndarray:
    return aim.direction_vector(math.radians(deg))


# --- rays --------------------------------------------------------------------------------------------------------

def test_ray_circle_entry_closed_form():
    # Ray along +x from the origin, circle of radius 1 at (2, 0.6): enters at x = 2 - sqrt(1 - 0.6^2) = 1.2.
    assert aim.ray_circle_entry(0.0, 0.0, 1.0, 0.0, 2.0, 0.6, 1.0) == pytest.approx(1.2, abs=1e-15)
    assert aim.ray_circle_entry(0.0, 0.0, -1.0, 0.0, 2.0, 0.6, 1.0) == math.inf  # pointing away
    assert aim.ray_circle_entry(0.0, 0.0, 1.0, 0.0, 2.0, 1.2, 1.0) == math.inf  # passes 1.2 > r from the centre
    assert aim.ray_circle_entry(2.1, 0.5, 0.0, 1.0, 2.0, 0.6, 1.0) == 0.0  # starts inside
    # A slanted ray aimed at the centre enters at distance |p - c| - r.
    u = _unit(37.0)
    p = np.array([2.0, 0.6]) - 3.0 * u
    assert aim.ray_circle_entry(p[0], p[1], u[0], u[1], 2.0, 0.6, 1.0) == pytest.approx(2.0, abs=1e-12)


def test_ray_cushion_hit_closed_form():
    # From (1, 0.5) at 30 deg: the right cushion line x = L - R is (L - R - 1) / cos 30 away, the top one
    # y = W - R is (W - R - 0.5) / sin 30: the nearer is the top cushion (id 3).
    u = _unit(30.0)
    d, cushion = aim.ray_cushion_hit(1.0, 0.5, u[0], u[1], L, W, R)
    assert cushion == 3 and d == pytest.approx((W - R - 0.5) / 0.5, abs=1e-12)
    assert aim.ray_cushion_hit(1.0, 0.5, -1.0, 0.0, L, W, R) == (pytest.approx(1.0 - R), 0)
    assert aim.ray_cushion_hit(1.0, 0.5, 0.0, -1.0, L, W, R) == (pytest.approx(0.5 - R), 2)
    assert aim.ray_cushion_hit(1.0, 0.5, 0.0, 0.0, L, W, R) == (math.inf, -1)
    assert aim.ray_cushion_distance(L - R, 0.5, 1.0, 0.0, L, W, R) == 0.0  # touching it, moving into it


def test_array_ray_tests_equal_the_scalar_ones():
    ang = np.linspace(-math.pi, math.pi, 37)
    ux, uy = np.cos(ang), np.sin(ang)
    t_in = aim.ray_circle_entries(1.0, 0.5, ux, uy, L, W, 0.06)
    t_wall = aim.ray_cushion_distances(1.0, 0.5, ux, uy, L, W, R)
    for k in range(len(ang)):
        assert t_in[k] == aim.ray_circle_entry(1.0, 0.5, ux[k], uy[k], L, W, 0.06)
        assert t_wall[k] == aim.ray_cushion_distance(1.0, 0.5, ux[k], uy[k], L, W, R)


@pytest.mark.parametrize("deg", [-150.0, -100.0, -20.0, 10.0, 75.0, 160.0])
def test_solver_meets_the_cushion_where_the_ray_test_says(deg):
    # A lone ball on a pocketless frictionless table: its first event is the cushion the ray test names, at the
    # point the ray test gives.
    u = _unit(deg)
    start = np.array([0.9, 0.4])
    table = Table().without_pockets()
    res = Simulator(table, frictionless(), max_time=20.0).run(
        Balls.from_positions([start], velocities=[2.0 * u]), record=True)
    d, cushion = aim.ray_cushion_hit(start[0], start[1], u[0], u[1], L, W, R)
    assert res.events.kind[0] == EV_CUSHION and res.events.other[0] == cushion
    hit = res.trajectory.sample([res.events.time[0]])[0][0, 0]
    np.testing.assert_allclose(hit, start + d * u, atol=1e-9)


# --- ghost ball, cut ---------------------------------------------------------------------------------------------

def test_ghost_ball_touches_the_object_ball_behind_it():
    obj = np.array([1.5, 0.7])
    g = aim.ghost_ball_position(obj, math.radians(40.0), 2 * R)
    assert np.hypot(*(obj - g)) == pytest.approx(2 * R, abs=1e-15)  # in contact
    assert aim.aim_angle(g, obj) == pytest.approx(math.radians(40.0), abs=1e-12)  # line of centres = direction


def test_cut_angle_straight_and_known_values():
    assert aim.cut_angle(_unit(25.0), _unit(25.0)) == pytest.approx(0.0, abs=1e-7)
    for deg in (15.0, 30.0, 60.0, 89.0):
        assert math.degrees(aim.cut_angle(_unit(10.0), _unit(10.0 + deg))) == pytest.approx(deg, abs=1e-9)
        assert aim.cut_cosine(_unit(10.0), _unit(10.0 - deg)) == pytest.approx(math.cos(math.radians(deg)))
    assert aim.cut_angle(_unit(0.0), _unit(180.0)) == pytest.approx(math.pi)


@pytest.mark.parametrize("cut_deg", [0.0, 20.0, -45.0, 70.0])
def test_offset_aim_gives_the_cut_of_its_offset(cut_deg):
    # A cue line passing the object centre at offset (2R) sin(cut) meets the ghost circle where the line of
    # centres makes that cut with it; offset > 0 sends the object ball to the left (counter-clockwise).
    cue, obj = np.array([0.5, 0.4]), np.array([1.6, 0.9])
    offset = 2 * R * math.sin(math.radians(cut_deg))
    angle = aim.offset_aim_angle(cue, obj, offset)
    assert aim.aim_offset(cue, obj, angle) == pytest.approx(offset, abs=1e-15)
    u = aim.direction_vector(angle)
    t = aim.ray_circle_entry(cue[0], cue[1], u[0], u[1], obj[0], obj[1], 2 * R)  # where the cue ball touches
    contact = cue + t * u
    obj_dir = (obj - contact) / np.hypot(*(obj - contact))
    assert math.degrees(aim.cut_angle(u, obj_dir)) == pytest.approx(abs(cut_deg), abs=1e-6)
    turn = aim.wrap_angle(aim.aim_angle(contact, obj) - angle)
    assert math.copysign(1.0, turn) == math.copysign(1.0, cut_deg) or cut_deg == 0.0


def test_angles():
    assert aim.angular_radius(1.0, 2.0) == pytest.approx(math.pi / 6)
    assert aim.angular_radius(1.0, 0.5) == pytest.approx(math.pi / 2)
    a = np.linspace(-20.0, 20.0, 101)
    w = aim.wrap_angle(a)
    assert np.all((w >= -math.pi) & (w < math.pi))
    np.testing.assert_allclose(np.cos(w), np.cos(a), atol=1e-12)


# --- pockets -----------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("start, pocket", [((1.27, 0.8), BOTTOM_SIDE), ((1.0, 0.6), BOTTOM_SIDE),
                                           ((1.5, 0.35), BOTTOM_SIDE), ((2.0, 0.75), TOP_RIGHT), ((1.6, 0.5), TOP_RIGHT)])
def test_pocket_window_contains_the_direct_direction_and_narrows_with_distance(start, pocket):
    obj = np.array(start)
    c = TABLE.pocket_xy[pocket]
    widths = []
    for f in (1.0, 0.75, 0.5, 0.25):  # slide the ball towards the pocket along the line to its centre
        p = c + f * (obj - c)
        centre, half, d_in = aim.pocket_window(p, R, TABLE, pocket)
        direct = aim.aim_angle(p, c)
        assert abs(aim.wrap_angle(direct - centre)) <= half
        assert half <= aim.angular_radius(TABLE.pocket_radius[pocket], np.hypot(*(c - p))) + 1e-12
        dist = np.hypot(*(c - p))
        assert dist - TABLE.pocket_radius[pocket] - 1e-12 <= d_in <= dist
        widths.append(half)
    assert all(a < b for a, b in zip(widths, widths[1:]))  # nearer: wider


def test_pocket_window_straight_above_the_side_pocket_and_inside_it():
    centre, half, d_in = aim.pocket_window((L / 2, 0.5), R, TABLE, BOTTOM_SIDE)
    assert centre == pytest.approx(-math.pi / 2, abs=1e-12)
    assert d_in == pytest.approx(0.5 - 0.052, abs=1e-9)
    assert aim.pocket_window((L / 2, 0.03), R, TABLE, BOTTOM_SIDE)[1:] == (math.pi / 2, 0.0)
    # A capture circle entirely behind the cushion line y = R is never reached.
    hidden = Table(pocket_xy=[[L / 2, -0.03]], pocket_radius=[0.05])
    assert aim.pocket_window((1.0, 0.5), R, hidden, 0) is None


def _sampled_window(obj, radius, table, pocket, samples=aim.WINDOW_SAMPLES):
    """The window as it was computed before the closed form: every one of ``samples`` directions ray-tested
    (numpy.linspace across the capture circle's angular size), the widest run of good ones."""
    obj = np.asarray(obj, dtype=float)
    c = table.pocket_xy[pocket]
    pr = float(table.pocket_radius[pocket])
    dist = float(np.hypot(*(c - obj)))
    theta_c = aim.aim_angle(obj, c)
    if dist <= pr:
        return float(theta_c), math.pi / 2, 0.0
    half = aim.angular_radius(pr, dist)
    angles = theta_c + np.linspace(-half, half, samples)
    ux, uy = np.cos(angles), np.sin(angles)
    t_in = aim.ray_circle_entries(obj[0], obj[1], ux, uy, c[0], c[1], pr)
    t_wall = aim.ray_cushion_distances(obj[0], obj[1], ux, uy, table.length, table.width, radius)
    ok = list(np.isfinite(t_in) & (t_in <= t_wall + 1e-9)) + [False]
    best_len, best_start, run_start = 0, 0, None
    for k, flag in enumerate(ok):
        if flag and run_start is None:
            run_start = k
        elif not flag and run_start is not None:
            if k - run_start > best_len:
                best_len, best_start = k - run_start, run_start
            run_start = None
    if best_len == 0:
        return None
    lo, hi = best_start, best_start + best_len - 1
    step = 2.0 * half / (samples - 1)
    centre = 0.5 * (angles[lo] + angles[hi])
    d_in = aim.ray_circle_entry(obj[0], obj[1], math.cos(centre), math.sin(centre), c[0], c[1], pr)
    return float(centre), float(0.5 * ((hi - lo) * step + step)), float(d_in if math.isfinite(d_in) else dist)


def test_closed_form_window_is_the_sampled_window():
    # The compiled window ray-tests only the samples next to where the capture circle crosses a cushion line; it
    # must equal ray-testing all of them, bit for bit: on random balls (some frozen on a cushion, some next to or
    # inside a pocket), on the standard table, a small one and one with odd pockets (one behind a cushion line,
    # one inside the playing area), with 41, 7 and 2 samples.
    rng = np.random.default_rng(11)
    tables = (TABLE, Table(length=2.24, width=1.12),
              Table(pocket_xy=[[1.0, -0.01], [2.0, 1.3], [0.5, 0.6], [L / 2, -0.03]],
                    pocket_radius=[0.05, 0.04, 0.03, 0.05]))
    checked = found = 0
    for table in tables:
        for n in range(1500):
            p = rng.uniform([R, R], [table.length - R, table.width - R])
            if n % 5 == 0:  # frozen on a cushion line
                axis = int(rng.integers(2))
                p[axis] = R if rng.random() < 0.5 else (table.length, table.width)[axis] - R
            elif n % 5 == 1:  # next to a pocket
                k = int(rng.integers(table.n_pockets))
                p = np.clip(table.pocket_xy[k] + rng.normal(0.0, 0.06, 2), R, [table.length - R, table.width - R])
            for k in range(table.n_pockets):
                for samples in ((41,) if n % 7 else (41, 7, 2)):
                    expected = _sampled_window(p, R, table, k, samples)
                    assert aim.pocket_window(p, R, table, k, samples) == expected
                    checked += 1
                    found += expected is not None
    assert checked > 20000 and 0.5 * checked < found < checked  # windows and blocked pockets both exercised


def test_dot2_rounds_once_after_the_first_product_and_cut_cosine_clips():
    """dot2 is ``ax * bx`` rounded, then ``ay * by`` added to it with one rounding (a fused multiply-add): checked
    against exact rational arithmetic, so it holds on every CPU (numpy's own 2-vector dot is OpenBLAS's, whose
    rounding depends on the kernel the CPU selects)."""
    from fractions import Fraction

    rng = np.random.default_rng(3)
    a, b = rng.normal(size=(2000, 2)), rng.normal(size=(2000, 2))
    want = [float(Fraction(x[1]) * Fraction(y[1]) + Fraction(float(x[0] * y[0]))) for x, y in zip(a, b)]
    assert [aim.dot2(x[0], x[1], y[0], y[1]) for x, y in zip(a, b)] == want
    assert sum(w != x[0] * y[0] + x[1] * y[1] for w, x, y in zip(want, a, b)) > 100  # not the plain sum
    u = _unit(20.0)
    assert aim.cut_cosine(u, u * (1.0 + 1e-15)) == 1.0  # clipped into [-1, 1]
    assert aim.cut_cosine(u, -u) == pytest.approx(-1.0)


def test_pocket_bearings_and_mouth_axes():
    axes = aim.pocket_mouth_axes(TABLE)
    s = 1 / math.sqrt(2)
    np.testing.assert_allclose(axes, [[-s, -s], [0, -1], [s, -s], [-s, s], [0, 1], [s, s]], atol=1e-15)
    angle, dist, square = aim.pocket_bearings((L / 2, 0.4), TABLE)
    assert angle[BOTTOM_SIDE] == pytest.approx(-math.pi / 2) and dist[BOTTOM_SIDE] == pytest.approx(0.4)
    assert square[BOTTOM_SIDE] == pytest.approx(1.0)  # straight in
    assert square[TOP_RIGHT] == pytest.approx(math.cos(math.atan2(W - 0.4, L / 2) - math.pi / 4))


# --- clear paths ---------------------------------------------------------------------------------------------------

def test_segment_blocked():
    a, b = (0.0, 0.0), (1.0, 0.0)
    assert aim.segment_blocked(a, b, np.array([[0.5, 0.05]]), np.array([0.06]))
    assert aim.path_clear(a, b, np.array([[0.5, 0.07], [1.2, 0.0]]), np.array([0.06, 0.06]))  # beside; beyond
    assert aim.segment_blocked(a, b, np.array([[1.03, 0.0]]), np.array([0.06]))  # near the end point
    assert aim.path_clear(a, b, np.zeros((0, 2)), np.zeros(0))


# --- collisions ------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("cut_deg", [10.0, 30.0, 60.0])
def test_ninety_degree_rule_and_momentum(cut_deg):
    v = 2.0 * _unit(cut_deg)  # cue velocity; the line of centres is +x
    line = np.array([1.0, 0.0])
    cue_after = aim.deflected_cue_velocity(v, line, 1.0, M, M)
    assert cue_after @ line == pytest.approx(0.0, abs=1e-15)  # leaves at 90 deg to the object ball's path
    assert np.hypot(*cue_after) == pytest.approx(2.0 * math.sin(math.radians(cut_deg)))
    # Any restitution and masses: momentum is conserved, energy at e = 1 too, and the object ball's speed is
    # m_c (1 + e) / (m_c + m_o) v cos(cut).
    for e, m_obj in ((1.0, 0.2), (0.95, 0.16), (0.5, M)):
        vc, vo = aim.collision_velocities(v, (0.0, 0.0), line, e, M, m_obj)
        np.testing.assert_allclose(M * vc + m_obj * vo, M * v, atol=1e-15)
        cos_cut = math.cos(math.radians(cut_deg))
        expected = M * (1 + e) / (M + m_obj) * 2.0 * cos_cut
        assert np.hypot(*vo) == pytest.approx(expected)
        assert aim.object_ball_speed(2.0, cos_cut, e, M, m_obj) == pytest.approx(expected)
        if e == 1.0:
            assert M * (vc @ vc) + m_obj * (vo @ vo) == pytest.approx(M * (v @ v))


# --- paths into pockets ------------------------------------------------------------------------------------------

def test_path_with_a_cushion_bounce_into_a_corner_pocket():
    # Mirror the top-right pocket in the bottom cushion line y = R: a ball aimed at the mirror image bounces off
    # the bottom cushion (restitution 1) straight into the pocket.
    table = Table(cushion_restitution=1.0)
    start = np.array([1.0, 0.5])
    mirror = np.array([L, 2 * R - W])
    u = (mirror - start) / np.hypot(*(mirror - start))
    physics = frictionless()
    assert aim.path_pocket(start, 3.0 * u, R, table, physics) == TOP_RIGHT
    assert aim.path_pocket(start, 3.0 * u, R, table, physics, max_bounces=0) == -1  # the bounce is needed
    assert not aim.path_enters_pocket(start, -3.0 * u, R, table, physics, max_bounces=0)
    # Too slow to get there under rolling friction: it stops first.
    assert aim.path_pocket(start, 0.5 * u, R, table, Physics()) == -1
    res = Simulator(table, physics, max_time=20.0).run(Balls.from_positions([start], velocities=[3.0 * u]))
    assert res.pocket[0] == TOP_RIGHT


def test_path_pocket_agrees_with_the_solver_for_a_lone_ball():
    rng = np.random.default_rng(7)
    sim = Simulator(TABLE, Physics())
    potted = 0
    for _ in range(60):
        start = rng.uniform([0.2, 0.2], [L - 0.2, W - 0.2])
        v = rng.uniform(1.0, 4.0) * aim.direction_vector(rng.uniform(-math.pi, math.pi))
        res = sim.run(Balls.from_positions([start], velocities=[v]))
        bounces = int(np.sum(res.events.kind == EV_CUSHION))
        predicted = aim.path_pocket(start, v, R, TABLE, Physics(), max_bounces=bounces)
        assert predicted == res.pocket[0]
        potted += predicted >= 0
    assert potted >= 10  # the sample exercises pots, not only misses


def test_ghost_ball_shot_pots_in_the_solver():
    # Everything from aim: the pocket window's direction, the ghost ball, the cut, the object ball's speed.
    physics = Physics()
    obj, cue = np.array([2.0, 0.85]), np.array([1.0, 0.75])
    centre, half, d_in = aim.pocket_window(obj, R, TABLE, TOP_RIGHT)
    ghost = aim.ghost_ball_position(obj, centre, 2 * R)
    angle = aim.aim_angle(cue, ghost)
    cut = aim.cut_angle(aim.direction_vector(angle), aim.direction_vector(centre))
    assert 0.2 < cut < 1.2  # a real cut shot
    res = Simulator(TABLE, physics).run(Balls.from_positions([cue, obj]).strike(0, angle, 2.5), record=True)
    assert res.pocket[1] == TOP_RIGHT
    assert res.events.kind[0] == EV_COLLISION
    # The object ball leaves along the window's direction.
    t = res.events.time[0]
    (p0, _), (p1, _) = res.trajectory.sample([t]), res.trajectory.sample([t + 1e-3])
    d_obj = p1[0, 1] - p0[0, 1]
    assert abs(aim.wrap_angle(math.atan2(d_obj[1], d_obj[0]) - centre)) < 1e-6


def _jaw_window_every_wall(obj, radius, table, pocket, samples=aim.WINDOW_SAMPLES):
    """A jaw table's window as it was computed before the walls were culled: every sample ray-tested against the
    first wall ahead of all the table's rails, jaw faces and tips (:func:`aim.cushion_ahead`)."""
    segs, tips = table.walls()
    c = table.pocket_xy[pocket]
    pr = float(table.pocket_radius[pocket])
    dist = math.hypot(c[0] - obj[0], c[1] - obj[1])
    theta_c = math.atan2(c[1] - obj[1], c[0] - obj[0])
    if dist <= pr:
        return float(theta_c), math.pi / 2, 0.0
    half = math.asin(min(1.0, pr / dist))
    ok = []
    for a in theta_c + np.linspace(-half, half, samples):
        ux, uy = math.cos(a), math.sin(a)
        t_in = aim.ray_circle_entry(obj[0], obj[1], ux, uy, c[0], c[1], pr)
        t_wall = aim.cushion_ahead(obj[0], obj[1], ux, uy, table.length, table.width, radius, segs, tips)[0]
        ok.append(math.isfinite(t_in) and t_in <= t_wall + 1e-9)
    ok.append(False)
    best_len, best_start, run_start = 0, 0, None
    for k, flag in enumerate(ok):
        if flag and run_start is None:
            run_start = k
        elif not flag and run_start is not None:
            if k - run_start > best_len:
                best_len, best_start = k - run_start, run_start
            run_start = None
    if best_len == 0:
        return None
    return best_start, best_len


@pytest.mark.parametrize("preset", ["wpa", "snooker_match", "pooltool"])
def test_jaw_window_with_culled_walls_is_the_window_of_every_wall(preset):
    # window_of on a jaw table tests each sample only against the walls near the window's reach and stops at the
    # first wall that fails it: the same run of samples as the first wall ahead of all walls, on random balls (some
    # in or next to a mouth, some beyond a cushion line). A run one sample longer or shifted moves the centre or
    # the width by half a sample step (~1e-3 rad), far beyond the tolerance (the reference's hypot rounds as
    # CPython's, not the compiled one's).
    from billiards_env.physics.scene import parse_table

    table = parse_table({"preset": preset})
    segs, tips = table.walls()
    assert len(segs) and len(tips)
    rng = np.random.default_rng(5)
    checked = found = 0
    for n in range(250):
        if n % 3 == 0:
            k = int(rng.integers(table.n_pockets))
            p = table.pocket_xy[k] + rng.normal(0.0, 0.07, 2)
        else:
            p = rng.uniform([-0.01, -0.01], [table.length + 0.01, table.width + 0.01])
        for k in range(table.n_pockets):
            expected = _jaw_window_every_wall(p, R, table, k)
            got = aim.window_of(p[0], p[1], R, table.pocket_xy[k, 0], table.pocket_xy[k, 1],
                                table.pocket_radius[k], table.length, table.width, aim.WINDOW_SAMPLES, segs, tips)
            checked += 1
            if expected is None:
                assert not got[3]
                continue
            found += 1
            assert got[3]
            if len(expected) == 3:  # from inside the circle
                assert got[:3] == expected
                continue
            start, length = expected
            c = table.pocket_xy[k]
            half = math.asin(min(1.0, table.pocket_radius[k] / math.hypot(c[0] - p[0], c[1] - p[1])))
            step = 2.0 * half / (aim.WINDOW_SAMPLES - 1)
            centre = math.atan2(c[1] - p[1], c[0] - p[0]) + (start + (length - 1) / 2) * step - half
            assert got[0] == pytest.approx(centre, abs=1e-12)
            assert got[1] == pytest.approx(0.5 * length * step, abs=1e-12)
    assert 0.3 * checked < found < checked


@njit(cache=True)
def _jaw_runs_every_sample(balls, radius, pocket_xy, pocket_r, samples, segs, tips):
    """Compiled twin of :func:`_jaw_window_every_wall` for many balls: ``(N, K, 2)`` rows (start, length) of the
    widest run of samples that enter each pocket's circle before the first wall ahead of all walls (length 0: no
    window, -1: the ball is inside the circle). Every sample is ray-tested."""
    out = np.zeros((balls.shape[0], pocket_r.shape[0], 2), np.int64)
    for i in range(balls.shape[0]):
        ox = balls[i, 0]
        oy = balls[i, 1]
        for p in range(pocket_r.shape[0]):
            cx = pocket_xy[p, 0]
            cy = pocket_xy[p, 1]
            pr = pocket_r[p]
            dist = math.hypot(cx - ox, cy - oy)
            if dist <= pr:
                out[i, p, 1] = -1
                continue
            half = math.asin(min(1.0, pr / dist))
            theta_c = math.atan2(cy - oy, cx - ox)
            div = samples - 1
            best_len = 0
            best_start = 0
            current = 0  # the length of the run of feasible samples ending at k (its own scan: a streak count)
            for k in range(samples):
                a = theta_c + half if k == div else theta_c + (k * (2.0 * half / div) - half)
                ux = math.cos(a)
                uy = math.sin(a)
                t_in = aim.ray_circle_entry(ox, oy, ux, uy, cx, cy, pr)
                ok = math.isfinite(t_in) and t_in <= aim.cushion_ahead(ox, oy, ux, uy, 0.0, 0.0, radius, segs,
                                                                       tips)[0] + 1e-9
                current = current + 1 if ok else 0
                if current > best_len:  # (strictly: the first of equal runs)
                    best_len = current
                    best_start = k - current + 1
            out[i, p, 0] = best_start
            out[i, p, 1] = best_len
    return out


@pytest.mark.parametrize("preset", ["wpa", "snooker_match", "pooltool"])
def test_jaw_window_tests_only_where_a_wall_may_change_its_verdict(preset):
    # window_of on a jaw table ray-tests only the samples next to a direction where a wall's verdict may change (the
    # contact line's ends and crossings with the pocket's circle, a tip's tangents and crossings, where a ray starts
    # approaching a wall) and the first, second and last; every other sample copies the one before. The widest run
    # must be the one of testing every sample against the first wall of all, on thousands of balls: anywhere, next
    # to a mouth, hugging a rail or just off a cushion line, for three ball sizes and three sample counts.
    from billiards_env.physics.scene import parse_table

    table = parse_table({"preset": preset})
    segs, tips = (np.ascontiguousarray(a, dtype=np.float64) for a in table.walls())
    pxy = np.ascontiguousarray(table.pocket_xy, dtype=np.float64)
    prs = np.ascontiguousarray(table.pocket_radius, dtype=np.float64)
    rng = np.random.default_rng(11)
    n = 1500
    for radius in (0.02625, R, 0.05):
        spread = rng.uniform([-0.01, -0.01], [table.length + 0.01, table.width + 0.01], (n, 2))
        mouths = pxy[rng.integers(len(prs), size=n)] + rng.normal(0.0, 0.08, (n, 2))
        rails = rng.uniform([0.0, 0.0], [table.length, table.width], (n, 2))
        side = rng.integers(4, size=n)
        rails[side == 0, 0] = radius + rng.exponential(1e-3, (side == 0).sum())
        rails[side == 1, 0] = table.length - radius
        rails[side == 2, 1] = radius + rng.normal(0.0, 1e-3, (side == 2).sum())
        rails[side == 3, 1] = table.width - radius - rng.exponential(1e-3, (side == 3).sum())
        balls = np.concatenate([spread, mouths, rails])
        for samples in (aim.WINDOW_SAMPLES, 21, 62):
            runs = _jaw_runs_every_sample(balls, radius, pxy, prs, samples, segs, tips)
            found = 0
            for i in range(balls.shape[0]):
                ox, oy = balls[i]
                for p in range(len(prs)):
                    got = aim.window_of(ox, oy, radius, pxy[p, 0], pxy[p, 1], prs[p], table.length, table.width,
                                        samples, segs, tips)
                    start, length = runs[i, p]
                    if length == 0:
                        assert not got[3], (preset, radius, samples, i, p)
                        continue
                    found += 1
                    if length < 0:
                        assert got[1] == math.pi / 2
                        continue
                    dist = math.hypot(pxy[p, 0] - ox, pxy[p, 1] - oy)
                    half = math.asin(min(1.0, prs[p] / dist))
                    step = 2.0 * half / (samples - 1)
                    centre = math.atan2(pxy[p, 1] - oy, pxy[p, 0] - ox) + (start + (length - 1) / 2) * step - half
                    assert got[3], (preset, radius, samples, i, p)
                    assert got[0] == pytest.approx(centre, abs=1e-12), (preset, radius, samples, i, p)
                    assert got[1] == pytest.approx(0.5 * length * step, abs=1e-12), (preset, radius, samples, i, p)
            # Not vacuous: many windows, and many of them cut short by a wall (a run shorter than the samples).
            assert 0.15 * runs.shape[0] * len(prs) < found < runs.shape[0] * len(prs)
            assert ((runs[:, :, 1] > 0) & (runs[:, :, 1] < samples)).sum() > 0.05 * runs.shape[0] * len(prs)


@pytest.mark.parametrize("preset", ["wpa", "snooker_match"])
def test_walls_ahead_with_groups_is_the_first_wall_of_all(preset):
    # walls_ahead passes over a pocket's jaw faces and tips when the ray misses their group's circle: the same
    # distance and wall index as ray-testing every wall; a lone ball's path the same pocket either way.
    from billiards_env.physics.kernel_io import wall_groups
    from billiards_env.physics.scene import parse_table

    table = parse_table({"preset": preset})
    segs, tips = table.walls()
    groups = wall_groups(segs, tips)
    assert len(groups) == table.n_pockets
    none = np.zeros((0, 3))
    rng = np.random.default_rng(9)
    passed_over = 0
    pots = 0
    for n in range(3000):
        if n % 3 == 0:
            k = int(rng.integers(table.n_pockets))
            p = table.pocket_xy[k] + rng.normal(0.0, 0.08, 2)
        else:
            p = rng.uniform([0.0, 0.0], [table.length, table.width])
        a = rng.uniform(-math.pi, math.pi)
        ux, uy = math.cos(a), math.sin(a)
        got = aim.walls_ahead(p[0], p[1], ux, uy, R, segs, tips, groups)
        assert got == aim.walls_ahead(p[0], p[1], ux, uy, R, segs, tips, none)
        assert got == aim.cushion_ahead(p[0], p[1], ux, uy, table.length, table.width, R, segs, tips)
        if got[1] >= 0 and got[1] < len(segs) - len(tips):
            passed_over += 1
        s = rng.uniform(0.1, 5.0)
        args = (p[0], p[1], s * ux, s * uy, R, table.length, table.width, 0.85, table.pocket_xy, table.pocket_radius,
                0, 0.0981, 0.0, 0.0, 4, segs, tips)
        pocket = aim.lone_path_pocket_grouped(*args, groups)
        assert pocket == aim.lone_path_pocket(*args)
        pots += pocket >= 0
    assert passed_over > 1000 and pots > 100
