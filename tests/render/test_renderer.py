"""Tests of the rendering layer: frame geometry, ball colours, pockets, cue line, sampling, GIF/PNG, window."""
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

import numpy as np  # noqa: E402
import pygame  # noqa: E402
import pytest  # noqa: E402
from PIL import Image  # noqa: E402

from billiards_env.physics.table import Table  # noqa: E402
from billiards_env.render import (  # noqa: E402
    HumanWindow, TableRenderer, ball_colour, frame_times, is_stripe, write_gif, write_png,
)
from billiards_env.render.table_renderer import BORDER  # noqa: E402

R = 0.028575  # pool ball radius (m)
# cue ball, a solid (3), a stripe (11), another solid (5): well apart, away from cushions and spots
NUMBERS = [0, 3, 11, 5]
POSITIONS = np.array([[0.60, 0.40], [1.50, 0.90], [1.90, 0.35], [2.10, 0.80]])


@pytest.fixture(scope="module")
def table() -> Table:
    return Table()


@pytest.fixture(scope="module")
def renderer(table: Table) -> TableRenderer:
    return TableRenderer(table, R, width_px=800)


def pixel(array: np.ndarray, r: TableRenderer, xy) -> np.ndarray:
    """The pixel of ``array`` at table point ``xy`` (metres)."""
    col, row = r.to_pixels(np.asarray(xy, dtype=float))[0]
    return array[row, col]


def is_cloth_green(rgb: np.ndarray) -> bool:
    r, g, b = (int(c) for c in rgb)
    return g > r + 40 and g > b + 20


# --- frame geometry ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("width_px", [320, 800, 1237])
def test_array_shape_dtype_and_size_follow_width(table: Table, width_px: int) -> None:
    r = TableRenderer(table, R, width_px=width_px)
    array = r.render_array(POSITIONS, np.ones(4, bool), NUMBERS)
    assert array.dtype == np.uint8
    assert array.shape == (r.height_px, width_px, 3)
    assert array.flags.c_contiguous
    assert r.size == (width_px, r.height_px)
    aspect = (table.width + 2 * BORDER) / (table.length + 2 * BORDER)
    assert abs(r.table_height_px - aspect * width_px) <= 1.0
    assert r.height_px >= r.table_height_px


def test_render_array_matches_surfarray_layout(renderer: TableRenderer) -> None:
    surface = renderer.draw(POSITIONS, np.ones(4, bool), NUMBERS, cue=(0.6, 0.4, 0.3))
    expected = pygame.surfarray.array3d(surface).transpose(1, 0, 2)
    array = renderer.render_array(POSITIONS, np.ones(4, bool), NUMBERS, cue=(0.6, 0.4, 0.3))
    np.testing.assert_array_equal(array, expected)


def test_to_pixels_flips_y_and_scales(renderer: TableRenderer, table: Table) -> None:
    corners = renderer.to_pixels(np.array([[0.0, 0.0], [table.length, table.width]]))
    (c0, r0), (c1, r1) = corners
    assert r0 > r1, "table y = 0 must be at the bottom of the image"
    assert c0 < c1
    assert abs((c1 - c0) - table.length * renderer.pixels_per_metre) <= 1
    assert abs((r0 - r1) - table.width * renderer.pixels_per_metre) <= 1
    assert renderer.to_pixels(np.array([1.0, 0.5])).shape == (1, 2)


def test_rendering_never_opens_a_display(renderer: TableRenderer) -> None:
    renderer.render_array(POSITIONS, np.ones(4, bool), NUMBERS, cue=(0.6, 0.4, 0.0))
    assert not pygame.display.get_init()


# --- balls ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("width_px", [400, 800, 1600])
def test_ball_centre_pixels_have_ball_colours(table: Table, width_px: int) -> None:
    r = TableRenderer(table, R, width_px=width_px)
    array = r.render_array(POSITIONS, np.ones(4, bool), NUMBERS)
    for xy, number in zip(POSITIONS, NUMBERS):
        assert tuple(pixel(array, r, xy)) == ball_colour(number), f"ball {number} at width {width_px}"


