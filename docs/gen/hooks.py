"""MkDocs hook: add the pages generated from the code (docs/gen/pages.py) to the site at build time.

Also: ``ARCHITECTURE.md`` and ``CHANGELOG.md`` from the repository root as ``architecture.md`` and
``changelog.md`` (one copy of each, kept at the root where a clone shows it), and the sweeps guide
``guide/sweeps.md`` in the navigation when it is present.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

from mkdocs.structure.files import File

ROOT = Path(__file__).resolve().parents[2]
ROOT_PAGES = {"architecture.md": "ARCHITECTURE.md", "changelog.md": "CHANGELOG.md"}


def _pages():
    spec = importlib.util.spec_from_file_location("femgear_doc_pages", Path(__file__).with_name("pages.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.PAGES


def on_config(config):
    if (Path(config["docs_dir"]) / "guide" / "sweeps.md").exists():
        for section in config["nav"]:
            if "User guide" in section:
                section["User guide"].insert(4, {"Sweeps, local and on a Dask cluster": "guide/sweeps.md"})
    return config


def on_files(files, config):
    for rel, make in _pages().items():
        files.append(File.generated(config, rel, content=make()))
    for rel, name in ROOT_PAGES.items():
        files.append(File.generated(config, rel, content=(ROOT / name).read_text(encoding="utf-8")))
    return files
