"""The native vector env (``envs/vector.py``) equals N single envs: ``gym.make_vec(id, n)`` against Gymnasium's
``SyncVectorEnv`` over ``gym.make(id)`` with the same seeds and actions gives the same observations, rewards,
terminations, truncations and info, bit for bit, in every autoreset mode, for every id and the configs that take
other code paths (aim types, noise, spin, features, truncation). The single envs of the reference run their
Python step path; the single env's compiled fast step (``envs/_pot_fast.py``) is checked against it too."""
from __future__ import annotations

import numba
import numpy as np
import pytest
from env_helpers import FAST_RENDER, GAME_IDS, IDS, POT_IDS, gym
from gymnasium.vector import AutoresetMode, SyncVectorEnv

from billiards_env.envs.config import ACTION_TYPES, OBSERVATION_TYPES
from billiards_env.envs.vector import BilliardsVectorEnv


def _same_info(a: dict, b: dict, where: str = "info", ordered: bool = False) -> None:
    """The same keys (``ordered``: in the same order too), arrays, dtypes and masks."""
    assert set(a) == set(b), (where, sorted(a), sorted(b))
    if ordered:
        assert list(a) == list(b), (where, list(a), list(b))
    for key in a:
        x, y = a[key], b[key]
        if isinstance(x, dict):
            _same_info(x, y, f"{where}/{key}", ordered)
            continue
        assert x.dtype == y.dtype, (where, key, x.dtype, y.dtype)
        if x.dtype == object:
            for p, q in zip(x.tolist(), y.tolist()):
                if isinstance(p, np.ndarray):
                    assert np.array_equal(p, q), (where, key)
                else:
                    assert p == q, (where, key, p, q)
        else:
            assert np.array_equal(x, y), (where, key, x, y)


def _follows_schema(info: dict, schema: dict, n: int) -> None:
    """A vector info in Gymnasium's layout of the single env's schema: every key of the schema, each an array of
    shape ``(n, *shape)`` and the schema's dtype with its ``_key`` mask (``final_info`` the same), never object
    arrays besides ``final_obs``."""
    keys = [k for k in info if not k.startswith("_") and k not in ("final_obs", "final_info")]
    assert keys == list(schema), (keys, list(schema))
    for key in keys:
        spec = schema[key]
        assert info[key].dtype == spec.dtype and info[key].shape == (n, *spec.shape), (key, info[key], spec)
        assert info["_" + key].dtype == np.bool_ and info["_" + key].shape == (n,)
    if "final_info" in info:
        _follows_schema(info["final_info"], schema, n)


def python_path_env(env_id: str, **kwargs) -> gym.Env:
    """``gym.make(env_id)`` on its Python step path (``fast_step`` off: no compiled fast step, shots through
    ``Simulator.run``): the reference the compiled paths must equal."""
    env = gym.make(env_id, **kwargs)
    env.unwrapped.fast_step = False
    return env


def _compare(env_id: str, mode: AutoresetMode, steps: int, n: int = 4, seed: int = 7, **kwargs) -> dict:
    """Step the native vector env and SyncVectorEnv of single envs on their Python path side by side; returns
    counts of what was exercised."""
    vec = gym.make_vec(env_id, n, autoreset_mode=mode, **kwargs)
    ref = SyncVectorEnv([lambda: python_path_env(env_id, **kwargs) for _ in range(n)], autoreset_mode=mode)
    obs, info = vec.reset(seed=seed)
    obs_r, info_r = ref.reset(seed=seed)
    assert np.array_equal(obs, obs_r)
    ordered = True  # the info's keys in Gymnasium's order
    _same_info(info, info_r, ordered=ordered)
    _follows_schema(info, vec.unwrapped.template.info_schema, n)
    rng = np.random.default_rng(seed)
    seen = {"done": 0, "scratch": 0, "pocketed": 0}
    needs_reset = np.zeros(n, bool)
    for step in range(steps):
        if mode == AutoresetMode.DISABLED and needs_reset.any():
            obs, _ = vec.reset(options={"reset_mask": needs_reset.copy()})
            obs_r, _ = ref.reset(options={"reset_mask": needs_reset.copy()})
            assert np.array_equal(obs, obs_r)
        action = rng.uniform(-1.0, 1.0, vec.action_space.shape).astype(np.float32)
        out, out_r = vec.step(action), ref.step(action)
        for x, y, name in zip(out[:4], out_r[:4], ("obs", "reward", "terminated", "truncated")):
            assert x.dtype == y.dtype and np.array_equal(x, y), (step, name, x, y)
        _same_info(out[4], out_r[4], ordered=ordered)
        _follows_schema(out[4], vec.unwrapped.template.info_schema, n)
        needs_reset = out[2] | out[3]
        seen["done"] += int(needs_reset.sum())
        info = out[4].get("final_info", out[4])
        seen["scratch"] += int(np.sum(info.get("scratch", [])))
        seen["pocketed"] += int(np.sum(info.get("pocketed", [])))
    vec.close()
    ref.close()
    return seen


