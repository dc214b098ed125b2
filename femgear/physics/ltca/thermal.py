"""Thermo-elastic flank deviation ζ_T on the 3-D member body (``physics.thermal = "fe3d"``).

The body is the LTCA's :func:`femgear.physics.mesh.segment.member_body` (both helices, the groove — one helix
of the real face width for a single-helical or spur pair —,
a whole ring with ``n_teeth`` teeth, the rim down to the bore; P1 tetrahedra), with the bore
of the thermal levels (the scene's, else half the root radius, as ``analytic`` and ``fe``).

Conduction (:func:`femgear.physics.body.conduction.solve_temperature_cases`, P1, one factor).  Tooth surfaces (``flank``,
``fillet``, ``tip``) and the toothless root circle of the ring (``rim``, which stands for the
roots of the teeth the body leaves out) at ΔT_f, the bore at ΔT_s; the end faces and the groove
are insulated — the assumption of the 2-D ``fe`` model (its cut sides and, in plane stress, its
faces), so the comparison isolates the 3-D elasticity.  With Dirichlet data only, T does not
depend on the conductivity.

Elasticity (:class:`femgear.physics.body.elastic3d.Elastic3D`, P1).  σ = 2μ ε + λ tr ε I − β_T ΔT I with
the 3-D thermal modulus β_T = (3λ + 2μ) λ_T = E λ_T/(1 − 2ν) (Timoshenko & Goodier, *Theory of
Elasticity*, 3rd ed., §150; :func:`femgear.physics.body.forms.thermal_modulus` with ``plane="strain"``,
whose λ is the 3-D one) and the load ∫ β_T ΔT div v (:data:`femgear.physics.body.forms.thermal_load`).
Support: the body is free.  The 2-D model lets the section grow radially (rollers on radial
cut sides, bore free) and the analytic level is a free hollow disc; a clamped bore would hold
the bore at the shaft's size, i.e. assume a rigid shaft that does not warm up, while a shrink
fit on a shaft at ΔT_s moves with it.  So six DOF at three bore nodes in the body's mid-plane
remove the rigid modes (statically determinate: no reactions), and the rigid motion that
best fits the bore nodes (least squares) is then subtracted: the flank moves relative to the
shaft axis, with no turn about it (the rollers' role in 2-D).

Reading.  ζ_t = u·n_t, n_t the outward transverse normal of the analytic flank at roll distance
ρ and face coordinate ζ of either helix (:func:`femgear.physics.ltca.compliance.reading_points`),
extrapolated linearly to the surface from two depths inside the body (exact for the linear
field of a uniform rise), and ζ_n = ζ_t cos β_b along the normal line of action, as the 2-D
levels.  The axial displacement is left out like in 2-D: equal axial growths of the two
members move their flanks together.  A uniform rise ΔT gives ζ_n = λ_T ΔT ρ cos β_b
(:mod:`femgear.physics.body.thermal`).

The problems are linear: unit solutions (ΔT_f = 1, ΔT_s = 0) and (0, 1) on a (ρ, ζ) grid of
both helices are cached on disk (:func:`femgear.physics.ltca.compliance.cache_dir`).
"""

from __future__ import annotations

import json
import math
import time
from dataclasses import dataclass, field, replace

import numpy as np

from femgear.physics.body.thermal import flank_radius
from femgear.physics.geometry.gear import GearPair

CACHE_VERSION = 1
READ_DEPTH = 0.05      #: first reading depth below the flank [m_n] (the second is twice that)


