"""Policies that choose among the options of the ``candidates_position`` observation (9-ball): the hand-written
rule of ``python -m agents.position_rule`` (:func:`position_action`) and the option scorer of ``python -m
agents.scorer`` (:class:`Scorer`), with their league players (``position_rule``, ``scorer:<file>`` in
:func:`agents.league.load_player`) and the rule as a distillation teacher. An option is a (pot slot, power, top) of
the observation's grid (:mod:`billiards_env.envs.position`). The command-line modules (agents/position_rule.py,
agents/scorer.py) hold what each is for and how it was measured; this module imports neither them nor the league.
"""
from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from billiards_env.envs.candidates import SLOT_FEATURES
from billiards_env.envs.position import POINT_VALUES, POSITION_FEATURES, POWERS, TOPS

#: The types the scorer observes and acts in (the 9-ball distillation's, agents.position_rule.RULE_KWARGS).
N_SLOTS, N_BALLS, N_GAME = 4, 10, 11
N_GRID = len(POWERS) * len(TOPS)
#: Features of one option: slot values, grid-point values, power, top, game features.
OPTION_FEATURES = SLOT_FEATURES + POINT_VALUES + 2 + N_GAME
_GRID_POWER = np.repeat(np.asarray(POWERS), len(TOPS))
_GRID_TOP = np.tile(np.asarray(TOPS), len(POWERS))


