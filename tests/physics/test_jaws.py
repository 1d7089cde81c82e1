"""The jaw pocket model: the geometry built from pooltool's specs, the solvers meeting rails, jaw faces and tips,
the laws at those walls, and the specs that make no table refused."""
from __future__ import annotations

import math

import numpy as np
import pytest
from physics_helpers import EV_CUSHION, EV_POCKET, R, balls, rolling

from billiards_env.physics import Physics, SceneError, Simulator
from billiards_env.physics.motion import time_for_distance
from billiards_env.physics.pocket_specs import (N_RAILS, N_SEGMENTS, POOLTOOL_7FT, SNOOKER_12FT, WPA_9FT,
                                                PocketSpecs, build_walls, pocket_circles, throat_leak,
                                                wall_overlaps)
from billiards_env.physics.scene import parse_table
from billiards_env.physics.table import CORNER_POCKET_RADIUS, SIDE_POCKET_RADIUS, jaw_table

SPECS = (POOLTOOL_7FT, WPA_9FT, SNOOKER_12FT)


@pytest.mark.parametrize("specs", SPECS)
def test_tips_round_the_corner_between_rail_and_jaw(specs):
    segs, tips = build_walls(specs)
    assert segs.shape == (N_SEGMENTS, 6) and tips.shape == (12, 3)
    assert np.allclose(np.hypot(segs[:, 4], segs[:, 5]), 1.0)
    # Each tip touches the end of its jaw face (tangent there: the radius to it is normal to the face)...
    for p in range(6):
        for k in range(2):
            jaw = segs[N_RAILS + 2 * p + k]
            cx, cy, rad = tips[2 * p + k]
            assert math.hypot(jaw[2] - cx, jaw[3] - cy) == pytest.approx(rad, abs=1e-12)
            to_tip = np.array([cx - jaw[2], cy - jaw[3]])
            along = jaw[2:4] - jaw[0:2]
            cos = abs(to_tip @ along) / (np.linalg.norm(to_tip) * np.linalg.norm(along))
            # pooltool starts a side jaw's deep end at cw sin(angle) along the rail where the face's line is at
            # cw tan(angle): a side face turns by under half a degree from the tangent (kept: pooltool's table).
            assert cos < (1e-12 if p in (0, 2, 3, 5) else 1e-2)
    # ...and one rail end, tangent to the cushion line there.
    ends = np.concatenate([segs[:N_RAILS, 0:2], segs[:N_RAILS, 2:4]])
    for cx, cy, rad in tips:
        d = np.hypot(ends[:, 0] - cx, ends[:, 1] - cy)
        assert d.min() == pytest.approx(rad, abs=1e-12)


@pytest.mark.parametrize("specs", SPECS)
def test_rails_lie_on_the_cushion_lines_and_face_the_table(specs):
    segs, _ = build_walls(specs)
    centre = np.array([specs.l / 2, specs.w / 2])
    for ax, ay, bx, by, nx, ny in segs[:N_RAILS]:
        assert (ay == by == 0.0) or (ay == by == specs.w) or (ax == bx == 0.0) or (ax == bx == specs.l)
        assert (centre - [ax, ay]) @ [nx, ny] > 0
    # A jaw face's open side holds its pocket's circle centre (the throat).
    xy, _ = pocket_circles(specs)
    for p in range(6):
        for k in range(2):
            ax, ay, bx, by, nx, ny = segs[N_RAILS + 2 * p + k]
            assert (xy[p] - [ax, ay]) @ [nx, ny] > 0


def test_pocket_circles_sit_behind_the_mouths_by_their_depth():
    s = POOLTOOL_7FT
    xy, r = pocket_circles(s)
    assert np.allclose(np.hypot(*xy[0]), s.corner_pocket_depth)
    assert xy[1, 1] == -s.side_pocket_depth and xy[4, 1] == s.w + s.side_pocket_depth
    assert r.tolist() == [s.corner_pocket_radius, s.side_pocket_radius, s.corner_pocket_radius] * 2


def _run(table, physics, pos, vel):
    b = balls([list(p) for p in pos], velocities=[list(v) for v in vel])
    return Simulator(table, physics).run(b, record=True)


