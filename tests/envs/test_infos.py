"""One info schema per env id: the same keys at reset and at every step, each value of the schema's type, dtype and
shape (never an object array), for the single env, its vector envs and the two-player envs; the documented tables
list exactly the schema's keys; the words of an info lose nothing."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from env_helpers import GAME_IDS, IDS, POT_IDS, gym

from billiards_env.envs import ENV_CLASSES
from billiards_env.envs.__main__ import info_tables_markdown
from billiards_env.envs.config import load_config
from billiards_env.envs.info import OPPONENT_TURNS, info_schema

DOC = Path(__file__).resolve().parents[2] / "docs" / "infos.md"
def check_info(info: dict, schema: dict, where: str) -> None:
    """``info`` has exactly the schema's keys in its order, each value of its form: for shape () a 0-d boolean
    array (a flag) or a numpy scalar of the dtype (TorchRL reads each value's dtype; Gymnasium's vector envs stack
    neither as objects), else a numpy array of the dtype and shape; ``np.asarray`` of it never an object array."""
    assert list(info) == list(schema), (where, list(info), list(schema))
    for key, spec in schema.items():
        value = info[key]
        arr = np.asarray(value)
        assert arr.dtype != object, (where, key, value)
        assert arr.dtype == spec.dtype and arr.shape == spec.shape, (where, key, value, spec)
        if spec.shape:
            assert type(value) is np.ndarray, (where, key, type(value))
        else:
            want = np.ndarray if spec.dtype is np.bool_ else spec.dtype
            assert type(value) is want, (where, key, type(value))
        if spec.names and value >= 0:
            assert value < len(spec.names), (where, key, value)


def rollout_infos(env, seeds=(0, 1, 2), steps: int = 8) -> list[dict]:
    """Reset infos and step infos of random actions over a few seeds (resetting at episode ends)."""
    out = []
    for seed in seeds:
        env.action_space.seed(seed)
        out.append(env.reset(seed=seed)[1])
        for _ in range(steps):
            *_, term, trunc, info = env.step(env.action_space.sample())
            out.append(info)
            if term or trunc:
                out.append(env.reset()[1])
    return out


@pytest.mark.parametrize("env_id", IDS)
def test_reset_and_step_infos_follow_the_schema(env_id):
    env = gym.make(env_id)
    schema = env.unwrapped.info_schema
    assert schema == info_schema(env.unwrapped.config)
    infos = rollout_infos(env)
    for k, info in enumerate(infos):
        check_info(info, schema, f"{env_id} info {k}")
    shots = [i for i in infos if i["status"] >= 0]  # the steps' (a reset says no shot: status -1)
    assert shots and len(shots) < len(infos)
    assert all(i["status"] == -1 and i["first_contact"] == -1 and not i["pocketed"].any()
               for i in infos if i["shots"] == 0)  # a reset: the shot's keys blank
    assert any(i["first_contact"] >= 0 for i in shots)
    if env_id in GAME_IDS:
        assert any(i["legal_targets"].any() for i in infos) and all(i["call"] >= 0 for i in shots)
    env.close()


@pytest.mark.parametrize("env_id", ["Billiards9Ball-v0", "BilliardsSnooker-v0"])
def test_other_configs_and_the_python_path_follow_the_schema(env_id):
    """More balls, the spin action, noise and the Python step path: still the schema of the config."""
    kw = {"physics": {"friction": "spin"}, "spin_action": True, "angle_noise": 0.01}
    if env_id == "Billiards9Ball-v0":
        kw["opening"] = "either"
    env = gym.make(env_id, **kw)
    env.unwrapped.fast_step = False
    for k, info in enumerate(rollout_infos(env, seeds=(3,), steps=6)):
        check_info(info, env.unwrapped.info_schema, f"{env_id} info {k}")
    pot = gym.make("BilliardsRack-v0", n_object_balls=6, **{k: v for k, v in kw.items() if k != "opening"})
    assert pot.unwrapped.info_schema["pocketed"].shape == (7,)
    for k, info in enumerate(rollout_infos(pot, seeds=(3,), steps=4)):
        check_info(info, pot.unwrapped.info_schema, f"rack-6 info {k}")


@pytest.mark.parametrize("env_id", IDS)
def test_vector_env_infos_follow_the_schema(env_id):
    """Every id's vector env (the native one, or its sub-envs one by one): each key of the schema stacked as
    ``(n, *shape)`` of its dtype, with its mask, at reset and at every step."""
    n = 2
    vec = gym.make_vec(env_id, n, vectorization_mode="vector_entry_point")
    schema = vec.unwrapped.template.info_schema

    def check(info: dict, where: str) -> None:
        keys = [k for k in info if not k.startswith("_") and k not in ("final_obs", "final_info")]
        assert keys == list(schema), (where, keys)
        for key, spec in schema.items():
            assert info[key].dtype == spec.dtype and info[key].shape == (n, *spec.shape), (where, key)
            assert info["_" + key].all(), (where, key)

    check(vec.reset(seed=0)[1], "reset")
    rng = np.random.default_rng(0)
    for step in range(4):
        check(vec.step(rng.uniform(-1, 1, vec.action_space.shape).astype(np.float32))[4], f"step {step}")
    vec.close()


@pytest.mark.parametrize("module", ["nine_ball_v0", "snooker_v0", "three_cushion_v0"])
def test_two_player_infos_have_fixed_keys_and_forms(module):
    import importlib

    env = importlib.import_module(f"billiards_env.multi.{module}").env()
    env.reset(seed=0)
    game = env.unwrapped.game_env
    schema = {k: v for k, v in game.info_schema.items() if not k.startswith("opponent_")}
    keys = None
    rng = np.random.default_rng(0)
    for n, agent in enumerate(env.agent_iter()):
        obs, r, term, trunc, info = env.last()
        own = {k: v for k, v in info.items() if k not in ("player", "shot_by")}
        check_info(own, {k: schema[k] for k in own}, f"{module} {n}")
        assert set(own) == set(schema), set(own) ^ set(schema)
        keys = keys or list(info)
        assert list(info) == keys
        env.step(None if term or trunc else rng.uniform(-1, 1, env.action_space(agent).shape).astype(np.float32))
        if n >= 8:
            break
    env.close()


def test_opponent_turns_only_with_the_option():
    """``opponent_infos=True`` adds the opponent's shots one by one (after the schema's keys, at reset and at every
    step), each entry in the info's forms; the schema's keys are the same either way."""
    env = gym.make("Billiards8Ball-v0", opponent_infos=True, first_shooter="opponent")
    schema = env.unwrapped.info_schema
    assert OPPONENT_TURNS not in schema
    seen = 0
    for info in rollout_infos(env, seeds=(0, 1), steps=6):
        turns = info[OPPONENT_TURNS]
        check_info({k: v for k, v in info.items() if k != OPPONENT_TURNS}, schema, "with opponent_infos")
        assert list(info)[-1] == OPPONENT_TURNS and len(turns) == info["opponent_shots"]
        for t in turns:
            check_info({k: t[k] for k in schema if k in t}, {k: schema[k] for k in schema if k in t}, "a turn")
            assert t["call"] >= 0 and t["shooter"] == 1
        seen += len(turns)
    assert seen > 0


@pytest.mark.parametrize("env_id", IDS)
def test_info_words_lose_nothing(env_id):
    """The words of an info (ids, names) map back to its values: masks, rows and codes."""
    env = gym.make(env_id, opponent_infos=True) if env_id in GAME_IDS else gym.make(env_id)
    u = env.unwrapped
    schema = u.info_schema
    for info in rollout_infos(env, seeds=(0,), steps=4):
        ids = u.ball_ids
        words = u.info_words(info, ids=ids)
        for key, spec in schema.items():
            got = words[key]
            if spec.names:
                assert (spec.names.index(got) if got is not None else -1) == info[key]
            elif key == "first_contact":
                assert (ids.index(got) if got is not None else -1) == info[key]
            elif spec.dtype is np.bool_ and spec.shape:
                assert tuple(ids[i] for i in np.flatnonzero(info[key])) == got
        if env_id == "BilliardsSnooker-v0":
            assert isinstance(words["on"], str) and words["on"] in ("red", "colour", "yellow", "green", "brown",
                                                                     "blue", "pink", "black")


def _doc_tables() -> dict[str, list[tuple[str, str, str]]]:
    """docs/infos.md's tables: env id -> its rows (key, dtype, shape)."""
    tables: dict[str, list[tuple[str, str, str]]] = {}
    current = None
    for line in DOC.read_text().splitlines():
        m = re.match(r"### (\S+)$", line)
        if m:
            current = tables.setdefault(m.group(1), [])
        m = re.match(r"\| `(\w+)` \| (\w+) \| (\([\d, ]*\)) \|", line)
        if m and current is not None:
            current.append(m.groups())
    return tables


