"""The bidirectional coupling of dynamics, lubrication, thermal expansion and wear.

- ``profile``  flank deviations along the path → drive/coast deviation tables per helix.
- ``thermal``  thermal unit responses (ζ_T per unit flank and shaft rise) and the bulk temperature.
- ``loop``     the outer loop as a generator of immutable states; :func:`run_coupled`.
"""

from femgear.system.coupling.loop import (
    CoupledResult,
    CouplingHistory,
    CouplingSetup,
    CouplingState,
    coupling_iterations,
    run_coupled,
)

__all__ = ["CoupledResult", "CouplingHistory", "CouplingSetup", "CouplingState", "coupling_iterations", "run_coupled"]
