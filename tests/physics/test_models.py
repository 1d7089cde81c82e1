"""The spin model's optional collision models against closed forms: Alciatore's throw (TP A-14) against cut angle and
speed, throw cancelled by gearing english; Stronge's compliant cushion (a square hit at the ball's rest height, the
gross-slip closed form, continuity across its regimes, energy); a raised cushion nose; the squirt angle (TP A-31);
and the ``pooltool`` preset and the scene fields (explicit fields override it, unknown values refused)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from numba import njit

from billiards_env.physics import Balls, Physics, SceneError, Simulator, Table
from billiards_env.physics.batch import run_shots
from billiards_env.physics.kernel_io import kernel_params
from billiards_env.physics.model import POOLTOOL_CUE_END_MASS, PRESETS
from billiards_env.physics.scene import Scene, parse_physics
from billiards_env.physics.spin_collide import resolve_ball_ball_alciatore, squirt_angle
from billiards_env.physics.stronge import BETA, compliant_impact
from billiards_env.physics.cushion_models import cushion_hit

R = 0.028575
M = 0.17
A, B, C = 0.009951, 0.108, 1.088  # Alciatore's fit, TP A-14 (pooltool's defaults)


def alciatore_throw(cut: float, speed: float, e: float = 1.0) -> float:
    """TP A-14's throw angle of a stun cut shot (cue ball sliding without spin at impact): the object ball leaves
    ``atan(min(mu v cos(cut), v sin(cut) / 7) / (v cos(cut)))`` off the line of centres, ``mu = a + b exp(-c v_rel)``
    of the contact points' slip speed ``v_rel = v sin(cut)``; with restitution ``e`` (pooltool's law) the Coulomb
    limit scales with the separation speed ``e v cos(cut)`` and the normal speed is ``(1 + e) / 2 v cos(cut)``."""
    vn, vt = speed * math.cos(cut), speed * math.sin(cut)
    mu = A + B * math.exp(-C * vt)
    return math.atan(min(mu * e * vn, vt / 7.0) / ((1.0 + e) / 2.0 * vn))


def _collide(cut: float, speed: float, e: float, wz_cue: float = 0.0):
    """Cue ball (row 1, spin ``wz_cue``) into a resting object ball (row 0) at cut angle ``cut``: the velocities
    after the alciatore law, normal ``n`` from the cue ball to the object ball = +x."""
    vel = np.array([[0.0, 0.0], [speed * math.cos(cut), speed * math.sin(cut)]])
    ang = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, wz_cue]])
    # n from j (cue, row 1) to i (object, row 0): the object ball is at +x of the cue ball.
    resolve_ball_ball_alciatore(vel, ang, 0, 1, 1.0, 0.0, M, M, R, R, e, A, B, C, 1e-3, False)
    return vel, ang


@pytest.mark.parametrize("speed", [0.5, 1.0, 2.0, 4.0])
@pytest.mark.parametrize("cut_deg", [5, 15, 30, 45, 60, 75])
@pytest.mark.parametrize("e", [1.0, 0.95])
def test_throw_angle_is_alciatores(cut_deg, speed, e):
    cut = math.radians(cut_deg)
    vel, _ = _collide(cut, speed, e)
    throw = math.atan2(vel[0, 1], vel[0, 0])
    assert throw == pytest.approx(alciatore_throw(cut, speed, e), rel=1e-12, abs=1e-15)


def test_throw_curves_shape():
    """The features of TP A-14's curves: no throw head-on, most throw at slow speed (its friction falls with the
    slip speed), the largest throw of a stun shot at a cut of some 30 degrees and 4 to 6 degrees at slow speed,
    throw falling with speed at every cut."""
    cuts = np.radians(np.arange(0.5, 90.0, 0.5))
    curves = {v: np.array([math.degrees(math.atan2(*_collide(c, v, 1.0)[0][0, ::-1])) for c in cuts])
              for v in (0.3, 1.0, 3.0)}
    assert _collide(0.0, 1.0, 1.0)[0][0, 1] == 0.0
    for slow, fast in ((0.3, 1.0), (1.0, 3.0)):
        assert np.all(curves[slow] >= curves[fast] - 1e-12)
    peak = math.degrees(cuts[int(np.argmax(curves[0.3]))])
    assert 15.0 <= peak <= 40.0
    assert 4.0 <= curves[0.3].max() <= 6.5
    assert 1.0 <= curves[3.0].max() <= 3.0


def test_gearing_english_has_no_throw():
    """Outside english that makes the contact points roll on each other (``R wz = v sin(cut)``) leaves no slip: no
    throw, and neither ball's spin changes."""
    cut, speed = math.radians(30), 1.5
    wz = -speed * math.sin(cut) / R  # the cue ball's contact point moves with -R wz along y: cancels v sin(cut)
    vel, ang = _collide(cut, speed, 0.95, wz)
    assert abs(vel[0, 1]) < 1e-15 and ang[1, 2] == wz and np.all(ang[0] == 0.0)
    vel2, _ = _collide(cut, speed, 0.95, -wz)  # inside english doubles the slip: throw
    assert vel2[0, 1] > 0.01


