"""A game's plain balls are drawn in the colours its session declares (its palette, handed to the renderer as
data), not from a list of games in the renderer."""
from __future__ import annotations

import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import billiards_env  # noqa: E402,F401
from billiards_env.games.carom import CaromSession  # noqa: E402
from billiards_env.games.snooker import SnookerSession  # noqa: E402
from billiards_env.physics import BALL_RADIUS, Table  # noqa: E402
from billiards_env.render import TableRenderer, ball_colour  # noqa: E402

POSITIONS = np.array([[0.60, 0.40], [1.50, 0.90], [1.90, 0.35]])


def test_a_plain_ball_is_drawn_in_its_palettes_colour_at_its_centre():
    r = TableRenderer(Table(), BALL_RADIUS, width_px=800, palette={30: (10, 200, 240)})
    frame = r.render_array(POSITIONS, np.ones(3, bool), [0, 30, 5])
    col, row = r.to_pixels(POSITIONS[1])[0]
    assert tuple(frame[row, col]) == (10, 200, 240) == ball_colour(30, r.palette)
    col, row = r.to_pixels(POSITIONS[2])[0]
    assert tuple(frame[row, col]) == ball_colour(5)  # the pool set is unchanged
    turned = r.render_array(POSITIONS, np.ones(3, bool), [0, 30, 5], orientations=np.tile(np.eye(3), (3, 1, 1)))
    assert tuple(turned[row, col]) == ball_colour(5)


def test_a_number_outside_the_pool_set_and_the_palette_is_refused():
    with pytest.raises(ValueError, match=r"0-15 .*got 16"):
        TableRenderer(Table(), BALL_RADIUS, width_px=300).render_array(POSITIONS, np.ones(3, bool), [0, 16, 5])
    with pytest.raises(ValueError, match="drawing numbers > 15"):
        TableRenderer(Table(), BALL_RADIUS, width_px=300, palette={3: (1, 2, 3)})
    with pytest.raises(ValueError, match="palette"):
        TableRenderer(Table(), BALL_RADIUS, width_px=300, palette={20: (1, 2)})


@pytest.mark.parametrize("env_id, session", [("BilliardsSnooker-v0", SnookerSession),
                                             ("BilliardsThreeCushion-v0", CaromSession)])
def test_the_games_hand_their_palettes_to_the_renderer(env_id, session):
    env = gym.make(env_id, render_mode="rgb_array", render_width=400)
    env.reset(seed=0)
    env.render()
    u = env.unwrapped
    assert u.renderer.palette == session.palette and set(session.palette) >= set(u.ball_numbers) - set(range(16))
    env.close()
