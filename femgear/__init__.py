"""femgear: finite-element tribo-dynamics of double-helical gear pairs.

The folders show the layers; imports only point down (``tests/architecture``):

- ``physics``  the leaves: ``geometry`` (involute/helical kinematics), ``mesh`` (gmsh),
  ``contact`` (Hertz, film formulas), ``lubrication`` (oil laws, traction), ``ehl`` and
  ``tehl`` (isothermal and thermal EHL), ``body`` (FE heat conduction, thermo-elasticity,
  compliance), ``stiffness`` (mesh stiffness), ``ltca`` (loaded tooth contact),
  ``excitation`` (errors, backlash), ``wear`` (Archard), ``rating`` (ISO 6336).
- ``system``   ``dynamics`` (gear-rotor model) and ``coupling`` (the outer loop).
- ``scene``, ``rexs``  input: TOML scenes and REXS gear data, validated, SI.
- ``case``, ``pipeline``, ``results``  the driver: bind a scene once, run it, typed results.
- ``edge``     ``io`` (files), ``plot`` (figures), ``cli``, ``sweep``.

Importing femgear has no side effects and does not import gmsh, VTK or matplotlib.
"""

__version__ = "0.1.0"
