"""Lubrication levels (the ``[physics] lubrication`` key): friction and contact temperature.

The names are the registry; factories are attached where a level is dispatched.
"""

from femgear.levels.registry import Registry

REGISTRY = Registry("lubrication", planned=('ehl-point',))
REGISTRY.add("none", "dry contact: no friction, no flash temperature")
REGISTRY.add("constant", "a constant friction coefficient (friction.coefficient) and Blok's flash temperature")
REGISTRY.add("formula", "an empirical friction formula (friction.model) with the film formulas of Dowson-Higginson/Hamrock-Dowson")
REGISTRY.add("ehl-line", "isothermal line-contact EHL (FE Reynolds, Newton-Krylov) with Eyring traction")
REGISTRY.add("tehl", "thermal line-contact EHL (Reynolds + energy) tabulated in a friction map over the path")
REGISTRY.add("tehl-point", "thermal point-contact EHL (crowned flank, multigrid) along the path")