def test_ball_is_drawn_with_its_size(renderer: TableRenderer) -> None:
    """Around the solid 3 (red), pixels inside its radius are reddish, pixels well outside are cloth."""
    array = renderer.render_array(POSITIONS, np.ones(4, bool), NUMBERS)
    x, y = POSITIONS[1]
    inside = pixel(array, renderer, (x - 0.6 * R, y + 0.2 * R))
    outside = pixel(array, renderer, (x - 1.8 * R, y + 0.2 * R))
    assert inside[0] > inside[1] + 60
    assert is_cloth_green(outside)


def test_stripe_has_white_body_and_coloured_band(renderer: TableRenderer) -> None:
    array = renderer.render_array(POSITIONS, np.ones(4, bool), NUMBERS)
    col, row = renderer.to_pixels(POSITIONS[2])[0]
    rr = int(renderer.pixels_per_metre * R * 0.75)
    patch = array[row - rr:row + rr + 1, col - rr:col + rr + 1].reshape(-1, 3).astype(int)
    whiteish = np.all(patch > 200, axis=1).sum()
    band = np.all(np.abs(patch - np.array(ball_colour(11))) < 30, axis=1).sum()
    assert whiteish > 5 and band > 5


def test_pocketed_ball_is_not_drawn(renderer: TableRenderer) -> None:
    on = np.ones(4, bool)
    empty = renderer.render_array(np.zeros((0, 2)), np.zeros(0, bool), [])
    drawn = renderer.render_array(POSITIONS, on, NUMBERS)
    on[3] = False
    pocketed = renderer.render_array(POSITIONS, on, NUMBERS)
    assert tuple(pixel(drawn, renderer, POSITIONS[3])) == ball_colour(5)
    cloth = pixel(pocketed, renderer, POSITIONS[3])
    np.testing.assert_array_equal(cloth, pixel(empty, renderer, POSITIONS[3]))
    assert is_cloth_green(cloth)


def test_pocketed_ball_goes_to_the_tray(renderer: TableRenderer) -> None:
    on = np.ones(4, bool)
    all_on = renderer.render_array(POSITIONS, on, NUMBERS)
    on[1] = False
    one_off = renderer.render_array(POSITIONS, on, NUMBERS)
    tray_all, tray_one = all_on[renderer.table_height_px:], one_off[renderer.table_height_px:]
    assert renderer.tray_height_px > 0
    assert np.any(tray_all != tray_one)
    reds = np.all(np.abs(tray_one.astype(int) - ball_colour(3)) < 40, axis=-1).sum()
    assert reds > 10


def test_bad_state_is_rejected(renderer: TableRenderer) -> None:
    with pytest.raises(ValueError, match="numbers"):
        renderer.draw(POSITIONS, np.ones(4, bool), [0, 1, 2])
    with pytest.raises(ValueError, match="0-15"):
        renderer.draw(POSITIONS, np.ones(4, bool), [0, 1, 2, 26])
    with pytest.raises(ValueError, match="shape"):
        renderer.draw(np.zeros((4, 3)), np.ones(4, bool), NUMBERS)


# --- cue ----------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("angle", [0.0, np.pi / 2, 2.5])
def test_cue_line_is_drawn_along_the_shot(renderer: TableRenderer, angle: float) -> None:
    start = np.array([1.27, 0.40]) if angle == np.pi / 2 else np.array([0.60, 0.40])
    positions, on, numbers = start[None], np.ones(1, bool), [0]
    plain = renderer.render_array(positions, on, numbers)
    aimed = renderer.render_array(positions, on, numbers, cue=(start[0], start[1], angle))
    direction = np.array([np.cos(angle), np.sin(angle)])
    ahead = [start + direction * d for d in (0.08, 0.15, 0.3, 0.5)]
    ahead = [p for p in ahead if 0.05 < p[0] < 2.49 and 0.05 < p[1] < 1.22]
    assert len(ahead) >= 2
    for p in ahead:
        assert np.any(pixel(aimed, renderer, p) != pixel(plain, renderer, p)), f"no aim line at {p}"
    side = start + np.array([-direction[1], direction[0]]) * 0.3  # perpendicular: untouched
    np.testing.assert_array_equal(pixel(aimed, renderer, side), pixel(plain, renderer, side))
    assert tuple(pixel(aimed, renderer, start)) == ball_colour(0)


