"""The option-scoring policy on the ``candidates_position`` observation (agents/scorer.py)."""
from __future__ import annotations

import numpy as np
import pytest

from agents.scorer import N_GRID, N_SLOTS, OPTION_FEATURES, Scorer, action_of, fit, option_of, options
from billiards_env.envs.candidates import SLOT_FEATURES
from billiards_env.envs.position import POINT_VALUES, POSITION_FEATURES, POWERS, TOPS

N_BALLS, N_GAME = 10, 11


def _obs(rng, n=1):
    """Observations with pots in the first ``N_SLOTS - 1`` slots and random position maps."""
    d = 3 * N_BALLS + (SLOT_FEATURES + POSITION_FEATURES) * N_SLOTS + N_GAME
    o = np.zeros((n, d), np.float32)
    base = 3 * N_BALLS
    slots = o[:, base:base + SLOT_FEATURES * N_SLOTS].reshape(n, N_SLOTS, SLOT_FEATURES)
    grid = o[:, base + SLOT_FEATURES * N_SLOTS:base + (SLOT_FEATURES + POSITION_FEATURES) * N_SLOTS].reshape(
        n, N_SLOTS, N_GRID, POINT_VALUES)
    slots[:, :N_SLOTS - 1, 0] = 1.0
    slots[:, :N_SLOTS - 1, 7] = rng.uniform(0, 1, (n, N_SLOTS - 1))
    grid[:, :N_SLOTS - 1] = rng.uniform(0, 1, (n, N_SLOTS - 1, N_GRID, POINT_VALUES))
    return o, grid


def test_options_and_actions():
    rng = np.random.default_rng(0)
    o, grid = _obs(rng, 2)
    feats, valid = options(o)
    assert feats.shape == (2, (N_SLOTS - 1) * N_GRID, OPTION_FEATURES) and valid.all()
    # option k * N_GRID + g carries slot k's values, grid point g's, its power and top
    k, g = 1, 7
    f = feats[0, k * N_GRID + g]
    assert np.array_equal(f[SLOT_FEATURES:SLOT_FEATURES + POINT_VALUES], grid[0, k, g])
    assert f[SLOT_FEATURES + POINT_VALUES] == pytest.approx(POWERS[g // len(TOPS)])
    assert f[SLOT_FEATURES + POINT_VALUES + 1] == pytest.approx(TOPS[g % len(TOPS)])
    # the action of an option maps back to it; the kick slot is not an option
    for opt in (0, 5, N_GRID + 3, 2 * N_GRID + N_GRID - 1):
        assert option_of(action_of(opt)) == divmod(opt, N_GRID)
    assert option_of(np.array([0.99, 0, 0, 0, 0, 0]))[0] == -1
    # an empty slot has no options; no options at all: action 0
    o[0, 3 * N_BALLS + SLOT_FEATURES * 1] = 0.0
    assert not options(o)[1][0, N_GRID:2 * N_GRID].any()
    empty = np.zeros_like(o[:1])
    assert not options(empty)[1].any()


def test_it_learns_a_choice_that_depends_on_the_options_features(tmp_path):
    """Teacher: the option with the largest next-shot ease among those that do not scratch. The scorer learns it
    (agreement well above chance, 1 / 36), and a saved scorer plays as the fitted one."""
    torch = pytest.importorskip("torch")
    rng = np.random.default_rng(1)
    o, grid = _obs(rng, 1500)
    grid[..., 1] = rng.uniform(0, 1, grid.shape[:3]) < 0.3
    value = grid[:, :N_SLOTS - 1, :, 4] * (1 - grid[:, :N_SLOTS - 1, :, 1])
    best = value.reshape(len(o), -1).argmax(1)
    actions = np.stack([action_of(int(b)) for b in best])
    net, info = fit(o, actions, epochs=20, hidden=32)
    assert info["used"] == len(o) and info["holdout_agreement"] > 0.6
    sc = Scorer(net)
    with torch.no_grad():
        feats, _ = options(o[:5])
        ref = net(torch.as_tensor(feats)).squeeze(-1).numpy()
    assert np.allclose(np.stack([sc.scores(f) for f in feats]), ref, atol=1e-5)
    path = tmp_path / "scorer.pt"
    sc.save(path)
    again = Scorer.load(path)
    for x in o[:20]:
        assert np.array_equal(again.predict(x), sc.predict(x))


def test_the_fallback_moves_with_the_scorer(tmp_path):
    """The fallback policy's path is kept relative to the scorer's folder: both can be moved together."""
    pytest.importorskip("torch")
    from agents.option_policies import make_net as mk

    (tmp_path / "a" / "clone").mkdir(parents=True)
    Scorer([mk(8)], tmp_path / "a" / "clone" / "bc_model.zip").save(tmp_path / "a" / "s.pt")
    (tmp_path / "a").rename(tmp_path / "b")
    assert Scorer.load(tmp_path / "b" / "s.pt").fallback == str((tmp_path / "b" / "clone" / "bc_model.zip").resolve())


def test_it_learns_where_to_put_the_cue_ball():
    """Ball-in-hand labels: the teacher picks the (place, option) with the largest next-shot ease over all places;
    the union of each decision's options is one softmax, so the scorer learns to compare places too."""
    pytest.importorskip("torch")
    from agents.option_policies import HAND_PLACES, hand_options

    rng = np.random.default_rng(2)
    o, grid = _obs(rng, 4500)
    m = len(o) // HAND_PLACES
    hand_obs = o[:m * HAND_PLACES].reshape(m, HAND_PLACES, -1)
    value = grid[:m * HAND_PLACES, :N_SLOTS - 1, :, 4].reshape(m, -1)
    target = value.argmax(1)
    target[:5] = -1  # unmatched labels are left out
    acts = np.zeros((len(o), 6), np.float32)  # the ordinary labels: all the kick (left out)
    acts[:, 0] = 0.99
    net, info = fit(o, acts, epochs=30, hidden=32, hand_obs=hand_obs, hand_target=target)
    assert info["used"] == 0 and info["hand_used"] == m - 5
    assert info["hand_holdout_agreement"] > 0.5  # chance: 1 / 108
    sc = Scorer(net)
    feats, valid = hand_options(hand_obs[7])
    assert valid.all() and feats.shape == (HAND_PLACES * (N_SLOTS - 1) * N_GRID, OPTION_FEATURES)
    p, k = sc.choose_hand(hand_obs[7])
    assert p * (N_SLOTS - 1) * N_GRID + k == int(np.argmax(sc.scores(feats)))
    assert sc.choose_hand(np.zeros_like(hand_obs[7])) is None  # no place with an option
