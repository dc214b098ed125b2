"""Lagrange-multiplier frequency-based substructuring (LM-FBS) of two subsystems joined at matching DOFs.

Subsystem A (here the gear rotor with its bearings, whose outer rings are free DOFs) and subsystem B (the housing,
known by its receptances) are joined by compatibility B u = u_A,Γ − u_B,Γ = 0 at the interface Γ and equilibrium
of the interface forces λ.  With the block-diagonal receptance Y = diag(Y_A, Y_B) and forces f on A only (de Klerk,
Rixen & Voormeeren, AIAA J. 46 (2008) 1169, the LM-FBS form):

    u = Y f − Y Bᵀ (B Y Bᵀ)⁻¹ B Y f,     B Y Bᵀ = Y_A,ΓΓ + Y_B,ΓΓ,

so u_A = Y_A f − Y_A,:Γ λ and u_B = Y_B,:Γ λ with λ = (Y_A,ΓΓ + Y_B,ΓΓ)⁻¹ (Y_A f)_Γ, the force A puts on B at
the interface.  Only B's columns at Γ are needed (the inputs of a measured FRF set at the bearing seats), and only
its rows where a response is wanted (seats and sensors).
"""

from __future__ import annotations

import numpy as np


def lm_fbs(Y_A: np.ndarray, f_A: np.ndarray, gamma_A: np.ndarray, Y_B_gamma: np.ndarray,
           gamma_B: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(u_A, u_B, λ) of the coupled system at one frequency (module docstring).

    ``Y_A`` (n_A, n_A) receptance of A; ``f_A`` (n_A, ...) forces on A (trailing axes: load cases); ``gamma_A``
    the interface DOFs in A; ``Y_B_gamma`` (n_B, n_Γ) the columns of B's receptance at its interface DOFs,
    whose rows ``gamma_B`` are the interface (matched in order with ``gamma_A``).  λ: the interface force on B.
    """
    gamma_A, gamma_B = np.asarray(gamma_A), np.asarray(gamma_B)
    if gamma_A.size != gamma_B.size or Y_B_gamma.shape[1] != gamma_A.size:
        raise ValueError("lm_fbs: the interface DOFs of A and B must match one to one")
    u0 = Y_A @ f_A
    lam = np.linalg.solve(Y_A[np.ix_(gamma_A, gamma_A)] + Y_B_gamma[gamma_B], u0[gamma_A])
    return u0 - Y_A[:, gamma_A] @ lam, Y_B_gamma @ lam, lam