def test_throw_conserves_momentum_and_loses_energy():
    rng = np.random.default_rng(3)
    for _ in range(200):
        vel = rng.uniform(-3, 3, (2, 2))
        ang = rng.uniform(-100, 100, (2, 3))
        m = rng.uniform(0.1, 0.3, 2)
        r = rng.uniform(0.02, 0.04, 2)
        th = rng.uniform(-math.pi, math.pi)
        p0 = m[0] * vel[0] + m[1] * vel[1]
        def ke(v, w):
            return sum(0.5 * m[k] * v[k] @ v[k] + 0.2 * m[k] * r[k] ** 2 * w[k] @ w[k] for k in range(2))

        k0 = ke(vel, ang)
        resolve_ball_ball_alciatore(vel, ang, 0, 1, math.cos(th), math.sin(th), m[0], m[1], r[0], r[1],
                                    rng.uniform(0, 1), A, B, C, 1e-3, False)
        assert np.allclose(m[0] * vel[0] + m[1] * vel[1], p0, rtol=0, atol=1e-13)
        assert ke(vel, ang) <= k0 * (1 + 1e-13)


# ------------------------------------------------------------------------------------------------ cushions

@njit
def _hit(v, w, prm, cushion, r, m, e_c):
    scratch = np.zeros(10)
    return cushion_hit(v, w, 0, cushion, r, m, e_c, prm, scratch)


def _cushion(physics: Physics, v, w, cushion=0, e_c=0.85):
    vel = np.array([v], dtype=float)
    ang = np.array([w], dtype=float)
    prm = kernel_params(Table(cushion_restitution=e_c), physics, 600.0)[0]
    speed = _hit(vel, ang, prm, cushion, R, M, e_c)
    return vel[0], ang[0], speed


@pytest.mark.parametrize("model", ["impulse", "stronge", "mathavan"])
@pytest.mark.parametrize("cushion", [0, 1, 2, 3])
def test_square_hit_at_rest_height(model, cushion):
    """A ball without spin meeting the cushion square, the nose at its centre's height (its rest height R): it
    comes straight back at ``e_c`` times its speed and gets no spin (the contact normal passes through the centre,
    and the contact point does not slip)."""
    physics = Physics(friction="spin", cushion=model, cushion_height=R)
    n = [(1, 0), (-1, 0), (0, 1), (0, -1)][cushion]
    v, w, speed = _cushion(physics, (-1.3 * n[0], -1.3 * n[1]), (0.0, 0.0, 0.0), cushion)
    assert speed == pytest.approx(1.3, rel=1e-15)
    if model == "mathavan":
        # Its steps of 0.001 N s end the restitution on the work done, not on the speed: within 1 % of e_c v. (It
        # also pushes the ball sideways by 1e-4 m/s: at zero slip its friction takes the direction atan2(0, 0) = 0,
        # as in the paper's equations and pooltool's implementation.)
        assert np.allclose(v, (1.3 * 0.85 * n[0], 1.3 * 0.85 * n[1]), rtol=0, atol=1.3e-2)
    else:
        assert np.allclose(v, (1.3 * 0.85 * n[0], 1.3 * 0.85 * n[1]), rtol=1e-14, atol=1e-15)
        assert np.all(np.abs(w) < 1e-12)