@pytest.mark.parametrize("mode", list(AutoresetMode))
@pytest.mark.parametrize("env_id", POT_IDS)
def test_native_vector_env_equals_single_envs(env_id, mode):
    seen = _compare(env_id, mode, steps=25 if env_id != "BilliardsRack-v0" else 12)
    assert seen["done"] > 0 or env_id == "BilliardsRack-v0"
    assert seen["pocketed"] > 0


@pytest.mark.parametrize("kwargs", [
    {"action_type": "relative", "angle_noise": 0.01, "speed_noise": 0.05, "max_shots": 3},
    {"action_type": "ghost", "observation_type": "features"},
    {"physics": {"friction": "spin"}, "spin_action": True, "tip_noise": 0.05},
    {"step_penalty": 0.1, "miss_penalty": 0.5, "scratch_penalty": 2.0, "n_object_balls": 5},
], ids=["relative-noise-truncation", "ghost-features", "spin", "rewards"])
def test_native_paths_equal_single_envs(kwargs):
    seen = _compare("BilliardsThreeBalls-v0", AutoresetMode.SAME_STEP, steps=20, **kwargs)
    assert seen["done"] > 0 and seen["scratch"] + seen["pocketed"] > 0


#: The games the native vector env plays in compiled code (rules and the geometric opponent included).
NATIVE_GAMES = ["Billiards9Ball-v0", "Billiards8Ball-v0"]


@pytest.mark.parametrize("mode", list(AutoresetMode))
@pytest.mark.parametrize("env_id", NATIVE_GAMES)
def test_native_games_equal_single_envs(env_id, mode):
    """9-ball and 8-ball against the geometric opponent: the agent's shots, the opponent's replies, the calls,
    rewards, resets (the opponent breaking too) and the info of every shot, bit for bit."""
    vec = gym.make_vec(env_id, 2)
    assert vec.unwrapped.native and vec.unwrapped.games is not None
    seen = _compare(env_id, mode, steps=12, n=3, first_shooter="random")
    assert seen["done"] > 0 and seen["pocketed"] > 0


def _same_values(got, want, where: str) -> None:
    """Equal values of the same Python types (recursing into dicts, lists and tuples)."""
    assert type(got) is type(want), (where, got, want)
    if isinstance(want, np.ndarray):
        assert got.dtype == want.dtype and np.array_equal(got, want), (where, got, want)
    elif isinstance(want, dict):
        assert list(got) == list(want), (where, list(got), list(want))
        for key in want:
            _same_values(got[key], want[key], f"{where}/{key}")
    elif isinstance(want, (list, tuple)):
        assert len(got) == len(want), (where, got, want)
        for i, (x, y) in enumerate(zip(got, want)):
            _same_values(x, y, f"{where}[{i}]")
    else:
        assert got == want, (where, got, want)


