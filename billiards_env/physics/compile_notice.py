"""One line on stderr when this process starts compiling the package's kernels because numba's cache is cold.

The first env (or first shot) on a fresh install compiles the numba kernels for this machine (30-60 s; cached
after, so once per install and source change); without a word the program seems to hang. Importing this module
(``billiards_env.physics`` does, before any kernel) registers a numba compile listener: at the first compilation of
a cached ``billiards_env`` kernel (numba compiles only on a cache miss; a warm cache loads and fires no event) it
prints :data:`NOTICE` once per process, where a person reads stderr: a terminal or a notebook. Output that goes to
a pipe or a file (CI, test runs comparing stderr) stays as it was. ``BILLIARDS_COMPILE_NOTICE=1`` prints it there
too, ``=0`` never.
"""
from __future__ import annotations

import os
import sys

from numba.core import event

#: What the user reads.
NOTICE = ("billiards_env: compiling the numba kernels for this machine (once: 30-60 s for a first env, cached for "
          "next time); `python -m billiards_env.warmup` does it ahead of time, `python -m billiards_env.prebuilt "
          "status` says why the prebuilt kernels are not used")
_state = {"installed": False, "said": False}


def _wanted() -> bool:
    """The notice is printed: forced on or off by ``BILLIARDS_COMPILE_NOTICE``, else when stderr is a terminal or
    the process is a notebook kernel."""
    flag = os.environ.get("BILLIARDS_COMPILE_NOTICE", "")
    if flag in ("0", "1"):
        return flag == "1"
    isatty = getattr(sys.stderr, "isatty", None)
    return bool(isatty and isatty()) or "ipykernel" in sys.modules


class _FirstCompile(event.Listener):
    """Says :data:`NOTICE` at the first compilation of a cached kernel of this package."""

    def on_start(self, ev: event.Event) -> None:
        if _state["said"]:
            return
        d = ev.data.get("dispatcher")
        func = getattr(d, "py_func", None)
        cached = type(getattr(d, "_cache", None)).__name__ != "NullCache"
        if func is not None and cached and str(getattr(func, "__module__", "")).startswith("billiards_env"):
            _state["said"] = True
            if _wanted():
                print(NOTICE, file=sys.stderr, flush=True)

    def on_end(self, ev: event.Event) -> None:
        """Nothing at the end of a compilation."""


def install() -> None:
    """Register the listener (idempotent; done on import)."""
    if not _state["installed"]:
        event.register("numba:compile", _FirstCompile())
        _state["installed"] = True


def said() -> bool:
    """Whether this process met a cold cache (and printed the notice where it is wanted)."""
    return bool(_state["said"])


install()

__all__ = ["NOTICE", "install", "said"]
