#!/usr/bin/env bash
# The test command: set up (scripts/setup.sh) and run the default test set headless. Extra args go to pytest
# (e.g. `scripts/test.sh -m slow` for the long tests).
# Without args it also runs the RLlib path in .venv-rllib (`scripts/setup.sh --rllib`; Ray RLlib pins Gymnasium
# 1.2.2 while .venv has the newest): the RLlib tests, and the env tests again on Ray's Gymnasium.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
if [ $# -eq 0 ]; then bash scripts/setup.sh --rllib; fi
export SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy
status=0
.venv/bin/python -m pytest -n 2 "$@" || status=$?
if [ $# -eq 0 ]; then
  .venv-rllib/bin/python -m pytest -n 2 -q tests/envs tests/multi || status=$?
  BILLIARDS_REQUIRE_RAY=1 .venv-rllib/bin/python -m pytest -q tests/agents/test_rllib.py \
    tests/agents/test_rllib_config.py || status=$?
fi
exit $status
