"""Scene files and the ``billiards-sim`` command line (``python -m billiards_env.sim``).

Every command-line run is a real subprocess; they are all started at once by one module fixture (each costs
about half a second of interpreter and numba start-up) and the tests read their outcomes.
"""
from __future__ import annotations

import copy
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from billiards_env.physics import SceneError
from billiards_env.physics.scene import Scene

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((REPO / "examples").glob("*.json"))
BALL_FIELDS = {"id", "x", "y", "vx", "vy", "pocketed", "pocket", "pocketed_at"}

BASE = {
    "table": {"length": 2.54, "width": 1.27, "cushion_restitution": 0.85},
    "physics": {"friction": "rolling", "mu_roll": 0.01, "ball_restitution": 0.95},
    "balls": [{"id": "cue", "x": 0.6, "y": 0.635}, {"id": "1", "x": 1.9, "y": 0.635}],
    "shot": {"ball": "cue", "angle": 0.0, "speed": 2.0},
}


def _mutate(fn):
    d = copy.deepcopy(BASE)
    fn(d)
    return d


def _set(path, value):
    def fn(d):
        node = d
        for k in path[:-1]:
            node = node[k]
        node[path[-1]] = value
    return fn


#: name -> (scene as a dict, or raw file text, or raw bytes; words the one-line error must contain)
BAD = {
    "unknown_field_ball": (_mutate(_set(["balls", 0, "colour"], "red")), ["colour"]),
    "unknown_field_top": (_mutate(_set(["tabel"], {})), ["tabel"]),
    "unknown_field_physics": (_mutate(_set(["physics", "mu"], 0.1)), ["mu"]),
    "unknown_friction_law": (_mutate(_set(["physics", "friction"], "sticky")), ["sticky"]),
    "ball_off_table_right": (_mutate(_set(["balls", 1, "x"], 2.53)), ["off the table"]),
    "ball_off_table_negative": (_mutate(_set(["balls", 0, "y"], -0.2)), ["off the table"]),
    "overlapping_balls": (_mutate(_set(["balls", 1, "x"], 0.6 + 0.03)), ["overlap"]),
    "negative_radius": (_mutate(_set(["balls", 0, "radius"], -0.01)), ["radius"]),
    "zero_radius": (_mutate(_set(["balls", 0, "radius"], 0)), ["radius"]),
    "negative_mass": (_mutate(_set(["balls", 1, "mass"], -0.17)), ["mass"]),
    "nan_literal": (json.dumps(BASE).replace('"x": 0.6', '"x": NaN'), ["balls[0].x"]),
    "infinity_literal": (json.dumps(BASE).replace('"speed": 2.0', '"speed": Infinity'), ["speed"]),
    "ball_restitution_above_1": (_mutate(_set(["physics", "ball_restitution"], 1.5)), ["ball_restitution"]),
    "cushion_restitution_negative": (_mutate(_set(["table", "cushion_restitution"], -0.1)), ["cushion_restitution"]),
    "unknown_shot_ball": (_mutate(_set(["shot", "ball"], "ghost")), ["ghost"]),
    "negative_shot_speed": (_mutate(_set(["shot", "speed"], -1.0)), ["speed"]),
    # Finite but beyond any ball's speed (MAX_BALL_SPEED): refused with the bound, not "run" to rest in no time.
    "absurd_shot_speed": (_mutate(_set(["shot", "speed"], 1e300)), ["shot.speed", "1e+300 m/s", "at most 50 m/s"]),
    "ball_velocity_too_fast": (_mutate(_set(["balls", 1, "vx"], 80.0)), ["ball '1'", "80 m/s", "at most 50 m/s"]),
    "unknown_solver": (_mutate(_set(["solver"], {"name": "rk4"})), ["rk4"]),
    "malformed_json": ('{"balls": [{"x": 0.5, "y": 0.5}', ["json"]),
    "empty_balls": (_mutate(_set(["balls"], [])), ["balls"]),
    "missing_balls": ({"table": {}}, ["balls"]),
    "not_an_object": ("[1, 2, 3]", ["scene"]),
    "string_number": (_mutate(_set(["balls", 0, "x"], "0.6")), ["balls[0].x"]),
    # Valid JSON the parser turns into numbers a float cannot hold, and a file that is not text at all.
    "integer_too_large_for_float": (json.dumps(BASE).replace('"x": 0.6', '"x": 1' + "0" * 400), ["balls[0].x"]),
    "integer_with_5000_digits": (json.dumps(BASE).replace('"x": 0.6', '"x": 1' + "0" * 5000), ["x"]),
    "not_utf8": (b"\xff\xfe{\x00}\x00", ["scene"]),
}

