#!/usr/bin/env bash
# The test command: set up (scripts/setup.sh) and run the default test set headless. Extra args go to pytest
# (e.g. `scripts/test.sh -m slow` for the long tests).
# Without args it also runs the RLlib path in .venv-rllib (`scripts/setup.sh --rllib`; Ray RLlib pins Gymnasium
# 1.2.2 while .venv has the newest): the RLlib tests, and the env tests again on Ray's Gymnasium; and the client
# libraries in .venv-clients (`scripts/setup.sh --clients`): tests/clients, each library as its docs show.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
if [ $# -eq 0 ]; then bash scripts/setup.sh --rllib; bash scripts/setup.sh --clients; fi
export SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy
status=0
if [ $# -eq 0 ]; then
  .venv/bin/python -m pytest -n 2 --ignore=tests/clients || status=$?  # tests/clients: in .venv-clients below
else
  .venv/bin/python -m pytest -n 2 "$@" || status=$?
fi
if [ $# -eq 0 ]; then
  BILLIARDS_REQUIRE_CLIENTS=1 .venv-clients/bin/python -m pytest -n 2 -q tests/clients || status=$?
  .venv-rllib/bin/python -m pytest -n 2 -q tests/envs tests/multi || status=$?
  BILLIARDS_REQUIRE_RAY=1 .venv-rllib/bin/python -m pytest -q tests/agents/test_rllib.py \
    tests/agents/test_rllib_config.py || status=$?
fi
exit $status