def test_cue_stick_lies_behind_the_cue_ball(renderer: TableRenderer) -> None:
    start = np.array([1.2, 0.6])
    plain = renderer.render_array(start[None], np.ones(1, bool), [0])
    aimed = renderer.render_array(start[None], np.ones(1, bool), [0], cue=(1.2, 0.6, 0.0))
    behind = start - np.array([0.3, 0.0])
    assert np.abs(pixel(aimed, renderer, behind).astype(int) - pixel(plain, renderer, behind)).sum() > 60


# --- colours ------------------------------------------------------------------------------------------------
def test_colours_of_the_ball_set() -> None:
    assert [is_stripe(n) for n in (0, 1, 8, 9, 15)] == [False, False, False, True, True]
    assert all(ball_colour(n + 8) == ball_colour(n) for n in range(1, 8))
    assert len({ball_colour(n) for n in range(9)}) == 9
    with pytest.raises(ValueError):
        ball_colour(26)


# --- time sampling --------------------------------------------------------------------------------------
def test_frame_times_whole_number_of_frames() -> None:
    t = frame_times(1.0, 30)
    assert len(t) == 31
    assert t[0] == 0.0 and t[-1] == 1.0
    np.testing.assert_allclose(np.diff(t), 1 / 30, rtol=1e-9)


def test_frame_times_end_exactly_at_duration() -> None:
    t = frame_times(0.1234, 30.0)
    assert t[0] == 0.0 and t[-1] == 0.1234
    np.testing.assert_allclose(np.diff(t)[:-1], 1 / 30, rtol=1e-9)
    assert 0 < t[-1] - t[-2] <= 1 / 30
    assert np.all(np.diff(t) > 0)


def test_frame_times_edge_cases() -> None:
    np.testing.assert_array_equal(frame_times(0.0, 30), [0.0])
    assert frame_times(0.1, 30)[-1] == 0.1 and len(frame_times(0.1, 30)) == 4
    with pytest.raises(ValueError):
        frame_times(1.0, 0.0)
    with pytest.raises(ValueError):
        frame_times(-1.0, 30)


# --- files --------------------------------------------------------------------------------------------------
def test_write_gif_round_trip(tmp_path, renderer: TableRenderer) -> None:
    frames = [renderer.render_array(POSITIONS + [dx, 0.0], np.ones(4, bool), NUMBERS) for dx in (0.0, 0.05, 0.1)]
    path = write_gif(frames, tmp_path / "clip" / "shot.gif", fps=25)
    assert path.exists()
    with Image.open(path) as gif:
        assert gif.n_frames == 3
        assert gif.size == (renderer.width_px, renderer.height_px)
        assert gif.info.get("loop") == 0
        gif.seek(2)
        last = np.asarray(gif.convert("RGB"))
    centre = pixel(last, renderer, POSITIONS[1] + [0.1, 0.0])
    assert np.abs(centre.astype(int) - ball_colour(3)).max() <= 8  # palette keeps the ball's colour


def test_write_gif_rejects_empty_and_bad_frames(tmp_path) -> None:
    with pytest.raises(ValueError, match="no frames"):
        write_gif([], tmp_path / "empty.gif")
    with pytest.raises(ValueError, match="uint8"):
        write_gif([np.zeros((4, 4, 3), float)], tmp_path / "bad.gif")


def test_write_png_round_trip(tmp_path) -> None:
    frame = np.random.default_rng(0).integers(0, 256, (12, 20, 3), dtype=np.uint8)
    path = write_png(frame, tmp_path / "f.png")
    np.testing.assert_array_equal(np.asarray(Image.open(path).convert("RGB")), frame)


