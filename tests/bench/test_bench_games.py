"""The games section of ``python -m benchmarks`` in a tiny configuration (no timed assertions): every figure is
there, the report renders, and the "before" it times is the same behaviour as now (the Python of before issue 21
swapped in observes and plays what the compiled code does)."""
from __future__ import annotations

import numpy as np
import pytest

from benchmarks import games


@pytest.fixture(scope="module")
def doc():
    tiny = {"seconds": 0.04, "rounds": 1, "games": 1, "steps": 3, "search_every": 1, "vector_tables": 2,
            "vector_seconds": 0.05, "job_seconds": 0.04, "bound_steps": 4, "bound_repeats": 1}
    saved = games._sizes
    games._sizes = lambda quick: tiny
    try:
        return games.run(quick=True)
    finally:
        games._sizes = saved


def test_every_figure_and_target_is_there(doc):
    for env_id in games.GAMES:
        assert set(doc["single"][env_id]) == {name for name, _ in games.CONFIGS}
        assert all(r["shots"] >= r["steps"] > 0 for r in doc["single"][env_id].values())
        assert doc["decisions"][env_id]["geometric"]["n"] > 0
        assert doc["vector"][env_id]["native"] and doc["vector"][env_id]["steps"] > 0
        assert 0.0 < doc["vector"][env_id]["kernel_cpu_s"] <= doc["vector"][env_id]["cpu_s"]
        b = doc["bound"][env_id]  # the physics bound: the same games' shots replayed alone
        assert b["shots"] >= b["steps"] > 0 and b["events"] > 0 and b["passes"] == 1
        assert b["bound_steps_per_cpu_s"] > 0 and b["physics_us_per_shot"] > 0
    assert set(doc["job"]) == set(games.JOB_CONFIGS)
    for j in doc["job"].values():
        assert j["before"]["shots"] > 0 and j["after"]["shots"] > 0 and j["native"]["shots"] > 0
    names = [r["name"] for r in games.targets(doc)]
    assert len(names) == 6 + 2 + 1 + 2
    md = games.render_markdown(doc)
    assert "## Targets" in md and "training job" in md and "physics bound" in md


def test_before_is_the_same_behaviour():
    import gymnasium as gym

    from billiards_env.envs import actions, games as env_games, observations

    kw = {"action_type": "candidates", "observation_type": "candidates", "opening": "either", "position_reward": 1.0,
          "opponent": None}
    saved = (actions.candidate_slots, observations.CandidateFeatures.features, env_games.next_shot_ease)
    runs = []
    for before in (False, True):
        env = gym.make("Billiards9Ball-v0", **kw)
        rng = np.random.default_rng(0)
        out = [env.reset(seed=3)[0]]
        for _ in range(6):
            ctx = games.before_issue_21() if before else _null()
            with ctx:
                obs, r, term, trunc, _ = env.step(rng.uniform(-1, 1, env.action_space.shape).astype(np.float32))
                out += [obs, r]
                if term or trunc:
                    out.append(env.reset()[0])
        runs.append(out)
    assert (actions.candidate_slots, observations.CandidateFeatures.features, env_games.next_shot_ease) == saved
    assert all(np.array_equal(a, b) for a, b in zip(*runs))


class _null:
    def __enter__(self):
        return None

    def __exit__(self, *exc):
        return False
