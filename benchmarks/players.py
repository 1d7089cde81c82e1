"""Decision time of the baseline players: the compiled geometry and search against today's Python path,
in one run.

    python -m benchmarks --only players [--quick]

The tables: every decision of seeded 9-ball and 8-ball games (``Billiards9Ball-v0``, ``Billiards8Ball-v0``, the
built-in geometric opponent; the agent plays the geometric player's shot or, one time in four, a seeded random
action), breaks and ball in hand included. On each table, interleaved:

- the geometric decision: ``geometric_decision`` on arrays (what a caller holding the table state calls), the same
  on the capture circles of a table of that size when the game's table has jaws (what the jaws cost the player),
  ``GeometricPlayer.decide`` on the env's table (with ``shot_context``), and today's Python
  (``benchmarks/reference_players.py``: ``GeometricPlayer.act`` before the games were compiled (2026-12-02) without the action); median of repeats per
  table, then the median and the worst over the tables;
- the search decision (not on breaks): ``SearchPlayer.act`` and today's ``ReferenceSearchPlayer.act`` (one run each
  per table), the search's time in the batch simulation (``run_shots``) and its own, and how many shots it simulates.

Both must choose the same (counted). Writes ``players.json`` and ``players.md`` into the output directory.
"""
from __future__ import annotations

import statistics
import time
from pathlib import Path
from typing import Any, Callable, Iterator

import numpy as np

from .common import fmt_time, load_now, log, machine_info, machine_markdown, publish, rerender, time_call

GAMES = ("Billiards9Ball-v0", "Billiards8Ball-v0")
#: The players' targets (seconds).
TARGETS = {"geometric_median": 1e-4, "geometric_worst": 2e-3, "search_median_9ball": 1e-2}


def _sizes(quick: bool) -> dict[str, int]:
    return {"games": 6, "steps": 20, "search_every": 2} if quick else {"games": 30, "steps": 30, "search_every": 1}


def game_decisions(env_id: str, games: int, steps: int, seed: int = 0) -> Iterator[tuple[Any, Any]]:
    """``(env, obs)`` at every decision of ``games`` seeded games (see the module docstring)."""
    import gymnasium as gym

    import billiards_env  # noqa: F401
    from billiards_env.players import make_player

    env = gym.make(env_id)
    env.action_space.seed(seed)
    rng = np.random.default_rng(seed)
    geo = make_player("geometric")
    try:
        for g in range(games):
            obs, _ = env.reset(seed=seed + g)
            for _ in range(steps):
                yield env, obs
                action = env.action_space.sample() if rng.random() < 0.25 else geo.act(env, obs)
                obs, _, term, trunc, _ = env.step(action)
                if term or trunc:
                    break
    finally:
        env.close()


def _stats(times: list[float]) -> dict[str, Any]:
    if not times:
        return {"n": 0, "median_s": None, "worst_s": None}
    return {"n": len(times), "median_s": statistics.median(times), "worst_s": max(times),
            "mean_s": statistics.fmean(times)}


class SimClock:
    """Wraps the search module's ``run_shots``: time spent in the batch simulation and shots simulated."""

    def __init__(self) -> None:
        from billiards_env.players import search

        self.module = search
        self.inner: Callable[..., Any] = search.run_shots
        self.seconds = 0.0
        self.shots = 0

    def __enter__(self) -> "SimClock":
        def timed(*args: Any, **kw: Any) -> Any:
            t = time.perf_counter()
            out = self.inner(*args, **kw)
            self.seconds += time.perf_counter() - t
            self.shots += len(out.time)
            return out

        self.module.run_shots = timed
        return self

    def __exit__(self, *exc: Any) -> None:
        self.module.run_shots = self.inner

    def reset(self) -> None:
        self.seconds = 0.0
        self.shots = 0


