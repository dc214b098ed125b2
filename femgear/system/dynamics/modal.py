"""Linearised modal analysis of a :class:`GearRotorModel` (mean mesh stiffness, flanks in contact).

Undamped generalized eigenproblem (K + Σ k̄_s G_sᵀ G_s) φ = ω² M φ, solved with
scipy.linalg.eigh.  The rigid rotation of the gear train (ω = 0) is reported as such.
Mode shapes are returned in the full 24 DOFs, mass-normalised in the reduced ones.

Modal energy per DOF group: the kinetic-energy fractions φ_i (M φ)_i / φᵀMφ summed
over the DOFs of each group (per member: lateral x-y, axial z, tilt θx-θy,
torsion θz; a coupled housing's coordinates as the group ``housing``), and the strain-energy fraction stored in the two mesh springs,
Σ k̄_s (G_s φ)² / φᵀ K̄ φ.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.linalg import eigh

from femgear.docfields import document_fields
from femgear.system.dynamics.model import GearRotorModel

GROUP_KINDS = {"lateral": (0, 1), "axial": (2,), "tilt": (3, 4), "torsion": (5,)}


@document_fields
@dataclass(frozen=True)
class ModalResult:
    frequencies: np.ndarray
    """natural frequencies, ascending (rigid-body modes ≈ 0) [Hz]"""
    shapes: np.ndarray
    """(24, m) mode shapes in the full DOFs, mass-normalised [-]"""
    energy: dict
    """group name → (m,) kinetic-energy fraction of each mode in the group; "mesh" → the mesh's strain-energy fraction
    [-]"""

    def dominant_group(self, mode: int) -> str:
        groups = {k: v[mode] for k, v in self.energy.items() if k != "mesh"}
        return max(groups, key=groups.get)


def _reduced_labels(model: GearRotorModel) -> list[tuple[int, int]]:
    """(member, direction) of each reduced DOF of the rotor ((-1, -1): a coordinate of a coupled housing)."""
    n = model.n if model.housing is None else model.housing.n_rotor
    rotor = [(m, d) for m in range(2) for d in range(6)] if n == 12 else [(b // 2, d) for b in range(4) for d in range(6)]
    return rotor + [(-1, -1)] * (model.n - n)


def modal_analysis(model: GearRotorModel) -> ModalResult:
    K = model.mean_stiffness_matrix()
    w2, phi = eigh(K, model.M)
    w2 = np.clip(w2, 0.0, None)
    f = np.sqrt(w2) / (2 * np.pi)
    Mphi = model.M @ phi
    ke = phi * Mphi                      # (n, m), columns sum to 1 (mass-normalised)
    labels = _reduced_labels(model)
    energy: dict = {}
    for m, member in enumerate(("pinion", "gear")):
        for kind, dirs in GROUP_KINDS.items():
            rows = [i for i, (mm, d) in enumerate(labels) if mm == m and d in dirs]
            energy[f"{member}.{kind}"] = ke[rows].sum(axis=0)
    if model.housing is not None:
        energy["housing"] = ke[model.housing.n_rotor:].sum(axis=0)
    kbar = np.array(model.stiffness.mean)
    strain = np.einsum("ij,ij->j", phi, K @ phi)
    mesh = (kbar[:, None] * (model.G @ phi) ** 2).sum(axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        energy["mesh"] = np.where(strain > 1e-12 * strain.max(), mesh / strain, 0.0)
    return ModalResult(frequencies=f, shapes=model.T @ phi, energy=energy)


#: mesh strain-energy fraction above which a mode counts as reached by the mesh excitation
MESH_ENERGY_MIN = 1e-3


def mesh_mode_limit(model: GearRotorModel) -> float:
    """The highest natural frequency [Hz] of the flexible modes that load the mesh (mesh
    strain-energy fraction ≥ :data:`MESH_ENERGY_MIN`); 0 when none does.

    Every mesh excitation (the stiffness table, transmission errors, flank deviations,
    friction) acts through the two mesh springs, so a mode that does not strain them is
    not driven by it; a mode that does is reached at every speed: the piecewise-linear
    stiffness tables carry content at all mesh orders (at 100 rpm the baseline's 8.3 kHz
    mode, mesh order 161, holds ~1/5 of the gear's velocity amplitude).
    """
    r = modal_analysis(model)
    flexible = r.frequencies > 1e-6 * max(r.frequencies.max(), 1e-300)
    hit = flexible & (r.energy["mesh"] >= MESH_ENERGY_MIN)
    return float(r.frequencies[hit].max()) if hit.any() else 0.0


#: a mode is marked as a mesh resonance when at least this fraction of its strain energy is in the mesh
RESONANCE_MESH_ENERGY = 0.05


def resonance_marks(frequencies, mesh_energy, f_lo: float, f_hi: float, min_energy: float = RESONANCE_MESH_ENERGY,
                    harmonics: int = 4) -> list[tuple[float, int, float]]:
    """Where the mesh excitation meets a natural frequency inside a mesh-frequency range [Hz].

    The k-th mesh harmonic excites a mode of natural frequency f_n when k f_m = f_n, so a mode with at
    least ``min_energy`` of its strain energy in the mesh resonates at the mesh frequencies f_n / k,
    k = 1 … ``harmonics``.  Returns (f_n / k, k, f_n) for those inside [f_lo, f_hi], by f_n / k.
    """
    marks = [(f / k, k, float(f)) for f, e in zip(frequencies, mesh_energy) if f > 0 and e >= min_energy
             for k in range(1, harmonics + 1) if f_lo <= f / k <= f_hi]
    return sorted(marks)
