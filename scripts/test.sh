#!/usr/bin/env bash
# The test command: set up (scripts/setup.sh) and run the default test set headless. Extra args go to pytest
# (e.g. `scripts/test.sh -m slow` for the long tests).
# Without args it also runs the RLlib path in .venv-rllib (`scripts/setup.sh --rllib`; Ray RLlib pins Gymnasium
# 1.2.2 while .venv has the newest): the RLlib tests, and the env tests again on Ray's Gymnasium. It says so first
# (Ray is 2.1 GB to install); BILLIARDS_SKIP_RLLIB=1 (or any pytest args) leaves that part out. Without args it also
# runs the client libraries in .venv-clients (`scripts/setup.sh --clients`): tests/clients, each library as its
# docs show; and it builds the docs site strictly (`mkdocs build --strict` in .venv-docs, `scripts/setup.sh --docs`:
# a broken link, a page missing from the nav or an API reference that does not resolve fails it) into site/.
# Without args it first lints: `ruff check` (the whole repository, [tool.ruff] in pyproject.toml) and `mypy` (the
# typed layers: physics, rules, games, table_state; [tool.mypy]), both from the dev extra in .venv.
set -euo pipefail
cd "$(dirname "$0")/.."
rllib=0
if [ $# -eq 0 ] && [ "${BILLIARDS_SKIP_RLLIB:-0}" != "1" ]; then rllib=1; fi
if [ $rllib -eq 1 ]; then
  if [ -x .venv-rllib/bin/python ]; then
    echo "test: the RLlib tests too, in .venv-rllib (set up already; checked)." \
         "Skip them: BILLIARDS_SKIP_RLLIB=1 bash scripts/test.sh"
  else
    echo "test: the RLlib tests too: this first sets up .venv-rllib" \
         "(Ray RLlib and the CPU torch: 2.1 GB, ~4 minutes)." \
         "Skip them: BILLIARDS_SKIP_RLLIB=1 bash scripts/test.sh (or pass pytest args, e.g. bash scripts/test.sh -q)"
  fi
else
  echo "test: the default test set in .venv (the RLlib tests and .venv-rllib left out)"
fi
if [ $# -eq 0 ] && [ ! -x .venv-clients/bin/python ]; then
  echo "test: the client libraries' tests too: this first sets up .venv-clients (TorchRL, Tianshou, skrl, Minari," \
       "RL Zoo: 2.4 GB, ~3 minutes) and .venv-docs (the docs site's tools, 170 MB)." \
       "Pass pytest args (e.g. bash scripts/test.sh -q) to run the default set alone."
fi
bash scripts/setup.sh
if [ $rllib -eq 1 ]; then bash scripts/setup.sh --rllib; fi
if [ $# -eq 0 ]; then bash scripts/setup.sh --clients; bash scripts/setup.sh --docs; fi
export SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy
status=0
if [ $# -eq 0 ]; then
  echo "test: linting (ruff check; mypy on physics, rules, games, table_state)"
  .venv/bin/python -m ruff check || status=$?
  .venv/bin/python -m mypy || status=$?
  echo "test: building the docs site (mkdocs build --strict)"
  NO_MKDOCS_2_WARNING=1 .venv-docs/bin/mkdocs build --strict || status=$?  # not --quiet: it hides the warnings strict counts
  .venv/bin/python -m pytest -n 2 --ignore=tests/clients || status=$?  # tests/clients: in .venv-clients below
  BILLIARDS_REQUIRE_CLIENTS=1 .venv-clients/bin/python -m pytest -n 2 -q tests/clients || status=$?
else
  .venv/bin/python -m pytest -n 2 "$@" || status=$?
fi
if [ $rllib -eq 1 ]; then
  .venv-rllib/bin/python -m pytest -n 2 -q tests/envs tests/multi || status=$?
  BILLIARDS_REQUIRE_RAY=1 .venv-rllib/bin/python -m pytest -q tests/agents/test_rllib.py \
    tests/agents/test_rllib_config.py || status=$?
fi
exit $status
