"""The speed side of ``benchmarks``: the env-timing function, the ``env`` section through the command line, and
the reports rendered from the committed JSON (no timed assertions: only that every figure is there and sane)."""
from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import pytest

from benchmarks import __main__ as bench_cli
from benchmarks import accuracy, speed

REPO = Path(__file__).resolve().parents[2]
DOCS = REPO / "docs" / "bench"
ONE = "BilliardsOneBall-v0"


@pytest.mark.parametrize("wrapped,fast", [(True, True), (False, True), (False, False)])
def test_time_env_measures_every_field(wrapped, fast):
    m = speed.time_env(ONE, 0.02, wrapped=wrapped, fast=fast)
    assert m["steps"] >= 100 and m["steps"] % 100 == 0
    # One-ball episodes end after every shot: one reset per step.
    assert m["resets"] == m["steps"] and m["mean_episode_steps"] == 1.0
    for key in ("steps_per_s", "steps_per_s_with_resets", "step_us", "reset_us"):
        assert math.isfinite(m[key]) and m[key] > 0, key
    assert m["steps_per_s_with_resets"] <= m["steps_per_s"]
    assert m["steps_per_cpu_s"] is None or m["steps_per_cpu_s"] > 0
    assert m["events_per_shot"] >= 1.0  # at least the cue ball's stop
    assert set(speed.ENV_REPORT_KEYS) <= set(m)


def test_env_section_from_the_command_line(tmp_path, capsys):
    code = bench_cli.main(["--only", "env", "--env-seconds", "0.02", "--env-ids", ONE, "--out", str(tmp_path)])
    assert code == 0
    doc = json.loads((tmp_path / "speed.json").read_text())
    env = doc["env_steps"]
    assert env["available"] and list(env["envs"]) == [ONE] and env["seconds_per_env"] == 0.02
    for label in ("make", "unwrapped"):
        assert tuple(env["envs"][ONE][label]) == speed.ENV_REPORT_KEYS
        assert env["envs"][ONE][label]["steps_per_s"] > 0
    assert "ours" not in doc and "pooltool" not in doc and "latency" not in doc  # only the section asked for
    md = (tmp_path / "speed.md").read_text()
    assert "## env.step per second" in md and f"| {ONE} |" in md
    target = [t for t in doc["targets"] if t["target"].startswith(f"env.step on {ONE}")]
    assert len(target) == 1 and target[0]["status"] in ("PASS", "FAIL")
    table = capsys.readouterr().out.splitlines()
    assert table[0].split()[:3] == ["id", "env", "path"]
    assert [line.split()[:3] for line in table[1:]] == [[ONE, "make", "kernel"], [ONE, "unwrapped", "kernel"]]


def test_unknown_section_is_refused(capsys):
    with pytest.raises(SystemExit) as exc:
        bench_cli.main(["--only", "nonsense"])
    assert exc.value.code == 2
    assert "invalid choice: 'nonsense'" in capsys.readouterr().err


def test_committed_reports_are_what_the_renderers_make(tmp_path):
    """docs/bench/*.md are exactly the Markdown rendered from the JSON beside them (reports are generated, never
    edited by hand; a change of format shows here). After changing a renderer on purpose, re-write the reports
    with ``python -m benchmarks --render-only``."""
    for name in ("speed.json", "speed_vs_error.json"):
        shutil.copy(DOCS / name, tmp_path / name)
    acc = json.loads((tmp_path / "speed_vs_error.json").read_text())
    acc["target_exact_faster"] = accuracy.exact_faster_check(acc)
    assert accuracy.render_markdown(acc, acc["machine"], "speed_vs_error.png") == \
        (DOCS / "speed_vs_error.md").read_text()
    doc = json.loads((tmp_path / "speed.json").read_text())
    doc["targets"] = speed.targets(doc, acc)
    assert speed.render_markdown(doc, acc) == (DOCS / "speed.md").read_text()
