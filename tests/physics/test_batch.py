"""The batch API (``physics/batch.py``): every row is bit-identical to the single ``Simulator.run`` of the same shot,
for each model; the summaries (first contact, cushions, event counts) agree with the event log; the result does not
depend on the thread count; bad input gets a clear error."""
from __future__ import annotations

import math

import numba
import numpy as np
import pytest

from billiards_env.physics import Balls, Physics, SceneError, Simulator, Table
from billiards_env.physics.batch import N_KINDS, run_shots, run_tables
from billiards_env.physics.codes import EV_COLLISION, EV_CUSHION, STATUS_NAMES
from billiards_env.physics.layout import rack_balls
from billiards_env.rules.summary import summarize_result
from physics_helpers import drag, pool, rolling

MODELS = {"rolling": rolling(), "drag": drag(0.5, 0.01), "spin": Physics(friction="spin")}


def _scene() -> Balls:
    """Cue ball and three object balls, two near pockets (so shots pocket, scratch, miss and bank)."""
    return Balls.from_positions([[0.62, 0.58], [1.9, 0.95], [2.3, 0.18], [1.2, 1.1]])


def _shots(n: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    return rng.uniform(-math.pi, math.pi, n), rng.uniform(0.3, 6.0, n)


def _assert_row_is(res, k: int, single, struck: int = 0) -> None:
    """Row ``k`` of a batch result equals the single ``ShotResult`` bit for bit, summaries included."""
    assert STATUS_NAMES[res.status[k]] == single.status
    assert res.time[k] == single.time and res.n_events[k] == single.n_events
    assert np.array_equal(res.pos[k], single.balls.pos) and np.array_equal(res.vel[k], single.balls.vel)
    assert np.array_equal(res.on_table[k], single.balls.on_table)
    assert np.array_equal(res.pocket[k], single.pocket)
    assert np.array_equal(res.pocketed_at[k], single.pocketed_at, equal_nan=True)
    if res.ang is not None:
        assert np.array_equal(res.ang[k], single.balls.ang)
    ev = single.events
    assert res.first_contact[k] == single.first_contact(struck)
    assert np.array_equal(res.event_counts[k], np.bincount(ev.kind, minlength=N_KINDS))
    assert np.array_equal(res.cushions[k], np.bincount(ev.ball[ev.kind == EV_CUSHION], minlength=len(single.pocket)))
    if res.events is not None:
        log = res.events.row(k)
        for f in ("time", "kind", "ball", "other", "speed"):
            assert np.array_equal(getattr(log, f), getattr(ev, f)), f


@pytest.mark.parametrize("model", sorted(MODELS))
def test_candidate_shots_equal_single_runs(model):
    table = pool()
    sim = Simulator(table, MODELS[model])
    balls = _scene()
    angles, speeds = _shots(40, seed=1)
    kw = {}
    if model == "spin":
        rng = np.random.default_rng(2)
        kw = {"side": rng.uniform(-0.3, 0.3, 40), "top": rng.uniform(-0.35, 0.35, 40)}
        kw["side"][:5] = 0.0
        kw["top"][:5] = 0.0
    before = balls.copy()
    res = run_shots(sim, balls, angles, speeds, events=True, **kw)
    fast = run_shots(sim, balls, angles, speeds, **kw)  # the summaries-only path
    for k in range(40):
        spin = {} if not kw else {"side": kw["side"][k], "top": kw["top"][k]}
        single = sim.run(balls.strike("cue", angles[k], speeds[k], **spin))
        _assert_row_is(res, k, single)
        _assert_row_is(fast, k, single)
    assert np.array_equal(balls.pos, before.pos) and np.array_equal(balls.vel, before.vel)  # input untouched
    # The shots really differ: some pocket a ball, some hit nothing first, some bank off cushions.
    assert res.pocketed[:, 1:].any() and (res.first_contact == -1).any() and (res.first_contact > 0).any()
    assert res.cushions.sum() > 0


def test_tables_in_place_equal_single_runs_with_long_logs():
    """Independent tables (a rack break among them: its log outgrows the first buffer) simulated in place."""
    table = pool()
    sim = Simulator(table, rolling())
    rack = rack_balls(table)
    n, nb = 6, len(rack)
    starts = []
    rng = np.random.default_rng(3)
    for k in range(n):
        b = rack.copy()
        if k % 2:  # some tables with object balls already pocketed
            b.on_table[rng.choice(np.arange(1, nb), 4, replace=False)] = False
        starts.append(b.strike("cue", rng.uniform(-0.05, 0.05), rng.uniform(3.0, 8.0)))
    pos = np.stack([b.pos for b in starts])
    vel = np.stack([b.vel for b in starts])
    on = np.stack([b.on_table for b in starts])
    res = run_tables(sim, pos, vel, on, rack.radius, rack.mass, events=True, validate=True, ids=rack.ids)
    assert res.pos is pos and res.on_table is on  # in place
    for k, b in enumerate(starts):
        _assert_row_is(res, k, sim.run(b))
    assert res.events.offsets[-1] > 16 * n + 16  # the log outgrew its first buffer (16 events a row)


def test_rail_after_contact_matches_the_rules_summary():
    table = pool()
    sim = Simulator(table, rolling())
    balls = _scene()
    angles, speeds = _shots(60, seed=4)
    res = run_shots(sim, balls, angles, speeds)
    checked = 0
    for k in range(60):
        summary = summarize_result(sim.run(balls.strike("cue", angles[k], speeds[k])), np.arange(len(balls)))
        assert tuple(np.flatnonzero(res.rail_after_contact[k]).tolist()) == summary.rail_balls
        assert (res.first_contact[k] if res.first_contact[k] >= 0 else None) == summary.first_contact
        checked += bool(summary.rail_balls)
    assert checked > 5


def test_radius_per_table_and_struck_ball_per_row():
    table = pool()
    sim = Simulator(table, rolling())
    b1 = Balls.from_positions([[0.6, 0.6], [1.5, 0.6]], radius=0.028575).strike(1, math.pi, 2.0)
    b2 = Balls.from_positions([[0.6, 0.6], [1.5, 0.6]], radius=[0.03, 0.026]).strike(0, 0.0, 2.5)
    pos = np.stack([b1.pos, b2.pos])
    vel = np.stack([b1.vel, b2.vel])
    on = np.stack([b1.on_table, b2.on_table])
    res = run_tables(sim, pos, vel, on, np.stack([b1.radius, b2.radius]), np.stack([b1.mass, b2.mass]),
                     ball=[1, 0])
    _assert_row_is(res, 0, sim.run(b1), struck=1)
    _assert_row_is(res, 1, sim.run(b2), struck=0)
    assert res.first_contact.tolist() == [0, 1]


@pytest.mark.skipif(numba.config.NUMBA_NUM_THREADS < 2, reason="needs two numba threads")
def test_same_result_whatever_the_thread_count():
    table = Table()
    sim = Simulator(table, rolling())
    angles, speeds = _shots(64, seed=5)
    balls = _scene()
    before = numba.get_num_threads()
    one = run_shots(sim, balls, angles, speeds, threads=1)
    two = run_shots(sim, balls, angles, speeds, threads=2)
    assert numba.get_num_threads() == before  # restored
    for f in one._fields:
        a, b = getattr(one, f), getattr(two, f)
        if a is None:
            assert b is None
        else:
            assert np.array_equal(a, b, equal_nan=True), f
    assert (one.event_counts[:, EV_COLLISION] > 0).any()


def test_bad_input_is_refused_with_the_fix():
    table = pool()
    balls = _scene()
    with pytest.raises(SceneError, match="solver='exact'"):
        run_shots(Simulator(table, rolling(), solver="step"), balls, [0.0], [1.0])
    sim = Simulator(table, rolling())
    with pytest.raises(SceneError, match="shot 1: angle"):
        run_shots(sim, balls, [0.0, math.nan], [1.0, 1.0])
    with pytest.raises(SceneError, match="speed >= 0"):
        run_shots(sim, balls, [0.0], [-1.0])
    with pytest.raises(SceneError, match="speeds: 3 values for 2 rows"):
        run_shots(sim, balls, [0.0, 1.0], [1.0, 2.0, 3.0])
    with pytest.raises(SceneError, match="only the spin model"):
        run_shots(sim, balls, [0.0], [1.0], side=[0.1])
    with pytest.raises(SceneError, match="miscue"):
        run_shots(Simulator(table, Physics(friction="spin")), balls, [0.0], [1.0], side=[0.5], top=[0.5])
    gone = balls.copy()
    gone.on_table[0] = False
    with pytest.raises(SceneError, match="pocketed and cannot be struck"):
        run_shots(sim, gone, [0.0], [1.0])
    pos = np.zeros((2, 4, 2), np.float32)
    with pytest.raises(SceneError, match="pos: expected a C-contiguous float64"):
        run_tables(sim, pos, np.zeros((2, 4, 2)), np.ones((2, 4), bool), balls.radius, balls.mass)
    bad = np.stack([balls.pos, balls.pos])
    bad[1, 2] = bad[1, 1]  # two balls on one spot
    with pytest.raises(SceneError, match="table 1: balls '1' and '2' overlap"):
        run_tables(sim, bad, np.zeros((2, 4, 2)), np.ones((2, 4), bool), balls.radius, balls.mass, validate=True,
                   ids=balls.ids)
