"""The FE housing: quadratic tetrahedra on a housing mesh, rigid bearing seats, clamped feet, Craig–Bampton.

:func:`housing_structure` assembles the stiffness and mass of isotropic linear elasticity (scikit-fem,
``ElementVector(ElementTetP2)`` by default: quadratic elements bend a thin wall correctly with one element through
its thickness, where linear ones lock) on a :class:`femgear.physics.mesh.housing.HousingMesh`, clamps the
soles of the feet and makes each bearing seat a rigid ring: every DOF of the seat's nodes follows the seat's
master point (the bearing station on the shaft axis, x_c) as u = t + θ × (x − x_c), six master DOFs per seat
(RBE2-like; the outer ring of a rolling bearing is far stiffer in its plane than the housing wall that carries
it).  The structure's DOFs are then w = (free node DOFs, 6 per seat), u = T w.

:meth:`HousingStructure.reduce` Craig–Bampton-reduces it onto the 12 seat translations (4 stations × x, y, z:
the DOFs the bearings connect to; the seats' rotations are interior DOFs, no bearing restrains them) with a
chosen number of fixed-interface modes (:mod:`femgear.physics.housing.reduction`) and returns a
:class:`ReducedHousing`: the reduced matrices, a modal damping matrix, and the maps from the reduced coordinates
to the sensors, to the outer surface's normal displacement (radiation) and to the displacement of every mesh
vertex (the operating deflection shape).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from femgear.physics.housing.reduction import CraigBampton, craig_bampton, natural_frequencies
from femgear.physics.mesh.housing import STATIONS, HousingMesh


@dataclass(frozen=True)
class HousingMaterial:
    """Isotropic elastic housing material and its damping."""

    youngs_modulus: float      #: E [Pa]
    poisson_ratio: float       #: ν [-]
    density: float             #: ρ [kg/m^3]
    damping_ratio: float = 0.02  #: modal damping ratio of every mode of the housing [-]


@dataclass(frozen=True)
class HousingStructure:
    """The assembled housing in the DOFs w (module docstring), before reduction."""

    K: sp.csr_matrix           #: stiffness in w [N/m]
    M: sp.csr_matrix           #: mass in w [kg]
    T: sp.csr_matrix           #: (N, n_w): node DOFs of the mesh (free, seat and clamped) = T w
    seat_dofs: np.ndarray      #: (4, 6) indices in w of each seat's master (t_x, t_y, t_z, θ_x, θ_y, θ_z) [-]
    vertex_dofs: np.ndarray    #: (3, n_vertices) node-DOF index of each mesh vertex's x, y, z component [-]
    mesh: HousingMesh
    material: HousingMaterial

    @property
    def boundary(self) -> np.ndarray:
        """The 12 seat translations (station-major, x y z) as indices in w."""
        return self.seat_dofs[:, :3].ravel()

    @property
    def n_dofs(self) -> int:
        return int(self.K.shape[0])

    def reduce(self, n_modes: int, sensors: np.ndarray | None = None,
               sensor_directions: np.ndarray | None = None) -> ReducedHousing:
        """Craig–Bampton onto :attr:`boundary` with ``n_modes`` fixed-interface modes (ValueError above what the
        structure holds) and the output maps: ``sensors`` (n_s, 3) points [m] on the outer surface (the nearest
        outer vertex is read), ``sensor_directions`` (n_s, 3) unit directions (None: the outward normal there)."""
        cb = craig_bampton(self.K, self.M, self.boundary, n_modes)
        return _reduced(self, cb, sensors, sensor_directions)


def assemble(mesh, order: int, lam: float, mu: float, rho: float):
    """(basis, K, M) of isotropic elasticity on vector Lagrange tetrahedra of ``order`` (1, 2), vectorised.

    The scalar basis's gradients at the quadrature points (degree 2(order − 1) for K, 2 order for M) give, per
    element, K_(a i)(b j) = Σ_q w_q [μ δ_ij ∇φ_a·∇φ_b + μ ∂_j φ_a ∂_i φ_b + λ ∂_i φ_a ∂_j φ_b] and
    M_(a i)(b j) = ρ δ_ij Σ_q w_q φ_a φ_b, scattered with the vector basis's DOF numbering (local DOF 3a + i:
    component i of scalar function a, as :class:`skfem.ElementVector` orders them).  The same matrices as
    scikit-fem's form assembly at a tenth of its time (``tests/housing/test_fe.py``).
    """
    from skfem import Basis, ElementTetP1, ElementTetP2, ElementVector

    scalar = ElementTetP2() if order == 2 else ElementTetP1()
    vector = Basis(mesh, ElementVector(scalar), intorder=2 * order)
    n_loc = scalar.refdom.nnodes if order == 1 else 10
    dofs = vector.element_dofs                                                   # (3 n_loc, ne)
    sk = Basis(mesh, scalar, intorder=max(1, 2 * (order - 1)))
    g = np.stack([sk.basis[a][0].grad for a in range(n_loc)], axis=0)            # (a, 3, ne, nq)
    dx = sk.dx                                                                   # (ne, nq)
    dot = np.einsum("akeq,bkeq,eq->eab", g, g, dx)
    cross = np.einsum("aieq,bjeq,eq->eaibj", g, g, dx)
    Ke = mu * dot[:, :, None, :, None] * np.eye(3)[None, None, :, None, :] + mu * cross.transpose(0, 1, 4, 3, 2) \
        + lam * cross
    sm = Basis(mesh, scalar, intorder=2 * order)
    phi = np.stack([sm.basis[a][0].value for a in range(n_loc)], axis=0)          # (a, ne, nq)
    me = rho * np.einsum("aeq,beq,eq->eab", phi, phi, sm.dx)
    Me = me[:, :, None, :, None] * np.eye(3)[None, None, :, None, :]
    shape = (vector.N, vector.N)

    def scatter(Ae):
        A = Ae.reshape(-1, 3 * n_loc, 3 * n_loc)
        rows = np.broadcast_to(dofs.T[:, :, None], A.shape).ravel()
        cols = np.broadcast_to(dofs.T[:, None, :], A.shape).ravel()
        return sp.coo_matrix((A.ravel(), (rows, cols)), shape=shape).tocsr()

    return vector, scatter(Ke), scatter(Me)


def housing_structure(hm: HousingMesh, material: HousingMaterial, order: int = 2) -> HousingStructure:
    """Assemble, clamp and tie the seats of the housing mesh ``hm`` (module docstring); ``order`` 1 or 2.

    ValueError naming the station when the mesh does not touch a bearing seat (no nodes on it) or covers less
    than its width, and when the mesh has no feet to clamp.
    """
    E, nu, rho = material.youngs_modulus, material.poisson_ratio, material.density
    if not (E > 0 and 0 < nu < 0.5 and rho > 0 and 0 <= material.damping_ratio < 1):
        raise ValueError(f"housing material out of range: E {E!r}, ν {nu!r}, ρ {rho!r}, ζ {material.damping_ratio!r}")
    mesh = hm.mesh
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    basis, K, M = assemble(mesh, order, lam, mu, rho)
    comp = np.empty(basis.N, dtype=np.int64)
    for c, idx in enumerate(basis.split_indices()):
        comp[idx] = c
    clamped = basis.get_dofs(mesh.boundaries.get("feet", np.zeros(0, dtype=np.int64))).all()
    if clamped.size == 0:
        raise ValueError("the housing mesh has no feet to clamp (boundary 'feet' is empty)")
    seats = [_seat_dofs(hm, basis, j) for j in range(4)]
    T, seat_dofs = _tie(basis.N, basis.doflocs, comp, seats, clamped, hm)
    Kw, Mw = (T.T @ K @ T).tocsr(), (T.T @ M @ T).tocsr()
    vertex_dofs = basis.nodal_dofs.reshape(3, -1) if basis.nodal_dofs.shape[0] == 3 else basis.nodal_dofs
    return HousingStructure(K=0.5 * (Kw + Kw.T), M=0.5 * (Mw + Mw.T), T=T, seat_dofs=seat_dofs,
                            vertex_dofs=vertex_dofs, mesh=hm, material=material)


def _seat_dofs(hm: HousingMesh, basis, j: int) -> np.ndarray:
    """The node DOFs of seat j; ValueError when the mesh does not touch it over its width."""
    g, name = hm.geometry, STATIONS[j]
    facets = hm.mesh.boundaries.get(f"seat_{name}", np.zeros(0, dtype=np.int64))
    x, y = g.axis(j)
    where = f"{name} (axis ({x:.4g}, {y:.4g}) m, z = {g.station_z[j]:.4g} m, bore radius {g.bore_radius[j // 2]:.4g} m)"
    if facets.size == 0:
        raise ValueError(f"the housing mesh does not touch the bearing seat {where}")
    z = hm.mesh.p[2, hm.mesh.facets[:, facets]]
    half, tol = 0.5 * g.bearing_width[j // 2], g.size
    if z.min() > g.station_z[j] - half + tol or z.max() < g.station_z[j] + half - tol:
        raise ValueError(f"the housing mesh touches the bearing seat {where} only over z = {z.min():.4g} … "
                         f"{z.max():.4g} m of its width ±{half:.4g} m")
    return basis.get_dofs(facets).all()


def _tie(N: int, doflocs: np.ndarray, comp: np.ndarray, seats: list[np.ndarray], clamped: np.ndarray, hm: HousingMesh):
    """(T, seat master indices): u = T w with the seat DOFs as rigid rings and the clamped DOFs removed."""
    g = hm.geometry
    tied = np.zeros(N, bool)
    for s in seats:
        if np.any(tied[s]):
            raise ValueError("two bearing seats of the housing share nodes")
        tied[s] = True
    free = np.flatnonzero(~tied & ~np.isin(np.arange(N), clamped))
    rows, cols, vals = list(free), list(range(free.size)), [1.0] * free.size
    seat_dofs = np.arange(free.size, free.size + 24).reshape(4, 6)
    for j, s in enumerate(seats):
        s = s[~np.isin(s, clamped)]
        r = doflocs[:, s] - np.array([*g.axis(j), g.station_z[j]])[:, None]     # (3, n) offsets from the master
        c = comp[s]
        # u_c = t_c + (θ × r)_c: (θ × r)_x = θ_y r_z − θ_z r_y, _y = θ_z r_x − θ_x r_z, _z = θ_x r_y − θ_y r_x
        rows += list(s)
        cols += list(seat_dofs[j, c])
        vals += [1.0] * s.size
        for ci, (a, b, ra, rb) in enumerate(((4, 5, 2, 1), (5, 3, 0, 2), (3, 4, 1, 0))):
            sel = c == ci
            rows += list(s[sel]) * 2
            cols += list(np.full(sel.sum(), seat_dofs[j, a])) + list(np.full(sel.sum(), seat_dofs[j, b]))
            vals += list(r[ra, sel]) + list(-r[rb, sel])
    T = sp.csr_matrix((vals, (rows, cols)), shape=(N, free.size + 24))
    return T, seat_dofs


@dataclass(frozen=True)
class ReducedHousing:
    """A Craig–Bampton housing ready to couple: coordinates (12 seat translations, η), and its output maps."""

    K: np.ndarray              #: reduced stiffness [N/m]
    M: np.ndarray              #: reduced mass [kg]
    C: np.ndarray              #: modal damping: ratio ``damping_ratio`` on every mode of (K, M) [N s/m]
    fixed_interface_hz: np.ndarray  #: frequencies of the retained fixed-interface modes [Hz]
    sensor_points: np.ndarray  #: (n_s, 3) the outer vertices read as sensors [m]
    sensor_directions: np.ndarray  #: (n_s, 3) the sensors' unit directions [-]
    sensor_map: np.ndarray     #: (n_s, n) sensor displacement along its direction per reduced coordinate [-]
    surface_area: np.ndarray   #: (n_o,) area lumped on each outer-surface vertex [m^2]
    outer_vertices: np.ndarray  #: (n_o,) mesh-vertex index of each outer-surface vertex [-]
    surface_normal_map: np.ndarray  #: (n_o, n) outward normal displacement of each outer vertex [-]
    vertex_map: np.ndarray     #: (3 n_vertices, n) displacement of every mesh vertex, x y z interleaved [-]
    points: np.ndarray         #: (3, n_vertices) mesh vertices [m]
    cells: np.ndarray          #: (4, n_tets) tetrahedra (vertex indices) [-]
    full_dofs: int             #: DOFs of the unreduced structure [-]
    damping_ratio: float       #: ζ of every housing mode [-]
    mass: float                #: the housing's mass, ρ × its volume [kg]

    @property
    def n(self) -> int:
        return int(self.K.shape[0])

    def frequencies(self) -> np.ndarray:
        """Natural frequencies of the reduced housing, seats free [Hz]."""
        return natural_frequencies(self.K, self.M)


def modal_damping(K: np.ndarray, M: np.ndarray, ratio: float) -> np.ndarray:
    """C = M Φ diag(2 ζ ω_k) Φᵀ M (Φ mass-normalised): damping ratio ``ratio`` on every mode of (K, M)."""
    from scipy.linalg import eigh

    w2, phi = eigh(K, M)
    Mphi = M @ phi
    return (Mphi * (2 * ratio * np.sqrt(np.clip(w2, 0.0, None)))) @ Mphi.T


def _reduced(st: HousingStructure, cb: CraigBampton, sensors, directions) -> ReducedHousing:
    mesh = st.mesh.mesh
    # the map of the reduced coordinates to the node DOFs of the vertices: T (vertex rows) · [expand of w]
    vrows = st.vertex_dofs.T.ravel()                                           # x, y, z per vertex
    Tv = st.T[vrows]
    used = np.unique(Tv.indices)
    vertex_map = Tv[:, used] @ cb.expand(used)
    area, normal, outer_vertices = _outer_surface(mesh)
    nmap = np.einsum("vc,vcn->vn", normal, vertex_map.reshape(-1, 3, cb.n)[outer_vertices])
    pts, dirs, smap = _sensors(mesh, vertex_map, outer_vertices, normal, sensors, directions)
    return ReducedHousing(K=cb.K, M=cb.M, C=modal_damping(cb.K, cb.M, st.material.damping_ratio),
                          fixed_interface_hz=cb.fixed_interface_hz, sensor_points=pts, sensor_directions=dirs,
                          sensor_map=smap, surface_area=area, outer_vertices=outer_vertices, surface_normal_map=nmap,
                          vertex_map=vertex_map, points=mesh.p, cells=mesh.t, full_dofs=st.n_dofs,
                          damping_ratio=st.material.damping_ratio, mass=st.material.density * _volume(mesh))


def _volume(mesh) -> float:
    """Volume of a tetrahedral mesh [m^3]."""
    x = mesh.p[:, mesh.t]                                                     # (3, 4, ne)
    return float(np.abs(np.linalg.det(np.transpose(x[:, 1:] - x[:, :1], (2, 0, 1)))).sum() / 6.0)


def _outer_surface(mesh) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(area per outer vertex, (n_o, 3) outward unit normal, vertex indices) of the ``outer`` boundary: facet
    areas and area-weighted normals lumped on the vertices (a third each)."""
    facets = mesh.boundaries["outer"]
    tri = mesh.facets[:, facets]                                              # (3, nf)
    a, b, c = (mesh.p[:, tri[k]] for k in range(3))
    n = np.cross((b - a).T, (c - a).T)                                        # (nf, 3), |n| = 2 area
    centroid = (a + b + c).T / 3
    # orient outward: away from the adjacent tetrahedron's fourth vertex
    t = mesh.t[:, mesh.f2t[0, facets]]
    inside = mesh.p[:, t].mean(axis=1).T
    n *= np.sign(np.einsum("fc,fc->f", n, centroid - inside))[:, None]
    verts = np.unique(tri)
    pos = np.searchsorted(verts, tri)
    area = np.zeros(verts.size)
    normal = np.zeros((verts.size, 3))
    for k in range(3):
        np.add.at(area, pos[k], np.linalg.norm(n, axis=1) / 6)
        np.add.at(normal, pos[k], n)
    return area, normal / np.linalg.norm(normal, axis=1, keepdims=True), verts


