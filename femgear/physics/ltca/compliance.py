"""Flank compliance of one member: FE bulk influence coefficients minus their half-space part.

Method (the FE + surface-integral split of the LDP/Calyx family; Vijayakar, IJNME 31:525,
1991; Andersson & Vedmar, JSV 260:195, 2003 for reading the FE below the surface and
subtracting the half-space part it already holds):

    C = R (G^FE_d − G^HS_d) Rᵀ + H₀

- The member is one body holding both helices, the groove and the rim down to the bore
  (:func:`femgear.physics.mesh.segment.member_body`).  Unit normal loads, one per node g of a (ρ, ζ)
  grid on the loaded flank of the left helix's middle tooth, spread as bilinear hats φ_g
  (total force 1 N); one factorisation (CHOLMOD, else SuperLU) or SA hierarchy
  (:class:`femgear.physics.body.elastic3d.Elastic3D`) serves all of them, solved in blocks of right-hand
  sides.  Before a body is built its DOF, memory and time are estimated and announced
  (:func:`build_estimate`, :func:`femgear.perf.announce`; ``docs/cost.md``).
- G^FE_d[k][g′, g]: approach (displacement along −n) at depth d(g′) below node g′ of
  tooth k (k = −(n−1)/2 … (n−1)/2, cyclic offsets) for load g on tooth 0, read on the loaded
  helix (``bulk``) and on the other helix at the same (ρ, ζ) (``cross``: the helices' coupling
  through the groove and the rim, which a one-helix segment drops).
- G^HS_d[g′, g]: the same reading for an elastic half-space under the same hat load
  (Boussinesq at depth, summed over the FE's own flank quadrature points), tooth 0 only,
  subtracted from both readings (near the apex of a grooveless body the two helices' tooth 0
  are one surface; :mod:`femgear.physics.ltca.contact` adds the surface part H₀ back between them).
- The differences are smooth (bending, shear, fillet, rim, neighbour teeth, the other helix)
  and are interpolated bilinearly (R) to contact points; H₀, the half-space surface response
  between contact points of the same tooth (Hertz strips), is added by
  :mod:`femgear.physics.ltca.contact`.
- Right helix.  A body without stagger is the mirror image of itself (z → 2b + g − z): the
  right helix's own kernels are the left ones, and mirror symmetry with Maxwell–Betti gives
  X[k] = X[−k]ᵀ for the cross kernel (the mean of the two is kept, so symmetric helices share
  the load exactly).  A staggered body is not symmetric: the right helix is loaded too (twice
  the solves) and gets its own kernels (``bulk_right``).
- One helix.  A single-helical (or spur) member is a body of that one helix of the real face width
  (``SegmentSpec.helices`` = 1): the unit loads are read on it alone, and there is no cross kernel.

Element order and resolution (baseline pair, 7 × 9 grid, 64 phases, 200 N m, unmodified;
``python studies/ltca/ltca_study.py``; member bodies down to the 20 mm shaft): P1 levels 1/2/3/4
(34 k … 139 k DOF pinion) give a mean mesh stiffness of 7.131/7.026/6.955/6.914e8 N/m and LTE
p-p 0.5226/0.5275/0.5414/0.5415 µm (the two finest differ by 0.60 % and 0.03 %); Richardson
puts level 1 at +4.9 % in stiffness.  P1 is this module's own default (``order=1``; level 1: mesh +
compliance ≈ 23–36 s for both members with the sparse LU); its bias is stiff, as expected of linear
tetrahedra in bending, so the ``ltca`` stiffness level defaults to ``order="p2-bending"`` at level 0
(``numerics.body_elements``, ``numerics.body_level``) and takes P1 only where a scene asks for it.  P2 converges much faster per element but
costs ≈ 21 s a unit load with SA-AMG on the bodies (176 k DOF at level 0): on a 5 × 7 grid P1
level 1 / P1 level 3 / P2 level 0 give 7.119 / 6.954 / 6.742e8 N/m and LTE p-p 0.536 / 0.556 /
0.564 µm (P1 level 1: +5.6 % / −4.9 % against P2; build 25 s / 183 s / 1503 s;
``python studies/ltca/ltca_element_order.py --ltca``).  ``order="p2-bending"``
(``numerics.body_elements``): P2 (hierarchical, :class:`femgear.physics.body.mixed3d.MixedElastic3D`) in the
loaded tooth down to :data:`ZONE_DEPTH` m_n below its root and in the rim below :data:`RIM_DEPTH` m_n
(:func:`bending_elements`), P1 elsewhere; on the baseline at level 0 it costs ≈ 1.9× the DOF of P1 at
the same level and gives k mean within 0.8 % of its level-2 value (``docs/cost.md``, "P2 where the body bends").

d(g′) = min(depth, ½ the half tooth thickness there), so the reading stays inside the
tooth near the tip.  The default depth is a fixed 0.4 m_n, not a multiple of the element
size: a depth that shrinks with the mesh moves the target of a refinement study (the
reading then converges to a different split at every level).  The split is insensitive
to the depth where the FE is converged: one mid-flank unit load on the baseline pinion's body,
P2 level 1 (252 k DOF), gives bulk = 10.93/10.91/11.04e-10 m/N at d = 0.7/0.9/1.2 mm, while P1
at level 5 (206 k DOF) is still 9 % below at 1.2 mm (P1 tetrahedra are stiff in bending)
(``python studies/ltca/ltca_element_order.py --split``).  Results are cached on disk (``out/cache/ltca`` or
``$FEMGEAR_CACHE``) under a hash of geometry, material, mesh and grid.
"""