def test_straight_down_the_diagonal_drops_when_the_centre_enters_the_pocket_circle():
    table = jaw_table(POOLTOOL_7FT)
    phys = rolling()
    x0 = 0.4
    res = _run(table, phys, [(x0, x0)], [(-1.0, -1.0)])
    assert res.pocket[0] == 0
    assert list(res.events.kind) == [EV_POCKET]  # between the jaws, touching none
    d = math.hypot(x0 - table.pocket_xy[0, 0], x0 - table.pocket_xy[0, 1]) - table.pocket_radius[0]
    expected = time_for_distance(math.sqrt(2.0), d, 0, phys.deceleration, 0.0)
    assert res.pocketed_at[0] == pytest.approx(expected, rel=1e-12)


def test_a_ball_along_the_rail_passes_the_side_mouth_that_a_capture_circle_swallows():
    y = R + 0.0005
    jaws = _run(jaw_table(POOLTOOL_7FT), rolling(), [(0.3, y)], [(1.0, 0.0)])
    capture = _run(parse_table({"preset": "pooltool", "pockets": "capture"}), rolling(), [(0.3, y)], [(1.0, 0.0)])
    assert capture.pocket[0] == 1  # the capture circle on the side pocket reaches the ball's centre
    assert jaws.pocket[0] != 1


@pytest.mark.parametrize("e_c", [1.0, 0.7])
def test_a_rail_of_a_jaw_table_reflects_as_a_straight_cushion(e_c):
    v = np.array([0.6, -0.8])
    res = _after_first_wall(jaw_table(POOLTOOL_7FT, e_c), (0.4, 0.3), v)
    assert res.events.other[0] == 0  # the bottom rail left of the middle pocket
    assert res.events.time[0] == pytest.approx((0.3 - R) / 0.8, rel=1e-12)
    assert res.balls.vel[0, 0] == pytest.approx(v[0], rel=1e-12)
    assert res.balls.vel[0, 1] == pytest.approx(-e_c * v[1], rel=1e-12)


def _after_first_wall(table, pos, vel, law=None):
    phys = law or Physics(friction="rolling", mu_roll=0.0)
    b = balls([list(pos)], velocities=[list(vel)])
    sim = Simulator(table, phys, max_events=1)
    res = sim.run(b)
    assert res.events.kind[0] == EV_CUSHION
    return res


def test_a_jaw_face_reflects_about_its_own_normal():
    table = jaw_table(POOLTOOL_7FT, 1.0)
    segs, _ = table.walls()
    face = segs[N_RAILS + 0]  # the bottom-left corner's jaw on the bottom rail
    mid = 0.5 * (face[0:2] + face[2:4])
    n = face[4:6]
    v = -n * 1.0 + 0.3 * np.array([-n[1], n[0]])
    start = mid + R * n - v * 0.03  # reaches the face's middle after 0.03 s
    res = _after_first_wall(table, start, v)
    assert res.events.other[0] == N_RAILS + 0
    assert res.events.time[0] == pytest.approx(0.03, rel=1e-9)
    vel = res.balls.vel[0]
    expected = v - 2.0 * (v @ n) * n
    assert np.allclose(vel, expected, atol=1e-12)


def test_a_tip_is_met_at_its_radius_plus_the_balls_and_pushes_along_the_line_of_centres():
    table = jaw_table(POOLTOOL_7FT, 1.0)
    segs, tips = table.walls()
    cx, cy, rad = tips[2]  # the middle pocket's left tip
    n = np.array([math.cos(1.1), math.sin(1.1)])  # a contact normal pointing into the table
    contact = np.array([cx, cy]) + (R + rad) * n
    v = np.array([0.2, -1.0])
    res = _after_first_wall(table, contact - v * 0.05, v)
    assert res.events.other[0] == N_SEGMENTS + 2
    assert res.events.time[0] == pytest.approx(0.05, rel=1e-9)
    assert np.allclose(res.balls.pos[0], contact, atol=1e-12)
    assert np.allclose(res.balls.vel[0], v - 2.0 * (v @ n) * n, atol=1e-12)


@pytest.mark.parametrize("physics", [rolling(), Physics(friction="drag", drag_k=0.3, min_speed=0.01),
                                     Physics.from_preset("pooltool")], ids=["rolling", "drag", "spin"])