#: The Python API must raise SceneError for the same cases (the dict ones; text ones go through Scene.load).
API_BAD = {k: v[0] for k, v in BAD.items()}
API_BAD["nan_literal"] = _mutate(_set(["balls", 0, "x"], float("nan")))
API_BAD["infinity_literal"] = _mutate(_set(["shot", "speed"], float("inf")))


def _write(path: Path, content) -> Path:
    if isinstance(content, bytes):
        path.write_bytes(content)
    elif isinstance(content, str):
        path.write_text(content)
    else:
        path.write_text(json.dumps(content))
    return path


def _cli(*args):
    return subprocess.Popen([sys.executable, "-m", "billiards_env.sim", *map(str, args)], cwd=REPO,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)


#: Bad scenes also run as real processes (exit status, stderr, no traceback at the process level); the rest of
#: the bad scenes go through the same ``main()`` in-process, which is much faster.
SUBPROCESS_BAD = ("malformed_json", "nan_literal")


@pytest.fixture(scope="module")
def cli(tmp_path_factory):
    """Start the command-line subprocesses in parallel; return name -> (returncode, stdout, stderr)."""
    d = tmp_path_factory.mktemp("scenes")
    procs = {}
    for name in SUBPROCESS_BAD:
        procs[f"bad:{name}"] = _cli(_write(d / f"{name}.json", BAD[name][0]))
    for ex in EXAMPLES:
        procs[f"example:{ex.name}"] = _cli(ex, "--events")
    # `billiards-sim ... | head`: the reader is gone before the result is written (read end closed up front).
    r, w = os.pipe()
    os.close(r)
    procs["broken_pipe"] = subprocess.Popen([sys.executable, "-m", "billiards_env.sim", str(EXAMPLES[0]), "--events"],
                                            cwd=REPO, stdout=w, stderr=subprocess.PIPE)
    os.close(w)
    out = {}
    for name, p in procs.items():
        try:
            so, se = p.communicate(timeout=300)
        except subprocess.TimeoutExpired:
            p.kill()
            so, se = p.communicate()
        out[name] = (p.returncode, (so or b"").decode("utf-8", "replace"), se.decode("utf-8", "replace"))
    return out


def _main(capsys, *args):
    """``billiards-sim`` in-process: (exit code, stdout, stderr). An exception escaping ``main`` is a traceback."""
    from billiards_env.sim import main
    rc = main([str(a) for a in args])
    cap = capsys.readouterr()
    return rc, cap.out, cap.err


def test_there_are_example_scenes():
    assert EXAMPLES, "examples/*.json: the README's example scenes are missing"


