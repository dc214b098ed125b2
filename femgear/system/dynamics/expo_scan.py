"""Whole mesh periods of ``expo``'s contact fast path at once (issue 26: low-speed dynamics at high-speed cost).

While both drive flanks stay in contact and each flank's normal-force argument keeps its sign,
one ``expo`` step is affine in the state: with x_i = (y_i, μ|N|_{i−1}) (the state and the
friction force of the step before, which the linear extrapolation of μ|N| needs),

    μ|N|_i = C_j y_i + d_i,        y_{i+1} = Φ_j y_i + W_j diag(AB_j) L (μ|N|_i, μ|N|_{i−1}) + k_i,

so x_{i+1} = P_j x_i + p_i with P_j depending on the mesh phase j = i mod per only (Φ_j, the
friction channels W_j and the friction shape factors A, B at the three hold nodes, C_j from
the stiffness at the start of the phase slot and the mesh damping) and p_i on the step's
known inputs.  With the prefix products R_j = P_{j−1}…P_0 (once per run), the forced parts
F_{c,j} (the recursion from a zero state, for all periods c of a chunk at once), and
Q = R_per, the period starts are X_{c+1} = Q X_c + F_{c,per} and every state of the chunk is
x_{c,j} = R_j X_c + F_{c,j}.  This is the same arithmetic as the step-by-step loop,
reassociated (agreement to round-off, ``tests/dynamics/test_expo_scan.py``), with O(per)
Python operations per chunk instead of O(steps).

The assumptions are then checked at every step of the chunk (contact on both drive flanks:
δ_s − e_s > b_s; the normal-force arguments positive), and the states are kept up to the
first step that breaks one; from there :func:`femgear.system.dynamics.expo.expo` goes on step by
step (contact loss, a flank switch) as before.
"""

from __future__ import annotations

import numpy as np

#: steps of states held at once by one chunk (bounds the temporaries to ~ 30 MB)
CHUNK_STEPS = 120_000

# μ|N| at the three hold nodes from (μ|N|_i, μ|N|_{i−1}) per flank: a, a + (a − a_prev)/2, a + (a − a_prev)
_L = np.array([[1, 0, 0, 0], [1, 0, 0, 0], [0, 1, 0, 0], [0, 1, 0, 0],
               [1.5, 0, -0.5, 0], [1.5, 0, -0.5, 0], [0, 1.5, 0, -0.5], [0, 1.5, 0, -0.5],
               [2, 0, -1, 0], [2, 0, -1, 0], [0, 2, 0, -1], [0, 2, 0, -1]], dtype=float)


class ContactScan:
    """The affine maps of the fast path of one ``expo`` segment.

    ``MJ``, ``known``, ``ABn``: :func:`femgear.system.dynamics.expo._fast_path_inputs`; ``Gz`` the mesh
    deflection and rate rows; ``e``, ``ed``, ``b``: (2, 2·steps+1) errors, their rates and the
    dead-zone half-widths on the half-step grid; ``k0``: (per, 2) stiffness at the start of each
    phase slot; ``cm``: mesh damping; ``mu``: friction coefficient scale of the model."""

    def __init__(self, MJ, known, ABn, Gz, e, ed, b, k0, cm, mu):
        per = MJ.shape[0]
        n2 = Gz.shape[1]
        self.per, self.n2, self.Gz = per, n2, Gz
        steps = known.shape[0]
        self.e, self.b = e[:, 0:2 * steps + 1:2].T, b[:, 0:2 * steps + 1:2].T     # (steps+1, 2) at the step starts
        self.friction = ABn is not None and mu > 0.0
        Phi = MJ[:, :n2, :n2]
        if self.friction:
            cm = np.asarray(cm, dtype=float)
            C = mu * (k0[:, :, None] * Gz[None, 0:2] + cm[None, :, None] * Gz[None, 2:4])      # (per, 2, n2)
            d = -mu * (np.asarray(k0)[np.arange(steps) % per] * (self.e[:steps] + self.b[:steps])
                       + cm * ed[:, 0:2 * steps:2].T)                                         # (steps, 2)
            WL = np.einsum("jak,jk,kl->jal", MJ[:, :n2, n2:], ABn[:per], _L)               # (per, n2, 4)
            P = np.zeros((per, n2 + 2, n2 + 2))
            P[:, :n2, :n2] = Phi + WL[:, :, :2] @ C
            P[:, :n2, n2:] = WL[:, :, 2:]
            P[:, n2:, :n2] = C
            p = np.empty((steps, n2 + 2))
            p[:, :n2] = known[:, :n2] + _periodic("jab,cjb->cja", WL[:, :, :2], d, per)
            p[:, n2:] = d
            self.C, self.d = C, d
        else:
            P, p = np.ascontiguousarray(Phi), known[:, :n2]
        self.P, self.p = P, p
        R = np.empty((per + 1,) + P.shape[1:])
        R[0] = np.eye(P.shape[1])
        for j in range(per):
            R[j + 1] = P[j] @ R[j]
        self.R = R

    def normal_force(self, i: int, y: np.ndarray) -> np.ndarray:
        """μ|N| argument (C_j y + d_i) of step ``i`` from the state ``y`` (friction only)."""
        return self.C[i % self.per] @ y + self.d[i]

    def run(self, i0: int, periods: int, x0: np.ndarray) -> tuple[np.ndarray, int]:
        """States x_i (i = i0 … i0 + periods·per) from x0 at i0 (a period start) and the number of
        steps from i0 whose assumptions hold (the states up to and including that index are exact)."""
        per, n2 = self.per, self.n2
        F = np.zeros((periods, per + 1, self.P.shape[1]))
        pc = self.p[i0:i0 + periods * per].reshape(periods, per, -1)
        for j in range(per):
            F[:, j + 1] = F[:, j] @ self.P[j].T + pc[:, j]
        X = np.empty((periods + 1, self.P.shape[1]))
        X[0] = x0
        for c in range(periods):
            X[c + 1] = self.R[per] @ X[c] + F[c, per]
        x = np.einsum("jab,cb->cja", self.R[:per], X[:periods]) + F[:, :per]
        x = np.concatenate([x.reshape(periods * per, -1), X[periods:]])
        y = x[:-1, :n2]
        g = y @ self.Gz[0:2].T - self.e[i0:i0 + periods * per]
        ok = np.all(g > self.b[i0:i0 + periods * per], axis=1)
        if self.friction:
            arg = _periodic("jab,cjb->cja", self.C, y, per) + self.d[i0:i0 + periods * per]
            ok &= np.all(arg > 0.0, axis=1)
        bad = np.flatnonzero(~ok)
        return x, int(bad[0]) if bad.size else periods * per


def _periodic(spec: str, M: np.ndarray, X: np.ndarray, per: int) -> np.ndarray:
    """M_{i mod per} X_i for every row i of X (rows from a period start), by whole periods (the last padded)."""
    n = X.shape[0]
    cyc = -(-n // per)
    pad = np.zeros((cyc * per, X.shape[1]))
    pad[:n] = X
    return np.einsum(spec, M, pad.reshape(cyc, per, -1), optimize=True).reshape(cyc * per, -1)[:n]
