"""Excitation of the gear-rotor model: transmission-error sources and the backlash gap.

- ``errors``   eccentricity (rotating with each member), profile-error harmonics of the
               mesh frequency, a seeded random tooth-to-tooth component, unbalance
               forces; each as value and time derivative, vectorised over time.
- ``backlash`` the dead-zone gap function of the dynamic backlash b(t).
"""

from femgear.physics.excitation.backlash import contact_indicator, gap_function
from femgear.physics.excitation.errors import CumulativePitchError, Eccentricity, ProfileError, RandomError, Unbalance

__all__ = [
    "CumulativePitchError", "Eccentricity", "ProfileError", "RandomError", "Unbalance", "contact_indicator", "gap_function",
]
