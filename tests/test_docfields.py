"""femgear.docfields: attribute docstrings with units, checked at class definition and shown by help()."""

from __future__ import annotations

import pydoc
from dataclasses import dataclass

import numpy as np
import pytest

from femgear.docfields import FieldDoc, FieldDocError, document_fields, field_docs, is_documented


@document_fields
@dataclass(frozen=True)
class Sample:
    """A documented frozen result."""

    force: float
    """total normal force along the line of action [N]"""
    phase: np.ndarray
    """mesh phase, one period is [0, 1) [base pitches]"""
    ratio: float = 0.5
    """load share of the left helix,
    a multi-line docstring [-]"""


def test_docs_and_units_are_read_in_field_order():
    docs = field_docs(Sample)
    assert list(docs) == ["force", "phase", "ratio"]
    assert docs["force"] == FieldDoc("total normal force along the line of action", "N")
    # only the trailing brackets are the unit; an interval in the meaning stays in the meaning
    assert docs["phase"] == FieldDoc("mesh phase, one period is [0, 1)", "base pitches")
    assert docs["ratio"] == FieldDoc("load share of the left helix, a multi-line docstring", "-")
    assert is_documented(Sample)


def test_help_shows_the_fields_with_units():
    text = pydoc.render_doc(Sample, renderer=pydoc.plaintext)
    assert "A documented frozen result." in text
    assert "force [N]" in text and "total normal force along the line of action" in text
    assert "ratio [-]" in text


def test_a_field_without_docstring_is_rejected_naming_it():
    with pytest.raises(FieldDocError, match=r"Bad\.torque: no attribute docstring"):
        @document_fields
        @dataclass(frozen=True)
        class Bad:
            force: float
            """normal force [N]"""
            torque: float


def test_a_docstring_without_unit_is_rejected_naming_the_field():
    with pytest.raises(FieldDocError, match=r"NoUnit\.speed: .* does not end with a unit"):
        @document_fields
        @dataclass
        class NoUnit:
            speed: float
            """pinion speed in rpm"""


def test_inherited_fields_keep_their_base_docs():
    @document_fields
    @dataclass(frozen=True)
    class Child(Sample):
        extra: int = 0
        """number of extra passes [-]"""

    assert list(field_docs(Child)) == ["force", "phase", "ratio", "extra"]
    assert field_docs(Child)["force"].unit == "N"


def test_not_a_dataclass_is_refused():
    with pytest.raises(TypeError, match="not a dataclass"):
        document_fields(type("Plain", (), {}))


def test_every_field_reachable_from_run_result_has_a_doc_and_a_unit():
    import dataclasses

    import femgear.pipeline  # noqa: F401  (imports every sub-model's result type)
    from femgear.docfields import field_tree
    from femgear.results import INPUT_TYPES, RunResult

    types = field_tree(RunResult, stop=INPUT_TYPES)
    names = {c.__name__ for c in types}
    # the walk reaches the typed products of every sub-model (a broken walk would check nothing)
    assert {"RunResult", "Tribology", "ContactPath", "MeshStiffness", "LTCACycle", "LTCAResult", "CouplingState",
            "CoupledResult", "DynamicsRun", "Response", "TEAnalysis", "PairRating", "LevelFilm"} <= names
    missing = [f"{path} ({c.__qualname__})" for c, path in types.items() if not is_documented(c)]
    assert not missing, f"not decorated with @document_fields: {missing}"
    for cls, path in types.items():
        docs = field_docs(cls)
        assert list(docs) == [f.name for f in dataclasses.fields(cls)], path
        for name, d in docs.items():
            assert d.doc and d.unit, f"{path}.{name}"


def test_the_units_table_lists_leaf_fields_by_path():
    import femgear.pipeline  # noqa: F401
    from femgear.edge.io.run import result_units

    units = result_units()
    assert units["contact.hertz_pressure"] == "Pa" and units["stiffness.k_left"] == "N/m"
    assert units["stiffness.ltca.result.lte"] == "m"           # through an annotation imported for typing only
    assert units["tribology.friction_coefficient"] == "-" and units["seconds"] == "s"
    assert units["rating.own.fillet.max_principal"] == "Pa"    # through tuple[FilletStress, FilletStress]
    assert "stiffness.ltca" not in units and not any(k.startswith("case.") for k in units)
