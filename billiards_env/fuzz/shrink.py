"""Shrink a failing fuzz case to a smaller scene that still fails (``python -m billiards_env.fuzz --shrink FILE``)."""
from __future__ import annotations

import copy
from typing import Any, Callable

from ..physics.invariants import run_case


def shrink_case(scene_dict: dict[str, Any], invariant: str | None = None, max_rounds: int = 4,
                log: Callable[[str], None] | None = None) -> dict[str, Any]:
    """A smaller scene that still violates ``invariant`` (default: any invariant the given scene violates):
    balls other than the cue are removed one by one, then parameters are set to round values where the
    violation persists. Greedy (delta debugging by single removals); deterministic."""
    def violates(d: dict[str, Any]) -> bool:
        try:
            rep, _ = run_case(d)
        except Exception:  # noqa: BLE001 - e.g. a simplified scene that is no longer valid
            return False
        return invariant in rep.violations if invariant else bool(rep.violations)

    cur = copy.deepcopy(scene_dict)
    if invariant is None:
        rep, _ = run_case(cur)
        if not rep.violations:
            return cur
        invariant = sorted(rep.violations)[0]
    if not violates(cur):
        return cur
    done: set = set()
    for _ in range(max_rounds):
        changed = False
        k = len(cur["balls"]) - 1
        while k >= 1:
            trial = copy.deepcopy(cur)
            del trial["balls"][k]
            if violates(trial):
                cur = trial
                changed = True
                if log:
                    log(f"shrink: removed ball {k}, {len(cur['balls'])} left")
            k -= 1
        simplifications = [("table", "pockets", ([],)), ("table", "cushion_restitution", (1.0, 0.0, 0.85)),
                           ("physics", "min_speed", (0.0,)), ("physics", "mu_roll", (0.01,)),
                           ("physics", "drag_k", (0.0, 1.0)), ("physics", "ball_restitution", (1.0, 0.0, 0.5)),
                           ("physics", "mu_slide", (0.2,)), ("physics", "mu_spin", (0.0127,)),
                           ("physics", "ball_friction", (0.0, 0.06)), ("physics", "cushion_friction", (0.2, 0.0)),
                           ("physics", "squirt", (0.0,)), ("physics", "cushion_height", (None,)),
                           ("physics", "omega_ratio", (1.8,)), ("physics", "cushion", ("impulse", "stronge")),
                           ("physics", "ball_ball", ("frictionless",)),
                           ("max_events", None, (2000,)), ("max_time", None, (10.0,))]
        for sec, key, values in simplifications:
            if (sec, key) in done:
                continue
            for val in values:
                trial = copy.deepcopy(cur)
                holder, name = (trial, sec) if key is None else (trial[sec], key)
                if sec == "physics" and key not in holder and key != "min_speed":
                    break
                if holder.get(name) == val:
                    break
                holder[name] = val
                if violates(trial):
                    cur = trial
                    changed = True
                    done.add((sec, key))
                    if log:
                        log(f"shrink: {sec}{'.' + key if key else ''} = {val}")
                    break
        if not changed:
            break
    return cur

