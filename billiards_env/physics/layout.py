"""Where balls go: the spots and strings of a pool table, racks, random starting layouts, re-spotting, and
ball-in-hand placement moved to the nearest legal point.

Table markings (the x axis runs along the length from the head cushion at ``x = 0``): the head string is the line
``x = length/4`` (the kitchen is ``x < length/4``), the head spot is ``(length/4, width/2)``, the foot spot
``(3 length/4, width/2)`` and the long string the line ``y = width/2``. Every other module asks this one.

A half-disc area (snooker's D is one): whether a point is in it, a point of it for an action's placement dims, and
the nearest legal point in it for a ball in hand. The games' own layouts (snooker's spots and D, three-cushion's
opening position) live with the games: :mod:`billiards_env.games.snooker_layout`,
:mod:`billiards_env.games.carom_layout`.
"""
from __future__ import annotations

import math
from typing import Sequence

import numpy as np
from numba import njit

from .balls import BALL_RADIUS, Balls
from .errors import SceneError
from .table import Table
from .plain import plain

#: Ball numbers of the 15-ball rack, row by row from the apex (8-ball in the middle of the third row).
RACK_ORDER = (1, 9, 2, 10, 8, 3, 11, 4, 12, 5, 13, 6, 14, 7, 15)
#: Ball numbers of the 9-ball diamond, row by row from the apex (1 at the apex, 9 in the middle).
DIAMOND_ORDER = (1, 2, 3, 4, 9, 5, 6, 7, 8)
#: Candidate points drawn per batch by :func:`place_random` (one generator call per batch).
PLACE_BATCH = 8
#: Batches tried per ball before :func:`place_random` gives up.
PLACE_TRIES = 500


# --- markings -----------------------------------------------------------------------------------------------------
def head_string_x(table: Table) -> float:
    """x of the head string: the kitchen (behind the head string) is ``x < length/4``."""
    return 0.25 * table.length


def head_spot(table: Table) -> tuple[float, float]:
    """The head spot ``(length/4, width/2)``: where the cue ball is spotted."""
    return 0.25 * table.length, 0.5 * table.width


def foot_spot(table: Table) -> tuple[float, float]:
    """The foot spot ``(3 length/4, width/2)``: the apex of the rack, where object balls are re-spotted."""
    return 0.75 * table.length, 0.5 * table.width


# --- racks --------------------------------------------------------------------------------------------------------
def rack_rows(n: int) -> int:
    """Rows of the smallest triangle holding ``n`` balls."""
    rows = 1
    while rows * (rows + 1) // 2 < n:
        rows += 1
    return rows


def triangle_positions(apex: tuple[float, float], radius: float = BALL_RADIUS, rows: int = 5,
                       gap: float = 0.0) -> np.ndarray:
    """Centres of a triangle rack of ``rows`` rows pointing to ``-x`` with its apex at ``apex``.

    Neighbours touch (``gap = 0``) or sit ``gap`` metres apart. Rows are filled bottom to top.
    """
    d = 2.0 * radius + gap
    pts = []
    for row in range(rows):
        x = apex[0] + row * d * math.sqrt(3.0) / 2.0
        for k in range(row + 1):
            pts.append((x, apex[1] + (k - row / 2.0) * d))
    return np.array(pts)


def diamond_positions(apex: tuple[float, float], radius: float = BALL_RADIUS, gap: float = 0.0) -> np.ndarray:
    """Centres of the 9-ball diamond (rows of 1, 2, 3, 2, 1 balls) pointing to ``-x`` with its apex at ``apex``."""
    d = 2.0 * radius + gap
    pts = []
    for row, count in enumerate((1, 2, 3, 2, 1)):
        x = apex[0] + row * d * math.sqrt(3.0) / 2.0
        for k in range(count):
            pts.append((x, apex[1] + (k - (count - 1) / 2.0) * d))
    return np.array(pts)


def rack_balls(table: Table | None = None, cue_xy: tuple[float, float] | None = None, gap: float = 0.0,
               radius: float = BALL_RADIUS) -> Balls:
    """Cue ball plus a 15-ball triangle with its apex on the foot spot. The cue ball defaults to the head spot.
    Ids are ``cue, 1..15`` in :data:`RACK_ORDER`."""
    table = table or Table()
    rack = triangle_positions(foot_spot(table), radius, gap=gap)
    cue = cue_xy if cue_xy is not None else head_spot(table)
    pos = np.vstack([np.asarray(cue, dtype=float)[None, :], rack])
    ids = ["cue"] + [str(n) for n in RACK_ORDER]
    return Balls.from_positions(pos, ids=ids, radius=radius)


