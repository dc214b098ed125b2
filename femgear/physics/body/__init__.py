"""The gear body as an elastic, heat-conducting solid (scikit-fem + pyamg).

- ``forms``       weak forms: conduction, plane elasticity, thermal load, traction, roller penalty.
- ``elastic``     :class:`ElasticProblem`: K assembled once, SA hierarchy with rigid-body modes built once.
- ``thermal``     steady conduction, thermo-elastic expansion, flank deviation ζ_T (analytic / FE levels).
- ``compliance``  FE tooth compliance along the path of contact (the ``fe`` stiffness level).
- ``fields``      a section's temperature, displacement and von Mises stress as plain arrays (written by ``edge/io``).
"""