def test_raised_nose_gives_a_square_stun_hit_follow():
    """The nose above the centre (pooltool's 0.036576 m): the contact normal tilts down by
    ``theta = atan((h - R) / R)``. Without friction a square hit without spin comes back at
    ``(1 - (1 + e) cos^2 theta) v`` (the normal impulse is along the tilted normal, its vertical part lost to the
    table) and without spin. With friction, the ball's contact point slides down the nose; the friction against it
    pushes up at a point above the centre, towards the cushion: the ball comes back with follow (``wx > 0`` for a
    ball rebounding along -y, the sense of rolling away from the cushion)."""
    h = PRESETS["pooltool"]["cushion_height"]
    th = math.atan((h - R) / R)
    for model in ("impulse", "stronge"):
        physics = Physics(friction="spin", cushion=model, cushion_height=h, cushion_friction=0.0)
        v, w, _ = _cushion(physics, (0.0, 2.0), (0.0, 0.0, 0.0), cushion=3)
        assert v[1] == pytest.approx(2.0 * (1.0 - 1.85 * math.cos(th) ** 2), rel=1e-13)
        assert v[0] == 0.0 and np.all(w == 0.0)
        physics = Physics(friction="spin", cushion=model, cushion_height=h, cushion_friction=0.2)
        v, w, _ = _cushion(physics, (0.0, 2.0), (0.0, 0.0, 0.0), cushion=3)
        assert v[1] < 0.0 and v[0] == 0.0 and w[0] > 0.0 and w[1] == 0.0 and w[2] == 0.0


def test_stronge_gross_slip_closed_form():
    """Gross slip (``r = v_t0 / v_n0`` above ``mu ((1 + e) beta - eta^2 / e)``): the contact slips throughout and
    its tangential speed changes by ``mu beta (1 + e) |v_n0|``, like a Coulomb impulse; the normal speed is
    ``-e v_n0``."""
    mu, e, om = 0.2, 0.85, 1.8
    eta2 = BETA / om ** 2
    for v_n0 in (-0.3, -1.0, -4.0):
        r = 1.5 * mu * ((1 + e) * BETA - eta2 / e)
        vt, vn = _stronge(r * v_n0, v_n0, mu, e, om)
        assert vt == pytest.approx(r * v_n0 - mu * BETA * (1 + e) * v_n0, rel=1e-14)
        assert vn == pytest.approx(-e * v_n0, rel=1e-15)
    # No incoming tangential speed: nothing to slip, nothing changes tangentially.
    assert _stronge(0.0, -2.0, mu, e, om)[0] == 0.0


@njit
def _stronge(vt, vn, mu, e, om):
    return compliant_impact(vt, vn, mu, e, om)


@pytest.mark.parametrize("mu,e,om", [(0.2, 0.85, 1.8), (0.1, 0.8, 1.3), (0.4, 0.95, 1.95), (0.25, 0.95, 1.1)])
def test_stronge_is_continuous_across_its_regimes(mu, e, om):
    """The outgoing tangential speed is continuous in ``r`` at the two regime boundaries (stick-slip /
    slip-stick-slip at ``mu eta^2``, slip-stick-slip / gross slip at ``mu ((1 + e) beta - eta^2 / e)``), where the
    gross-slip boundary lies above ``mu beta``, ``e > 1 / omega`` (0.56 at pooltool's 1.8; below, the regimes as
    pooltool orders them jump there: see docs/physics.md)."""
    assert e > 1.0 / om
    eta2 = BETA / om ** 2
    for boundary in (mu * eta2, mu * ((1 + e) * BETA - eta2 / e)):
        if boundary <= 0.0:
            continue
        below = _stronge(-boundary * (1 - 1e-9), -1.0, mu, e, om)[0]
        above = _stronge(-boundary * (1 + 1e-9), -1.0, mu, e, om)[0]
        assert abs(below - above) < 1e-6


def test_stronge_never_gains_energy_at_pooltools_parameters():
    """The kinetic energy of the contact's motion, ``(v_t^2 / beta + v_n^2) / 2`` per unit mass, never rises at
    pooltool's parameters (mu 0.2, e 0.85, omega 1.8), whatever the incidence."""
    for r in np.concatenate([np.logspace(-6, 2, 400), [0.0]]):
        vt, vn = _stronge(-r, -1.0, 0.2, 0.85, 1.8)
        assert vt * vt / BETA + vn * vn <= r * r / BETA + 1.0


