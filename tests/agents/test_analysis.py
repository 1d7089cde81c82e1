"""agents.analysis: scripted one-ball shots are read back into geometry and classified as the module says (pot,
aim error, too soft, no contact, scratch), and the summary counts and bins them."""
from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest

import billiards_env  # noqa: F401
from agents.analysis import CLASSES, classify, markdown, object_direction, summarise, table_geometry
from billiards_env.physics import Table
from billiards_env.physics.aim import aim_angle, pocket_window

#: The object ball 0.5 m from the bottom-left corner pocket along the diagonal, the cue ball 0.5 m behind it.
OBJ = np.array([0.05 + 0.5 / math.sqrt(2), 0.05 + 0.5 / math.sqrt(2)])
CUE = OBJ + 0.5 / math.sqrt(2)


def _play(angle: float, speed: float, cue=CUE, obj=OBJ):
    env = gym.make("BilliardsOneBall-v0", speed_max=5.0)
    env.reset(seed=0, options={"positions": [list(cue), list(obj)]})
    geo = table_geometry(env)
    shot = env.unwrapped.action_from_shot(angle, speed)
    played = env.unwrapped.shot_from_action(shot)
    info = env.step(shot)[4]
    return classify(env, geo, played.angle, played.speed, info), geo, info


def test_object_direction_is_the_line_of_centres_at_contact():
    theta, d = object_direction(CUE, OBJ, aim_angle(CUE, OBJ), 2 * 0.028575)
    assert theta == pytest.approx(aim_angle(CUE, OBJ), abs=1e-12)
    assert d == pytest.approx(0.5 - 2 * 0.028575, abs=1e-12)
    assert object_direction(CUE, OBJ, aim_angle(CUE, OBJ) + 0.5, 2 * 0.028575) is None


def test_a_straight_pot_is_a_success_in_the_corner_pocket():
    row, geo, info = _play(aim_angle(CUE, OBJ), 1.2)
    assert info["is_success"] and row["class"] == "success"
    assert row["pocket"] == 0 and row["pocket_kind"] == "corner" and row["aim_error_deg"] == 0.0
    assert geo["best_pocket"] == 0 and geo["cut_deg"] == pytest.approx(0.0, abs=0.5)


def test_a_cut_sent_between_the_pockets_is_an_aim_error_and_a_cue_line_past_the_ball_no_direct_hit():
    # A half-ball hit: the object ball leaves ~30 degrees off the diagonal, towards no pocket's window.
    half_ball = aim_angle(CUE, OBJ) + math.asin(0.5 * 2 * 0.028575 / 0.5)
    row, _, info = _play(half_ball, 1.0)
    assert not info["is_success"] and row["class"] == "aim" and row["aim_error_deg"] > 1.0
    row, _, info = _play(aim_angle(CUE, OBJ) + 0.5, 1.0)
    assert row["class"] == "no direct hit" and row["pocket"] == -1


def test_a_straight_shot_that_stops_short_is_too_soft():
    obj = np.array([1.2, 0.9])  # ~1.4 m from the top-right corner pocket: through the middle of its window
    direction = pocket_window(obj, 0.028575, Table(), 5)[0]
    cue = obj - 0.4 * np.array([math.cos(direction), math.sin(direction)])
    row, _, info = _play(direction, 0.5, cue=cue, obj=obj)
    assert not info["is_success"] and row["class"] == "too soft" and row["reach_margin"] < 0.0
    assert row["pocket"] == 5


def test_summary_counts_classes_and_bins():
    rows = []
    for k, cls in enumerate(["success"] * 7 + ["aim", "too soft", CLASSES[0]]):
        rows.append({"success": cls == "success", "class": cls, "cut_deg": 10.0 * k, "d_obj": 0.1 * k,
                     "d_cue": 0.2 * k, "rail_gap": 0.05 * k, "tolerance_mrad": float(k), "window_offset_deg": 0.3 * k,
                     "pocket": k % 6, "best_pocket": 0, "pocket_kind": "corner", "aim_error_deg": 1.0,
                     "speed": 1.0, "best_speed": 0.9})
    s = summarise(rows, {"geometric": [True] * 10})
    assert s["pocket_rate"] == pytest.approx(0.7)
    assert s["classes"]["aim"] == 1 and s["classes"]["too soft"] == 1 and s["classes"][CLASSES[0]] == 1
    assert sum(b["tables"] for b in s["bins"]["cut angle of the easiest shot"]) == 10
    assert s["baselines_on_failures"]["geometric"]["pots_agent_failures"] == 3
    text = markdown(s, "run", 0)
    assert "pocket rate **70.0%**" in text and "| aim | 1 | 1 |" in text
