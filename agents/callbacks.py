"""Training callbacks: fixed-seed evaluation with success rates, checkpoints with the replay buffer, a time budget
(wall or CPU seconds) that schedules follow, and a clock that records steps/s and the time each evaluation figure
was reached."""
from __future__ import annotations

import json
import os
import time
from pathlib import Path
from typing import Any

import numpy as np
from stable_baselines3.common.callbacks import BaseCallback, EvalCallback


def _atomic_write_text(path: Path, text: str) -> None:
    tmp = path.with_suffix(path.suffix + ".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


class SeededEvalCallback(EvalCallback):
    """:class:`EvalCallback` that replays the same episodes at every evaluation (the eval env is re-seeded
    with ``eval_seed`` first), so successive evaluations and the kept best model are compared on equal
    terms; logs ``eval/success_rate`` and keeps a history (timesteps, wall seconds, success, reward)."""

    def __init__(self, *args: Any, eval_seed: int = 10_000, clock: "TrainingClock | None" = None,
                 stop_at_success: float = 0.0, **kwargs: Any):
        super().__init__(*args, **kwargs)
        self.eval_seed = int(eval_seed)
        self.clock = clock
        self.stop_at_success = float(stop_at_success)
        self.history: list[dict[str, float]] = []
        self.print_progress = False

    def _on_step(self) -> bool:
        if self.eval_freq > 0 and self.n_calls % self.eval_freq == 0:
            self.eval_env.seed(self.eval_seed)
            now = self.clock.now if self.clock is not None else time.perf_counter
            t0 = now()
            cont = super()._on_step()
            eval_time = now() - t0
            if self.clock is not None:
                self.clock.exclude(eval_time)
            success = float(np.mean(self._is_success_buffer)) if self._is_success_buffer else float("nan")
            entry = {
                "timesteps": int(self.num_timesteps),
                "wall_seconds": float(self.clock.elapsed() if self.clock else 0.0),
                "train_seconds": float(self.clock.train_seconds() if self.clock else 0.0),
                "success_rate": success,
                "mean_reward": float(self.last_mean_reward),
                "eval_seconds": eval_time,
            }
            self.history.append(entry)
            if self.clock is not None:
                self.clock.record_eval(entry)
            if self.print_progress:
                print(f"eval @ {entry['timesteps']} steps, {entry['wall_seconds']:.0f} s: success "
                      f"{success:.3f}, reward {entry['mean_reward']:.3f}", flush=True)
            if self.stop_at_success > 0 and success >= self.stop_at_success:
                if self.print_progress:
                    print(f"success {success:.3f} >= stop_at_success {self.stop_at_success}: stopping", flush=True)
                return False
            return cont
        return True


def _schedules(model: Any) -> list[Any]:
    """The :class:`agents.config.Schedule` objects of a model (learning rate, PPO's clip ranges)."""
    from .config import Schedule

    found = []
    for attr in ("lr_schedule", "clip_range", "clip_range_vf"):
        obj = getattr(model, attr, None)
        obj = getattr(obj, "value_schedule", obj)  # SB3 wraps schedules in FloatSchedule
        if isinstance(obj, Schedule):
            found.append(obj)
    return found


class TrainingClock(BaseCallback):
    """Measures time and steps/s (evaluation time reported apart), stops at a time budget, and writes
    ``progress.json`` in the run folder (milestones: first time each success level was reached).

    ``clock``: ``"wall"`` (elapsed seconds) or ``"cpu"`` (this process's CPU seconds, for runs compared on a
    shared machine). With a budget, the model's :class:`agents.config.Schedule` schedules (``lin_``/``cos_``
    learning rates, clip ranges) follow the clock: they reach their final value when the budget is spent."""

    MILESTONES = (0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95)

    def __init__(self, run_dir: Path, max_seconds: float = 0.0, offset_seconds: float = 0.0,
                 offset_steps: int = 0, verbose: int = 0, clock: str = "wall"):
        super().__init__(verbose)
        if clock not in ("wall", "cpu"):
            raise ValueError(f"clock: unknown {clock!r}; use 'wall' or 'cpu'")
        self.run_dir = Path(run_dir)
        self.max_seconds = float(max_seconds)
        self.clock = clock
        self.now = time.perf_counter if clock == "wall" else time.process_time
        self.offset_seconds = float(offset_seconds)  # time of earlier sessions (resume)
        self.offset_steps = int(offset_steps)
        self.t_start = self.now()
        self.excluded = 0.0
        self.evals: list[dict[str, float]] = []
        self.milestones: dict[str, dict[str, float]] = {}
        self.stopped_by_budget = False
        self._start_steps = 0
        self._schedules: list[Any] = []

    def _on_training_start(self) -> None:
        self.t_start = self.now()
        self._start_steps = int(self.model.num_timesteps)
        self._schedules = _schedules(self.model)
        self._set_schedules()

    def _set_schedules(self) -> None:
        if self.max_seconds > 0 and self._schedules:
            remaining = min(max(1.0 - self.elapsed() / self.max_seconds, 0.0), 1.0)
            for sched in self._schedules:
                sched.clock_remaining = remaining

    def elapsed(self) -> float:
        """Seconds (of the budget's clock) since the run started (all sessions)."""
        return self.offset_seconds + self.now() - self.t_start

    def session_seconds(self) -> float:
        return self.now() - self.t_start

    def train_seconds(self) -> float:
        """Wall seconds of this session minus evaluations."""
        return self.session_seconds() - self.excluded

    def exclude(self, seconds: float) -> None:
        self.excluded += seconds

    def steps_per_second(self) -> float:
        t = self.train_seconds()
        return (self.model.num_timesteps - self._start_steps) / t if t > 0 else 0.0

    def record_eval(self, entry: dict[str, float]) -> None:
        self.evals.append(entry)
        for level in self.MILESTONES:
            key = f"{level:.2f}"
            if key not in self.milestones and entry["success_rate"] >= level:
                self.milestones[key] = {"timesteps": entry["timesteps"], "wall_seconds": entry["wall_seconds"]}
        self.write()

    def summary(self) -> dict[str, Any]:
        return {
            "timesteps": int(self.model.num_timesteps) if self.model is not None else 0,
            "wall_seconds": self.elapsed(),
            "session_seconds": self.session_seconds(),
            "eval_seconds": self.excluded,
            "train_steps_per_second": self.steps_per_second() if self.model is not None else 0.0,
            "clock": self.clock,
            "stopped_by_budget": self.stopped_by_budget,
            "evaluations": self.evals,
            "milestones": self.milestones,
        }

    def write(self) -> None:
        _atomic_write_text(self.run_dir / "progress.json", json.dumps(self.summary(), indent=2))

    def _on_step(self) -> bool:
        self._set_schedules()
        if self.max_seconds > 0 and self.elapsed() >= self.max_seconds:
            self.stopped_by_budget = True
            if self.verbose:
                print(f"{self.clock} budget of {self.max_seconds:.0f} s reached at {self.num_timesteps} steps",
                      flush=True)
            return False
        return True


class RunCheckpoint(BaseCallback):
    """Every ``save_freq`` env steps (and/or ``save_seconds`` wall seconds): save the model
    (``checkpoints/model_<steps>_steps.zip``), the replay buffer (``checkpoints/replay_buffer.pkl``, latest only,
    written atomically) and VecNormalize statistics, then ``checkpoints/latest.json`` naming them. Keeps the
    ``keep`` newest model files. :meth:`save_now` is also called when training ends or is interrupted."""

    def __init__(self, run_dir: Path, save_freq: int = 0, save_seconds: float = 0.0, keep: int = 3,
                 save_replay_buffer: bool = True, clock: TrainingClock | None = None, verbose: int = 0):
        super().__init__(verbose)
        self.dir = Path(run_dir) / "checkpoints"
        self.save_freq = int(save_freq)
        self.save_seconds = float(save_seconds)
        self.keep = max(int(keep), 1)
        self.save_replay_buffer = save_replay_buffer
        self.clock = clock
        self._last_step = 0
        self._last_time = time.perf_counter()

    def _on_training_start(self) -> None:
        self.dir.mkdir(parents=True, exist_ok=True)
        self._last_step = int(self.model.num_timesteps)
        self._last_time = time.perf_counter()

    def _on_step(self) -> bool:
        due = self.save_freq > 0 and self.num_timesteps - self._last_step >= self.save_freq
        due = due or (self.save_seconds > 0 and time.perf_counter() - self._last_time >= self.save_seconds)
        if due:
            self.save_now()
        return True

    def save_now(self, tag: str | None = None) -> Path:
        now = self.clock.now if self.clock is not None else time.perf_counter
        t0 = now()
        self.dir.mkdir(parents=True, exist_ok=True)
        steps = int(self.model.num_timesteps)
        name = f"model_{steps}_steps" if tag is None else f"model_{tag}"
        model_path = self.dir / f"{name}.zip"
        tmp = self.dir / f"{name}.tmp.zip"
        self.model.save(tmp)
        os.replace(tmp, model_path)
        meta: dict[str, Any] = {"model": model_path.name, "timesteps": steps,
                                "wall_seconds": self.clock.elapsed() if self.clock else None}
        if self.save_replay_buffer and hasattr(self.model, "replay_buffer") and self.model.replay_buffer is not None:
            rb_tmp = self.dir / "replay_buffer.tmp.pkl"
            self.model.save_replay_buffer(rb_tmp)
            os.replace(rb_tmp, self.dir / "replay_buffer.pkl")
            meta["replay_buffer"] = "replay_buffer.pkl"
        vn = self.model.get_vec_normalize_env()
        if vn is not None:
            vn.save(str(self.dir / "vecnormalize.pkl"))
            meta["vecnormalize"] = "vecnormalize.pkl"
        _atomic_write_text(self.dir / "latest.json", json.dumps(meta, indent=2))
        self._prune()
        self._last_step = steps
        self._last_time = time.perf_counter()
        if self.clock is not None:
            self.clock.exclude(now() - t0)
        if self.verbose:
            print(f"checkpoint: {model_path} ({steps} steps)", flush=True)
        return model_path

    def _prune(self) -> None:
        models = sorted(self.dir.glob("model_*_steps.zip"),
                        key=lambda p: int(p.stem.split("_")[1]) if p.stem.split("_")[1].isdigit() else -1)
        for p in models[: -self.keep]:
            p.unlink(missing_ok=True)


class BudgetProgressBar(BaseCallback):
    """A progress bar whose end (and ETA) is the run's real limit: with a time budget, the budget's seconds (wall or
    CPU, :class:`TrainingClock`), with the env steps beside it; without one, the ``steps`` to do. (SB3's own bar
    counts ``n_timesteps``, which a budgeted run never reaches: a 30-minute job showed an ETA of 3.5 hours.)"""

    def __init__(self, clock: TrainingClock, steps: int, every: int = 50) -> None:
        super().__init__(0)
        self.clock = clock
        self.steps = int(steps)
        self.every = max(int(every), 1)
        self.bar: Any = None
        self._start_steps = 0

    def _on_training_start(self) -> None:
        from tqdm import tqdm

        self._start_steps = int(self.model.num_timesteps)
        c = self.clock
        if c.max_seconds > 0:
            unit = "CPU s" if c.clock == "cpu" else "s"
            self.bar = tqdm(total=round(c.max_seconds), initial=min(round(c.elapsed()), round(c.max_seconds)),
                            unit=unit, desc=f"budget ({c.clock} clock)", dynamic_ncols=True,
                            bar_format="{desc}: {percentage:3.0f}%|{bar}| {n:.0f}/{total:.0f} " + unit
                                       + " [{elapsed}<{remaining}{postfix}]")
        else:
            self.bar = tqdm(total=self.steps, unit="step", desc="steps", dynamic_ncols=True)

    def _on_step(self) -> bool:
        if self.bar is not None and self.n_calls % self.every == 0:
            self._update()
        return True

    def _update(self) -> None:
        c = self.clock
        done = int(self.model.num_timesteps) - self._start_steps
        if c.max_seconds > 0:
            self.bar.n = min(c.elapsed(), c.max_seconds)
            self.bar.set_postfix_str(f"{self.model.num_timesteps:,} steps", refresh=False)
        else:
            self.bar.n = min(done, self.steps)
        self.bar.refresh()

    def _on_training_end(self) -> None:
        if self.bar is not None:
            self._update()
            self.bar.close()
            self.bar = None


__all__ = ["SeededEvalCallback", "TrainingClock", "RunCheckpoint", "BudgetProgressBar"]
