"""The error raised for bad input to the rules layer, and the check of an options class's keywords."""
from __future__ import annotations

import difflib
import functools
from dataclasses import fields
from typing import Any, TypeVar

T = TypeVar("T")


class RulesError(ValueError):
    """A game state, shot summary, declaration or option that cannot be: the message names the field and the fix."""


def check_keywords(cls: type, keys: Any) -> None:
    """Refuse a keyword of ``keys`` that the options dataclass ``cls`` does not have: :class:`RulesError` naming the
    allowed options, with a did-you-mean (every game's rules options go through this, e.g. an env's ``rules``)."""
    names = [f.name for f in fields(cls)]
    for key in keys:
        if key not in names:
            close = difflib.get_close_matches(str(key), names, n=1)
            hint = f"did you mean {close[0]!r}? " if close else ""
            raise RulesError(f"{cls.__name__}: unknown option {key!r}; {hint}valid options: {', '.join(names)}")


def checked_keywords(cls: type[T]) -> type[T]:
    """Class decorator for a ruleset's options dataclass (apply it above ``@dataclass``): an unknown keyword raises
    :class:`RulesError` naming the allowed options, with a did-you-mean, instead of Python's ``__init__() got an
    unexpected keyword argument`` (``rules={"push_outt": True}`` in an env config)."""
    init = cls.__init__

    @functools.wraps(init)
    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
        check_keywords(cls, kwargs)
        init(self, *args, **kwargs)

    cls.__init__ = __init__  # type: ignore[method-assign]
    return cls


__all__ = ["RulesError", "check_keywords", "checked_keywords"]
