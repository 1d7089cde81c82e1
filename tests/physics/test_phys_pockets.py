"""Pockets: capture at the closed-form time, in the right pocket; pocketed balls are gone for good."""
from __future__ import annotations

import math

import numpy as np
import pytest

from billiards_env.physics import default_pockets
from physics_helpers import (EV_COLLISION, EV_POCKET, L, R, W, A_ROLL, balls, collisions, events_of, pool, rolling,
                             rolling_time_for_distance, run)

TOL = 1e-9


def test_default_pocket_order():
    xy, r = default_pockets(L, W)
    np.testing.assert_array_equal(xy, [[0, 0], [L / 2, 0], [L, 0], [0, W], [L / 2, W], [L, W]])
    np.testing.assert_array_equal(r, [0.06, 0.052, 0.06, 0.06, 0.052, 0.06])


@pytest.mark.parametrize("solver", ["exact", "step"])
def test_ball_at_rest_outside_pockets_stays(solver):
    # Resting balls near every pocket (but outside its capture circle) and one in the middle.
    table = pool()
    pos = [[L / 2, W / 2], [0.1, 0.1], [L / 2, 0.1], [L - 0.1, W - 0.1], [L / 2 + 0.06, W - R]]
    b = balls(pos)
    res = run(table, rolling(), b, solver=solver)
    assert res.status == "rest"
    assert len(res.events) == 0
    assert np.array_equal(res.balls.pos, b.pos) and res.balls.on_table.all()
    assert np.all(res.pocket == -1) and np.all(np.isnan(res.pocketed_at))


@pytest.mark.parametrize("side", ["bottom", "top"])
@pytest.mark.parametrize("direction", [1, -1])
def test_ball_rolled_along_cushion_into_side_pocket(side, direction):
    table = pool()
    y = R if side == "bottom" else W - R
    x0 = L / 2 - direction * 0.9
    v = 1.5
    b = balls([[x0, y]], velocities=[[direction * v, 0.0]])  # exactly along the cushion
    res = run(table, rolling(), b)
    expected_pocket = 1 if side == "bottom" else 4
    cap = table.pocket_radius[expected_pocket]
    # Captured where the path (at distance R from the pocket centre's line) enters the capture circle.
    d = 0.9 - math.sqrt(cap ** 2 - R ** 2)
    assert res.pocket[0] == expected_pocket
    assert abs(res.pocketed_at[0] - rolling_time_for_distance(v, d, A_ROLL)) <= TOL
    assert list(res.events.kind) == [EV_POCKET]
    st = run(table, rolling(), b, solver="step", dt=1e-4)
    assert st.pocket[0] == expected_pocket
    assert abs(st.pocketed_at[0] - res.pocketed_at[0]) <= 1e-3


@pytest.mark.parametrize("solver", ["exact", "step"])
def test_pocketed_balls_stay_pocketed_and_leave_no_events(solver):
    # Ball 1 runs along the bottom cushion into the side pocket; the cue follows the same line over the spot where
    # ball 1 disappeared and drops into the same pocket later, without ever touching it.
    table = pool()
    b = balls([[0.5, R], [0.9, R]], velocities=[[1.5, 0.0], [1.2, 0.0]])
    res = run(table, rolling(), b, solver=solver, **({"dt": 1e-4} if solver == "step" else {}))
    assert res.status == "rest"
    assert res.pocket.tolist() == [1, 1]
    assert res.pocketed_at[1] < res.pocketed_at[0]
    assert not res.balls.on_table.any()
    ev = res.events
    for i in (0, 1):
        mine = np.flatnonzero((ev.ball == i) | ((ev.kind == EV_COLLISION) & (ev.other == i)))
        q_pocket = np.flatnonzero((ev.kind == EV_POCKET) & (ev.ball == i))
        assert len(q_pocket) == 1
        assert mine.max() == q_pocket[0], "no event involves a ball after it is pocketed"
    assert len(events_of(res, EV_COLLISION)) == 0
    if solver == "exact":
        cap = table.pocket_radius[1]
        x_in = L / 2 - math.sqrt(cap ** 2 - R ** 2)
        assert abs(res.pocketed_at[1] - rolling_time_for_distance(1.2, x_in - 0.9, A_ROLL)) <= TOL
        assert abs(res.pocketed_at[0] - rolling_time_for_distance(1.5, x_in - 0.5, A_ROLL)) <= TOL


@pytest.mark.parametrize("solver", ["exact", "step"])
def test_ball_already_off_the_table_is_ignored(solver):
    # A ball flagged as pocketed lies in the cue's path: the cue rolls straight through its old spot.
    b = balls([[0.5, 0.6], [1.0, 0.6]]).strike("cue", 0.0, 1.0)
    b.on_table[1] = False
    res = run(pool(), rolling(), b, solver=solver, max_time=0.8)  # before the cue comes back from a cushion
    assert collisions(res) == []
    assert not res.balls.on_table[1] and np.array_equal(res.balls.pos[1], [1.0, 0.6])
    assert res.balls.pos[0, 0] > 1.0
    assert np.all(res.balls.vel[1] == 0.0)


def test_pocketed_ball_in_trajectory_is_flagged_off_table():
    table = pool()
    b = balls([[L / 2, 0.6]]).strike("cue", -math.pi / 2, 1.0)
    res = run(table, rolling(), b, record=True)
    t_in = res.pocketed_at[0]
    _, on = res.trajectory.sample(np.array([0.0, 0.5 * t_in, 0.999 * t_in, t_in + 1e-6, res.time]))
    assert on[:, 0].tolist() == [True, True, True, False, False]


def test_custom_pocket_list_from_scene():
    # One pocket in the middle of the table (scene format): a ball rolled at it drops in at the closed-form time;
    # "pockets": [] gives a table a ball can rattle around without ever being pocketed.
    from billiards_env.physics.scene import Scene
    scene = Scene.from_dict({
        "table": {"pockets": [{"x": 1.27, "y": 0.635, "radius": 0.05}]},
        "balls": [{"id": "cue", "x": 0.5, "y": 0.635}],
        "shot": {"ball": "cue", "angle": 0.0, "speed": 1.0},
    })
    assert scene.table.n_pockets == 1
    res = scene.run()
    assert res.pocket[0] == 0
    assert abs(res.pocketed_at[0] - rolling_time_for_distance(1.0, 0.77 - 0.05, A_ROLL)) <= TOL
    empty = Scene.from_dict({
        "table": {"pockets": []},
        "balls": [{"id": "cue", "x": 0.1, "y": 0.1}],
        "shot": {"ball": "cue", "angle": -2.0, "speed": 2.0},
    })
    assert empty.table.n_pockets == 0
    res = empty.run()
    assert res.status == "rest" and res.pocket[0] == -1 and res.balls.on_table[0]
