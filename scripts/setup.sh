#!/usr/bin/env bash
# Create .venv (if missing) and install billiards_env with its dependencies into it. Idempotent and quick when
# nothing changed. Torch goes first, pinned to the CPU build (a loose requirement would pull a CUDA build).
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${PYTHON:-python3}
if [ ! -x .venv/bin/python ]; then
  "$PY" -m venv .venv
fi
stamp=.venv/.setup-stamp
want=$(cat pyproject.toml scripts/setup.sh | sha256sum | cut -c1-16)
if [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
  .venv/bin/python -m pip install -q --upgrade pip
  .venv/bin/python -m pip install -q "torch==2.13.0"
  .venv/bin/python -m pip install -q -e ".[agents,dev]"
  echo "$want" > "$stamp"
fi
# Compile the physics kernels into numba's cache now, so the first shot a user runs is fast.
.venv/bin/python -m billiards_env.warmup
