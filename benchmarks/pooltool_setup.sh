#!/usr/bin/env bash
# Create a separate venv with pooltool-billiards 0.6.0 for the speed comparison of the benchmarks
# (`python -m benchmarks --only pooltool`, run from the repository root). Not needed by billiards_env itself or
# its tests.
#
# A plain `pip install pooltool-billiards` resolves to the old 0.3.3: 0.6.0 pins panda3d==1.11.0.dev3702 on
# Linux, a development build that is not on PyPI. So: download the 0.6.0 wheel, read its Requires-Dist, install
# every requirement except panda3d, install panda3d==1.10.16 (the newest release; pooltool's simulation does
# not need the 1.11 dev features), then the wheel itself with --no-deps.
#
# Usage: bash benchmarks/pooltool_setup.sh [VENV_DIR]   (default: .venv-pooltool in the repo root)
# Environment: PYTHON (interpreter for the venv; default: the one .venv was made from, else python3).
# Idempotent: does nothing if the venv already imports pooltool 0.6.0.
set -euo pipefail
cd "$(dirname "$0")/.."
VENV=${1:-.venv-pooltool}
PT_VERSION=0.6.0
PANDA3D=panda3d==1.10.16

if [ -x "$VENV/bin/python" ] && "$VENV/bin/python" - <<PY 2>/dev/null
import importlib.metadata as m, sys
sys.exit(0 if m.version("pooltool-billiards") == "$PT_VERSION" else 1)
PY
then
  echo "pooltool $PT_VERSION already installed in $VENV"
  exit 0
fi

if [ -z "${PYTHON:-}" ]; then
  if [ -f .venv/pyvenv.cfg ] && home=$(sed -n 's/^home *= *//p' .venv/pyvenv.cfg) && [ -x "$home/python3" ]; then
    PYTHON="$home/python3"
  else
    PYTHON=python3
  fi
fi
"$PYTHON" -m venv "$VENV"
# Keep the venv out of git without touching the repo's .gitignore.
echo '*' > "$VENV/.gitignore"
PIP=("$VENV/bin/python" -m pip)
"${PIP[@]}" install -q --upgrade pip

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"${PIP[@]}" download -q --no-deps -d "$tmp" "pooltool-billiards==$PT_VERSION"
wheel=$(ls "$tmp"/pooltool_billiards-"$PT_VERSION"-*.whl)
# Requirements from the wheel's METADATA, evaluated for this platform, panda3d left out.
"$VENV/bin/python" - "$wheel" > "$tmp/reqs.txt" <<'PY'
import sys, zipfile
from email.parser import Parser
from pip._vendor.packaging.requirements import Requirement
z = zipfile.ZipFile(sys.argv[1])
meta = Parser().parsestr(z.read(next(n for n in z.namelist() if n.endswith(".dist-info/METADATA"))).decode())
for line in meta.get_all("Requires-Dist") or []:
    req = Requirement(line)
    if req.marker is not None and not req.marker.evaluate({"extra": ""}):
        continue
    if req.name.lower() == "panda3d":
        continue
    req.marker = None
    print(req)
PY
echo "pooltool $PT_VERSION requirements (panda3d replaced by $PANDA3D):"
sed 's/^/  /' "$tmp/reqs.txt"
"${PIP[@]}" install -q -r "$tmp/reqs.txt" "$PANDA3D"
"${PIP[@]}" install -q --no-deps "$wheel"
"$VENV/bin/python" -c "import importlib.metadata as m; print('installed pooltool-billiards', m.version('pooltool-billiards'), 'panda3d', m.version('panda3d'))"
