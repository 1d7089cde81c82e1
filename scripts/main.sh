#!/usr/bin/env bash
# The main job: set up, train the default agent on the one-ball scene, evaluate it against the baselines and
# write the report. Extra args go to agents.main.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy
exec .venv/bin/python -m agents.main "$@"
