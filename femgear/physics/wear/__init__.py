"""Archard wear of the flanks.

- ``load_sharing``  load per unit length along the contact lines with flank deviations (Winkler layer,
                    or a contact analysis's load map such as the LTCA's moved by the deviation change).
- ``archard``       single-point-observation wear per load cycle, stable update steps,
                    checkpoint/resume of long runs.
"""

from femgear.physics.wear.archard import WearSetup, WearState, run_wear, wear_rates, wear_steps
from femgear.physics.wear.load_sharing import LoadMap, ReferenceLoad, load_map, reference_load_map

__all__ = ["LoadMap", "ReferenceLoad", "WearSetup", "WearState", "load_map", "reference_load_map", "run_wear",
           "wear_rates", "wear_steps"]
