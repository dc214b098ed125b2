"""Isothermal elastohydrodynamic lubrication (EHL): point/elliptical and line contacts.

Two discretisations on one shared core, which never import each other:

core/  Moes groups <-> Hertzian parameters (``params``), Barus / Roelands viscosity and
       Dowson-Higginson density (``rheology``), nested node grids and transfers (``grid``),
       the DC-FFT half-space deflection and line log-kernel (``elastic``), the point-contact
       domain and its checks (``domain``), the solver ``history``, the frozen
       :class:`~femgear.physics.ehl.core.results.EHLResult` and its assembly (``assemble``), Richardson
       error estimates and flags (``accuracy``), roughness as a film term (``surface``).
fe/    finite elements, Newton–Krylov: Q1/P1 element tables (``stencil``), the stabilised
       Galerkin Reynolds residual and exact Jacobian (``reynolds``), one level (``level``:
       film, cavitation complementarity, dense Jacobian), dense Newton and Newton-Krylov with a
       multilevel preconditioner (``newton``, ``krylov``), the nested point solve with its
       fallbacks (``point``) and the line contact (``line``).
fd/    finite differences, nonlinear multigrid (Venner & Lubrecht 2000): the FD operator with
       the second-order upstream wedge and grid transfers (``operator``), zebra line relaxation
       (``relax``), the coarsest grid's dense semi-smooth Newton (``newton``), outlet-spike
       elimination (``eliminate``), FAS / FMG cycles (``fas``), the point driver (``point``).

Entry points (this folder): :func:`femgear.physics.ehl.point.solve_point` (multigrid inside its
validated range, Newton elsewhere or when the multigrid fails),
:func:`femgear.physics.ehl.fe.line.solve_line`, :mod:`femgear.physics.ehl.dimensional` (SI in,
metres and pascals out), :mod:`femgear.physics.ehl.transient` (roughness moving through the
contact: FE time steps from the steady solve) and :mod:`femgear.physics.ehl.path` (the ``ehl-line``
lubrication level along the path).  Files (VTK fields, the centre-line figure) are written at the edge:
:mod:`femgear.edge.io.ehl`.
"""
