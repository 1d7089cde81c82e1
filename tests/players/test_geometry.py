"""The compiled players' geometry (players/geometry.py) chooses what the Python it replaced chose.

Reference: the Python players before the compiled geometry (``benchmarks/reference_players.py``), through their
recorded results (the ``golden`` fixture, ``tests/conftest.py``). On fixed tables (9-ball and 8-ball games after
breaks and play, random layouts, ball in hand and not, rolling, drag and spin physics) the compiled code must give
the same ghost-ball shot lists (every field), and the geometric player the same decision (place, target, pocket,
angle, speed), bit for bit.
"""
from __future__ import annotations

import contextlib
import math

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401  (registers the ids)
from billiards_env.physics import BALL_RADIUS, Balls, Physics, Simulator, Table
from billiards_env.physics.layout import nearest_free_point
from billiards_env.players import GeometricPlayer, ShotContext, ghost_ball_shots, shot_context
from billiards_env.players.geometric import choose_placement, geometric_shot
from billiards_env.players.geometry import COL_POCKET, COL_SCORE, COL_TARGET, geometric_decision, ghost_shots, table_model

from golden import reference_players as reference

R = BALL_RADIUS


def _game_tables(env_id: str, seeds: range, steps: int, **kw):
    """The env at every decision of seeded games (the agent plays the geometric player's shot, or a seeded random
    action one time in four; the built-in opponent plays its own turns)."""
    env = gym.make(env_id, **kw)
    env.action_space.seed(seeds.start)
    rng = np.random.default_rng(seeds.start)
    player = GeometricPlayer()
    try:
        for seed in seeds:
            obs, _ = env.reset(seed=seed)
            for _ in range(steps):
                yield env
                action = env.action_space.sample() if rng.random() < 0.25 else player.act(env, obs)
                obs, _, term, trunc, _ = env.step(action)
                if term or trunc:
                    break
    finally:
        env.close()


def _check_env(env, golden) -> tuple[int, bool]:
    """Compare the compiled shots and decision with the reference's on the env's table now; returns (1, ball in
    hand)."""
    ctx = shot_context(env)
    if ctx.targets:
        new = ghost_ball_shots(ctx.balls, ctx.table, ctx.physics, ctx.cue, ctx.targets, ctx.speed_range)
        golden.check(new, lambda: reference().ghost_ball_shots(ctx.balls, ctx.table, ctx.physics, ctx.cue,
                                                               ctx.targets, ctx.speed_range))
    player = GeometricPlayer()
    d = player.decide(ctx)
    assert d.pocket == (player.last.pocket if player.last is not None else -1)

    def want():
        place, angle, speed, cand = reference().reference_geometric_act(env)
        return place, angle, speed, cand

    golden.check((d.place, d.angle, d.speed, player.last), want)  # bit-identical
    return 1, ctx.place_area is not None


@pytest.mark.parametrize("env_id, friction, seeds, steps", [
    ("Billiards9Ball-v0", "rolling", range(0, 6), 12),
    ("Billiards8Ball-v0", "rolling", range(100, 103), 10),
    ("Billiards8Ball-v0", "drag", range(200, 206), 8),
    ("Billiards9Ball-v0", "spin", range(300, 304), 8),
])
def test_geometric_player_same_choices_in_games(env_id, friction, seeds, steps, golden):
    checked = in_hand = 0
    for env in _game_tables(env_id, seeds, steps, friction=friction):
        n, bih = _check_env(env, golden)
        checked += n
        in_hand += bih
    assert checked >= len(seeds) + 2 and in_hand >= 1  # breaks, ball in hand and shots from where the cue lies


@pytest.mark.slow
@pytest.mark.parametrize("env_id, friction", [("Billiards9Ball-v0", "rolling"), ("Billiards8Ball-v0", "rolling"),
                                              ("Billiards9Ball-v0", "drag"), ("Billiards8Ball-v0", "spin")])
def test_geometric_player_same_choices_in_many_games(env_id, friction, golden):
    checked = sum(_check_env(env, golden)[0]
                  for env in _game_tables(env_id, range(1000, 1060), 30, friction=friction))
    assert checked >= 100  # decisions: on real pockets a 9-ball game takes fewer than before


