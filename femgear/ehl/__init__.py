"""Isothermal elastohydrodynamic lubrication (EHL): point/elliptical and line contacts.

Modules
-------
params     Moes groups <-> Hertzian dimensionless parameters (lam_bar, alpha_bar, H scaling).
rheology   Barus / Roelands viscosity, Dowson-Higginson density (dimensionless, with d/dP).
grid       uniform nested node grids, skfem meshes, bilinear prolongation.
elastic    DC-FFT half-space deflection (point), log-kernel matrix (line).
reynolds   Q1/P1 Reynolds residual and Jacobian blocks with artificial diffusion (skfem).
level      one discretisation level: film, complementarity residual, dense Jacobian.
newton     dense Newton (coarse grids, line) and Newton-Krylov with a multilevel
           preconditioner (fine grids); histories; ConvergenceError on failure.
"""