# --- window -------------------------------------------------------------------------------------------------
def test_human_window_shows_frames_and_closes_twice(renderer: TableRenderer) -> None:
    window = HumanWindow(renderer.size, title="test", allow_headless=True)
    try:
        assert not window.closed
        window.show(renderer.draw(POSITIONS, np.ones(4, bool), NUMBERS), fps=120)
        window.show(renderer.render_array(POSITIONS, np.ones(4, bool), NUMBERS), fps=None)
        assert pygame.display.get_init()
        assert not window.closed
        shown = pygame.surfarray.array3d(pygame.display.get_surface()).transpose(1, 0, 2)
        assert tuple(pixel(shown, renderer, POSITIONS[1])) == ball_colour(3)
    finally:
        window.close()
        window.close()
    assert window.closed
    assert not pygame.display.get_init()
    window.show(renderer.draw(POSITIONS, np.ones(4, bool), NUMBERS), fps=30)  # no-op once closed


def test_human_window_notices_quit_event() -> None:
    window = HumanWindow((64, 48), allow_headless=True)
    try:
        assert not window.closed
        pygame.event.post(pygame.event.Event(pygame.QUIT))
        assert window.closed
    finally:
        window.close()


@pytest.mark.parametrize("driver", ["dummy", "offscreen"])
def test_human_window_draws_invisibly_on_a_driver_the_user_chose(monkeypatch, driver: str) -> None:
    """SDL_VIDEODRIVER=dummy (how pygame programs run in CI) asks for an invisible window: no project variable is
    needed, as with Gymnasium's own pygame envs; nobody watches, so frames are not paced."""
    from billiards_env.render.window import ALLOW_HEADLESS_ENV

    monkeypatch.setenv("SDL_VIDEODRIVER", driver)
    monkeypatch.delenv(ALLOW_HEADLESS_ENV, raising=False)
    with HumanWindow((64, 48)) as window:
        assert not window.closed and pygame.display.get_driver() == driver
        assert not window.paced
        window.show(np.zeros((48, 64, 3), np.uint8), fps=0.5)  # would wait 2 s if paced
    assert not pygame.display.get_init()


def test_human_window_refuses_the_silent_fallback_of_a_machine_without_display(monkeypatch) -> None:
    """No driver chosen and no display server answering: pygame falls back to 'offscreen' without a word, and a
    program would wait on a window nobody sees. That stays an error saying what to do."""
    from billiards_env.render.window import ALLOW_HEADLESS_ENV, HeadlessDisplayError

    monkeypatch.delenv("SDL_VIDEODRIVER", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    monkeypatch.delenv(ALLOW_HEADLESS_ENV, raising=False)
    monkeypatch.setenv("DISPLAY", ":97")  # no X server there
    with pytest.raises(HeadlessDisplayError, match="no X server answered at DISPLAY=:97.*rgb_array.*"
                                                   "SDL_VIDEODRIVER=dummy"):
        HumanWindow((64, 48))
    assert not pygame.display.get_init()
    monkeypatch.setenv(ALLOW_HEADLESS_ENV, "1")  # the opt-in billiards-play's tests use
    with HumanWindow((64, 48)) as window:
        assert not window.closed and pygame.display.get_driver() == "offscreen"
    monkeypatch.setenv("WAYLAND_DISPLAY", "wayland-97")  # no compositor either: SDL falls back to offscreen
    monkeypatch.delenv(ALLOW_HEADLESS_ENV)
    with pytest.raises(HeadlessDisplayError, match="offscreen.*no display server answered"):
        HumanWindow((64, 48))


def test_human_window_without_any_display_says_what_to_do(monkeypatch) -> None:
    from billiards_env.render import window as window_module

    monkeypatch.setattr(window_module.sys, "platform", "linux")
    for var in ("SDL_VIDEODRIVER", "DISPLAY", "WAYLAND_DISPLAY", window_module.ALLOW_HEADLESS_ENV):
        monkeypatch.delenv(var, raising=False)
    with pytest.raises(window_module.HeadlessDisplayError, match="DISPLAY and WAYLAND_DISPLAY are unset.*"
                                                                 "SDL_VIDEODRIVER=dummy"):
        HumanWindow((64, 48))
    assert not pygame.display.get_init()
