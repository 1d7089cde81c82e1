"""The search player's position term skips shots by a bound (players/geometry.py ``tolerance_bound``) and must
find what trying every shot finds.

``layout_tolerance`` works out a moved ball's pocket window only when that (ball, pocket) shot's bound beats the best
tolerance so far. Here, on random layouts (capture and jaw tables, several cut limits): the bound is never below
the tolerance the shot has, a shot the bound rules out (-1) never counts, and ``layouts_ease`` / ``places_ease``
equal, bit for bit, the brute force that tries every ball and every pocket (``_every_shot``, the kernel as it was
before the bound).
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from numba import njit

from billiards_env.physics import BALL_RADIUS, Physics, Table
from billiards_env.physics.aim import WINDOW_SAMPLES, dot2, ghost_point, segment_touched_by, window_of
from billiards_env.physics.pocket_specs import SNOOKER_12FT, WPA_9FT
from billiards_env.physics.table import jaw_table
from billiards_env.players.geometry import (MAX_CUT, layouts_ease, model, places_ease, pot_chance, table_model,
                                            tolerance_bound)

R = BALL_RADIUS
TABLES = {"capture": Table(), "wpa_jaws": jaw_table(WPA_9FT), "snooker_jaws": jaw_table(SNOOKER_12FT)}


@njit
def _shot_tolerance(cx, cy, ox, oy, rc, rj, p, tm, cos_max):  # type: ignore[no-untyped-def]
    """One (ball, pocket) shot's tolerance before blocking, as layout_tolerance works it out; -inf when it does not
    count (no window, the ghost ball off the table, or a cut beyond ``cos_max``)."""
    contact = rc + rj
    c, h, d_in, ok = window_of(ox, oy, rj, tm.pocket_xy[p, 0], tm.pocket_xy[p, 1], tm.pocket_r[p], tm.length,
                               tm.width, WINDOW_SAMPLES, tm.segs, tm.tips)
    if not ok:
        return -math.inf, c, d_in
    gx, gy = ghost_point(ox, oy, c, contact)
    if not (rc <= gx <= tm.length - rc and rc <= gy <= tm.width - rc):
        return -math.inf, c, d_in
    vx = gx - cx
    vy = gy - cy
    d = math.hypot(vx, vy)
    cos_cut = dot2(vx, vy, math.cos(c), math.sin(c)) / max(d, 1e-12)
    if cos_cut < cos_max:
        return -math.inf, c, d_in
    return h * contact * cos_cut / (d + contact), c, d_in


@njit
def _every_shot(cx, cy, pos, on, radius, cue, targets, pocket_xy, pocket_r, params, cos_max):  # type: ignore
    """The easiest shot's tolerance trying every ball and every pocket (no bound, no window cache)."""
    tm = model(pocket_xy, pocket_r, params)
    rc = radius[cue]
    best = 0.0
    if not on[cue]:
        return best
    for t in range(targets.shape[0]):
        j = targets[t]
        if not on[j] or j == cue:
            continue
        ox = pos[j, 0]
        oy = pos[j, 1]
        for p in range(pocket_r.shape[0]):
            tol, wa, wd = _shot_tolerance(cx, cy, ox, oy, rc, radius[j], p, tm, cos_max)
            if tol <= best:
                continue
            gx, gy = ghost_point(ox, oy, wa, rc + radius[j])
            ux = math.cos(wa)
            uy = math.sin(wa)
            if segment_touched_by(cx, cy, gx, gy, pos, on, radius, cue, j, rc) or \
                    segment_touched_by(ox, oy, ox + ux * wd, oy + uy * wd, pos, on, radius, cue, j, radius[j]):
                tol /= 10.0
            if tol > best:
                best = tol
    return best


def _layouts(rng: np.random.Generator, table: Table, n: int, nb: int) -> np.ndarray:
    """``n`` layouts of ``nb`` balls anywhere between the cushion lines (overlaps allowed: the geometry does not
    mind), about half of each layout's balls where they are in the first."""
    pos = np.empty((n, nb, 2))
    pos[..., 0] = rng.uniform(R, table.length - R, (n, nb))
    pos[..., 1] = rng.uniform(R, table.width - R, (n, nb))
    keep = rng.random((n, nb)) < 0.5
    pos[keep] = np.broadcast_to(pos[0], pos.shape)[keep]
    return pos


@pytest.mark.parametrize("name", sorted(TABLES))
def test_the_bound_is_never_below_a_shots_tolerance(name):
    table = TABLES[name]
    tm = table_model(table, Physics())
    m = model(*tm)
    rng = np.random.default_rng(7)
    counted = ruled_out = 0
    for max_cut in (MAX_CUT, math.radians(60.0), math.radians(88.0)):
        cos_max = math.cos(max_cut)
        for _ in range(400):
            cx, ox = rng.uniform(R, table.length - R, 2)
            cy, oy = rng.uniform(R, table.width - R, 2)
            d_co = math.hypot(ox - cx, oy - cy)
            a_co = math.atan2(oy - cy, ox - cx)
            for p in range(len(table.pocket_radius)):
                tol = _shot_tolerance(cx, cy, ox, oy, R, R, p, m, cos_max)[0]
                bound = tolerance_bound(ox, oy, 2 * R, d_co, a_co, float(tm.pocket_xy[p, 0]),
                                        float(tm.pocket_xy[p, 1]), float(tm.pocket_r[p]), WINDOW_SAMPLES, cos_max)
                if bound < 0.0:
                    ruled_out += 1
                    assert tol == -math.inf, (cx, cy, ox, oy, p, tol)
                elif tol > -math.inf:
                    counted += 1
                    assert tol <= bound, (cx, cy, ox, oy, p, tol, bound)
    assert counted > 1000 and ruled_out > 1000  # both sides of the bound were exercised


@pytest.mark.parametrize("name", sorted(TABLES))
def test_position_terms_equal_trying_every_shot(name):
    table = TABLES[name]
    tm = table_model(table, Physics())
    rng = np.random.default_rng(11)
    nb, n = 10, 60
    radius = np.full(nb, R)
    t_flat = np.arange(1, nb, dtype=np.int64)
    t_off = np.array([0, 1, 4, nb - 1], np.int64)  # one target, three, all nine
    for trial in range(20):
        pos = _layouts(rng, table, n, nb)
        on = rng.random((n, nb)) > 0.1
        group = rng.integers(0, 3, n).astype(np.int64)
        rows = np.arange(n, dtype=np.int64)
        for sigma, max_cut in ((0.002, MAX_CUT), (0.01, math.radians(88.0))):
            got = layouts_ease(pos, on, radius, 0, rows, group, t_flat, t_off, *tm, sigma, max_cut, pos[0].copy())
            want = [pot_chance(_every_shot(pos[k, 0, 0], pos[k, 0, 1], pos[k], on[k], radius, 0,
                                           t_flat[t_off[group[k]]:t_off[group[k] + 1]], *tm, math.cos(max_cut)),
                               sigma) for k in rows]
            assert got.tobytes() == np.array(want).tobytes()
        on0 = on[0].copy()
        on0[0] = True
        places = pos[1:6, 0].copy()
        got = places_ease(places, pos[0], on[0], radius, 0, t_flat, *tm, 0.002, MAX_CUT)
        want = [pot_chance(_every_shot(x, y, pos[0], on0, radius, 0, t_flat, *tm, math.cos(MAX_CUT)), 0.002)
                for x, y in places]
        assert got.tobytes() == np.array(want).tobytes()
