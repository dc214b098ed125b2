"""The gearbox housing: from the bearing seats to the sensors and the air (docs/models/housing.md).

- ``reduction``  Craig–Bampton reduction onto boundary DOFs and fixed-interface modes (dense or sparse).
- ``fe``         the FE housing on a :mod:`femgear.physics.mesh.housing` mesh: quadratic tetrahedra, rigid bearing
                 seats, clamped feet; reduced at the seats with its sensor, surface and vertex maps.
- ``frf``        FRF sets from the seats to sensors (receptance inside; mobility, accelerance converted), the
                 few-parameter path model of a gain and one mode.
- ``fbs``        Lagrange-multiplier frequency-based substructuring (LM-FBS).
- ``acoustics``  equivalent radiated power and the ISO/TS 7849 arithmetic, A-weighting (IEC 61672-1).
"""
