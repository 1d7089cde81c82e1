"""pooltool's side of the spin-model cross-check (:mod:`benchmarks.spin_crosscheck`). Run with the pooltool venv's
Python, as a script: it reads one JSON document from standard input and prints one.

In: ``{"length", "width", "R", "m", "e_c", "f_c", "scenes": [{"name", "balls": [{"id", "x", "y", "vx", "vy", "wx",
"wy", "wz", "state"}]}]}`` in pooltool's own frame (the caller maps billiards_env's frame onto it).
Out: ``{"version", "scenes": [{"name", "balls": [{"id", "x", "y", "vx", "vy", "wx", "wy", "wz", "state"}],
"events": [[type, time, ids], ...], "seconds": s}]}``.

The sub-models match billiards_env's spin model: frictionless elastic ball-ball collisions, the
``impulse_frictional_inelastic`` cushion with the nose at the ball's equator (``cushion_height = R``, so the
contact normal is horizontal), a pocketless table. Never imports billiards_env.
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
    import numpy as np
    import pooltool as pt
    from pooltool.objects import BilliardTableSpecs
    from pooltool.objects.ball.datatypes import BallState
    from pooltool.physics.engine import PhysicsEngine
    from pooltool.physics.resolve.ball_ball.frictionless_elastic import FrictionlessElastic
    from pooltool.physics.resolve.ball_cushion.impulse_frictional_inelastic import (
        ImpulseFrictionalInelasticCircular, ImpulseFrictionalInelasticLinear)
    from pooltool.physics.resolve.ball_pocket import CanonicalBallPocket
    from pooltool.physics.resolve.resolver import Resolver
    from pooltool.physics.resolve.stick_ball.instantaneous_point import InstantaneousPoint
    from pooltool.physics.resolve.transition import CanonicalTransition

    R = spec["R"]
    table = pt.Table.from_table_specs(BilliardTableSpecs(l=spec["length"], w=spec["width"], cushion_height=R))
    engine = PhysicsEngine(resolver=Resolver(
        ball_ball=FrictionlessElastic(),
        ball_linear_cushion=ImpulseFrictionalInelasticLinear(),
        ball_circular_cushion=ImpulseFrictionalInelasticCircular(),
        ball_pocket=CanonicalBallPocket(),
        stick_ball=InstantaneousPoint(english_throttle=1.0, squirt_throttle=1.0),
        transition=CanonicalTransition(),
    ))
    out = {"version": pt.__version__, "scenes": []}
    for scene in spec["scenes"]:
        balls = {}
        for b in scene["balls"]:
            ball = pt.Ball.create(b["id"], xy=(b["x"], b["y"]), R=R, m=spec["m"], e_c=spec["e_c"], f_c=spec["f_c"])
            rvw = np.array([[b["x"], b["y"], R], [b["vx"], b["vy"], 0.0], [b["wx"], b["wy"], b["wz"]]])
            ball.state = BallState(rvw, b["state"])
            balls[b["id"]] = ball
        system = pt.System(cue=pt.Cue(cue_ball_id=scene["balls"][0]["id"]), table=table, balls=balls)
        t = time.perf_counter()
        pt.simulate(system, engine=engine, inplace=True)
        seconds = time.perf_counter() - t
        res = {"name": scene["name"], "seconds": seconds, "balls": [], "events": []}
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
