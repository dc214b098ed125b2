"""Loaded tooth contact analysis (LTCA) of a double-helical pair on 3-D FE teeth.

- ``flank``       the loaded flank of a meshed helix as an analytic involute helicoid (points, normals, roll range).
- ``halfspace``   Boussinesq, Love-rectangle and Hertz line-contact formulas (the local contact part).
- ``compliance``  FE bulk flank kernels minus their half-space part, one SA hierarchy, disk cache.
- ``separation``  initial normal separation from ``[modifications]`` and wear/thermal/error fields.
- ``contact``     contact points of a mesh phase, the compliance matrix, the active-set contact solve.
- ``analysis``    one mesh cycle: loaded/unloaded TE, secant/tangent stiffness, loads, pressures; dynamics input.
- ``level``       the ``ltca`` stiffness level (resolved mesh orders, deviated cycles).
- ``flank_map``   the (ρ, ζ) pressure/load map of a cycle on the pinion's flanks.
- ``te``          TE p-p and mesh harmonics, stiffness mean/ripple, load share, peak pressure and edge flag
                  (a frozen ``TEAnalysis``), each helix alone, the Harris map, the tool's input checks.
- ``maps``        pressure and load maps of both members, each turned into its meshing position.
- ``tool``        ``femgear ltca``: the LTCA alone at several torques (a frozen ``LTCAToolResult``).
- ``thermal``     the 3-D thermo-elastic flank deviation ζ_T on the member body (``physics.thermal = "fe3d"``),
                  read at the LTCA's flank points and cached with its disk cache.
"""
