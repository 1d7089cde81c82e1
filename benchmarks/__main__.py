"""``python -m benchmarks [--quick] [--only speed|env|accuracy|pooltool|latency|spin|batch|players|ladder|games|cold_start|profile] [--write | --out DIR]``,
from the repository root.

It prints what it measured and nothing else; reports are written only when asked: ``--write`` updates the
committed ones in ``docs/bench/``, ``--out DIR`` writes them elsewhere (a section run alone merges into the
report's JSON, the other sections keeping their earlier figures and time stamps).

Without ``--only`` every part runs: the accuracy suite (speed against error, ``speed_vs_error.md/.json/.png``),
then time per shot, ``env.step`` per second, pooltool and the first-call latency (``speed.md/.json``), then the
spin model's speed (against pooltool) and speed against error (``spin.md/.json``), then the batch API, the native
vector env, the search player, the single env and the first call against their targets
(``batch.md/.json``). ``--only profile`` (not part of the default run) profiles the exact solvers per event
(``benchmarks/solver_profile.py``, ``solver_profile.md/.json``).
``--only cold_start`` (not part of the default run: it compiles every kernel from an empty cache, about ten
minutes) times the set-up's compile step and the first step of an env after it and on an empty cache
(``cold_start.md/.json``).
``--quick`` runs a small configuration of everything (about a minute); the full run takes about four minutes on
two cores. The comparisons with pooltool run where pooltool is installed (``.venv-pooltool``); a missing pooltool
is installed only with ``--with-pooltool`` (about 734 MB), otherwise those comparisons are left out with a line
saying how to include them. ``--only env`` also prints a table of ``env.step`` throughput per id (``--env-seconds``,
``--env-ids``, ``--env-compare``).
"""
from __future__ import annotations

import argparse
import time
from pathlib import Path

SECTIONS = ("speed", "env", "accuracy", "pooltool", "latency", "spin", "batch", "players", "ladder", "games",
            "cold_start", "profile")
#: Sections that run only when named with ``--only``.
ON_REQUEST = ("cold_start", "profile")
#: Where ``--write`` puts the reports (the committed ones).
DEFAULT_OUT = Path("docs/bench")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(
        prog="python -m benchmarks",
        description="Benchmarks of billiards_env (run from the repository root): speed against error of the step "
                    "solver vs exact (speed_vs_error.md/.json/.png), and speed: time per shot, env.step/s, "
                    "first-call latency, pooltool (speed.md/.json).")
    ap.add_argument("--quick", action="store_true", help="small configuration (about a minute)")
    ap.add_argument("--only", choices=SECTIONS, action="append",
                    help="run only this part (repeatable); default: all")
    where = ap.add_mutually_exclusive_group()
    where.add_argument("--write", action="store_true",
                       help=f"write the reports into {DEFAULT_OUT}/ (the committed ones); default: print only")
    where.add_argument("--out", type=Path, default=None, help="write the reports into this directory")
    ap.add_argument("--pooltool-python", default=None,
                    help="python of the pooltool venv (default .venv-pooltool/bin/python in the repo, or "
                         "$BILLIARDS_BENCH_POOLTOOL_PYTHON)")
    setup = ap.add_mutually_exclusive_group()
    setup.add_argument("--with-pooltool", action="store_true",
                       help="install pooltool if its venv is missing (benchmarks/pooltool_setup.sh: about 734 MB in "
                            ".venv-pooltool, a few minutes) and include the comparison with it; without this flag a "
                            "missing pooltool is never installed: its comparison is left out, saying so")
    setup.add_argument("--no-pooltool-setup", action="store_true",
                       help="never install pooltool (the default; kept for older commands)")
    ap.add_argument("--env-seconds", type=float, default=None,
                    help="env section: timing per env id and wrapping (default 3 s, 1 s with --quick)")
    ap.add_argument("--env-ids", nargs="+", default=None, help="env section: the ids to time (default: all)")
    ap.add_argument("--env-compare", action="store_true",
                    help="env section: also time the unwrapped envs with shots through Simulator.run(validate=False) "
                         "instead of the in-place kernel call (printed only)")
    ap.add_argument("--render-only", action="store_true",
                    help="measure nothing: re-write the Markdown (and the plot) from the JSON files of --out/--write")
    args = ap.parse_args(argv)
    out: Path | None = DEFAULT_OUT if args.write else args.out
    if args.render_only and out is None:
        ap.error("--render-only re-writes reports: give --write (docs/bench) or --out DIR")
    only = tuple(args.only) if args.only else tuple(s for s in SECTIONS if s not in ON_REQUEST)
    t0 = time.perf_counter()
    # Import everything now: other people may be editing the engine while a long run goes on, and modules
    # imported later would then not match the ones already loaded.
    from . import accuracy, batch, cold_start, games, ladder, players, solver_profile, speed, spin
    from .common import log
    try:
        import billiards_env.envs  # noqa: F401
    except Exception:  # the envs are optional here: their section says why it was skipped
        pass

    if args.render_only:
        assert out is not None
        if "accuracy" in only and (out / "speed_vs_error.json").exists():
            accuracy.render(out)
        if (out / "speed.json").exists():
            speed.render(out)
        if (out / "spin.json").exists():
            spin.render(out)
        if (out / "batch.json").exists():
            batch.render(out)
        if (out / "players.json").exists():
            players.render(out)
        if (out / "ladder.json").exists():
            ladder.render(out)
        if (out / "games.json").exists():
            games.render(out)
        if (out / "cold_start.json").exists():
            cold_start.render(out)
        log(f"[bench] re-rendered the reports in {out}")
        return 0
    acc = accuracy.main(out, quick=args.quick) if "accuracy" in only else None
    rest = tuple(s for s in ("speed", "env", "pooltool", "latency") if s in only)
    if rest:
        speed.main(out, quick=args.quick, sections=rest, pooltool_python=args.pooltool_python,
                   allow_setup=args.with_pooltool, env_seconds=args.env_seconds,
                   env_ids=tuple(args.env_ids) if args.env_ids else None, env_compare=args.env_compare,
                   accuracy=acc)
    if "spin" in only:
        spin.main(out, quick=args.quick, pooltool_python=args.pooltool_python,
                  allow_setup=args.with_pooltool)
    if "batch" in only:
        batch.main(out, quick=args.quick, pooltool_python=args.pooltool_python,
                   allow_setup=args.with_pooltool)
    if "players" in only:
        players.main(out, quick=args.quick)
    if "ladder" in only:
        ladder.main(out, quick=args.quick)
    if "games" in only:
        games.main(out, quick=args.quick)
    if "cold_start" in only:
        cold_start.main(out, quick=args.quick)
    if "profile" in only:
        solver_profile.main(out, quick=args.quick)
    log(f"[bench] done in {time.perf_counter() - t0:.0f} s; "
        + (f"reports in {out}" if out is not None else "no report written (--write or --out DIR to write them)"))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