@dataclass(frozen=True)
class Thermal3DUnits:
    """ζ_n per kelvin on the loaded flanks of one member: ``flank``/``shaft`` (2 helices, n_ρ, n_ζ) [m/K]; a
    single-helical member's one helix fills both rows (the right one is never loaded)."""

    member: int
    rho: np.ndarray      #: roll distances [m]
    zeta: np.ndarray     #: face coordinates of a helix, 0 at its outer end, b at the groove [m]
    flank: np.ndarray    #: unit flank rise (ΔT_f = 1 K, ΔT_s = 0)
    shaft: np.ndarray    #: unit shaft rise
    info: dict = field(default_factory=dict)

    def grid(self, flank_rise: float, shaft_rise: float) -> np.ndarray:
        """ζ_n on the grid (2, n_ρ, n_ζ) for the given rises [m]."""
        return flank_rise * self.flank + shaft_rise * self.shaft

    def at(self, rho, zeta, helix: int, flank_rise: float, shaft_rise: float) -> np.ndarray:
        """ζ_n at roll distances ``rho`` and face coordinates ``zeta`` of ``helix`` (0 left, 1 right) [m]."""
        from scipy.interpolate import RegularGridInterpolator

        f = RegularGridInterpolator((self.rho, self.zeta), self.grid(flank_rise, shaft_rise)[helix])
        rho, zeta = np.broadcast_arrays(np.asarray(rho, float), np.asarray(zeta, float))
        pts = np.column_stack([np.clip(rho.ravel(), self.rho[0], self.rho[-1]),
                               np.clip(zeta.ravel(), self.zeta[0], self.zeta[-1])])
        return f(pts).reshape(rho.shape)

    def face_field(self, rho, zeta, flank_rise: float, shaft_rise: float) -> np.ndarray:
        """ζ_n (2 helices, n, m) at the roll distances ``rho`` (n,) × face coordinates ``zeta`` (m,) [m]
        (:meth:`at` on the outer product, bilinear in the unit grid)."""
        R, Z = np.meshgrid(np.asarray(rho, float), np.asarray(zeta, float), indexing="ij")
        return np.array([self.at(R, Z, h, flank_rise, shaft_rise) for h in (0, 1)])

    def face_mean(self, rho, flank_rise: float, shaft_rise: float) -> np.ndarray:
        """ζ_n at ``rho`` averaged over the face of both helices (trapezoid rule) [m]."""
        g = self.grid(flank_rise, shaft_rise)
        mean = np.trapezoid(g, self.zeta, axis=2).mean(axis=0) / (self.zeta[-1] - self.zeta[0])
        return np.interp(np.asarray(rho, float), self.rho, mean)

    def tables(self, flank_rise: float, shaft_rise: float) -> dict:
        """``{(helix name, member): (rho, zeta, values)}`` for :func:`femgear.physics.ltca.separation.tabulated_deviation`
        (thermal growth removes clearance: the values are −ζ_n)."""
        g = self.grid(flank_rise, shaft_rise)
        return {(name, self.member): (self.rho, self.zeta, -g[h]) for h, name in enumerate(("left", "right"))}


def body_spec(pair: GearPair, member: int, level: int = 1, bore_radius: float = 0.0, groove: float = 0.0,
              stagger: float = 0.0, n_teeth: int = 5):
    """The member body's :class:`~femgear.physics.mesh.segment.SegmentSpec` with the thermal levels' bore
    (``bore_radius``, 0: half the root radius)."""
    from femgear.physics.mesh.segment import default_spec

    rf = pair.rf1 if member == 1 else pair.rf2
    r_bore = bore_radius if bore_radius > 0 else 0.5 * rf
    return default_spec(pair, member, level, n_teeth=n_teeth, r_bore=r_bore, groove=groove, stagger=stagger)


def thermal_cache_path(pair: GearPair, member: int, spec, expansion: float, youngs_modulus: float,
                       poisson_ratio: float, n_rho: int = 13, n_z: int = 9):
    """The disk-cache file of :func:`thermal_units_3d` with these arguments (it may not exist)."""
    from femgear.physics.ltca.compliance import cache_dir, cache_key
    from femgear.physics.mesh.segment import mesh_revision

    payload = {"v": CACHE_VERSION, "pair": pair.identity(), "member": member, "spec": spec.key(),
               "E": youngs_modulus, "nu": poisson_ratio, "expansion": expansion, "grid": [n_rho, n_z]}
    if mesh_revision(pair, member, spec) is not None:     # the far-field rule or the graded groove changed the mesh
        payload["mesh"] = mesh_revision(pair, member, spec)
    return cache_dir() / f"thermal3d-member{member}-{cache_key(payload)}.npz"


def thermal_estimate(pair: GearPair, member: int, spec):
    """:class:`femgear.perf.Estimate` of one member's unit solutions (P1 body, two load cases)."""
    from femgear.physics.ltca.compliance import build_estimate

    est = build_estimate(pair, member, spec, 1, 2)
    return replace(est, stage=est.stage.replace("LTCA", "fe3d thermal"))


def check_thermal_memory(pair: GearPair, expansion: float, youngs_modulus: float, poisson_ratio: float,
                         bores: tuple[float, float], groove: float, stagger: float, level: int) -> None:
    """Refuse (:class:`femgear.errors.ResourceError` naming ``numerics.body_level`` and the finest level that fits)
    before either member's body is built when one that is not cached needs more memory than the budget."""
    from femgear.errors import ResourceError
    from femgear.perf import memory_budget

    def estimates(k: int, cached: bool) -> list:
        out = []
        for member in (1, 2):
            spec = body_spec(pair, member, k, bores[member - 1], groove, stagger)
            if cached and thermal_cache_path(pair, member, spec, expansion, youngs_modulus, poisson_ratio).exists():
                continue
            out.append(thermal_estimate(pair, member, spec))
        return out

    budget = memory_budget()
    over = [e for e in estimates(level, True) if e.memory_bytes > budget]
    if not over:
        return
    fits = next((k for k in range(level - 1, -1, -1) if all(e.memory_bytes <= budget for e in estimates(k, False))),
                None)
    hint = f"numerics.body_level = {fits} fits" if fits is not None else "no body level fits"
    worst = max(over, key=lambda e: e.memory_bytes)
    raise ResourceError("numerics.body_level", worst.memory_bytes, budget, f"{worst.stage} at level {level}; {hint}")


