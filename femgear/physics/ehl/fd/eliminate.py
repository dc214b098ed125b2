"""Nonlinear elimination of the outlet pressure spike on one FD multigrid level.

Cai & Li (2011, SIAM J. Sci. Comput. 33:746, "Inexact Newton methods with restricted
additive Schwarz based nonlinear elimination"): where a global (here: multigrid)
iteration fails because its linear model does not hold on a small set S of unknowns,
those unknowns are eliminated by solving the local nonlinear problem

    F_S(P_S; P_rest, H0) = 0     (P_rest, H0 fixed)

exactly, by Newton's method, before the global iteration goes on. For the strongly
piezoviscous point contact S is the crescent of the outlet spike, the nodes within
``radius`` of a face across which ln eps jumps by more than 2 (:func:`fas._steep`), where
P falls from ~4 to ~0.1 within one cell on 257^2 and both the line relaxation (capped per
sweep) and the coarse-grid correction (the coarser grid cannot carry the spike) fail.

The local equations are the NCP form of the FD Reynolds equation of :mod:`fd`,
F_i = min(P_i, c_i (f_i - L_i)), i in S, with c_i = 1 / |dL_i/dP_i| (the diagonal of
the local Jacobian, elastic part included) frozen at the start. The local Jacobian is
exact: the sparse stencil derivatives of :func:`femgear.physics.ehl.fd.newton.jacobian_blocks` (rows S,
columns S) plus dL_S/dH times the dense S-block of the influence matrix (the deflection
at every node of the stencils of S caused by a unit P at each node of S); semi-smooth
Newton with backtracking on |F_S|, P projected onto P >= 0 and a positive film (as the
coarsest-grid solver :class:`femgear.physics.ehl.fd.newton.CoarseNewton`). The film of a trial is computed on
the whole grid (DC-FFT), so the local solve sees the exact deflection.

Measured at (20, 20), alpha_bar 19.8, on 257^2 (2100 nodes in S for radius 6): the
local Newton converges from |F_S| ~ 0.3 to 1e-12 in 4-8 full steps, where the Newton
direction of the global FE solver had to be damped to 0.003-0.1.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla

from femgear.physics.ehl.fd.newton import jacobian_blocks
from femgear.physics.ehl.fd.operator import FDLevel

# chord steps are kept while each reduces |F_S| by this factor; a slower one refactorises
# (measured at (20, 20) on 257^2 from the interpolated 129^2 solution: chord steps at a
# rate of 0.27 took 20 steps to 5e-10)
CHORD_RATE = 0.2


class SpikeElimination:
    """Exact local solve on the interior nodes ``mask`` ((ny-2, nx-2) bool) of ``lv``."""

    def __init__(self, lv: FDLevel, mask: np.ndarray, max_iter: int = 30, tol: float = 1e-9):
        self.lv, self.max_iter, self.tol = lv, max_iter, tol
        self.jj, self.ii = np.nonzero(mask)
        self.rows = self.jj * (lv.nx - 2) + self.ii  # interior flat index
        self.full = (self.jj + 1) * lv.nx + self.ii + 1  # full-grid flat index
        self.mask = mask
        self._nb, self._K, self._c, self._chord = None, None, None, None

    def jacobian(self, P: np.ndarray, H: np.ndarray) -> np.ndarray:
        """dL_S / dP_S at (P, H), the elastic part through the dense kernel block."""
        JP, JH = jacobian_blocks(self.lv, P, H)
        JHs = JH[self.rows].tocsc()
        nb = np.nonzero(np.diff(JHs.indptr))[0]  # the nodes whose film enters L_S
        if self._nb is None or not np.array_equal(self._nb, nb):
            self._nb, self._K = nb, self.lv.defl.dense(nb, self.full)
        return JP[self.rows][:, self.full].toarray() + JHs[:, nb] @ self._K

    def merit(self, P: np.ndarray, H0: float, f: np.ndarray, c: np.ndarray):
        """F_S, the film and the active (cavitated) set of S."""
        r, H, _, _ = self.lv.residual(P, H0, f)
        Ps = P[self.jj + 1, self.ii + 1]
        cr = c * r[self.jj, self.ii]
        return np.minimum(Ps, cr), H, Ps <= cr

    def solve(self, P: np.ndarray, H0: float, f: np.ndarray) -> list[float]:
        """P_S in place (P elsewhere and H0 fixed); returns the history of |F_S|. Stops at
        ``tol``, after ``max_iter`` steps, or when the line search finds no decrease (the
        best iterate is kept: inside a cycle the elimination is one part of the
        iteration, whose own convergence test decides). Chord steps: the factors of the
        last Jacobian are kept while the active set stays and each step reduces |F_S| by
        CHORD_RATE or more (a dense factorisation of the ~1000-3000 free nodes costs
        0.3-0.8 s, a chord step a few ms); a later ``solve`` on the same set (the next
        cycle's) starts from them, with the row scaling of the first."""
        if self.rows.size == 0:
            return [0.0]
        H, J0 = self.lv.film(P, H0), None
        if self._c is None:
            J0 = self.jacobian(P, H)
            self._c = 1.0 / np.maximum(np.abs(np.diag(J0)), 1e-12)
        c, chord = self._c, self._chord
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            F, H, act = self.merit(P, H0, f, c)
            hist = [float(np.linalg.norm(F))]
            for _ in range(self.max_iter):
                if hist[-1] < self.tol:
                    break
                try:
                    if chord is None or not np.array_equal(chord[0], act):
                        chord, J0 = (act, *self._factor(P, H, c, act, J0)), None
                    d = self._direction(F, *chord)
                except (sla.LinAlgError, ValueError):
                    break
                trial = self._search(P, H0, f, c, d, hist[-1])
                if trial is None:
                    if chord[-1]:  # a stale chord: once more with a fresh Jacobian
                        chord = None
                        continue
                    break
                P[...], (F, H, act) = trial[0], trial[1:]
                hist.append(float(np.linalg.norm(F)))
                chord = chord[:-1] + (True,) if hist[-1] <= CHORD_RATE * hist[-2] else None
        self._chord = None if chord is None else chord[:-1] + (True,)
        return hist

    def _factor(self, P, H, c, act, J=None):
        """(LU of J_II, J_IA, False) at (P, H): the rows of the free (pressurised) nodes
        of the scaled local Jacobian -c dL/dP (``J``: dL/dP at (P, H) when known), split
        by the active set."""
        J = -c[:, None] * (self.jacobian(P, H) if J is None else J)
        free = ~act
        lu = sla.lu_factor(J[np.ix_(free, free)], check_finite=False) if free.any() else None
        return lu, J[np.ix_(free, act)], False

    @staticmethod
    def _direction(F, act, lu, J_IA, _stale) -> np.ndarray:
        """The semi-smooth Newton direction: d = -F on the active (cavitated) nodes, whose
        rows are the identity, and on the others the reduced system
        J_II d_I = -F_I - J_IA d_A (the dense solve only over the pressurised part of S;
        about half of S lies in the cavitation downstream of the spike)."""
        d = -F.copy()
        free = ~act
        if free.any():
            d[free] = sla.lu_solve(lu, -F[free] - J_IA @ d[act], check_finite=False)
        return d

    def _search(self, P, H0, f, c, d, norm0):
        """Backtracking from the full step: (P, F, H, active) of the first trial that
        decreases |F_S| (Armijo, 1e-4), or None."""
        a, at = 1.0, (self.jj + 1, self.ii + 1)
        for _ in range(20):
            Pt = P.copy()
            Pt[at] = np.maximum(P[at] + a * d, 0.0)
            Ft, Ht, act = self.merit(Pt, H0, f, c)
            if np.all(np.isfinite(Ft)) and Ht.min() > 0.0 and np.linalg.norm(Ft) <= (1 - 1e-4 * a) * norm0:
                return Pt, Ft, Ht, act
            a *= 0.5
        return None
