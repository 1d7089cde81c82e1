"""The snooker and carom tables and their layouts (the games' own: games/snooker_layout.py, games/carom_layout.py,
on the physics' generic half-disc): pocket sizes, markings, the reds' triangle, the D, re-spotting
colours, the three-cushion opening position, and pocketless shots through every kernel."""
from __future__ import annotations

import math

import numpy as np
import pytest

from billiards_env.physics import BALL_RADIUS, Balls, Physics, Simulator, Table, validate_balls
from billiards_env.physics.batch import run_shots
from billiards_env.physics.invariants import check_shot
from billiards_env.games.carom_layout import CAROM_IDS, carom_balls, carom_start_positions
from billiards_env.games.snooker_layout import (SNOOKER_COLOURS, SNOOKER_IDS, SNOOKER_REDS, baulk_line_x, d_geometry,
                                                d_point, in_d, nearest_point_in_d, snooker_balls, snooker_rack,
                                                snooker_spots, spot_snooker_colours)
from billiards_env.physics.scene import Scene, Shot
from billiards_env.physics.table import (CAROM_BALL_MASS, CAROM_BALL_RADIUS, CORNER_POCKET_RADIUS,
                                        POOL_BALL_RADIUS, POOL_CORNER_MOUTH, POOL_SIDE_MOUTH,
                                        SIDE_POCKET_RADIUS, SNOOKER_BALL_RADIUS, SNOOKER_CORNER_MOUTH,
                                        SNOOKER_SIDE_MOUTH, capture_radii, carom_table, corner_capture_radius,
                                        corner_entry_half_width, side_capture_radius, side_entry_half_width,
                                        snooker_table)

SNK = snooker_table()
CAROM = carom_table()
RS = SNOOKER_BALL_RADIUS


# --- pocket sizes -------------------------------------------------------------------------------------------------

def test_pool_ball_radius_is_the_engines():
    assert POOL_BALL_RADIUS == BALL_RADIUS


def test_capture_radius_inverses():
    for r in (0.04, 0.047, 0.06):
        assert corner_capture_radius(corner_entry_half_width(r, RS), RS) == pytest.approx(r, rel=1e-12)
        assert side_capture_radius(side_entry_half_width(r, RS), RS) == pytest.approx(r, rel=1e-12)


def test_corner_half_width_is_where_the_ball_meets_the_cushion_on_the_circle():
    """A ball offset d from the diagonal touches the bottom cushion (y = R) at x = R + sqrt2 d: that point lies on
    the capture circle exactly at the half-width."""
    r = 0.05
    d = corner_entry_half_width(r, RS)
    assert math.hypot(RS + math.sqrt(2.0) * d, RS) == pytest.approx(r, rel=1e-12)


def test_calibration_reproduces_the_pool_table_and_scales_snooker_pockets():
    assert capture_radii(POOL_CORNER_MOUTH, POOL_SIDE_MOUTH, POOL_BALL_RADIUS) == pytest.approx(
        (CORNER_POCKET_RADIUS, SIDE_POCKET_RADIUS), rel=1e-12)
    corner, side = SNK.pocket_radius[0], SNK.pocket_radius[1]
    assert SNK.pocket_radius.tolist() == [corner, side, corner] * 2
    # the same fraction of the real entry width as on the pool table, pocket kind by kind
    k_pool = corner_entry_half_width(CORNER_POCKET_RADIUS, BALL_RADIUS) / (POOL_CORNER_MOUTH / 2 - BALL_RADIUS)
    k_snk = corner_entry_half_width(corner, RS) / (SNOOKER_CORNER_MOUTH / 2 - RS)
    assert k_snk == pytest.approx(k_pool, rel=1e-12)
    k_pool = side_entry_half_width(SIDE_POCKET_RADIUS, BALL_RADIUS) / (POOL_SIDE_MOUTH / 2 - BALL_RADIUS)
    k_snk = side_entry_half_width(side, RS) / (SNOOKER_SIDE_MOUTH / 2 - RS)
    assert k_snk == pytest.approx(k_pool, rel=1e-12)
    # snooker pockets are tighter for their balls than pool pockets
    assert corner / RS < CORNER_POCKET_RADIUS / BALL_RADIUS and side / RS < SIDE_POCKET_RADIUS / BALL_RADIUS


