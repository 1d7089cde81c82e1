"""The renderer's spin and game marks: turned ball sprites, the integration of spins into orientations, the tip
diagram, the game panel and its marks on the table."""
import math
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from billiards_env.physics.table import Table  # noqa: E402
from billiards_env.render import TableRenderer  # noqa: E402
from billiards_env.render import colors as C  # noqa: E402
from billiards_env.render.animation import (  # noqa: E402
    MAX_SPIN_STEPS, SPIN_STEP, _rotations, integrate_orientations, spin_times,
)
from billiards_env.render.hud import panel_height  # noqa: E402
from billiards_env.render.overlays import TIP_DOT, tip_from_point, tip_point  # noqa: E402
from billiards_env.render.sprites import OrientedSprites, _shade, _shading_terms, ball_rgba  # noqa: E402

R = 0.028575
NUMBERS = [0, 1, 9, 8]
POSITIONS = np.array([[0.50, 0.60], [1.60, 0.70], [1.90, 0.35], [2.20, 0.95]])
HUD = {"game": "9-ball", "players": ("agent", "geometric"), "shooter": 0, "groups": None,
       "ball_in_hand": "kitchen", "kitchen_x": 0.635, "call": "FOUL: scratch (geometric)", "foul": True,
       "winner": None, "wins": (1, 2), "pocketed": ((2, 3), (4,)), "targets": (1,), "call_pocket": False,
       "called_pocket": None}


