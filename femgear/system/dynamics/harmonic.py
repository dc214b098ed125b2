"""Steady-state whine per order by harmonic balance: the gear-rotor model in the frequency domain.

While the drive flanks of both helices stay in contact, the mesh law of
:class:`~femgear.system.dynamics.model.GearRotorModel`,
N_s = k_s(t) f_gap(δ_s; b̄_s) + c_s δ̇_s with δ_s = G_s q − e_s(t), is linear in the state:
N_s = k_s(t) (G_s q − e_s − b̄_s) + c_s (G_s q̇ − ė_s).  About the loaded static state the equations
of motion are then *exactly* linear with mesh-periodic coefficients (the stiffness k_s(t) the
parametric term, the friction direction w_s(t) = μ (A_s H0_s + B_s H1_s) a second one):

    M q̈ + C q̇ + K q + Σ_s (G_sᵀ + w_s(t)) N_s = f(t).

Excitations, split into families by their carrier frequency ν ω_m (ω_m = 2π f_m):

- ``mesh`` (ν = 0): the torques, the stiffness variation acting on the static deflection and the
  backlash (the loaded transmission error), profile-error harmonics and flank deviations
  (wear, thermal, the LTCA's unloaded TE);
- ``pinion`` / ``gear`` (ν = Ω_i/ω_m = ±1/z_i): the eccentricity and unbalance of that member,
  whose response lies at the sidebands (ν + k) f_m of the mesh orders.

The families superpose (the system is linear); random pitch errors repeat only over the hunting
period and are left to the time integration (:func:`applies`).  Per family the response is
q(t) = Σ_{k=−H}^{H} Q_k e^{i(ν+k)ω_m t} (the physical one 2 Re of it for ν ≠ 0); the
harmonics couple through the Fourier coefficients κ_{s,m} of k_s (Hill's method, the parametric
coupling kept to ±2H orders).  With the mean mesh springs put into the dynamic stiffness
D̃_k = K + Σ k̄_s G_sᵀG_s − ω_k² M + iω_k (C + Σ c_s G_sᵀG_s) the unknowns condense onto the two
mesh coordinates Y_s,k = G_s Q_k:

    [I + R (T − k̄) + V (T + iΩ c)] Y = Y⁰ + (R + V) P,     R_k = G D̃_k⁻¹ Gᵀ,  Y⁰_k = G D̃_k⁻¹ F_k,

T the block-Toeplitz matrix of κ, V_{k,j} = G D̃_k⁻¹ Ŵ_{k−j} the friction's, P_s the harmonics of
k_s (e_s + b̄_s) + c_s ė_s: a dense system of 2(2H+1) unknowns per family (one solve, no
iteration), after which Q_k, the mesh forces and the bearing stations follow.  The coefficients
of the piecewise-linear tables are exact (:func:`periodic_coefficients`), so the truncation at H
harmonics is the only approximation.  The free rotation of the train (a zero of D̃_0 without a
power loop) carries no mesh or bearing load and is projected out of the mean.

Contact: the solution is linear only while δ_s − b̄_s > 0 (and N_s > 0 with friction, whose
sign |N_s| takes).  :attr:`HarmonicSolution.contact_margin` is a lower bound of min_t(δ_s − b̄_s)
over all families together (the mesh family on a dense phase grid minus the envelopes of the
others); a solution with a margin ≤ 0 is flagged (``contact_kept`` False) and must not be used
as the answer (:mod:`femgear.system.dynamics.harmonic_sweep` hands those speeds to the time
integration).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.system.dynamics.bearings import force_matrices
from femgear.system.dynamics.harmonic_core import (
    check_shared,
    member_families,
    mesh_family,
    operators,
    periodic_coefficients,
    solve_family,
)
from femgear.system.dynamics.model import GearRotorModel

__all__ = ["HarmonicSolution", "applies", "harmonic_response", "harmonic_responses", "periodic_coefficients"]

#: mesh harmonics per family to start with (:func:`harmonic_response` doubles them until converged)
HARMONICS = 24
#: ... at most
MAX_HARMONICS = 384
#: relative change of the lines allowed between H/2 and H harmonics (the truncation estimate)
TRUNCATION_TOL = 1e-3
#: phase samples per mesh period of the contact check (at least; and 8 per harmonic)
CONTACT_SAMPLES = 2048


def applies(model: GearRotorModel) -> str | None:
    """None when the harmonic balance models every excitation of ``model``; else why not (one line)."""
    if any(r.amplitude != 0.0 for r in model.random_errors):
        return "random pitch errors (errors.random) repeat over the hunting period, not the mesh period"
    if any(k <= 0 for k in model.stiffness.mean[: model.pair.n_helices]):
        return "a mesh without stiffness"
    return None


@document_fields
@dataclass(frozen=True)
class HarmonicSolution:
    """The steady state of one model by harmonic balance: lines (orders) with complex amplitudes.

    A signal is x(t) = mean + Σ_l Re[X_l e^{2πi f_l t}]: ``|X_l|`` is the single-sided (peak) amplitude
    of line l, as the Hanning spectra of :func:`femgear.system.dynamics.response.spectrum` read it.
    """

    mesh_frequency: float
    """mesh frequency f_m [Hz]"""
    harmonics: int
    """H: mesh harmonics kept per family (the parametric coupling spans ±2H orders; lines up to order H/2 are
    reported) [-]"""
    families: tuple[str, ...]
    """the excitation families solved (``mesh``, ``pinion``, ``gear``) [-]"""
    frequency: np.ndarray
    """(L,) line frequencies, ascending: the mesh orders k f_m and the sidebands k f_m ± f_shaft [Hz]"""
    mesh_force: np.ndarray
    """(2, L) complex amplitude of the dynamic mesh force N_s per helix (left, right) [N]"""
    mesh_force_mean: np.ndarray
    """(2,) mean mesh force per helix [N]"""
    dte: np.ndarray
    """(L,) complex amplitude of the dynamic transmission error (mean of δ_L, δ_R) [m]"""
    displacement: np.ndarray
    """(24, L) complex amplitude of the full DOFs (the four helix halves) [m, rad]"""
    displacement_mean: np.ndarray
    """(24,) mean displacement of the full DOFs (the free rotation of the train removed) [m, rad]"""
    contact_margin: np.ndarray
    """(2,) lower bound of min over time of δ_s − b̄_s, the drive-flank overlap (≤ 0: the flanks may separate and
    the linear answer does not hold) [m]"""
    normal_force_min: np.ndarray
    """(2,) lower bound of min over time of N_s (friction takes its sign) [N]"""
    truncation: float
    """the truncation estimate: largest change of the mesh-force and DTE lines of orders ≤ H/4 between H/2 and H
    harmonics, relative to the largest line [-]"""
    bearing_force: np.ndarray
    """(4, 3, L) complex amplitude of the bearing-station loads (pinion-L/R, gear-L/R; x, y, z), the force of the
    shaft on the bearing (:func:`femgear.system.dynamics.bearings.force_matrices`) [N]"""
    bearing_force_mean: np.ndarray
    """(4, 3) mean bearing-station loads [N]"""

    @property
    def order(self) -> np.ndarray:
        """Line frequencies in mesh orders f/f_m [-]."""
        return self.frequency / self.mesh_frequency

    @property
    def contact_kept(self) -> bool:
        """Both loaded flanks stay in contact throughout (the linear answer holds)."""
        return bool(np.all(self.contact_margin > 0) and np.all(self.normal_force_min >= 0))

    @property
    def dte_rms(self) -> float:
        """RMS of the dynamic transmission error over the steady state [m]."""
        return float(np.sqrt(0.5 * np.sum(np.abs(self.dte) ** 2)))

    def line(self, order: float) -> int:
        """Index of the line at ``order`` mesh orders (KeyError if there is none)."""
        hit = np.flatnonzero(np.abs(self.order - order) <= 1e-9 * max(1.0, abs(order)))
        if not hit.size:
            raise KeyError(f"no line at mesh order {order!r}")
        return int(hit[0])

    def mesh_force_peak(self, samples: int = 32) -> np.ndarray:
        """(2,) largest mesh force per helix over the steady state [N] (what K_v reads), from its lines: the waveform
        N̄ + Re Σ X_l exp(2πi f_l t) over one period of the smallest line spacing (a mesh period, or a member's
        revolution where its sidebands are lines), ``samples`` points per period of the highest line.  The lines stop at
        order H/2, so content above it is missing (on the baseline at 500 rpm K_v 1.0017 against 1.0038 from the
        time record: half of its small dynamic part lies above order 12)."""
        f = self.frequency
        gaps = np.diff(np.concatenate([[0.0], f]))
        period = 1.0 / gaps[gaps > 1e-9 * f.max()].min()
        t = np.arange(int(np.ceil(samples * f.max() * period))) * (period / np.ceil(samples * f.max() * period))
        wave = self.mesh_force_mean[:, None] + np.real(self.mesh_force @ np.exp(2j * np.pi * np.outer(f, t)))
        return wave.max(axis=1)

    def order_amplitudes(self, values: np.ndarray, orders) -> np.ndarray:
        """|values| at the mesh orders ``orders`` (last axis = lines), 0 where a line is absent [unit]."""
        out = []
        for o in orders:
            try:
                out.append(np.abs(values[..., self.line(o)]))
            except KeyError:
                out.append(np.zeros(values.shape[:-1]))
        return np.stack(out, axis=-1)


def _lines(fams, values: list[tuple[np.ndarray, ...]], H: int):
    """Line orders and complex amplitudes of per-family harmonics ``values`` (each (B, …, 2H+1)): the lines of every
    family summed where they coincide, conjugate lines (ν + k < 0) folded onto positive orders, the mean left out."""
    orders, picks = [], []
    for fam in fams:
        o = fam.nu + np.arange(-H, H + 1)
        keep = o > 0 if fam.nu == 0.0 else np.ones(o.size, bool)
        orders.append(o[keep])
        picks.append(keep)
    o = np.concatenate(orders)
    key = np.round(np.abs(o) * 1e9).astype(np.int64)
    uniq, inv = np.unique(key, return_inverse=True)
    out = []
    for q in range(len(values[0])):
        x = np.concatenate([2 * vals[q][..., keep] for vals, keep in zip(values, picks)], axis=-1)
        x = np.where(o < 0, np.conj(x), x)
        summed = np.zeros(x.shape[:-1] + (uniq.size,), dtype=complex)
        np.add.at(np.moveaxis(summed, -1, 0), inv, np.moveaxis(x, -1, 0))
        out.append(summed)
    return uniq / 1e9, out


def _on_grid(X: np.ndarray, m: int) -> np.ndarray:
    """Σ_{k=−H}^{H} X_k e^{2πikj/m} at j = 0 … m−1 (rows of X (…, 2H+1)), by an inverse FFT."""
    H = (X.shape[-1] - 1) // 2
    padded = np.zeros(X.shape[:-1] + (m,), dtype=complex)
    padded[..., np.arange(-H, H + 1) % m] = X
    return np.fft.ifft(padded, axis=-1) * m


def _contact(model: GearRotorModel, fams, sols, H: int) -> tuple[np.ndarray, np.ndarray]:
    """(B, 2) lower bounds of min_t (δ_s − b̄_s) and of min_t N_s: the mesh family on a phase grid minus the envelopes
    |Σ_k X_k e^{2πikφ}| of the other families (their carriers take every phase over the shaft revolutions)."""
    m = max(CONTACT_SAMPLES, 8 * (2 * H + 1), 4 * model.stiffness.k_left.size)
    margin, force = 0.0, 0.0
    for fam, (Y, N, _) in zip(fams, sols):
        g, f = _on_grid(Y - fam.gap, m), _on_grid(N, m)
        if fam.nu == 0.0:
            margin, force = margin + g.real, force + f.real
        else:
            margin, force = margin - 2 * np.abs(g), force - 2 * np.abs(f)
    meshes = np.array(model.stiffness.mean) > 0
    return np.where(meshes, margin.min(axis=-1), np.inf), np.where(meshes, force.min(axis=-1), np.inf)


def _solve(models: list[GearRotorModel], H: int):
    """Families, their solutions (Y, N, Q) and the lines (orders, (mesh force, DTE, reduced states, bearing loads))."""
    model = models[0]
    ops = operators(models, H)
    fams = [mesh_family(models, H)] + member_families(models, H, ops.kappa)
    sols = [solve_family(models, ops, fam, H) for fam in fams]
    KF, CF = force_matrices(model)
    fm = np.array([m.mesh_frequency for m in models])
    values = []
    for fam, (Y, N, Q) in zip(fams, sols):
        w = (fam.nu + np.arange(-H, H + 1))[None] * 2 * np.pi * fm[:, None]                # (B, K)
        bearing = np.einsum("jdn,bkn->bjdk", KF, Q) + 1j * w[:, None, None] * np.einsum("jdn,bkn->bjdk", CF, Q)
        values.append((N, 0.5 * (Y - fam.error).sum(axis=1), Q.transpose(0, 2, 1), bearing))
    return fams, sols, _lines(fams, values, H)


def _upto(lines, order: float):
    """The lines of order ≤ ``order``."""
    o, vals = lines
    keep = o <= order * (1 + 1e-12)
    return o[keep], [v[..., keep] for v in vals]


def _truncation(coarse, fine, order: float) -> np.ndarray:
    """(B,) largest change of the mesh-force and DTE lines of order ≤ ``order`` from ``coarse`` to ``fine``, relative to
    the largest line of each quantity [-]."""
    (oc, vc), (of, vf) = _upto(coarse, order), _upto(fine, order)
    if oc.shape != of.shape or not np.allclose(oc, of):     # both hold every line of order ≤ H/4
        raise AssertionError("harmonic balance: the line sets of H/2 and H harmonics differ")
    err = np.zeros(vf[0].shape[0])
    for a, b in zip(vc[:2], vf[:2]):
        axes = tuple(range(1, b.ndim))
        scale = np.abs(b).max(axis=axes, initial=0.0)
        diff = np.abs(b - a).max(axis=axes, initial=0.0)
        err = np.maximum(err, np.where(scale > 0, diff / np.where(scale > 0, scale, 1.0), 0.0))
    return err


def _take(lines, idx):
    o, vals = lines
    return o, [v[idx] for v in vals]


def harmonic_responses(models: list[GearRotorModel], harmonics: int | None = None,
                       tol: float = TRUNCATION_TOL) -> list[HarmonicSolution]:
    """The steady states of ``models`` by harmonic balance, solved together: models that differ in speed only (one
    :class:`~femgear.system.dynamics.family.SpeedFamily`; ValueError otherwise, and where :func:`applies` says the
    harmonic balance does not model an excitation).

    ``harmonics``: H mesh harmonics per family, fixed; default: :data:`HARMONICS`, doubled (up to
    :data:`MAX_HARMONICS`) until the lines of orders ≤ H/4 of H/2 harmonics agree with those of H within ``tol``
    (relative to the largest line): :attr:`HarmonicSolution.truncation`.  The lines of orders ≤ H/2 are
    returned (the upper half of the harmonics carries the parametric coupling of the lower).  The answer is the
    linear one of the loaded flanks in contact: read :attr:`HarmonicSolution.contact_kept` before using it
    (:mod:`femgear.system.dynamics.harmonic_sweep` does)."""
    models = list(models)
    for m in models:
        why = applies(m)
        if why is not None:
            raise ValueError(f"harmonic balance does not apply: {why}")
    check_shared(models)
    if harmonics is not None and int(harmonics) < 2:
        raise ValueError(f"harmonics must be ≥ 2 (got {harmonics!r})")
    H = HARMONICS if harmonics is None else int(harmonics)
    out: list[HarmonicSolution | None] = [None] * len(models)
    todo = np.arange(len(models))
    coarse = _solve(models, H // 2)[2]
    while todo.size:
        batch = [models[i] for i in todo]
        fams, sols, fine = _solve(batch, H)
        err = _truncation(coarse, fine, H // 4)
        done = (err <= tol) | (harmonics is not None) | (2 * H > MAX_HARMONICS)
        margin, nmin = _contact(batch[0], fams, sols, H)
        o, (force, dte, q, bearing) = _upto(fine, H // 2)
        KF = force_matrices(batch[0])[0]
        for j in np.flatnonzero(done):
            m, q0 = batch[j], sols[0][2][j, H].real
            out[todo[j]] = HarmonicSolution(
                mesh_frequency=m.mesh_frequency, harmonics=H, families=tuple(f.name for f in fams),
                frequency=o * m.mesh_frequency, mesh_force=force[j], mesh_force_mean=sols[0][1][j, :, H].real,
                dte=dte[j], displacement=m.T @ q[j], displacement_mean=m.T @ q0, contact_margin=margin[j],
                normal_force_min=nmin[j], truncation=float(err[j]), bearing_force=bearing[j],
                bearing_force_mean=KF @ q0)
        todo, coarse, H = todo[~done], _take(fine, ~done), 2 * H
    return out


def harmonic_response(model: GearRotorModel, harmonics: int | None = None,
                      tol: float = TRUNCATION_TOL) -> HarmonicSolution:
    """The steady state of one model (:func:`harmonic_responses`)."""
    return harmonic_responses([model], harmonics, tol)[0]
