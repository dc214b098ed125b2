"""Isothermal elastohydrodynamic lubrication (EHL): point/elliptical and line contacts.

Entry points: :func:`femgear.physics.ehl.point.solve_point`, :func:`femgear.physics.ehl.line.solve_line`
(Moes groups in, :class:`femgear.physics.ehl.results.EHLResult` out) and
:mod:`femgear.physics.ehl.dimensional` (SI in, metres and pascals out).

Modules
-------
params       Moes groups <-> Hertzian dimensionless parameters (lam_bar, alpha_bar, H scaling).
rheology     Barus / Roelands viscosity, Dowson-Higginson density (dimensionless, with d/dP).
grid         uniform nested node grids, bilinear prolongation.
elastic      DC-FFT half-space deflection (point), log-kernel matrix (line).
stencil      Q1/P1 element tables on the uniform grid; assembly by array arithmetic.
reynolds     Q1/P1 Reynolds residual and Jacobian blocks with artificial diffusion and
             streamline diffusion, both differentiated exactly.
level        one discretisation level: film, complementarity (cavitation) residual, dense Jacobian.
newton       dense Newton (coarse grids, line) and Newton-Krylov with a multilevel
             preconditioner (fine grids); histories; ConvergenceError on failure.
point, line  drivers: nested iteration, continuation strategies, result assembly.
fd           finite-difference point operator (second-order upstream wedge) and grid transfers.
relax        zebra line relaxation, Gauss-Seidel / distributive (Venner & Lubrecht 2000).
fdnewton     dense semi-smooth Newton of one FD grid (the multigrid's coarsest-grid solver).
fas          FAS cycles and full multigrid; fas_point: the point driver (method='fas').
surface      roughness as a film term: the paper's single peak, waviness, seeded random surfaces.
transient    transient Reynolds (squeeze term, BDF2) for roughness moving through a contact.
assemble     EHLResult from solved fields (shared by the Newton and multigrid drivers).
results      frozen EHLResult (with error_estimate, tol, flags) and centre-line quantities.
accuracy     Richardson error estimates from the nested levels, flags, inlet adequacy.
dimensional  SI entry for point and line contacts.
"""
