"""The prebuilt kernels' command line: ``python -m billiards_env.prebuilt {status,build}``.

``status``: whether this interpreter uses the kernels shipped with the package (:mod:`billiards_env.kernel_cache`),
and if not, why not. ``build``: rebuild this platform's archive after a kernel source changed (3-4 minutes on 2
cores: every kernel compiled for the generic CPU into an empty cache, then packed).
"""
from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence

from . import kernel_cache


def main(argv: Sequence[str] | None = None) -> int:
    """Parse ``argv`` and run the command; returns the exit code."""
    ap = argparse.ArgumentParser(prog="python -m billiards_env.prebuilt",
                                 description="The prebuilt kernels shipped with billiards_env: whether they are used "
                                             "here (status), or rebuild this platform's archive (build).")
    ap.add_argument("command", choices=("status", "build"))
    ap.add_argument("--workers", type=int, default=None,
                    help="build: worker processes of the warm-up that compiles (default: one per core)")
    args = ap.parse_args(argv)
    if args.workers is not None and args.workers < 1:
        ap.error(f"--workers: must be >= 1, got {args.workers}")
    if args.command == "build":
        m = json.loads(kernel_cache.build(workers=args.workers).read_text())
        print(f"built {m['archive']}: {m['files']} files, {m['bytes'] / 1e6:.1f} MB in numba's cache, "
              f"{m['archive_bytes'] / 1e6:.1f} MB packed, in {m['build_s']:.0f} s")
        return 0
    print(f"platform {kernel_cache.platform_tag()}; prebuilt kernels: {kernel_cache.status()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
