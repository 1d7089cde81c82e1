"""The spin model's collision laws (cue strike, cushion, ball-ball with throw, pressed contacts) against the spec's
formulas written out independently here with 3-D vector algebra, and against conservation laws: momentum in every
ball-ball law exactly, kinetic energy (translational + rotational, ``I = 2/5 m R^2``) never rising."""
from __future__ import annotations

import math

import numpy as np
import pytest

from billiards_env.physics import Balls, SceneError
from billiards_env.physics.codes import MS_ROLLING, MS_SLIDING
from billiards_env.physics.spin_collide import (MAX_TIP_OFFSET, merge_pair, resolve_ball_ball_spin,
                                                resolve_cushion_spin, settle_on_cushion, strike_spin)
from billiards_env.physics.spin_motion import classify, slip

R = 0.028575
M = 0.17
Z = np.array([0.0, 0.0, 1.0])
NORMALS = {0: (1.0, 0.0), 1: (-1.0, 0.0), 2: (0.0, 1.0), 3: (0.0, -1.0)}  # inward normal of each cushion


def energy(m, r, v, w):
    return 0.5 * m * float(np.dot(v, v)) + 0.2 * m * r * r * float(np.dot(w, w))


# --- cue strike -------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("angle", [0.0, 0.9, -2.4])
def test_strike_natural_roll_has_no_slip_and_stun_slips_with_v(angle):
    v = 2.0
    vx, vy, wx, wy, wz = strike_spin(angle, v, 0.0, 0.4, R)
    assert math.hypot(*slip(vx, vy, wx, wy, R)) < 1e-14
    assert classify(vx, vy, wx, wy, wz, R) == MS_ROLLING
    vx, vy, wx, wy, wz = strike_spin(angle, v, 0.0, 0.0, R)
    assert (wx, wy, wz) == (0.0, 0.0, 0.0)
    assert classify(vx, vy, wx, wy, wz, R) == MS_SLIDING


def test_strike_spin_directions_and_sizes():
    v = 3.0
    # Draw along +x: back spin, wy < 0, of size 5 |b| v / 2R.
    _, _, wx, wy, wz = strike_spin(0.0, v, 0.0, -0.3, R)
    assert wy == pytest.approx(-5 * 0.3 * v / (2 * R)) and wx == pytest.approx(0.0, abs=1e-12) and wz == 0.0
    # Right english spins counter-clockwise seen from above (wz > 0): wz = 5 a v / 2R.
    _, _, _, _, wz = strike_spin(1.0, v, 0.25, 0.0, R)
    assert wz == pytest.approx(5 * 0.25 * v / (2 * R))
    # Follow along +y: the spin axis is -x (z^ x d^ = (-1, 0)).
    _, _, wx, wy, _ = strike_spin(math.pi / 2, v, 0.0, 0.2, R)
    assert wx == pytest.approx(-5 * 0.2 * v / (2 * R)) and abs(wy) < 1e-12


def test_strike_beyond_the_miscue_limit_is_refused_with_the_values_and_limit():
    b = Balls.from_positions([[0.5, 0.5]])
    with pytest.raises(SceneError) as err:
        b.strike("cue", 0.0, 2.0, side=0.4, top=0.35)
    msg = str(err.value)
    assert "0.4" in msg and "0.35" in msg and str(MAX_TIP_OFFSET) in msg and "miscue" in msg
    with pytest.raises(SceneError, match="shot.top"):
        b.strike("cue", 0.0, 2.0, top=float("nan"))
    ok = b.strike("cue", 0.0, 2.0, side=0.3, top=-0.4)  # exactly on the limit: accepted
    assert ok.ang[0, 2] == pytest.approx(5 * 0.3 * 2.0 / (2 * R))


# --- cushion ----------------------------------------------------------------------------------------------------

def cushion_reference(v, w, n2, e, mu):
    """The spec's cushion law in 3-D vectors: impulse at the equator contact point -R n."""
    n = np.array([n2[0], n2[1], 0.0])
    v3 = np.array([v[0], v[1], 0.0])
    vn = v3 @ n
    jn = -(1 + e) * vn
    v_t = v3 - vn * n
    s = v_t + np.cross(w, -R * n)
    size = min(mu * jn, 2.0 / 7.0 * np.linalg.norm(s)) if np.linalg.norm(s) > 0 else 0.0
    j = -size * s / np.linalg.norm(s) if size > 0 else np.zeros(3)
    v_new = v3 + jn * n + j
    w_new = w - 5.0 / (2.0 * R) * np.cross(n, j)
    return v_new[:2], w_new


def random_state(rng, speed=3.0):
    v = rng.normal(size=2) * speed
    w = rng.normal(size=3) * speed / R
    return v, w


