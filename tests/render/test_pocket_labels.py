"""The pocket numbers (a called pocket in 8-ball and straight pool) sit inside the table image, beside their own
pocket, clear of its hole and of each other."""
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import billiards_env  # noqa: E402,F401


@pytest.mark.parametrize("env_id", ["Billiards8Ball-v0", "BilliardsStraightPool-v0", "BilliardsOneBall-v0"])
@pytest.mark.parametrize("width", [400, 766, 1000])
def test_every_label_is_inside_the_image_beside_its_pocket(env_id, width):
    env = gym.make(env_id, render_mode="rgb_array", render_width=width)
    r = env.unwrapped.renderer
    centres, size = r.pocket_label_centres()
    half = 0.62 * size  # the label disc's radius
    pockets = r.to_pixels_float(np.asarray(r.table.pocket_xy, dtype=float))
    holes = np.asarray(r.table.pocket_radius) * r.pixels_per_metre
    assert centres.shape == pockets.shape
    assert np.all(centres - half >= 0.0)
    assert np.all(centres[:, 0] + half <= r.width_px) and np.all(centres[:, 1] + half <= r.table_height_px)
    d = np.linalg.norm(centres[:, None, :] - pockets[None, :, :], axis=2)
    assert np.all(np.argmin(d, axis=1) == np.arange(len(pockets)))  # nearest its own pocket
    assert np.all(np.diag(d) >= holes)  # not over its hole
    apart = np.linalg.norm(centres[:, None, :] - centres[None, :, :], axis=2) + np.eye(len(centres)) * 1e9
    assert np.all(apart >= 2 * half)  # no two labels overlap
    env.close()
