"""Players for the games (9-ball, 8-ball) from trained policies, and the shot-noise settings of the league.

A trained policy acts in the action type and observes in the observation type of the env it was trained on (for the
9-ball agent of ``agents.main --game nine-ball``: the ``candidates`` types with the spin model). In a league every
player meets every other on one two-player env; :class:`TrainedPlayer` lets a policy play there as it was trained:
it builds its own observation and action types (from its run's env kwargs) on the table state it plays, observes
through them, and turns its action into the shot it means, which it hands over in the action type it is given (so
the league env uses an exact action type: the absolute one, with the spin dims under the spin model). It is a
player (:class:`billiards_env.players.BasePlayer`: ``shot(state, obs, codec)``, ``act(state, obs, codec)``). The
physics must match.
"""
from __future__ import annotations

import dataclasses
import math
from typing import Any, Callable

import numpy as np

from billiards_env.envs.config import NOISE_PRESETS
from billiards_env.games import GAMES
from billiards_env.physics.balls import BALL_RADIUS
from billiards_env.players import BasePlayer

#: Single-agent env id of each game (what a trained game policy was trained on), from the game registry.
GAME_ENV_IDS = {g.name: g.env_id for g in GAMES.values()}

def noise_kwargs(noise: str | float, spin: bool, ball_radius: float = BALL_RADIUS) -> dict[str, Any]:
    """Env kwargs of a league noise setting: a named noise of the envs (``"olympiad"``: FastFiz's level-1 noise,
    ``"fastfiz"``: the older FastFiz-like setting; :data:`billiards_env.envs.config.NOISE_PRESETS`, written out
    key by key, the tip noise only under the spin model), ``0`` (none), or an angle spread in rad (the speed's,
    relative, 3x it: the league's older setting)."""
    if isinstance(noise, str) and noise.lower() in NOISE_PRESETS:
        kw = dict(NOISE_PRESETS[noise.lower()])
        tip_mm = kw.pop("tip_noise_mm")
        if spin:
            kw["tip_noise"] = tip_mm * 1e-3 / ball_radius
        if kw.get("speed_noise_mode") == "relative":
            del kw["speed_noise_mode"]  # the default
        return kw
    try:
        x = float(noise)
    except (TypeError, ValueError):
        x = math.nan
    if not math.isfinite(x) or x < 0:
        raise ValueError(f"noise: expected {' or '.join(map(repr, NOISE_PRESETS))} or an angle spread >= 0 (rad), "
                         f"got {noise!r}")
    return {"angle_noise": x, "speed_noise": 3.0 * x} if x > 0 else {}


def game_config(env_id: str, env_kwargs: dict[str, Any]) -> Any:
    """The :class:`~billiards_env.envs.config.EnvConfig` of ``gym.make(env_id, **env_kwargs)`` (without making it)."""
    from billiards_env.envs import ENV_CLASSES
    from billiards_env.envs.config import load_config

    return load_config(ENV_CLASSES[env_id].scene, None, **env_kwargs)


