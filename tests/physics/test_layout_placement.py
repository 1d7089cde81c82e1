"""Ball in hand: the nearest legal point (physics/layout.py ``nearest_free_point``, one compiled call) equals the Python
it replaced (kept below verbatim) bit for bit on random layouts, areas and asked points; its result is legal, and no
legal point of a fine grid around the asked point is nearer. ``py_hypot`` is CPython's ``math.hypot``."""
from __future__ import annotations

import math

import numpy as np
import pytest

from billiards_env.physics import BALL_RADIUS, SceneError, Table
from billiards_env.physics.layout import free_discs, nearest_free, nearest_free_point, py_hypot

R = BALL_RADIUS


def python_nearest_free_point(x: float, y: float, pos: np.ndarray, on_table: np.ndarray, radius: np.ndarray | float,
                       row: int, area: tuple[float, float, float, float], clearance: float = 1e-6,
                       holes: np.ndarray | None = None) -> tuple[float, float]:
    """The legal point nearest to ``(x, y)`` for ball ``row``: inside ``area = (x0, x1, y0, y1)`` (its centre's
    allowed rectangle), at least ``r_row + r_other + clearance`` from every other ball on the table, and (with
    ``holes``, rows ``(x, y, r)``: the pockets' capture circles) at least ``r + clearance`` from each hole's centre,
    so that a ball placed there does not drop at once.

    Ball in hand: an agent outputs any point, and an illegal one (off the area, overlapping a ball) moves here.
    Exact for the rectangle minus the union of the forbidden discs: the nearest point is the clipped point
    itself, its projection onto one disc's boundary, or a corner where two boundaries (disc/disc, disc/edge)
    meet; every candidate is checked and the nearest legal one returned. Raises :class:`SceneError` if there is
    no legal point at all.
    """
    x0, x1, y0, y1 = area
    if not (x0 <= x1 and y0 <= y1):
        raise SceneError(f"placement area {area}: empty; x0 <= x1 and y0 <= y1 are required")
    rad = np.broadcast_to(np.asarray(radius, dtype=float), (len(pos),))
    discs = [(float(pos[k, 0]), float(pos[k, 1]), float(rad[row] + rad[k] + clearance))
             for k in range(len(pos)) if on_table[k] and k != row]
    if holes is not None:
        discs += [(float(hx), float(hy), float(hr) + clearance) for hx, hy, hr in np.asarray(holes, dtype=float)]

    def legal(px: float, py: float) -> bool:
        if not (x0 <= px <= x1 and y0 <= py <= y1):
            return False
        return all((px - cx) ** 2 + (py - cy) ** 2 >= (rr * (1.0 - 1e-12)) ** 2 for cx, cy, rr in discs)

    px = min(max(float(x), x0), x1)
    py = min(max(float(y), y0), y1)
    if legal(px, py):
        return px, py
    cands: list[tuple[float, float]] = []
    for cx, cy, rr in discs:  # projections onto each disc's boundary
        dx, dy = px - cx, py - cy
        d = math.hypot(dx, dy)
        ux, uy = (dx / d, dy / d) if d > 0.0 else (1.0, 0.0)
        cands.append((cx + ux * rr, cy + uy * rr))
    for a in range(len(discs)):  # disc/disc intersections
        ax, ay, ar = discs[a]
        for b in range(a + 1, len(discs)):
            bx, by, br = discs[b]
            d = math.hypot(bx - ax, by - ay)
            if d == 0.0 or d > ar + br or d < abs(ar - br):
                continue
            along = (ar * ar - br * br + d * d) / (2.0 * d)
            h = math.sqrt(max(ar * ar - along * along, 0.0))
            mx, my = ax + along * (bx - ax) / d, ay + along * (by - ay) / d
            cands.append((mx - h * (by - ay) / d, my + h * (bx - ax) / d))
            cands.append((mx + h * (by - ay) / d, my - h * (bx - ax) / d))
    for cx, cy, rr in discs:  # disc/edge intersections
        for ex in (x0, x1):
            h2 = rr * rr - (ex - cx) ** 2
            if h2 >= 0.0:
                cands += [(ex, cy + math.sqrt(h2)), (ex, cy - math.sqrt(h2))]
        for ey in (y0, y1):
            h2 = rr * rr - (ey - cy) ** 2
            if h2 >= 0.0:
                cands += [(cx + math.sqrt(h2), ey), (cx - math.sqrt(h2), ey)]
    cands += [(x0, y0), (x0, y1), (x1, y0), (x1, y1)]
    best = None
    best_d2 = math.inf
    for qx, qy in cands:
        qx = min(max(qx, x0), x1)
        qy = min(max(qy, y0), y1)
        if legal(qx, qy):
            d2 = (qx - px) ** 2 + (qy - py) ** 2
            if d2 < best_d2:
                best, best_d2 = (qx, qy), d2
    if best is None:
        raise SceneError(f"no legal point for ball row {row} in the area {area}: it is covered by other balls")
    return best


