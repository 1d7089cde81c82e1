"""The prebuilt kernels (:mod:`billiards_env.kernel_cache`): built from these very sources, unpacked into an empty
numba cache at import, a first 9-ball step that then compiles nothing, stale or mismatched ones never used, and
``BILLIARDS_PREBUILT=0`` leaving numba alone."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import tarfile
from pathlib import Path

import pytest

from billiards_env import kernel_cache, prebuilt

REPO = Path(__file__).resolve().parents[1]
MANIFESTS = sorted(kernel_cache.PREBUILT_DIR.glob("*.json"))
HERE = kernel_cache.manifest_path()
for_this_platform = pytest.mark.skipif(not HERE.exists(), reason=f"no prebuilt kernels ship for {HERE.stem}")

#: A fresh process: counts the package's kernels numba compiles (a cache load fires no compile event) while it
#: imports the package and makes, resets and steps the env ``argv[1]``.
_FIRST_STEP = """
import json, os, sys
from numba.core import event

compiled = []


class Count(event.Listener):
    def on_start(self, ev):
        f = getattr(ev.data.get("dispatcher"), "py_func", None)
        if f is not None and str(f.__module__).startswith("billiards_env"):
            compiled.append(f.__qualname__)

    def on_end(self, ev):
        pass


event.register("numba:compile", Count())
import gymnasium as gym
import billiards_env
from billiards_env import kernel_cache

if sys.argv[1] != "-":
    env = gym.make(sys.argv[1])
    env.reset(seed=0)
    env.step(env.action_space.sample())
