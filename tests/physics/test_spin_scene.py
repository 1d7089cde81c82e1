"""Spin fields in scene files and billiards-sim: ball ``wx wy wz``, shot ``side``/``top``, the result's spins and
motion states, clear errors for a miscue and for spin under the rolling or drag law, the example scenes."""
from __future__ import annotations

import copy
import json
import math
from pathlib import Path

import numpy as np
import pytest

from billiards_env.physics import SceneError
from billiards_env.physics.codes import MOTION_STATES
from billiards_env.physics.scene import Scene
from billiards_env.sim import main as sim_main

R = 0.028575
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
BASE = {"table": {"pockets": []}, "physics": {"friction": "spin"},
        "balls": [{"id": "cue", "x": 0.7, "y": 0.635}, {"id": "1", "x": 1.0, "y": 0.635}],
        "shot": {"ball": "cue", "angle": 0.0, "speed": 2.0, "top": -0.4, "side": 0.2}}


def scene(**changes) -> dict:
    d = copy.deepcopy(BASE)
    for key, value in changes.items():
        d[key] = value
    return d


def test_shot_side_and_top_give_the_strike_spin():
    s = Scene.from_dict(scene())
    b = s.initial_balls()
    v0 = 2.0
    np.testing.assert_allclose(b.ang[0], [0.0, 5 * -0.4 * v0 / (2 * R), 5 * 0.2 * v0 / (2 * R)], atol=1e-9)
    assert b.vel[0].tolist() == [2.0, 0.0]


def test_ball_spin_fields_are_read():
    d = scene(shot=None)
    d["balls"][1].update(wx=1.5, wy=-2.0, wz=30.0)
    s = Scene.from_dict(d)
    assert s.balls.ang[1].tolist() == [1.5, -2.0, 30.0]
    res = s.run()
    assert res.status == "rest" and res.n_events >= 1  # a spinning, sliding ball moves and comes to rest


def test_miscue_is_refused_naming_the_values_and_the_limit():
    d = scene(shot={"ball": "cue", "angle": 0.0, "speed": 2.0, "top": 0.45, "side": 0.3})
    with pytest.raises(SceneError) as err:
        Scene.from_dict(d)
    assert "0.45" in str(err.value) and "0.3" in str(err.value) and "0.25" in str(err.value)


@pytest.mark.parametrize("friction", ["rolling", "drag"])
def test_spin_under_rolling_or_drag_says_spin_needs_the_spin_law(friction):
    with pytest.raises(SceneError, match="needs physics.friction 'spin'"):
        Scene.from_dict(scene(physics={"friction": friction}))
    d = scene(physics={"friction": friction}, shot=None)
    d["balls"][0]["wz"] = 5.0
    with pytest.raises(SceneError, match="friction to 'spin'"):
        Scene.from_dict(d)


def test_bad_spin_values_name_the_field():
    d = scene(shot=None)
    d["balls"][0]["wy"] = "fast"
    with pytest.raises(SceneError, match=r"balls\[0\].wy"):
        Scene.from_dict(d)
    d = scene(physics={"friction": "spin", "mu_slide": -0.1})
    with pytest.raises(SceneError, match="physics.mu_slide"):
        Scene.from_dict(d)
    with pytest.raises(SceneError, match="min_speed"):
        Scene.from_dict(scene(physics={"friction": "spin", "min_speed": 0.01}))


def test_cli_reports_spins_and_motion_states(tmp_path, capsys):
    path = tmp_path / "draw.json"
    path.write_text(json.dumps(scene()))
    assert sim_main([str(path), "--events", "--indent", "0"]) == 0
    out = json.loads(capsys.readouterr().out)
    for ball in out["balls"]:
        assert {"wx", "wy", "wz", "state"} <= set(ball)
        assert ball["state"] in MOTION_STATES
        assert ball["state"] == "stationary" and out["status"] == "rest"
    kinds = [e["kind"] for e in out["events"]]
    assert kinds[0] == "collision" and "roll" in kinds and kinds[-1] == "stop"
    first = out["events"][0]
    assert first["state"] == "sliding" and first["other_state"] == "sliding"
    for e in out["events"]:
        expect = {"roll": "rolling", "spin": "spinning", "stop": "stationary"}.get(e["kind"])
        if expect:
            assert e["state"] == expect


def test_cli_rolling_output_has_no_spin_fields(tmp_path, capsys):
    d = scene(physics={"friction": "rolling"}, shot={"ball": "cue", "angle": 0.0, "speed": 2.0})
    path = tmp_path / "plain.json"
    path.write_text(json.dumps(d))
    assert sim_main([str(path), "--events", "--indent", "0"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert not {"wx", "wy", "wz", "state"} & set(out["balls"][0])
    assert all("state" not in e for e in out["events"])


def test_cli_miscue_exits_2_with_one_line(tmp_path, capsys):
    path = tmp_path / "miscue.json"
    path.write_text(json.dumps(scene(shot={"ball": "cue", "angle": 0.0, "speed": 2.0, "side": 0.6})))
    assert sim_main([str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "miscue" in err


@pytest.mark.parametrize("name", ["draw_shot", "follow_shot", "english_shot"])
def test_example_spin_scenes_run(name):
    s = Scene.load(EXAMPLES / f"{name}.json")
    assert s.physics.friction == "spin"
    assert s.shot is not None and (s.shot.side != 0.0 or s.shot.top != 0.0)
    res = s.run()
    assert res.status == "rest"
    if name == "draw_shot":  # ball 1 goes in; the cue ball comes back along the line it came
        assert res.pocket[1] >= 0 and res.pocket[0] < 0
        start = s.balls.pos[0]
        d = np.subtract(s.balls.pos[1], start)
        back = np.subtract(res.balls.pos[0], start) @ d / np.linalg.norm(d)
        assert back < 0 and math.isfinite(back)
