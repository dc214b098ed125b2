"""Campbell (interference) diagram: natural frequencies against speed, tracked by MAC, with the excitation orders.

At driver speed n the undamped linearised model (mean mesh stiffness, flanks in contact) with the
gyroscopic moments of the spinning gear bodies,

    M q̈ + G(n) q̇ + K̄ q = 0,   G(n) = Tᵀ G₂₄(n) T,

is solved as the first-order eigenproblem of (q, q̇): its eigenvalues ±iω give the natural
frequencies, which split into forward and backward whirl as the speed grows.  G₂₄ couples the
tilts of each body (rigid member or helix half): a body of polar inertia I_p spinning at Ω about +z has
I_d θ̈x + I_p Ω θ̇y = M_x and I_d θ̈y − I_p Ω θ̇x = M_y (angular momentum I_p Ω along the tilted
axis (θy, −θx, 1)); Ω is each member's signed speed (the members turn opposite ways).  The
shafts' own distributed gyroscopic matrix is not built (what of their polar inertia the
condensation puts on the bodies spins with them), and the time integrators carry no gyroscopic term: the diagram shows how far the gyroscopic coupling
moves each mode from the zero-speed frequencies the time-domain runs see.  At n = 0 the
frequencies are those of :func:`femgear.system.dynamics.modal.modal_analysis`.

Modes are followed from one speed to the next by the modal assurance criterion (mass-weighted,
MAC_ij = |φ_iᴴ M φ_j|² / (φ_iᴴ M φ_i · φ_jᴴ M φ_j), assigned one to one by
:func:`scipy.optimize.linear_sum_assignment`), so a curve is one mode even where curves cross.

Strain-energy shares of each mode (Velex's criterion for the modes a mesh excites: notes nvh.md):
the fractions of φᴴ K̄ φ stored in each mesh spring (left and right helix), k̄_s |G_s φ|², in each
bearing station, Σ_d K_jd |B_jd φ|², in the power loop, and in the shafts (the rest).

Critical speeds: where an excitation order meets a mode whose mesh strain energy (both helices) is
at least :data:`MESH_ENERGY_MIN` (5 %): the mesh orders k (f = k z n_member/60 of the driver) and the
shaft orders j of each member (f = j n_member/60), located by linear interpolation between the
sweep's speeds.  For a mode whose frequency does not depend on speed (a torsional mode) the
mesh-order-1 critical speed is n = 60 f_n / z.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import eig
from scipy.optimize import linear_sum_assignment

from femgear.docfields import document_fields
from femgear.system.dynamics.model import GearRotorModel

#: a mode meets an order as a critical speed when at least this share of its strain energy is in the meshes
MESH_ENERGY_MIN = 0.05
#: default excitation orders of the diagram: mesh orders and shaft orders
MESH_ORDERS = (1, 2, 3, 4)
SHAFT_ORDERS = (1, 2)
ENERGY_KEYS = ("mesh_L", "mesh_R", "bearing_pinion_L", "bearing_pinion_R", "bearing_gear_L", "bearing_gear_R",
               "loop", "shafts")


def gyroscopic_matrix(model: GearRotorModel, pinion_rpm: float) -> np.ndarray:
    """G in the model's reduced coordinates with the pinion at ``pinion_rpm`` (the gear at its ratio) [N m s].

    The reduced coordinates are bodies of 6 DOF (the rigid members of ``lumped`` and of a one-mesh
    ``timoshenko`` model, the four helix halves of a double-helical ``timoshenko`` one); each spins at its
    member's signed speed with the polar inertia of its torsional diagonal of M (the gear body and, at the
    ``timoshenko`` level, the share of the shaft's polar inertia condensed onto it)."""
    n = model.n
    per_member = n // 12
    scale = pinion_rpm / (60.0 * abs(model.omega[0]) / (2 * math.pi))
    G = np.zeros((n, n))
    for body in range(n // 6):
        omega = model.omega[body // per_member] * scale
        ip = model.M[6 * body + 5, 6 * body + 5]
        rx, ry = 6 * body + 3, 6 * body + 4
        G[rx, ry], G[ry, rx] = ip * omega, -ip * omega
    return G


@document_fields
@dataclass(frozen=True)
class CampbellDiagram:
    """Natural frequencies of the linearised model against driver speed, tracked by MAC."""

    speed_rpm: np.ndarray
    """(n_s,) driver speeds of the sweep [rpm]"""
    frequency: np.ndarray
    """(n_s, n_m) natural frequency of each tracked mode at each speed (modes ordered by their frequency at the
    first speed) [Hz]"""
    mac: np.ndarray
    """(n_s, n_m) MAC of each mode with itself at the previous speed (1 at the first) [-]"""
    energy: dict
    """ENERGY_KEYS → (n_s, n_m) strain-energy share of each mode at each speed: each mesh (helix), each bearing
    station, the power loop and the shafts [-]"""
    orders: tuple
    """the excitation orders drawn: (label, member index 0/1 of the speed, multiple of that member's speed)
    [-]"""
    critical: tuple
    """critical speeds: dicts of ``order``, ``speed_rpm``, ``frequency_hz``, ``mode`` and the mode's shares there
    [rpm, Hz, -]"""
    speed_ratio: tuple
    """(pinion, gear) speed over the driver speed [-]"""
    teeth: tuple
    """(z1, z2) [-]"""

    @property
    def mesh_energy(self) -> np.ndarray:
        """(n_s, n_m) share of both meshes [-]."""
        return self.energy["mesh_L"] + self.energy["mesh_R"]


def _modes(model: GearRotorModel, Kbar: np.ndarray, speed_rpm: float) -> tuple[np.ndarray, np.ndarray]:
    """(frequencies [Hz], mass-normalised complex shapes (n, m)) of the flexible modes at one speed, ascending."""
    n = model.n
    G = gyroscopic_matrix(model, speed_rpm)
    if not np.any(G):
        from scipy.linalg import eigh

        w2, phi = eigh(Kbar, model.M)
        keep = w2 > 1e-8 * w2.max()
        return np.sqrt(w2[keep]) / (2 * math.pi), phi[:, keep].astype(complex)
    Minv = np.linalg.inv(model.M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ Kbar, -Minv @ G]])
    lam, vec = eig(A)
    w = lam.imag
    scale = np.abs(lam).max()
    keep = (w > 1e-4 * scale) & (np.abs(lam.real) < 1e-6 * scale)
    order = np.argsort(w[keep])
    phi = vec[:n, keep][:, order]
    phi = phi / np.sqrt(np.einsum("im,ij,jm->m", phi.conj(), model.M, phi).real)
    return w[keep][order] / (2 * math.pi), phi


