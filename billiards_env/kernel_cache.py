"""numba's cache of the package's kernels: the prebuilt kernels shipped with the package, and stale-cache clearing.

numba compiles a kernel at its first call and caches the machine code (in ``__pycache__`` beside the source, or
under ``NUMBA_CACHE_DIR``), keyed on the source file's content, the Python and numba versions and the CPU the code is
built for. Compiling every kernel takes about 3 minutes on 2 cores, a first env 30-60 s. So the package ships that
cache, built for a generic CPU of its architecture, in ``prebuilt_kernels/`` (an archive and its manifest per
Python, platform and numba version). At import (:func:`install_prebuilt`, called by ``billiards_env/__init__``),
when the interpreter, the platform, numba and the package's kernel sources are the ones an archive was built from,
the archive is unpacked into the directories numba reads, once per directory, and numba is told to build for the
generic CPU (``NUMBA_CPU_NAME=generic``, unless the user set it), which is what the cached code is keyed on.

Generic code runs the same IEEE arithmetic as code built for this CPU (numba contracts no multiply-adds without
``fastmath``): results are bit-identical (``python -m benchmarks.corpus_digest`` gives the same digest either way).

- ``BILLIARDS_PREBUILT=0`` turns it off: no archive unpacked, numba's CPU left alone (kernels compile here, for this
  CPU, on first use or in ``python -m billiards_env.warmup``).
- ``python -m billiards_env.prebuilt build`` rebuilds this platform's archive after a kernel source changed (3-4
  minutes); ``tests/test_kernel_cache.py`` fails until it is rebuilt.
- ``python -m billiards_env.prebuilt status`` says whether this process uses the prebuilt kernels, and if not,
  why not.
"""
from __future__ import annotations

import hashlib
import io
import json
import lzma
import os
import re
import subprocess
import sys
import sysconfig
import tarfile
import tempfile
import time
from importlib import metadata
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent
#: Where the archives and their manifests live (package data: they ship in the wheel).
PREBUILT_DIR = PACKAGE / "prebuilt_kernels"
#: The file in each cache directory that says which archive was unpacked there.
MARKER = "billiards_env.prebuilt"
#: The stamp of :func:`clear_stale_cache`: the kernel sources' digest the in-tree cache was compiled from.
_STAMP = PACKAGE / "__pycache__" / "kernels.sha256"
#: A line that compiles a function: ``@njit(...)`` or ``@numba.njit(...)``.
_COMPILED = re.compile(r"^\s*@(?:numba\.)?njit\b", re.MULTILINE)
#: The CPU the archives are built for (numba's ``NUMBA_CPU_NAME``; LLVM's baseline of each architecture).
CPU = "generic"
_status = {"last": "not checked yet"}


def kernel_sources() -> list[Path]:
    """Every module of the package with compiled code (an ``@njit`` decorator), and all of ``physics/``."""
    out = set((PACKAGE / "physics").glob("*.py"))
    for path in PACKAGE.rglob("*.py"):
        if _COMPILED.search(path.read_text()):
            out.add(path)
    return sorted(out)