def test_a_mouth_narrower_than_the_ball_is_refused():
    with pytest.raises(ValueError, match="corner_mouth"):
        capture_radii(0.05, 0.09, RS)


def test_snooker_and_carom_tables():
    assert (SNK.length, SNK.width, SNK.n_pockets) == (3.569, 1.778, 6)
    assert (CAROM.length, CAROM.width, CAROM.n_pockets) == (2.84, 1.42, 0)
    assert CAROM == Table(2.84, 1.42).without_pockets()


@pytest.mark.parametrize("pocket, start", [(2, (3.2, 0.3)), (1, (1.7845, 0.6))])
def test_a_straight_pot_drops_into_a_snooker_pocket(pocket, start):
    """A ball rolled straight at a corner (along its diagonal) or square into a middle pocket drops; offset
    by more than the entry half-width it does not (it meets the cushion first)."""
    target = SNK.pocket_xy[pocket]
    sim = Simulator(SNK, Physics())
    ang = math.atan2(target[1] - start[1], target[0] - start[0])
    res = sim.run(Balls.from_positions([start], ids=["cue"], radius=RS).strike("cue", ang, 2.0))
    assert res.pocket[0] == pocket
    half = (corner_entry_half_width if pocket != 1 else side_entry_half_width)(SNK.pocket_radius[pocket], RS)
    normal = np.array([-math.sin(ang), math.cos(ang)])
    off = np.asarray(start) + (half + 0.004) * normal * (1 if pocket == 1 else -1)
    res = sim.run(Balls.from_positions([off], ids=["cue"], radius=RS).strike("cue", ang, 2.0))
    assert res.pocket[0] == -1


# --- snooker markings and the opening layout -------------------------------------------------------------------------

def test_snooker_markings():
    spots = snooker_spots(SNK)
    cx, cy, r = d_geometry(SNK)
    assert baulk_line_x(SNK) == cx == pytest.approx(0.737) and r == pytest.approx(0.292) and cy == SNK.width / 2
    assert spots["brown"] == (cx, cy)
    assert spots["yellow"] == pytest.approx((cx, cy - r))  # on the right seen from the baulk end (+x ahead)
    assert spots["green"] == pytest.approx((cx, cy + r))
    assert spots["blue"] == pytest.approx((SNK.length / 2, cy))
    assert SNK.length - spots["black"][0] == pytest.approx(0.324)
    assert spots["pink"][0] == pytest.approx(0.5 * (spots["blue"][0] + SNK.length))


def test_markings_scale_with_the_table():
    small = Table(SNK.length / 2, SNK.width / 2)
    assert snooker_spots(small)["black"] == pytest.approx(tuple(0.5 * np.array(snooker_spots(SNK)["black"])))


def test_reds_triangle_touches_itself_but_not_the_pink():
    rack = snooker_rack(SNK)
    reds = np.array([rack[i] for i in SNOOKER_REDS])
    pink = np.array(rack["pink"])
    d = np.hypot(*(reds[:, None, :] - reds[None, :, :]).transpose(2, 0, 1))
    np.fill_diagonal(d, np.inf)
    assert d.min() == pytest.approx(2 * RS, abs=1e-12)  # a tight triangle
    assert np.all((d < 2 * RS + 1e-9).sum(axis=1) >= 2)  # every red touches at least two others
    gaps = np.hypot(*(reds - pink).T) - 2 * RS
    assert 0.0 < gaps.min() < 0.005  # the apex red sits just behind the pink without touching it
    assert reds[:, 0].min() > pink[0] and reds[:, 0].max() < rack["black"][0] - 2 * RS
    back = reds[-5:]
    assert np.allclose(back[:, 0], back[0, 0])  # the back row is parallel to the top cushion


def test_snooker_balls_are_a_valid_scene():
    b = snooker_balls(SNK)
    assert b.ids == SNOOKER_IDS and len(b) == 22
    validate_balls(b, SNK)
    assert in_d(*b.pos[0], SNK)


# --- the D ---------------------------------------------------------------------------------------------------------

