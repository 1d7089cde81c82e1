"""The play window fits the screen's height: ``fitted_width`` and ``PlayApp`` without a width."""
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import pytest  # noqa: E402

from billiards_env import play  # noqa: E402
from billiards_env.render import window  # noqa: E402


def test_a_window_that_fits_keeps_its_width():
    assert window.fitted_width(1000, 570, 200, 1080) == 1000
    assert window.fitted_width(1000, 570, 200, None) == 1000  # no screen size known: as asked


def test_a_window_too_tall_narrows_until_it_fits():
    screen, panel = 768, 220
    w = window.fitted_width(1000, 570, panel, screen)
    assert w < 1000
    # The table image scales with the width: at the fitted width the window's height is within the screen's room.
    assert 570 * w / 1000 + panel <= screen - window.SCREEN_MARGIN
    # and one pixel wider would not fit (the widest that fits).
    assert 570 * (w + 2) / 1000 + panel > screen - window.SCREEN_MARGIN


def test_never_narrower_than_the_floor():
    assert window.fitted_width(1000, 570, 700, 768) == window.MIN_FIT_WIDTH


@pytest.mark.parametrize("env_id", ["Billiards9Ball-v0", "BilliardsOneBall-v0"])
def test_play_app_without_a_width_fits_a_small_screen(monkeypatch, env_id):
    monkeypatch.setattr(window, "screen_height", lambda: 600)
    app = play.PlayApp(env_id, seed=0, realtime=False, allow_headless=True)
    try:
        w, h = app.screen.get_size()
        assert h <= 600 - window.SCREEN_MARGIN
        assert w < play.DEFAULT_WIDTH
        assert app.renderer.size[0] == w  # the table image drawn at the narrowed width
    finally:
        app.close()


def test_play_app_keeps_a_width_it_is_given(monkeypatch):
    monkeypatch.setattr(window, "screen_height", lambda: 600)
    app = play.PlayApp("BilliardsOneBall-v0", seed=0, width=900, realtime=False, allow_headless=True)
    try:
        assert app.screen.get_size()[0] == 900
    finally:
        app.close()