def thermal_units_3d(pair: GearPair, member: int, expansion: float, youngs_modulus: float = 210e9,
                     poisson_ratio: float = 0.3, bore_radius: float = 0.0, groove: float = 0.0,
                     stagger: float = 0.0, level: int = 1, n_rho: int = 13, n_z: int = 9,
                     cache: bool = True) -> Thermal3DUnits:
    """Unit responses of ``member`` on its 3-D body at resolution ``level``, from the disk cache when present."""
    from femgear.physics.ltca.compliance import save_cache

    if level < 0:
        raise ValueError(f"level must be ≥ 0, got {level}")
    spec = body_spec(pair, member, level, bore_radius, groove, stagger)
    path = thermal_cache_path(pair, member, spec, expansion, youngs_modulus, poisson_ratio, n_rho, n_z)
    if cache and path.exists():
        d = np.load(path, allow_pickle=False)
        info = json.loads(str(d["info"]))
        info["cached"] = True
        return Thermal3DUnits(member, d["rho"], d["zeta"], d["flank"], d["shaft"], info)
    from femgear.perf import announce, interruptible

    announce(thermal_estimate(pair, member, spec), "numerics.body_level",
             lambda budget: "choose a coarser numerics.body_level")
    res = interruptible(_compute, pair, member, spec, expansion, youngs_modulus, poisson_ratio, n_rho, n_z)
    if cache:
        save_cache(path, rho=res.rho, zeta=res.zeta, flank=res.flank, shaft=res.shaft, info=json.dumps(res.info))
    return res


def determinate_support_3d(basis, mesh, z_mid: float) -> np.ndarray:
    """Six DOF at bore nodes nearest (r,0), (−r,0), (0,r) in the plane z = ``z_mid``: u_y, u_z at the
    first two, u_x, u_z at the third (translations and rotations, no reaction for a free body)."""
    nodes = np.unique(mesh.facets[:, mesh.boundaries["bore"]])
    p = mesh.p[:, nodes]
    r = float(np.mean(np.hypot(p[0], p[1])))
    ix, iy, iz = (np.asarray(i) for i in basis.split_indices())

    def nearest(x, y):
        return nodes[np.argmin((p[0] - x) ** 2 + (p[1] - y) ** 2 + (p[2] - z_mid) ** 2)]

    a, b, c = nearest(r, 0.0), nearest(-r, 0.0), nearest(0.0, r)
    if len({a, b, c}) < 3:
        raise ValueError("determinate support: the bore has too few nodes")
    # P1: DOF k of component c sits at node k in each component's index array
    return np.array([iy[a], iz[a], iy[b], iz[b], ix[c], iz[c]])


def remove_bore_rigid_motion(model, mesh, U: np.ndarray, z_mid: float, n_angles: int = 72,
                             n_levels: int = 5) -> np.ndarray:
    """U (N, m) minus the rigid motion that fits the bore best (least squares over points at equal angles
    on the bore circle, just inside the body, at levels symmetric about ``z_mid``): the bore keeps its
    centre and its angular position.  A field λ(x, y, z − z_mid) (uniform expansion) fits no rigid
    motion at such points, so it is returned unchanged."""
    from femgear.physics.body.elastic3d import rigid_body_modes_3d

    nodes = np.unique(mesh.facets[:, mesh.boundaries["bore"]])
    r = 1.001 * float(np.max(np.hypot(*mesh.p[:2, nodes])))   # outside the inscribed bore polygon: in the body
    zs = mesh.p[2, nodes]
    half = 0.5 * min(z_mid - zs.min(), zs.max() - z_mid)
    th = np.linspace(0.0, 2 * math.pi, n_angles, endpoint=False)
    TH, ZZ = np.meshgrid(th, z_mid + np.linspace(-half, half, n_levels))
    x = np.vstack([r * np.cos(TH.ravel()), r * np.sin(TH.ravel()), ZZ.ravel()])
    mats = model.probe_matrices(x)
    A = np.vstack([M @ rigid_body_modes_3d(model.basis) for M in mats])          # (3n, 6)
    c, *_ = np.linalg.lstsq(A, np.vstack([M @ U for M in mats]), rcond=None)
    return U - rigid_body_modes_3d(model.basis) @ c