print(json.dumps({"status": kernel_cache.status(), "compiled": compiled, "cpu": os.environ.get("NUMBA_CPU_NAME")}))
"""


def _fresh(cache: Path, env_id: str = "-", **env: str) -> dict:
    base = {k: v for k, v in os.environ.items() if not k.startswith(("NUMBA_", "BILLIARDS_"))}
    out = subprocess.run([sys.executable, "-c", _FIRST_STEP, env_id], cwd=REPO, capture_output=True, text=True,
                         timeout=600, env={**base, "NUMBA_CACHE_DIR": str(cache), "SDL_VIDEODRIVER": "dummy", **env})
    assert out.returncode == 0, out.stderr[-3000:]
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_every_shipped_archive_was_built_from_these_sources():
    assert MANIFESTS, f"no prebuilt kernels in {kernel_cache.PREBUILT_DIR}"
    digest = kernel_cache.kernels_digest()
    for path in MANIFESTS:
        m = json.loads(path.read_text())
        assert m["kernels_digest"] == digest, (
            f"{path.name}: the kernel sources changed since these prebuilt kernels were built; rebuild them with "
            "`python -m billiards_env.prebuilt build` (3-4 min) and commit the archive")
        archive = kernel_cache.PREBUILT_DIR / m["archive"]
        with tarfile.open(archive, "r:xz") as tar:
            names = tar.getnames()
        assert len(names) == m["files"] and any(n.startswith("physics/exact.") for n in names)
        assert sorted({n.rpartition("/")[0] for n in names}) == m["dirs"]
        assert set(m["dirs"]) <= set(kernel_cache.source_dirs())


@for_this_platform
def test_an_empty_cache_gets_them_and_a_first_9ball_step_compiles_nothing(tmp_path):
    first = _fresh(tmp_path, "Billiards9Ball-v0")
    assert first["status"].startswith("used: unpacked into"), first["status"]
    assert first["compiled"] == [] and first["cpu"] == kernel_cache.CPU
    again = _fresh(tmp_path, "BilliardsOneBall-v0")
    assert again["status"] == "used: unpacked before" and again["compiled"] == []


@for_this_platform
def test_opting_out_unpacks_nothing_and_leaves_numbas_cpu_alone(tmp_path):
    got = _fresh(tmp_path, BILLIARDS_PREBUILT="0")
    assert got["status"].startswith("off") and got["cpu"] is None
    assert not any(tmp_path.rglob("*.nb[ic]"))


@for_this_platform
def test_another_target_cpu_does_not_use_them(tmp_path):
    got = _fresh(tmp_path, NUMBA_CPU_NAME="x86-64-v2")
    assert "NUMBA_CPU_NAME is 'x86-64-v2'" in got["status"] and not any(tmp_path.rglob("*.nb[ic]"))


@for_this_platform
def test_changed_sources_are_never_served_and_a_lost_directory_is_refilled(tmp_path, monkeypatch):
    from numba.core import config

    monkeypatch.setattr(config, "CACHE_DIR", str(tmp_path))
    real = kernel_cache.kernels_digest()
    monkeypatch.setattr(kernel_cache, "kernels_digest", lambda: "0" * 64)
    assert "kernel sources changed" in kernel_cache.install_prebuilt()
    assert not any(tmp_path.rglob("*.nb[ic]")) and "kernel sources changed" in kernel_cache.status()
    monkeypatch.setattr(kernel_cache, "kernels_digest", lambda: real)
    n_dirs = len(json.loads(HERE.read_text())["dirs"])
    assert kernel_cache.install_prebuilt() == f"used: unpacked into {n_dirs} cache directories"
    files = sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*.nb[ic]"))
    assert len(files) == json.loads(HERE.read_text())["files"]
    assert kernel_cache.install_prebuilt() == "used: unpacked before"
    physics = kernel_cache.cache_dir(kernel_cache.PACKAGE / "physics" / "exact.py")
    assert physics is not None and physics.parent == tmp_path
    for f in physics.iterdir():
        f.unlink()
    assert kernel_cache.install_prebuilt() == "used: unpacked into 1 cache directory"
    assert sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*.nb[ic]")) == files


def test_the_command_line_says_what_it_does_and_refuses_bad_input(capsys):
    assert prebuilt.main(["status"]) == 0
    out = capsys.readouterr().out
    assert kernel_cache.platform_tag() in out and kernel_cache.status() in out
    for argv in (["rebuild"], ["build", "--workers", "0"]):
        with pytest.raises(SystemExit) as exc:
            prebuilt.main(argv)
        assert exc.value.code == 2


@pytest.mark.slow
@for_this_platform
def test_a_rebuild_packs_the_same_kernels(tmp_path):
    """Every kernel compiled again for the generic CPU (3-4 min): the same files as the shipped archive's."""
    built = json.loads(kernel_cache.build(out_dir=tmp_path).read_text())
    shipped = json.loads(HERE.read_text())
    assert built["kernels_digest"] == shipped["kernels_digest"] == kernel_cache.kernels_digest()
    with tarfile.open(tmp_path / built["archive"], "r:xz") as a, \
            tarfile.open(kernel_cache.PREBUILT_DIR / shipped["archive"], "r:xz") as b:
        assert a.getnames() == b.getnames()


@for_this_platform
def test_a_damaged_archive_or_manifest_is_reported_not_raised(tmp_path, monkeypatch):
    from numba.core import config

    monkeypatch.setattr(config, "CACHE_DIR", str(tmp_path / "cache"))
    shipped = tmp_path / "prebuilt"
    shipped.mkdir()
    manifest = json.loads(HERE.read_text())
    (shipped / HERE.name).write_text(json.dumps(manifest))
    data = (kernel_cache.PREBUILT_DIR / manifest["archive"]).read_bytes()
    (shipped / manifest["archive"]).write_bytes(data[: len(data) // 2])  # cut short
    monkeypatch.setattr(kernel_cache, "PREBUILT_DIR", shipped)
    got = kernel_cache.install_prebuilt()
    assert got.startswith(f"not used: could not unpack {manifest['archive']}"), got
    assert not any((tmp_path / "cache").rglob(kernel_cache.MARKER))  # tried again next time
    (shipped / HERE.name).write_text("{not json")
    assert kernel_cache.install_prebuilt().startswith(f"not used: unreadable manifest {HERE.name}")