@pytest.mark.parametrize("env_id", NATIVE_GAMES)
def test_native_game_sub_infos_are_the_single_envs_infos(env_id):
    """``sub_infos`` (the per-table dicts, made only when asked for) is each table's info as its single env returns
    it, key order, values and types (the opponent's turns included), after a reset and through next-step
    autoresets."""
    n = 5
    kw = {"first_shooter": "random", "opening": "either", "opponent_infos": True}
    vec = gym.make_vec(env_id, n, **kw)
    singles = [python_path_env(env_id, **kw) for _ in range(n)]
    vec.reset(seed=3)
    want = [env.reset(seed=3 + k)[1] for k, env in enumerate(singles)]
    _same_values(vec.unwrapped.sub_infos, want, "reset")
    done = [False] * n
    rng = np.random.default_rng(4)
    turns = 0
    for step in range(10):
        action = rng.uniform(-1.0, 1.0, vec.action_space.shape).astype(np.float32)
        vec.step(action)
        want = []
        for k, env in enumerate(singles):
            if done[k]:
                info = env.reset()[1]
                done[k] = False
            else:
                _, _, term, trunc, info = env.step(action[k])
                done[k] = term or trunc
            turns += len(info["opponent_turns"])
            want.append(info)
        _same_values(vec.unwrapped.sub_infos, want, f"step {step}")
    assert turns > 0 and vec.unwrapped.sub_infos is vec.unwrapped.sub_infos  # made once per step


@pytest.mark.parametrize("kwargs", [
    {"action_type": "relative", "angle_noise": 0.01, "speed_noise": 0.05, "opening": "ball_in_hand"},
    {"action_type": "ghost", "observation_type": "features", "first_shooter": "opponent"},
    {"physics": {"friction": "spin"}, "spin_action": True, "tip_noise": 0.02, "angle_noise": 0.003},
    {"action_type": "candidates", "observation_type": "candidates", "opening": "either"},
    {"opponent": None, "opening": "either", "pot_reward": 0.1, "foul_penalty": 0.2, "position_reward": 0.5,
     "max_shots": 4},
    {"rules": {"three_foul_rule": True, "eight_on_break": "win", "call_eight": False}, "speed_noise": 0.05,
     "speed_noise_mode": "absolute", "first_shooter": "random", "placement": "random"},
    {"physics": {"preset": "pooltool"}, "spin_action": True, "tip_noise": 0.02},
], ids=["relative-noise-bih", "ghost-features-opp-breaks", "spin-noise", "candidates-either", "alone-shaping",
        "rules-options-random-rack", "pooltool-squirt"])
@pytest.mark.parametrize("env_id", NATIVE_GAMES)
def test_native_game_paths_equal_single_envs(env_id, kwargs):
    if "rules" in kwargs and env_id == "Billiards9Ball-v0":
        kwargs = {**kwargs, "rules": {"push_out": True, "three_foul_rule": False, "break_rail_balls": 2}}
    seen = _compare(env_id, AutoresetMode.SAME_STEP, steps=16, n=3, **kwargs)
    assert seen["done"] > 0


@pytest.mark.parametrize("env_id", NATIVE_GAMES)
def test_native_games_with_scenes_set_by_hand(env_id):
    """``reset(options=...)`` (positions, ball in hand, groups) goes through the single env's own reset per table."""
    n_balls = 10 if env_id == "Billiards9Ball-v0" else 16
    rng = np.random.default_rng(0)
    vec = gym.make_vec(env_id, 2, autoreset_mode="disabled")
    ref = SyncVectorEnv([lambda: python_path_env(env_id) for _ in range(2)], autoreset_mode=AutoresetMode.DISABLED)
    vec.reset(seed=1)
    ref.reset(seed=1)
    single = gym.make(env_id)
    single.reset(seed=5)
    pos = single.unwrapped.balls.pos.copy()
    pos[0] = (0.4, 0.3)
    options = {"positions": pos, "ball_in_hand": "anywhere", "reset_mask": np.array([False, True])}
    if n_balls == 16:
        options["groups"] = ("stripes", "solids")
    obs, info = vec.reset(options=dict(options))
    obs_r, info_r = ref.reset(options=dict(options))
    assert np.array_equal(obs, obs_r)
    _same_info(info, info_r)
    for _ in range(3):
        action = rng.uniform(-1.0, 1.0, vec.action_space.shape).astype(np.float32)
        out, out_r = vec.step(action), ref.step(action)
        for x, y in zip(out[:4], out_r[:4]):
            assert np.array_equal(x, y)
        _same_info(out[4], out_r[4])
        if (out[2] | out[3]).any():
            break


def test_other_opponents_run_the_sub_envs_one_by_one():
    vec = gym.make_vec("Billiards9Ball-v0", 2, opponent="random")
    assert isinstance(vec.unwrapped, BilliardsVectorEnv) and not vec.unwrapped.native
    assert "opponent" in vec.unwrapped.not_native
    _compare("Billiards9Ball-v0", AutoresetMode.NEXT_STEP, steps=4, n=2, opponent="random")


