"""The measurement helpers of the benchmarks (no timing is asserted)."""

import numpy as np
import pytest

from femgear.perf import measure, pareto_front


def test_measure_traces_numpy_allocations_and_returns_the_value():
    m = measure(lambda: np.ones(1_000_000).sum(), repeats=2)
    assert m.value == 1_000_000 and m.repeats == 2
    assert m.peak_bytes >= 8_000_000
    with pytest.raises(ValueError, match="repeats"):
        measure(lambda: None, repeats=0)


def test_pareto_front_keeps_only_non_dominated_rows():
    rows = [dict(name="a", seconds=1, error=0.1), dict(name="b", seconds=2, error=0.2),
            dict(name="c", seconds=3, error=0.01), dict(name="d", seconds=0.5, error=0.5)]
    assert [r["name"] for r in pareto_front(rows)] == ["d", "a", "c"]
