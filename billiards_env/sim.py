"""billiards-sim SCENE.json [--solver exact|step] [--dt S] [--preset NAME]: simulate a scene file and print the result JSON.

--preset NAME plays the scene under a physics preset (pooltool: pooltool 0.6.0's default physics) instead of the
physics section of the file. --dt and --contact set the step solver; with the exact solver (the default, unless --solver or the scene says
step) they are refused with exit status 2 rather than silently ignored. A bad scene exits 2 with one line.
Output piped into a program that stops reading early (billiards-sim ... | head) ends quietly with status 1.
"""
from __future__ import annotations

import argparse
import json
import os
import sys

from .physics.codes import CUSHION_NAMES
from .physics.errors import SceneError
from .physics.model import PRESETS
from .physics.pocket_specs import WALL_NAMES
from .physics.scene import Scene
from .physics.simulate import SOLVERS
from .physics.step import CONTACT_MODES


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="billiards-sim", description=__doc__.split("\n")[0].split(": ", 1)[1].strip(),
                                epilog=__doc__.split("\n\n", 1)[1].strip(),
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene", help="scene file (.json, or .yaml/.yml)")
    p.add_argument("--solver", choices=SOLVERS, help="override the scene's solver")
    p.add_argument("--dt", type=float, help="time step of the step solver (s); needs --solver step (or a step scene)")
    p.add_argument("--contact", choices=CONTACT_MODES,
                   help="contact treatment of the step solver; needs --solver step (or a step scene)")
    p.add_argument("--preset", choices=tuple(PRESETS),
                   help="play the scene under this physics preset instead of the file's physics section")
    p.add_argument("--events", action="store_true", help="include the event list in the output")
    p.add_argument("--indent", type=int, default=2, help="JSON indent (0 for one line)")
    return p


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        scene = Scene.load(args.scene, preset=args.preset)
        solver = args.solver or scene.solver
        step_only = [flag for flag, v in (("--dt", args.dt), ("--contact", args.contact)) if v is not None]
        if step_only and solver != "step":
            flags = " and ".join(step_only)
            whose = "" if args.solver else " (the scene's solver)"
            raise SceneError(f"{flags} {'apply' if len(step_only) > 1 else 'applies'} only to the step solver, "
                             f"and this run uses {solver!r}{whose}; add --solver step, or drop {flags}")
        # Under spin, --events reports each ball's motion state after each event: that needs the state log.
        record = args.events and scene.physics.has_spin
        result = scene.run(solver=args.solver, dt=args.dt, contact=args.contact, record=record)
    except SceneError as exc:
        print(f"billiards-sim: error: {exc}", file=sys.stderr)
        return 2
    try:
        names = WALL_NAMES if scene.table.has_jaws else CUSHION_NAMES
        json.dump(result.to_dict(include_events=args.events, cushion_names=names), sys.stdout,
                  indent=args.indent or None)
        sys.stdout.write("\n")
        sys.stdout.flush()
    except BrokenPipeError:
        # The reader stopped early (`| head`): not an error of ours. Point stdout at devnull so the interpreter's
        # final flush does not fail again (the recipe of the Python docs, "Note on SIGPIPE").
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
