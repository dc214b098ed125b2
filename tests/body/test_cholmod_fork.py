"""The system's CHOLMOD (scikit-sparse) and the forked body stages: GNU OpenMP does not survive fork.

A process that has factored with the system's CHOLMOD holds an OpenMP team; a forked child that factors again
waits for it forever.  :func:`femgear.perf.interruptible` must then run its stage in this process.
"""

import subprocess
import sys
import textwrap

import pytest

from femgear.physics.body.elastic3d import cholmod_backend

pytestmark = pytest.mark.skipif(cholmod_backend() != "scikit-sparse", reason="needs the system's CHOLMOD (scikit-sparse)")

SCRIPT = textwrap.dedent("""
    import os
    import numpy as np, scipy.sparse as sp
    from femgear.perf import interruptible
    from femgear.physics.body.elastic3d import _CholmodFactor

    n = 20
    T = sp.diags([-np.ones(n - 1), 2 * np.ones(n), -np.ones(n - 1)], [-1, 0, 1])
    I = sp.identity(n)
    K = (sp.kron(sp.kron(T, I), I) + sp.kron(sp.kron(I, T), I) + sp.kron(sp.kron(I, I), T)).tocsr()
    b = np.ones((K.shape[0], 2))
    x0 = _CholmodFactor(K).solve(b)                 # the parent factors first (its OpenMP team starts)

    def stage():
        return os.getpid(), _CholmodFactor(K).solve(b)

    pid, x = interruptible(stage)                   # a forked child would hang here
    assert np.allclose(x, x0)
    print("same process" if pid == os.getpid() else "child")
""")


def test_a_stage_after_a_factor_in_this_process_runs_here_and_returns():
    run = subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True, timeout=120,
                         env=None)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "same process"


def test_a_stage_forks_while_this_process_has_not_factored():
    script = SCRIPT.replace("x0 = _CholmodFactor(K).solve(b)", "x0 = sp.linalg.spsolve(K.tocsc(), b)")
    run = subprocess.run([sys.executable, "-c", "import scipy.sparse.linalg\n" + script], capture_output=True,
                         text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "child"
