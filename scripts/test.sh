#!/usr/bin/env bash
# The test command: set up (scripts/setup.sh) and run the default test set headless. Extra args go to pytest
# (e.g. `scripts/test.sh -m slow` for the long tests).
# Without args it also runs the RLlib path in .venv-rllib (`scripts/setup.sh --rllib`; Ray RLlib pins Gymnasium
# 1.2.2 while .venv has the newest): the RLlib tests, and the env tests again on Ray's Gymnasium; and it builds the
# docs site strictly (`mkdocs build --strict` in .venv-docs, `scripts/setup.sh --docs`: a broken link, a page
# missing from the nav or an API reference that does not resolve fails it) into site/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
if [ $# -eq 0 ]; then bash scripts/setup.sh --rllib; bash scripts/setup.sh --docs; fi
export SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy
status=0
if [ $# -eq 0 ]; then
  echo "test: building the docs site (mkdocs build --strict)"
  NO_MKDOCS_2_WARNING=1 .venv-docs/bin/mkdocs build --strict || status=$?  # not --quiet: it hides the warnings strict counts
fi
.venv/bin/python -m pytest -n 2 "$@" || status=$?
if [ $# -eq 0 ]; then
  .venv-rllib/bin/python -m pytest -n 2 -q tests/envs tests/multi || status=$?
  BILLIARDS_REQUIRE_RAY=1 .venv-rllib/bin/python -m pytest -q tests/agents/test_rllib.py \
    tests/agents/test_rllib_config.py || status=$?
fi
exit $status
