"""Transient line-contact EHL: moving roughness through the contact.

Hertzian line scaling of :mod:`femgear.physics.ehl.fe.line` with time T = t u_m / b (Venner &
Lubrecht 2000, ch. 11; Venner, Couhier, Lubrecht & Greenwood 1997):

    d/dX(eps dP/dX) - d(rho H)/dX - d(rho H)/dT = 0,
    H(X, T) = H0(T) + X^2/2 + D[P](X) - R(X - c T),   int P dX = pi/2 at every T,

where the roughness R is carried by a surface of speed u_s = c u_m (c = 1 +/- SRR/2,
:func:`femgear.physics.ehl.core.surface.surface_speed`): c = 1 is pure rolling, c = 0 a roughness
on a surface at rest (steady). Each time level is the steady problem of
:class:`femgear.physics.ehl.fe.level.Level` plus the squeeze term, solved by the same semi-smooth
Newton (cavitation as complementarity, Reynolds cavitation condition at each T).

Time discretisation: second-order backward differences (BDF2),

    d(rho H)/dT ~ [3 (rho H)^(n+1) - 4 (rho H)^n + (rho H)^(n-1)] / (2 dT),

started by one implicit-Euler step. Why BDF2: in the Hertzian zone eps -> 0 and the
equation is pure transport of rho H at unit speed, so the scheme's own damping of the
film pattern is the error that matters for the amplitude reduction. Implicit Euler
damps a wave of kX = 0.2 per step by (1 + 0.04)^(-1/2) (a 2 % loss per cell: the
pattern is gone after a contact width); BDF2 loses (k dT)^4 / 4 per step (~4e-4
here) and is A-stable; Crank-Nicolson has no damping but needs the old Reynolds
residual, which in the cavitated zone is the complementarity multiplier (not a flux),
and rings at the abrupt entry of a feature. The squeeze term is discretised with the
consistent P1 mass matrix (Galerkin; fourth-order phase accuracy for the transport).
The step is dT = h / |c| by default: the roughness moves exactly one cell per step,
so its nodal values are exact shifts. Streamline diffusion is off (``sd_factor`` = 0):
its steady weight h/2 dQ/dX would, in a transient, diffuse the moving film pattern at
O(h); the isotropic artificial diffusion of P (O(h^2)) is kept. The start is the
converged steady smooth solution on the same grid and discretisation, so a zero
roughness stays at rest to the Newton tolerance (tested).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

from femgear.errors import ArgumentError, ConvergenceError
from femgear.physics.contact.film import moes_line_central
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.domain import default_domain
from femgear.physics.ehl.core.grid import Grid
from femgear.physics.ehl.core.rheology import Rheology
from femgear.physics.ehl.core.surface import apply_surface
from femgear.physics.ehl.fe.level import Level
from femgear.physics.ehl.fe.line import X0_DEFAULT, line_level, solve_line
from femgear.physics.ehl.fe.newton import newton_dense, newton_krylov
from femgear.physics.ehl.fe.reynolds import Linearization
from femgear.physics.ehl.point import solve_point

NEWTON_TOL = 1e-9
STEP_RESIDUAL_TOL = 1e-9


class _SqueezeReynolds:
    """A :class:`femgear.physics.ehl.fe.reynolds.ReynoldsFE` plus the discrete squeeze term
    Mc (a rho H + q_old), Mc the consistent mass matrix (int phi_i phi_j): ``a`` is the
    coefficient of the new level (1/dT Euler, 3/(2 dT) BDF2), ``q_old`` the old levels'
    part (nodal). Everything else is delegated."""

    def __init__(self, base):
        self.base = base
        e = base.basis
        self.Mc = e.matrix(np.broadcast_to(e.products(e.phi, e.phi), (e.ne, e.npe, e.npe)))
        self.a, self.q_old = 0.0, np.zeros(e.n)

    def __getattr__(self, name):
        return getattr(self.base, name)

    def _squeeze(self, P, H):
        rho, drho = self.base.rheology.density(P)
        return self.Mc @ (self.a * rho * H + self.q_old), rho, drho

    def residual(self, P, H):
        return self.base.residual(P, H) + self._squeeze(P, H)[0]

    def linearize(self, P, H) -> Linearization:
        lin = self.base.linearize(P, H)
        S, rho, drho = self._squeeze(P, H)
        JP = (lin.JP + self.Mc @ sp.diags(self.a * drho * H)).tocsr()
        JH = (lin.JH + self.Mc @ sp.diags(self.a * rho)).tocsr()
        return Linearization(lin.R + S, JP, JH, lin.eps_node_scale)


@dataclass(frozen=True)
class TransientLineResult:
    """Time history of a transient line (or point) solve (Hertzian units; Moes films via ``fac``).

    Per step n (``T[n]``, n = 0 the steady start): ``H_centre`` H(X=0), ``H0``,
    ``Hmin``, ``Pmax``, ``newton`` iterations. ``snapshots``: {step: (P, H)} for the
    requested steps. ``x`` nodes, ``dT``, ``speed`` c, ``scheme``; ``flags``: those of the
    steady start (its error estimate against its tolerance, a truncated inlet).
    Cavitation is the Reynolds condition at every T (not mass-conserving): a feature
    leaving through the outlet is followed only qualitatively there."""

    M: float
    L: float
    x: np.ndarray = field(repr=False)
    T: np.ndarray = field(repr=False)
    H_centre: np.ndarray = field(repr=False)
    H0: np.ndarray = field(repr=False)
    Hmin: np.ndarray = field(repr=False)
    Pmax: np.ndarray = field(repr=False)
    newton: np.ndarray = field(repr=False)
    snapshots: dict = field(repr=False, default_factory=dict)
    dT: float = 0.0
    speed: float = 1.0
    scheme: str = "bdf2"
    fac: float = 1.0
    seconds: float = 0.0
    steady_Hc: float = 0.0
    flags: tuple[str, ...] = ()

    def amplitude(self, T_from: float) -> float:
        """Half the peak-to-peak of H(X=0, T) for T >= ``T_from`` (Venner et al. 1997's
        deformed amplitude A_d, Hertzian units)."""
        w = self.T >= T_from
        if w.sum() < 3:
            raise ArgumentError("T_from", f"fewer than 3 steps after T = {T_from:g}")
        return 0.5 * float(self.H_centre[w].max() - self.H_centre[w].min())


def solve_line_transient(M: float, L: float, feature: Callable, *, speed: float = 1.0,
                         T_end: float, level: int = 5, dT: float | None = None,
                         scheme: str = "bdf2", x0: float = X0_DEFAULT, x1: float = 1.5,
                         ad_factor: float = 1.0, rheology: dict | None = None,
                         snapshots: tuple[int, ...] = (), max_iter: int = 30,
                         reuse: bool = True) -> TransientLineResult:
    """Moving roughness R(X - c T) = ``feature``(X - c T) through a line contact (Moes
    (M, L)), from the steady smooth solution at T = 0 to ``T_end`` (Hertzian units;
    ``feature`` takes the surface coordinate at T = 0 and must vanish wherever the
    roughness has not yet entered, or the start is not smooth). ``speed`` c = u_s/u_m
    (:func:`femgear.physics.ehl.core.surface.surface_speed`); ``dT`` default h/|c| (h at c = 0);
    ``scheme`` 'bdf2' (default) or 'euler'. Raises ConvergenceError (with the step and
    its Newton history) when a time step does not converge; no NaN is returned."""
    _check(scheme, T_end)
    t0 = time.perf_counter()
    rheology = dict(rheology or {})
    steady = solve_line(M, L, level=level, x0=x0, x1=x1, ad_factor=ad_factor, sd_factor=0.0,
                        **rheology)
    lv = line_level(M, L, np.linspace(x0, x1, 16 * 2**level + 1), rheology=rheology,
                    ad_factor=ad_factor, sd_factor=0.0)
    reuse_d: dict | None = {} if reuse else None

    def step(PI, H0, case):
        PI, H0, hist = newton_dense(lv, PI, H0, max_iter=max_iter, tol=NEWTON_TOL, case=case,
                                    residual_tol=STEP_RESIDUAL_TOL, reuse=reuse_d)
        return PI, H0, len(hist.residual)

    rec = _march([lv], step, lambda X, Y: feature(X), steady.P.ravel()[lv.interior], steady.H0,
                 speed=speed, T_end=T_end, dT=dT, scheme=scheme, snapshots=snapshots,
                 case=f"ehl line transient M={M:g} L={L:g}")
    return rec.result(M, L, rec.dT, speed, scheme, time.perf_counter() - t0, steady,
                      pr.line_h_moes_factor(M))


def solve_point_transient(M: float, L: float, feature: Callable, *, speed: float = 1.0,
                          T_end: float, level: int = 3, coarse_level: int = 1,
                          dT: float | None = None, scheme: str = "bdf2", ratio: float = 1.0,
                          ad_factor: float = 1.0, snapshots: tuple[int, ...] = (),
                          max_iter: int = 20) -> TransientLineResult:
    """Point-contact version of :func:`solve_line_transient` (Barus, incompressible):
    ``feature``(X - c T, Y) moves along X through the contact; each step is Newton-Krylov
    on level ``level`` with the multilevel preconditioner of :mod:`femgear.physics.ehl.fe.newton`,
    its coarse factorisations kept across the steps (every level carries the squeeze
    term and the surface, so the preconditioner sees the transient Jacobian). Returns the
    same record (``x`` the flattened node X; snapshots flattened (ny nx))."""
    _check(scheme, T_end)
    t0 = time.perf_counter()
    steady = solve_point(M, L, level=level, coarse_level=coarse_level, ratio=ratio,
                         ad_factor=ad_factor, sd_factor=0.0)
    dom = default_domain(ratio)
    levels = [Level(Rheology(pr.point_alpha_bar(M, L)), pr.point_lam_bar(M), pr.POINT_LOAD,
                    grid=Grid.build(dom, k), ratio=ratio, ad_factor=ad_factor, sd_factor=0.0)
              for k in range(coarse_level, level + 1)]
    factorised: dict = {}

    def step(PI, H0, case):
        PI, H0, hist = newton_krylov(levels, PI, H0, max_iter=max_iter, tol=NEWTON_TOL, case=case,
                                     residual_tol=STEP_RESIDUAL_TOL, reuse=factorised)
        return PI, H0, len(hist.residual)

    rec = _march(levels, step, feature, steady.P.ravel()[levels[-1].interior], steady.H0,
                 speed=speed, T_end=T_end, dT=dT, scheme=scheme, snapshots=snapshots,
                 case=f"ehl point transient M={M:g} L={L:g}")
    return rec.result(M, L, rec.dT, speed, scheme, time.perf_counter() - t0, steady,
                      pr.point_h_moes_factor(M))


def _check(scheme: str, T_end: float) -> None:
    if scheme not in ("bdf2", "euler"):
        raise ArgumentError("scheme", f"must be 'bdf2' or 'euler', got {scheme!r}")
    if not (T_end > 0 and np.isfinite(T_end)):
        raise ArgumentError("T_end", f"must be > 0, got {T_end!r}")


def _march(levels: list, step: Callable, feature: Callable, PI, H0, *, speed: float, T_end: float,
           dT: float | None, scheme: str, snapshots, case: str) -> _Recorder:
    """Time loop shared by the line and point solvers: at each step the surface at its new
    position on every level, the BDF2 (first step: Euler) squeeze coefficients on every
    level (old levels on the finest only: the coarser ones serve the preconditioner), and
    ``step``(PI, H0, case) -> (PI, H0, Newton iterations) unless nothing moved."""
    fine = levels[-1]
    dT = (fine.h / abs(speed) if speed != 0 else fine.h) if dT is None else dT
    if not (dT > 0 and np.isfinite(dT)):
        raise ArgumentError("dT", f"must be > 0, got {dT!r}")
    for lv in levels:
        lv.reynolds = _SqueezeReynolds(lv.reynolds)
    smooth = [lv.geometry.copy() for lv in levels]
    rec = _Recorder(fine, PI, H0, snapshots, dT)
    Q_prev = Q_old = rec.Q
    for n in range(1, int(np.ceil(T_end / dT - 1e-9)) + 1):
        T = n * dT
        bdf2 = scheme == "bdf2" and n > 1
        for lv, G in zip(levels, smooth):
            apply_surface(lv, feature(lv.X - speed * T, lv.Y), smooth=G)
            lv.reynolds.a = (1.5 if bdf2 else 1.0) / dT
        fine.reynolds.q_old = (-2.0 * Q_old + 0.5 * Q_prev) / dT if bdf2 else -Q_old / dT
        its = 0
        if not _at_rest(fine, PI, H0):
            PI, H0, its = step(PI, H0, f"{case} step {n} (T={T:.4g})")
        Q_prev, Q_old = Q_old, rec.add(n, T, PI, H0, its)
    return rec


def _at_rest(lv, PI, H0) -> bool:
    """The previous state already solves this step (Newton's scaled residual below
    :data:`STEP_RESIDUAL_TOL`, load balanced): nothing moved."""
    F, *_ = lv.evaluate(PI, H0)
    scale = np.ones_like(F)
    scale[-1] = 1.0 / lv.load
    return bool(np.linalg.norm(scale * F) < STEP_RESIDUAL_TOL and abs(F[-1]) / lv.load < 1e-6)


class _Recorder:
    """Per-step scalars and snapshots of a transient solve."""

    def __init__(self, lv, PI, H0, snapshots, dT: float):
        self.lv, self.want, self.dT = lv, set(snapshots), dT
        self.i0 = int(np.argmin(lv.X**2 + lv.Y**2))
        self.rows: list[tuple] = []
        self.snaps: dict = {}
        self.Q = self.add(0, 0.0, PI, H0, 0)

    def add(self, n, T, PI, H0, its) -> np.ndarray:
        P, H = self.lv.film(PI, H0)
        if not (np.all(np.isfinite(P)) and np.all(np.isfinite(H))):
            raise ConvergenceError("ehl line transient", f"non-finite state at step {n}")
        self.rows.append((T, H[self.i0], H0, H.min(), P.max(), its))
        if n in self.want:
            self.snaps[n] = (P.copy(), H.copy())
        return self.lv.reynolds.rheology.density(P)[0] * H

    def result(self, M, L, dT, speed, scheme, seconds, steady, fac: float) -> TransientLineResult:
        a = np.array(self.rows)
        return TransientLineResult(M=float(M), L=float(L), x=self.lv.X.copy(), T=a[:, 0],
                                   H_centre=a[:, 1], H0=a[:, 2], Hmin=a[:, 3], Pmax=a[:, 4],
                                   newton=a[:, 5].astype(int), snapshots=self.snaps, dT=float(dT),
                                   speed=float(speed), scheme=scheme, fac=fac,
                                   seconds=seconds, steady_Hc=float(steady.Hc_hertz),
                                   flags=tuple(steady.flags))


def nabla_line(wavelength: float, M: float, L: float) -> float:
    """Venner, Couhier, Lubrecht & Greenwood (1997, Tribology Series 32:103) reduced
    wavelength of a line contact: nabla = (lambda/b) M^(3/4) / L^(1/2) (Moes line groups;
    ``wavelength`` in units of b)."""
    return wavelength * M**0.75 / L**0.5


def wavelength_for(nabla: float, M: float, L: float) -> float:
    """lambda/b for a given nabla (inverse of :func:`nabla_line`)."""
    return nabla * L**0.5 / M**0.75


def amplitude_reduction_fit(nabla):
    """A_d/A_i = 1 / (1 + 0.15 nabla + 0.015 nabla^2): the pure-rolling amplitude
    reduction curve of transverse harmonic waviness as quoted from Venner & Lubrecht
    (Lubrecht & Venner 1999, Proc. IMechE J 213:397; Venner & Lubrecht 2000, J. Tribol.
    122:...). The form and coefficients are recalled (the stored sources give only the
    abstracts: A_d/A_i = F(nabla) for all (M, L), ~1 for lambda/b < 1, -> 0 for long
    waves); the scatter of the published points about it is of order 0.05."""
    nabla = np.asarray(nabla, dtype=float)
    return 1.0 / (1.0 + 0.15 * nabla + 0.015 * nabla**2)


def steady_hc_hertz(M: float, L: float) -> float:
    """Moes (1992) central film of the line contact in Hertzian units (a scale for
    amplitudes)."""
    return float(moes_line_central(M, L)) / pr.line_h_moes_factor(M)


def entering_waviness(amplitude: float, wavelength: float, *, front: float = X0_DEFAULT,
                      ramp: float = 0.5) -> Callable:
    """Surface-coordinate profile of harmonic waviness A cos(2 pi (xi - front)/lambda)
    upstream of ``front`` (the inlet boundary at T = 0), switched on over ``ramp`` by a
    raised cosine: zero downstream of the front, so the start is the smooth solution and
    the waviness enters through the inlet (Venner et al. 1997's set-up)."""
    if not (wavelength > 0 and ramp > 0):
        raise ArgumentError("wavelength", "wavelength and ramp must be > 0")

    def feature(xi):
        s = np.clip((front - np.asarray(xi, dtype=float)) / ramp, 0.0, 1.0)
        return amplitude * (0.5 - 0.5 * np.cos(np.pi * s)) * np.cos(2 * np.pi * (xi - front) / wavelength)

    return feature


def measure_amplitude_reduction(M: float, L: float, nabla: float, *, amplitude: float = 0.1,
                                speed: float = 1.0, level: int = 5, x0: float = X0_DEFAULT,
                                x1: float = 1.5, periods: float = 1.0) -> float:
    """A_d/A_i of transverse waviness of reduced wavelength ``nabla`` (:func:`nabla_line`)
    and amplitude ``amplitude`` x the smooth central film, carried at ``speed`` c through
    the line contact (M, L): A_d from the film at X = 0 over the last ``periods``
    wavelengths, which start once the front (and its ramp) has left the domain."""
    lam = wavelength_for(nabla, M, L)
    A = amplitude * steady_hc_hertz(M, L)
    ramp = 0.5
    T_front = (x1 - x0 + ramp) / speed
    T_end = T_front + periods * lam / speed
    r = solve_line_transient(M, L, entering_waviness(A, lam, front=x0, ramp=ramp), speed=speed,
                             T_end=T_end, level=level, x0=x0, x1=x1)
    return r.amplitude(T_end - periods * lam / speed - 1e-9) / A
