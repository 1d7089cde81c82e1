#!/usr/bin/env bash
# Create .venv (if missing) and install billiards_env with its dependencies into it. Idempotent and quick when
# nothing changed. Torch goes first, pinned to the CPU build (a loose requirement would pull a CUDA build).
# `--rllib`: the same plus the rllib extra (Ray RLlib) in .venv-rllib. Ray pins its own Gymnasium (1.2.2 for
# ray 2.60), so it gets a venv of its own: .venv keeps the newest Gymnasium and no Ray.
# `--docs`: only the docs extra (MkDocs, Material, mkdocstrings) in .venv-docs, for `mkdocs build` (the site reads
# the package's source without importing it: no numba, no torch, no kernels to compile).
# `--clients`: the same plus the clients extra (TorchRL, Tianshou, skrl, Minari's collector, RL Zoo: the libraries
# tests/clients runs) in .venv-clients, so their pins never move .venv's.
# It says what it is doing at each step (a first set-up takes a few minutes installing; the kernels come prebuilt:
# seconds, or 3-4 minutes compiling where the prebuilt ones do not fit, see billiards_env/kernel_cache.py).
# TORCH_INDEX_URL: where torch comes from (e.g. PyTorch's CPU wheel index, see the README), if the default index
# would give a CUDA build (PyPI on Linux does).
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${PYTHON:-python3}
VENV=.venv
EXTRAS=agents,dev
case "${1:-}" in
  --rllib) VENV=.venv-rllib; EXTRAS=agents,rllib,dev ;;
  --clients) VENV=.venv-clients; EXTRAS=agents,clients,dev ;;
  --docs | "") ;;
  *) echo "setup: unknown option ${1}; use --rllib, --clients, --docs or nothing" >&2; exit 2 ;;
esac
say() { echo "setup: $*"; }
docs=0
if [ "${1:-}" = "--docs" ]; then docs=1; VENV=.venv-docs; fi
if [ ! -x "$VENV/bin/python" ]; then
  say "creating $VENV"
  "$PY" -m venv "$VENV"
fi
stamp=$VENV/.setup-stamp
want=$(cat pyproject.toml scripts/setup.sh | sha256sum | cut -c1-16)
if [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
  say "upgrading pip in $VENV"
  "$VENV/bin/python" -m pip install -q --upgrade pip
  if [ $docs -eq 1 ]; then
    say "installing the docs extra into $VENV (MkDocs, Material, mkdocstrings: ~40 s, 170 MB)"
    mapfile -t reqs < <(sed -n '/^docs = \[/,/^\]/p' pyproject.toml | grep -o '"[^"]*"' | tr -d '"')  # the docs extra
    "$VENV/bin/python" -m pip install -q "${reqs[@]}"
  else
    torch_index=()
    if [ -n "${TORCH_INDEX_URL:-}" ]; then torch_index=(--index-url "$TORCH_INDEX_URL"); fi
    say "installing torch 2.13.0, the CPU build${TORCH_INDEX_URL:+ (from $TORCH_INDEX_URL)} (~200 MB to download on a cold pip cache)"
    "$VENV/bin/python" -m pip install -q "torch==2.13.0" ${torch_index[@]+"${torch_index[@]}"}
    say "installing billiards_env and its dependencies (extras: $EXTRAS)"
    "$VENV/bin/python" -m pip install -q -e ".[$EXTRAS]"
  fi
  echo "$want" > "$stamp"
else
  say "$VENV is up to date"
fi
if [ $docs -eq 1 ]; then exit 0; fi  # the site reads the sources: no kernels to compile
# Load every physics kernel into numba's cache now (the prebuilt ones, or compiled here), so the first shot is fast.
say "$("$VENV/bin/python" -m billiards_env.prebuilt status)"
say "loading the physics kernels into numba's cache (seconds with the prebuilt kernels; 3-4 min compiling without)"
start=$SECONDS
"$VENV/bin/python" -m billiards_env.warmup
say "kernels ready in $((SECONDS - start)) s"