def _random_layout(rng: np.random.Generator, n: int, table: Table) -> np.ndarray:
    pts: list[np.ndarray] = []
    while len(pts) < n:
        p = rng.uniform([R, R], [table.length - R, table.width - R])
        if rng.random() < 0.15:  # some balls frozen on a cushion
            p[rng.integers(2)] = R
        if all(np.hypot(*(p - q)) >= 2 * R for q in pts):
            pts.append(p)
    return np.array(pts)


def test_py_hypot_is_pythons_hypot():
    rng = np.random.default_rng(0)
    for scale in (1e-6, 1e-2, 1.0, 3.0):
        xs = rng.normal(size=20000) * scale
        ys = rng.normal(size=20000) * scale * rng.uniform(0.0, 1.0, 20000)
        assert [py_hypot(x, y) for x, y in zip(xs.tolist(), ys.tolist())] == \
            [math.hypot(x, y) for x, y in zip(xs.tolist(), ys.tolist())]
    assert py_hypot(0.0, 0.0) == 0.0 and py_hypot(-3.0, 4.0) == 5.0 and math.isinf(py_hypot(math.inf, 1.0))


def test_nearest_free_point_equals_the_python_it_replaced():
    rng = np.random.default_rng(5)
    table = Table()
    holes = np.column_stack([table.pocket_xy, table.pocket_radius])
    moved = 0
    for k in range(400):
        pos = _random_layout(rng, int(rng.integers(2, 16)), table)
        on = rng.random(len(pos)) < 0.9
        radius = np.full(len(pos), R) if k % 4 else R  # an array or one radius for all
        area = (R, table.length / 4, R, table.width - R) if k % 2 else (R, table.length - R, R, table.width - R)
        # Aim at a ball, a pocket or anywhere: the asked point is often illegal.
        x, y = (pos[int(rng.integers(len(pos)))] + rng.normal(0, R, 2)) if k % 3 else rng.uniform(-0.1, 2.6, 2)
        with_holes = holes if k % 5 else None
        row = int(rng.integers(len(pos)))
        expected = python_nearest_free_point(x, y, pos, on, radius, row, area, holes=with_holes)
        got = nearest_free_point(x, y, pos, on, radius, row, area, holes=with_holes)
        assert got == expected and all(type(v) is float for v in got)
        clipped = (min(max(x, area[0]), area[1]), min(max(y, area[2]), area[3]))
        assert nearest_free(*clipped, free_discs(pos, on, np.full(len(pos), R), row,
                                                  holes if with_holes is not None else np.zeros((0, 3)), 1e-6),
                            *area)[:2] == expected
        moved += expected != clipped
    assert moved >= 80  # the sample exercises the moves, not only legal points


def test_nearest_free_point_is_legal_and_nearest():
    rng = np.random.default_rng(9)
    table = Table()
    holes = np.column_stack([table.pocket_xy, table.pocket_radius])
    area = (R, table.length - R, R, table.width - R)
    for _ in range(40):
        pos = _random_layout(rng, 12, table)
        on = np.ones(len(pos), bool)
        x, y = pos[1] + rng.normal(0, R, 2)
        px, py = nearest_free_point(x, y, pos, on, R, 0, area, holes=holes)
        need = 2 * R + 1e-6
        assert area[0] <= px <= area[1] and area[2] <= py <= area[3]
        assert all(math.hypot(px - q[0], py - q[1]) >= need * (1 - 1e-9) for q in pos[1:])
        assert all(math.hypot(px - h[0], py - h[1]) >= (h[2] + 1e-6) * (1 - 1e-9) for h in holes)
        d = math.hypot(px - x, py - y)
        g = np.linspace(-4 * R, 4 * R, 81)
        for gx in x + g:
            for gy in y + g:
                if not (area[0] <= gx <= area[1] and area[2] <= gy <= area[3]):
                    continue
                if np.all(np.hypot(pos[1:, 0] - gx, pos[1:, 1] - gy) >= need) and \
                        np.all(np.hypot(holes[:, 0] - gx, holes[:, 1] - gy) >= holes[:, 2] + 1e-6):
                    assert math.hypot(gx - x, gy - y) >= d - 1e-12


def test_a_covered_or_empty_area_is_refused():
    pos = np.array([[0.5, 0.5], [0.5, 0.5]])
    with pytest.raises(SceneError, match="covered"):
        nearest_free_point(0.5, 0.5, pos, np.ones(2, bool), R, 0, (0.5, 0.5, 0.5, 0.5))
    with pytest.raises(SceneError, match="empty"):
        nearest_free_point(0.5, 0.5, pos, np.ones(2, bool), R, 0, (0.6, 0.5, 0.5, 0.5))


