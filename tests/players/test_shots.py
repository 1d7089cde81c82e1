"""The geometric aimer by construction: build the balls, let it choose, simulate its shot with the exact solver."""
from __future__ import annotations

import math

import numpy as np
import pytest

from billiards_env.players import ShotContext, geometric_shot, search_shot, SearchSettings
from billiards_env.players.shots import ghost_ball_shots, pocket_window, segment_blocked, speed_to_travel, travel_distance
from billiards_env.physics import BALL_RADIUS, Balls, Physics, Simulator, Table

R = BALL_RADIUS
TABLE = Table()
PHYS = Physics()
SIM = Simulator(TABLE, PHYS)
BOTTOM_SIDE = 1  # pocket order: bottom-left, bottom-side, bottom-right, top-left, top-side, top-right
TOP_RIGHT = 5


def _ctx(positions, speed_range=(0.5, 5.0)) -> ShotContext:
    balls = Balls.from_positions(positions)
    return ShotContext(balls, TABLE, PHYS, SIM, 0, list(range(1, len(balls))), speed_range)


def _play(ctx: ShotContext, angle: float, speed: float):
    return SIM.run(ctx.balls.strike(0, angle, speed))


def test_straight_shot_into_side_pocket():
    # Object ball 0.4 m above the bottom side pocket, cue ball straight behind it.
    x = TABLE.length / 2
    ctx = _ctx([[x, 0.9], [x, 0.4]])
    angle, speed, cand = geometric_shot(ctx)
    assert cand is not None and cand.pocket == BOTTOM_SIDE and cand.target == 1
    assert cand.cut < math.radians(1.0)
    assert abs(angle - (-math.pi / 2)) < 1e-3  # straight down
    res = _play(ctx, angle, speed)
    assert res.pocket[1] == BOTTOM_SIDE  # the object ball drops in the aimed pocket
    assert res.pocket[0] == -1  # and the cue ball stays on the table
    assert res.first_contact(0) == 1


def test_thirty_degree_cut_into_corner_pocket():
    # Object ball on the diagonal of the top-right corner; the cue ball placed so that the cut is 30 degrees.
    P = TABLE.pocket_xy[TOP_RIGHT]
    u = np.array([1.0, 1.0]) / math.sqrt(2.0)
    Obj = P - 0.6 * u
    G = Obj - 2 * R * u
    rot = math.radians(30.0)
    w = np.array([u[0] * math.cos(rot) - u[1] * math.sin(rot), u[0] * math.sin(rot) + u[1] * math.cos(rot)])
    C = G - 0.7 * w  # cue path direction w is 30 degrees off the object's path u
    ctx = _ctx([C, Obj])
    angle, speed, cand = geometric_shot(ctx)
    assert cand is not None and cand.pocket == TOP_RIGHT
    assert abs(math.degrees(cand.cut) - 30.0) < 2.0
    res = _play(ctx, angle, speed)
    assert res.pocket[1] == TOP_RIGHT
    assert res.pocket[0] == -1
    # The aim matters: 1.5 degrees off, the same shot misses the pocket.
    miss = _play(ctx, angle + math.radians(1.5), speed)
    assert miss.pocket[1] != TOP_RIGHT


def test_blocked_path_is_flagged_and_avoided():
    x = TABLE.length / 2
    free = ghost_ball_shots(Balls.from_positions([[x, 0.9], [x, 0.5]]), TABLE, PHYS, 0, [1], (0.5, 5.0))
    # A third ball sits between the object ball and the bottom side pocket.
    ctx = _ctx([[x, 0.9], [x, 0.5], [x, 0.25]])
    shots = ghost_ball_shots(ctx.balls, TABLE, PHYS, 0, [1], (0.5, 5.0))
    side = next(s for s in shots if s.pocket == BOTTOM_SIDE)
    side_free = next(s for s in free if s.pocket == BOTTOM_SIDE)
    assert side_free.clear and not side.clear
    assert math.isclose(side.score, side_free.score / 10.0)
    # With the cue ball off to the side, a clear pot into a corner beats the blocked side pocket.
    ctx2 = _ctx([[0.7, 0.9], [x, 0.5], [x, 0.25]])
    ctx2 = ShotContext(ctx2.balls, TABLE, PHYS, SIM, 0, [1], (0.5, 5.0))  # ball 1 only (the blocker is ball 2)
    angle, speed, cand = geometric_shot(ctx2)
    assert cand is not None and cand.target == 1 and cand.clear and cand.pocket != BOTTOM_SIDE
    res = _play(ctx2, angle, speed)
    assert res.pocket[1] == cand.pocket and res.pocket[0] == -1


