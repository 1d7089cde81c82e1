"""The error raised for bad input to the rules layer."""
from __future__ import annotations


class RulesError(ValueError):
    """A game state, shot summary, declaration or option that cannot be: the message names the field and the fix."""


__all__ = ["RulesError"]
