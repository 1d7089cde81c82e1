"""``python -m billiards_env.envs``: list every env config key (name, type, default, meaning).

``--markdown`` prints the same as a Markdown table. The keys are documented in :mod:`.config`; each id's own
defaults are its scene file (``billiards_env/envs/scenes/<scene>.yaml``). ``--infos`` prints the info's keys of
every id instead (its default config), a Markdown table each: key, dtype, shape, meaning (``docs/infos.md``).
"""
from __future__ import annotations

import argparse
import os
import sys

from .config import EnvConfig, config_table_markdown, load_config
from .info import info_schema


def info_tables_markdown() -> str:
    """The info's keys of every registered id (its default config) as Markdown: a heading and a table each."""
    from . import ENV_CLASSES

    out = []
    for env_id, cls in ENV_CLASSES.items():
        schema = info_schema(load_config(cls.scene))
        out += [f"### {env_id}", "", "| key | dtype | shape | meaning |", "|---|---|---|---|"]
        for key, spec in schema.items():
            out.append(f"| `{key}` | {spec.dtype.__name__.rstrip('_')} | {spec.shape} | {spec.meaning} |")
        out.append("")
    return "\n".join(out).rstrip("\n")


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m billiards_env.envs", description=__doc__.split("\n")[0].split(": ", 1)[1])
    p.add_argument("--markdown", action="store_true", help="print a Markdown table")
    p.add_argument("--infos", action="store_true", help="print the info's keys of every id (Markdown tables)")
    args = p.parse_args(argv)
    try:
        if args.infos:
            print(info_tables_markdown(), flush=True)
        else:
            print(config_table_markdown() if args.markdown else EnvConfig.describe(), flush=True)
    except BrokenPipeError:
        # The reader stopped early (`| head`): not an error of ours. Point stdout at devnull so the interpreter's
        # final flush does not fail again (the recipe of the Python docs, "Note on SIGPIPE").
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