def test_cushion_laws_never_add_energy():
    """Every cushion law, random hits and parameters (friction up to 1, restitution 0 to 1, soft to stiff tangential
    springs, the nose anywhere in [R, 2R)): the ball's kinetic energy, translation and rotation, never rises
    (Stronge's and Mathavan's hits that would gain some are resolved by the impulse law)."""
    rng = np.random.default_rng(7)
    for _ in range(300):
        model = rng.choice(["impulse", "stronge", "mathavan"])
        physics = Physics(friction="spin", cushion=str(model), cushion_height=float(rng.uniform(R, 1.99 * R)),
                          omega_ratio=float(rng.uniform(1.01, 1.99)), cushion_friction=float(rng.uniform(0, 1)))
        speed = 10 ** rng.uniform(-3, 0.7)
        v0 = (float(rng.uniform(-1, 1) * speed), float(rng.uniform(0.01, 1) * speed))
        w0 = tuple(float(x) for x in rng.uniform(-1, 1, 3) * speed / R)
        v, w, _ = _cushion(physics, v0, w0, cushion=3, e_c=float(rng.uniform(0, 1)))
        def k(v, w):
            return 0.5 * (v @ v) + 0.2 * R * R * (w @ w)

        assert k(v, w) <= k(np.array(v0), np.array(w0)) * (1 + 1e-13)


# ------------------------------------------------------------------------------------------------ squirt

def test_squirt_angle_is_tp_a31():
    """TP A-31: ``atan(5/2 a sqrt(1 - a^2) / (1 + m_b / m_e + 5/2 (1 - a^2)))`` for tip offset ``a``; pooltool's
    cue end mass: about 1.9 degrees at half a radius of english, to the left for right english."""
    for side in (0.1, 0.3, 0.5):
        a2 = 1 - side * side
        expect = math.atan(2.5 * side * math.sqrt(a2) / (1 + M / POOLTOOL_CUE_END_MASS + 2.5 * a2))
        assert squirt_angle(side, M, POOLTOOL_CUE_END_MASS, 1.0) == pytest.approx(expect, rel=1e-15)
        assert squirt_angle(-side, M, POOLTOOL_CUE_END_MASS, 1.0) == pytest.approx(-expect, rel=1e-15)
    assert math.degrees(squirt_angle(0.5, M, POOLTOOL_CUE_END_MASS, 1.0)) == pytest.approx(1.89, abs=0.01)
    assert squirt_angle(0.5, M, POOLTOOL_CUE_END_MASS, 0.0) == 0.0


def test_strike_with_squirt_turns_the_path_not_the_spin():
    physics = PRESET
    plain = Balls.from_positions([[1.0, 0.6]]).strike("cue", 0.4, 2.0, side=0.4, top=0.2)
    b = Balls.from_positions([[1.0, 0.6]]).strike("cue", 0.4, 2.0, side=0.4, top=0.2, physics=physics)
    alpha = squirt_angle(0.4, M, physics.cue_end_mass, 1.0)
    assert math.atan2(b.vel[0, 1], b.vel[0, 0]) == pytest.approx(0.4 + alpha, rel=1e-14)
    assert np.linalg.norm(b.vel[0]) == pytest.approx(2.0, rel=1e-15)
    assert np.array_equal(b.ang, plain.ang)
    # No side english: no squirt, bit for bit the plain strike.
    s = Balls.from_positions([[1.0, 0.6]]).strike("cue", 0.4, 2.0, top=0.3, physics=physics)
    assert np.array_equal(s.vel, Balls.from_positions([[1.0, 0.6]]).strike("cue", 0.4, 2.0, top=0.3).vel)


def test_batch_rows_strike_with_squirt_like_single_shots():
    sim = Simulator(Table(), PRESET)
    balls = Balls.from_positions([[0.62, 0.58], [1.9, 0.95], [2.3, 0.18]])
    angles = np.array([0.2, 0.5, -0.3])
    speeds = np.array([1.0, 2.5, 4.0])
    side = np.array([0.3, -0.2, 0.0])
    top = np.array([0.1, -0.3, 0.2])
    res = run_shots(sim, balls, angles, speeds, side=side, top=top, threads=1)
    for k in range(3):
        single = sim.run(balls.strike("cue", angles[k], speeds[k], side=side[k], top=top[k], physics=PRESET))
        assert np.array_equal(res.pos[k], single.balls.pos) and np.array_equal(res.ang[k], single.balls.ang)


# ------------------------------------------------------------------------------------------------ fields, preset

