"""One BLAS thread for the EHL tests when numpy is not imported yet: the dense coarse
solves thrash with two threads on a shared two-core machine (0.1 s vs 0.4 s per
963x963 solve measured)."""

import os
import sys

if "numpy" not in sys.modules:
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    os.environ.setdefault("OMP_NUM_THREADS", "1")