def options(obs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The options of a batch of observations ``(B, d)``: features ``(B, (N_SLOTS - 1) * N_GRID, OPTION_FEATURES)``
    (option ``k * N_GRID + g``: pot slot ``k``, grid point ``g``) and which exist ``(B, ...)`` (the slot holds a pot
    from where the cue ball lies, with its map)."""
    o = np.asarray(obs, dtype=np.float32).reshape(len(obs), -1)
    base = 3 * N_BALLS
    slots = o[:, base:base + SLOT_FEATURES * N_SLOTS].reshape(-1, N_SLOTS, SLOT_FEATURES)[:, :N_SLOTS - 1]
    grid = o[:, base + SLOT_FEATURES * N_SLOTS:base + (SLOT_FEATURES + POSITION_FEATURES) * N_SLOTS].reshape(
        -1, N_SLOTS, N_GRID, POINT_VALUES)[:, :N_SLOTS - 1]
    game = o[:, -N_GAME:]
    b, k = len(o), N_SLOTS - 1
    feats = np.concatenate([np.broadcast_to(slots[:, :, None, :], (b, k, N_GRID, SLOT_FEATURES)), grid,
                            np.broadcast_to(_GRID_POWER[None, None, :, None], (b, k, N_GRID, 1)),
                            np.broadcast_to(_GRID_TOP[None, None, :, None], (b, k, N_GRID, 1)),
                            np.broadcast_to(game[:, None, None, :], (b, k, N_GRID, N_GAME))], axis=3)
    valid = (slots[:, :, 0] != 0.0) & (slots[:, :, 2] != -1.0) & grid[:, :, :, 2:4].any(axis=(2, 3))
    valid = np.broadcast_to(valid[:, :, None], (b, k, N_GRID))
    return feats.reshape(b, k * N_GRID, OPTION_FEATURES).astype(np.float32), valid.reshape(b, k * N_GRID).copy()


def option_of(action: np.ndarray) -> tuple[int, int]:
    """The option nearest a ``candidates`` action (its slot, and the grid point of the nearest power and top), and
    -1 for the slot when it is the kick."""
    k = min(int(abs(float(action[0])) * N_SLOTS), N_SLOTS - 1)
    if k == N_SLOTS - 1:
        return -1, 0
    p = int(np.argmin(np.abs(np.asarray(POWERS) - float(action[1]))))
    t = int(np.argmin(np.abs(np.asarray(TOPS) - float(action[3])))) if len(action) > 3 else 1
    return k, p * len(TOPS) + t


def action_of(option: int, n_action: int = 6) -> np.ndarray:
    """The ``candidates`` action of option ``option`` (its slot's middle, power, no side, top)."""
    a = np.zeros(n_action, np.float32)
    k, g = divmod(int(option), N_GRID)
    a[0] = (k + 0.5) / N_SLOTS
    a[1] = _GRID_POWER[g]
    a[3] = _GRID_TOP[g]
    return a


#: Ball in hand: the places weighed, the search player's own (its ``placement_candidates``, as many as it searches).
HAND_PLACES = 3
#: The game features that say the cue ball is in hand (anywhere, in the kitchen): 0 in a placed observation.
_HAND_FLAGS = (0, 1)


def hand_places(state: Any, codec: Any) -> list[tuple[float, float]]:
    """Ball in hand: the search player's places (:func:`billiards_env.players.search.placement_candidates`, best
    first, at its own spread), so the teacher's choice of place is among the scorer's options."""
    from billiards_env.players.context import shot_context
    from billiards_env.players.search import SearchSettings, placement_candidates

    ctx = shot_context(state, codec)
    sigma = max(ctx.angle_noise, SearchSettings().ease_noise)
    return placement_candidates(ctx, HAND_PLACES, sigma=sigma)


def placed_observations(state: Any, obs_type: Any, places: list[tuple[float, float]]) -> np.ndarray:
    """``(len(places), d)``: the observation with the cue ball lying at each place (``state.cue_placed``), the
    ball-in-hand flags of the game features cleared: the table as the shot from there sees it."""
    rows = []
    for place in places:
        with state.cue_placed(place):
            rows.append(np.asarray(obs_type.observe(state), dtype=np.float32))
    out = np.stack(rows) if rows else np.zeros((0, obs_type.space.shape[0]), np.float32)
    for c in _HAND_FLAGS:
        out[:, out.shape[1] - N_GAME + c] = 0.0
    return out


def hand_options(obs_places: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The options of one ball-in-hand decision: :func:`options` of each placed observation, flattened
    (option ``p * n + k``: place ``p``, option ``k`` from there)."""
    feats, valid = options(obs_places)
    return feats.reshape(-1, OPTION_FEATURES), valid.reshape(-1)


def hand_label(state: Any, obs_type: Any, codec: Any, action: np.ndarray, tol: float = 0.01
               ) -> tuple[np.ndarray, int]:
    """A ball-in-hand label: the placed observations of :func:`hand_places` (padded to :data:`HAND_PLACES` with
    zeros, which have no options) and the option of the teacher's action ``action`` (in ``codec``, a ``candidates``
    type) among :func:`hand_options`: the place within ``tol`` metres of where the action puts the cue ball, the
    pot slot there of the same ball and pocket, the grid point nearest its power and top; -1 when there is none
    (the teacher placed elsewhere, or chose a pot that is not a slot from there)."""
    places = hand_places(state, codec)
    obs_p = placed_observations(state, obs_type, places)
    pad = np.zeros((HAND_PLACES - len(obs_p), obs_p.shape[1]), np.float32)
    shot = codec.shot(state, action)
    pot = codec.chosen_pot(state, action)
    if shot.place is None or pot is None or not places:
        return np.concatenate([obs_p, pad]), -1
    d = [math.hypot(p[0] - shot.place[0], p[1] - shot.place[1]) for p in places]
    p = int(np.argmin(d))
    target = -1
    if d[p] <= tol:
        with state.cue_placed(places[p]):
            slots = codec.slots(state)
            same = [j for j in range(min(slots.count, N_SLOTS - 1))
                    if slots.at(j).target == pot.target and slots.at(j).pocket == pot.pocket]
        if same:
            _, g = option_of(np.array([0.0, action[1], 0.0, action[3] if len(action) > 3 else 0.0]))
            option = same[0] * N_GRID + g
            if options(obs_p[p:p + 1])[1][0, option]:
                target = p * (N_SLOTS - 1) * N_GRID + option
    return np.concatenate([obs_p, pad]), target


def make_net(hidden: int = 64) -> Any:
    import torch.nn as nn

    return nn.Sequential(nn.Linear(OPTION_FEATURES, hidden), nn.ReLU(), nn.Linear(hidden, hidden), nn.ReLU(),
                         nn.Linear(hidden, 1))


def _split(keep: np.ndarray, holdout: float, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """``keep`` shuffled and cut into a held-out ``holdout`` fraction and the rest."""
    keep = keep[rng.permutation(len(keep))]
    n_val = int(holdout * len(keep))
    return keep[:n_val], keep[n_val:]


def fit(obs: np.ndarray, actions: np.ndarray, epochs: int = 60, hidden: int = 64, lr: float = 1e-3, seed: int = 0,
        holdout: float = 0.1, hand_obs: np.ndarray | None = None, hand_target: np.ndarray | None = None
        ) -> tuple[Any, dict[str, Any]]:
    """Train a scorer on ``(obs, actions)``: the teacher's option (:func:`option_of`) among the state's options by
    cross-entropy, Adam; states whose teacher chose the kick, or with no options or whose choice is not an option,
    are left out. With ``hand_obs`` ``(M, HAND_PLACES, d)`` and ``hand_target`` ``(M,)`` (ball-in-hand labels,
    :func:`hand_label`; -1 left out) the same cross-entropy over each decision's :func:`hand_options`, its batches
    among the others. Returns the net and its fit (agreement with the teacher on a held-out tenth of each)."""
    import torch

    torch.manual_seed(seed)
    feats, valid = options(obs)
    target = np.full(len(obs), -1, np.int64)
    for i, a in enumerate(actions):
        k, g = option_of(a)
        if k >= 0 and valid[i, k * N_GRID + g]:
            target[i] = k * N_GRID + g
    rng = np.random.default_rng(seed)
    sets = {"": (torch.as_tensor(feats), torch.as_tensor(valid), torch.as_tensor(target),
                 *_split(np.flatnonzero(target >= 0), holdout, rng))}
    if hand_obs is not None and len(hand_obs):
        m, p, d = hand_obs.shape
        hf, hv = options(hand_obs.reshape(m * p, d))
        ht = np.asarray(hand_target, dtype=np.int64)
        sets["hand_"] = (torch.as_tensor(hf.reshape(m, -1, OPTION_FEATURES)), torch.as_tensor(hv.reshape(m, -1)),
                         torch.as_tensor(ht), *_split(np.flatnonzero(ht >= 0), holdout, rng))
    net = make_net(hidden)
    opt = torch.optim.Adam(net.parameters(), lr=lr)

    def logits(key: str, idx: Any) -> Any:
        x, msk = sets[key][0], sets[key][1]
        return net(x[idx]).squeeze(-1).masked_fill(~msk[idx], -1e9)

    for _ in range(int(epochs)):
        batches = []  # every set's training rows, shuffled, in batches of 256; the batches in a random order
        for key, (*_, tr) in sets.items():
            perm = tr[rng.permutation(len(tr))]
            batches += [(key, perm[j:j + 256]) for j in range(0, len(perm), 256)]
        for b in rng.permutation(len(batches)):
            key, idx = batches[b]
            idx = torch.as_tensor(idx)
            loss = torch.nn.functional.cross_entropy(logits(key, idx), sets[key][2][idx])
            opt.zero_grad()
            loss.backward()
            opt.step()
    info: dict[str, Any] = {"labels": int(len(obs)), "epochs": int(epochs), "hidden": int(hidden)}
    with torch.no_grad():
        for key, (_, _, y, val, tr) in sets.items():
            agree = {}
            for name, idx in (("holdout", val), ("train", tr)):
                agree[name] = float((logits(key, torch.as_tensor(idx)).argmax(1) == y[idx]).float().mean()) \
                    if len(idx) else float("nan")
            info.update({f"{key}used": int(len(val) + len(tr)), f"{key}train_agreement": agree["train"],
                         f"{key}holdout_agreement": agree["holdout"]})
    return net, info


class Scorer:
    """A trained scorer: ``predict(obs) -> action``, deterministic. The break: action 0 (the geometric player's full
    break). With options: the best by the scores summed over ``nets`` (an ensemble of fits; the forward passes in
    numpy: a decision is a few small matrix products, no torch call per shot). With the cue ball in hand and
    ``hand`` (:meth:`shot`, :meth:`act`): the best option of all :func:`hand_places`, played from its place.
    Without options (no pot from where the cue ball lies, nor from any place): the ``fallback`` policy (an SB3 model
    zip in the same types, e.g. the SAC clone of the same teacher), else action 0. :meth:`predict` sees the
    observation only: with the cue ball in hand it plays the fallback (the scorers before ``hand``)."""

    def __init__(self, nets: Any, fallback: str | Path | None = None, hand: bool = True) -> None:
        self.hand = bool(hand)
        self.nets = list(nets) if isinstance(nets, (list, tuple)) else [nets]
        for net in self.nets:
            net.eval()
        self._w = [[(m.weight.detach().numpy().T.astype(np.float32).copy(), m.bias.detach().numpy().astype(np.float32))
                    for m in net if hasattr(m, "weight")] for net in self.nets]
        self.fallback = str(fallback) if fallback else None
        self._fallback: Any = None

    @property
    def net(self) -> Any:
        return self.nets[0]

    def scores(self, feats: np.ndarray) -> np.ndarray:
        """The scores of option features ``(M, OPTION_FEATURES)`` summed over the nets (linear layers, ReLU between)."""
        total = np.zeros(len(feats), np.float32)
        for layers in self._w:
            h = feats
            for i, (w, b) in enumerate(layers):
                h = h @ w + b
                if i < len(layers) - 1:
                    np.maximum(h, 0.0, out=h)
            total += h[:, 0]
        return total

    def predict(self, obs: np.ndarray) -> np.ndarray:
        o = np.asarray(obs, dtype=np.float32).reshape(1, -1)
        if o[0, -N_GAME + 2] > 0.5:  # the break (the game's break flag)
            return np.zeros(6, np.float32)
        feats, valid = options(o)
        if not valid[0].any():
            fb = self.load_fallback()
            if fb is None:
                return np.zeros(6, np.float32)
            return np.asarray(fb.act(None, o[0]), np.float32).reshape(-1)
        s = self.scores(feats[0])
        s[~valid[0]] = -np.inf
        return action_of(int(np.argmax(s)))

    def choose_hand(self, obs_places: np.ndarray) -> tuple[int, int] | None:
        """Ball in hand: the best ``(place, option)`` of :func:`hand_options` (scored as every option), None when
        no place has one."""
        feats, valid = hand_options(obs_places)
        if not valid.any():
            return None
        s = self.scores(feats)
        s[~valid] = -np.inf
        return divmod(int(np.argmax(s)), (N_SLOTS - 1) * N_GRID)

    def shot(self, state: Any, obs_type: Any, action_type: Any) -> Any:
        """The shot (:class:`~billiards_env.envs.actions.CueShot`) this policy plays on a table state, observing in
        ``obs_type`` and acting in ``action_type`` (:data:`RULE_KWARGS`' types). With the cue ball in hand it weighs
        the options from each of :func:`hand_places` and plays the best from its place; else :meth:`predict`."""
        view = state.view
        if self.hand and view.place_area is not None and not view.break_shot:
            places = hand_places(state, action_type)
            pick = self.choose_hand(placed_observations(state, obs_type, places))
            if pick is not None:
                p, k = pick
                with state.cue_placed(places[p]):
                    shot = action_type.shot(state, action_of(k, action_type.space.shape[0]))
                return shot._replace(place=places[p])
        return action_type.shot(state, self.predict(obs_type.observe(state)))

    def act(self, source: Any, obs: np.ndarray, codec: Any = None) -> np.ndarray:
        """The action on a table state (or an env's) in the action type ``codec`` (default an env's own; both in
        :data:`RULE_KWARGS`' types, as ``obs``): :meth:`predict`, or with the cue ball in hand the :meth:`shot` from
        its place, observed in :func:`rule_observation_type`, in ``codec`` (a ``candidates`` action places the cue
        ball behind the chosen ghost ball: as near that place as it can say)."""
        from billiards_env.players.context import player_inputs

        state, codec = player_inputs(source, codec)
        view = state.view
        if self.hand and view.place_area is not None and not view.break_shot:
            s = self.shot(state, rule_observation_type(state), codec)
            return codec.action(state, s.angle, s.speed, s.side, s.top, s.place, **dict(s.calls))
        return self.predict(obs)

    def load_fallback(self) -> Any:
        """The fallback policy (loaded once), or None."""
        if self._fallback is None and self.fallback is not None:
            from .evaluate import model_player

            self._fallback = model_player(self.fallback)
        return self._fallback

    def save(self, path: Path) -> None:
        import torch

        fallback = self.fallback
        if fallback is not None:  # kept relative to the scorer's folder where it can be, so the two move together
            try:
                fallback = str(Path(fallback).resolve().relative_to(Path(path).resolve().parent))
            except ValueError:
                fallback = str(Path(fallback).resolve())
        torch.save({"state_dicts": [n.state_dict() for n in self.nets], "hidden": self.nets[0][0].out_features,
                    "fallback": fallback, "hand": self.hand}, str(path))

    @classmethod
    def load(cls, path: Path) -> "Scorer":
        import torch

        d = torch.load(str(path), weights_only=True)
        nets = []
        for sd in d["state_dicts"]:
            net = make_net(int(d["hidden"]))
            net.load_state_dict(sd)
            nets.append(net)
        fallback = d.get("fallback")
        if fallback is not None and not Path(fallback).is_absolute():
            fallback = str(Path(path).resolve().parent / fallback)
        return cls(nets, fallback, bool(d.get("hand", True)))


def reinforce(net: Any, episodes: int, env_kwargs: dict[str, Any], lr: float = 3e-4, batch: int = 32,
              seed: int = 0, log: Any = None) -> dict[str, Any]:
    """RL fine-tuning of a scorer (REINFORCE): ``episodes`` games of ``Billiards9Ball-v0`` in ``env_kwargs`` (the
    rule's types, against the geometric player), the options sampled from the softmax of the scores; every decision
    of a game is credited with its result (+1 won, -1 lost) less a running mean, Adam on ``batch`` games at a time.
    Decisions without options play action 0 and are not trained. Returns the win rate per batch."""
    import gymnasium as gym
    import torch

    import billiards_env  # noqa: F401

    torch.manual_seed(seed)
    env = gym.make("Billiards9Ball-v0", **env_kwargs)
    opt = torch.optim.Adam(net.parameters(), lr=lr)
    base = 0.0
    wins: list[float] = []
    pending: list[tuple[Any, float]] = []
    net.train()
    for ep in range(int(episodes)):
        obs, _ = env.reset(seed=seed * 1_000_003 + ep)
        logps = []
        done = False
        info: dict[str, Any] = {}
        while not done:
            feats, valid = options(np.asarray(obs, dtype=np.float32).reshape(1, -1))
            a = np.zeros(env.action_space.shape, np.float32)
            if valid[0].any():
                s = net(torch.as_tensor(feats[0])).squeeze(-1).masked_fill(~torch.as_tensor(valid[0]), -1e9)
                dist = torch.distributions.Categorical(logits=s)
                k = dist.sample()
                logps.append(dist.log_prob(k))
                a = action_of(int(k), a.shape[0])
            obs, _, term, trunc, info = env.step(a)
            done = term or trunc
        g = 1.0 if info.get("is_success", False) else -1.0
        wins.append(float(g > 0))
        if logps:
            pending.append((torch.stack(logps).sum(), g))
        if len(pending) >= batch:
            loss = -sum((g_ - base) * lp for lp, g_ in pending) / len(pending)
            opt.zero_grad()
            loss.backward()
            opt.step()
            base = 0.9 * base + 0.1 * float(np.mean([g_ for _, g_ in pending]))
            pending = []
            if log is not None:
                log(f"reinforce: {ep + 1} games, win rate of the last {batch * 10}: "
                    f"{np.mean(wins[-batch * 10:]):.3f}")
    net.eval()
    env.close()
    return {"episodes": int(episodes), "win_rate": float(np.mean(wins)) if wins else float("nan"),
            "win_rate_last_quarter": float(np.mean(wins[-max(len(wins) // 4, 1):])) if wins else float("nan")}


def scorer_player(path: str | Path, hand: bool | None = None) -> Any:
    """A saved scorer as a league player (a :class:`agents.games.TrainedPlayer` in the position rule's types that
    plays :meth:`Scorer.shot`: its own place with the cue ball in hand); ``hand`` overrides the saved choice of
    weighing the places (False: the fallback places, as scorers before it did)."""
    from .games import TrainedPlayer

    sc = Scorer.load(Path(path))
    if hand is not None:
        sc.hand = bool(hand)
    sc.load_fallback()  # now, not in the first decision that needs it

    class ScorerPlayer(TrainedPlayer):
        def policy_shot(self, state: Any) -> Any:
            return sc.shot(state, self.observation_type, self.action_type)

    name = f"scorer({Path(path).name})" if sc.hand else f"scorer({Path(path).name}, fallback in hand)"
    return ScorerPlayer(name, sc.predict, RULE_KWARGS)


#: The env kwargs the rule plays in (the 9-ball distillation's types, spin model).
RULE_KWARGS = {"action_type": "candidates", "observation_type": "candidates_position", "friction": "spin",
               "spin_action": True, "noise": "olympiad"}


def position_value(obs: np.ndarray, n_slots: int = 4, n_balls: int = 10, c: float = 0.3,
                   min_power: int = 1) -> tuple[float, tuple[int, int] | None]:
    """The rule's best option on one ``candidates_position`` observation: its value (ease now x drops x no scratch x
    (``c`` + the next ease); 0 when there is none) and its (pot slot, grid point), None when no option is worth
    anything; ``min_power``: the grid powers left out, softest first."""
    o = np.asarray(obs, dtype=np.float64).reshape(-1)
    base = 3 * n_balls
    slots = o[base:base + SLOT_FEATURES * n_slots].reshape(n_slots, SLOT_FEATURES)
    grid = o[base + SLOT_FEATURES * n_slots:base + (SLOT_FEATURES + POSITION_FEATURES) * n_slots].reshape(
        n_slots, len(POWERS) * len(TOPS), POINT_VALUES)
    best, choice = 0.0, None
    for k in range(n_slots - 1):
        if slots[k, 0] == 0.0 or slots[k, 2] == -1.0 or not grid[k, :, 2:4].any():
            continue
        v = slots[k, 7] * grid[k, :, 0] * (1.0 - grid[k, :, 1]) * (c + grid[k, :, 4])
        v[:min_power * len(TOPS)] = 0.0
        g = int(np.argmax(v))
        if v[g] > best:
            best, choice = float(v[g]), (k, g)
    return best, choice


def position_action(obs: np.ndarray, n_slots: int = 4, n_balls: int = 10, c: float = 0.3,
                    min_power: int = 1, n_action: int = 6) -> np.ndarray:
    """The rule of the module docstring on one ``candidates_position`` observation (``n_slots`` candidate slots,
    ``n_balls`` balls): :func:`position_value`'s option, or action 0 when there is none. Returns the ``candidates``
    action (``n_action`` dims: slot, power, side, top, then placement, 0)."""
    act = np.zeros(n_action, np.float32)
    _, choice = position_value(obs, n_slots, n_balls, c, min_power)
    if choice is None:
        return act
    k, g = choice
    act[0] = (k + 0.5) / n_slots
    act[1] = POWERS[g // len(TOPS)]
    act[3] = TOPS[g % len(TOPS)]
    return act


class PositionRulePlayer:
    """:func:`position_action` as a policy of the 9-ball env whose observation it is given (``act(state, obs,
    codec)``: ``obs`` a ``candidates_position`` observation and ``codec`` the ``candidates`` action type, as in
    :data:`RULE_KWARGS`; an env in those types may be given for ``state``); a distillation teacher (``python -m
    agents.distill --teacher position_rule``)."""

    name = "position_rule"

    def __init__(self, c: float = 0.3, min_power: int = 1) -> None:
        self.c = c
        self.min_power = min_power

    def reset(self, seed: int | None = None) -> None:
        """No state."""

    def act(self, source: Any, obs: Any, codec: Any = None) -> np.ndarray:
        """The rule's ``candidates`` action on ``obs`` (``codec``: the action type, default an env's own)."""
        from billiards_env.players.context import player_inputs

        state, codec = player_inputs(source, codec)
        n_slots, n_balls = int(getattr(codec, "n_slots", 0)), state.n_balls
        n_game = 0 if state.game is None else state.game.n_features
        size = 3 * n_balls + (SLOT_FEATURES + POSITION_FEATURES) * n_slots + n_game
        o = np.asarray(obs)
        if codec.name != "candidates" or o.size != size:
            raise ValueError("position_rule: plays the 'candidates' action on the 'candidates_position' observation "
                             f"({size} values), not {codec.name!r} on {o.size} values")
        return position_action(o, n_slots, n_balls, self.c, self.min_power, codec.space.shape[0])


_RULE_TYPES: dict[int, tuple[Any, Any]] = {}


def rule_observation_type(state: Any) -> Any:
    """The ``candidates_position`` observation type of :data:`RULE_KWARGS` on the table of ``state`` (a 9-ball
    table state; made once per state): what the scorer observes from its ball-in-hand places."""
    key = id(state)
    kept = _RULE_TYPES.get(key)
    if kept is not None and kept[0] is state:
        return kept[1]
    from billiards_env.envs.observations import OBSERVATION_TYPES

    from .games import game_config

    config = game_config("Billiards9Ball-v0", RULE_KWARGS)
    n_game = 0 if state.game is None else state.game.n_features
    obs_type = OBSERVATION_TYPES[config.observation_type](config, state.table, state.n_balls, n_game)
    _RULE_TYPES.clear()  # one state at a time: no growth over a long run
    _RULE_TYPES[key] = (state, obs_type)
    return obs_type


def rule_player(c: float = 0.3, min_power: int = 1) -> Any:
    """The rule as a league player (:class:`agents.games.TrainedPlayer`: it observes the table in its own types and
    plays on the league's absolute-action env)."""
    from .games import TrainedPlayer

    n_slots, n_balls = 4, 10
    return TrainedPlayer(f"position_rule(c={c}, min_power={min_power})",
                         lambda o: position_action(o, n_slots, n_balls, c, min_power), RULE_KWARGS)



__all__ = ["options", "option_of", "action_of", "fit", "hand_places", "placed_observations", "hand_options",
           "hand_label", "HAND_PLACES", "reinforce", "Scorer", "scorer_player", "OPTION_FEATURES",
           "RULE_KWARGS", "position_action", "position_value", "PositionRulePlayer", "rule_player", "make_net", "N_GRID", "N_SLOTS"]