def strain_energy_shares(model: GearRotorModel, Kbar: np.ndarray, phi: np.ndarray) -> dict[str, np.ndarray]:
    """ENERGY_KEYS → (m,) shares of φᴴ K̄ φ of the (complex) shapes ``phi`` (n, m) [-]."""
    total = np.einsum("im,ij,jm->m", phi.conj(), Kbar, phi).real
    kbar = np.array(model.stiffness.mean)
    out = {f"mesh_{side}": kbar[s] * np.abs(model.G[s] @ phi) ** 2 / total for s, side in enumerate("LR")}
    u = (model.bearing_map @ phi).reshape(4, 3, -1)
    for j, station in enumerate(("pinion_L", "pinion_R", "gear_L", "gear_R")):
        out[f"bearing_{station}"] = np.einsum("d,dm->m", model.bearings.stiffness[j], np.abs(u[j]) ** 2) / total
    if model.load_stiffness > 0:
        from femgear.system.dynamics.build import loop_spring

        Kl = loop_spring(model.pair, model.T, model.load_stiffness)
        out["loop"] = np.einsum("im,ij,jm->m", phi.conj(), Kl, phi).real / total
    else:
        out["loop"] = np.zeros(phi.shape[1])
    out["shafts"] = np.clip(1.0 - sum(out.values()), 0.0, None)
    return out