from __future__ import annotations

import hashlib
import json
import logging
import os
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from femgear.perf import LONG_STAGE_SECONDS, NOTICE, Estimate, Progress, announce, interruptible
from femgear.physics.body.elastic3d import SOLVE_CHUNK
from femgear.physics.geometry.gear import GearPair
from femgear.physics.ltca.flank import flank_normals, flank_points, half_thickness, roll_range
from femgear.physics.ltca.halfspace import boussinesq_depth
from femgear.physics.mesh.segment import SegmentSpec

log = logging.getLogger(__name__)

CACHE_VERSION = 3     #: 3: both helices, the groove and the rim down to the bore in one body (cross kernels)
DEFAULT_DEPTH = 0.4    #: reading depth below the flank, in normal modules (clipped near the tip)
SOLVE_TOL = 1e-8       #: relative residual of the SA-CG unit-load solves
BENDING = "p2-bending"  #: ``order`` of P2 where the body bends, P1 elsewhere (:func:`bending_elements`)
ORDERS = (1, 2, BENDING)
ZONE_DEPTH = 1.0       #: the loaded tooth is quadratic down to this many m_n below its root circle
RIM_DEPTH = 3.0        #: and the rim below this many m_n under the root circle (all round, the whole face)


@dataclass(frozen=True)
class MemberCompliance:
    """Bulk influence kernels of one member's loaded flanks [m/N] (grid index i_rho*n_z + i_z)."""

    member: int
    rho: np.ndarray          #: grid roll distances [m]
    z: np.ndarray            #: grid face coordinates ζ of a helix [m]
    offsets: np.ndarray      #: tooth offsets k of the kernels
    bulk: np.ndarray         #: (n_offsets, n_grid, n_grid): left helix, response on tooth k, load on tooth 0
    fe_self: np.ndarray      #: G^FE_d on tooth 0 of the left helix (diagnostics)
    depth: np.ndarray        #: reading depth per grid node [m]
    ndofs: int
    info: dict = field(default_factory=dict)
    cross: np.ndarray | None = None       #: (n_offsets, n_grid, n_grid): right helix's tooth k read, left tooth 0 loaded
    bulk_right: np.ndarray | None = None  #: the right helix's own kernels; None: the left ones (mirror-symmetric body)
    groove: float = 0.0                   #: groove width g of the body [m]
    fe_cross: np.ndarray | None = None    #: G^FE_d on the right helix's tooth 0, left tooth 0 loaded (diagnostics)

    def kernel(self, offset: int, helix: int = 0) -> np.ndarray:
        """Same-helix kernel at tooth ``offset`` of helix 0 (left) or 1 (right)."""
        hit = np.nonzero(self.offsets == offset)[0]
        if hit.size == 0:
            return np.zeros(self.bulk.shape[1:])
        kern = self.bulk_right if helix == 1 and self.bulk_right is not None else self.bulk
        return kern[hit[0]]

    def cross_kernel(self, offset: int) -> np.ndarray:
        """Cross-helix kernel: reading on the right helix's tooth ``offset``, unit loads on the left tooth 0."""
        hit = np.nonzero(self.offsets == offset)[0]
        if self.cross is None or hit.size == 0:
            return np.zeros(self.bulk.shape[1:])
        return self.cross[hit[0]]

    def weights(self, rho: np.ndarray, z: np.ndarray) -> np.ndarray:
        """Bilinear interpolation matrix R (n_points, n_grid) at (ρ, z), clamped to the grid."""
        return _bilinear(self.rho, self.z, np.asarray(rho, float), np.asarray(z, float))


