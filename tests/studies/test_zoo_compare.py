"""studies/validation/zoo_compare.py: two zoo matrix folders compared number by number (the refactor check)."""

import json

from studies.validation.zoo_compare import compare


def _cell(root, name, summary):
    p = root / name / "default"
    p.mkdir(parents=True)
    (p / "results.json").write_text(json.dumps({"summary": summary}))


def test_equal_runs_agree_and_a_moved_number_or_a_removed_key_is_found(tmp_path):
    base = {"film": {"minimum": 1.0e-7, "level": "formula"}, "dynamics": {"seconds": 3.0, "x": [1.0, 2.0]}}
    _cell(tmp_path / "a", "s", base)
    _cell(tmp_path / "b", "s", {**base, "dynamics": {"seconds": 9.0, "x": [1.0, 2.0]}, "new": 1})
    same = compare(tmp_path / "a", tmp_path / "b", 1e-9, 1e-300)["cells"]["s/default"]
    assert not same["differ"] and not same["removed"] and same["added"] == ["new"] and same["compared"] == 3
    _cell(tmp_path / "c", "s", {"film": {"minimum": 1.0e-7 * (1 + 1e-6), "level": "formula"}})
    moved = compare(tmp_path / "a", tmp_path / "c", 1e-9, 1e-300)["cells"]["s/default"]
    assert [k for k, _, _ in moved["differ"]] == ["film.minimum"] and moved["removed"] == ["dynamics"]


def test_the_moved_numbers_by_key_fold_list_indices_and_keep_the_largest_move(tmp_path):
    from studies.validation.zoo_compare import by_key

    _cell(tmp_path / "a", "s", {"S_H": [1.0, 2.0], "film": {"method": "FE"}})
    _cell(tmp_path / "b", "s", {"S_H": [1.1, 3.0], "film": {"method": "FD"}})
    rows = by_key(compare(tmp_path / "a", tmp_path / "b", 0.01, 1e-300))
    assert set(rows) == {"S_H[]", "film.method"}
    assert rows["S_H[]"]["cells"] == ["s/default"] and abs(rows["S_H[]"]["max_rel"] - 1 / 3) < 1e-12
    assert rows["film.method"]["max_rel"] is None