@pytest.mark.parametrize("cushion", [0, 1, 2, 3])
def test_cushion_law_matches_the_spec_and_never_adds_energy(cushion):
    rng = np.random.default_rng(cushion)
    n = np.array(NORMALS[cushion])
    for _ in range(300):
        v, w = random_state(rng)
        if v @ n > 0:
            v = v - 2 * (v @ n) * n  # moving into the cushion
        e = rng.uniform(0, 1)
        mu = rng.choice([0.0, rng.uniform(0, 0.3), 5.0])
        vel = v[None, :].copy()
        ang = w[None, :].copy()
        speed = resolve_cushion_spin(vel, ang, 0, cushion, R, e, mu)
        assert speed == pytest.approx(-(v @ n))
        v_ref, w_ref = cushion_reference(v, w, n, e, mu)
        np.testing.assert_allclose(vel[0], v_ref, rtol=0, atol=1e-12 * (1 + np.abs(v).max()))
        np.testing.assert_allclose(ang[0], w_ref, rtol=0, atol=1e-12 * (1 + np.abs(w).max()))
        assert vel[0] @ n == pytest.approx(-e * (v @ n), abs=1e-12)  # normal law
        assert ang[0] @ np.array([n[0], n[1], 0]) == pytest.approx(w @ np.array([n[0], n[1], 0]))  # w along n
        assert energy(M, R, vel[0], ang[0]) <= energy(M, R, v, w) * (1 + 1e-14)


def test_cushion_no_slip_cap_stops_the_in_plane_slip():
    # With ample friction the impulse is the no-slip one: the contact point's slip along the cushion is gone.
    v = np.array([-1.0, 0.7])
    w = np.array([3.0, -20.0, 40.0])
    vel, ang = v[None].copy(), w[None].copy()
    resolve_cushion_spin(vel, ang, 0, 0, R, 0.8, 10.0)  # left cushion, n = +x
    s_y = vel[0, 1] - R * ang[0, 2] * 1.0  # s = v_t + w x (-R n): its y part is vy - R wz nx
    assert abs(s_y) < 1e-12


def test_cushion_moving_away_changes_nothing():
    vel = np.array([[0.5, 0.2]])
    ang = np.array([[1.0, 2.0, 3.0]])
    assert resolve_cushion_spin(vel, ang, 0, 0, R, 0.85, 0.2) == 0.0
    assert vel.tolist() == [[0.5, 0.2]] and ang.tolist() == [[1.0, 2.0, 3.0]]


def test_settle_on_cushion_removes_the_normal_slip_and_energy():
    vel = np.array([[2e-4, 0.4]])
    ang = np.array([[-14.0, -30.0, 5.0]])  # slip x: vx - R wy > 0: friction drives it into the left cushion
    e0 = energy(M, R, vel[0], ang[0])
    settle_on_cushion(vel, ang, 0, 0)
    ux, _ = slip(vel[0, 0], vel[0, 1], ang[0, 0], ang[0, 1], R)
    assert ux == 0.0 and vel[0, 0] == 0.0
    assert energy(M, R, vel[0], ang[0]) <= e0


# --- ball-ball --------------------------------------------------------------------------------------------------

def ball_ball_reference(v1, w1, v2, w2, n2, m1, m2, r1, r2, e, mu):
    """The spec's ball-ball law in 3-D vectors (normal n from ball 2 to ball 1)."""
    n = np.array([n2[0], n2[1], 0.0])
    v1 = np.array([*v1, 0.0])
    v2 = np.array([*v2, 0.0])
    v_close = -((v1 - v2) @ n)
    jn = m1 * m2 / (m1 + m2) * (1 + e) * v_close
    rel = v1 - v2
    s = rel - (rel @ n) * n + np.cross(w1, -r1 * n) - np.cross(w2, r2 * n)
    p = np.zeros(3)
    if mu > 0 and np.linalg.norm(s) > 0:
        size = min(mu * jn, 2.0 / 7.0 * np.linalg.norm(s) / (1 / m1 + 1 / m2))
        p = -size * s / np.linalg.norm(s)
    v1n = v1 + jn / m1 * n + p / m1
    v2n = v2 - jn / m2 * n - p / m2
    w1n = w1 + np.cross(-r1 * n, p) / (0.4 * m1 * r1 * r1)
    w2n = w2 + np.cross(r2 * n, -p) / (0.4 * m2 * r2 * r2)
    return v1n[:2], w1n, v2n[:2], w2n


