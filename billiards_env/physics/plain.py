"""``plain(value)``: a constant handed from compiled code to another compiled function as its plain type.

numba types a constant (``False``, ``0``, ``3``) as a literal type (``Literal[bool](False)``, ``Literal[int](0)``)
and compiles the function it is passed to once more for that literal: a kernel that Python calls with a ``bool``
would be compiled again for ``Literal[bool](False)`` from each compiled caller, and a helper called with a different
constant from each of its call sites once per constant. A compiled caller writes ``f(x, plain(False))`` instead, and
``f`` is compiled once, for ``bool`` (the type Python's calls give it); the value and the arithmetic are the same.

In Python ``plain`` returns its argument.
"""
from __future__ import annotations

from typing import TypeVar

from numba.extending import overload

T = TypeVar("T")


def plain(value: T) -> T:
    """``value`` itself; in compiled code typed as its plain type (``bool``, ``int64``), never as a literal."""
    return value


@overload(plain)
def _plain(value):
    """numba's implementation: an overload is typed on its arguments' plain types first, so this identity is
    compiled for ``bool`` or ``int64`` and returns that type. Not inlined into numba's IR (``inline="always"``):
    a ``prange`` loop's body is typed again after such inlining, and the constant would be a literal there (LLVM
    inlines the compiled identity anyway)."""
    return lambda value: value


__all__ = ["plain"]
