"""MkDocs hook: the docstrings' reST roles (:class:`X`, :func:`~a.b.f`...) shown as plain code in the API pages.

The package's docstrings are written for ``help()`` and Sphinx-style readers; mkdocstrings renders them as
Markdown, where a role would show as ``:class:`` before the name. This drops the role (and a leading ``~``), and
the ``::`` that introduces a literal block becomes a colon (the block itself renders as code already).
"""
import re

_ROLE = re.compile(r":(?:py:)?(?:class|mod|func|meth|data|attr|exc|obj|const):<code>~?")

_LITERAL = re.compile(r"::(\s*</p>)")


def on_page_content(html, page, config, files):
    if not page.file.src_uri.startswith("api/"):
        return html
    return _LITERAL.sub(r":\1", _ROLE.sub("<code>", html))
