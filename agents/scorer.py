"""A policy that scores the shots the ``candidates_position`` observation lists, trained on a teacher's choices.

The teacher's choices in the ``candidates`` action type are discrete in effect (a pot slot, one of a few speeds, draw
/ none / follow) and depend on the position each leaves. Cloned into a Gaussian policy (SAC's actor, agents.distill)
they are averaged where the teacher picks between modes: a follow and a draw shot average to a half-follow that
leaves the cue ball where neither would, and the clones stay below the geometric player whichever teacher they copy
(agents/README.md, "Distillation"). This policy chooses instead: every (pot slot, power, top) of the observation's
grid is an *option* with its own features (the slot's 12 ``candidates`` values, the grid point's 5 position-map
values, the power and top, the game's features); a small MLP scores each option (the same weights for all: the
options are a set) and the policy plays the best (``top`` as the tip, no side). Trained by cross-entropy on the
teacher's choices mapped to the nearest option (:func:`fit`); several fits with different seeds can be summed (an
ensemble). The break is action 0 (the geometric player's full break); where the observation has no options (ball in
hand, no pot from where the cue ball lies) a fallback policy plays (the SAC clone of the same labels, which learnt
the teacher's placements), else action 0.

    python -m agents.scorer --labels runs/<distill run>/labels.npz [more.npz ...] --ensemble 3 \
        --fallback runs/<distill run>/bc_model.zip --out runs/scorer.pt --games 400

A saved scorer plays in the league as ``scorer:<path>`` (:func:`league_player`).
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any, Sequence

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


def make_net(hidden: int = 64) -> Any:
    import torch.nn as nn

    return nn.Sequential(nn.Linear(OPTION_FEATURES, hidden), nn.ReLU(), nn.Linear(hidden, hidden), nn.ReLU(),
                         nn.Linear(hidden, 1))


def fit(obs: np.ndarray, actions: np.ndarray, epochs: int = 60, hidden: int = 64, lr: float = 1e-3, seed: int = 0,
        holdout: float = 0.1) -> tuple[Any, dict[str, Any]]:
    """Train a scorer on ``(obs, actions)``: the teacher's option (:func:`option_of`) among the state's options by
    cross-entropy, Adam; states whose teacher chose the kick, or with no options or whose choice is not an option,
    are left out. Returns the net and its fit (agreement with the teacher on a held-out tenth)."""
    import torch

    torch.manual_seed(seed)
    feats, valid = options(obs)
    target = np.full(len(obs), -1, np.int64)
    for i, a in enumerate(actions):
        k, g = option_of(a)
        if k >= 0 and valid[i, k * N_GRID + g]:
            target[i] = k * N_GRID + g
    keep = np.flatnonzero(target >= 0)
    rng = np.random.default_rng(seed)
    keep = keep[rng.permutation(len(keep))]
    n_val = int(holdout * len(keep))
    val, tr = keep[:n_val], keep[n_val:]
    x = torch.as_tensor(feats)
    m = torch.as_tensor(valid)
    y = torch.as_tensor(target)
    net = make_net(hidden)
    opt = torch.optim.Adam(net.parameters(), lr=lr)

    def logits(idx: Any) -> Any:
        s = net(x[idx]).squeeze(-1)
        return s.masked_fill(~m[idx], -1e9)

    for _ in range(int(epochs)):
        perm = tr[rng.permutation(len(tr))]
        for start in range(0, len(perm), 256):
            idx = torch.as_tensor(perm[start:start + 256])
            loss = torch.nn.functional.cross_entropy(logits(idx), y[idx])
            opt.zero_grad()
            loss.backward()
            opt.step()
    with torch.no_grad():
        agree_val = float((logits(torch.as_tensor(val)).argmax(1) == y[val]).float().mean()) if n_val else float("nan")
        agree_tr = float((logits(torch.as_tensor(tr)).argmax(1) == y[tr]).float().mean())
    return net, {"labels": int(len(obs)), "used": int(len(keep)), "train_agreement": agree_tr,
                 "holdout_agreement": agree_val, "epochs": int(epochs), "hidden": int(hidden)}


class Scorer:
    """A trained scorer: ``predict(obs) -> action``, deterministic. The break: action 0 (the geometric player's full
    break). With options: the best by the scores summed over ``nets`` (an ensemble of fits; the forward passes in
    numpy: a decision is a few small matrix products, no torch call per shot). Without (ball in hand, no pot from
    where the cue ball lies): the ``fallback`` policy (an SB3 model zip in the same types, e.g. the SAC clone of the
    same teacher, which learnt the teacher's placements), else action 0."""

    def __init__(self, nets: Any, fallback: str | Path | None = None) -> None:
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

    def load_fallback(self) -> Any:
        """The fallback policy (loaded once), or None."""
        if self._fallback is None and self.fallback is not None:
            from .evaluate import model_player

            self._fallback = model_player(self.fallback)
        return self._fallback

    def save(self, path: Path) -> None:
        import torch

        torch.save({"state_dicts": [n.state_dict() for n in self.nets], "hidden": self.nets[0][0].out_features,
                    "fallback": self.fallback}, str(path))

    @classmethod
    def load(cls, path: Path) -> "Scorer":
        import torch

        d = torch.load(str(path), weights_only=True)
        nets = []
        for sd in d["state_dicts"]:
            net = make_net(int(d["hidden"]))
            net.load_state_dict(sd)
            nets.append(net)
        return cls(nets, d.get("fallback"))


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


def league_player(path: str | Path) -> Any:
    """A saved scorer as a league player (:class:`agents.games.TrainedPlayer` in the position rule's types)."""
    from .games import TrainedPlayer
    from .position_rule import RULE_KWARGS

    sc = Scorer.load(Path(path))
    sc.load_fallback()  # now, not in the first decision that needs it
    return TrainedPlayer(f"scorer({Path(path).name})", sc.predict, RULE_KWARGS)


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m agents.scorer``: train a scorer on label files (agents.distill's ``labels.npz``) and play it
    against the geometric player without noise and under olympiad noise."""
    import torch

    p = argparse.ArgumentParser(prog="python -m agents.scorer", description=main.__doc__)
    p.add_argument("--labels", type=Path, nargs="*", default=[], help="label files to fit on (cross-entropy)")
    p.add_argument("--init", type=Path, default=None, help="a saved scorer to start from instead of fitting")
    p.add_argument("--reinforce", type=int, default=0, help="games of RL fine-tuning (REINFORCE) after")
    p.add_argument("--rl-lr", type=float, default=3e-4)
    p.add_argument("--out", type=Path, required=True)
    p.add_argument("--epochs", type=int, default=60)
    p.add_argument("--hidden", type=int, default=64)
    p.add_argument("--ensemble", type=int, default=1, help="nets fitted with different seeds, their scores summed")
    p.add_argument("--fallback", type=Path, default=None, help="an SB3 model zip in the same types for the states "
                   "without options (ball in hand, no pot), e.g. agents.distill's bc_model.zip of the same labels")
    p.add_argument("--games", type=int, default=400, help="league games against the geometric player (0: none)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--league-seed", type=int, default=0, help="the league's racks: game k on seed league_seed + k")
    args = p.parse_args(argv)
    torch.set_num_threads(1)
    if args.init is not None:
        nets, info = Scorer.load(args.init).nets, {"init": str(args.init)}
    else:
        if not args.labels:
            p.error("give --labels to fit on, or --init")
        obs = np.concatenate([np.load(f)["obs"] for f in args.labels])
        act = np.concatenate([np.load(f)["actions"] for f in args.labels])
        nets, infos = [], []
        for k in range(max(args.ensemble, 1)):
            net, one = fit(obs, act, args.epochs, args.hidden, seed=args.seed + k)
            nets.append(net)
            infos.append(one)
        info = {**infos[0], "holdout_agreement": [i["holdout_agreement"] for i in infos]}
    print(f"scorer: {info}", flush=True)
    net = nets[0]
    if args.reinforce:
        from .position_rule import RULE_KWARGS

        kw = {**RULE_KWARGS, "opponent": "geometric", "first_shooter": "random"}
        rl = reinforce(net, args.reinforce, kw, lr=args.rl_lr, seed=args.seed,
                       log=lambda m: print(m, flush=True))
        print(f"reinforce: {rl}", flush=True)
    sc = Scorer(nets, args.fallback)
    sc.save(args.out)
    print(f"saved {args.out}")
    if args.games:
        from billiards_env.players import make_player

        from .evaluate import wilson_interval
        from .league import league_env_kwargs, play_pair

        me = ("scorer", league_player(args.out))
        geo = ("geometric", make_player("geometric", seed=args.seed, game="nine_ball"))
        for noise in ("0", "olympiad"):
            kw = league_env_kwargs([me, geo], True, noise if noise != "0" else 0.0)
            r = play_pair("nine_ball", me, geo, args.games, args.league_seed, kw)
            lo, hi = wilson_interval(r.wins_a, r.games)
            print(f"scorer vs geometric, noise {noise}: {r.wins_a}-{r.wins_b} = {100 * r.wins_a / r.games:.1f}% "
                  f"[{100 * lo:.0f}, {100 * hi:.0f}], break-and-runs {r.break_and_runs_by[0]} vs "
                  f"{r.break_and_runs_by[1]}, {r.ms_per_decision[0]:.2f} ms a decision")
    return 0


__all__ = ["options", "option_of", "action_of", "fit", "reinforce", "Scorer", "league_player", "main", "OPTION_FEATURES"]


if __name__ == "__main__":
    sys.exit(main())
