"""The native games' geometric decision skips shots by a bound (players/geometry.py ``best_shot_cached``) and must
play what ranking every shot plays.

``geometric_choice_cached`` (the native vector env's opponent) tries the (ball, pocket) shots in order and passes
over a shot, before its pocket window, when ``tolerance_bound`` says its ease cannot beat the best score so far (or
allows it no cut within the limit), and ``shot_row`` drops it before its paths and speeds when its ease cannot. Here,
on random layouts (capture and jaw tables; rolling and drag; balls moving between decisions, so the windows cache
is both used and refreshed; ball in hand and not; a cut limit low enough that the 88 degree fallback or the direct
hit is played), its decision must be ``geometric_decision_arrays``' (every shot ranked), bit for bit: the place,
the aim, the speed, the status and the played shot's whole row. A bound that pruned a shot that would have won
fails here.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from billiards_env.physics import BALL_RADIUS, Physics, Table
from billiards_env.physics.pocket_specs import SNOOKER_12FT, WPA_9FT
from billiards_env.physics.table import jaw_table
from billiards_env.players.geometry import (COL_CUT, MAX_CUT, N_COLS, WIN_FOUND, WIN_UNKNOWN, geometric_choice_cached,
                                            geometric_decision_arrays, table_model)

R = BALL_RADIUS
TABLES = {"capture": Table(), "wpa_jaws": jaw_table(WPA_9FT), "snooker_jaws": jaw_table(SNOOKER_12FT)}
PHYSICS = {"rolling": Physics(), "drag": Physics(friction="drag", drag_k=0.4, min_speed=0.02)}


def _layout(rng: np.random.Generator, n: int, table: Table, keep: np.ndarray | None = None,
            old: np.ndarray | None = None) -> np.ndarray:
    """``n`` balls apart on ``table`` (the rows of ``old`` where ``keep`` stay): some frozen on a cushion, some
    next to another ball (blocked paths), the rest anywhere."""
    out = np.zeros((n, 2))
    placed: list[np.ndarray] = []
    fresh = []
    for i in range(n):
        if keep is not None and old is not None and keep[i]:
            out[i] = old[i]
            placed.append(old[i])
        else:
            fresh.append(i)
    for i in fresh:
        while True:
            if placed and rng.random() < 0.3:
                a = rng.uniform(0.0, 2.0 * math.pi)
                p = placed[int(rng.integers(len(placed)))] + (2.0 * R + rng.uniform(0.0, 0.02)) * np.array(
                    [math.cos(a), math.sin(a)])
            else:
                p = rng.uniform([R, R], [table.length - R, table.width - R])
                if rng.random() < 0.15:
                    p[rng.integers(2)] = R
            inside = R <= p[0] <= table.length - R and R <= p[1] <= table.width - R
            if inside and all(np.hypot(*(p - q)) >= 2.0 * R for q in placed):
                out[i] = p
                placed.append(p)
                break
    return out


@pytest.mark.parametrize("table_name", list(TABLES))
@pytest.mark.parametrize("law", list(PHYSICS))
def test_bounded_decision_plays_what_every_shot_ranked_plays(table_name, law):
    table = TABLES[table_name]
    tm = table_model(table, PHYSICS[law])
    k_p = tm.pocket_r.shape[0]
    rng = np.random.default_rng(sum(map(ord, table_name + law)))
    seen = {"within": 0, "fallback": 0, "direct": 0, "in_hand": 0, "skipped_windows": 0}
    for game in range(8):
        n = int(rng.integers(3, 17))
        radius, mass = np.full(n, R), np.full(n, 0.17)
        cache = (np.zeros((n, 2)), np.zeros((n, k_p, 4)), np.zeros(n, np.bool_))  # one table's, kept all game
        pos = _layout(rng, n, table)
        for k in range(12):
            if k:  # some balls move, the others keep their cached windows
                pos = _layout(rng, n, table, keep=rng.random(n) < 0.6, old=pos)
            on = rng.random(n) < 0.9
            on[0] = True
            targets = (1 + rng.permutation(n - 1))[:int(rng.integers(1, n))].astype(np.int64)
            in_hand = rng.random() < 0.3
            area = np.array([R, table.length - R, R, table.width - R] if in_hand else [0.0] * 4)
            max_cut = MAX_CUT if rng.random() < 0.7 else math.radians(float(rng.uniform(5.0, 40.0)))
            args = (np.ascontiguousarray(pos), on, radius, mass, 0, targets, tm.pocket_xy, tm.pocket_r, tm.params,
                    0.5, 5.0, area, in_hand, False, max_cut)
            want = geometric_decision_arrays(*args)
            got = geometric_choice_cached(*args, *cache)
            wx, wy, wplaced, wangle, wspeed, wk, wrows, wstatus = want
            gx, gy, gplaced, gangle, gspeed, gk, grows, gstatus = got
            assert (gx, gy, gplaced, gangle, gspeed, gstatus) == (wx, wy, wplaced, wangle, wspeed, wstatus)
            assert grows.shape[1] == N_COLS
            if wk >= 0:
                assert gk == 0 and grows.shape[0] == 1
                assert np.array_equal(grows[0], wrows[wk])
                seen["within" if wrows[wk, COL_CUT] <= max_cut else "fallback"] += 1
            else:
                assert gk == -1 and grows.shape[0] == 0
                seen["direct"] += wstatus == 0
            seen["in_hand"] += in_hand
            seen["skipped_windows"] += int((cache[1][:, :, WIN_FOUND] == WIN_UNKNOWN).sum())
    # Every branch of the choice was compared, and the bound did pass over windows.
    assert all(v > 0 for v in seen.values()), seen
