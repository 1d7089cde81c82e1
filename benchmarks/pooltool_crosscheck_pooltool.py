"""pooltool's side of the cross-check of the ``pooltool`` preset (:mod:`benchmarks.pooltool_crosscheck`). Run with
the pooltool venv's Python, as a script: it reads one JSON document from standard input and prints one.

In: ``{"length", "width", "R", "m", "e_c", "f_c", "cushion_height", "cushion", "pocket_specs" (optional: a
``PocketTableSpecs``' fields, for a table with pockets instead of the pocketless one), "scenes": [{"name", "balls": [{"id", "x",
"y"}], "cue": {"ball", "V0", "phi", "a", "b"}}]}`` in pooltool's own frame (the caller maps billiards_env's frame
onto it): balls at rest, the cue strikes ``ball``.
Out: ``{"version", "scenes": [{"name", "struck": {"vx", "vy", "wx", "wy", "wz"}, "balls": [{"id", "x", "y", "vx",
"vy", "wx", "wy", "wz", "state"}], "events": [[type, time, ids], ...], "seconds": s}]}``. With ``"warm_repeats": n``
in: ``seconds`` is the median of ``n`` more simulations of the same scene from the start (pooltool's own numba
compiled by then), ``first_seconds`` the first one's.

The physics is pooltool's default (``default_resolver()``: frictional inelastic ball-ball collisions with
Alciatore's friction, Stronge's compliant cushions, the instantaneous-point cue strike with squirt) on a pocketless
table whose cushion nose is at ``cushion_height`` (``cushion`` ``"mathavan"``: its Mathavan 2010 cushions
instead of Stronge's); the balls get ``m``, ``R``, ``e_c`` and ``f_c``, the other
ball parameters are pooltool's defaults. Never imports billiards_env.
"""
from __future__ import annotations

import json
import os
import sys
import time


def main() -> int:
    spec = json.loads(sys.stdin.read())
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != here]
    import pooltool as pt
    from pooltool.objects import BilliardTableSpecs
    from pooltool.physics.engine import PhysicsEngine
    from pooltool.physics.resolve.resolver import default_resolver

    R = spec["R"]
    if spec.get("pocket_specs"):  # a pocket table (the pocket cross-check): PocketTableSpecs' fields as given
        from pooltool.objects import PocketTableSpecs
        table = pt.Table.from_table_specs(PocketTableSpecs(**spec["pocket_specs"]))
    else:
        table = pt.Table.from_table_specs(BilliardTableSpecs(l=spec["length"], w=spec["width"],
                                                             cushion_height=spec["cushion_height"]))
    resolver = default_resolver()
    if spec.get("cushion") == "mathavan":  # the alternative cushion model, for its own cross-check
        from pooltool.physics.resolve.ball_cushion.mathavan_2010.model import (Mathavan2010Circular,
                                                                               Mathavan2010Linear)
        resolver.ball_linear_cushion = Mathavan2010Linear()
        resolver.ball_circular_cushion = Mathavan2010Circular()
    engine = PhysicsEngine(resolver=resolver)
    out = {"version": pt.__version__, "resolver": repr(resolver), "scenes": []}
    def struck_system(scene: dict) -> "pt.System":
        balls = {b["id"]: pt.Ball.create(b["id"], xy=(b["x"], b["y"]), R=R, m=spec["m"], e_c=spec["e_c"],
                                         f_c=spec["f_c"]) for b in scene["balls"]}
        cue = scene["cue"]
        system = pt.System(cue=pt.Cue(cue_ball_id=cue["ball"]), table=table, balls=balls)
        system.strike(V0=cue["V0"], phi=cue["phi"], theta=0.0, a=cue["a"], b=cue["b"])
        return system

    def timed(system: "pt.System") -> float:
        t = time.perf_counter()
        pt.simulate(system, engine=engine, inplace=True)
        return time.perf_counter() - t

    for scene in spec["scenes"]:
        system = struck_system(scene)
        cue = scene["cue"]
        # The struck ball's state just after the strike (the same resolver, on copies).
        _, struck = resolver.stick_ball.resolve(system.cue.copy(), system.balls[cue["ball"]].copy())
        (_, _, _), (svx, svy, _), (swx, swy, swz) = struck.state.rvw.tolist()
        first = timed(system)
        warm = sorted(timed(struck_system(scene)) for _ in range(int(spec.get("warm_repeats", 0))))
        seconds = warm[len(warm) // 2] if warm else first
        res = {"name": scene["name"], "seconds": seconds, "first_seconds": first, "balls": [], "events": [],
               "struck": {"vx": svx, "vy": svy, "wx": swx, "wy": swy, "wz": swz}}
        for b in scene["balls"]:
            s = system.balls[b["id"]].state
            (x, y, _), (vx, vy, _), (wx, wy, wz) = s.rvw.tolist()
            res["balls"].append({"id": b["id"], "x": x, "y": y, "vx": vx, "vy": vy, "wx": wx, "wy": wy, "wz": wz,
                                 "state": int(s.s)})
        for ev in system.events:
            res["events"].append([str(ev.event_type), float(ev.time), list(ev.ids)])
        out["scenes"].append(res)
    print(json.dumps(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