def test_d_point_maps_the_square_onto_the_half_disc():
    cx, cy, r = d_geometry(SNK)
    assert d_point(-1, 1, SNK) == pytest.approx((cx, cy - r))
    assert d_point(1, -1, SNK) == pytest.approx((cx, cy + r))
    assert d_point(0, -1, SNK) == pytest.approx((cx - r, cy))
    assert d_point(0, 1, SNK) == pytest.approx((cx, cy))
    for u in np.linspace(-1, 1, 9):
        for v in np.linspace(-1, 1, 9):
            assert in_d(*d_point(u, v, SNK), SNK)
    assert d_point(5, 5, SNK) == d_point(1, 1, SNK)  # clipped


def test_nearest_point_in_d():
    b = snooker_balls(SNK)
    pos, on = b.pos.copy(), b.on_table.copy()
    cx, cy, r = d_geometry(SNK)
    # a free point in the D stays; a point beyond the baulk line moves onto it; a point outside the arc onto it
    assert nearest_point_in_d(cx - 0.1, cy - 0.1, pos, on, RS, 0, SNK) == (cx - 0.1, cy - 0.1)
    assert nearest_point_in_d(cx + 0.5, cy - 0.1, pos, on, RS, 0, SNK) == pytest.approx((cx, cy - 0.1))
    p = nearest_point_in_d(cx - 1.0, cy, pos, on, RS, 0, SNK)
    assert p == pytest.approx((cx - r, cy))
    # on the brown spot: pushed to touching distance from the brown, still in the D
    x, y = nearest_point_in_d(cx - 0.01, cy, pos, on, RS, 0, SNK)
    assert in_d(x, y, SNK) and math.hypot(x - cx, y - cy) == pytest.approx(2 * RS + 1e-6, rel=1e-6)
    assert math.hypot(x - (cx - 0.01), y - cy) < 2 * RS  # and near where it was asked for


def test_nearest_point_in_d_raises_when_the_d_is_covered():
    cx, cy, r = d_geometry(SNK)
    grid = [(x, y) for x in np.arange(cx - r, cx + 0.06, 0.05) for y in np.arange(cy - r - 0.02, cy + r + 0.06, 0.05)]
    pos = np.array([(0.3, 0.3)] + grid)
    with pytest.raises(ValueError, match="no legal point in the D"):
        nearest_point_in_d(cx - 0.1, cy, pos, np.ones(len(pos), bool), RS, 0, SNK)


# --- re-spotting colours -------------------------------------------------------------------------------------------

def _table_with(extra: dict[str, tuple[float, float]]) -> tuple[np.ndarray, np.ndarray, dict[str, int]]:
    """Rows: the six colours (off the table, to be spotted), then the balls of ``extra`` on the table."""
    pos = np.zeros((6 + len(extra), 2))
    on = np.zeros(len(pos), bool)
    for k, xy in enumerate(extra.values()):
        pos[6 + k] = xy
        on[6 + k] = True
    return pos, on, {c: k for k, c in enumerate(SNOOKER_COLOURS)}


def test_colour_goes_on_its_own_spot():
    pos, on, rows = _table_with({})
    spot_snooker_colours(pos, on, RS, SNK, {"blue": rows["blue"]})
    assert on[rows["blue"]] and tuple(pos[rows["blue"]]) == snooker_spots(SNK)["blue"]


def test_colour_whose_spot_is_taken_goes_on_the_highest_free_spot():
    spots = snooker_spots(SNK)
    pos, on, rows = _table_with({"r1": spots["yellow"], "r2": (spots["black"][0] + 0.01, spots["black"][1])})
    spot_snooker_colours(pos, on, RS, SNK, {"yellow": rows["yellow"]})
    assert tuple(pos[rows["yellow"]]) == spots["pink"]  # black's spot is taken (a red touches it): the pink's


def test_own_spots_first_then_the_highest_value_takes_precedence():
    spots = snooker_spots(SNK)
    pos, on, rows = _table_with({"r1": spots["black"], "r2": spots["green"]})
    spot_snooker_colours(pos, on, RS, SNK, {"pink": rows["pink"], "black": rows["black"], "green": rows["green"]})
    assert tuple(pos[rows["pink"]]) == spots["pink"]  # its own spot is free
    assert tuple(pos[rows["black"]]) == spots["blue"]  # the highest free spot once the pink is on its own
    assert tuple(pos[rows["green"]]) == spots["brown"]