def _hat_1d(nodes: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Piecewise-linear hat functions of ``nodes`` at ``x``: (n_nodes, n_x), zero outside the grid."""
    H = np.zeros((nodes.size, x.size))
    for i in range(nodes.size):
        if i > 0:
            s = (x >= nodes[i - 1]) & (x <= nodes[i])
            H[i, s] = (x[s] - nodes[i - 1]) / (nodes[i] - nodes[i - 1])
        if i < nodes.size - 1:
            s = (x >= nodes[i]) & (x <= nodes[i + 1])
            H[i, s] = (nodes[i + 1] - x[s]) / (nodes[i + 1] - nodes[i])
    return H


def _bilinear(gr: np.ndarray, gz: np.ndarray, rho: np.ndarray, z: np.ndarray) -> np.ndarray:
    Hr = _hat_1d(gr, np.clip(rho, gr[0], gr[-1]))
    Hz = _hat_1d(gz, np.clip(z, gz[0], gz[-1]))
    return (Hr[:, None, :] * Hz[None, :, :]).reshape(gr.size * gz.size, -1).T


def cache_dir() -> Path:
    return Path(os.environ.get("FEMGEAR_CACHE", "out/cache/ltca"))


def cache_key(payload: dict) -> str:
    """Short hash of a JSON-able ``payload`` (geometry, material, mesh, …) naming a cache file."""
    return hashlib.sha256(json.dumps(payload, sort_keys=True).encode()).hexdigest()[:20]


def save_cache(path: Path, **arrays) -> None:
    """Write ``arrays`` to the ``.npz`` cache file ``path`` atomically: a temporary file of a name unique to this
    writer (two sweep workers building the same entry must not write into one file), then a rename."""
    import tempfile

    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.stem}.", suffix=".tmp.npz")
    try:
        with os.fdopen(fd, "wb") as fh:
            np.savez(fh, **arrays)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _key(pair: GearPair, member: int, spec: SegmentSpec, E: float, nu: float, order: int | str,
         n_rho: int, n_z: int, depth: float) -> str:
    from femgear.physics.mesh.segment import mesh_revision

    payload = {"v": CACHE_VERSION, "pair": pair.identity(), "member": member, "spec": spec.key(),
               "E": E, "nu": nu, "order": order, "grid": [n_rho, n_z], "depth": depth}
    revision = mesh_revision(pair, member, spec)
    if revision is not None:      # the far-field rule or the graded groove changed this body's mesh
        payload["mesh"] = revision
    return cache_key(payload)


def cache_path(pair: GearPair, member: int, spec: SegmentSpec, youngs_modulus: float, poisson_ratio: float,
               order: int | str = 1, n_rho: int = 7, n_z: int = 9, depth: float | None = None) -> Path:
    """The disk-cache file of :func:`member_compliance` with these arguments (it may not exist)."""
    d0 = depth if depth is not None else DEFAULT_DEPTH * pair.m_n
    key = _key(pair, member, spec, youngs_modulus, poisson_ratio, order, n_rho, n_z, d0)
    return cache_dir() / f"member{member}-{key}.npz"


def member_compliance(pair: GearPair, member: int, spec: SegmentSpec, youngs_modulus: float,
                      poisson_ratio: float, order: int | str = 1, n_rho: int = 7, n_z: int = 9,
                      depth: float | None = None, cache: bool = True) -> MemberCompliance:
    """Bulk flank kernels of ``member`` (1 pinion, 2 gear), from the disk cache when present.

    ``order``: 1 or 2 (P1 or P2 everywhere) or :data:`BENDING` (P2 in :func:`bending_elements`, P1 elsewhere).
    """
    d0 = depth if depth is not None else DEFAULT_DEPTH * pair.m_n
    path = cache_path(pair, member, spec, youngs_modulus, poisson_ratio, order, n_rho, n_z, d0)
    if cache and path.exists():
        data = np.load(path, allow_pickle=False)
        info = json.loads(str(data["info"]))
        info["cached"] = True
        right = data["bulk_right"] if data["bulk_right"].size else None
        cross = data["cross"] if data["cross"].size else None          # a one-helix body has no cross kernel
        return MemberCompliance(member, data["rho"], data["z"], data["offsets"], data["bulk"], data["fe_self"],
                                data["depth"], int(data["ndofs"]), info, cross, right, float(data["groove"]),
                                data["fe_cross"] if data["fe_cross"].size else None)
    if order not in ORDERS:
        raise ValueError(f"order must be one of {ORDERS}, got {order!r}")
    estimate = build_estimate(pair, member, spec, order, n_rho * n_z * (1 if spec.stagger == 0 else 2))
    announce(estimate, "numerics.body_level", lambda budget: "choose a coarser numerics.body_level")
    result = interruptible(_compute, pair, member, spec, youngs_modulus, poisson_ratio, order, n_rho, n_z, d0,
                           estimate)
    if cache:
        def stored(a):
            return np.zeros(0) if a is None else a

        save_cache(path, rho=result.rho, z=result.z, offsets=result.offsets, bulk=result.bulk, fe_self=result.fe_self,
                   depth=result.depth, ndofs=result.ndofs, info=json.dumps(result.info), cross=stored(result.cross),
                   bulk_right=stored(result.bulk_right), groove=result.groove, fe_cross=stored(result.fe_cross))
    return result


def flank_unit_loads(pair: GearPair, member: int, model, grid_rho: np.ndarray, grid_z: np.ndarray, helix: int = 0,
                     frame=None):
    """Load vectors of unit normal hat loads (1 N each) at the (ρ, ζ) grid nodes of a helix's loaded flank.

    ``helix`` 0 (left, region ``loaded_flank``) or 1 (right, ``loaded_flank_right``, ζ = 2b + g − z from
    ``frame``, a :class:`femgear.physics.mesh.segment.HelixFrame`).  Returns (loads, xq, weights): ``loads[g]`` the
    FE load vector of node g (grid index i_ρ·n_z + i_z), ``xq`` (3, n_q) the flank quadrature points and
    ``weights[g]`` (n_q,) the share of node g's 1 N carried by each quadrature point.
    """
    from skfem import LinearForm

    mesh = model.mesh
    rb = pair.rb1 if member == 1 else pair.rb2
    region = "loaded_flank" if helix == 0 else "loaded_flank_right"
    fb = model.facet_basis(mesh.boundaries[region])
    xq = np.asarray(fb.global_coordinates())                      # (3, n_facets, n_qp)
    rq = np.sqrt(np.maximum(xq[0] ** 2 + xq[1] ** 2 - rb**2, 0.0))
    zeta = xq[2] if helix == 0 else frame.z_of(xq[2], 1)
    hats = _bilinear(grid_rho, grid_z, rq.ravel(), zeta.ravel()).T.reshape(grid_rho.size * grid_z.size, *rq.shape)
    dA = fb.dx                                                # (n_facets, n_qp) quadrature weights × area

    @LinearForm
    def pressure(v, w):                                       # traction −p n (into the tooth)
        return -w.p * (w.n[0] * v[0] + w.n[1] * v[1] + w.n[2] * v[2])

    loads, weights = [], []
    for g in range(hats.shape[0]):
        area = float(np.sum(hats[g] * dA))
        if area <= 0:
            raise ValueError(f"flank grid node {g} carries no flank area: the {region} region misses the active flank")
        loads.append(model.lift(pressure.assemble(fb, p=hats[g] / area)))
        weights.append((hats[g] * dA).ravel() / area)
    return loads, xq.reshape(3, -1), weights


def halfspace_reading(x: np.ndarray, normals: np.ndarray, xq: np.ndarray, weight: np.ndarray, E: float,
                      nu: float) -> np.ndarray:
    """Half-space approach at points ``x`` (3, n) below flank points of normals ``normals`` for one hat load
    spread over the quadrature points ``xq`` with ``weight`` (Boussinesq at depth, tangent-plane distances)."""
    s = weight > 0
    v = x[:, :, None] - xq[:, s][:, None, :]                       # (3, n, n_q)
    dn = -np.einsum("ig,igq->gq", normals, v)                      # depth below the tangent plane
    r = np.sqrt(np.maximum(np.sum(v**2, axis=0) - dn**2, 0.0))
    return boussinesq_depth(r, dn, E, nu) @ weight[s]


def reading_points(pair: GearPair, member: int, rho: np.ndarray, z: np.ndarray, depth: np.ndarray, tooth: int = 0,
                   frame=None, helix: int = 0):
    """(points (3, n) at ``depth`` below the flank of ``tooth``, outward normals (3, n)).

    ``helix`` 1: the right helix of the body ``frame`` (:class:`femgear.physics.mesh.segment.HelixFrame`): the left
    helix's points at the same (ρ, ζ) turned by the stagger angle Δ and mirrored to z = 2b + g − ζ.
    """
    p = flank_points(pair, member, rho, z, tooth)
    n = flank_normals(pair, member, rho, z, tooth)
    x = p - depth * _transverse(n)
    x[2] = np.clip(x[2], 1e-6 * pair.b, (1 - 1e-6) * pair.b)   # end-face nodes: just inside
    if helix == 0:
        return x, n
    return frame.to_right(x), frame.to_right(n, direction=True)


def _readings(model, probes, u):
    """Approach (−u·n) at every probe set [(matrices, normals), …] → (n_sets, n_points)."""
    out = []
    for mats, n in probes:
        disp = np.vstack([M @ u for M in mats])
        out.append(-np.sum(disp * n, axis=0))
    return np.array(out)


def _influence(pair, member, model, frame, grid, depth, offsets, loaded_helices, E, nu, progress_seconds=0.0,
               read_helices=(0, 1)):
    """Kernels of the loaded helices: {(read helix, loaded helix): G (n_off, n_grid, n_grid)}, and the
    half-space parts [HS_self, HS_cross] of the readings on tooth 0 of the left and the right helix for
    loads on the left tooth 0, one column per grid node (``read_helices`` (0,): a one-helix body, [HS_self])."""
    grid_rho, grid_z, rho_g, z_g = grid
    probes = {h: [(model.probe_matrices(x), n) for x, n in
                  (reading_points(pair, member, rho_g, z_g, depth, int(k), frame, h) for k in offsets)]
              for h in read_helices}
    G = {}
    HS = None
    for hl in loaded_helices:
        loads, xq, weights = flank_unit_loads(pair, member, model, grid_rho, grid_z, hl, frame)
        for h in read_helices:
            G[(h, hl)] = np.zeros((offsets.size, rho_g.size, rho_g.size))
        progress = Progress(f"LTCA unit loads, {'pinion' if member == 1 else 'gear'} body, helix {hl}", len(loads),
                            expected_seconds=progress_seconds)
        for lo in range(0, len(loads), SOLVE_CHUNK):      # a block at a time: the displacements are read, not kept
            U = model.solve_many(np.column_stack(loads[lo:lo + SOLVE_CHUNK]),
                                 case=f"flank compliance member {member}, helix {hl}",
                                 progress=lambda done, lo=lo: progress(lo + done))
            for j in range(U.shape[1]):
                for h in read_helices:
                    G[(h, hl)][:, :, lo + j] = _readings(model, probes[h], U[:, j])
        if hl == 0:
            HS = [np.column_stack([halfspace_reading(x0, n0, xq, weights[g], E, nu) for g in range(rho_g.size)])
                  for x0, n0 in (reading_points(pair, member, rho_g, z_g, depth, 0, frame, h) for h in read_helices)]
    return G, HS


def build_estimate(pair: GearPair, member: int, spec: SegmentSpec, order: int | str = 1,
                   n_loads: int = 63) -> Estimate:
    """Expected DOF, peak memory and time of one member's kernels (:func:`member_compliance`, not cached).

    The DOF come from the body's section (:func:`femgear.physics.mesh.segment.body_size`, exact for P1); memory and
    time from :func:`femgear.physics.body.elastic3d.solve_cost`, measured on this 2-core machine (``docs/cost.md``).
    """
    from femgear.physics.body.elastic3d import solve_cost
    from femgear.physics.mesh.segment import body_size

    nodes, tets = body_size(pair, member, spec)
    if order == BENDING:
        dofs = 3 * nodes + int(3.1 * tets * _zone_share(pair, member, spec))   # bubbles: 3 per free edge
    else:
        dofs = 3 * (nodes if order == 1 else nodes + int(1.2 * tets))
    memory, seconds = solve_cost(dofs, tets, 1 if order == 1 else 2, n_loads)
    name = "pinion" if member == 1 else "gear"
    label = BENDING if order == BENDING else f"P{order}"
    return Estimate(f"LTCA {name} body ({label}, h_tooth = m_n/{pair.m_n / spec.h_tooth:.3g})", dofs, memory,
                    seconds)


def _zone_share(pair: GearPair, member: int, spec: SegmentSpec) -> float:
    """Share of the body's elements that :func:`bending_elements` makes quadratic, from its section's triangles
    (those of the far field count once per ``coarse_step`` layers: an estimate, transition columns aside)."""
    from femgear.physics.mesh.segment import body_section, coarse_step, far_triangles, section_zone

    sec = body_section(pair, member, spec)
    step = coarse_step(pair, spec)
    weight = np.where(far_triangles(pair, member, sec, spec), 1.0 / step, 1.0) if step > 1 else np.ones(sec.t.shape[1])
    c = sec.p[:, sec.t].mean(axis=1)
    tooth, below = section_zone(pair, member, c[0], c[1], depth=ZONE_DEPTH, rim=RIM_DEPTH)
    loaded = 1 if spec.stagger == 0 else 2
    width = 2 + spec.groove / pair.b if spec.helices == 2 else 1.0     # the body's width in face widths
    share = np.sum(weight * below) + np.sum(weight * tooth) * loaded / width
    return float(share / np.sum(weight))


def bending_elements(mesh, pair: GearPair, member: int, spec: SegmentSpec) -> np.ndarray:
    """The quadratic elements of the ``p2-bending`` body (bool per tetrahedron): the loaded middle tooth (of the
    left helix; of both on a staggered body, where both are loaded) down to :data:`ZONE_DEPTH` m_n below its
    root circle, and the rim below :data:`RIM_DEPTH` m_n under it, all round and over the whole face.

    Where that choice comes from (``docs/cost.md``, "P2 where the body bends"): the loaded tooth's own
    compliance is what the unit loads read, and it bends; its neighbours only carry readings (rigid motion
    on the rim); the rim — coarse P1 elements far from the teeth — was the other stiff part (the baseline:
    k mean 7.012e8 N/m with the tooth alone quadratic, 6.859e8 with the rim too, at level 0).
    """
    from femgear.physics.mesh.segment import bending_zone

    helices = (0,) if spec.stagger == 0 or spec.helices == 1 else (0, 1)
    return bending_zone(mesh, pair, member, spec, teeth=1, depth=ZONE_DEPTH, helices=helices, rim=RIM_DEPTH)


def _body_model(mesh, pair, member, spec, E, nu, order):
    from femgear.physics.body.elastic3d import Elastic3D
    from femgear.physics.body.mixed3d import MixedElastic3D

    if order == BENDING:
        return MixedElastic3D(mesh, E, nu, bending_elements(mesh, pair, member, spec), clamped="bore", tol=SOLVE_TOL)
    return Elastic3D(mesh, E, nu, order=order, clamped="bore", tol=SOLVE_TOL, solver="auto")


def _compute(pair, member, spec, E, nu, order, n_rho, n_z, d0, estimate: Estimate) -> MemberCompliance:
    from femgear.physics.body.elastic3d import solver_name
    from femgear.physics.mesh.segment import helix_frame, member_body

    t0 = time.perf_counter()
    mesh = member_body(pair, member, spec)
    t_mesh = time.perf_counter() - t0
    frame = helix_frame(pair, member, spec)
    model = _body_model(mesh, pair, member, spec, E, nu, order)
    log.log(NOTICE if estimate.seconds > LONG_STAGE_SECONDS else logging.INFO,
            f"{estimate.stage}: meshed and assembled ({model.free.size / 1e3:.0f} k DOF, "
            f"{time.perf_counter() - t0:.0f} s); {solver_name(model.solver)} factor and {n_rho * n_z} unit loads next")
    r0, r1 = roll_range(pair, member)
    grid_rho = np.linspace(r0, r1, n_rho)
    grid_z = np.linspace(0.0, pair.b, n_z)
    RR, ZZ = np.meshgrid(grid_rho, grid_z, indexing="ij")
    rho_g, z_g = RR.ravel(), ZZ.ravel()
    depth = np.minimum(d0, 0.5 * half_thickness(pair, member, rho_g))
    half = (spec.n_teeth - 1) // 2
    offsets = np.arange(-half, half + 1)
    symmetric = spec.stagger == 0          # mirror-symmetric body: the right helix's kernels are the left ones
    read = (0, 1) if spec.helices == 2 else (0,)
    G, HS = _influence(pair, member, model, frame, (grid_rho, grid_z, rho_g, z_g), depth, offsets,
                       (0,) if symmetric else (0, 1), E, nu, estimate.seconds, read)
    mid = int(np.nonzero(offsets == 0)[0][0])
    bulk = G[(0, 0)].copy()
    bulk[mid] -= HS[0]
    cross = right = fe_cross = None
    if spec.helices == 2:
        cross, fe_cross = G[(1, 0)].copy(), G[(1, 0)][mid]
        cross[mid] -= HS[1]                # across the apex / groove: H₀ adds the surface part back (contact.py)
    if spec.helices == 2 and symmetric:    # mirror + reciprocity: X[k] = X[−k]ᵀ exactly; the mean keeps the swap symmetry
        cross = 0.5 * (cross + np.transpose(cross[::-1], (0, 2, 1)))
    elif spec.helices == 2:
        right = G[(1, 1)].copy()
        right[mid] -= HS[0]                # the mirrored flank and reading: the same half-space part
    st = model.stats()
    same = G[(0, 0)][mid]
    info = {"mesh_seconds": t_mesh, "assembly_seconds": st.assembly_seconds, "setup_seconds": st.setup_seconds,
            "solve_seconds": st.solve_seconds, "solves": st.solves, "cg_iterations": st.iterations,
            "seconds": time.perf_counter() - t0, "n_tets": int(mesh.t.shape[1]), "order": order,
            "h_tooth": spec.h_tooth, "cached": False,
            "cross_ratio": 0.0 if cross is None else float(np.abs(cross).max() / np.abs(bulk).max()),
            "asymmetry": float(np.linalg.norm(same - same.T) / np.linalg.norm(same)),   # load ≠ reading functional
            "helices": spec.helices}
    return MemberCompliance(member, grid_rho, grid_z, offsets, bulk, same, depth, st.ndofs, info, cross, right,
                            spec.groove, fe_cross)


def _transverse(n: np.ndarray) -> np.ndarray:
    """Unit transverse part of the normals (3, n): the reading depth direction (stays in the section)."""
    t = n.copy()
    t[2] = 0.0
    return t / np.linalg.norm(t, axis=0)


def mean_self_compliance(c: MemberCompliance) -> float:
    """Mean of the diagonal bulk compliance [m/N] (diagnostic)."""
    mid = int(np.nonzero(c.offsets == 0)[0][0])
    return float(np.mean(np.diag(c.bulk[mid])))


__all__ = ["MemberCompliance", "member_compliance", "cache_dir", "cache_key", "cache_path", "save_cache",
           "mean_self_compliance", "build_estimate", "bending_elements", "BENDING", "ORDERS"]