def run_game(env_id: str, sizes: dict[str, int]) -> dict[str, Any]:
    """Both players' decisions on the tables of ``env_id`` (see the module docstring)."""
    from billiards_env.players import GeometricPlayer, shot_context
    from benchmarks import reference_players as reference
    from billiards_env.players.geometry import geometric_decision, table_model
    from billiards_env.players.search import SearchPlayer

    from billiards_env.physics import Table

    geo: dict[str, list[float]] = {"arrays": [], "arrays_in_hand": [], "arrays_capture": [], "player": [],
                                   "reference": []}
    geo_same = geo_n = 0
    search: dict[str, list[float]] = {k + hand: [] for k in ("new", "cpu", "reference", "sim", "own", "shots")
                                      for hand in ("", "_in_hand")}
    search_same = search_n = 0
    player = GeometricPlayer()
    warm = search_warm = False
    k = 0
    with SimClock() as clock:
        for env, obs in game_decisions(env_id, sizes["games"], sizes["steps"]):
            ctx = shot_context(env)
            b = ctx.balls
            brk = bool(ctx.game.game_state.break_shot)
            args = (b.pos.copy(), b.on_table.copy(), b.radius.copy(), b.mass.copy(),
                    np.asarray(ctx.targets, dtype=np.int64), table_model(ctx.table, ctx.physics), ctx.speed_range,
                    ctx.place_area, brk)
            # The capture circles of a table that size (the default pockets), on a jaw table: what the jaws cost.
            cap = args[:5] + (table_model(Table(ctx.table.length, ctx.table.width, ctx.table.cushion_restitution),
                                          ctx.physics),) + args[6:] if ctx.table.has_jaws else None
            if not warm:  # load the compiled code outside the timings
                geometric_decision(*args)
                if cap is not None:
                    geometric_decision(*cap)
                player.decide(ctx)
                warm = True
            t_arr, d = time_call(lambda: geometric_decision(*args))
            if cap is not None:
                geo["arrays_capture"].append(time_call(lambda: geometric_decision(*cap))[0])
            t_player, _ = time_call(lambda: player.decide(ctx))
            t_ref, ref = time_call(lambda: reference.reference_geometric_act(env))
            geo["arrays"].append(t_arr)
            geo["player"].append(t_player)
            geo["reference"].append(t_ref)
            if ctx.place_area is not None and not brk:
                geo["arrays_in_hand"].append(t_arr)
            geo_n += 1
            geo_same += (d.place == ref[0] and d.angle == ref[1] and d.speed == ref[2]
                         and d.pocket == (ref[3].pocket if ref[3] is not None else -1))
            k += 1
            if brk or k % sizes["search_every"]:
                continue
            if not search_warm:
                SearchPlayer().act(env, obs)
                search_warm = True
            hand = "_in_hand" if ctx.place_area is not None else ""
            new, old = SearchPlayer(seed=k), reference.ReferenceSearchPlayer(seed=k)
            clock.reset()
            c0 = time.process_time()
            t0 = time.perf_counter()
            a_new = new.act(env, obs)
            t1 = time.perf_counter()
            c1 = time.process_time()
            a_ref = old.act(env, obs)
            t2 = time.perf_counter()
            search["new" + hand].append(t1 - t0)
            search["cpu" + hand].append(c1 - c0)
            search["reference" + hand].append(t2 - t1)
            search["sim" + hand].append(clock.seconds)
            search["own" + hand].append(t1 - t0 - clock.seconds)
            search["shots" + hand].append(clock.shots)
            search_n += 1
            search_same += bool(np.array_equal(a_new, a_ref))
    out: dict[str, Any] = {"geometric": {name: _stats(v) for name, v in geo.items()}, "geometric_same": geo_same,
                           "geometric_tables": geo_n, "search_same": search_same, "search_tables": search_n,
                           "search": {}}
    for name, v in search.items():
        if name.startswith("shots"):
            out["search"][name] = {"n": len(v), "median": statistics.median(v) if v else None}
        else:
            out["search"][name] = _stats(v)
    return out


def run(quick: bool = False) -> dict[str, Any]:
    sizes = _sizes(quick)
    doc: dict[str, Any] = {"machine": machine_info(), "quick": quick, "sizes": sizes, "games": {}}
    for env_id in GAMES:
        log(f"[players] {env_id}")
        doc["games"][env_id] = run_game(env_id, sizes)
    doc["end_load"] = load_now()
    return doc


def _ratio(a: float | None, b: float | None) -> str:
    return f"{b / a:.1f}x" if a and b else "-"


def targets(doc: dict[str, Any]) -> list[dict[str, Any]]:
    """The issue-21 targets with their figures."""
    rows = []
    for env_id, g in doc["games"].items():
        arr = g["geometric"]["arrays"]
        rows.append({"name": f"geometric decision, median ({env_id})", "value": fmt_time(arr["median_s"]),
                     "target": "<= 0.1 ms", "ok": arr["median_s"] is not None
                     and arr["median_s"] <= TARGETS["geometric_median"]})
        rows.append({"name": f"geometric decision, worst, ball in hand included ({env_id})",
                     "value": fmt_time(arr["worst_s"]), "target": "<= 2 ms",
                     "ok": arr["worst_s"] is not None and arr["worst_s"] <= TARGETS["geometric_worst"]})
    g9 = doc["games"].get("Billiards9Ball-v0")
    if g9:
        s = g9["search"]["new"]
        cpu = g9["search"]["cpu"]["median_s"]
        rows.append({"name": "search decision, median (9-ball, cue ball where it lies)",
                     "value": f"{fmt_time(s['median_s'])} (CPU {fmt_time(cpu)})", "target": "<= 10 ms",
                     "ok": s["median_s"] is not None and s["median_s"] <= TARGETS["search_median_9ball"]})
    return rows