class TrainedPlayer(BasePlayer):
    """A trained policy ``predict(obs) -> action`` as a player of a game env (see the module docstring).

    ``env_kwargs``: the kwargs of the env the policy was trained on (``env_id``): its action type, observation type,
    candidate slots, speed range and physics. ``act(state, obs, codec)`` / ``shot(state, obs, codec)`` ignore
    ``obs`` (the env's, in the env's types) and observe the table itself in the policy's types
    (:meth:`policy_shot`); the shot is handed over in ``codec``, which must express every shot (``exact_inverse``).
    """

    #: It observes the table itself, in its own type (the env need not observe for it).
    reads_observation = False

    def __init__(self, name: str, predict: Callable[[np.ndarray], np.ndarray], env_kwargs: dict[str, Any],
                 env_id: str = "Billiards9Ball-v0") -> None:
        self.name = name
        self.predict = predict
        self.env_id = env_id
        self.env_kwargs = dict(env_kwargs)
        self.config = game_config(env_id, self.env_kwargs)
        self._on: tuple[Any, Any] | None = None  # the table state and action type its types were built for
        self._obs_type: Any = None
        self._action_type: Any = None

    @property
    def physics(self) -> Any:
        return self.config.physics

    def reset(self, seed: int | None = None) -> None:
        """Deterministic policies keep no state."""

    @property
    def action_type(self) -> Any:
        """The policy's own action type on the table it plays (built by :meth:`prepare`), else None."""
        return self._action_type

    @property
    def observation_type(self) -> Any:
        """The policy's own observation type on the table it plays (built by :meth:`prepare`), else None."""
        return self._obs_type

    def prepare(self, state: Any, codec: Any) -> None:
        """Build the policy's own observation and action types for the table state ``state`` played in the action
        type ``codec`` (its placement and declaration dims; once per state and type). A different physics, or spin
        dims the codec lacks, raise ``ValueError``."""
        if self._on is not None and self._on[0] is state and self._on[1] is codec:
            return
        from billiards_env.envs.actions import action_factory
        from billiards_env.envs.observations import OBSERVATION_TYPES

        if state.physics != self.config.physics:
            raise ValueError(f"{self.name}: trained with physics {self.config.physics}, asked to play with "
                             f"{state.physics}; give the league env the same physics (python -m agents.league "
                             "--spin, or the run's physics keys)")
        if self.config.spin_action and not codec.spin:
            raise ValueError(f"{self.name}: its actions set tip offsets; the env it plays needs spin_action=True")
        n_features = 0 if state.game is None else state.game.n_features
        self._action_type = action_factory(self.config, codec.placement, codec.declarations, codec.n_pockets)
        self._obs_type = OBSERVATION_TYPES[self.config.observation_type](self.config, state.table, state.n_balls,
                                                                         n_features)
        if self._obs_type.space.shape != self._expected_shape():
            raise ValueError(f"{self.name}: observation of shape {self._obs_type.space.shape} on this env, trained "
                             f"on {self._expected_shape()}; is it the same game?")
        self._on = (state, codec)

    def _expected_shape(self) -> tuple[int, ...]:
        if not hasattr(self, "_shape"):
            import gymnasium as gym

            import billiards_env  # noqa: F401

            env = gym.make(self.env_id, **{**self.env_kwargs, "opponent": None})
            self._shape = env.observation_space.shape
            env.close()
        return self._shape

    def choose(self, state: Any, obs: Any, codec: Any) -> np.ndarray:
        """The action of ``codec`` (an exact action type) for the shot the policy means (:meth:`policy_shot`)."""
        self.prepare(state, codec)
        if not codec.exact_inverse:
            raise ValueError(f"{self.name}: the action type ({codec.name}) cannot express every shot; play trained "
                             "policies on an env with an exact type (the league uses 'absolute')")
        shot = self.policy_shot(state)
        return codec.action(state, shot.angle, shot.speed, shot.side, shot.top, shot.place, **dict(shot.calls))

    def policy_shot(self, state: Any) -> Any:
        """The shot (:class:`~billiards_env.shot_path.CueShot`) the policy means on a table state (its types built
        by :meth:`prepare`): it observes in its own type and acts in its own."""
        return self._action_type.shot(state, self.predict(self._obs_type.observe(state)))


def trained_player(path: str, game: str = "nine_ball") -> TrainedPlayer:
    """A trained SB3 run folder / model zip, or an RLlib checkpoint / run folder (needs the ``rllib`` extra), as a
    :class:`TrainedPlayer` of ``game`` (its run's env kwargs; deterministic actions)."""
    from .evaluate import model_player

    spec = model_player(path)
    want = GAME_ENV_IDS[game]
    if spec.env_id != want:
        raise ValueError(f"{path}: trained on {spec.env_id}, not {want}; a {game} league plays {want} policies")
    return TrainedPlayer(spec.label, lambda o: spec.act(None, o), spec.env_kwargs, spec.env_id)


def physics_kwargs(config: Any) -> dict[str, Any]:
    """The env kwargs that give another env ``config``'s physics (and the spin dims under the spin model)."""
    kw: dict[str, Any] = {"physics": dataclasses.asdict(config.physics)}
    if config.physics.has_spin:
        kw["spin_action"] = True
    return kw


__all__ = ["TrainedPlayer", "trained_player", "noise_kwargs", "GAME_ENV_IDS", "game_config",
           "physics_kwargs"]
