"""Search with a learned prior (agents/prior_search.py): the policy's proposals take the sweep's place in the search,
at the search player's own simulation budget."""
from __future__ import annotations

import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from agents.config import load_train_config  # noqa: E402
from agents.distill import distill  # noqa: E402


@pytest.fixture(scope="module")
def policy_zip(tmp_path_factory):
    """A 9-ball policy in the agent's types, cloned from a few of the geometric player's shots (quick)."""
    root = tmp_path_factory.mktemp("prior")
    cfg = load_train_config("configs/train/nine_ball_distill.yaml", overrides={"run_root": str(root)})
    rep = distill(cfg, teacher="geometric", states=2, bc_epochs=2, workers=1, eval_episodes=0, quiet=True)
    return f"{rep['run_dir']}/bc_model.zip"


def _rows_simulated(monkeypatch):
    import billiards_env.players.search as search

    calls: list[int] = []
    real = search.run_shots

    def counting(sim, balls, angles, *a, **kw):
        calls.append(len(np.atleast_1d(angles)))
        return real(sim, balls, angles, *a, **kw)

    monkeypatch.setattr(search, "run_shots", counting)
    return calls


def test_the_prior_search_plays_at_the_search_players_budget(policy_zip, monkeypatch):
    import gymnasium as gym

    import billiards_env  # noqa: F401
    from billiards_env.players import make_player

    from agents.prior_search import PriorSearchPlayer, prior_search_player

    prior = prior_search_player(policy_zip, "nine_ball", seed=1)
    assert isinstance(prior, PriorSearchPlayer) and prior.budget() == 72 * 3
    plain = make_player("search", seed=1, game="nine_ball")
    env = gym.make("Billiards9Ball-v0", friction="spin", spin_action=True, opponent=None)
    pos = np.array([[0.6, 0.5], [1.6, 0.7], [1.9, 0.3], [2.1, 1.0], [0.9, 1.0], [1.3, 0.25], [2.3, 0.6],
                    [1.1, 0.7], [0.4, 1.1], [1.8, 1.05]])
    obs, _ = env.reset(seed=4, options={"positions": pos, "pocketed": np.zeros(10, bool), "ball_in_hand": False,
                                        "break_shot": False})
    calls = _rows_simulated(monkeypatch)
    a_plain = plain.act(env, obs)
    n_plain = list(calls)
    calls.clear()
    a_prior = prior.act(env, obs)
    assert list(calls) == n_plain  # the same batches of simulated shots, row for row
    space = env.action_space
    assert space.contains(np.asarray(a_prior, np.float32)) and space.contains(np.asarray(a_plain, np.float32))
    # its proposals: the policy's own shot first, within the budget
    state = env.unwrapped.table_state
    prior.policy.prepare(state, env.unwrapped.action_type)
    mine = prior.policy.action_type.shot(state, prior.policy.predict(prior.policy.observation_type.observe(state)))
    rows = prior.proposals(state, mine, True)
    assert 1 <= len(rows) <= prior.budget()
    assert rows[0, 0] == pytest.approx(mine.angle) and rows[0, 1] == pytest.approx(mine.speed)


def test_the_league_takes_a_prior_player(policy_zip):
    from agents.league import league_env_kwargs, load_player

    name, player = load_player(f"prior:{policy_zip}", 0, "nine_ball")
    assert name.startswith("search+prior(")
    kw = league_env_kwargs([(name, player)], spin=False, noise="0")
    assert kw["physics"]["friction"] == "spin" and kw["spin_action"]  # the policy's physics


#: A table whose 1 is a straight-in at a corner pocket (an easy pot), and one whose easiest pot is a long cut (hard).
EASY = np.array([[0.6, 0.6], [0.3, 0.3], [1.9, 0.3], [2.1, 1.0], [0.9, 1.0], [1.3, 0.25], [2.3, 0.6], [1.1, 0.7],
                 [0.4, 1.1], [1.8, 1.05]])
