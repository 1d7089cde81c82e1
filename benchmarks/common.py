"""Shared pieces of the benchmark suite: the seeded shot sets, the physics settings, timing and the machine."""
from __future__ import annotations

import json
import math
import statistics
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import numpy as np

from billiards_env.machine import engine_version, load_now, machine_info, machine_markdown  # noqa: F401 (shared)
from billiards_env.physics import BALL_RADIUS, Balls, Physics, Table
from billiards_env.physics.layout import rack_balls

#: The lecture's per-frame friction factor and its frame, from which the drag law's rate is derived.
DRAG_FACTOR = 0.999
DRAG_FRAME_DT = 1.0 / 60.0
DRAG_MIN_SPEED = 0.005  #: m/s
ROLLING_MU = 0.01


def physics_laws() -> dict[str, Physics]:
    """The two friction laws every accuracy cell is run under."""
    return {
        "rolling": Physics("rolling", mu_roll=ROLLING_MU),
        "drag": Physics("drag", drag_k=Physics.drag_k_from_factor(DRAG_FACTOR, DRAG_FRAME_DT),
                        min_speed=DRAG_MIN_SPEED),
    }


def physics_description() -> dict[str, str]:
    k = Physics.drag_k_from_factor(DRAG_FACTOR, DRAG_FRAME_DT)
    return {
        "rolling": f"rolling, mu_roll = {ROLLING_MU} (deceleration {ROLLING_MU * 9.81:.4f} m/s^2), min_speed 0",
        "drag": f"drag, k = -ln({DRAG_FACTOR}) / (1/{1 / DRAG_FRAME_DT:.0f} s) = {k:.5f} 1/s, "
                f"min_speed {DRAG_MIN_SPEED} m/s",
    }


@dataclass(frozen=True)
class Shot:
    """One benchmark shot: balls at rest, then ball ``ball`` struck at ``angle`` (rad) with ``speed`` (m/s)."""

    category: str
    index: int
    balls: Balls
    ball: int
    angle: float
    speed: float

    def struck(self, nudge: float = 0.0) -> Balls:
        """The balls just after the strike, the aim turned by ``nudge`` rad."""
        return self.balls.strike(self.ball, self.angle + nudge, self.speed)

    def spec(self) -> dict[str, Any]:
        """JSON form (for the pooltool subprocess)."""
        return {"ids": list(self.balls.ids), "pos": self.balls.pos.tolist(), "ball": self.ball,
                "angle": self.angle, "speed": self.speed}


def _place(rng: np.random.Generator, table: Table, n: int, r: float = BALL_RADIUS) -> np.ndarray:
    """``n`` centres uniform on the table, clear of each other (1 mm), the cushions and the pockets' mouths."""
    margin = r + 0.002
    while True:
        pos = np.column_stack([rng.uniform(margin, table.length - margin, n),
                               rng.uniform(margin, table.width - margin, n)])
        d_pocket = np.linalg.norm(pos[:, None, :] - table.pocket_xy[None, :, :], axis=-1)
        if np.any(d_pocket < table.pocket_radius[None, :] + 2 * r):
            continue
        d = np.linalg.norm(pos[:, None, :] - pos[None, :, :], axis=-1) + np.eye(n) * 1e9
        if np.all(d > 2 * r + 0.001):
            return pos


def _aim_with_cut(rng: np.random.Generator, pos: np.ndarray, target: int, r: float = BALL_RADIUS) -> float:
    """An angle from ball 0 towards ball ``target``, turned by a random cut of up to 1.2x the widest angle
    that still hits it (so most shots hit, some miss)."""
    dx, dy = pos[target] - pos[0]
    d = math.hypot(dx, dy)
    widest = math.asin(min(1.0, 2 * r / d))
    return math.atan2(dy, dx) + rng.uniform(-1.2, 1.2) * widest


def _random_shots(kind: str, n: int, seed: int, table: Table | None, n_balls: int, v_max: float) -> list[Shot]:
    """``n_balls`` balls at random places; the cue aimed at ball 1 with a random cut; speed uniform in
    [0.5, ``v_max``] m/s."""
    table = table or Table()
    rng = np.random.default_rng(seed)
    shots = []
    for k in range(n):
        pos = _place(rng, table, n_balls)
        angle = _aim_with_cut(rng, pos, 1)
        speed = float(rng.uniform(0.5, v_max))
        shots.append(Shot(kind, k, Balls.from_positions(pos), 0, angle, speed))
    return shots


def one_ball_shots(n: int, seed: int = 1, table: Table | None = None) -> list[Shot]:
    """Cue ball and one object ball at random places; the cue aimed at the object ball with a random cut;
    speed uniform in [0.5, 3] m/s."""
    return _random_shots("one_ball", n, seed, table, 2, 3.0)