def render_markdown(doc: dict[str, Any]) -> str:
    m = doc["machine"]
    lines = ["# Players' decisions: compiled geometry against today's Python", "",
             f"Measured by `python -m benchmarks --only players{' --quick' if doc['quick'] else ''}` on "
             f"{m['time']} (all figures from this one run).", "", machine_markdown(m, doc.get("end_load")), "",
             "Tables: every decision of seeded games with the built-in geometric opponent (the agent plays the "
             "geometric player's shot, or a seeded random action one time in four); breaks and ball in hand "
             "included. Today's Python: `benchmarks/reference_players.py` (the players before their geometry was "
             "compiled).", "",
             "## Targets", "", "| | measured | target | |", "|---|---|---|---|"]
    for r in targets(doc):
        lines.append(f"| {r['name']} | {r['value']} | {r['target']} | {'pass' if r['ok'] else '**miss**'} |")
    lines += ["", "## Geometric decision", "",
              "Per table the median of repeated calls; then the median and the worst over the tables.", "",
              "On capture circles: the same decisions on a table of that size with the capture pocket model "
              "(the default pockets), when the game's table has jaws: what the jaws cost the player.", "",
              "| game | tables | arrays (`geometric_decision`) median / worst | ball in hand median / worst | "
              "on capture circles median / worst | "
              "`GeometricPlayer.decide` median | today's Python median / worst | speed-up (median) | same choice |",
              "|---|---|---|---|---|---|---|---|---|"]
    for env_id, g in doc["games"].items():
        s = g["geometric"]
        cap = s.get("arrays_capture", {"median_s": None, "worst_s": None})
        lines.append(f"| {env_id} | {s['arrays']['n']} | {fmt_time(s['arrays']['median_s'])} / "
                     f"{fmt_time(s['arrays']['worst_s'])} | {fmt_time(s['arrays_in_hand']['median_s'])} / "
                     f"{fmt_time(s['arrays_in_hand']['worst_s'])} | {fmt_time(cap['median_s'])} / "
                     f"{fmt_time(cap['worst_s'])} | {fmt_time(s['player']['median_s'])} | "
                     f"{fmt_time(s['reference']['median_s'])} / {fmt_time(s['reference']['worst_s'])} | "
                     f"{_ratio(s['arrays']['median_s'], s['reference']['median_s'])} | "
                     f"{g['geometric_same']}/{g['geometric_tables']} |")
    lines += ["", "## Search decision", "",
              "One decision per table (breaks excluded): the new search (wall time, and the CPU time of the process, "
              "steadier when other work shares the cores), its time in the batch simulation (`run_shots`) and its "
              "own, the shots it simulated, and today's Python search on the same table.", "",
              "| game | cue ball | tables | new median | CPU time | simulation | own | shots simulated | "
              "today's median | speed-up | same action |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for env_id, g in doc["games"].items():
        s = g["search"]
        for hand, label in (("", "where it lies"), ("_in_hand", "in hand")):
            lines.append(f"| {env_id} | {label} | {s['new' + hand]['n']} | {fmt_time(s['new' + hand]['median_s'])} | "
                         f"{fmt_time(s['cpu' + hand]['median_s'])} | "
                         f"{fmt_time(s['sim' + hand]['median_s'])} | {fmt_time(s['own' + hand]['median_s'])} | "
                         f"{s['shots' + hand]['median'] or '-'} | {fmt_time(s['reference' + hand]['median_s'])} | "
                         f"{_ratio(s['new' + hand]['median_s'], s['reference' + hand]['median_s'])} | "
                         + (f"{g['search_same']}/{g['search_tables']} |" if not hand else "|"))
    return "\n".join(lines) + "\n"


def render(out: Path) -> None:
    """Re-write ``players.md`` from ``players.json``, without measuring."""
    rerender(out, "players", render_markdown)


def main(out: Path | None, quick: bool = False) -> dict[str, Any]:
    """Measure, print the figures, and write ``players.json`` and ``players.md`` into ``out`` if given."""
    doc = run(quick)
    publish(doc, render_markdown(doc), out, "players")
    return doc


__all__ = ["run", "targets", "render_markdown", "render", "main", "game_decisions", "TARGETS"]