def kernels_digest() -> str:
    """SHA-256 over the kernel sources' package paths and contents: what a cache of compiled kernels belongs to."""
    digest = hashlib.sha256()
    for path in kernel_sources():
        digest.update(path.relative_to(PACKAGE).as_posix().encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()


def clear_stale_cache(digest: str | None = None) -> bool:
    """Delete the in-tree cached machine code (and prebuilt markers) if a kernel source changed since it was built.

    numba keys each cached function on its own file only, so a kernel that calls into another module would
    otherwise keep stale code after that module changes. ``digest``: :func:`kernels_digest`, if already known.
    Returns True if the cache was cleared.
    """
    want = kernels_digest() if digest is None else digest
    if _STAMP.exists() and _STAMP.read_text() == want:
        return False
    for pattern in ("*.nbi", "*.nbc", MARKER):
        for f in PACKAGE.rglob(pattern):
            f.unlink(missing_ok=True)
    _STAMP.parent.mkdir(exist_ok=True)
    _STAMP.write_text(want)
    return True


def platform_tag() -> str:
    """What an archive's compiled code needs to match: interpreter (and its ABI), platform and numba version."""
    abi = getattr(sys, "abiflags", "")
    return f"{sys.implementation.cache_tag}{abi}-{sysconfig.get_platform()}-numba{metadata.version('numba')}"


def manifest_path(tag: str | None = None) -> Path:
    """The manifest of the archive for ``tag`` (default: this interpreter's :func:`platform_tag`)."""
    return PREBUILT_DIR / f"{tag or platform_tag()}.json"


def source_dirs() -> dict[str, Path]:
    """Each package directory holding kernel sources, by its path in the archive (``.`` for the package's own),
    mapped to one of its source files (numba's cache locators work from a source file's path)."""
    out: dict[str, Path] = {}
    for path in kernel_sources():
        rel = path.parent.relative_to(PACKAGE).as_posix()
        out.setdefault(rel, path)
    return out


def _probe() -> None:
    """A function numba's cache locators can be asked about (they read only its first line number)."""


def cache_dir(source: Path) -> Path | None:
    """The directory numba caches ``source``'s kernels in: the first of numba's default locators that accepts it
    (``NUMBA_CACHE_DIR``, then ``__pycache__`` beside it if writable, then the user's cache directory). None if
    ``NUMBA_CACHE_LOCATOR_CLASSES`` replaces numba's locators or no directory is writable."""
    from numba.core import caching, config

    if getattr(config, "CACHE_LOCATOR_CLASSES", None):
        return None
    for cls in (caching.UserProvidedCacheLocator, caching.InTreeCacheLocator, caching.UserWideCacheLocator):
        locator = cls.from_function(_probe, str(source))
        if locator is not None:
            return Path(locator.get_cache_path())
    return None


def _read(path: Path) -> str:
    try:
        return path.read_text()
    except OSError:
        return ""


def _write_atomic(path: Path, data: bytes) -> None:
    """Write ``path`` through a temporary file and a rename: a concurrent reader sees the old file or the new one."""
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    tmp.write_bytes(data)
    os.replace(tmp, path)


def install_prebuilt() -> str:
    """Use the prebuilt kernels in this process if they fit; returns what happened (also :func:`status`).

    Sets ``NUMBA_CPU_NAME=generic`` when an archive for this platform exists (unless the user set it), then, when
    the package's kernel sources are the ones it was built from, unpacks it into numba's cache directories that do
    not hold it yet. Never raises for a cache that cannot be written: the kernels then compile as without it.
    """
    _status["last"] = _install()
    return _status["last"]


def _install() -> str:
    if os.environ.get("BILLIARDS_PREBUILT", "") == "0":
        return "off: BILLIARDS_PREBUILT=0 (the kernels compile here, for this CPU)"
    tag = platform_tag()
    manifest_file = manifest_path(tag)
    if not manifest_file.exists():
        return f"none for this platform ({tag}): the kernels compile here"
    cpu = os.environ.setdefault("NUMBA_CPU_NAME", CPU)
    if cpu != CPU:
        return f"not used: NUMBA_CPU_NAME is {cpu!r} and the prebuilt kernels are for {CPU!r}"
    if "numba" in sys.modules:  # imported before this package: its config read the environment without the CPU
        from numba.core import config
        from numba.core.registry import cpu_target

        config.reload_config()
        built_for = tuple(cpu_target.target_context.codegen().magic_tuple()[1:])
        if built_for != (CPU, ""):  # numba's code generator was made before: it keeps this CPU's features
            return ("not used: numba set up its code generator for this CPU before billiards_env was imported "
                    "(import billiards_env before compiling anything else with numba)")
    try:
        manifest = json.loads(manifest_file.read_text())
        want = f"{tag} {manifest['kernels_digest']}"
        archive, manifest_dirs = PREBUILT_DIR / manifest["archive"], list(manifest["dirs"])
    except (OSError, ValueError, KeyError, TypeError) as err:
        return f"not used: unreadable manifest {manifest_file.name} ({err!r})"
    if "numba" not in sys.modules and not os.environ.get("NUMBA_CACHE_DIR") and all(
            _read(PACKAGE / rel / "__pycache__" / MARKER) == want for rel in manifest_dirs):
        return "used: unpacked before"  # in the directories numba uses by default: no need to import numba to ask
    dirs = {rel: cache_dir(PACKAGE / rel / "__init__.py") for rel in manifest_dirs}
    if any(d is None for d in dirs.values()):
        return "not used: numba has no writable cache directory for the package (or custom cache locators)"
    todo = {rel: d for rel, d in dirs.items() if d is not None and _read(d / MARKER) != want}
    if not todo:
        return "used: unpacked before"
    digest = kernels_digest()
    if digest != manifest["kernels_digest"]:
        return ("not used: the kernel sources changed since the prebuilt kernels were built (rebuild them: "
                "python -m billiards_env.prebuilt build)")
    try:
        if _STAMP.parent in dirs.values() and clear_stale_cache(digest):  # code compiled from other sources: gone
            todo = {rel: d for rel, d in dirs.items() if d is not None and _read(d / MARKER) != want}
        _unpack(archive, todo)
        for d in todo.values():
            _write_atomic(d / MARKER, want.encode())
        if _STAMP.parent in todo.values():  # the in-tree cache now holds code compiled from these very sources
            _write_atomic(_STAMP, digest.encode())
    except (OSError, EOFError, tarfile.TarError, lzma.LZMAError) as err:  # unwritable cache, damaged archive
        return f"not used: could not unpack {archive.name} into numba's cache ({err!r})"
    return f"used: unpacked into {len(todo)} cache director{'y' if len(todo) == 1 else 'ies'}"


def _unpack(archive: Path, dirs: dict[str, Path]) -> None:
    """Write the archive's files of each directory in ``dirs`` (archive path -> cache directory) into it."""
    with tarfile.open(archive, "r:xz") as tar:
        for member in tar:
            rel, _, name = member.name.rpartition("/")
            dest = dirs.get(rel)
            if dest is None or not member.isfile() or not name.endswith((".nbi", ".nbc")):
                continue
            f = tar.extractfile(member)
            if f is not None:
                _write_atomic(dest / name, f.read())


def status() -> str:
    """What :func:`install_prebuilt` did in this process (``billiards_env``'s import runs it)."""
    return _status["last"]


def build(out_dir: Path = PREBUILT_DIR, workers: int | None = None) -> Path:
    """Compile every kernel (``python -m billiards_env.warmup``) for the generic CPU into an empty cache and pack it
    as this platform's archive in ``out_dir``, with its manifest; returns the manifest's path."""
    start = time.perf_counter()
    tag, digest = platform_tag(), kernels_digest()
    with tempfile.TemporaryDirectory(prefix="billiards-prebuilt-") as cache:
        env = {**os.environ, "NUMBA_CACHE_DIR": cache, "NUMBA_CPU_NAME": CPU, "NUMBA_CPU_FEATURES": "",
               "BILLIARDS_PREBUILT": "0", "BILLIARDS_COMPILE_NOTICE": "0", "SDL_VIDEODRIVER": "dummy"}
        cmd = [sys.executable, "-m", "billiards_env.warmup"] + ([] if workers is None else ["--workers", str(workers)])
        subprocess.run(cmd, env=env, check=True)
        from numba.core.caching import UserProvidedCacheLocator

        root = Path(cache)
        members: list[tuple[str, Path]] = []
        seen: set[Path] = set()
        for rel, source in source_dirs().items():
            sub = root / UserProvidedCacheLocator.get_suitable_cache_subpath(str(source))
            seen.add(sub)
            members += [(f"{rel}/{f.name}", f) for f in sorted(sub.glob("*.nb[ic]"))]
        stray = sorted(p.name for p in root.iterdir() if p not in seen)
        if stray:
            raise RuntimeError(f"compiled kernels outside the package's kernel directories: {stray}")
        buf = io.BytesIO()
        with tarfile.open(fileobj=buf, mode="w:xz", preset=9) as tar:
            for name, f in members:
                info = tarfile.TarInfo(name)  # no dates, owners or modes: the same files give the same archive
                data = f.read_bytes()
                info.size, info.mode = len(data), 0o644
                tar.addfile(info, io.BytesIO(data))
        size = sum(f.stat().st_size for _, f in members)
    if kernels_digest() != digest:
        raise RuntimeError("a kernel source changed while the prebuilt kernels were being built: build them again")
    out_dir.mkdir(parents=True, exist_ok=True)
    archive = out_dir / f"{tag}.tar.xz"
    archive.write_bytes(buf.getvalue())
    manifest = {"tag": tag, "archive": archive.name, "cpu": CPU, "kernels_digest": digest,
                "dirs": sorted({name.rpartition("/")[0] for name, _ in members}), "files": len(members),
                "bytes": size, "archive_bytes": archive.stat().st_size,
                "built": time.strftime("%Y-%m-%d %H:%M:%S %z"), "build_s": round(time.perf_counter() - start, 1)}
    path = out_dir / f"{tag}.json"
    path.write_text(json.dumps(manifest, indent=1) + "\n")
    return path