def test_every_id_has_a_native_vector_entry_point():
    for env_id in IDS:
        spec = gym.spec(env_id)
        assert spec.vector_entry_point is not None
        vec = gym.make_vec(env_id, 2)  # the default mode uses the vector entry point
        assert isinstance(vec, BilliardsVectorEnv) and vec.env_id == env_id
        assert isinstance(vec.metadata["autoreset_mode"], AutoresetMode)
        assert vec.single_observation_space == gym.make(env_id).observation_space
        vec.close()


def test_seeding_per_sub_env():
    vec = gym.make_vec("BilliardsThreeBalls-v0", 3)
    single = gym.make("BilliardsThreeBalls-v0")
    obs, _ = vec.reset(seed=[11, None, 5])
    assert np.array_equal(obs[0], single.reset(seed=11)[0]) and np.array_equal(obs[2], single.reset(seed=5)[0])
    assert vec.np_random_seed[0] == 11 and vec.np_random_seed[2] == 5
    # Resetting without a seed continues each sub-env's stream, as a single env does.
    single.reset(seed=11)
    again, _ = vec.reset(options={"reset_mask": np.array([True, False, False])})
    assert np.array_equal(again[0], single.reset()[0]) and np.array_equal(again[1:], obs[1:])


@pytest.mark.parametrize("env_id, n, steps", [("BilliardsThreeBalls-v0", 32, 5), ("Billiards9Ball-v0", 24, 4)])
def test_result_does_not_depend_on_the_thread_count(env_id, n, steps):
    """The native step (the pot task's kernel, and the games' with the opponent's turns) gives the same batch on one
    numba thread as on two."""
    if numba.config.NUMBA_NUM_THREADS < 2:
        pytest.skip("needs two numba threads")
    runs = []
    for threads in (1, 2):
        vec = gym.make_vec(env_id, n, threads=threads, autoreset_mode="same_step")
        vec.reset(seed=1)
        rng = np.random.default_rng(2)
        runs.append([vec.step(rng.uniform(-1, 1, vec.action_space.shape))[:4] for _ in range(steps)])
    for a, b in zip(*runs):
        for x, y in zip(a, b):
            assert np.array_equal(x, y)


@pytest.mark.parametrize("kwargs", [{}, {"physics": {"friction": "spin"}, "spin_action": True, "angle_noise": 0.01}])
def test_pot_step_on_threads_gives_the_serial_batch(kwargs):
    """The pot task's parallel step (slices of the tables on Python threads, one compiled call each) gives the serial
    step's batch and infos on any thread count, the final observations and infos of a same-step autoreset too."""
    runs = []
    for threads in (1, 2, 3):
        vec = gym.make_vec("BilliardsThreeBalls-v0", 20, threads=threads, autoreset_mode="same_step", **kwargs)
        vec.reset(seed=3)
        rng = np.random.default_rng(4)
        runs.append([vec.step(rng.uniform(-1, 1, vec.action_space.shape)) for _ in range(6)])
    for other in runs[1:]:
        for a, b in zip(runs[0], other):
            for x, y in zip(a[:4], b[:4]):
                assert np.array_equal(x, y)
            _assert_same_info(a[4], b[4])


def _assert_same_info(a: dict, b: dict) -> None:
    """Two vector infos alike: the same keys in the same order, arrays of the same dtype and values."""
    assert list(a) == list(b)
    for key in a:
        x, y = a[key], b[key]
        if isinstance(x, dict):
            _assert_same_info(x, y)
        elif x.dtype == object:
            assert all((u is None and v is None) or np.array_equal(u, v) for u, v in zip(x, y))
        else:
            assert x.dtype == y.dtype and np.array_equal(x, y)


