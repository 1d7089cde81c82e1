"""``python -m billiards_env.fuzz``: the fuzz command (:mod:`billiards_env.fuzz.cli`)."""
import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
