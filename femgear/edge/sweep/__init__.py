"""Parameter sweeps: many load cases of one base scene, locally or on a Dask cluster.

- ``spec``    sweep files (base scene, grid and list of overrides, outputs), stable case ids.
- ``check``   every case's scene checked before any case runs; the workers of a cluster checked.
- ``runner``  resumable execution with atomic per-case outputs.
- ``table``   ``results.csv``: a column per swept key, rows in numeric order.
- ``figure``  ``summary.png``: the chosen outputs against the swept keys.
"""

from femgear.edge.sweep.check import check_cases
from femgear.edge.sweep.runner import SweepInterrupted, SweepResult, run_sweep, run_sweep_case
from femgear.edge.sweep.spec import Case, SweepSpec, parse_sweep

__all__ = ["Case", "SweepInterrupted", "SweepResult", "SweepSpec", "check_cases", "parse_sweep", "run_sweep_case",
           "run_sweep"]
