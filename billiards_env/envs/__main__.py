"""``python -m billiards_env.envs``: list every env config key (name, type, default, meaning).

``--markdown`` prints the same as a Markdown table. The keys are documented in :mod:`.config`; each id's own
defaults are its scene file (``billiards_env/envs/scenes/<scene>.yaml``).
"""
from __future__ import annotations

import argparse
import os
import sys

from .config import EnvConfig, config_table_markdown


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m billiards_env.envs", description=__doc__.split("\n")[0].split(": ", 1)[1])
    p.add_argument("--markdown", action="store_true", help="print a Markdown table")
    args = p.parse_args(argv)
    try:
        print(config_table_markdown() if args.markdown else EnvConfig.describe(), flush=True)
    except BrokenPipeError:
        # The reader stopped early (`| head`): not an error of ours. Point stdout at devnull so the interpreter's
        # final flush does not fail again (the recipe of the Python docs, "Note on SIGPIPE").
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
