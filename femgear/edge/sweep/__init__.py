"""Parameter sweeps: many load cases of one base scene, locally or on a Dask cluster.

- ``spec``    sweep files (base scene, grid and list of overrides), stable case ids.
- ``runner``  resumable execution with atomic per-case outputs and a results table.
"""

from femgear.edge.sweep.runner import SweepInterrupted, SweepResult, run_sweep, run_sweep_case
from femgear.edge.sweep.spec import Case, SweepSpec, parse_sweep

__all__ = ["Case", "SweepInterrupted", "SweepResult", "SweepSpec", "parse_sweep", "run_sweep", "run_sweep_case"]