PRESET = Physics.from_preset("pooltool")


def test_pooltool_preset_fields():
    p = PRESET
    assert (p.friction, p.ball_ball, p.cushion, p.squirt) == ("spin", "alciatore", "stronge", 1.0)
    assert (p.mu_slide, p.mu_roll, p.mu_spin, p.ball_restitution, p.cushion_friction) == (0.2, 0.01, 0.0127, 0.95, 0.2)
    assert (p.alciatore_a, p.alciatore_b, p.alciatore_c, p.omega_ratio) == (A, B, C, 1.8)
    assert p.cushion_height == pytest.approx(0.036576, abs=1e-15)
    assert p.mu_spin == pytest.approx(10 * 2 / 5 / 9 * R, rel=1e-12)  # pooltool's u_sp = 0.4444 R


def test_explicit_fields_override_the_preset():
    p = parse_physics({"preset": "pooltool", "ball_ball": "frictionless", "cushion_height": None, "mu_roll": 0.02})
    assert (p.ball_ball, p.cushion_height, p.mu_roll, p.cushion) == ("frictionless", None, 0.02, "stronge")
    assert Physics.from_preset("pooltool", squirt=0.0).squirt == 0.0


def test_scene_with_the_preset_runs():
    scene = Scene.from_dict({"table": {"pockets": []}, "physics": {"preset": "pooltool"},
                             "balls": [{"x": 0.6, "y": 0.5}, {"x": 1.5, "y": 0.62}],
                             "shot": {"angle": 0.15, "speed": 2.0, "side": 0.3, "top": 0.1}})
    res = scene.run()
    assert res.status == "rest" and res.first_contact(0) == 1
    assert scene.physics == PRESET


@pytest.mark.parametrize("fields,words", [
    ({"preset": "pooltol"}, ["preset", "did you mean 'pooltool'"]),
    ({"friction": "spin", "cushion": "strong"}, ["physics.cushion", "did you mean 'stronge'", "mathavan"]),
    ({"friction": "spin", "ball_ball": "alciator"}, ["physics.ball_ball", "alciatore"]),
    ({"cushion": "stronge"}, ["needs the spin model", "friction"]),
    ({"squirt": 1.0}, ["needs the spin model"]),
    ({"friction": "spin", "omega_ratio": 2.5}, ["omega_ratio", "(1, 2)"]),
    ({"friction": "spin", "ball_ball": "alciatore", "ball_friction": 0.1}, ["ball_friction", "leave ball_friction 0"]),
    ({"friction": "spin", "cushion_height": -0.01}, ["cushion_height", "> 0"]),
    ({"friction": "spin", "squirt": -1.0}, ["squirt", ">= 0"]),
])
def test_bad_model_fields_are_refused_with_the_fix(fields, words):
    with pytest.raises(SceneError) as exc:
        parse_physics(fields)
    for w in words:
        assert w in str(exc.value)


def test_cushion_height_outside_the_ball_is_refused():
    sim = Simulator(Table(), Physics.from_preset("pooltool", cushion_height=0.06))
    with pytest.raises(SceneError, match=r"cushion_height.*\[R, 2R\)"):
        sim.run(Balls.from_positions([[1.0, 0.6]]).strike("cue", 0.0, 1.0))


def test_billiards_sim_takes_a_preset(tmp_path, capsys):
    """``billiards-sim SCENE --preset pooltool`` plays the scene under the preset instead of its physics section;
    an unknown preset is refused by the parser (exit status 2)."""
    import json

    from billiards_env.sim import main

    scene = {"table": {"pockets": []}, "physics": {"friction": "rolling"},
             "balls": [{"x": 0.6, "y": 0.5}, {"x": 1.5, "y": 0.62}],
             "shot": {"angle": 0.15, "speed": 2.0}}
    path = tmp_path / "s.json"
    path.write_text(json.dumps(scene))
    assert main([str(path), "--preset", "pooltool", "--indent", "0"]) == 0
    out = json.loads(capsys.readouterr().out)
    ref = Scene.from_dict({**scene, "physics": {"preset": "pooltool"}}).run()
    assert [b["x"] for b in out["balls"]] == ref.balls.pos[:, 0].tolist()
    with pytest.raises(SystemExit) as exc:
        main([str(path), "--preset", "pooltol"])
    assert exc.value.code == 2
