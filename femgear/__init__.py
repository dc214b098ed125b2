"""femgear: finite-element tribo-dynamics of double-helical gear pairs.

The folders show the layers, low to high; imports only point down (``tests/architecture``, ARCHITECTURE.md):

- ``physics``  the leaves: ``geometry`` (involute/helical kinematics), ``mesh`` (gmsh),
  ``contact`` (Hertz, film formulas), ``lubrication`` (oil laws, traction), ``ehl`` and
  ``tehl`` (isothermal and thermal EHL), ``body`` (FE heat conduction, thermo-elasticity,
  compliance), ``stiffness`` (mesh stiffness), ``ltca`` (loaded tooth contact),
  ``excitation`` (errors, backlash), ``wear`` (Archard), ``rating`` (ISO 6336).
- ``levels``   one registry per sub-model: the level names and their factories (the only dispatch on a name).
- ``scene``, ``rexs``  input: TOML scenes and REXS gear data, validated, SI.
- ``case``     the Case: the scene bound once per run (pair, operating point, path, typed tables).
- ``system``   ``dynamics`` (gear-rotor model) and ``coupling`` (the outer loop).
- ``pipeline``, ``results``, ``rate``, ``summary``  the driver: run a case (pure), typed results.
- ``edge``     ``io`` (files), ``plot`` (figures), ``run`` (bind + run + write), ``cli``, ``sweep``.

Importing femgear has no side effects and does not import gmsh, VTK or matplotlib.
"""

__version__ = "0.1.0"
