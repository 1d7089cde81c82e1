"""The spin model's ``exact`` solver against closed-form results (stun, natural roll, draw, side spin, a sliding
ball's parabola), the mirror symmetry, conservation at every event, determinism, and ``step -> exact``.

Every expected value is computed here from the equations of motion and the collision laws, never from a run."""
from __future__ import annotations

import math

import numpy as np
import pytest

from billiards_env.physics import Balls, SceneError, Simulator
from billiards_env.physics.codes import (EV_COLLISION, EV_CUSHION, EV_ROLL, EV_SPIN, EV_STOP, MS_ROLLING, MS_SLIDING,
                                         MS_SPINNING, MS_STATIONARY)
from billiards_env.physics.layout import rack_balls
from spin_helpers import (ALPHA, F_ROLL, F_SLIDE, M, R, energy_of, event_states, long_table, mirror_balls, run,
                          slide_time, sliding_position, spin_physics)

TOL = 1e-9


def test_stun_shot_slides_then_rolls_at_five_sevenths():
    v0 = 2.0
    x0 = 1.0
    b = Balls.from_positions([[x0, 0.6]]).strike("cue", 0.0, v0)
    res = run(long_table(), spin_physics(), b)
    ev = res.events
    assert list(ev.kind) == [EV_ROLL, EV_STOP]
    t_s = 2 * v0 / (7 * F_SLIDE)
    assert ev.time[0] == pytest.approx(0.29124799767, abs=1e-10) and abs(ev.time[0] - t_s) <= 1e-12
    st, _, code = res.trajectory.sample_states([t_s])
    slid = v0 * t_s - 0.5 * F_SLIDE * t_s ** 2
    assert slid == pytest.approx(0.4993, abs=1e-4)
    assert abs(st[0, 0, 0] - (x0 + slid)) <= TOL
    assert abs(st[0, 0, 2] - 10 / 7) <= TOL  # 5/7 of 2 m/s
    assert abs(st[0, 0, 5] - (10 / 7) / R) <= 1e-7  # rolling: wy = v / R
    assert code[0, 0] == MS_ROLLING
    # Then it rolls to a stop: v^2 / (2 mu_roll g) further, after v / (mu_roll g).
    assert abs(ev.time[1] - (t_s + (10 / 7) / F_ROLL)) <= TOL
    assert abs(res.balls.pos[0, 0] - (x0 + slid + (10 / 7) ** 2 / (2 * F_ROLL))) <= TOL
    # Mid-slide: v = v0 - mu g t, wy = 5 mu g t / 2R.
    t = 0.1
    st, _, code = res.trajectory.sample_states([t])
    assert code[0, 0] == MS_SLIDING
    np.testing.assert_allclose(st[0, 0, 2:7], [v0 - F_SLIDE * t, 0, 0, 2.5 * F_SLIDE * t / R, 0], atol=1e-9)


@pytest.mark.parametrize("angle", [0.0, 1.1, -2.3])
def test_natural_roll_has_no_sliding_phase(angle):
    v0 = 1.0
    b = Balls.from_positions([[10.0, 10.0]]).strike("cue", angle, v0, top=0.4)
    res = run(long_table(width=20.0), spin_physics(), b)
    assert list(res.events.kind) == [EV_STOP]
    assert abs(res.time - v0 / F_ROLL) <= TOL
    d = v0 ** 2 / (2 * F_ROLL)
    np.testing.assert_allclose(res.balls.pos[0], [10.0 + d * math.cos(angle), 10.0 + d * math.sin(angle)], atol=TOL)
    _, _, code = res.trajectory.sample_states([0.5, 3.0])
    assert (code == MS_ROLLING).all()


def test_draw_shot_into_a_full_ball_comes_back_by_the_closed_form_distance():
    v0, b_top, e = 2.0, -0.4, 0.95
    x_cue, gap = 1.0, 0.2  # the cue ball travels `gap` before it touches the object ball
    table = long_table()
    balls = Balls.from_positions([[x_cue, 0.6], [x_cue + gap + 2 * R, 0.6]]).strike("cue", 0.0, v0, top=b_top)
    res = run(table, spin_physics(ball_restitution=e), balls)
    # Closed form. Before the hit the cue ball slides: u = v - R wy along +x, a = -f.
    wy0 = 5 * b_top * v0 / (2 * R)
    u0 = v0 - R * wy0
    t_hit = (v0 - math.sqrt(v0 ** 2 - 2 * F_SLIDE * gap)) / F_SLIDE
    assert t_hit < slide_time([u0, 0])
    v_hit = v0 - F_SLIDE * t_hit
    wy_hit = wy0 + 2.5 * F_SLIDE * t_hit / R
    assert abs(res.events.time[0] - t_hit) <= 1e-12 and res.events.kind[0] == EV_COLLISION
    # The 1-D restitution law (equal masses); spins unchanged.
    v_cue = (1 - e) / 2 * v_hit
    v_obj = (1 + e) / 2 * v_hit
    # The cue ball: slip u = v_cue - R wy_hit > 0 (back spin left): friction pulls it back (towards -x).
    u = v_cue - R * wy_hit
    assert u > 0
    t_s = 2 * u / (7 * F_SLIDE)
    x_after_slide = v_cue * t_s - 0.5 * F_SLIDE * t_s ** 2
    v_roll = v_cue - F_SLIDE * t_s
    assert v_roll < 0  # it comes back
    back = x_after_slide - v_roll ** 2 / (2 * F_ROLL)
    x_contact = x_cue + gap
    assert abs(res.balls.pos[0, 0] - (x_contact + back)) <= TOL
    assert back < -0.5  # a real draw: well over half a metre
    # The object ball: stun (no spin), slides to 5/7 then rolls.
    t_o = 2 * v_obj / (7 * F_SLIDE)
    x_o = v_obj * t_o - 0.5 * F_SLIDE * t_o ** 2 + (5 / 7 * v_obj) ** 2 / (2 * F_ROLL)
    assert abs(res.balls.pos[1, 0] - (x_contact + 2 * R + x_o)) <= TOL