def test_render_draws_the_chosen_sub_env():
    vec = gym.make_vec("BilliardsThreeBalls-v0", 3, render_mode="rgb_array", render_env=2, **FAST_RENDER)
    single = gym.make("BilliardsThreeBalls-v0", render_mode="rgb_array", **FAST_RENDER)
    vec.reset(seed=4)
    single.reset(seed=6)
    assert np.array_equal(vec.render(), single.render())
    actions = np.array([[0.3, 0.2]] * 3, np.float32)
    vec.step(actions)
    single.step(actions[2])
    assert np.array_equal(vec.render(), single.render())  # after the shot, with its cue line

    vec = gym.make_vec("BilliardsOneBall-v0", 2, render_mode="rgb_array_list", render_env=1, **FAST_RENDER)
    single = gym.make("BilliardsOneBall-v0", render_mode="rgb_array_list", **FAST_RENDER)
    vec.reset(seed=0)
    single.reset(seed=1)
    vec.step(np.array([[0.1, 0.5], [0.1, 0.5]], np.float32))
    single.step(np.array([0.1, 0.5], np.float32))
    frames, frames_single = vec.render(), single.render()
    assert len(frames) == len(frames_single) > 2
    assert all(np.array_equal(a, b) for a, b in zip(frames, frames_single))


def test_bad_use_is_refused_with_the_fix():
    vec = gym.make_vec("BilliardsOneBall-v0", 2, autoreset_mode="disabled")
    with pytest.raises(gym.error.ResetNeeded, match="reset"):
        vec.step(np.zeros((2, 2), np.float32))
    vec.reset(seed=0)
    with pytest.raises(ValueError, match=r"actions\[1\]: must be finite"):
        vec.step(np.array([[0.0, 0.0], [np.nan, 0.0]]))
    with pytest.raises(ValueError, match=r"expected a batch of shape \(2, 2\)"):
        vec.step(np.zeros(3))
    vec.step(np.zeros((2, 2), np.float32))  # one-shot episodes: both end
    with pytest.raises(gym.error.ResetNeeded, match="reset_mask"):
        vec.step(np.zeros((2, 2), np.float32))
    with pytest.raises(ValueError, match="autoreset_mode"):
        gym.make_vec("BilliardsOneBall-v0", 2, autoreset_mode="sometimes")
    with pytest.raises(ValueError, match="render_env"):
        gym.make_vec("BilliardsOneBall-v0", 2, render_env=2)


@pytest.mark.parametrize("kwargs", [{}, {"action_type": "relative", "angle_noise": 0.02, "speed_noise": 0.1},
                                    {"physics": {"friction": "spin"}, "spin_action": True, "tip_noise": 0.05}],
                         ids=["plain", "relative-noise", "spin"])
@pytest.mark.parametrize("env_id", POT_IDS)
def test_single_env_fast_step_equals_its_python_path(env_id, kwargs):
    fast, slow = gym.make(env_id, **kwargs), python_path_env(env_id, **kwargs)
    assert fast.unwrapped._pot_fast is not None
    rng = np.random.default_rng(5)
    for episode in range(6):
        obs = fast.reset(seed=episode)[0]
        assert np.array_equal(obs, slow.reset(seed=episode)[0])
        for _ in range(6):
            a = rng.uniform(-1, 1, fast.action_space.shape).astype(np.float32)
            out, ref = fast.step(a), slow.step(a)
            assert np.array_equal(out[0], ref[0]) and out[0].dtype == ref[0].dtype
            assert out[1:4] == ref[1:4]
            _same_values(out[4], ref[4], "fast step")
            assert [type(v) for v in out[4].values()] == [type(v) for v in ref[4].values()]
            assert fast.unwrapped.last_shot == slow.unwrapped.last_shot
            if out[2] or out[3]:
                break


COMBINATIONS = [(env_id, at, ot, spin) for env_id in IDS for at in ACTION_TYPES for ot in OBSERVATION_TYPES
                for spin in (False, True)]


@pytest.mark.parametrize("env_id,action_type,observation_type,spin", COMBINATIONS,
                         ids=[f"{e}-{a}-{o}-{'spin' if s else 'plain'}" for e, a, o, s in COMBINATIONS])
def test_every_combination_vectorises_with_the_same_results(env_id, action_type, observation_type, spin):
    """Every id x action type x observation type x spin dims: the native vector env equals N single envs (reset and
    a few steps, bit for bit), the candidates types included."""
    kwargs = {"action_type": action_type, "observation_type": observation_type}
    if env_id in GAME_IDS:
        kwargs["opponent"] = None  # the types are under test; the opponent's are test_native_games_...
    if spin:
        kwargs.update(physics={"friction": "spin"}, spin_action=True)
    _compare(env_id, AutoresetMode.NEXT_STEP, steps=3 if env_id in POT_IDS else 2, n=2, **kwargs)