def test_the_documented_tables_list_exactly_the_schemas_keys():
    tables = _doc_tables()
    assert list(tables) == IDS
    for env_id, rows in tables.items():
        schema = info_schema(load_config(ENV_CLASSES[env_id].scene))
        assert [key for key, _, _ in rows] == list(schema), env_id
        for key, dtype, shape in rows:
            assert dtype == schema[key].dtype.__name__.rstrip("_") and shape == str(schema[key].shape), (env_id, key)
    assert info_tables_markdown() in DOC.read_text()  # the page holds the tables the command prints


def test_pot_and_game_schemas_share_the_shot_keys():
    pot = info_schema(load_config(ENV_CLASSES[POT_IDS[0]].scene))
    game = info_schema(load_config(ENV_CLASSES["Billiards9Ball-v0"].scene))
    shot = [k for k in pot if k != "is_success"]
    assert list(game)[-len(shot):] == shot and list(game)[0] == list(pot)[0] == "is_success"


@pytest.mark.parametrize("env_id", IDS)
def test_an_episodes_infos_stack_and_go_to_hdf5(env_id, tmp_path):
    """What Minari's DataCollector(record_infos=True) does with the infos: each step's info checked against the
    reset's (its own check where Minari is installed: same keys, Python types, array shapes and dtypes), each key
    stacked over the episode into one array of the schema's dtype, written to HDF5 and read back equal."""
    h5py = pytest.importorskip("h5py")
    env = gym.make(env_id)
    infos = rollout_infos(env, seeds=(0,), steps=6)
    try:
        from minari.data_collector.data_collector import _check_infos_same_shape
    except ImportError:  # (Minari absent or moved: the keys, types and forms are checked above)
        _check_infos_same_shape = None
    if _check_infos_same_shape is not None:
        assert all(_check_infos_same_shape(infos[0], info) for info in infos[1:])
    schema = env.unwrapped.info_schema
    with h5py.File(tmp_path / "infos.h5", "w") as f:
        for key, spec in schema.items():
            stacked = np.stack([info[key] for info in infos])
            assert stacked.dtype == spec.dtype and stacked.shape == (len(infos), *spec.shape)
            f.create_dataset(key, data=stacked)
    with h5py.File(tmp_path / "infos.h5", "r") as f:
        for key in schema:
            assert np.array_equal(f[key][()], np.stack([info[key] for info in infos]))