def test_random_shots_on_jaw_tables_keep_every_ball_clear_of_the_walls_and_lose_energy(physics):
    rng = np.random.default_rng(5)
    for specs in (POOLTOOL_7FT, SNOOKER_12FT):
        table = jaw_table(specs)
        segs, tips = table.walls()
        sim = Simulator(table, physics)
        for _ in range(60):
            pos = []
            while len(pos) < 4:
                p = (rng.uniform(R, specs.l - R), rng.uniform(R, specs.w - R))
                if all(math.dist(p, q) > 2 * R + 1e-6 for q in pos):
                    pos.append(p)
            b = balls(pos).strike("cue", rng.uniform(-math.pi, math.pi), rng.uniform(0.5, 6.0), physics=physics)
            res = sim.run(b)
            assert res.status == "rest"
            for i in np.flatnonzero(res.balls.on_table):
                x, y = res.balls.pos[i]
                for ax, ay, bx, by, nx, ny in segs:
                    s = ((x - ax) * (bx - ax) + (y - ay) * (by - ay)) / ((bx - ax) ** 2 + (by - ay) ** 2)
                    gap = (x - ax) * nx + (y - ay) * ny
                    if 0 <= s <= 1 and gap > -R:
                        assert gap >= R - 1e-9
                for tx, ty, tr in tips:
                    assert math.hypot(x - tx, y - ty) >= R + tr - 1e-9
            again = sim.run(b)  # the same input, bit for bit the same output
            assert np.array_equal(again.balls.pos, res.balls.pos)


@pytest.mark.parametrize("physics", [rolling(), Physics(friction="drag", drag_k=0.3, min_speed=0.01),
                                     Physics.from_preset("pooltool")], ids=["rolling", "drag", "spin"])
@pytest.mark.parametrize("contact", ["lecture", "rewind"])
def test_random_step_shots_on_jaw_tables_stay_clear_of_the_walls_and_repeat_bit_for_bit(physics, contact):
    rng = np.random.default_rng(8)
    for specs in (POOLTOOL_7FT, SNOOKER_12FT):
        table = jaw_table(specs)
        segs, tips = table.walls()
        sim = Simulator(table, physics, solver="step", dt=1e-3, contact=contact)
        for _ in range(8):
            pos = []
            while len(pos) < 4:
                p = (rng.uniform(R, specs.l - R), rng.uniform(R, specs.w - R))
                if all(math.dist(p, q) > 2 * R + 1e-6 for q in pos) and wall_overlaps(segs, tips, *p, R)[0] < 0:
                    pos.append(p)
            b = balls(pos).strike("cue", rng.uniform(-math.pi, math.pi), rng.uniform(0.5, 6.0), physics=physics)
            res = sim.run(b)
            assert res.status == "rest"
            on = res.balls.on_table
            assert np.all(wall_overlaps(segs, tips, res.balls.pos[on, 0], res.balls.pos[on, 1], R)[0] <= 1e-9)
            again = sim.run(b)
            assert np.array_equal(again.balls.pos, res.balls.pos) and np.array_equal(again.pocket, res.pocket)


def test_a_ball_may_rest_in_a_mouth_and_stays_there():
    table = jaw_table(POOLTOOL_7FT)
    y = -0.002  # the centre behind the cushion line, in the middle pocket's mouth, outside its pocket circle
    res = _run(table, rolling(), [(POOLTOOL_7FT.l / 2, y), (0.5, 0.5)], [(0.0, 0.0), (0.0, 0.0)])
    assert res.balls.on_table[0] and np.array_equal(res.balls.pos[0], [POOLTOOL_7FT.l / 2, y])


def test_a_ball_inside_a_rail_is_refused_with_the_mouths_named():
    with pytest.raises(SceneError, match="mouth"):
        _run(jaw_table(POOLTOOL_7FT), rolling(), [(0.5, -0.01)], [(0.0, 0.0)])


SPIN = Physics(friction="spin")


def _final(table, physics, pos, vel, **solver):
    b = balls([list(p) for p in pos], velocities=[list(v) for v in vel])
    return Simulator(table, physics, **solver).run(b)


@pytest.mark.parametrize("physics", [rolling(), SPIN], ids=["rolling", "spin"])
@pytest.mark.parametrize("contact", ["lecture", "rewind"])
def test_the_step_solver_converges_to_the_exact_one_off_a_side_tip(physics, contact):
    # Along the bottom rail, drifting into the middle pocket's mouth: it meets the mouth's far tip (wall
    # N_SEGMENTS + 3) and ends on the table.
    table = jaw_table(POOLTOOL_7FT)
    pos, vel = [(0.75, R + 0.001)], [(0.5, -0.002)]
    exact = _final(table, physics, pos, vel)
    assert exact.pocket[0] == -1 and N_SEGMENTS + 3 in exact.events.other[exact.events.kind == EV_CUSHION]
    err = []
    for dt in (1e-3, 1e-4, 1e-5):
        step = _final(table, physics, pos, vel, solver="step", dt=dt, contact=contact)
        assert step.status == "rest" and step.pocket[0] == -1
        assert N_SEGMENTS + 3 in step.events.other[step.events.kind == EV_CUSHION]
        err.append(float(np.hypot(*(step.balls.pos[0] - exact.balls.pos[0]))))
    assert err[1] < 2e-3 and err[2] < 0.5 * err[1] and err[2] < 2e-4  # m: a few mm at 1e-4, closer as dt shrinks


