"""The source distribution: the package, README and the MIT LICENSE the metadata names; no tests (they need the
clone's agents/, benchmarks/, examples/ and docs, which do not ship: MANIFEST.in says why). The wheel: the package
with its scenes and the prebuilt kernels."""
from __future__ import annotations

import shutil
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _tracked() -> list[str]:
    out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True).stdout
    return [f for f in out.splitlines() if (ROOT / f).is_file()]


def _build(tmp_path: Path, kind: str) -> Path:
    """Build a ``kind`` ("sdist" or "wheel") from a copy of the tracked files; returns its path."""
    src = tmp_path / "src"
    for f in _tracked():  # a copy: building writes billiards_env.egg-info into the source tree
        (src / f).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(ROOT / f, src / f)
    for extra in ("LICENSE", "MANIFEST.in"):  # as committed (also when this runs before they are)
        shutil.copy2(ROOT / extra, src / extra)
    dist = tmp_path / "dist"
    code = f"from setuptools import build_meta; print(build_meta.build_{kind}({str(dist)!r}))"
    name = subprocess.run([sys.executable, "-c", code], cwd=src, capture_output=True, text=True, check=True,
                          timeout=300).stdout.strip().splitlines()[-1]
    return dist / name


def test_the_wheel_ships_the_prebuilt_kernels(tmp_path):
    with zipfile.ZipFile(_build(tmp_path, "wheel")) as whl:
        names = set(whl.namelist())
    shipped = {f"billiards_env/prebuilt_kernels/{p.name}" for p in (ROOT / "billiards_env/prebuilt_kernels").iterdir()}
    assert shipped and shipped <= names and any(n.endswith(".tar.xz") for n in shipped)
    assert "billiards_env/envs/scenes/nine_ball.yaml" in names and not [n for n in names if n.startswith("tests/")]


def test_the_sdist_has_the_license_and_no_tests(tmp_path):
    sdist = _build(tmp_path, "sdist")
    with tarfile.open(sdist) as tar:
        names = [n.split("/", 1)[1] for n in tar.getnames() if "/" in n]
        pkg_info = tar.extractfile(next(m for m in tar.getmembers() if m.name.endswith("/PKG-INFO"))).read().decode()
    assert "LICENSE" in names and "README.md" in names and "billiards_env/envs/scenes/nine_ball.yaml" in names
    assert not [n for n in names if n.startswith("tests/")]
    assert "License-Expression: MIT" in pkg_info and "License-File: LICENSE" in pkg_info
    assert "Copyright (c) 2026 the billiards_env authors" in (ROOT / "LICENSE").read_text()
