"""The README is a short front page and the docs site (mkdocs.yml, docs/) holds the rest: the README stays within
200 lines, its links to the docs resolve, every page of the site is in the nav and has its blocks run by
tests/docs/test_doc_blocks.py, results pages carry their date and commit, and no page a user reads speaks of
issue numbers. (`mkdocs build --strict`, run by scripts/test.sh, checks the site's own links and API references.)
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest
import yaml

from test_doc_blocks import DOCS

ROOT = Path(__file__).resolve().parents[2]
README_MAX_LINES = 200
#: Pages of the site that are generated or included rather than written in docs/ (page -> the file it includes).
INCLUDES = re.compile(r'^--8<--\s+"([^"]+)"', re.M)
#: Links in Markdown: [text](target), not images' data or web addresses.
LINK = re.compile(r"(?<!!)\[[^\]]*\]\(([^)\s]+)\)")
IMAGE = re.compile(r"!\[[^\]]*\]\(([^)\s]+)\)")
#: "issue 21", "issues 12 and 21", "issue #7", "pre-#21", "(#21)": project-tracker wording a reader cannot follow.
ISSUE = re.compile(r"\bissues?\s*#?\d+|(?<![\w/&#])#\d{1,4}\b", re.I)


def _nav_pages(nav) -> list[str]:
    out: list[str] = []
    for item in nav:
        if isinstance(item, str):
            out.append(item)
        elif isinstance(item, dict):
            for value in item.values():
                out.extend(_nav_pages(value) if isinstance(value, list) else [value])
    return out


def _mkdocs() -> dict:
    return yaml.safe_load((ROOT / "mkdocs.yml").read_text())


NAV = _nav_pages(_mkdocs()["nav"])
#: What a user reads: the README, every page of the site, and the files the site includes.
READ = ["README.md", *(f"docs/{p}" for p in NAV),
        *sorted({m for p in NAV for m in INCLUDES.findall((ROOT / "docs" / p).read_text())})]


def slug(heading: str) -> str:
    """A heading's anchor as MkDocs (Python-Markdown's toc) and GitHub make it, for the headings used here."""
    text = re.sub(r"[`*_]", "", heading).strip().lower()
    text = re.sub(r"[^\w\s-]", "", text)
    return re.sub(r"[-\s]+", "-", text).strip("-")


def anchors(path: Path) -> set[str]:
    text = re.sub(r"^(`{3,}).*?^\1", "", path.read_text(), flags=re.S | re.M)
    return {slug(m.group(1)) for m in re.finditer(r"^#{1,6}\s+(.*?)\s*$", text, re.M)}


def test_readme_is_short():
    n = len((ROOT / "README.md").read_text().splitlines())
    assert n <= README_MAX_LINES, (f"README.md has {n} lines (at most {README_MAX_LINES}): move the detail into a "
                                   "page of docs/ and link it")


@pytest.mark.parametrize("doc", ["README.md", *(f"docs/{p}" for p in NAV)])
def test_links_resolve(doc: str):
    """Every relative link and image of the README and the pages points at a file that exists, and an anchor
    into a Markdown file at one of its headings."""
    path = ROOT / doc
    text = re.sub(r"^(`{3,}).*?^\1", "", path.read_text(), flags=re.S | re.M)
    bad = []
    for target in LINK.findall(text) + IMAGE.findall(text):
        if re.match(r"[a-z]+:", target):
            continue
        file, _, anchor = target.partition("#")
        dest = (path.parent / file).resolve() if file else path
        if not dest.exists():
            bad.append(f"{target}: no file {dest.relative_to(ROOT) if dest.is_relative_to(ROOT) else dest}")
        elif anchor and dest.suffix == ".md" and anchor not in anchors(dest):
            bad.append(f"{target}: no heading with anchor #{anchor} in {dest.relative_to(ROOT)}")
    assert not bad, f"{doc}: broken links: {bad}"


def test_readme_links_the_docs_pages():
    """The README leads to the site: it links every top-level page of the nav but the home page (or, for a page that
    includes a file, that file)."""
    linked = {t.partition("#")[0] for t in LINK.findall((ROOT / "README.md").read_text())}
    missing = [p for p in NAV if p != "index.md" and "/" not in p and f"docs/{p}" not in linked
               and not set(INCLUDES.findall((ROOT / "docs" / p).read_text())) & linked]
    assert not missing, f"README.md links none of these docs pages: {missing}"


def test_every_page_is_in_the_nav_and_tested():
    """Every Markdown page under docs/ is in mkdocs.yml's nav, and its code blocks (or the file it includes) are
    among those tests/docs/test_doc_blocks.py runs."""
    pages = sorted(p.relative_to(ROOT / "docs").as_posix() for p in (ROOT / "docs").rglob("*.md"))
    assert sorted(set(NAV)) == pages, ("pages and nav differ: not in the nav "
                                       f"{sorted(set(pages) - set(NAV))}, in the nav but missing "
                                       f"{sorted(set(NAV) - set(pages))}")
    for doc in READ:
        assert doc in DOCS, f"{doc}: its code blocks are not collected by tests/docs/test_doc_blocks.py (DOCS)"


def test_no_issue_numbers_where_users_read():
    bad = [f"{doc}:{n}: {line.strip()[:100]}" for doc in READ
           for n, line in enumerate((ROOT / doc).read_text().splitlines(), 1) if ISSUE.search(line)]
    assert not bad, "say what changed (and when) instead of an issue number:\n" + "\n".join(bad)


#: The code a user runs and reads the help of: the package, the agents' and benchmarks' commands, the scripts, configs.
CODE_DIRS = ["billiards_env", "agents", "benchmarks", "scripts", "configs"]


def test_no_issue_numbers_in_the_code_users_run():
    files = sorted(p for d in CODE_DIRS for p in (ROOT / d).rglob("*")
                   if p.is_file() and p.suffix in (".py", ".sh", ".yaml", ".yml"))
    assert len(files) > 50
    bad = [f"{p.relative_to(ROOT)}:{n}: {line.strip()[:100]}" for p in files
           for n, line in enumerate(p.read_text().splitlines(), 1) if ISSUE.search(line)]
    assert not bad, "docstrings, help and comments: say what changed (and when), not an issue number:\n" + \
        "\n".join(bad)


#: Results pages: the figures they hold name the date and the commit they were measured at.
RESULTS = ["docs/benchmarks.md", "docs/training.md", "docs/games.md", "docs/rllib.md", "docs/stability.md",
           "docs/physics-engine.md",
           *sorted(f"docs/{p}" for p in NAV if p.startswith("bench/"))]


@pytest.mark.parametrize("doc", RESULTS)
def test_results_pages_carry_date_and_commit(doc: str):
    text = (ROOT / doc).read_text()
    assert re.search(r"\b20\d\d-\d\d-\d\d\b", text), f"{doc}: no date (YYYY-MM-DD) of its figures"
    assert re.search(r"\bcommit [0-9a-f]{7,40}\b", text), f"{doc}: no commit of its figures"
