"""Every code block of docs/rules.md runs (the docs' examples of the rulesets, snooker and three-cushion
included)."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

DOC = Path(__file__).resolve().parents[2] / "docs" / "rules.md"
BLOCKS = re.findall(r"```python\n(.*?)```", DOC.read_text(encoding="utf-8"), re.S)


def test_the_doc_has_examples():
    assert len(BLOCKS) >= 3


@pytest.mark.parametrize("k", range(len(BLOCKS)))
def test_code_block_runs(k):
    scope: dict = {}
    exec(compile(BLOCKS[k], f"{DOC.name}[block {k}]", "exec"), scope)  # noqa: S102 - our own docs
    assert "call" in scope and "state" in scope  # each example ends with a call and the next state
