#!/usr/bin/env bash
# The test command: set up (scripts/setup.sh) and run the default test set headless. Extra args go to pytest
# (e.g. `scripts/test.sh -m slow` for the long tests).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy
exec .venv/bin/python -m pytest -n 2 "$@"