def rack_fits(table: Table, n: int, radius: float, gap: float) -> bool:
    """Whether an ``n``-ball triangle with its apex on the foot spot fits between the foot spot and the cushions."""
    rows = rack_rows(n)
    d = 2.0 * radius + gap
    depth = foot_spot(table)[0] + (rows - 1) * d * math.sqrt(3.0) / 2.0 + radius
    spread = (rows - 1) * d + 2.0 * radius
    return depth <= table.length and spread <= table.width


# --- random layouts -------------------------------------------------------------------------------------------
@njit(cache=True)
def place_rows(first, start, pos, rand_rows, regions, placed, n_placed, pockets, pocket_margin, min_dist, batch):
    """Place rows ``rand_rows[start:]`` in order, each uniformly in its region ``regions[m] = (x0, x_span, y0,
    y_span)``, from its first batch of candidates ``first[2 batch m: 2 batch (m + 1)]`` (uniform [0, 1) pairs), away
    from the pocket centres ``pockets`` (K, 2) by ``pocket_margin`` and from the first ``n_placed`` points of
    ``placed`` (fixed balls and rows placed so far; the array has room for every row) by ``min_dist``. Stops at the
    first row whose batch holds no free point. Returns ``(m, n_placed)``: that row's index (``len(rand_rows)`` when
    every row was placed) and the points placed so far."""
    nr = rand_rows.shape[0]
    for m in range(start, nr):
        if not place_row(first[2 * batch * m: 2 * batch * (m + 1)], m, pos, rand_rows, regions, placed, n_placed,
                         pockets, pocket_margin, min_dist):
            return m, n_placed
        n_placed += 1
    return nr, n_placed


@njit(cache=True)
def place_row(u, m, pos, rand_rows, regions, placed, n_placed, pockets, pocket_margin, min_dist):
    """Place row ``rand_rows[m]`` at the first free candidate of the batch ``u`` (pairs in [0, 1), mapped onto its
    region; see :func:`place_rows`), appended to ``placed``; False (nothing written) if none is free."""
    pm2 = pocket_margin * pocket_margin
    d2 = min_dist * min_dist
    x0 = regions[m, 0]
    sx = regions[m, 1]
    y0 = regions[m, 2]
    sy = regions[m, 3]
    for c in range(0, u.shape[0] - 1, 2):
        x = x0 + sx * u[c]
        y = y0 + sy * u[c + 1]
        ok = True
        for p in range(pockets.shape[0]):
            dx = x - pockets[p, 0]
            dy = y - pockets[p, 1]
            if dx * dx + dy * dy < pm2:
                ok = False
                break
        if ok:
            for h in range(n_placed):
                qx = placed[h, 0]
                qy = placed[h, 1]
                if (x - qx) * (x - qx) + (y - qy) * (y - qy) < d2:
                    ok = False
                    break
        if ok:
            row = rand_rows[m]
            pos[row, 0] = x
            pos[row, 1] = y
            placed[n_placed, 0] = x
            placed[n_placed, 1] = y
            return True
    return False


@njit(cache=True)
def place_random_rows(g, pos, rand_rows, regions, placed, n_placed, pockets, pocket_margin, min_dist, batch,
                      tries):
    """:func:`place_random` inside compiled code, drawing from the generator ``g`` (the native vector env runs it
    per table): the same draws in the same order. Returns -1, or the first row that could not be placed in
    ``tries`` batches."""
    nr = rand_rows.shape[0]
    if nr == 0:
        return -1
    first = g.random(2 * batch * nr)
    m = plain(0)  # (plain: place_rows compiled for int64, as Python calls it)
    while True:
        m, n_placed = place_rows(first, m, pos, rand_rows, regions, placed, n_placed, pockets, pocket_margin,
                                 min_dist, batch)
        if m == nr:
            return -1
        found = False
        for attempt in range(1, tries):
            if place_row(g.random(2 * batch), m, pos, rand_rows, regions, placed, n_placed, pockets,
                         pocket_margin, min_dist):
                found = True
                break
        if not found:
            return rand_rows[m]
        n_placed += 1
        m += 1