def _sensors(mesh, vertex_map, outer, normal, sensors, directions):
    """The outer vertices nearest ``sensors`` and their direction maps; ValueError for a point farther than the
    local element size from the outer surface."""
    n = vertex_map.shape[1]
    if sensors is None or len(sensors) == 0:
        return np.zeros((0, 3)), np.zeros((0, 3)), np.zeros((0, n))
    sensors = np.atleast_2d(np.asarray(sensors, dtype=float))
    xo = mesh.p[:, outer].T
    d = np.linalg.norm(xo[None] - sensors[:, None], axis=2)
    k = d.argmin(axis=1)
    edge = np.linalg.norm(np.diff(mesh.p[:, mesh.t[:2]], axis=1)[:, 0], axis=0).max()
    for s, (kk, p) in enumerate(zip(k, sensors)):
        if d[s, kk] > edge:
            raise ValueError(f"sensor {s + 1} at {p.tolist()} m is {d[s, kk]:.3g} m from the housing's outer surface")
    dirs = normal[k] if directions is None else np.atleast_2d(np.asarray(directions, dtype=float))
    if dirs.shape != sensors.shape or np.any(np.linalg.norm(dirs, axis=1) == 0):
        raise ValueError("sensor directions must be one non-zero (x, y, z) per sensor")
    dirs = dirs / np.linalg.norm(dirs, axis=1, keepdims=True)
    rows = vertex_map.reshape(-1, 3, n)[outer[k]]                              # (n_s, 3, n)
    return xo[k], dirs, np.einsum("sc,scn->sn", dirs, rows)


def housing_frf(red: ReducedHousing, frequency: np.ndarray, sensors: tuple[str, ...]):
    """The FE housing's own receptances as an :class:`~femgear.physics.housing.frf.FRFSet` at ``frequency`` [Hz]:
    inputs the 12 seat DOFs, outputs the seats and the sensors (named ``sensors``, along their directions)."""
    from femgear.physics.housing.frf import SEAT_DOFS, FRFSet

    f = np.asarray(frequency, dtype=float)
    H = np.zeros((f.size, 12 + len(sensors), 12), dtype=complex)
    for k, fk in enumerate(f):
        w = 2 * np.pi * fk
        Y = np.linalg.solve(red.K + 1j * w * red.C - w**2 * red.M, np.eye(red.n)[:, :12])
        H[k] = np.vstack([Y[:12], red.sensor_map @ Y])
    return FRFSet(frequency=f, H=H, outputs=SEAT_DOFS + tuple(sensors), inputs=SEAT_DOFS, source="FE housing")
