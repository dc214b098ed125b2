"""A typo in one half of a double-helical REXS member is reported on that attribute (issue 37, item 7).

Before, the halves no longer matched as twins, and the pair was refused as "neither single- nor
double-helical" on the helix angle of the other member: a helix-hand problem the file did not have.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ZOO = Path(__file__).resolve().parents[2] / "studies" / "zoo"


@pytest.mark.parametrize("half, attribute, new, said", [
    ("pinion right half", "normal_module", "6.5", "6.5 mm differs from 6 mm"),
    ("gear right half", "number_of_teeth", "98", "98 differs from 97"),
])
def test_a_typo_in_one_half_of_a_double_helical_rexs_member_names_that_attribute(half, attribute, new, said, cli,
                                                                                   tmp_path):
    """marine's pair exported to REXS, then one attribute of one gear half changed: the halves no longer agree,
    and the refusal names that attribute on that half, not the helix hand."""
    rexs = tmp_path / "marine.rexs"
    rc, _, err = cli("rexs", "--export", ZOO / "marine.toml", "-o", rexs)
    assert rc == 0, err
    text = rexs.read_text(encoding="utf-8")
    start = text.index(f'name="{half}" type="cylindrical_gear"')
    block = re.compile(f'(id="{attribute}" unit="[^"]*">)([^<]*)(<)')
    hit = block.search(text, start)
    edited = text[:hit.start()] + hit.group(1) + new + hit.group(3) + text[hit.end():]
    bad = tmp_path / "typo.rexs"
    bad.write_text(edited, encoding="utf-8")
    rc, _, err = cli("rexs", bad, "--stage", 2)
    assert rc == 2 and len(err.strip().splitlines()) == 1, err
    assert f'"{half}" (cylindrical_gear), attribute {attribute}' in err and said in err, err
    assert "helix_angle" not in err and "neither single- nor double-helical" not in err