def _track(prev: np.ndarray, phi: np.ndarray, M: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(permutation of the columns of ``phi`` onto ``prev``, their MAC) by a one-to-one assignment."""
    cross = np.abs(prev.conj().T @ M @ phi) ** 2
    norms = np.outer(np.einsum("im,ij,jm->m", prev.conj(), M, prev).real,
                     np.einsum("im,ij,jm->m", phi.conj(), M, phi).real)
    mac = cross / norms
    rows, cols = linear_sum_assignment(-mac)
    return cols[np.argsort(rows)], mac[rows, cols][np.argsort(rows)]


def _orders(model: GearRotorModel, driver: str, mesh_orders, shaft_orders):
    """(label, member, multiple): the multiple of member ``member``'s speed that each order excites."""
    z1 = model.pair.z1
    out = [(f"mesh order {k}", 0, k * z1) for k in mesh_orders]
    out += [(f"{name} shaft order {j}", m, j) for m, name in enumerate(("pinion", "gear")) for j in shaft_orders]
    return tuple(out)


def campbell(model: GearRotorModel, speeds_rpm, *, driver: str = "pinion", mesh_orders=MESH_ORDERS,
             shaft_orders=SHAFT_ORDERS, progress=None) -> CampbellDiagram:
    """The Campbell diagram of ``model`` over the driver speeds ``speeds_rpm`` [rpm] (ascending, ≥ 0).

    ``driver``: the member the speeds are of ("pinion" or "gear", the scene's ``operating.driver``);
    ``mesh_orders``, ``shaft_orders``: the positive excitation orders drawn and searched for critical speeds;
    ``progress``: called as progress(i, n) after each speed (long sweeps report through it).
    """
    speeds = np.asarray(speeds_rpm, dtype=float)
    if speeds.ndim != 1 or speeds.size < 2 or np.any(np.diff(speeds) <= 0) or speeds[0] < 0:
        raise ValueError("campbell: speeds must be ≥ 0, ascending, at least two")
    if any(k <= 0 for k in (*mesh_orders, *shaft_orders)):
        raise ValueError("campbell: orders must be positive")
    ratio = model.pair.z1 / model.pair.z2
    speed_ratio = (1.0, ratio) if driver == "pinion" else (1.0 / ratio, 1.0)     # member speed / driver speed
    Kbar = model.mean_stiffness_matrix()
    freqs, macs, shares, prev = [], [], [], None
    for i, n in enumerate(speeds):
        f, phi = _modes(model, Kbar, n * speed_ratio[0])
        if prev is not None:
            if phi.shape[1] != prev.shape[1]:
                raise ValueError(f"campbell: {phi.shape[1]} flexible modes at {n:g} rpm, {prev.shape[1]} before")
            perm, mac = _track(prev, phi, model.M)
            f, phi = f[perm], phi[:, perm]
        else:
            mac = np.ones(f.size)
        freqs.append(f)
        macs.append(mac)
        shares.append(strain_energy_shares(model, Kbar, phi))
        prev = phi
        if progress is not None:
            progress(i + 1, speeds.size)
    freq = np.array(freqs)
    energy = {k: np.array([s[k] for s in shares]) for k in ENERGY_KEYS}
    orders = _orders(model, driver, mesh_orders, shaft_orders)
    diagram = CampbellDiagram(speed_rpm=speeds, frequency=freq, mac=np.array(macs), energy=energy, orders=orders,
                              critical=(), speed_ratio=speed_ratio, teeth=(model.pair.z1, model.pair.z2))
    return _with_critical(diagram)


def order_frequency(diagram: CampbellDiagram, order: tuple, speeds: np.ndarray) -> np.ndarray:
    """Frequency [Hz] of an excitation ``order`` (label, member, multiple) at driver ``speeds`` [rpm]."""
    _, member, multiple = order
    return multiple * diagram.speed_ratio[member] * np.asarray(speeds, dtype=float) / 60.0


def _with_critical(d: CampbellDiagram) -> CampbellDiagram:
    """``d`` with its critical speeds: sign changes of f_mode − f_order between neighbouring speeds, by linear
    interpolation, for the modes with ≥ :data:`MESH_ENERGY_MIN` mesh strain energy there."""
    from dataclasses import replace

    out = []
    n = d.speed_rpm
    mesh = d.mesh_energy
    for order in d.orders:
        diff = d.frequency - order_frequency(d, order, n)[:, None]
        for mode in range(d.frequency.shape[1]):
            for i in np.flatnonzero(np.sign(diff[:-1, mode]) * np.sign(diff[1:, mode]) <= 0):
                a, b = diff[i, mode], diff[i + 1, mode]
                if a == b:
                    continue
                x = a / (a - b)                              # fraction of the step where they meet
                e = {k: float(v[i, mode] + x * (v[i + 1, mode] - v[i, mode])) for k, v in d.energy.items()}
                if mesh[i, mode] + x * (mesh[i + 1, mode] - mesh[i, mode]) < MESH_ENERGY_MIN:
                    continue
                rpm = float(n[i] + x * (n[i + 1] - n[i]))
                f = float(d.frequency[i, mode] + x * (d.frequency[i + 1, mode] - d.frequency[i, mode]))
                out.append({"order": order[0], "speed_rpm": rpm, "frequency_hz": f, "mode": mode, "energy": e})
                if a == 0 and i > 0:
                    break
    out.sort(key=lambda c: c["speed_rpm"])
    return replace(d, critical=tuple(_unique(out)))


def _unique(crossings: list[dict]) -> list[dict]:
    """Drop the duplicate of a crossing that falls exactly on a sweep speed (found from both sides)."""
    seen, out = set(), []
    for c in crossings:
        key = (c["order"], c["mode"], round(c["speed_rpm"], 6))
        if key not in seen:
            seen.add(key)
            out.append(c)
    return out
