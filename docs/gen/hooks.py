"""MkDocs hook: add the pages generated from the code (docs/gen/pages.py) to the site at build time.

Also: ``<!-- figure: NAME -->`` lines show the gallery's figures (``docs/gen/gallery.py``);
``README.md``, ``ARCHITECTURE.md`` and ``CHANGELOG.md`` from the repository root as the site's
``index.md``, ``architecture.md`` and ``changelog.md`` (one copy of each, kept at the root where a clone
shows it; their links rewritten for the site).
"""

from __future__ import annotations

import functools
import importlib.util
import re
from pathlib import Path

from mkdocs.structure.files import File

ROOT = Path(__file__).resolve().parents[2]
ROOT_PAGES = {"index.md": "README.md", "architecture.md": "ARCHITECTURE.md", "changelog.md": "CHANGELOG.md"}
#: links of the root pages as the site has them
ROOT_LINKS = {"](docs/": "](", "](ARCHITECTURE.md)": "](architecture.md)", "](CHANGELOG.md)": "](changelog.md)"}


@functools.cache
def _pages_module():
    spec = importlib.util.spec_from_file_location("femgear_doc_pages", Path(__file__).with_name("pages.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _pages():
    return _pages_module().PAGES


#: the section that takes any other page of docs/ that the navigation does not name
MORE = "More notes"


def _nav_files(nav) -> set[str]:
    out: set[str] = set()
    for item in nav if isinstance(nav, list) else [nav]:
        if isinstance(item, dict):
            for value in item.values():
                out |= _nav_files(value)
        elif isinstance(item, str):
            out.add(item)
    return out


def _add_unlisted(files, config) -> None:
    """A page of docs/ that the navigation does not name (a note added by another change) goes under MORE,
    so that a new page is always reachable and never fails the strict build for that alone."""
    listed = _nav_files(config["nav"])
    extra = sorted(f.src_uri for f in files.documentation_pages() if f.src_uri not in listed)
    if extra:
        config["nav"].append({MORE: extra})


def on_files(files, config):
    _pages_module.cache_clear()             # once per build: `mkdocs serve` reads edits of docs/gen/*.py
    for rel, make in _pages().items():
        files.append(File.generated(config, rel, content=make()))
    for rel, name in ROOT_PAGES.items():      # their links into docs/ are relative to the root
        text = (ROOT / name).read_text(encoding="utf-8")
        if not (Path(config["docs_dir"]) / "guide" / "sweeps.md").exists():   # the sweeps guide not in this tree
            text = re.sub(r"\[([^\]]+)\]\(docs/guide/sweeps\.md\)", r"\1 (`docs/guide/sweeps.md`)", text)
        for old, new in ROOT_LINKS.items():
            text = text.replace(old, new)
        files.append(File.generated(config, rel, content=text))
    _add_unlisted(files, config)
    return files


#: Sphinx roles in docstrings (``:class:`X```) before the code span mkdocstrings made of the backticks
_ROLE = re.compile(r":(?:class|func|mod|meth|attr|data|exc|obj):(?=<code)")


def on_page_markdown(markdown, page, config, files):
    """A line ``<!-- figure: NAME -->`` shows the gallery's figure NAME: its picture, command and two lines
    (``docs/gen/gallery.py``); an unknown NAME stops the build."""
    if "<!-- figure:" not in markdown:
        return markdown
    return _pages_module().gallery().expand(markdown, prefix="../" * page.file.src_uri.count("/"))


def on_page_content(html, page, config, files):
    """The API pages show ``X`` for the docstrings' :class:`X` (the source keeps Sphinx's roles)."""
    return _ROLE.sub("", html)