def place_random(rng: np.random.Generator, pos: np.ndarray, rows: Sequence[int],
                 regions: Sequence[tuple[float, float, float, float]] | np.ndarray,
                 fixed_points: Sequence[tuple[float, float]] | np.ndarray,
                 pockets: Sequence[tuple[float, float]] | np.ndarray, pocket_margin: float, min_dist: float) -> None:
    """Put each ball of ``rows`` (in order) uniformly at random in its region ``(x0, x_span, y0, y_span)``,
    rejecting points within ``pocket_margin`` of a pocket centre or closer than ``min_dist`` to a ball already
    placed (``fixed_points``, then earlier rows). Writes ``pos[row]``.

    All draws come from ``rng``: one call for a first batch of :data:`PLACE_BATCH` candidates for every ball, more
    only when a ball rejects its whole batch (the draws of :func:`place_random_rows`, here taken in Python: handing
    a generator to compiled code costs more than the placement). Raises :class:`SceneError` after
    :data:`PLACE_TRIES` batches.
    """
    rows_a = np.asarray(rows, dtype=np.int64).reshape(-1)
    nr = len(rows_a)
    if not nr:
        return
    fixed = np.asarray(fixed_points, dtype=float).reshape(-1, 2)
    placed = np.empty((len(fixed) + nr, 2))
    placed[:len(fixed)] = fixed
    reg = np.asarray(regions, dtype=float).reshape(-1, 4)
    pk = np.asarray(pockets, dtype=float).reshape(-1, 2)
    pocket_margin, min_dist = float(pocket_margin), float(min_dist)
    first = rng.random(2 * PLACE_BATCH * nr)
    m, n_placed = 0, len(fixed)
    while True:
        m, n_placed = place_rows(first, m, pos, rows_a, reg, placed, n_placed, pk, pocket_margin, min_dist,
                                 PLACE_BATCH)
        if m == nr:
            return
        for _ in range(1, PLACE_TRIES):
            if place_row(rng.random(2 * PLACE_BATCH), m, pos, rows_a, reg, placed, n_placed, pk, pocket_margin,
                         min_dist):
                break
        else:
            raise SceneError(f"could not place ball row {int(rows_a[m])} at random after "
                             f"{PLACE_TRIES * PLACE_BATCH} tries; use fewer balls or smaller margins")
        n_placed += 1
        m += 1