HARD = np.array([[0.6, 0.5], [1.6, 0.7], [1.9, 0.3], [2.1, 1.0], [0.9, 1.0], [1.3, 0.25], [2.3, 0.6], [1.1, 0.7],
                 [0.4, 1.1], [1.8, 1.05]])


def _noisy_table(pos):
    import gymnasium as gym

    import billiards_env  # noqa: F401

    env = gym.make("Billiards9Ball-v0", friction="spin", spin_action=True, opponent=None, noise="olympiad")
    obs, _ = env.reset(seed=4, options={"positions": pos, "pocketed": np.zeros(10, bool), "ball_in_hand": False,
                                        "break_shot": False})
    return env, obs


def test_under_noise_the_sweep_pays_for_more_re_runs(policy_zip):
    """With shot noise, on a table with an easy pot, the sweep shrinks to the proposals and the re-runs take what it
    frees: the same simulations a decision (up to rounding); without noise, or without a pot for the policy, the
    search's own settings."""
    from agents.prior_search import REALLOCATE_POT_CHANCE, REALLOCATED_TOP_K, pot_chance, prior_search_player

    prior = prior_search_player(policy_zip, "nine_ball", seed=1)
    env, obs = _noisy_table(EASY)
    state = env.unwrapped.table_state
    assert pot_chance(state, prior.search.settings.ease_noise) > REALLOCATE_POT_CHANCE
    prior.policy.prepare(state, env.unwrapped.action_type)
    rows = prior.proposals(state, prior.policy.policy_shot(state), True)
    st = prior.search.settings
    new = prior.settings_for(state, len(rows), noisy=True)
    sweep = lambda s: s.sweep_angles * len(s.sweep_speeds)  # noqa: E731
    budget = sweep(st) + st.top_k * st.robust_samples
    spent = sweep(new) + new.top_k * new.robust_samples
    assert sweep(new) >= len(rows) > sweep(new) - len(st.sweep_speeds)
    assert new.top_k == REALLOCATED_TOP_K and new.robust_samples > st.robust_samples
    assert budget - new.top_k < spent <= budget
    assert (new.n_geometric, new.angle_offsets, new.speed_factors) == (st.n_geometric, st.angle_offsets,
                                                                       st.speed_factors)
    assert prior.settings_for(state, len(rows), noisy=False) is st
    prior.reallocate = False
    assert prior.settings_for(state, len(rows), noisy=True) is st
    prior.reallocate = True
    assert np.asarray(prior.act(env, obs)) in env.action_space


def test_on_a_hard_table_the_sweep_stays(policy_zip):
    """Where the easiest pot is a poor chance under the noise the sweep's safeties and kicks are kept: the search's
    own settings, though the policy has a pot to play."""
    from agents.prior_search import REALLOCATE_POT_CHANCE, pot_chance, prior_search_player

    prior = prior_search_player(policy_zip, "nine_ball", seed=1)
    env, _ = _noisy_table(HARD)
    state = env.unwrapped.table_state
    st = prior.search.settings
    assert pot_chance(state, st.ease_noise) < REALLOCATE_POT_CHANCE
    prior.policy.prepare(state, env.unwrapped.action_type)
    at = prior.policy.action_type
    assert at.slots(state).count > 0
    rows = prior.proposals(state, prior.policy.policy_shot(state), True)
    assert prior.settings_for(state, len(rows), noisy=True) is st
    from agents.league import load_player

    name, always = load_player(f"prior-always:{policy_zip}", 1, "nine_ball")  # the ablation: reallocate anyway
    always.policy.prepare(state, env.unwrapped.action_type)
    assert name.endswith("reallocating on every table") and always.min_pot_chance == 0.0
    assert always.settings_for(state, len(rows), noisy=True).top_k > st.top_k


def test_the_league_names_the_prior_without_reallocation_apart(policy_zip):
    from agents.league import load_player

    name, player = load_player(f"prior-plain:{policy_zip}", 0, "nine_ball")
    other, _ = load_player(f"prior:{policy_zip}", 0, "nine_ball")
    assert not player.reallocate and name != other and name.startswith(other)