@pytest.mark.parametrize("start", [(0.27, 0.3), (0.9, 0.6), (1.27, 0.5), (2.0, 0.15), (1.7, 0.06)])
def test_pocket_window_matches_the_simulator(start):
    # A lone ball rolled along the window's centre and edges drops in the bottom side pocket; outside, it doesn't.
    Obj = np.array(start)
    win = pocket_window(Obj, R, TABLE, BOTTOM_SIDE)
    assert win is not None
    centre, half, _ = win
    for off, should_drop in ((0.0, True), (0.8 * half, True), (-0.8 * half, True), (1.6 * half, False),
                             (-1.6 * half, False)):
        ang = centre + off
        balls = Balls.from_positions([Obj], velocities=[[2.0 * math.cos(ang), 2.0 * math.sin(ang)]])
        res = SIM.run(balls)
        dropped_here = res.pocket[0] == BOTTOM_SIDE and res.events.kind[0] == 2  # first event: the pocket
        assert dropped_here == should_drop, (start, off / half)


def test_pocket_window_from_straight_above_is_wide():
    win = pocket_window(np.array([TABLE.length / 2, 0.5]), R, TABLE, BOTTOM_SIDE)
    assert win is not None and win[1] > math.radians(3.0)
    assert abs(win[0] + math.pi / 2) < 1e-9


def test_speed_model_matches_the_rolling_law():
    v = speed_to_travel(2.0, 0.3, PHYS)
    assert math.isclose(v * v, 0.3 ** 2 + 2 * PHYS.deceleration * 2.0)
    assert math.isclose(travel_distance(v, PHYS), 2.0 + 0.3 ** 2 / (2 * PHYS.deceleration))
    drag = Physics(friction="drag", drag_k=0.5)
    assert math.isclose(speed_to_travel(2.0, 0.3, drag), 0.3 + 0.5 * 2.0)


def test_segment_blocked():
    a, b = np.array([0.0, 0.0]), np.array([1.0, 0.0])
    assert segment_blocked(a, b, np.array([[0.5, 0.05]]), np.array([0.06]))
    assert not segment_blocked(a, b, np.array([[0.5, 0.2]]), np.array([0.06]))
    assert not segment_blocked(a, b, np.zeros((0, 2)), np.zeros(0))


def test_search_player_finds_a_pot_the_geometric_aimer_scratches_or_misses():
    # Random layouts with the env's margins: the search player pots at least as often as the aimer.
    rng = np.random.default_rng(3)
    wins = {"geometric": 0, "search": 0}
    settings = SearchSettings(n_geometric=4, sweep_angles=24, robust_samples=2, top_k=3)
    for _ in range(15):
        while True:
            p = np.column_stack([rng.uniform(0.1, TABLE.length - 0.1, 2), rng.uniform(0.1, TABLE.width - 0.1, 2)])
            if np.hypot(*(p[0] - p[1])) > 3 * R and np.min(np.hypot(*(TABLE.pocket_xy[:, None] - p[None]).T)) > 0.15:
                break
        ctx = _ctx(p)
        for name, (a, s) in (("geometric", geometric_shot(ctx)[:2]), ("search", search_shot(ctx, settings)[:2])):
            res = _play(ctx, a, s)
            wins[name] += int(res.pocket[1] >= 0 and res.pocket[0] < 0)
    assert wins["search"] >= wins["geometric"]
    assert wins["search"] >= 13


@pytest.mark.parametrize("cut_deg", [0.0, 15.0, 45.0, 60.0])
def test_cut_angles_pot_by_construction(cut_deg):
    P = TABLE.pocket_xy[BOTTOM_SIDE]
    u = np.array([0.0, -1.0])
    Obj = P - 0.5 * u
    G = Obj - 2 * R * u
    rot = math.radians(cut_deg)
    w = np.array([u[0] * math.cos(rot) - u[1] * math.sin(rot), u[0] * math.sin(rot) + u[1] * math.cos(rot)])
    ctx = _ctx([G - 0.5 * w, Obj])
    angle, speed, cand = geometric_shot(ctx)
    res = _play(ctx, angle, speed)
    assert cand is not None and res.pocket[1] >= 0 and res.pocket[0] == -1