def _check_result_json(doc, scene: Scene):
    assert set(doc) >= {"status", "time", "n_events", "balls"}
    assert doc["status"] in ("rest", "time_cap", "event_cap")
    assert isinstance(doc["time"], float) and math.isfinite(doc["time"]) and doc["time"] >= 0
    assert isinstance(doc["n_events"], int) and doc["n_events"] >= 0
    assert [b["id"] for b in doc["balls"]] == list(scene.balls.ids)
    L, W = scene.table.length, scene.table.width
    for b, r in zip(doc["balls"], scene.balls.radius):
        assert set(b) >= BALL_FIELDS, b
        for f in ("x", "y", "vx", "vy"):
            assert isinstance(b[f], float) and math.isfinite(b[f])
        assert isinstance(b["pocketed"], bool)
        if b["pocketed"]:
            assert isinstance(b["pocket"], int) and 0 <= b["pocket"] < scene.table.n_pockets
            assert isinstance(b["pocketed_at"], float) and 0 <= b["pocketed_at"] <= doc["time"]
        else:
            assert b["pocket"] is None and b["pocketed_at"] is None
            assert r - 1e-12 <= b["x"] <= L - r + 1e-12 and r - 1e-12 <= b["y"] <= W - r + 1e-12
        if doc["status"] == "rest":
            assert b["vx"] == 0.0 and b["vy"] == 0.0


@pytest.mark.parametrize("example", EXAMPLES, ids=[e.name for e in EXAMPLES])
def test_example_scene_runs_from_the_command_line(cli, example):
    rc, out, err = cli[f"example:{example.name}"]
    assert rc == 0, err
    assert "Traceback" not in err
    doc = json.loads(out)
    scene = Scene.load(example)
    _check_result_json(doc, scene)
    # --events: the event list, in time order, consistent with n_events.
    assert len(doc["events"]) == doc["n_events"]
    times = [e["time"] for e in doc["events"]]
    assert times == sorted(times)
    assert {e["kind"] for e in doc["events"]} <= {"collision", "cushion", "pocket", "stop", "roll", "spin"}
    # The command line and the Python API give the same numbers, to the last bit (JSON floats round-trip).
    res = scene.run()
    assert doc["status"] == res.status and doc["time"] == res.time and doc["n_events"] == res.n_events
    for b, i in zip(doc["balls"], range(len(res.balls))):
        assert (b["x"], b["y"]) == tuple(res.balls.pos[i].tolist())


@pytest.mark.parametrize("example", EXAMPLES, ids=[e.name for e in EXAMPLES])
def test_example_scene_with_step_solver_options(capsys, example):
    rc, out, err = _main(capsys, example, "--solver", "step", "--dt", "0.001", "--contact", "rewind")
    assert rc == 0, err
    doc = json.loads(out)
    _check_result_json(doc, Scene.load(example))
    assert doc.get("solver") == "step-rewind"
    assert isinstance(doc.get("n_steps"), int) and doc["n_steps"] >= 1
    assert "events" not in doc


def test_good_scene_one_line_json(capsys, tmp_path):
    rc, out, err = _main(capsys, _write(tmp_path / "good.json", BASE), "--indent", "0")
    assert rc == 0 and err == ""
    assert len(out.strip().splitlines()) == 1
    _check_result_json(json.loads(out), Scene.from_dict(BASE))


def _check_error(rc, out, err, words):
    assert "Traceback" not in err, err[-2000:]
    assert rc == 2, (rc, err[-500:])
    lines = err.strip().splitlines()
    assert len(lines) == 1, err[-2000:]
    assert lines[0].startswith("billiards-sim: error: ")
    assert out == ""
    for word in words:
        assert word.lower() in lines[0].lower(), (word, lines[0])


@pytest.mark.parametrize("name", SUBPROCESS_BAD)
def test_bad_scene_process_exits_2_with_one_line(cli, name):
    _check_error(*cli[f"bad:{name}"], BAD[name][1])


@pytest.mark.parametrize("name", list(BAD))
def test_bad_scene_is_one_clear_error_line(capsys, tmp_path, name):
    content, words = BAD[name]
    _check_error(*_main(capsys, _write(tmp_path / f"{name}.json", content)), words)


@pytest.mark.parametrize("args", [["does_not_exist.json"], ["{good}", "--solver", "step", "--dt", "0"],
                                  ["{good}", "--solver", "step", "--dt", "nan"]],
                         ids=["missing-file", "dt-0", "dt-nan"])
