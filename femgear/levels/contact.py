"""The quasi-static contact pass of a case: Hertz and films along the path with the load sharing of
the stiffness level's pair stiffness k'(u).

Not a sub-model with levels of its own: every run makes this pass (:func:`contact_pass`); it reads
the ``stiffness`` level to share the load (:func:`pair_stiffness_curve`), so it lives here, between
the Case and :func:`femgear.physics.contact.path.contact_along_path`.
"""

from __future__ import annotations

import numpy as np

from femgear.case import Case
from femgear.physics.contact.hertz import reduced_modulus
from femgear.physics.contact.path import ContactPath, contact_along_path
from femgear.physics.contact.sharing import StiffnessPerWidth
from femgear.physics.geometry import kinematics, path_positions
from femgear.physics.stiffness.pem import pair_stiffness_per_width
from femgear.physics.stiffness.tvms import tabulated


def pair_stiffness_curve(case: Case, stiffness=None) -> StiffnessPerWidth | None:
    """k'(u) of the case's mesh-stiffness level for load sharing (None: uniform).

    ``constant`` and ``iso6336`` are uniform along the path (their catalogue spec's ``uniform_along_path``).  ``pem`` is evaluated here;
    ``fe`` uses the FE curve of a given :class:`femgear.physics.stiffness.MeshStiffness` and falls
    back to PEM without one (the FE tooth solves are not repeated for the static pass).
    """
    if case.levels.spec("stiffness").uniform_along_path:
        return None
    pair = case.pair
    if getattr(stiffness, "k_pair_per_width", None) is not None:
        return tabulated(pair, stiffness.u, stiffness.k_pair_per_width)
    u = np.linspace(pair.u_start, pair.u_end, 81)
    m = case.material
    k = pair_stiffness_per_width(pair, u, m.youngs_modulus, m.poisson_ratio, case.bore_radii)
    return tabulated(pair, u, k)


def reduced_modulus_of(case: Case) -> float:
    """E' of the case's material (both members of one steel) [Pa]."""
    return reduced_modulus(case.material.youngs_modulus, case.material.poisson_ratio)


def contact_pass(case: Case, u: np.ndarray | None = None, stiffness=None, *, n: int | None = None,
                 shared: bool = True) -> ContactPath:
    """Hertz pressure, films and velocities at the case's path positions, or at ``u`` [m], or at ``n``
    positions from A to E plus the pitch point.

    ``stiffness`` (a :class:`MeshStiffness` of the case's level) supplies k'(u) for the load sharing
    instead of recomputing it; ``shared=False`` shares the load uniformly (for callers that read only the
    path's mean load per length, which the sharing does not change).
    """
    if n is not None:
        u = np.unique(np.append(path_positions(case.pair, n), case.pair.u_pitch))
    kin = case.path if u is None else kinematics(case.pair, np.asarray(u, float), case.operating.pinion_speed)
    curve = pair_stiffness_curve(case, stiffness) if shared else None
    return contact_along_path(case.pair, kin, case.operating.normal_force, reduced_modulus_of(case),
                              case.oil.viscosity, case.oil.pressure_viscosity, curve)
