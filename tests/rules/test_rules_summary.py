"""ShotSummary: what the rules read from a shot's event log, from arrays (the env's hot path) or a ShotResult."""
from __future__ import annotations

import numpy as np
import pytest
from rules_helpers import FOOT_SPOT, HEAD_SPOT, SIM, angle_to, diamond_rack, shoot, triangle_rack

from billiards_env.physics import Balls
from billiards_env.physics.codes import EV_COLLISION, EV_CUSHION, EV_POCKET, EV_STOP
from billiards_env.rules import (RulesError, ShotSummary, ball_numbers, summarize_arrays, summarize_result)


def scene(rack: dict, speed: float = 8.0, angle: float = 0.0) -> Balls:
    ids = ["cue", *rack]
    pos = [HEAD_SPOT, *rack.values()]
    return Balls.from_positions(pos, ids=ids).strike("cue", angle, speed)


@pytest.mark.parametrize("rack", [triangle_rack(FOOT_SPOT), diamond_rack(FOOT_SPOT)], ids=["15", "9"])
@pytest.mark.parametrize("speed", [3.0, 8.0])
def test_arrays_and_result_give_the_same_summary(rack, speed):
    balls = scene(rack, speed)
    res = SIM.run(balls)
    in_place = balls.copy()
    status, _, n_events, pocket, events = SIM.run_in_place(in_place)
    assert status == res.status and n_events == len(res.events)
    numbers = ball_numbers(balls.ids)
    assert summarize_arrays(events, pocket, numbers) == summarize_result(res)


@pytest.mark.parametrize("speed", [3.0, 5.0, 8.0])
def test_summary_agrees_with_the_event_log(speed):
    """Invariants against the timed event log of a break: pockets in time order, the first contact, and the
    cushion contacts after it."""
    balls = scene(triangle_rack(FOOT_SPOT), speed)
    res = SIM.run(balls)
    s = summarize_result(res)
    nums = ball_numbers(balls.ids)
    row = {int(n): r for r, n in enumerate(nums)}
    times = [res.pocketed_at[row[n]] for n in s.pocketed]
    assert times == sorted(times) and len(s.pocketed) == int(np.sum(res.pocket[1:] >= 0))
    assert all(res.pocket[row[n]] == p for n, p in zip(s.pocketed, s.pockets))
    assert s.first_contact is not None and s.first_contact == int(nums[res.first_contact(0)])
    ev = res.events
    k0 = next(k for k in range(len(ev)) if ev.kind[k] == EV_COLLISION and 0 in (ev.ball[k], ev.other[k]))
    after = {int(nums[ev.ball[k]]) for k in range(k0 + 1, len(ev)) if ev.kind[k] == EV_CUSHION}
    assert set(s.rail_balls) == after and list(s.rail_balls) == sorted(after)


def test_rows_map_to_numbers_through_the_ids():
    """Rows in any order: the 9 in row 0, the cue ball in row 1."""
    res = SIM.run(Balls.from_positions([(1.6, 0.635), (1.0, 0.635), (0.3, 0.3)], ids=["9", "cue", "1"])
                  .strike("cue", 0.0, 0.6))
    s = summarize_result(res)
    assert s.first_contact == 9 and s.rail_balls == (9,) and not s.pocketed


def test_a_ball_at_rest_gives_an_empty_summary():
    res = SIM.run(Balls.from_positions([(1.0, 0.635), (0.3, 0.3)], ids=["cue", "1"]))
    assert summarize_result(res) == ShotSummary()


def test_hand_made_arrays():
    """Rows: 0 = ball 3, 1 = cue, 2 = ball 8. The cue ball cushions (before contact), hits the 8, the 8 cushions and
    drops in pocket 4, the 3 never moves."""
    events = np.array([[EV_CUSHION, 1, 2], [EV_COLLISION, 2, 1], [EV_CUSHION, 2, 3], [EV_POCKET, 2, 4],
                       [EV_STOP, 1, -1]])
    pocket = np.array([-1, -1, 4])
    s = summarize_arrays(events, pocket, [3, 0, 8])
    assert s == ShotSummary(first_contact=8, rail_balls=(8,), pocketed=(8,), pockets=(4,))
    assert s.pocket_of(8) == 4 and s.pocket_of(3) is None and s.pocket_of(0) is None
    assert s.rail_after_contact and s.object_balls_to_rail == 1
    s = summarize_arrays(np.zeros((0, 3), np.int64), np.array([-1, -1, -1]), [3, 0, 8])
    assert s.first_contact is None and not s.rail_after_contact


def test_scratch_is_reported_apart_from_object_balls():
    cue = (2.0, 0.5)
    s = shoot({"cue": cue, "1": (0.3, 0.3)}, angle_to(cue, (2.54, 0.0)), 1.5)
    assert s.cue_pocketed and s.cue_pocket == 2 and s.pocketed == () and s.pocket_of(0) == 2


def test_ball_numbers():
    assert ball_numbers(["cue", "1", "15"]).tolist() == [0, 1, 15]
    for ids, what in ((["cue", "x"], "'x'"), (["cue", "16"], "'16'"), (["1", "2"], "exactly one"),
                      (["cue", "1", "1"], "twice"), (["cue", "0"], "'0'")):
        with pytest.raises(RulesError, match=what):
            ball_numbers(ids)


def test_bad_arrays_are_refused():
    with pytest.raises(RulesError, match="events"):
        summarize_arrays(np.zeros(3), np.array([-1, -1]), [0, 1])
    with pytest.raises(RulesError, match="pocket"):
        summarize_arrays(np.zeros((0, 3)), np.array([-1]), [0, 1])
    with pytest.raises(RulesError, match="number 0"):
        summarize_arrays(np.zeros((0, 3)), np.array([-1, -1]), [1, 2])


def test_bad_summaries_are_refused():
    with pytest.raises(RulesError, match="pockets"):
        ShotSummary(pocketed=(1,), pockets=())
    with pytest.raises(RulesError, match="cue_pocketed"):
        ShotSummary(pocketed=(0,), pockets=(1,))
    with pytest.raises(RulesError, match="twice"):
        ShotSummary(pocketed=(1, 1), pockets=(1, 2))
    with pytest.raises(RulesError, match="first_contact"):
        ShotSummary(first_contact=0)