class _Layout:
    """Just enough of an env for the reference's ball-in-hand code: ``legal_cue_position`` and ``cue_moved_to``."""

    def __init__(self, ctx: ShotContext):
        self.ctx = ctx
        self.unwrapped = self

    def legal_cue_position(self, x: float, y: float) -> tuple[float, float]:
        b, t = self.ctx.balls, self.ctx.table
        return nearest_free_point(x, y, b.pos, b.on_table, b.radius, 0, self.ctx.place_area,
                                  holes=np.column_stack([t.pocket_xy, t.pocket_radius]))

    @contextlib.contextmanager
    def cue_moved_to(self, place):
        b = self.ctx.balls
        saved, on = b.pos[0].copy(), bool(b.on_table[0])
        b.pos[0] = place
        b.on_table[0] = True
        try:
            yield
        finally:
            b.pos[0] = saved
            b.on_table[0] = on


PHYSICS = {"rolling": Physics(), "drag": Physics(friction="drag", drag_k=0.4, min_speed=0.02),
           "spin": Physics(friction="spin")}


def _random_layout(rng: np.random.Generator, n: int, table: Table) -> np.ndarray:
    pts: list[np.ndarray] = []
    while len(pts) < n:
        p = rng.uniform([R, R], [table.length - R, table.width - R])
        if rng.random() < 0.15:  # some balls frozen on a cushion
            p[rng.integers(2)] = R
        if all(np.hypot(*(p - q)) >= 2 * R for q in pts):
            pts.append(p)
    return np.array(pts)


@pytest.mark.parametrize("law", ["rolling", "drag", "spin"])
def test_random_layouts_same_shots_and_placements(law, golden):
    rng = np.random.default_rng({"rolling": 1, "drag": 2, "spin": 3}[law])
    physics = PHYSICS[law]
    tables = (Table(), Table(length=2.24, width=1.12, cushion_restitution=0.7))
    for k in range(40):
        table = tables[k % 2]
        n = int(rng.integers(2, 12))
        balls = Balls.from_positions(_random_layout(rng, n, table))
        targets = [int(j) for j in rng.permutation(np.arange(1, n))[:int(rng.integers(1, n))]]
        speed_range = (float(rng.uniform(0.05, 1.0)), float(rng.uniform(3.0, 7.0)))
        area = (R, table.length / 4, R, table.width - R) if k % 3 == 0 else (R, table.length - R, R, table.width - R)
        ctx = ShotContext(balls, table, physics, Simulator(table, physics), 0, targets, speed_range, place_area=area)
        cut = math.radians(float(rng.choice([60.0, 80.0, 85.0])))
        golden.check(ghost_ball_shots(balls, table, physics, 0, targets, speed_range, cut),
                     lambda: reference().ghost_ball_shots(balls, table, physics, 0, targets, speed_range, cut))
        golden.check(geometric_shot(ctx, cut), lambda: reference().geometric_shot(ctx, cut))
        place = choose_placement(ctx, cut)
        golden.check(place, lambda: reference().choose_placement(_Layout(ctx), ctx, cut))
        d = geometric_decision(balls.pos, balls.on_table, balls.radius, balls.mass, np.array(targets),
                               table_model(table, physics), speed_range, area, max_cut=cut)
        assert d.place == place

        def want():
            with _Layout(ctx).cue_moved_to(place):
                return (place, *reference().geometric_shot(ctx, cut)[:2])

        golden.check((d.place, d.angle, d.speed), want)


def test_ghost_shots_rows_are_ranked_and_complete():
    # Every (ball, pocket) with a window and a cut under the limit is a row; rows are ranked by score, ties in
    # (ball, pocket) order.
    table, physics = Table(), Physics()
    balls = Balls.from_positions([[0.6, 0.6], [1.27, 0.635], [1.9, 0.3], [2.0, 1.0]])
    tm = table_model(table, physics)
    rows = ghost_shots(balls.pos, balls.on_table, balls.radius, balls.mass, 0, np.array([1, 2, 3]), *tm, 0.5, 5.0,
                       math.radians(89.0), 0.35, np.array([1.0, 0.6, 0.3, 1.8, 3.0]), True)
    assert len(rows) >= 6
    assert np.all(np.diff(rows[:, COL_SCORE]) <= 0.0)
    keys = [(int(r[COL_TARGET]), int(r[COL_POCKET])) for r in rows]
    assert len(set(keys)) == len(keys)