def rz(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


@pytest.fixture(scope="module")
def table() -> Table:
    return Table()


def crop(frame: np.ndarray, r: TableRenderer, xy, radius_px: float) -> np.ndarray:
    col, row = r.to_pixels(np.asarray(xy, dtype=float))[0]
    k = int(radius_px)
    return frame[row - k:row + k + 1, col - k:col + k + 1].astype(int)


# --- turned sprites ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("radius_px", [5.3, 11.0])
def test_turned_sprite_at_rest_is_the_rest_sprite(radius_px: float) -> None:
    """The identity orientation draws every ball as the cached sprite at rest (same supersampling)."""
    maker = OrientedSprites(radius_px, supersample=3)
    turned = maker.rgba(list(range(16)), np.tile(np.eye(3), (16, 1, 1)), cue_dots=False)
    for n in range(16):
        assert np.abs(turned[n].astype(int) - ball_rgba(n, radius_px, supersample=3).astype(int)).max() <= 1, n


def test_shading_is_linear_in_the_albedo() -> None:
    """The turned sprites' shading (gain, base) is the rest sprites' shading written as albedo * gain + base."""
    rng = np.random.default_rng(0)
    u, v = rng.uniform(-1, 1, (2, 500))
    r = np.hypot(u, v)
    albedo = rng.uniform(0, 255, (500, 3))
    gain, base = _shading_terms(u, v, r)
    np.testing.assert_allclose(_shade(albedo, u, v, r), albedo * gain[:, None] + base, rtol=1e-12, atol=1e-9)


def test_spin_about_the_vertical_turns_the_number_disc_with_it() -> None:
    """A ball turned by 90 degrees about the vertical shows its number disc turned by 90 degrees (counter-
    clockwise on the image, as on the table: y is up in both), and a whole turn gives the ball at rest back."""
    maker = OrientedSprites(20.0)
    rest, quarter, whole = maker.rgba([3, 3, 3], np.stack([np.eye(3), rz(math.pi / 2), rz(2 * math.pi)]))

    def disc_angle(sprite: np.ndarray) -> float:
        disc = np.all(np.abs(sprite[..., :3].astype(int) - C.NUMBER_DISC) < 40, axis=-1) & (sprite[..., 3] == 255)
        rows, cols = np.nonzero(disc)
        c = maker.half
        return math.atan2(-(rows.mean() - c), cols.mean() - c)  # table orientation: rows grow downwards

    turn = (disc_angle(quarter) - disc_angle(rest)) % (2 * math.pi)
    assert turn == pytest.approx(math.pi / 2, abs=math.radians(6))
    assert np.mean(np.any(whole != rest, axis=-1)) < 0.01


def disc_centre(sprite: np.ndarray) -> np.ndarray:
    """Column and row of the middle of a sprite's number disc."""
    disc = np.all(np.abs(sprite[..., :3].astype(int) - C.NUMBER_DISC) < 40, axis=-1) & (sprite[..., 3] == 255)
    rows, cols = np.nonzero(disc)
    return np.array([cols.mean(), rows.mean()])


@pytest.mark.parametrize("number", [1, 3, 6])
def test_rolling_carries_the_disc_the_way_the_ball_rolls(number: int) -> None:
    """Turned as by rolling towards +x (spin about +y) the disc moves right on the image; towards -y (spin about
    +x) it moves down (the image shows table y = 0 at the bottom)."""
    maker = OrientedSprites(20.0)
    rest, east, south = maker.rgba([number] * 3, np.stack([np.eye(3), _rotations(np.array([0.0, 0.3, 0.0])),
                                                           _rotations(np.array([0.3, 0.0, 0.0]))]))
    assert disc_centre(east)[0] > disc_centre(rest)[0] + 2 and abs(disc_centre(east)[1] - disc_centre(rest)[1]) < 1
    assert disc_centre(south)[1] > disc_centre(rest)[1] + 2 and abs(disc_centre(south)[0] - disc_centre(rest)[0]) < 1


def test_cue_ball_dots_show_under_the_spin_model_only() -> None:
    maker = OrientedSprites(15.0)
    dotted, plain = maker.rgba([0], np.eye(3)[None], cue_dots=True)[0], maker.rgba([0], np.eye(3)[None],
                                                                                      cue_dots=False)[0]
    def reds(sprite: np.ndarray) -> int:
        return int((np.all(np.abs(sprite[..., :3].astype(int) - (196, 30, 36)) < 60, axis=-1)
                    & (sprite[..., 3] > 0)).sum())

    assert reds(dotted) > 5
    assert reds(plain) == 0  # no dot without cue_dots


def test_renderer_redraws_only_turned_balls(table: Table) -> None:
    r = TableRenderer(table, R, width_px=400)
    on = np.ones(4, bool)
    rest = np.tile(np.eye(3), (4, 1, 1))
    first = r.render_array(POSITIONS, on, NUMBERS, orientations=rest)
    turned = rest.copy()
    turned[1] = rz(1.0) @ _rotations(np.array([0.7, -0.3, 0.0]))
    second = r.render_array(POSITIONS, on, NUMBERS, orientations=turned)
    rp = R * r.pixels_per_metre * 0.8
    assert np.any(crop(first, r, POSITIONS[1], rp) != crop(second, r, POSITIONS[1], rp))  # ball 1 turned
    for k in (0, 2, 3):
        np.testing.assert_array_equal(crop(first, r, POSITIONS[k], rp), crop(second, r, POSITIONS[k], rp))
    with pytest.raises(ValueError, match="orientations"):
        r.render_array(POSITIONS, on, NUMBERS, orientations=np.eye(3))


# --- spins integrated into orientations ------------------------------------------------------------------------
def test_constant_spin_turns_by_omega_t() -> None:
    t = np.linspace(0.0, 2.0, 9)
    w = np.zeros((9, 2, 3))
    w[:, 0] = [0.0, 0.0, 3.0]  # ball 0 spins about the vertical at 3 rad/s
    turned = integrate_orientations(np.tile(np.eye(3), (2, 1, 1)), t, w)
    for k, tk in enumerate(t):
        np.testing.assert_allclose(turned[k, 0], rz(3.0 * tk), atol=1e-12)
        assert np.array_equal(turned[k, 1], np.eye(3))  # no spin: the orientation is kept bit for bit


def test_spin_slowing_down_linearly_turns_by_its_integral() -> None:
    """w(t) = w0 - a t about a fixed axis: the angle is w0 t - a t^2 / 2 (the interval mean is exact here)."""
    axis = np.array([1.0, 2.0, -2.0]) / 3.0
    t = np.linspace(0.0, 1.5, 31)
    w = ((8.0 - 4.0 * t)[:, None] * axis)[:, None, :]
    turned = integrate_orientations(np.eye(3)[None], t, w)
    angle = 8.0 * t[-1] - 2.0 * t[-1] ** 2
    np.testing.assert_allclose(turned[-1, 0], _rotations(angle * axis), atol=1e-12)
    np.testing.assert_allclose(turned[-1, 0] @ turned[-1, 0].T, np.eye(3), atol=1e-12)  # still a rotation


def test_a_rolling_ball_carries_its_top_forward() -> None:
    """Rolling along +x (w = (0, v/R, 0)) the point on top moves towards +x, and after rolling one circumference
    every point is back."""
    v = 1.0
    period = 2 * math.pi * R / v
    t = np.linspace(0.0, period, 201)
    w = np.tile([0.0, v / R, 0.0], (201, 1, 1))
    turned = integrate_orientations(np.eye(3)[None], t, w)
    top = turned[:, 0] @ np.array([0.0, 0.0, 1.0])
    assert top[5, 0] > 0.0 and top[5, 2] > 0.9
    np.testing.assert_allclose(turned[-1, 0], np.eye(3), atol=1e-9)


def test_spin_times_hold_every_frame_time() -> None:
    times = np.array([0.0, 0.05, 0.1, 2.0, 2.01])
    fine, at = spin_times(times)
    np.testing.assert_array_equal(fine[at], times)
    assert np.all(np.diff(fine) > 0)
    gaps = np.diff(fine)
    short = np.r_[gaps[: at[2]], gaps[at[3]:]]
    assert short.max() <= SPIN_STEP * (1 + 1e-9)  # short intervals: steps of at most SPIN_STEP
    assert at[4] - at[3] == 3 and at[3] - at[2] == MAX_SPIN_STEPS  # a long one is capped


# --- the tip diagram --------------------------------------------------------------------------------------------
def red_pixels(frame: np.ndarray, box: tuple[int, int, int, int]) -> np.ndarray:
    x0, y0, x1, y1 = box
    patch = frame[y0:y1, x0:x1].astype(int)
    rows, cols = np.nonzero(np.all(np.abs(patch - TIP_DOT) < 50, axis=-1))
    return np.stack([cols + x0, rows + y0], axis=1)


@pytest.mark.parametrize("tip", [(0.4, 0.0), (-0.3, 0.2), (0.0, -0.45)])
def test_tip_diagram_puts_the_dot_where_the_tip_struck(table: Table, tip) -> None:
    r = TableRenderer(table, R, width_px=800)
    on = np.ones(4, bool)
    plain = r.render_array(POSITIONS, on, NUMBERS)
    drawn = r.render_array(POSITIONS, on, NUMBERS, tip=tip)
    (cx, cy), rad = r.tip_diagram
    box = (int(cx - rad - 2), int(cy - rad - 2), int(cx + rad + 3), int(cy + rad + 3))
    dot = red_pixels(drawn, box)
    assert len(dot) >= 3 and len(red_pixels(plain, box)) == 0
    np.testing.assert_allclose(dot.mean(axis=0), tip_point((cx, cy), rad, *tip), atol=1.0)
    assert np.all(drawn[: r.table_height_px] == plain[: r.table_height_px])  # only the tray changes


def test_tip_from_point_inverts_tip_point_and_clamps() -> None:
    c, rad = (50.0, 40.0), 20.0
    assert tip_from_point(tuple(tip_point(c, rad, 0.2, -0.1)), c, rad, 0.5) == pytest.approx((0.2, -0.1))
    side, top = tip_from_point((c[0] + 3 * rad, c[1] - 4 * rad), c, rad, 0.5)  # far outside: onto the rim
    assert math.hypot(side, top) == pytest.approx(0.5) and side / top == pytest.approx(0.75)


# --- the game panel and its table marks ------------------------------------------------------------------------
def test_panel_adds_its_height_and_pot_frames_keep_theirs(table: Table) -> None:
    plain = TableRenderer(table, R, width_px=600)
    game = TableRenderer(table, R, width_px=600, hud=True)
    assert game.hud_height_px == panel_height(600) > 0 and plain.hud_height_px == 0
    assert game.size == (600, plain.height_px + game.hud_height_px)
    on = np.ones(4, bool)
    frame = game.render_array(POSITIONS, on, NUMBERS, hud=HUD)
    assert frame.shape == (game.height_px, 600, 3)
    with pytest.raises(ValueError, match="hud=True"):
        plain.draw(POSITIONS, on, NUMBERS, hud=HUD)


def test_panel_shows_the_names_the_call_and_the_pocketed_balls(table: Table) -> None:
    r = TableRenderer(table, R, width_px=800, hud=True)
    on = np.ones(4, bool)
    frame = r.render_array(POSITIONS, on, NUMBERS, hud=HUD)
    panel = frame[r.hud_rect.top + 1:].astype(int)
    bright = np.all(panel > 200, axis=-1).sum()
    assert bright > 100  # names and words
    blue = np.all(np.abs(panel - C.ball_colour(2)) < 40, axis=-1).sum()  # ball 2, pocketed by the agent
    assert blue > 10
    legal = r.render_array(POSITIONS, on, NUMBERS, hud={**HUD, "call": "agent: pocketed 2", "foul": False})
    other = legal[r.hud_rect.top + 1:].astype(int)
    changed = np.any(other != panel, axis=-1)
    assert changed[:, r.width_px // 2:].any() and not changed[:, : r.width_px // 2].any()  # the call, right
    red = (242, 92, 78)
    assert np.all(np.abs(panel - red) < 40, axis=-1).sum() > np.all(np.abs(other - red) < 40, axis=-1).sum() + 50


def test_table_marks_kitchen_target_ring_and_pockets_to_call(table: Table) -> None:
    r = TableRenderer(table, R, width_px=800, hud=True)
    on = np.ones(4, bool)
    quiet = {**HUD, "ball_in_hand": False, "kitchen_x": None, "targets": ()}
    base = r.render_array(POSITIONS, on, NUMBERS, hud=quiet)
    kitchen = r.render_array(POSITIONS, on, NUMBERS, hud={**quiet, "kitchen_x": 0.635})
    line = [(0.635, y) for y in (0.2, 0.9, 1.1)]
    for xy in line:
        col, row = r.to_pixels(np.array(xy))[0]
        assert kitchen[row, col].sum() > base[row, col].sum() + 120  # a bright line on the head string
    col, row = r.to_pixels(np.array([1.5, 0.2]))[0]
    np.testing.assert_array_equal(kitchen[row, col], base[row, col])  # right of the head string: untouched
    ringed = r.render_array(POSITIONS, on, NUMBERS, hud={**quiet, "targets": (1,)})
    around = POSITIONS[1] + 1.5 * R * np.array([[1, 0], [0, 1], [-1, 0], [0, -1]])
    for xy in around:
        col, row = r.to_pixels(xy)[0]
        assert ringed[row, col, 0] > base[row, col, 0] + 80  # yellow ring around the target
    other = POSITIONS[2] + np.array([1.5 * R, 0.0])
    col, row = r.to_pixels(other)[0]
    np.testing.assert_array_equal(ringed[row, col], base[row, col])
    calling = r.render_array(POSITIONS, on, NUMBERS, hud={**quiet, "call_pocket": True, "called_pocket": 2})
    assert np.any(calling[: r.table_height_px] != base[: r.table_height_px])
    col, row = r.to_pixels(table.pocket_xy[2] + np.array([0.0, 0.0]))[0]
    ring_px = r.to_pixels(table.pocket_xy[2] + np.array([-1.25 * table.pocket_radius[2], 0.0]))[0]
    assert calling[ring_px[1], ring_px[0], 0] > base[ring_px[1], ring_px[0], 0] + 80  # the called pocket
