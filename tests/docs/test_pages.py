"""The generated docs pages and the README follow the code (issue 30).

The scene-key, result-field and level pages are generated from the schema, the typed results
and the registries; the README's levels table must equal the one generated from the registries
(``python docs/gen/pages.py --readme`` rewrites it). The README stays a short entry page.
"""

from __future__ import annotations

import dataclasses
import importlib.util
import re
from pathlib import Path

from femgear.levels import REGISTRIES
from femgear.results import RunResult
from femgear.scene.keys import scene_keys

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"


def pages():
    spec = importlib.util.spec_from_file_location("femgear_doc_pages", ROOT / "docs" / "gen" / "pages.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_scene_keys_page_lists_every_key_with_its_unit():
    text = pages().scene_keys_page()
    for k in scene_keys():
        row = next((line for line in text.splitlines() if line.startswith(f"| `{k.name}` |")
                    and k.description[:30].replace("[", "\\[").replace("]", "\\]") in line), None)
        assert row is not None, k.key
        if k.unit:
            assert f"| {k.unit.replace('[', '')} |" in row or k.unit in row, k.key
    assert text.count("## `[") == len({k.table for k in scene_keys()})


def test_result_fields_page_lists_the_run_result_fields():
    text = pages().result_fields_page()
    section = text.split("## `RunResult`")[1].split("\n## ")[0]
    for f in dataclasses.fields(RunResult):
        assert f"| `{f.name}` |" in section
    assert "## `Tribology`" in text and "## `ContactPath`" in text and "## `MeshStiffness`" in text
    assert "## `results.json`" in text and "along_path" in text, \
        "the layout contract of results.json is read from femgear/edge/io/run.py: moved? update docs/gen/pages.py"


def test_levels_page_lists_every_registered_level():
    text = pages().levels_page()
    for sub, reg in REGISTRIES.items():
        assert f"## `physics.{sub}`" in text
        for name, level in reg.items():
            assert f"| `{name}` | {level.summary}" in text


def test_readme_levels_table_is_the_generated_one():
    text = README.read_text(encoding="utf-8")
    begin, end = pages().README_MARKERS
    block = text.split(begin)[1].split(end)[0].strip()
    assert block == pages().levels_table(), "run: python docs/gen/pages.py --readme"


def test_readme_is_a_short_entry_page():
    text = README.read_text(encoding="utf-8")
    assert len(text.splitlines()) <= 200
    for gone in ("coupled_path", "femgear/friction", "femgear.friction"):
        assert gone not in text
    for command in ("make demo", "make test", "femgear run", "femgear sweep", "femgear new", "ParaView"):
        assert command in text


def test_readme_and_docs_links_point_at_files():
    """Relative links of the README and the docs pages resolve (pages generated at build time aside)."""
    files = [README, *(ROOT / "docs").rglob("*.md")]
    generated = (*pages().PAGES, "architecture.md", "changelog.md", "index.md", "guide/sweeps.md")  # made at build
    missing = []
    for path in files:
        for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", path.read_text(encoding="utf-8")):
            if target.startswith(("http://", "https://", "mailto:")):
                continue
            resolved = (path.parent / target).resolve()
            if resolved.is_relative_to(ROOT / "docs") and str(resolved.relative_to(ROOT / "docs")) in generated:
                continue
            if not resolved.exists():
                missing.append(f"{path.relative_to(ROOT)} -> {target}")
    assert not missing, missing
