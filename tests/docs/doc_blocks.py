"""Fenced code blocks of the project's Markdown files, and the commands in them, for tests/docs/test_doc_blocks.py.

A block is a fenced block (```lang ... ```), indented or not (inside a list item). Its language decides what the
tests do with it:

- ``python``: executed; the python blocks of one file run in order in one process, sharing their names (a block
  may use what an earlier one imported or made);
- ``bash`` / ``sh`` / ``shell``: every command runs (a command is a line, with ``\\``-continued lines joined and
  comments removed), with the budget tests/docs/doc_commands.py gives it;
- ``json`` / ``yaml``: parsed (a sample that is not valid JSON fails);
- ``text``: not run (a layout tree, output shown as text);
- no language: an error (say ``text`` if it is not meant to run), so a command cannot hide in an unlabelled block.

Directives, in an HTML comment right above the fence (invisible when rendered, visible in the source):

- ``<!-- docs-test: skip: REASON -->``: the block is not run. Only for what cannot run in a CI job (a display, a
  Ray cluster, the test suite itself); the reason is required and shown in the test report.
- ``<!-- docs-test: before: COMMAND -->``: run COMMAND first (e.g. make the trained run a block loads), with the
  same budgets as the commands of bash blocks.
- ``<!-- docs-test: venv: .venv-clients -->``: a python block that runs in that venv's interpreter (the client
  libraries of docs/ecosystem.md live in .venv-clients); the python blocks of a file run in one process per venv.
- ``<!-- docs-test: output-of: COMMAND -->`` above a JSON block: the block is what COMMAND prints (same keys in the
  same order, each number equal to the printed one to the digits the block shows).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

RUN_LANGS = ("python", "bash", "sh", "shell")
DATA_LANGS = ("json", "yaml")
QUIET_LANGS = ("text",)
LANGS = RUN_LANGS + DATA_LANGS + QUIET_LANGS

_FENCE = re.compile(r"^(?P<indent>[ \t]*)(?P<fence>`{3,})(?P<info>[^`]*)$")
_DIRECTIVE = re.compile(r"<!--\s*docs-test:\s*(?P<kind>[a-z-]+)\s*:?\s*(?P<arg>.*?)\s*-->", re.S)


@dataclass
class Block:
    """One fenced code block: where it is, its language, its code (dedented), and its directives."""

    path: Path
    line: int  #: 1-based line of the opening fence
    lang: str
    code: str
    skip: str | None = None  #: the reason given by a skip directive
    before: list[str] = field(default_factory=list)  #: commands of before directives
    output_of: str | None = None  #: the command whose output this block shows (an output-of directive)
    venv: str = ".venv"  #: the venv whose python runs it (a venv directive)

    @property
    def where(self) -> str:
        return f"{self.path.as_posix()}:{self.line}"


class DocsFormatError(ValueError):
    """A block the runner cannot take as written: the message names the file, the line and the fix."""


def read_blocks(path: Path, root: Path) -> list[Block]:
    """Every fenced block of ``path`` (named relative to ``root``), with the directives in the comment lines right
    above each; raises :class:`DocsFormatError` on an unclosed fence or a directive it does not know."""
    lines = path.read_text(encoding="utf-8").splitlines()
    rel = path.relative_to(root)
    blocks: list[Block] = []
    k = 0
    while k < len(lines):
        m = _FENCE.match(lines[k])
        if not m:
            k += 1
            continue
        indent, fence, info = m.group("indent"), m.group("fence"), m.group("info").strip()
        start = k
        body: list[str] = []
        k += 1
        while k < len(lines) and not (lines[k].strip().startswith(fence) and lines[k].strip().strip("`") == ""):
            text = lines[k]
            body.append(text[len(indent):] if text.startswith(indent) else text.lstrip())
            k += 1
        if k >= len(lines):
            raise DocsFormatError(f"{rel}:{start + 1}: the code block opened here is never closed")
        k += 1
        block = Block(rel, start + 1, info.split()[0].lower() if info else "", "\n".join(body) + "\n")
        _read_directives(block, lines, start)
        blocks.append(block)
    return blocks


def _read_directives(block: Block, lines: list[str], start: int) -> None:
    """Directives in the HTML comments on the lines right above the fence (no blank line between)."""
    k = start - 1
    above: list[str] = []
    inside = False
    while k >= 0:
        text = lines[k].strip()
        if not inside:
            if not text.endswith("-->"):
                break
            inside = True
        above.insert(0, lines[k])
        if "<!--" in text:
            inside = False
        k -= 1
    for m in _DIRECTIVE.finditer("\n".join(above)):
        kind, arg = m.group("kind"), " ".join(m.group("arg").split())
        if kind == "skip":
            if not arg:
                raise DocsFormatError(f"{block.where}: a skip directive needs a reason: "
                                      "<!-- docs-test: skip: needs a display -->")
            block.skip = arg
        elif kind == "before":
            block.before.append(arg)
        elif kind == "output-of":
            block.output_of = arg
        elif kind == "venv":
            if not re.fullmatch(r"\.venv(-[\w]+)?", arg):
                raise DocsFormatError(f"{block.where}: docs-test: venv: expected a venv folder such as .venv-clients, "
                                      f"got {arg!r}")
            block.venv = arg
        else:
            raise DocsFormatError(f"{block.where}: unknown directive 'docs-test: {kind}'; use skip, before, venv or "
                                  "output-of")


def commands(code: str) -> list[str]:
    """The commands of a shell block: lines joined at a trailing backslash, comments and blank lines removed.
    A line that is only a comment is dropped; quotes are respected (``#`` inside quotes stays)."""
    out: list[str] = []
    pending = ""
    for raw in code.splitlines():
        line = pending + raw
        if line.rstrip().endswith("\\"):
            pending = line.rstrip()[:-1] + " "
            continue
        pending = ""
        text = strip_comment(line).strip()
        if text:
            out.append(" ".join(text.split()) if "'" not in text and '"' not in text else text)
    if pending.strip():
        out.append(strip_comment(pending).strip())
    return out


def strip_comment(line: str) -> str:
    """``line`` without a shell comment (a ``#`` at the start or after whitespace, outside quotes)."""
    quote: str | None = None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "#" and (i == 0 or line[i - 1].isspace()):
            return line[:i]
    return line


__all__ = ["Block", "DocsFormatError", "read_blocks", "commands", "strip_comment", "LANGS", "RUN_LANGS",
           "DATA_LANGS", "QUIET_LANGS"]
