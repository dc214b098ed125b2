"""Archard wear of the flanks.

- ``load_sharing``  load per unit length along the contact lines with flank deviations (Winkler layer,
                    or a contact analysis's load map such as the LTCA's moved by the deviation change).
- ``archard``       single-point-observation wear per load cycle, stable update steps,
                    checkpoint/resume of long runs.
- ``regime``        the asperity-borne share of the load (JGP split, tabulated): wear that knows the film.
"""

from femgear.physics.wear.archard import WearSetup, WearState, run_wear, wear_rates, wear_steps
from femgear.physics.wear.load_sharing import LoadMap, ReferenceLoad, load_map, reference_load_map
from femgear.physics.wear.regime import AsperityShare, Regime, regime

__all__ = ["AsperityShare", "LoadMap", "ReferenceLoad", "Regime", "WearSetup", "WearState", "load_map",
           "reference_load_map", "regime", "run_wear", "wear_rates", "wear_steps"]