def python_spot_object_ball(pos, on_table, radius, table, row):
    """``spot_object_ball`` as it was in Python (before issue 21), verbatim but for the helper inlined."""
    from billiards_env.physics.layout import foot_spot

    others = [(float(x), float(y)) for k, ((x, y), on) in enumerate(zip(pos.tolist(), on_table.tolist()))
              if on and k != row]
    need2 = (2.0 * radius + 1e-6) ** 2
    fx, fy = foot_spot(table)
    step = radius / 8.0
    n_back = int((table.length - radius - fx) / step)
    n_front = int((fx - radius) / step)
    candidates = [fx + k * step for k in range(n_back + 1)] + [fx - k * step for k in range(1, n_front + 1)]
    for x in candidates:
        if all((x - qx) * (x - qx) + (fy - qy) * (fy - qy) >= need2 for qx, qy in others):
            pos[row, 0] = x
            pos[row, 1] = fy
            on_table[row] = True
            return
    raise SceneError("could not re-spot a ball: the long string is full")


def test_spot_object_ball_equals_the_python_it_replaced():
    from billiards_env.physics.layout import foot_spot, spot_object_ball

    rng = np.random.default_rng(2)
    table = Table()
    fx, fy = foot_spot(table)
    moved = 0
    for k in range(300):
        pos = _random_layout(rng, 10, table)
        # Crowd the long string around the foot spot: the spot is often taken.
        for i in range(1, 1 + int(rng.integers(0, 5))):
            pos[i] = (fx + rng.normal(0, 4 * R), fy + rng.normal(0, R))
        on = rng.random(len(pos)) < 0.85
        row = int(rng.integers(1, len(pos)))
        on[row] = False
        a_pos, a_on, b_pos, b_on = pos.copy(), on.copy(), pos.copy(), on.copy()
        spot_object_ball(a_pos, a_on, R, table, row)
        python_spot_object_ball(b_pos, b_on, R, table, row)
        assert np.array_equal(a_pos, b_pos) and np.array_equal(a_on, b_on) and a_on[row]
        moved += a_pos[row, 0] != fx
    assert moved >= 20


# --- a half-disc area (the generic geometry snooker's D stands on) -------------------------------------------------
def test_a_half_disc_places_the_ball_in_hand_nearest_and_legal():
    from billiards_env.physics.layout import half_disc_point, in_half_disc, nearest_point_in_half_disc

    cx, cy, r = 1.0, 0.6, 0.3
    pos = np.array([(0.2, 0.2), (cx - 0.1, cy)])  # the cue ball (row 0) and a ball inside the half-disc
    on = np.array([True, True])
    # a free point stays; beyond the straight side it goes onto it; beyond the arc onto the arc
    assert nearest_point_in_half_disc(cx - 0.2, cy + 0.2, pos, on, R, 0, cx, cy, r) == (cx - 0.2, cy + 0.2)
    assert nearest_point_in_half_disc(cx + 0.4, cy - 0.2, pos, on, R, 0, cx, cy, r) == pytest.approx((cx, cy - 0.2))
    assert nearest_point_in_half_disc(cx - 1.0, cy, pos, on, R, 0, cx, cy, r) == pytest.approx((cx - r, cy))
    # asked on the ball: pushed out to touching distance, still in the half-disc
    x, y = nearest_point_in_half_disc(cx - 0.1 + 1e-3, cy, pos, on, R, 0, cx, cy, r)
    assert in_half_disc(x, y, cx, cy, r) and math.hypot(x - (cx - 0.1), y - cy) == pytest.approx(2 * R + 1e-6)
    # the square maps onto it: corners of the straight side, the far point of the arc, clipped beyond [-1, 1]
    assert half_disc_point(-1, 1, cx, cy, r) == pytest.approx((cx, cy - r))
    assert half_disc_point(0, -1, cx, cy, r) == pytest.approx((cx - r, cy))
    assert half_disc_point(3, 3, cx, cy, r) == half_disc_point(1, 1, cx, cy, r)
    assert not in_half_disc(cx + 0.01, cy, cx, cy, r) and not in_half_disc(cx - r - 0.01, cy, cx, cy, r)


def test_a_covered_half_disc_raises_naming_the_area():
    from billiards_env.physics.layout import nearest_point_in_half_disc

    cx, cy, r = 1.0, 0.6, 0.1
    pos = np.array([(0.2, 0.2), (cx - 0.05, cy)])
    with pytest.raises(SceneError, match="no legal point in the box for the cue ball"):
        nearest_point_in_half_disc(cx, cy, pos, np.ones(2, bool), 0.1, 0, cx, cy, r, area="the box")