@pytest.mark.parametrize("physics,angle,wall", [(rolling(), 3.67915, N_SEGMENTS + 1), (SPIN, 3.68264, N_SEGMENTS + 1),
                                                (rolling(), 3.69486, N_RAILS + 1), (SPIN, 3.69486, N_RAILS + 1)],
                         ids=["rolling-tip", "spin-tip", "rolling-jaw", "spin-jaw"])
@pytest.mark.parametrize("contact", ["lecture", "rewind"])
def test_the_step_solver_pots_off_a_jaw_as_the_exact_one(physics, angle, wall, contact):
    # Into the bottom-left corner off its tip or jaw face on the left rail's side (exact: one wall, then the pocket).
    table = jaw_table(POOLTOOL_7FT)
    pos, vel = [(0.5, 0.35)], [(1.5 * math.cos(angle), 1.5 * math.sin(angle))]
    exact = _final(table, physics, pos, vel)
    assert exact.pocket[0] == 0 and list(exact.events.other[exact.events.kind == EV_CUSHION]) == [wall]
    for dt in (1e-3, 1e-4):
        step = _final(table, physics, pos, vel, solver="step", dt=dt, contact=contact)
        assert step.pocket[0] == 0
        assert list(step.events.other[step.events.kind == EV_CUSHION]) == [wall]
        assert abs(step.pocketed_at[0] - exact.pocketed_at[0]) < 2 * dt + 1e-9


@pytest.mark.parametrize("physics", [rolling(), SPIN], ids=["rolling", "spin"])
@pytest.mark.parametrize("specs", SPECS, ids=["pooltool", "wpa", "snooker"])
def test_straightforward_pots_go_to_the_same_pocket_in_both_solvers(physics, specs):
    table = jaw_table(specs)
    rng = np.random.default_rng(11)
    for p in range(6):
        # From a point of the table towards the pocket circle's centre, the jaws untouched.
        # From the pocket's axis (a corner's diagonal, a side pocket's normal), within a degree of it.
        px, py = table.pocket_xy[p]
        axis = np.array([0.0 if p in (1, 4) else (1.0 if px < specs.l / 2 else -1.0), 1.0 if py < 0 else -1.0])
        turn = math.radians(rng.uniform(-1.0, 1.0))
        c, s_ = math.cos(turn), math.sin(turn)
        d = np.array([c * axis[0] - s_ * axis[1], s_ * axis[0] + c * axis[1]]) / np.linalg.norm(axis)
        start = table.pocket_xy[p] + rng.uniform(0.3, 0.8) * specs.w * d
        d = table.pocket_xy[p] - start
        v = 2.0 * d / np.linalg.norm(d)
        exact = _final(table, physics, [start], [v])
        assert exact.pocket[0] == p
        for contact in ("lecture", "rewind"):
            step = _final(table, physics, [start], [v], solver="step", dt=1e-3, contact=contact)
            assert step.pocket[0] == p


@pytest.mark.parametrize("specs,dx,y", [(POOLTOOL_7FT, 0.01, -0.002), (SNOOKER_12FT, 0.02, SNOOKER_12FT.w + 0.0005)],
                         ids=["pooltool", "snooker"])
@pytest.mark.parametrize("contact", ["lecture", "rewind"])
def test_the_step_solver_keeps_a_ball_in_a_mouth_where_it_is(specs, dx, y, contact):
    # Snooker's side jaws round off deeper than their faces reach (pooltool's table): its mouth is their hull.
    table = jaw_table(specs)
    res = _final(table, rolling(), [(specs.l / 2 + dx, y), (0.5, 0.5)], [(0.0, 0.0), (1.0, 0.3)], solver="step",
                 contact=contact)
    assert res.balls.on_table[0] and np.array_equal(res.balls.pos[0], [specs.l / 2 + dx, y])