def test_bad_command_line_is_one_clear_error_line(capsys, tmp_path, args):
    good = _write(tmp_path / "good.json", BASE)
    args = [a.replace("{good}", str(good)) if a != "does_not_exist.json" else str(tmp_path / a) for a in args]
    _check_error(*_main(capsys, *args), [])


def test_output_into_a_closed_pipe_ends_quietly(cli):
    rc, _, err = cli["broken_pipe"]
    assert err == "" and rc == 1  # no BrokenPipeError traceback; status 1 as in the Python docs' recipe


@pytest.mark.parametrize("args,flags", [(["--dt", "0.001"], ["--dt"]), (["--contact", "rewind"], ["--contact"]),
                                        (["--solver", "exact", "--dt", "0.001", "--contact", "lecture"],
                                         ["--dt", "--contact"])],
                         ids=["dt", "contact", "exact-dt-contact"])
def test_step_solver_flags_without_the_step_solver_are_refused(capsys, tmp_path, args, flags):
    rc, out, err = _main(capsys, _write(tmp_path / "good.json", BASE), *args)
    _check_error(rc, out, err, flags + ["step solver", "--solver step", "'exact'"])


def test_step_solver_flags_apply_to_a_step_scene(capsys, tmp_path):
    scene = _write(tmp_path / "step.json", {**BASE, "solver": {"name": "step", "dt": 0.01}})
    rc, out, err = _main(capsys, scene, "--dt", "0.002", "--contact", "rewind")
    assert rc == 0, err
    doc = json.loads(out)
    assert doc["solver"] == "step-rewind"
    coarse = json.loads(_main(capsys, scene)[1])
    assert doc["n_steps"] > coarse["n_steps"]  # --dt 0.002 was used, not the scene's 0.01


@pytest.mark.parametrize("name", [k for k, v in API_BAD.items() if not isinstance(v, (str, bytes))])
def test_python_api_rejects_bad_scene_dict(name):
    with pytest.raises(SceneError):
        Scene.from_dict(copy.deepcopy(API_BAD[name]))


@pytest.mark.parametrize("name", [k for k, v in API_BAD.items() if isinstance(v, (str, bytes))])
def test_python_api_rejects_bad_scene_file(name, tmp_path):
    path = _write(tmp_path / "scene.json", API_BAD[name])
    with pytest.raises(SceneError):
        Scene.load(path)


def test_the_speed_bound_holds_in_the_batch_api_and_the_env_config():
    """The bound lives with the balls' validation (``physics.balls.MAX_BALL_SPEED``): the batch API and an env's
    ``speed_max`` meet the same limit; a shot at the limit itself is played."""
    from billiards_env.physics import MAX_BALL_SPEED
    from billiards_env.physics.batch import run_shots

    scene = Scene.from_dict(BASE)
    sim, balls = scene.simulator(), scene.balls
    with pytest.raises(SceneError, match=r"shot 1: speed: 1e\+300 m/s is faster than any ball can move here \(at most "
                                         r"50 m/s"):
        run_shots(sim, balls, [0.0, 0.0], [2.0, 1e300])
    res = run_shots(sim, balls, [0.0], [MAX_BALL_SPEED])
    assert res.status[0] == 0 and res.time[0] > 0.0  # 0: at rest
    gym = pytest.importorskip("gymnasium")
    import billiards_env  # noqa: F401
    from billiards_env.envs.config import ConfigError

    with pytest.raises(ConfigError, match=r"speed_max: 1000.0 m/s is faster than any ball can move here \(at most 50"):
        gym.make("BilliardsOneBall-v0", speed_max=1000.0)


def test_python_api_scene_round_trip_matches_direct_simulation():
    from billiards_env.physics import Balls, Physics, Table, simulate
    scene = Scene.from_dict(BASE)
    res = scene.run()
    b = Balls.from_positions([[0.6, 0.635], [1.9, 0.635]], ids=["cue", "1"]).strike("cue", 0.0, 2.0)
    direct = simulate(Table(), Physics(), b)
    assert np.array_equal(res.balls.pos, direct.balls.pos)
    assert res.status == direct.status == "rest"