def three_ball_shots(n: int, seed: int = 2, table: Table | None = None) -> list[Shot]:
    """Cue ball and two object balls at random places; the cue aimed at the first with a random cut; speed
    uniform in [0.5, 4] m/s."""
    return _random_shots("three_ball", n, seed, table, 3, 4.0)


def break_shots(n: int, table: Table | None = None, speed: float = 8.0) -> list[Shot]:
    """15-ball breaks: touching triangle at the foot spot, the cue ball on the head string at ``n`` places
    spread over the middle 60 % of the width (the centre one first), aimed at the apex ball's centre."""
    table = table or Table()
    if n == 1:
        offsets = [0.0]
    else:
        offsets = sorted(np.linspace(-0.3, 0.3, n).tolist(), key=lambda o: (abs(o), o))
    shots = []
    for k, off in enumerate(offsets):
        cue = (0.25 * table.length, (0.5 + off) * table.width)
        balls = rack_balls(table, cue_xy=cue)
        dx, dy = balls.pos[1] - balls.pos[0]
        shots.append(Shot("break", k, balls, 0, math.atan2(dy, dx), speed))
    return shots


def straight_shot(table: Table | None = None, speed: float = 2.0) -> Shot:
    """The fixed single-ball shot: cue ball at the head spot, object ball at the table's centre, struck
    straight at it along the length."""
    table = table or Table()
    pos = [(0.25 * table.length, 0.5 * table.width), (0.5 * table.length, 0.5 * table.width)]
    return Shot("straight", 0, Balls.from_positions(pos), 0, 0.0, speed)


def time_call(fn: Callable[[], Any], min_total: float = 0.002, max_reps: int = 20, min_reps: int = 3,
              once_above: float = 0.05) -> tuple[float, Any]:
    """Median wall time of ``fn()`` (seconds) and its last result. A call slower than ``once_above`` s is timed
    once; faster ones at least ``min_reps`` times and until the calls total ``min_total`` s (at most
    ``max_reps``), so that a fast call is not judged on one sample that a hiccup of the machine may spoil."""
    times = []
    total = 0.0
    out = None
    while True:
        t = time.perf_counter()
        out = fn()
        el = time.perf_counter() - t
        times.append(el)
        total += el
        if len(times) >= max_reps or (len(times) == 1 and el >= once_above):
            break
        if total >= min_total and len(times) >= min_reps:
            break
    return statistics.median(times), out


def repeat_median(fn: Callable[[], Any], repeats: int, warmup: int = 1) -> float:
    """Median of ``repeats`` timed calls after ``warmup`` untimed ones (seconds)."""
    for _ in range(warmup):
        fn()
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def fmt_time(s: float | None) -> str:
    """Seconds as a short human string (us / ms / s)."""
    if s is None or (isinstance(s, float) and math.isnan(s)):
        return "-"
    if s < 1e-3:
        return f"{s * 1e6:.1f} us"
    if s < 1.0:
        return f"{s * 1e3:.2f} ms"
    return f"{s:.2f} s"


def fmt_num(x: float | None, digits: int = 3) -> str:
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    if x == 0:
        return "0"
    if abs(x) >= 1e4 or abs(x) < 1e-3:
        return f"{x:.{digits - 1}e}"
    return f"{x:.{digits}g}"


def fmt_rate(x: float | None) -> str:
    """A count per second: thousands separators from 100 up, 3 significant digits below."""
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    return f"{x:,.0f}" if x >= 100 else f"{x:.3g}"


def write_json(path: Path, data: Any) -> None:
    """Strict JSON (NaN and infinities become null)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(_finite(data), indent=1, default=_json_default, allow_nan=False) + "\n")


def rerender(out: Path, name: str, render_markdown: Callable[[dict[str, Any]], str]) -> None:
    """Re-write a section's ``name.md`` from its ``name.json`` in ``out``, without measuring."""
    (out / f"{name}.md").write_text(render_markdown(json.loads((out / f"{name}.json").read_text())))


def publish(doc: dict[str, Any], md: str, out: Path | None, name: str) -> None:
    """Print a section's report ``md``; with ``out``, also write ``name.json`` (``doc``) and ``name.md`` there."""
    print(md)
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
        write_json(out / f"{name}.json", doc)
        (out / f"{name}.md").write_text(md)
        log(f"[{name}] wrote {out / (name + '.md')}")


def _finite(o: Any) -> Any:
    if isinstance(o, dict):
        return {k: _finite(v) for k, v in o.items()}
    if isinstance(o, (list, tuple)):
        return [_finite(v) for v in o]
    if isinstance(o, (float, np.floating)):
        return float(o) if math.isfinite(o) else None
    return o


def _json_default(o: Any) -> Any:
    if isinstance(o, np.integer):
        return int(o)
    if isinstance(o, np.floating):
        return float(o)
    if isinstance(o, np.ndarray):
        return o.tolist()
    raise TypeError(f"not JSON serialisable: {type(o)}")


def log(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)
