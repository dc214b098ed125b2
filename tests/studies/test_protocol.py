"""Every study follows the one small protocol (ARCHITECTURE.md, "Studies"; the Devito habit) and imports from its topic folder.

``setup()`` says what to run, ``run()`` computes and returns the results, ``main()`` prints and writes behind
``if __name__ == "__main__"``; tests call ``run(coarse=True)`` where a study has a coarse level.  Studies
live in ``studies/<topic>/`` (the speed benchmarks in ``studies/benchmarks/`` follow their own table-and-JSON
convention).
"""

from __future__ import annotations

import ast
import importlib.util
from pathlib import Path

import pytest

STUDIES = Path(__file__).resolve().parents[2] / "studies"
FILES = sorted(p for p in STUDIES.glob("*/*.py") if p.parent.name not in ("benchmarks", "zoo"))


def test_studies_are_grouped_by_topic():
    assert len(FILES) >= 30
    assert sorted(p.name for p in STUDIES.glob("*.py")) == ["_common.py"]     # only the shared helper at the top
    assert {p.parent.name for p in FILES} == {"body", "dynamics", "ehl", "ltca", "paper", "validation"}


@pytest.mark.parametrize("path", FILES, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_study_protocol(path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    defined = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    assert {"setup", "run", "main"} <= defined, f"missing {sorted({'setup', 'run', 'main'} - defined)}"
    guards = [n for n in tree.body if isinstance(n, ast.If) and ast.unparse(n.test) == "__name__ == '__main__'"]
    assert guards and "main(" in ast.unparse(guards[0])


@pytest.mark.parametrize("path", FILES, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_study_imports(path):
    """The module loads from its topic folder (its imports and the paths it builds at import time resolve)."""
    spec = importlib.util.spec_from_file_location(f"study_{path.parent.name}_{path.stem}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    assert callable(module.run) and callable(module.setup) and callable(module.main)
