#!/usr/bin/env bash
# Create .venv (if missing) and install billiards_env with its dependencies into it. Idempotent and quick when
# nothing changed. Torch goes first, pinned to the CPU build (a loose requirement would pull a CUDA build).
# `--rllib`: the same plus the rllib extra (Ray RLlib) in .venv-rllib. Ray pins its own Gymnasium (1.2.2 for
# ray 2.60), so it gets a venv of its own: .venv keeps the newest Gymnasium and no Ray.
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${PYTHON:-python3}
VENV=.venv
EXTRAS=agents,dev
if [ "${1:-}" = "--rllib" ]; then
  VENV=.venv-rllib
  EXTRAS=agents,rllib,dev
fi
if [ ! -x "$VENV/bin/python" ]; then
  "$PY" -m venv "$VENV"
fi
stamp=$VENV/.setup-stamp
want=$(cat pyproject.toml scripts/setup.sh | sha256sum | cut -c1-16)
if [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
  "$VENV/bin/python" -m pip install -q --upgrade pip
  "$VENV/bin/python" -m pip install -q "torch==2.13.0"
  "$VENV/bin/python" -m pip install -q -e ".[$EXTRAS]"
  echo "$want" > "$stamp"
fi
# Compile the physics kernels into numba's cache now, so the first shot a user runs is fast.
"$VENV/bin/python" -m billiards_env.warmup
