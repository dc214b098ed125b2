"""The bidirectional coupling of dynamics, lubrication, thermal expansion and wear.

- ``profile``  flank deviations along the path → drive/coast deviation tables per helix.
- ``thermal``  thermal unit responses (ζ_T per unit flank and shaft rise) and the bulk temperature.
- ``setup``    what stays fixed over the passes (:class:`CouplingSetup`, built once) and the LTCA reference loads.
- ``state``    the immutable records: one :class:`CouplingState` per pass, the history and the result.
- ``passes``   the pure functions of one pass (reference loads, contact response, thermal growth, wear, dynamics).
- ``loop``     the outer loop as a generator of states and its policy, :func:`run_coupled`.
"""

from femgear.system.coupling.loop import coupling_iterations, run_coupled
from femgear.system.coupling.setup import CouplingSetup
from femgear.system.coupling.state import CoupledResult, CouplingHistory, CouplingState

__all__ = ["CoupledResult", "CouplingHistory", "CouplingSetup", "CouplingState", "coupling_iterations", "run_coupled"]
