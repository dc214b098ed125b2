"""femgear: finite-element tribo-dynamics of double-helical gear pairs.

Folders follow the data flow of a computation:

- ``scene``      TOML scene files validated into frozen models (SI units).
- ``geometry``   involute/helical gear-pair geometry and kinematics (pure numpy).
- ``contact``    Hertz contact and EHL film-thickness formulas (analytic oracles).
- ``ehl``        finite-element (thermal) elastohydrodynamic lubrication.
- ``body``       gear-body heat conduction, thermo-elasticity, FE tooth compliance.
- ``stiffness``  time-varying mesh stiffness (ISO 6336, potential energy, FE).
- ``dynamics``   gear-rotor dynamics; ``excitation`` its error sources.
- ``wear``       Archard wear; ``coupling`` the bidirectional outer loop.
- ``io``, ``plot``, ``cli``  results files, figures, command line.

Importing femgear has no side effects and does not import gmsh, VTK or matplotlib.
"""

__version__ = "0.1.0"