# --- re-spotting and ball in hand ----------------------------------------------------------------------------------
@njit(cache=True)
def spot_cue_row(pos, on_table, radius, row, hx, hy, width):
    """The compiled core of :func:`spot_cue_ball` (also run by the native vector env): ball ``row`` on the point
    ``(hx, hy)`` or the nearest free point of the line ``x = hx`` (outwards in y in steps of a quarter radius),
    then of lines further towards the cushion at ``x = 0``. Returns False if none is free."""
    n = pos.shape[0]
    need2 = (2.0 * radius + 1e-6) ** 2
    step = radius / 4.0
    k_max = int((0.5 * width - radius) / step)
    x = hx
    while x >= radius:
        for c in range(2 * k_max + 1):
            y = hy + step * ((c + 1) // 2) * (1 if c % 2 else -1)
            free = True
            for q in range(n):
                if q != row and on_table[q] and (x - pos[q, 0]) * (x - pos[q, 0]) + (y - pos[q, 1]) * (
                        y - pos[q, 1]) < need2:
                    free = False
                    break
            if free:
                pos[row, 0] = x
                pos[row, 1] = y
                on_table[row] = True
                return True
        x -= 2.0 * radius
    return False


def spot_cue_ball(pos: np.ndarray, on_table: np.ndarray, radius: float, table: Table, row: int = 0) -> None:
    """Put ball ``row`` (a pocketed cue ball) on the head spot, or the nearest free point along the head string
    (searching outwards in y in steps of a quarter radius), or failing that the same search on lines further
    towards the head cushion (:func:`spot_cue_row`). Sets ``pos[row]`` and ``on_table[row]``."""
    hx, hy = head_spot(table)
    if not spot_cue_row(pos, on_table, float(radius), int(row), hx, hy, float(table.width)):
        raise SceneError("could not re-spot the cue ball: the head of the table is full")  # pragma: no cover


@njit(cache=True)
def spot_object_row(pos, on_table, radius, row, fx, fy, length):
    """The compiled core of :func:`spot_object_ball` (also run by the native vector env): ball ``row`` on the point
    ``(fx, fy)`` (the foot spot) or the nearest free point of the line ``y = fy`` behind it (towards ``x =
    length``, in steps of an eighth of a radius), else in front of it. Returns False if none is free."""
    n = pos.shape[0]
    need2 = (2.0 * radius + 1e-6) ** 2
    step = radius / 8.0
    n_back = int((length - radius - fx) / step)
    n_front = int((fx - radius) / step)
    for c in range(n_back + 1 + n_front):
        x = fx + c * step if c <= n_back else fx - (c - n_back) * step
        free = True
        for q in range(n):
            if q != row and on_table[q] and (x - pos[q, 0]) * (x - pos[q, 0]) + (fy - pos[q, 1]) * (
                    fy - pos[q, 1]) < need2:
                free = False
                break
        if free:
            pos[row, 0] = x
            pos[row, 1] = fy
            on_table[row] = True
            return True
    return False


def spot_object_ball(pos: np.ndarray, on_table: np.ndarray, radius: float, table: Table, row: int) -> None:
    """Re-spot ball ``row`` (rules: a ball pocketed on a foul): on the foot spot, or if that is taken on the long
    string as close to it as possible behind it (towards the foot cushion), else in front of it
    (:func:`spot_object_row`). Sets ``pos[row]`` and ``on_table[row]``."""
    fx, fy = foot_spot(table)
    if not spot_object_row(pos, on_table, float(radius), int(row), float(fx), float(fy), float(table.length)):
        raise SceneError("could not re-spot a ball: the long string is full")  # pragma: no cover


@njit(cache=True)
def _split(x: float) -> tuple:
    t = x * 134217729.0  # Veltkamp's constant, 2^27 + 1
    hi = t - (t - x)
    return hi, x - hi


@njit(cache=True)
def _exact_product(x: float, y: float) -> tuple:
    xh, xl = _split(x)
    yh, yl = _split(y)
    p = xh * yh
    q = xh * yl + xl * yh
    z = p + q
    return z, p - z + q + xl * yl


@njit(cache=True)
def py_hypot(x: float, y: float) -> float:
    """``math.hypot(x, y)`` exactly as CPython 3.11 computes it (a scaled, compensated sum and one correction
    step: correctly rounded in nearly all cases), so compiled code agrees with Python code that uses it."""
    ax = abs(x)
    ay = abs(y)
    mx = max(ax, ay)
    if math.isinf(mx):
        return mx
    if math.isnan(x) or math.isnan(y):
        return math.nan
    if mx == 0.0:
        return mx
    _, e = math.frexp(mx)
    if e < -1023:  # subnormal: the hardware's hypot (the last bit may differ from CPython's)
        return math.hypot(x, y)
    scale = math.ldexp(1.0, -e)
    csum = 1.0
    frac1 = 0.0
    frac2 = 0.0
    for v in (ax, ay):
        v = v * scale
        ph, pl = _exact_product(v, v)
        s = csum + ph
        frac2 += (csum - s) + ph
        csum = s
        frac1 += pl
    h = math.sqrt(csum - 1.0 + (frac1 + frac2))
    ph, pl = _exact_product(-h, h)
    s = csum + ph
    frac2 += (csum - s) + ph
    csum = s
    frac1 += pl
    h += (csum - 1.0 + (frac1 + frac2)) / (2.0 * h)
    return h / scale


@njit(cache=True)
def free_discs(pos: np.ndarray, on: np.ndarray, radius: np.ndarray, row: int, holes: np.ndarray,
               clearance: float) -> np.ndarray:
    """The forbidden discs ``(D, 3)`` (x, y, radius) for ball ``row``: every other ball on the table (the two
    radii and ``clearance``), then each hole of ``holes`` (rows x, y, r: the pockets' capture circles) widened by
    ``clearance`` (see :func:`nearest_free_point`)."""
    n_on = 0
    for k in range(pos.shape[0]):
        if on[k] and k != row:
            n_on += 1
    out = np.empty((n_on + holes.shape[0], 3))
    d = 0
    for k in range(pos.shape[0]):
        if on[k] and k != row:
            out[d, 0] = pos[k, 0]
            out[d, 1] = pos[k, 1]
            out[d, 2] = radius[row] + radius[k] + clearance
            d += 1
    for h in range(holes.shape[0]):
        out[d, 0] = holes[h, 0]
        out[d, 1] = holes[h, 1]
        out[d, 2] = holes[h, 2] + clearance
        d += 1
    return out


@njit(cache=True)
def _legal(px: float, py: float, discs: np.ndarray, x0: float, x1: float, y0: float, y1: float) -> bool:
    if not (x0 <= px <= x1 and y0 <= py <= y1):
        return False
    for d in range(discs.shape[0]):
        rr = discs[d, 2] * (1.0 - 1e-12)
        if (px - discs[d, 0]) ** 2 + (py - discs[d, 1]) ** 2 < rr ** 2:
            return False
    return True


@njit(cache=True)
def _consider(qx: float, qy: float, px: float, py: float, discs: np.ndarray, x0: float, x1: float, y0: float,
              y1: float, best: np.ndarray) -> None:
    qx = min(max(qx, x0), x1)
    qy = min(max(qy, y0), y1)
    d2 = (qx - px) ** 2 + (qy - py) ** 2
    if d2 < best[2] and _legal(qx, qy, discs, x0, x1, y0, y1):  # the nearer test first: it is the cheap one
        best[0] = qx
        best[1] = qy
        best[2] = d2


@njit(cache=True)
def nearest_free(x: float, y: float, discs: np.ndarray, x0: float, x1: float, y0: float, y1: float) -> tuple:
    """The legal point nearest to ``(x, y)``: inside ``[x0, x1] x [y0, y1]`` and outside every disc of ``discs``
    (:func:`free_discs`). Returns ``(x, y, found)``. The exact nearest point of the rectangle minus the discs (see
    :func:`nearest_free_point`): the clipped point if legal, else the nearest legal one of the candidates (its
    projections onto the discs, the disc/disc and disc/edge crossings, the corners; the first of equals)."""
    px = min(max(x, x0), x1)
    py = min(max(y, y0), y1)
    if _legal(px, py, discs, x0, x1, y0, y1):
        return px, py, True
    best = np.array([0.0, 0.0, math.inf])
    nd = discs.shape[0]
    for a in range(nd):  # projections onto each disc's boundary
        cx, cy, rr = discs[a, 0], discs[a, 1], discs[a, 2]
        dx = px - cx
        dy = py - cy
        d = py_hypot(dx, dy)
        ux, uy = (dx / d, dy / d) if d > 0.0 else (1.0, 0.0)
        _consider(cx + ux * rr, cy + uy * rr, px, py, discs, x0, x1, y0, y1, best)
    for a in range(nd):  # disc/disc intersections
        ax, ay, ar = discs[a, 0], discs[a, 1], discs[a, 2]
        for b in range(a + 1, nd):
            bx, by, br = discs[b, 0], discs[b, 1], discs[b, 2]
            # Discs far apart do not cross: tested on squares first where clear-cut (margins far above round-off,
            # so that the hypot test below would say the same), most pairs without a hypot.
            far = (ar + br) * (1.0 + 1e-12)
            if (bx - ax) * (bx - ax) + (by - ay) * (by - ay) > far * far:
                continue
            d = py_hypot(bx - ax, by - ay)
            if d == 0.0 or d > ar + br or d < abs(ar - br):
                continue
            along = (ar * ar - br * br + d * d) / (2.0 * d)
            h = math.sqrt(max(ar * ar - along * along, 0.0))
            mx = ax + along * (bx - ax) / d
            my = ay + along * (by - ay) / d
            _consider(mx - h * (by - ay) / d, my + h * (bx - ax) / d, px, py, discs, x0, x1, y0, y1, best)
            _consider(mx + h * (by - ay) / d, my - h * (bx - ax) / d, px, py, discs, x0, x1, y0, y1, best)
    for a in range(nd):  # disc/edge intersections
        cx, cy, rr = discs[a, 0], discs[a, 1], discs[a, 2]
        for ex in (x0, x1):
            h2 = rr * rr - (ex - cx) ** 2
            if h2 >= 0.0:
                _consider(ex, cy + math.sqrt(h2), px, py, discs, x0, x1, y0, y1, best)
                _consider(ex, cy - math.sqrt(h2), px, py, discs, x0, x1, y0, y1, best)
        for ey in (y0, y1):
            h2 = rr * rr - (ey - cy) ** 2
            if h2 >= 0.0:
                _consider(cx + math.sqrt(h2), ey, px, py, discs, x0, x1, y0, y1, best)
                _consider(cx - math.sqrt(h2), ey, px, py, discs, x0, x1, y0, y1, best)
    for qx, qy in ((x0, y0), (x0, y1), (x1, y0), (x1, y1)):
        _consider(qx, qy, px, py, discs, x0, x1, y0, y1, best)
    if best[2] == math.inf:
        return px, py, False
    return best[0], best[1], True


def nearest_free_point(x: float, y: float, pos: np.ndarray, on_table: np.ndarray, radius: np.ndarray | float,
                       row: int, area: tuple[float, float, float, float], clearance: float = 1e-6,
                       holes: np.ndarray | None = None) -> tuple[float, float]:
    """The legal point nearest to ``(x, y)`` for ball ``row``: inside ``area = (x0, x1, y0, y1)`` (its centre's
    allowed rectangle), at least ``r_row + r_other + clearance`` from every other ball on the table, and (with
    ``holes``, rows ``(x, y, r)``: the pockets' capture circles) at least ``r + clearance`` from each hole's centre,
    so that a ball placed there does not drop at once.

    Ball in hand: an agent outputs any point, and an illegal one (off the area, overlapping a ball) moves here.
    Exact for the rectangle minus the union of the forbidden discs: the nearest point is the clipped point
    itself, its projection onto one disc's boundary, or a corner where two boundaries (disc/disc, disc/edge)
    meet; every candidate is checked and the nearest legal one returned (one compiled call: :func:`free_discs`,
    :func:`nearest_free`). Raises :class:`SceneError` if there is no legal point at all.
    """
    x0, x1, y0, y1 = area
    if not (x0 <= x1 and y0 <= y1):
        raise SceneError(f"placement area {area}: empty; x0 <= x1 and y0 <= y1 are required")
    n = len(pos)
    rad = radius if isinstance(radius, np.ndarray) and radius.dtype == np.float64 and radius.shape == (n,) else \
        np.ascontiguousarray(np.broadcast_to(np.asarray(radius, dtype=np.float64), (n,)))
    hole_rows = _NO_HOLES if holes is None else np.ascontiguousarray(holes, dtype=np.float64).reshape(-1, 3)
    px, py, ok = nearest_free_xy(float(x), float(y), np.ascontiguousarray(pos, dtype=np.float64),
                                 np.ascontiguousarray(on_table, dtype=np.bool_), np.ascontiguousarray(rad), int(row),
                                 float(x0), float(x1), float(y0), float(y1), float(clearance), hole_rows)
    if not ok:
        raise SceneError(f"no legal point for ball row {row} in the area {area}: it is covered by other balls")
    return px, py


_NO_HOLES = np.zeros((0, 3))


@njit(cache=True)
def nearest_free_xy(x: float, y: float, pos: np.ndarray, on: np.ndarray, radius: np.ndarray, row: int, x0: float,
                    x1: float, y0: float, y1: float, clearance: float, holes: np.ndarray) -> tuple:
    """:func:`nearest_free_point` on arrays (for compiled callers): ``(x, y, found)``."""
    return nearest_free(min(max(x, x0), x1), min(max(y, y0), y1), free_discs(pos, on, radius, row, holes, clearance),
                        x0, x1, y0, y1)


# --- a half-disc (e.g. snooker's D) ------------------------------------------------------------------------------
# The half-disc of radius ``r`` centred on ``(cx, cy)`` on its ``x <= cx`` side: the straight side is the line
# ``x = cx`` (snooker's baulk line), the arc faces ``x = 0``. A game gives its own geometry (games/snooker_layout.py).

def in_half_disc(x: float, y: float, cx: float, cy: float, r: float, tol: float = 1e-9) -> bool:
    """Whether ``(x, y)`` is on or within the half-disc ``(cx, cy, r)``."""
    return x <= cx + tol and (x - cx) ** 2 + (y - cy) ** 2 <= (r + tol) ** 2


def half_disc_point(u: float, v: float, cx: float, cy: float, r: float) -> tuple[float, float]:
    """The point of the half-disc ``(cx, cy, r)`` for ``(u, v)`` in ``[-1, 1]^2`` (clipped): ``u`` across (``y =
    cy - r`` at -1, ``cy + r`` at +1), ``v`` from the arc (-1) to the straight side (+1) along the line ``y`` fixed.
    A continuous one-to-one map of the square onto the half-disc, for an action's placement dims."""
    u = min(max(float(u), -1.0), 1.0)
    v = min(max(float(v), -1.0), 1.0)
    y = cy + r * u
    depth = math.sqrt(max(r * r - (r * u) ** 2, 0.0))
    return cx - depth * 0.5 * (1.0 - v), y


def nearest_point_in_half_disc(x: float, y: float, pos: np.ndarray, on_table: np.ndarray,
                               radius: np.ndarray | float, row: int, cx: float, cy: float, r: float,
                               clearance: float = 1e-6, area: str = "the half-disc") -> tuple[float, float]:
    """The legal point for ball ``row`` (a cue ball in hand) nearest to ``(x, y)``: in the half-disc ``(cx, cy, r)``
    (:func:`in_half_disc`) and at least ``r_row + r_other + clearance`` from every other ball on the table. As
    :func:`nearest_free_point` does for a rectangle: the point itself moved into the half-disc, or its projection
    onto a ball's forbidden disc, or where two boundaries meet (disc/disc, disc/straight side, disc/arc), the
    nearest legal candidate. Raises :class:`SceneError` if the half-disc is covered (``area`` names it in the
    message)."""
    rad = np.broadcast_to(np.asarray(radius, dtype=float), (len(pos),))
    discs = [(float(pos[k, 0]), float(pos[k, 1]), float(rad[row] + rad[k] + clearance))
             for k in range(len(pos)) if on_table[k] and k != row]
    discs = [q for q in discs if math.hypot(q[0] - cx, q[1] - cy) < r + q[2]]  # only those reaching into it

    def into_half_disc(px: float, py: float) -> tuple[float, float]:
        dx, dy = px - cx, py - cy
        if dx > 0.0:  # beyond the straight side: onto it, then into the half-disc
            dx = 0.0
        d = math.hypot(dx, dy)
        if d > r:
            dx, dy = dx * r / d, dy * r / d
        return cx + dx, cy + dy

    def legal(px: float, py: float) -> bool:
        return in_half_disc(px, py, cx, cy, r, 1e-12) and all(
            (px - qx) ** 2 + (py - qy) ** 2 >= (rr * (1.0 - 1e-12)) ** 2 for qx, qy, rr in discs)

    px, py = into_half_disc(x, y)
    if legal(px, py):
        return px, py
    cands: list[tuple[float, float]] = [(cx, cy - r), (cx, cy + r)]
    for qx, qy, rr in discs:
        dx, dy = px - qx, py - qy
        d = math.hypot(dx, dy)
        ux, uy = (dx / d, dy / d) if d > 0.0 else (-1.0, 0.0)
        cands.append((qx + ux * rr, qy + uy * rr))
        h2 = rr * rr - (cx - qx) ** 2  # the disc meets the straight side
        if h2 >= 0.0:
            cands += [(cx, qy + math.sqrt(h2)), (cx, qy - math.sqrt(h2))]
    circles = discs + [(cx, cy, r)]  # disc/disc and disc/arc intersections
    for a in range(len(circles)):
        ax, ay, ar = circles[a]
        for b in range(a + 1, len(circles)):
            bx, by, br = circles[b]
            d = math.hypot(bx - ax, by - ay)
            if d == 0.0 or d > ar + br or d < abs(ar - br):
                continue
            along = (ar * ar - br * br + d * d) / (2.0 * d)
            h = math.sqrt(max(ar * ar - along * along, 0.0))
            mx, my = ax + along * (bx - ax) / d, ay + along * (by - ay) / d
            cands += [(mx - h * (by - ay) / d, my + h * (bx - ax) / d),
                      (mx + h * (by - ay) / d, my - h * (bx - ax) / d)]
    best, best_d2 = None, math.inf
    for qx, qy in cands:
        qx, qy = into_half_disc(qx, qy)
        if legal(qx, qy):
            d2 = (qx - px) ** 2 + (qy - py) ** 2
            if d2 < best_d2:
                best, best_d2 = (qx, qy), d2
    if best is None:
        raise SceneError(f"no legal point in {area} for the cue ball: it is covered by other balls")
    return best


__all__ = [
    "RACK_ORDER", "DIAMOND_ORDER", "head_string_x", "head_spot", "foot_spot", "rack_rows", "triangle_positions",
    "diamond_positions", "rack_balls", "rack_fits", "place_random", "place_random_rows", "place_rows", "place_row",
    "spot_cue_ball", "spot_cue_row", "spot_object_ball", "spot_object_row",
    "nearest_free_point", "nearest_free", "nearest_free_xy", "free_discs", "py_hypot",
    "in_half_disc", "half_disc_point", "nearest_point_in_half_disc",
]
