"""MkDocs hooks for the docs site (mkdocs.yml ``hooks:``).

- Lists written for GitHub: the pages indent a list item's continuation, its nested lists and its code blocks by
  two spaces (CommonMark reads that), while Python-Markdown needs four. :func:`on_page_markdown` doubles the
  indentation inside top-level lists (code blocks in them move with their fence, their own indentation kept), so
  the site nests what GitHub nests; the Markdown files stay as they are.
- The API pages: the docstrings' reST roles (:class:`X`, :func:`~a.b.f`...) are written for ``help()`` and
  Sphinx-style readers; mkdocstrings renders them as Markdown, where a role would show as ``:class:`` before the
  name. :func:`on_page_content` drops the role (and a leading ``~``), and the ``::`` that introduces a literal
  block becomes a colon (the block itself renders as code already).
"""
import re

_ITEM = re.compile(r"^(?:[-*+]|\d+\.)\s")
_FENCE = re.compile(r"^(\s*)(`{3,}|~{3,})")
_ROLE = re.compile(r":(?:py:)?(?:class|mod|func|meth|data|attr|exc|obj|const):<code>~?")
_LITERAL = re.compile(r"::(\s*</p>)")


def relist(markdown: str) -> str:
    """``markdown`` with the indentation inside top-level lists doubled (fenced code keeps its own)."""
    out = []
    in_list = False
    fence = None  # (marker, original indent, added indent) of an open fenced block inside a list
    for line in markdown.split("\n"):
        if fence is not None:
            marker, indent, add = fence
            stripped = line.lstrip()
            out.append(" " * add + line if line.strip() else line)
            if stripped.startswith(marker) and stripped.strip().strip(marker[0]) == "":
                fence = None
            continue
        if _ITEM.match(line):
            if in_list and out and out[-1][:1] == " " and out[-1].strip():
                out.append("")  # else Python-Markdown reads the item as the previous paragraph's lazy continuation
            in_list = True
            out.append(line)
            continue
        if in_list and line.strip() and not line[0].isspace():
            in_list = False
        if in_list and line.strip():
            indent = len(line) - len(line.lstrip(" "))
            m = _FENCE.match(line)
            if m:
                fence = (m.group(2), indent, indent)
            out.append(" " * (2 * indent) + line.lstrip(" "))
            continue
        m = _FENCE.match(line)
        if m and not in_list:  # a top-level code block: copied through untouched
            fence = (m.group(2), 0, 0)
        out.append(line)
    return "\n".join(out)


def on_page_markdown(markdown, page, config, files):
    return relist(markdown)


def on_page_content(html, page, config, files):
    if not page.file.src_uri.startswith("api/"):
        return html
    return _LITERAL.sub(r":\1", _ROLE.sub("<code>", html))