def test_side_spin_leaves_the_path_alone_and_decays_at_its_rate():
    v0 = 1.2
    plain = Balls.from_positions([[5.0, 0.635]]).strike("cue", 0.3, v0, top=0.1)
    side = Balls.from_positions([[5.0, 0.635]]).strike("cue", 0.3, v0, side=0.45, top=0.1)
    phys = spin_physics()
    a = run(long_table(width=20.0), phys, plain)
    b = run(long_table(width=20.0), phys, side)
    ts = np.linspace(0.0, 6.0, 13)
    sa, _, _ = a.trajectory.sample_states(ts)
    sb, _, code = b.trajectory.sample_states(ts)
    np.testing.assert_allclose(sb[:, 0, :6], sa[:, 0, :6], rtol=0, atol=1e-12)
    wz0 = 5 * 0.45 * v0 / (2 * R)
    np.testing.assert_allclose(sb[:, 0, 6], np.maximum(wz0 - ALPHA * ts, 0.0), rtol=0, atol=1e-9)
    # The spin is gone before the ball stops (no event then): the same events as without side spin.
    assert wz0 / ALPHA < a.time
    assert list(b.events.kind) == list(a.events.kind) and np.array_equal(b.events.time, a.events.time)
    assert abs(ALPHA - 5 * 0.0127 * 9.81 / (2 * R)) < 1e-12 and 10.8 < ALPHA < 11.0


def test_stun_with_side_into_a_full_ball_leaves_the_cue_ball_spinning_in_place():
    # A stun hit (no slip left at impact is not needed: e = 1 stops the cue ball dead) keeps the side spin.
    v0 = 2.0
    balls = Balls.from_positions([[1.0, 0.6], [1.0 + 2 * R + 1e-3, 0.6]]).strike("cue", 0.0, v0, side=0.4)
    res = run(long_table(), spin_physics(ball_restitution=1.0), balls)
    t_hit = res.events.time[0]
    assert res.events.kind[0] == EV_COLLISION
    cue_events = [(float(t), int(k)) for t, k, b in zip(res.events.time, res.events.kind, res.events.ball) if b == 0]
    # After the hit the cue ball has v = 0 and w = (0, wy, wz): it slides (wy from the slide), then rolls a little,
    # then spins in place, then rests when wz reaches 0.
    wz0 = 5 * 0.4 * v0 / (2 * R)
    assert cue_events[-1][1] == EV_STOP and abs(cue_events[-1][0] - wz0 / ALPHA) <= TOL
    assert EV_SPIN in [k for _, k in cue_events]
    t_spin = next(t for t, k in cue_events if k == EV_SPIN)
    _, _, code = res.trajectory.sample_states([0.5 * (t_spin + wz0 / ALPHA)])
    assert code[0, 0] == MS_SPINNING and t_hit < t_spin


def test_spinning_ball_at_rest_stops_at_its_closed_form_time():
    b = Balls.from_positions([[1.0, 0.6]], spins=[[0.0, 0.0, -30.0]])
    res = run(long_table(), spin_physics(), b)
    assert list(res.events.kind) == [EV_STOP]
    assert abs(res.time - 30.0 / ALPHA) <= TOL
    assert res.balls.pos[0].tolist() == [1.0, 0.6]
    _, _, code = res.trajectory.sample_states([0.0, res.time])
    assert code[0].tolist() == [MS_SPINNING] and code[1].tolist() == [MS_STATIONARY]


def test_sliding_ball_with_lateral_slip_follows_its_parabola():
    x0 = np.array([5.0, 5.0])
    v0 = np.array([1.0, 0.2])
    w0 = np.array([25.0, -10.0, 3.0])
    b = Balls.from_positions([x0], velocities=[v0], spins=[w0])
    res = run(long_table(width=20.0), spin_physics(), b)
    u0 = np.array([v0[0] - R * w0[1], v0[1] + R * w0[0]])
    t_s = slide_time(u0)
    assert res.events.kind[0] == EV_ROLL and abs(res.events.time[0] - t_s) <= 1e-12
    ts = np.linspace(0.0, t_s, 9)
    st, _, _ = res.trajectory.sample_states(ts)
    expected = np.array([sliding_position(x0, v0, u0, t) for t in ts])
    np.testing.assert_allclose(st[:, 0, :2], expected, rtol=0, atol=1e-12)
    # It is a real curve: the path is off the straight line through its ends.
    chord = expected[-1] - expected[0]
    mid = expected[4] - expected[0]
    assert abs(chord[0] * mid[1] - chord[1] * mid[0]) / np.linalg.norm(chord) > 1e-3
    pos, on = res.trajectory.sample(ts)
    np.testing.assert_allclose(pos[:, 0], expected, rtol=0, atol=1e-12)