@pytest.mark.parametrize("field,value,match", [
    ("l", -1.0, "table.specs.l: must be > 0"),
    ("w", 0.0, "table.specs.w: must be > 0"),
    ("corner_pocket_angle", 50.0, r"corner_pocket_angle: 50.0 degrees is outside \(-45, 45\)"),
    ("side_jaw_radius", 0.5, "side_jaw_radius: 0.5 m does not fit a side mouth of 0.137 m"),
    ("corner_pocket_radius", 0.005, "corner_pocket_radius: .* cannot be reached"),
    ("side_pocket_width", 1.8, "long rails have no length"),
])
def test_specs_that_make_no_table_are_refused_naming_the_field(field, value, match):
    with pytest.raises(SceneError, match=match):
        PocketSpecs(**{field: value})


def test_a_table_whose_pocket_circle_misses_a_throats_exit_is_refused_for_its_balls():
    # A wide corner mouth with pooltool's circle: a ball could leave the throat past the jaws' deep ends and run off
    # the table (the jaw fuzz found one at x = -2.1 m).
    table = parse_table({"preset": "wpa", "specs": {"corner_pocket_width": 0.144, "corner_pocket_angle": 0.6,
                                                    "corner_pocket_depth": 0.0498}})
    with pytest.raises(SceneError, match="corner_pocket_radius at least"):
        _run(table, rolling(), [(0.5, 0.5)], [(0.0, 0.0)])
    assert throat_leak(table.specs, R) is not None
    for specs in SPECS:
        assert throat_leak(specs, R) is None and throat_leak(specs, 0.02625) is None


def test_an_unknown_spec_field_is_refused_with_a_did_you_mean():
    with pytest.raises(SceneError, match="unknown field 'corner_pocket_widht'; did you mean 'corner_pocket_width'"):
        parse_table({"specs": {"corner_pocket_widht": 0.12}})


def test_scene_tables_with_jaws_and_capture_circles():
    wpa = parse_table({"preset": "wpa"})
    assert wpa.has_jaws and wpa.specs == WPA_9FT
    # The WPA table under the capture model: the default table's calibrated circles (same mouths, same balls).
    cap = parse_table({"preset": "wpa", "pockets": "capture"})
    assert not cap.has_jaws
    assert cap.pocket_radius[0] == pytest.approx(CORNER_POCKET_RADIUS, abs=2e-4)
    assert cap.pocket_radius[1] == pytest.approx(SIDE_POCKET_RADIUS, abs=2e-4)
    own = parse_table({"specs": {"l": 2.84, "w": 1.42, "side_pocket_width": 0.14}})
    assert own.has_jaws and own.length == 2.84 and own.specs.corner_pocket_width == POOLTOOL_7FT.corner_pocket_width
    with pytest.raises(SceneError, match="'jaws' needs the table's geometry"):
        parse_table({"pockets": "jaws"})
    with pytest.raises(SceneError, match="unknown pocket model 'jaw'"):
        parse_table({"preset": "wpa", "pockets": "jaw"})


def test_a_steep_side_pot_the_capture_circle_offers_is_no_window_through_the_jaws():
    from billiards_env.physics.aim import pocket_window

    jaws = jaw_table(WPA_9FT)
    capture = parse_table({"preset": "wpa", "pockets": "capture"})
    obj = (WPA_9FT.l / 2 - 0.45, 0.08)  # low along the rail: the middle pocket seen nearly edge-on
    assert pocket_window(obj, R, capture, 1) is not None
    assert pocket_window(obj, R, jaws, 1) is None


@pytest.mark.parametrize("obj,pocket", [((0.6, 0.4), 0), ((1.1, 0.5), 1), ((2.2, 1.0), 5), ((1.05, 0.3), 1)])
def test_every_direction_of_a_jaw_window_drops_the_ball_in_the_engine(obj, pocket):
    from billiards_env.physics.aim import pocket_window

    table = jaw_table(WPA_9FT)
    win = pocket_window(obj, R, table, pocket)
    assert win is not None
    centre, half, _ = win
    sim = Simulator(table, rolling())
    for a in np.linspace(centre - 0.9 * half, centre + 0.9 * half, 7):
        res = sim.run(balls([list(obj)]).strike("cue", float(a), 2.0))
        assert res.pocket[0] == pocket


def test_the_batch_api_plays_a_jaw_table_as_the_simulator_does():
    from billiards_env.physics.batch import run_shots

    sim = Simulator(parse_table({"preset": "wpa"}), rolling())
    b = balls([[0.5, 0.5], [0.3, 0.3]])
    angles = np.linspace(-3.0, 3.0, 48)
    res = run_shots(sim, b, angles, np.full(len(angles), 2.0))
    single = np.array([sim.run(b.strike(0, float(a), 2.0)).balls.pos for a in angles])
    assert res.pocketed.any()
    assert np.array_equal(single, res.pos)
