"""``billiards-sim SCENE.json [--solver exact|step] [--dt S]``: simulate a scene file and print the result JSON."""
from __future__ import annotations

import argparse
import json
import sys

from .physics.errors import SceneError
from .physics.scene import Scene
from .physics.simulate import SOLVERS
from .physics.step import CONTACT_MODES


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="billiards-sim", description=__doc__.split(":", 1)[1].strip())
    p.add_argument("scene", help="scene file (.json, or .yaml/.yml)")
    p.add_argument("--solver", choices=SOLVERS, help="override the scene's solver")
    p.add_argument("--dt", type=float, help="time step of the step solver (s)")
    p.add_argument("--contact", choices=CONTACT_MODES, help="contact treatment of the step solver")
    p.add_argument("--events", action="store_true", help="include the event list in the output")
    p.add_argument("--indent", type=int, default=2, help="JSON indent (0 for one line)")
    return p


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        scene = Scene.load(args.scene)
        result = scene.run(solver=args.solver, dt=args.dt, contact=args.contact)
    except SceneError as exc:
        print(f"billiards-sim: error: {exc}", file=sys.stderr)
        return 2
    json.dump(result.to_dict(include_events=args.events), sys.stdout, indent=args.indent or None)
    sys.stdout.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
