"""The EHL core shared by both discretisations: Moes groups (``params``), rheology, node grids
(``grid``), the half-space deflection (``elastic``), the contact domain (``domain``), the solver
history (``history``), the frozen :class:`~femgear.physics.ehl.core.results.EHLResult` and its
assembly (``results``, ``assemble``), Richardson error estimates (``accuracy``) and roughness as a
film term (``surface``)."""
