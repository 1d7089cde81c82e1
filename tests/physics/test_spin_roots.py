"""The event-time root finder (``roots.first_entry``) against high-precision roots (mpmath) on the quartics of the
spin model: two balls on quadratic paths (ball-ball), a ball on a parabola and a pocket circle, and the hard cases:
near-equal velocities, Newton's cradle (touching, closing), grazing contacts, clusters of roots, tiny leading
coefficients, long windows.

What is checked, for the first time ``f`` enters ``f <= 0`` from above in ``[0, T]``:
- backward error: the returned time is an exact root of ``f`` perturbed by at most a few units of round-off in
  its terms (``|f(t)| <= 8 eps sum |c_k t^k|``, evaluated with 60 digits): nothing better exists in doubles;
- forward error: within the root's condition (``|dt| <= 8 eps sum |c_k t^k| / |f'(t)|`` plus a few ulps) for a
  simple root, and within ``sqrt`` of it for the grazing double roots;
- no missed or extra event: a crossing the 60-digit roots show is found, the first one, and a polynomial that
  stays positive gives ``inf``.
"""
from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from billiards_env.physics.roots import first_entry

mp.mp.dps = 60
EPS = np.finfo(float).eps
R = 0.028575
D = 2 * R
G = 9.81


def pair_quartic(a, b, c, dist=D):
    """``|a + b t + c t^2|^2 - dist^2`` as quartic coefficients (highest first), in doubles."""
    a, b, c = (np.asarray(x, float) for x in (a, b, c))
    return (float(c @ c), float(2 * b @ c), float(b @ b + 2 * a @ c), float(2 * a @ b), float(a @ a - dist * dist))


def reference_first_entry(coeffs, t_max):
    """The first time in ``(0, t_max]`` where ``f`` (60-digit arithmetic, the same double coefficients) goes from
    positive to ``<= 0``, or ``inf``; also the smallest distance from it to another root (for the tests' scale)."""
    cs = [mp.mpf(c) for c in coeffs]
    while len(cs) > 1 and cs[0] == 0:
        cs = cs[1:]
    if len(cs) == 1:
        return math.inf, math.inf
    roots = mp.polyroots(cs, maxsteps=400, extraprec=600)
    real = sorted(mp.re(r) for r in roots if abs(mp.im(r)) < mp.mpf(10) ** -45)
    for k, r in enumerate(real):
        if not 0 < r <= t_max:
            continue
        others = [abs(r - s) for s in real if s is not r] or [mp.inf]
        h = min(min(others) / 4, max(abs(r), 1) * mp.mpf(10) ** -30)
        if mp.polyval(cs, r - h) > 0 and mp.polyval(cs, r + h) <= 0:
            return r, min(others)
    return math.inf, math.inf


def check(coeffs, t_max, closing_tol=0.0, graze=False):
    """Run ``first_entry`` and check it against the 60-digit reference; returns its answer."""
    t = first_entry(*coeffs, t_max, closing_tol)
    ref, _ = reference_first_entry(coeffs, t_max)
    if ref == math.inf:
        assert t == math.inf, (coeffs, t)
        return t
    assert t < math.inf, (coeffs, float(ref))
    cs = [mp.mpf(c) for c in coeffs]
    tt = mp.mpf(t)
    scale = sum(abs(c) * tt ** (4 - k) for k, c in enumerate(cs))
    assert abs(mp.polyval(cs, tt)) <= 8 * EPS * scale, (coeffs, t)  # backward stable
    cs = [mp.mpf(0)] * (5 - len(cs)) + cs
    deriv = abs(mp.polyval([4 * cs[0], 3 * cs[1], 2 * cs[2], cs[3]], ref))
    bound = 8 * EPS * scale / deriv + 4 * EPS * abs(ref) if deriv > 0 else mp.inf
    if graze:  # a near-double root: the error grows like the square root of the round-off
        second = abs(mp.polyval([12 * cs[0], 6 * cs[1], 2 * cs[2]], ref))
        bound = max(bound, mp.sqrt(16 * EPS * scale / second))
    assert abs(tt - ref) <= bound, (coeffs, t, float(ref), float(bound))
    return t


def test_generic_sliding_pair_is_accurate_to_round_off():
    # A sliding ball on a parabola meets one rolling straight: a well-conditioned simple root.
    c = pair_quartic([0.45, 0.12], [-1.6, -0.2], [0.5 * 0.2 * G * 0.6, -0.5 * 0.2 * G * 0.8])
    t = check(c, 2.0)
    assert 0.1 < t < 1.0