def test_all_spots_taken_colour_goes_towards_the_top_cushion():
    spots = snooker_spots(SNK)
    pos, on, rows = _table_with({f"b{k}": xy for k, xy in enumerate(spots.values())})
    spot_snooker_colours(pos, on, RS, SNK, {"blue": rows["blue"]})
    x, y = pos[rows["blue"]]
    assert y == spots["blue"][1] and spots["blue"][0] + 2 * RS <= x < spots["blue"][0] + 2 * RS + RS / 4


def test_black_with_no_room_above_goes_below_its_spot():
    spots = snooker_spots(SNK)
    bx, by = spots["black"]
    above = {f"a{k}": (x, by) for k, x in enumerate(np.arange(bx + 0.01, SNK.length - RS, 2 * RS))}
    pos, on, rows = _table_with({**{f"b{k}": xy for k, xy in enumerate(spots.values())}, **above})
    spot_snooker_colours(pos, on, RS, SNK, {"black": rows["black"]})
    x, y = pos[rows["black"]]
    assert y == by and bx - 2 * RS - RS / 4 < x <= bx - 2 * RS


# --- three-cushion opening ------------------------------------------------------------------------------------------

def test_carom_opening_position():
    p = carom_start_positions(CAROM, breaker=0, side=1)
    assert p["red"] == (0.75 * 2.84, 0.71) and p["yellow"] == (0.71, 0.71)
    assert p["white"] == pytest.approx((0.71, 0.71 + 0.182))
    q = carom_start_positions(CAROM, breaker=1, side=-1)
    assert q["white"] == (0.71, 0.71) and q["yellow"] == pytest.approx((0.71, 0.71 - 0.182))
    b = carom_balls(CAROM)
    assert b.ids == CAROM_IDS and np.all(b.radius == CAROM_BALL_RADIUS) and np.all(b.mass == CAROM_BALL_MASS)
    validate_balls(b, CAROM)
    with pytest.raises(ValueError, match="breaker"):
        carom_start_positions(CAROM, breaker=2)


# --- pocketless shots through every kernel --------------------------------------------------------------------------

LAWS = {"rolling": Physics(), "drag": Physics(friction="drag", drag_k=0.4, min_speed=0.01),
        "spin": Physics(friction="spin")}


@pytest.mark.parametrize("law", list(LAWS))
@pytest.mark.parametrize("solver", ["exact", "step"])
def test_pocketless_shots_run_terminate_and_pass_the_invariants(law, solver):
    spin = law == "spin"
    balls = carom_balls(CAROM)
    for k, (angle, speed) in enumerate([(0.25, 5.0), (2.0, 3.0), (-1.3, 6.0)]):
        shot = Shot("white", angle, speed, 0.3 * spin, -0.2 * spin)
        scene = Scene(CAROM, LAWS[law], balls, shot, solver=solver, max_time=120.0)
        res = scene.run(record=True)
        rep = check_shot(scene, res)
        assert res.status == "rest" and rep.ok, (k, rep.violations)
        assert np.all(res.pocket == -1) and res.balls.on_table.all()
        assert res.events.kind.size and not np.any(res.events.kind == 2)  # events, no pocket event


@pytest.mark.parametrize("law", ["rolling", "spin"])
def test_pocketless_batch_equals_single_shots(law):
    phys = LAWS[law]
    sim = Simulator(CAROM, phys)
    balls = carom_balls(CAROM)
    angles = np.linspace(-3.0, 3.0, 7)
    side = np.linspace(-0.3, 0.3, 7) if law == "spin" else None
    res = run_shots(sim, balls, angles, 4.0, ball="white", side=side)
    assert np.all(res.status == 0) and np.all(res.pocket == -1)
    for k in (0, 3, 6):
        one = sim.run(balls.strike("white", angles[k], 4.0, side=0.0 if side is None else side[k]))
        assert np.array_equal(one.balls.pos, res.pos[k])
