"""femgear's errors survive pickling (a process pool sends a worker's error back to the parent)."""

import pickle
from concurrent.futures import ProcessPoolExecutor

import pytest

from femgear.errors import ArgumentError, ConvergenceError, OutputError, ResourceError, SceneError

ERRORS = [
    ArgumentError("--workers", "must be >= 1"),
    OutputError("--out", "/nonexistent/x", "permission denied"),
    ResourceError("numerics.level", 3.0 * 1024**3, 1.0 * 1024**3, "use a coarser level"),
    SceneError("wear.field", "needs physics.stiffness = \"ltca\""),
    ConvergenceError("ltca phase 3", "Hertz-width passes did not converge", {"load_change": [1e-2, 3e-4]}),
]


@pytest.mark.parametrize("err", ERRORS, ids=lambda e: type(e).__name__)
def test_errors_round_trip_through_pickle_with_their_attributes(err):
    back = pickle.loads(pickle.dumps(err))
    assert type(back) is type(err) and str(back) == str(err)
    assert back.__dict__ == err.__dict__
    assert back.exit_code == err.exit_code


def _fail(_):
    raise ConvergenceError("case 7", "did not converge", {"residual": [1.0, 0.5]})


def test_a_worker_convergence_error_reaches_the_parent_as_itself():
    """Before, the parent's unpickling failed (TypeError in __init__) and broke the whole pool."""
    with ProcessPoolExecutor(max_workers=1) as pool:
        with pytest.raises(ConvergenceError) as info:
            pool.submit(_fail, 0).result()
    assert info.value.history == {"residual": [1.0, 0.5]} and info.value.case == "case 7"
