"""The oil at the temperature the contact sees, bound once per run.

A scene gives its oil's data at ``oil.reference_temperature`` (default the supply temperature
``operating.ambient_temperature``).  :func:`oil_at` carries the table to another temperature by the
oil's own laws (:meth:`femgear.physics.lubrication.oil.OilLaw.at`: Roelands viscosity with its
pressure index z0 and temperature index S0, the density law): viscosity η0, pressure–viscosity α,
temperature–viscosity β_T, density ρ0 and its expansion coefficient at the new temperature, which
becomes the table's ``reference_temperature``.  :func:`femgear.case.build_case` binds the oil at the
supply temperature, so every reader of ``case.oil`` (the contact pass's films, the Moes numbers, the
lubrication levels, the ratings' film, the power loss) sees the same, right values.
"""

from __future__ import annotations

from femgear.physics.lubrication.oil import OilLaw
from femgear.scene.schema import Oil


def oil_at(oil: Oil, reference_temperature: float, temperature: float) -> Oil:
    """The ``[oil]`` table ``oil`` (data at ``reference_temperature`` [K]) re-based at ``temperature`` [K]."""
    law = OilLaw.from_table_at(oil, reference_temperature, temperature)
    return oil.model_copy(update={"viscosity": law.eta0, "pressure_viscosity": law.alpha,
                                  "temperature_viscosity": law.beta_t, "density": law.rho0,
                                  "thermal_expansion": law.expansion, "reference_temperature": law.T0})