@pytest.mark.parametrize("gap", [1e-15, 1e-13, 1e-10])
def test_newtons_cradle_touching_and_closing(gap):
    # Balls a hair apart, closing at 1 m/s: the root is ~gap seconds away.
    c = pair_quartic([D + gap, 0.0], [-1.0, 0.0], [0.5 * 1.962, 0.0])
    t = check(c, 1.0)
    assert t == pytest.approx(gap, rel=1e-3)


def test_touching_pair_closing_counts_at_once():
    c = pair_quartic([D, 0.0], [-1.0, 0.0], [0.5, 0.0])
    assert first_entry(*c, 1.0, 1e-12) == 0.0


@pytest.mark.parametrize("velocity_gap", [1e-4, 1e-7, 1e-10])
def test_near_equal_velocities_far_apart(velocity_gap):
    # Two balls 0.3 m apart moving almost together: the approach takes 0.3 / gap seconds (a long window).
    a = [0.3 + D, 0.01]
    b = [-velocity_gap, 1e-3 * velocity_gap]
    c = [-0.5 * 1e-2 * velocity_gap, 0.0]
    t_max = 4.0 / velocity_gap
    t = check(pair_quartic(a, b, c), t_max)
    assert t < math.inf


@pytest.mark.parametrize("miss", [1e-6, 1e-9, 1e-11, -1e-11, -1e-9])
@pytest.mark.parametrize("curve", [0.0, 0.05])
def test_grazing_contacts(miss, curve):
    # Centre lines pass at D - miss: a contact (miss > 0) that is nearly tangential, or (miss < 0) a near miss.
    a = [1.0, D - miss]
    b = [-2.0, 0.0]
    c = [0.3, curve * 0.0]
    t = check(pair_quartic(a, b, c), 2.0, graze=True)
    assert (t < math.inf) == (miss > 0)


@pytest.mark.parametrize("spread", [1e-2, 1e-3, 1e-4])
def test_clusters_of_four_roots(spread):
    # (t - 1)(t - 1 - s)(t - 1 - 2s)(t - 1 - 3s): the first of four close roots. (At s = 1e-4 the rounding of
    # the coefficients to doubles moves f by more than its tiny wiggles: the crossings may vanish, and then the
    # answer must be inf like the 60-digit reference's.)
    coeffs = tuple(float(x) for x in np.poly([1.0, 1 + spread, 1 + 2 * spread, 1 + 3 * spread]))
    t = check(coeffs, 3.0)
    assert abs(t - 1.0) < spread or (spread < 1e-3 and t == math.inf)


def test_tiny_leading_coefficient():
    c = pair_quartic([0.4, 0.1], [-1.0, -0.3], [1e-9, 2e-9])
    check(c, 2.0)


def test_parabola_into_pocket_circle():
    # A ball curving (sliding with lateral slip) into a pocket of capture radius 0.06 around the origin.
    x0 = np.array([0.5, 0.25])
    v0 = np.array([-1.4, -0.2])
    acc = -0.2 * G * np.array([0.3, 0.95393920141695])
    c = pair_quartic(x0, v0, 0.5 * acc, dist=0.06)
    check(c, 0.5)


def test_polynomial_that_stays_positive_has_no_event():
    c = pair_quartic([0.5, 0.3], [-1.5, -0.2], [0.7, -0.5])
    assert first_entry(*c, 2.0, 0.0) == math.inf
    assert reference_first_entry(c, 2.0)[0] == math.inf


def test_random_hard_quartics_against_mpmath():
    """Random pairs of balls on quadratic paths aimed to pass within +-1e-8 m of contact or hit nearly
    head-on at nearly equal velocities: every answer backward stable and within its conditioning."""
    rng = np.random.default_rng(11)
    for _ in range(60):
        d = rng.normal(size=2)
        d *= rng.uniform(0.06, 1.0) / np.linalg.norm(d)
        v = -d / np.linalg.norm(d) * rng.uniform(0.01, 3.0)
        perp = np.array([-d[1], d[0]]) / np.linalg.norm(d)
        kind = rng.integers(3)
        if kind == 0:  # grazing: the straight path's closest approach D - miss
            miss = 10.0 ** rng.uniform(-12, -6) * rng.choice([-1.0, 1.0])
            a = d + perp * (D - miss - d @ perp)
            c = np.zeros(2)
        elif kind == 1:  # near-equal velocities: a slow relative approach
            a = d
            v = v * 10.0 ** rng.uniform(-9, -3)
            c = rng.normal(size=2) * 1e-3 * np.linalg.norm(v)
        else:  # sliding against rolling: different accelerations
            a = d
            c = rng.normal(size=2) * 0.5 * 0.2 * G
        t_max = 4.0 * np.linalg.norm(a) / np.linalg.norm(v) + 1.0
        check(pair_quartic(a, v, c), float(t_max), graze=(kind == 0))