def _spin_scene():
    """Cue ball with draw and english into a ball near a cushion, and a third ball: collisions, cushions, throw."""
    balls = Balls.from_positions([[0.7, 0.45], [1.6, 0.62], [2.2, 0.3]])
    return balls.strike("cue", 0.21, 3.0, side=0.3, top=-0.25)


@pytest.mark.parametrize("ball_friction", [0.0, 0.06])
def test_mirrored_shot_gives_the_mirrored_result(ball_friction):
    from billiards_env.physics import Table
    table = Table().without_pockets()
    phys = spin_physics(ball_friction=ball_friction)
    b = _spin_scene()
    mb = mirror_balls(b, table.width)
    # The mirrored shot: angle -> -angle, side -> -side (top unchanged).
    assert mb.ang[0].tolist() == pytest.approx(
        Balls.from_positions([[0.7, table.width - 0.45]]).strike("cue", -0.21, 3.0, side=-0.3, top=-0.25).ang[0]
        .tolist())
    r1 = run(table, phys, b)
    r2 = run(table, phys, mb)
    assert r1.n_events == r2.n_events and r1.n_events > 8
    assert list(r1.events.kind) == list(r2.events.kind)
    assert sum(r1.events.kind == EV_COLLISION) >= 1 and sum(r1.events.kind == EV_CUSHION) >= 2
    np.testing.assert_allclose(r1.events.time, r2.events.time, rtol=0, atol=1e-9)
    m = mirror_balls(r1.balls, table.width)
    np.testing.assert_allclose(r2.balls.pos, m.pos, rtol=0, atol=1e-9)


@pytest.mark.parametrize("ball_friction,e_ball", [(0.0, 0.95), (0.06, 0.95), (0.3, 0.5)])
def test_energy_never_rises_and_momentum_is_conserved_at_every_event(ball_friction, e_ball):
    from billiards_env.physics import Table
    phys = spin_physics(ball_friction=ball_friction, ball_restitution=e_ball)
    table = Table()
    balls = rack_balls(table).strike("cue", 0.02, 7.0, side=-0.2, top=0.3)
    res = run(table, phys, balls)
    assert res.status == "rest"
    n_coll = 0
    for q, inv, before, after in event_states(res, phys):
        e0 = sum(energy_of(M, R, before[b]) for b in inv)
        e1 = sum(energy_of(M, R, after[b]) for b in inv)
        assert e1 <= e0 + 1e-12 * max(e0, 1e-300), (q, res.events.kind[q], e0, e1)
        if res.events.kind[q] == EV_COLLISION:
            n_coll += 1
            p0 = sum(M * before[b][2:4] for b in inv)
            p1 = sum(M * after[b][2:4] for b in inv)
            np.testing.assert_allclose(p1, p0, rtol=0, atol=1e-12 * (1 + np.abs(p0).max()))
    assert n_coll > 20


def test_same_input_gives_bit_identical_output():
    from billiards_env.physics import Table
    table = Table()
    phys = spin_physics(ball_friction=0.05)
    balls = rack_balls(table).strike("cue", 0.01, 8.0, side=0.2, top=-0.2)
    a = run(table, phys, balls)
    b = run(table, phys, balls)
    assert a.balls.pos.tobytes() == b.balls.pos.tobytes()
    assert a.balls.ang.tobytes() == b.balls.ang.tobytes()
    assert a.events.time.tobytes() == b.events.time.tobytes()
    assert a.events.kind.tolist() == b.events.kind.tolist()


def test_step_converges_to_exact():
    from billiards_env.physics import Table
    table = Table().without_pockets()
    phys = spin_physics()
    balls = _spin_scene()
    ref = run(table, phys, balls, record=False)
    errors = []
    for dt in (1e-3, 1e-4, 1e-5):
        for contact in ("rewind",):
            res = run(table, phys, balls, solver="step", record=False, dt=dt, contact=contact)
            errors.append(float(np.abs(res.balls.pos - ref.balls.pos).max()))
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] < 1e-3


def test_rolling_and_drag_refuse_spin_with_a_clear_error():
    from billiards_env.physics import Physics, Table
    b = Balls.from_positions([[0.5, 0.5]]).strike("cue", 0.0, 2.0, top=0.3)
    for friction in ("rolling", "drag"):
        with pytest.raises(SceneError, match="friction to 'spin'"):
            Simulator(Table(), Physics(friction=friction)).run(b)
    res = Simulator(Table(), Physics(friction="spin")).run(b)
    assert res.status == "rest"