def test_ball_ball_law_matches_the_spec_conserves_momentum_and_never_adds_energy():
    rng = np.random.default_rng(5)
    for _ in range(500):
        m1, m2 = rng.uniform(0.1, 0.3, size=2)
        r1, r2 = rng.uniform(0.02, 0.04, size=2)
        phi = rng.uniform(0, 2 * math.pi)
        n = np.array([math.cos(phi), math.sin(phi)])
        v1, w1 = random_state(rng)
        v2, w2 = random_state(rng)
        if (v1 - v2) @ n > 0:
            v1, v2 = v2, v1
        e = rng.uniform(0, 1)
        mu = rng.choice([0.0, rng.uniform(0, 0.2), 10.0])
        vel = np.array([v1, v2])
        ang = np.array([w1, w2])
        speed = resolve_ball_ball_spin(vel, ang, 0, 1, n[0], n[1], m1, m2, r1, r2, e, mu, 0.0, False)
        assert speed == pytest.approx(-((v1 - v2) @ n))
        ref = ball_ball_reference(v1, w1, v2, w2, n, m1, m2, r1, r2, e, mu)
        scale = 1 + np.abs(np.r_[v1, v2]).max()
        np.testing.assert_allclose(vel[0], ref[0], rtol=0, atol=1e-12 * scale)
        np.testing.assert_allclose(vel[1], ref[2], rtol=0, atol=1e-12 * scale)
        np.testing.assert_allclose(ang[0], ref[1], rtol=0, atol=1e-10 * scale / R)
        np.testing.assert_allclose(ang[1], ref[3], rtol=0, atol=1e-10 * scale / R)
        p0 = m1 * v1 + m2 * v2
        np.testing.assert_allclose(m1 * vel[0] + m2 * vel[1], p0, rtol=0, atol=1e-14 * scale)
        e0 = energy(m1, r1, v1, w1) + energy(m2, r2, v2, w2)
        e1 = energy(m1, r1, vel[0], ang[0]) + energy(m2, r2, vel[1], ang[1])
        assert e1 <= e0 * (1 + 1e-14)


def test_frictionless_ball_ball_keeps_spins_and_tangential_velocities():
    vel = np.array([[2.0, 0.5], [0.0, 0.0]])
    ang = np.array([[1.0, -40.0, 30.0], [0.0, 0.0, 0.0]])
    resolve_ball_ball_spin(vel, ang, 0, 1, -1.0, 0.0, M, M, R, R, 1.0, 0.0, 0.0, False)
    assert ang.tolist() == [[1.0, -40.0, 30.0], [0.0, 0.0, 0.0]]
    assert vel[0].tolist() == [0.0, 0.5] and vel[1].tolist() == [2.0, 0.0]


def test_cut_shot_throws_the_object_ball_by_mu_times_the_normal_impulse():
    # A stun (spin-less) cue ball hits the object ball at a cut: with ball friction the object ball gains a
    # tangential velocity along the cue ball's tangential one (cut-induced throw), mu_b J_n / m in the slip regime.
    v = 2.0
    cut = math.radians(30)
    n = np.array([-math.cos(cut), -math.sin(cut)])  # from the object ball (1) to the cue ball (0)
    vel = np.array([[v, 0.0], [0.0, 0.0]])
    ang = np.zeros((2, 3))
    mu_b, e = 0.06, 0.95
    resolve_ball_ball_spin(vel, ang, 0, 1, n[0], n[1], M, M, R, R, e, mu_b, 0.0, False)
    t = np.array([-n[1], n[0]])
    v_close = -(np.array([v, 0.0]) @ n)
    jn_per_m = 0.5 * (1 + e) * v_close
    assert vel[1] @ t == pytest.approx(mu_b * jn_per_m * np.sign(np.array([v, 0.0]) @ t), rel=1e-12)
    # Throw angle: the object ball leaves off the line of centres by atan(mu_b J_n / J_n) = atan(mu_b).
    off = math.atan2(abs(vel[1] @ t), vel[1] @ -n)
    assert off == pytest.approx(math.atan(mu_b), rel=1e-12)
    # Both balls pick up spin (the friction torque), with the same wz (equal masses and radii).
    assert ang[0, 2] == pytest.approx(ang[1, 2]) and ang[0, 2] != 0.0


def test_pressed_pair_merge_conserves_momentum_and_never_adds_energy():
    rng = np.random.default_rng(2)
    for _ in range(200):
        m1, m2 = rng.uniform(0.1, 0.3, size=2)
        r1, r2 = rng.uniform(0.02, 0.04, size=2)
        vel = rng.normal(size=(2, 2))
        ang = rng.normal(size=(2, 3)) * 30
        p0 = m1 * vel[0] + m2 * vel[1]
        e0 = energy(m1, r1, vel[0], ang[0]) + energy(m2, r2, vel[1], ang[1])
        w_z = ang[:, 2].copy()
        merge_pair(vel, ang, 0, 1, m1, m2, r1, r2)
        np.testing.assert_allclose(m1 * vel[0] + m2 * vel[1], p0, rtol=1e-14, atol=1e-15)
        assert energy(m1, r1, vel[0], ang[0]) + energy(m2, r2, vel[1], ang[1]) <= e0 * (1 + 1e-14)
        # Identical motion: same velocity and the same slip, so the same acceleration.
        assert vel[0].tolist() == vel[1].tolist()
        np.testing.assert_allclose(slip(*vel[0], ang[0, 0], ang[0, 1], r1), slip(*vel[1], ang[1, 0], ang[1, 1], r2),
                                   rtol=1e-14, atol=1e-15)
        assert ang[:, 2].tolist() == w_z.tolist()