def test_game_infos_stack_as_gymnasiums_add_info():
    """``stack_infos`` (the games' vector info, a key at a time) equals ``VectorEnv._add_info`` called sub-env by
    sub-env: dtypes from each key's first value (a bool array when the first ``ball_in_hand`` is False), masks, nested
    dicts, ``final_obs``, key order."""
    from gymnasium.vector import VectorEnv

    from billiards_env.envs._vector_games import stack_infos

    class Stub(VectorEnv):
        num_envs = 4

    stub = Stub()
    obs = np.arange(3, dtype=np.float32)
    entries = [(0, {"ball_in_hand": False, "winner": -1, "turns": [], "groups": None}),
               (1, {"final_obs": obs, "final_info": {"ball_in_hand": "anywhere", "call": "legal"}}),
               (1, {"ball_in_hand": "kitchen", "winner": 1, "turns": [{"a": 1}], "call": "scratch", "x": 0.5}),
               (3, {"groups": ("solids", "stripes"), "winner": 0, "x": np.float64(2.0)})]
    want: dict = {}
    for k, info in entries:
        want = stub._add_info(want, info, k)
    got = stack_infos(4, entries)
    assert list(got) == list(want)
    _same_info({k: v for k, v in got.items() if k != "final_obs"}, {k: v for k, v in want.items() if k != "final_obs"})
    assert got["final_obs"][1] is obs and got["final_obs"][0] is None


@pytest.mark.parametrize("spin", [False, True])
def test_native_candidates_kicks(spin):
    """The ``candidates`` types compiled in the native games: a hidden ball (every pot blocked) is kicked at, the
    kick's values observed, as the single env does (a scene set by hand, then the kick slot and others)."""
    kw = {"action_type": "candidates", "observation_type": "candidates", "opponent": None}
    if spin:
        kw.update(physics={"friction": "spin"}, spin_action=True)
    vec = gym.make_vec("Billiards9Ball-v0", 3, autoreset_mode=AutoresetMode.DISABLED, **kw)
    ref = SyncVectorEnv([lambda: python_path_env("Billiards9Ball-v0", **kw) for _ in range(3)],
                        autoreset_mode=AutoresetMode.DISABLED)
    pos = np.array([[0.5, 0.35], [1.5, 0.35], [1.0, 0.35]] + [[0.3 + 0.1 * k, 1.2] for k in range(7)])
    off = np.array([False] * 3 + [True] * 7)
    for env in (vec, ref):
        env.reset(seed=0)
    options = {"positions": pos, "pocketed": off, "reset_mask": np.ones(3, bool)}
    obs, _ = vec.reset(options=dict(options))
    obs_r, _ = ref.reset(options=dict(options))
    assert np.array_equal(obs, obs_r)
    kick_row = obs[0, 30 + 3 * 12:30 + 4 * 12]
    assert kick_row[0] == 1.0 and kick_row[2] == kick_row[3] == -1.0  # the kick is observed
    action = np.zeros(vec.action_space.shape, np.float32)
    action[:, 0] = (-1.0, 0.2, 0.9)  # the kick, a blocked pot, the kick again
    action[:, 1] = (0.5, -0.3, 0.0)
    out, out_r = vec.step(action), ref.step(action)
    for x, y in zip(out[:4], out_r[:4]):
        assert np.array_equal(x, y)
    _same_info(out[4], out_r[4])
    assert out[4]["first_contact"][0] == 1  # the kick hit the hidden ball (row 1: ball "1")


def test_fast_step_values_carry_the_record_fields_in_order():
    """The single env's compiled step reads a table's shot and outcome records as named tuples made from
    ``item()``: a field added to, dropped from or moved in a record without the tuple would read the wrong value."""
    from billiards_env.envs._pot_fast import OutcomeValues, ShotValues
    from billiards_env.envs._vector_kernels import POT_OUTCOME, POT_SHOT

    assert ShotValues._fields == POT_SHOT.names
    assert OutcomeValues._fields == POT_OUTCOME.names
    record = np.zeros((), POT_SHOT)
    record["speed"] = 2.5
    assert ShotValues._make(record.item()).speed == 2.5