def _compute(pair, member, spec, expansion, E, nu, n_rho, n_z) -> Thermal3DUnits:
    from skfem import Basis

    from femgear.physics.body.conduction import solve_temperature_cases
    from femgear.physics.body.elastic3d import Elastic3D
    from femgear.physics.body.forms import thermal_load, thermal_modulus
    from femgear.physics.ltca.flank import roll_range
    from femgear.physics.mesh.segment import helix_frame, member_body

    t0 = time.perf_counter()
    mesh = member_body(pair, member, spec)
    t_mesh = time.perf_counter() - t0
    frame = helix_frame(pair, member, spec)
    hot = ("flank", "fillet", "tip", "rim")
    _, fields = solve_temperature_cases(mesh, 1.0, [{**{n: f for n in hot if n in mesh.boundaries}, "bore": s}
                                                    for f, s in ((1.0, 0.0), (0.0, 1.0))], order=1)
    temps = [(None, T) for T in fields]
    t_cond = time.perf_counter() - t0 - t_mesh
    from skfem import ElementTetP1, ElementVector

    vb = Basis(mesh, ElementVector(ElementTetP1()), intorder=1)
    model = Elastic3D(mesh, E, nu, order=1, clamped=None, solver="auto",
                      fixed=determinate_support_3d(vb, mesh, 0.5 * frame.width))
    sb = Basis(mesh, ElementTetP1(), quadrature=model.basis.quadrature)
    bT = thermal_modulus(E, nu, expansion, "strain")          # 3-D: (3λ + 2μ) λ_T
    F = np.column_stack([thermal_load.assemble(model.basis, beta_T=bT, dT=sb.interpolate(T)) for _, T in temps])
    U = model.solve_many(F, case=f"3-D thermo-elastic member {member}")
    U = remove_bore_rigid_motion(model, mesh, U, 0.5 * frame.width)
    r0, r1 = roll_range(pair, member)
    rho = np.linspace(r0, r1, n_rho)
    zeta = np.linspace(0.0, pair.b, n_z)
    read = (0, 1) if spec.helices == 2 else (0, 0)     # one helix (single-helical): its row twice, same shape
    vals = np.array([[_flank_reading(pair, member, model, frame, rho, zeta, h, U[:, j]) for h in read]
                     for j in range(2)])
    st = model.stats()
    info = {"seconds": time.perf_counter() - t0, "mesh_seconds": t_mesh, "conduction_seconds": t_cond,
            "factor_seconds": st.setup_seconds, "solve_seconds": st.solve_seconds, "ndofs": int(st.ndofs),
            "factor_mb": 12e-6 * st.factor_nnz,
            "n_tets": int(mesh.t.shape[1]), "h_tooth": spec.h_tooth, "r_bore": spec.r_bore, "cached": False,
            "T_min": float(min(T.min() for _, T in temps)), "T_max": float(max(T.max() for _, T in temps))}
    return Thermal3DUnits(member, rho, zeta, vals[0], vals[1], info)


def _flank_reading(pair, member, model, frame, rho, zeta, helix, u) -> np.ndarray:
    """ζ_n = (u·n_t) cos β_b on the (ρ, ζ) grid of ``helix``, extrapolated to the flank from two depths."""
    from femgear.physics.ltca.compliance import reading_points

    RR, ZZ = np.meshgrid(rho, zeta, indexing="ij")
    d = READ_DEPTH * pair.m_n
    out = []
    for depth in (d, 2 * d):
        x, n = reading_points(pair, member, RR.ravel(), ZZ.ravel(), np.full(RR.size, depth), 0, frame, helix)
        nt = n[:2] / np.linalg.norm(n[:2], axis=0)
        disp = model.probe(u, x)
        out.append(np.sum(disp[:2] * nt, axis=0))
    zt = 2 * out[0] - out[1]
    if not np.all(np.isfinite(zt)):
        raise ValueError(f"3-D thermal reading on helix {helix} of member {member}: a point lies outside the body")
    return (zt * math.cos(pair.beta_b)).reshape(RR.shape)


def fe3d_flank_deviation(pair: GearPair, member: int, u, dT_flank: float, dT_shaft: float, expansion: float,
                         youngs_modulus: float = 210e9, poisson_ratio: float = 0.3, bore_radius: float = 0.0,
                         groove: float = 0.0, stagger: float = 0.0, body_level: int = 1) -> np.ndarray:
    """ζ_T [m] at ``u`` [m], the face mean of the 3-D member body's thermo-elastic growth (the ``fe3d`` level;
    ``groove`` and ``stagger`` shape the body, ``body_level`` its resolution)."""
    _, _, rho = flank_radius(pair, member, u)
    units = thermal_units_3d(pair, member, expansion, youngs_modulus, poisson_ratio, bore_radius, groove, stagger,
                             level=body_level)
    return units.face_mean(rho, dT_flank, dT_shaft)