def test_decision_with_a_windows_cache_is_the_same_decision():
    """``geometric_decision_cached`` (the native games' opponent: each table keeps its balls' pocket windows by
    position) decides as ``geometric_decision_arrays``, bit for bit, while some balls move between decisions and
    others stay (their windows then come from the cache)."""
    from billiards_env.players.geometry import MAX_CUT, geometric_decision_arrays, geometric_decision_cached

    rng = np.random.default_rng(4)
    table, physics = Table(), PHYSICS["rolling"]
    tm = table_model(table, physics)
    n = 10
    pos = _random_layout(rng, n, table)
    on = np.ones(n, np.bool_)
    radius, mass = np.full(n, BALL_RADIUS), np.full(n, 0.17)
    cache = (np.zeros((n, 2)), np.zeros((n, tm.pocket_r.shape[0], 4)), np.zeros(n, np.bool_))
    hits = 0
    for k in range(30):
        if k:  # a few balls move (a fresh layout drawn, some of its points kept)
            fresh = _random_layout(rng, n, table)
            moved = rng.random(n) < 0.3
            candidate = np.where(moved[:, None], fresh, pos)
            if all(np.hypot(*(candidate[i] - candidate[j])) >= 2 * R for i in range(n) for j in range(i)):
                hits += int((~moved[1:]).sum())
                pos = candidate
        targets = np.arange(1, n, dtype=np.int64)
        in_hand = k % 3 == 0
        area = np.array([R, table.length - R, R, table.width - R] if in_hand else [0.0] * 4)
        args = (np.ascontiguousarray(pos), on, radius, mass, 0, targets, tm.pocket_xy, tm.pocket_r, tm.params, 0.5,
                5.0, area, in_hand, False, MAX_CUT)
        want, got = geometric_decision_arrays(*args), geometric_decision_cached(*args, *cache)
        for a, b in zip(want, got):
            assert np.array_equal(np.asarray(a), np.asarray(b))
    assert hits > 0 and cache[2][1:].all()


@pytest.mark.parametrize("pockets", ["jaws", "capture"])
def test_shots_with_only_the_windows_they_need_are_all_the_shots(pockets):
    """``ghost_shots_windowed`` (the decision from where the cue ball lies) works out a (ball, pocket) window only
    when ``tolerance_bound`` allows that shot a cut within the limit: the same rows as ``ghost_shots_from`` on every
    window, bit for bit, on a jaw table and its capture circles; the bound passes over pockets behind the balls."""
    from billiards_env.physics.scene import parse_table
    from billiards_env.players.geometry import (FALLBACK_CUT, WINDOW_SAMPLES, ghost_shots_from, ghost_shots_windowed,
                                                 model, tolerance_bound, windows_of)

    rng = np.random.default_rng(8)
    table = parse_table({"preset": "wpa", "pockets": pockets})
    tm = table_model(table, Physics())
    m = model(*tm)
    factors = np.array([1.0, 0.6, 0.3, 1.8, 3.0])
    skipped = rows_seen = 0
    for k in range(60):
        n = int(rng.integers(2, 12))
        pos = _random_layout(rng, n, table)
        on = np.ones(n, np.bool_)
        radius, mass = np.full(n, BALL_RADIUS), np.full(n, 0.17)
        targets = np.arange(1, n, dtype=np.int64)
        cx, cy = pos[0]
        want = ghost_shots_from(cx, cy, pos, on, radius, mass, 0, targets, windows_of(pos, radius, targets, m), m,
                                0.5, 5.0, FALLBACK_CUT, 0.35, factors, True)
        got = ghost_shots_windowed(cx, cy, pos, on, radius, mass, 0, targets, m, 0.5, 5.0, FALLBACK_CUT, 0.35,
                                   factors, True)
        assert np.array_equal(want, got)
        rows_seen += len(want)
        for j in targets:
            for p in range(table.n_pockets):
                a_co = math.atan2(pos[j, 1] - cy, pos[j, 0] - cx)
                skipped += tolerance_bound(pos[j, 0], pos[j, 1], 2 * R, math.hypot(pos[j, 0] - cx, pos[j, 1] - cy),
                                           a_co, table.pocket_xy[p, 0], table.pocket_xy[p, 1],
                                           table.pocket_radius[p], WINDOW_SAMPLES, math.cos(FALLBACK_CUT)) < 0.0
    assert rows_seen > 300 and skipped > 300
