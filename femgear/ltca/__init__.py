"""Loaded tooth contact analysis (LTCA) of a double-helical pair on 3-D FE teeth.

- ``flank``       the loaded flank of a meshed helix as an analytic involute helicoid (points, normals, roll range).
- ``halfspace``   Boussinesq, Love-rectangle and Hertz line-contact formulas (the local contact part).
- ``compliance``  FE bulk flank kernels minus their half-space part, one SA hierarchy, disk cache.
- ``separation``  initial normal separation from ``[modifications]`` and wear/thermal/error fields.
- ``contact``     contact points of a mesh phase, the compliance matrix, the active-set contact solve.
- ``analysis``    one mesh cycle: loaded/unloaded TE, secant/tangent stiffness, loads, pressures; dynamics input.
"""
