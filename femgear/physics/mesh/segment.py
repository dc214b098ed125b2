"""3-D tetrahedral body of a gear member: both helices and the groove (one helix for a single-helical pair), the rim
down to the bore.

The transverse section of :func:`femgear.physics.mesh.section.gear_section` (rack-generated
involute + trochoid fillet, ``n_teeth`` teeth on a whole ring — the root circle goes on round
outside them —, the rim down to the clamped bore circle) is meshed with a size field that is
fine (``h_tooth``) on the middle tooth, ``h`` on the next ones (``fine_teeth``) and grows with
the depth below the groove floor and with the distance beyond those teeth (rate ``grade``,
capped at ``h_far``: the far field is coarse), with the groove-floor circle embedded.  A sector
cut along radial lines with free sides would turn about the bore as a cantilever wedge (a
3-tooth sector clamped at r = 20 mm gave 1/9 of the mesh stiffness); the ring keeps the
hoop support of the rest of the body, whose teeth are left out (they carry no load and add
little to the rim's stiffness).  That 2-D mesh is swept
along z through three parts (structured layers, every prism cut into three tetrahedra by
the global vertex order, which makes neighbouring prisms conform):

- the left helix, z ∈ [0, b], section turned by θ(z) = hand · z tan β / r_ref;
- the groove, z ∈ [b, b + g] (``groove``; none when g = 0): only the section below the groove
  floor r_g = r_f − ``groove_depth`` (the body under the groove stays continuous); across it
  the section turns on by the stagger angle Δ (below);
- the right helix, z ∈ [b + g, 2b + g], the opposite hand: θ(z) = Δ + hand · (2b + g − z) tan β / r_ref,
  i.e. its face coordinate is ζ = 2b + g − z (the groove at ζ = b for both helices, as in
  :mod:`femgear.physics.ltca.contact`).

A single-helical member (``SegmentSpec.helices`` = 1) is the left helix alone, z ∈ [0, b], of the real
face width: no groove, no right helix (its face end at z = b is a free end face, ``end1``).

Stagger.  The scene's ``stagger`` s puts the right helix's contact lines s·p_bt further along
the path at the same phase (:func:`femgear.physics.geometry.kinematics.double_helical_contact`).  A
tooth turned counter-clockwise by one pitch meets the plane of action p_bt earlier
(:mod:`femgear.physics.ltca.flank`), and the pinion's roll distance is the path coordinate while the
gear's runs the other way, so the right helix's teeth are turned by Δ = −s·2π/z₁ on the pinion
and +s·2π/z₂ on the gear.  A staggered body needs a groove (the turn is taken across it).

Hand.  The loaded flank is the +X flank of the middle tooth (tooth 0 centred on +y at
z = 0).  On that flank the transverse section turns by ``hand · z tan β / r``, so the
roll distance ρ of a generator (contact line) varies as dρ/dz = −hand · tan β_b
(derived in :mod:`femgear.physics.ltca.flank`).  The pinion is built with hand −1 and the gear
with hand +1 (meshing helical gears have opposite hands); then both flank kernels see
the contact lines of :func:`femgear.physics.geometry.contact_lines` with z = ζ on the left helix.

Named regions (boundary facet sets, integer tags never leave :mod:`femgear.physics.mesh`):
``flank``, ``fillet``, ``tip``, ``bore``, ``rim`` (the toothless root circle), ``end0``, ``end1`` (the outer end faces),
``groove_wall`` (the teeth's end faces at the groove, or the apex plane's free part: none when
g = 0), ``groove_floor``, plus ``loaded_flank`` / ``loaded_flank_right`` (the +X flank of the
middle tooth of each helix); :func:`flank_regions` splits ``flank`` per helix, tooth and side
(``meshes/export.py`` writes them for ParaView).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from femgear.physics.geometry.gear import GearPair

HAND = {1: -1, 2: 1}   #: helix hand of the left helix per member
GROOVE_DEPTH = 0.5     #: groove floor below the root circle, in normal modules (hob run-out; a choice, not a standard)
FAR_FRACTION = 0.25    #: far-field element size cap as a fraction of the rim depth below the groove floor
FAR_DZ = 2.0           #: layer spacing of the far field, in normal modules (every k-th layer of the teeth's)
FAR_MARGIN = 1.0       #: the far field starts this many m_n beyond the five teeth and below the groove floor
TIP_FLOOR = 0.5        #: h_tooth is at least this fraction of m_n/(2 + level), whatever the tip's width


@dataclass(frozen=True)
class SegmentSpec:
    """Resolution and extent of a member body (all lengths in m)."""

    h_tooth: float       #: element size on the middle tooth
    h: float             #: element size on the other teeth
    layers: int          #: structured layers over the face width of one helix
    n_teeth: int = 5     #: teeth in the segment (odd: the middle one is loaded)
    r_bore: float = 0.0  #: clamped bore radius; 0: r_f − 3 m_n (no shaft known)
    groove: float = 0.0  #: groove width g between the helices
    stagger: float = 0.0  #: right helix against the left one [transverse base pitches]
    grade: float = 0.35  #: growth of the element size with the depth below the groove floor / the distance [m/m]
    h_far: float = 0.0   #: largest element size in the rim; 0: :func:`far_size` (max(12 h_tooth, ¼ rim depth))
    fine_teeth: int = 3  #: middle teeth kept at ≤ h (the outer ones only carry kernel readings: coarser)
    far_dz: float = FAR_DZ  #: layer spacing of the far field [m_n] (beyond the teeth, below the rim's top); 0: none
    helices: int = 2     #: helices of the body: 2 (double-helical) or 1 (single-helical: the left helix alone)

    def key(self) -> tuple:
        base = (round(self.h_tooth, 12), round(self.h, 12), self.layers, self.n_teeth, round(self.r_bore, 12),
                round(self.groove, 12), round(self.stagger, 12), round(self.grade, 12), round(self.h_far, 12),
                self.fine_teeth, "body-v2")
        base = base if self.far_dz == FAR_DZ else base + (round(self.far_dz, 9),)
        return base if self.helices == 2 else base + ("one-helix",)


def default_spec(pair: GearPair, member: int, level: int = 1, n_teeth: int = 5, r_bore: float = 0.0,
                 groove: float = 0.0, stagger: float = 0.0) -> SegmentSpec:
    """Body resolution ``level`` (0 coarse, 1 default, 2 fine, 3 finer) of ``pair``'s member: both helices of a
    double-helical pair, the one helix of a single-helical or spur pair (``pair.n_helices``; no groove, no stagger).

    h_tooth = m_n / (2 + level), at most half the tip width but never below :data:`TIP_FLOOR` of m_n / (2 + level)
    (module units: a narrower tip, a pointed one of a high addendum modification, gets its own size near the
    tip circles, :func:`femgear.physics.mesh.section.tip_size`, instead of refining the whole body; the FZG A
    pinion's 0.13 m_n tip would give 26 to 29 times the nodes); the other teeth are capped alike; layers ≈
    b / (1.6 h_tooth) per helix.
    """
    if level < 0:
        raise ValueError(f"level must be ≥ 0, got {level}")
    tip = min(pair.tip_thickness(1), pair.tip_thickness(2))
    h_tooth = min(pair.m_n / (2 + level), max(0.49 * tip, TIP_FLOOR * pair.m_n / (2 + level)))
    h = max(min(0.49 * tip, 2.0 * h_tooth), h_tooth)
    layers = max(4, int(math.ceil(pair.b / (1.6 * h_tooth))))
    if pair.n_helices == 1:
        return SegmentSpec(h_tooth=h_tooth, h=h, layers=layers, n_teeth=n_teeth, r_bore=r_bore, helices=1)
    return SegmentSpec(h_tooth=h_tooth, h=h, layers=layers, n_teeth=n_teeth, r_bore=r_bore, groove=groove,
                       stagger=stagger)


def bore_radius(pair: GearPair, member: int, spec: SegmentSpec) -> float:
    rf = pair.rf1 if member == 1 else pair.rf2
    return spec.r_bore if spec.r_bore > 0 else rf - 3.0 * pair.m_n


def groove_radius(pair: GearPair, member: int) -> float:
    """Radius of the groove floor r_g = r_f − GROOVE_DEPTH · m_n [m]."""
    return (pair.rf1 if member == 1 else pair.rf2) - GROOVE_DEPTH * pair.m_n


@dataclass(frozen=True)
class HelixFrame:
    """Where the helices of a member body lie: z ranges and the section's turn θ(z)."""

    b: float
    groove: float
    twist: float          #: tan β / r_ref · hand [rad/m]
    stagger_angle: float  #: Δ [rad]
    helices: int = 2      #: 1: the left helix alone (single-helical), z ∈ [0, b]

    @property
    def width(self) -> float:
        """Axial width of the body: 2b + g, or b for one helix [m]."""
        return 2 * self.b + self.groove if self.helices == 2 else self.b

    def theta(self, z: np.ndarray) -> np.ndarray:
        """Turn of the section at axial position z [rad]."""
        z = np.asarray(z, float)
        left = self.twist * z
        g = max(self.groove, 1e-300)
        groove = self.twist * self.b + self.stagger_angle * np.clip((z - self.b) / g, 0.0, 1.0)
        right = self.stagger_angle + self.twist * (self.width - z)
        return np.where(z <= self.b, left, np.where(z < self.b + self.groove, groove, right))

    def z_of(self, zeta: np.ndarray, helix: int) -> np.ndarray:
        """Axial position of face coordinate ζ on helix 0 (left) or 1 (right)."""
        return np.asarray(zeta, float) if helix == 0 else self.width - np.asarray(zeta, float)

    def to_right(self, x: np.ndarray, direction: bool = False) -> np.ndarray:
        """Points (3, n) of the left helix at face coordinate ζ = z → the right helix's at the same (ρ, ζ): mirrored
        to z = 2b + g − ζ and turned by the stagger angle Δ (``direction``: vectors, no shift along z)."""
        c, s = math.cos(self.stagger_angle), math.sin(self.stagger_angle)
        out = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, -1.0]]) @ np.asarray(x, float)
        if not direction:
            out[2] += self.width
        return out


def frame_of(pair: GearPair, member: int, groove: float = 0.0, stagger: float = 0.0, helices: int = 2) -> HelixFrame:
    """The :class:`HelixFrame` of ``member`` with groove width ``groove`` [m] and ``stagger`` [base pitches]
    (``helices`` 1: the one helix of a single-helical body)."""
    z = pair.z1 if member == 1 else pair.z2
    r_ref = z * pair.m_t / 2
    delta = (-1 if member == 1 else 1) * stagger * 2 * math.pi / z
    return HelixFrame(pair.b, groove, HAND[member] * math.tan(pair.beta) / r_ref, delta, helices)


def helix_frame(pair: GearPair, member: int, spec: SegmentSpec) -> HelixFrame:
    return frame_of(pair, member, spec.groove, spec.stagger, spec.helices)


def far_size(pair: GearPair, member: int, spec: SegmentSpec) -> float:
    """Largest element size of the body [m]: ``spec.h_far`` if > 0, else max(12 h_tooth, ¼ of the rim's depth
    below the groove floor) — in module units, so that geometrically similar gears get the same mesh; the
    deep rim of a large wheel (the marine gear: 40 m_n) is coarsened with its depth, not capped at 4 m_n."""
    if spec.h_far > 0:
        return spec.h_far
    return max(12.0 * spec.h_tooth, FAR_FRACTION * (groove_radius(pair, member) - bore_radius(pair, member, spec)))


def mesh_revision(pair: GearPair, member: int, spec: SegmentSpec) -> str | None:
    """None when :func:`member_body` gives the same mesh as before the far-field rule of :func:`far_size`,
    the graded groove layers and the coarse far-field layers (no groove, a far size of 12 h_tooth or a given
    one, ``far_dz`` 0), else a tag for cache keys."""
    same_far = spec.h_far > 0 or far_size(pair, member, spec) == 12.0 * spec.h_tooth
    if spec.groove <= 0 and same_far and coarse_step(pair, spec) == 1:
        return None
    return "body-v3"


def coarse_step(pair: GearPair, spec: SegmentSpec) -> int:
    """Every k-th layer of the teeth carries the far field: k = round(far_dz m_n / layer spacing), ≥ 1."""
    if spec.far_dz <= 0:
        return 1
    return max(1, int(round(spec.far_dz * pair.m_n / (pair.b / spec.layers))))


def groove_layers(b: float, groove: float, dz: float, rate: float, cap: float) -> np.ndarray:
    """Interior layer positions across the groove (z − b in (0, g]): the layer spacing ``dz`` of the helices at
    both ends, growing by ``rate`` per unit distance from the nearer helix towards the middle, at most ``cap``."""
    if groove <= 0:
        return np.zeros(0)
    z, out = 0.0, []
    while True:
        d = min(z, groove - z)
        step = min(cap, dz + rate * d)
        if z + step >= groove - 0.5 * dz:
            out.append(groove)
            break
        z += step
        out.append(z)
    out = np.array(out)
    return out * (groove / out[-1])


def _layers(pair: GearPair, spec: SegmentSpec, h_far: float | None = None) -> tuple[np.ndarray, int, int]:
    """(z of every layer, index of the layer at z = b, at z = b + g); one helix: the layers of [0, b] alone."""
    left = np.linspace(0.0, pair.b, spec.layers + 1)
    if spec.helices == 1:
        return left, spec.layers, spec.layers
    if spec.groove > 0:
        dz = pair.b / spec.layers
        mid = pair.b + groove_layers(pair.b, spec.groove, dz, spec.grade, h_far or 12.0 * spec.h_tooth)
        ng = mid.size
    else:
        ng, mid = 0, np.zeros(0)
    right = pair.b + spec.groove + left[1:]
    return np.concatenate([left, mid, right]), spec.layers, spec.layers + ng


def member_body(pair: GearPair, member: int, spec: SegmentSpec):
    """The tetrahedral body (skfem ``MeshTet``) of ``member``, both helices (one: ``spec.helices`` = 1), named
    regions attached."""
    import skfem

    if spec.helices not in (1, 2) or (spec.helices == 1 and (spec.groove > 0 or spec.stagger != 0)):
        raise ValueError(f"helices must be 1 or 2 (one helix has no groove and no stagger), got helices="
                         f"{spec.helices}, groove={spec.groove}, stagger={spec.stagger}")
    if spec.n_teeth < 1 or spec.n_teeth % 2 == 0:
        raise ValueError(f"n_teeth must be odd and ≥ 1 (the middle tooth is loaded), got {spec.n_teeth}")
    if not 0 < spec.h_tooth <= spec.h:
        raise ValueError(f"need 0 < h_tooth ≤ h, got h_tooth={spec.h_tooth}, h={spec.h}")
    if spec.stagger != 0 and spec.groove <= 0:
        raise ValueError(f"stagger={spec.stagger}: a staggered double-helical body needs groove_width > 0 "
                         "(the right helix's teeth are turned across the groove)")
    r_g = groove_radius(pair, member)
    h_far = far_size(pair, member, spec)
    sec = body_section(pair, member, spec)
    zs, k_b, k_g = _layers(pair, spec, h_far)
    frame = helix_frame(pair, member, spec)
    mesh, layer_of, node2d = _sweep(sec, zs, frame, (k_b, k_g), r_g, far_triangles(pair, member, sec, spec),
                                    coarse_step(pair, spec))
    boundaries = _name_facets(mesh, sec, layer_of, node2d, (0, k_b, k_g, zs.size - 1))
    boundaries["loaded_flank"] = _loaded_flank(mesh, boundaries["flank"], pair, member, frame, 0)
    if spec.helices == 2:
        boundaries["loaded_flank_right"] = _loaded_flank(mesh, boundaries["flank"], pair, member, frame, 1)
    return skfem.MeshTet(mesh.p, mesh.t, _boundaries=boundaries)


@functools.lru_cache(maxsize=8)
def body_section(pair: GearPair, member: int, spec: SegmentSpec):
    """The transverse section (skfem ``MeshTri``) that :func:`member_body` sweeps (cached: the cost estimate
    meshes it before the body)."""
    from femgear.physics.mesh.section import gear_section

    rf = pair.rf1 if member == 1 else pair.rf2
    ra = pair.ra1 if member == 1 else pair.ra2
    return gear_section(pair, member, spec.h, n_teeth=spec.n_teeth, bore_radius=bore_radius(pair, member, spec),
                        refine_at=(0.0, 0.5 * (rf + ra)), refine_ratio=spec.h_tooth / spec.h,
                        refine_radius=0.75 * (ra - rf), split_radius=groove_radius(pair, member),
                        grade=(spec.grade, far_size(pair, member, spec), min(spec.fine_teeth, spec.n_teeth)),
                        ring=True)


def body_size(pair: GearPair, member: int, spec: SegmentSpec) -> tuple[int, int]:
    """(nodes, tetrahedra) of :func:`member_body` counted from its section alone (a fraction of a second;
    exact without the far-field layers, within a few per cent with them: transition columns are estimated)."""
    sec = body_section(pair, member, spec)
    zs, k_b, k_g = _layers(pair, spec, far_size(pair, member, spec))
    inner = _below_split(sec)
    step = coarse_step(pair, spec)
    far = far_triangles(pair, member, sec, spec) if step > 1 else np.zeros(sec.t.shape[1], bool)
    fine_node = np.zeros(sec.p.shape[1], bool)
    fine_node[sec.t[:, ~far].ravel()] = True
    fine_col = ~far | fine_node[sec.t].all(axis=0)
    inner_node = np.zeros(sec.p.shape[1], bool)
    inner_node[sec.t[:, inner].ravel()] = True
    coarse = coarse_layers(zs.size, k_b, k_g, step)
    n_g = k_g - k_b                                       # groove slabs
    n_mid = max(0, n_g - 1)                               # layers strictly inside the groove
    c_mid = int(np.sum((coarse > k_b) & (coarse < k_g)))
    lines = [(fine_node, zs.size, n_mid), (~fine_node, coarse.size, c_mid)]
    nodes = sum(int(m.sum()) * (n - mid) + int((m & inner_node).sum()) * mid for m, n, mid in lines)
    slabs, c_slabs = zs.size - 1, coarse.size - 1
    c_groove = int(np.sum((coarse[:-1] >= k_b) & (coarse[:-1] < k_g)))
    trans = ~fine_col & fine_node[sec.t].any(axis=0)
    pure = ~fine_col & ~trans
    tets = 3 * (int(fine_col.sum()) * (slabs - n_g) + int((fine_col & inner).sum()) * n_g)
    tets += 3 * (int(pure.sum()) * (c_slabs - c_groove) + int((pure & inner).sum()) * c_groove)
    n_trans = int(trans.sum()) * (c_slabs - c_groove) + int((trans & inner).sum()) * c_groove
    return int(nodes + n_trans), int(tets + n_trans * (2 + 4 * step))


def bending_zone(mesh, pair: GearPair, member: int, spec: SegmentSpec, teeth: int = 1, depth: float = 1.0,
                 helices: tuple[int, ...] = (0, 1), rim: float | None = None, reach: float | None = None) -> np.ndarray:
    """Elements (bool per tetrahedron of :func:`member_body`'s ``mesh``) of the middle ``teeth`` teeth of the
    ``helices`` (0 left, 1 right) down to ``depth`` m_n below the root circle: where the loaded teeth bend.

    A centroid test in the section's own frame (turned back by θ(z), tooth 0 on +y): polar angle within
    ``teeth``/2 pitches of +y and radius above r_f − ``depth`` m_n, axial position on one of the ``helices``.
    """
    frame = helix_frame(pair, member, spec)
    c = mesh.p[:, mesh.t].mean(axis=1)
    th = frame.theta(c[2])
    sx = np.cos(th) * c[0] + np.sin(th) * c[1]
    sy = -np.sin(th) * c[0] + np.cos(th) * c[1]
    on = np.zeros(c.shape[1], bool)
    if 0 in helices:
        on |= c[2] <= pair.b
    if 1 in helices:
        on |= c[2] >= pair.b + spec.groove
    tooth, below = section_zone(pair, member, sx, sy, teeth, depth, rim, reach)
    return (on & tooth) | below


def section_zone(pair: GearPair, member: int, x: np.ndarray, y: np.ndarray, teeth: int = 1, depth: float = 1.0,
                 rim: float | None = None, reach: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The zone of :func:`bending_zone` at points (``x``, ``y``) of the section's own frame (tooth 0 on +y):
    (in the middle ``teeth`` teeth down to ``depth`` m_n below the root circle, in the rim below ``rim`` m_n under
    it within ``reach`` m_n of the root of tooth 0 (None: all round; ``rim`` None: no rim))."""
    z_teeth = pair.z1 if member == 1 else pair.z2
    rf = pair.rf1 if member == 1 else pair.rf2
    r = np.hypot(x, y)
    tooth = (np.abs(np.arctan2(x, y)) < 0.5 * teeth * 2 * math.pi / z_teeth) & (r > rf - depth * pair.m_n)
    below = np.zeros(r.shape, bool) if rim is None else r < rf - rim * pair.m_n
    if rim is not None and reach is not None:
        below &= np.hypot(x, y - rf) < reach * pair.m_n
    return tooth, below


def _below_split(sec) -> np.ndarray:
    """Triangles of the section on the bore's side of the embedded ``split`` edges (connected components of
    the triangles joined across every other interior edge; a centroid test fails for flat triangles on
    the arc's chords)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    f2t = sec.f2t
    cut = np.zeros(sec.facets.shape[1], bool)
    cut[sec.boundaries["split"]] = True
    inner_edge = (f2t[1] >= 0) & ~cut
    a, b = f2t[0, inner_edge], f2t[1, inner_edge]
    n = sec.t.shape[1]
    _, label = connected_components(coo_matrix((np.ones(a.size), (a, b)), shape=(n, n)), directed=False)
    bore_tris = np.unique(f2t[0, sec.boundaries["bore"]])
    return np.isin(label, label[bore_tris])


def coarse_layers(n_layers: int, k_b: int, k_g: int, step: int) -> np.ndarray:
    """Indices of the layers that carry the far field: every ``step``-th one from each end of a helix and the
    groove's ends (the helices' outer faces and the groove walls are kept)."""
    keep = {0, n_layers - 1, k_b, k_g}
    for lo, hi in ((0, k_b), (k_b, k_g), (k_g, n_layers - 1)):
        keep.update(range(lo, hi, step))
    return np.array(sorted(keep))


def far_triangles(pair: GearPair, member: int, sec, spec: SegmentSpec) -> np.ndarray:
    """Section triangles of the far field (coarse layers): centroid more than :data:`FAR_MARGIN` m_n below the
    groove floor, or that far beyond the tips of the five teeth (from the middle tooth's centre)."""
    from femgear.physics.geometry.profile import tooth_profile
    from femgear.physics.mesh.section import _teeth_reach

    rf = pair.rf1 if member == 1 else pair.rf2
    ra = pair.ra1 if member == 1 else pair.ra2
    centre = np.array([0.0, 0.5 * (rf + ra)])
    c = sec.p[:, sec.t].mean(axis=1)
    reach = _teeth_reach(tooth_profile(pair, member), spec.n_teeth, tuple(centre)) + FAR_MARGIN * pair.m_n
    deep = np.hypot(c[0], c[1]) < groove_radius(pair, member) - FAR_MARGIN * pair.m_n
    return deep | (np.hypot(c[0] - centre[0], c[1] - centre[1]) > reach)


def _sweep(sec, zs: np.ndarray, frame: HelixFrame, groove_layers: tuple[int, int], r_g: float,
           far: np.ndarray | None = None, step: int = 1):
    """Sweep the section mesh through the layers ``zs`` → (MeshTet, layer of each node, 2-D node of each node).

    ``far`` (bool per triangle) with ``step`` > 1: those triangles are swept through every ``step``-th layer
    only (:func:`coarse_layers`).  Where a far column meets a node of the fine sweep it becomes a transition
    column: its faces are triangulated to match both neighbours (the fine split on faces between fine node
    lines, a fan from the lower coarse node on faces with one) and coned to a node at its centroid, so the mesh
    stays conforming.  Such interior nodes have layer and 2-D node −1.
    """
    import skfem

    n2, tri = sec.p.shape[1], sec.t
    inner = _below_split(sec)
    th = frame.theta(zs)
    cos, sin = np.cos(th)[:, None], np.sin(th)[:, None]
    x = cos * sec.p[0] - sin * sec.p[1]
    y = sin * sec.p[0] + cos * sec.p[1]
    p = np.vstack([x.ravel(), y.ravel(), np.repeat(zs, n2)])
    tri_sorted = np.sort(tri, axis=0)                    # a < b < c: the prism split below conforms
    far = np.zeros(tri.shape[1], bool) if far is None or step <= 1 else np.asarray(far, bool)
    fine_node = np.zeros(n2, bool)
    fine_node[tri[:, ~far].ravel()] = True
    fine_col = ~far | fine_node[tri].all(axis=0)          # far triangles whose nodes are all fine: swept finely

    def in_groove(k):
        return groove_layers[0] <= k < groove_layers[1]

    tets = []
    for k in range(zs.size - 1):
        sel = fine_col & (inner if in_groove(k) else True)
        lo, hi = k * n2, (k + 1) * n2
        A, B, C = tri_sorted[:, sel]
        tets += [np.vstack([A + lo, B + lo, C + lo, C + hi]), np.vstack([A + lo, B + lo, B + hi, C + hi]),
                 np.vstack([A + lo, A + hi, B + hi, C + hi])]
    extra = []
    if (~fine_col).any():
        layers = coarse_layers(zs.size, *groove_layers, step)
        pure = ~fine_col & ~fine_node[tri].any(axis=0)
        for s0, s1 in zip(layers[:-1], layers[1:]):
            groove = in_groove(s0)
            sel = pure & (inner if groove else True)
            lo, hi = s0 * n2, s1 * n2
            A, B, C = tri_sorted[:, sel]
            tets += [np.vstack([A + lo, B + lo, C + lo, C + hi]), np.vstack([A + lo, B + lo, B + hi, C + hi]),
                     np.vstack([A + lo, A + hi, B + hi, C + hi])]
            for j in np.nonzero(~fine_col & ~pure & (inner if groove else True))[0]:
                faces = _column_faces(tri_sorted[:, j], fine_node, s0, s1, n2)
                extra.append(p[:, np.unique(faces)].mean(axis=1))
                apex = p.shape[1] + len(extra) - 1
                tets.append(np.vstack([faces.T, np.full(faces.shape[0], apex)]))
    if extra:
        p = np.hstack([p, np.array(extra).T])
    t = np.hstack(tets)
    used = np.unique(t)
    remap = np.full(p.shape[1], -1, dtype=np.int64)
    remap[used] = np.arange(used.size)
    mesh = skfem.MeshTet(p[:, used].copy(), remap[t])
    grid = used < n2 * zs.size
    return mesh, np.where(grid, used // n2, -1), np.where(grid, used % n2, -1)


def _column_faces(abc: np.ndarray, fine_node: np.ndarray, s0: int, s1: int, n2: int) -> np.ndarray:
    """Boundary triangles (n, 3 node indices) of a transition column: section triangle ``abc`` (sorted) between
    layers ``s0`` and ``s1``, node lines of fine nodes at every layer, of coarse ones at s0 and s1 only."""
    def at(node, layer):
        return layer * n2 + node

    a, b, c = (int(v) for v in abc)
    out = [(at(a, s0), at(b, s0), at(c, s0)), (at(a, s1), at(b, s1), at(c, s1))]
    for u, v in ((a, b), (a, c), (b, c)):                 # u < v
        fu, fv = fine_node[u], fine_node[v]
        if fu and fv:                                    # the fine sweep's diagonal: (min, j) to (max, j + 1)
            for j in range(s0, s1):
                out += [(at(u, j), at(v, j), at(v, j + 1)), (at(u, j), at(u, j + 1), at(v, j + 1))]
        elif fu or fv:                                   # fan from the coarse node's lower end
            f, q = (u, v) if fu else (v, u)
            out += [(at(q, s0), at(f, j), at(f, j + 1)) for j in range(s0, s1)]
            out.append((at(q, s0), at(f, s1), at(q, s1)))
        else:                                            # the coarse sweep's diagonal
            out += [(at(u, s0), at(v, s0), at(v, s1)), (at(u, s0), at(u, s1), at(v, s1))]
    return np.array(out, dtype=np.int64)


def _name_facets(mesh, sec, layer_of: np.ndarray, node2d: np.ndarray, ends: tuple[int, int, int, int]) -> dict:
    """Boundary facets of the swept body by name: lateral ones from the section's named edges, flat ones by layer."""
    first, k_b, k_g, last = ends
    edge_name = {}
    names = [n for n in sec.boundaries if n != "split"] + ["split"]
    for i, name in enumerate(names):
        for f in sec.boundaries[name]:
            edge_name[tuple(sorted(sec.facets[:, f]))] = i
    bf = mesh.boundary_facets()
    nodes = mesh.facets[:, bf]
    lay = layer_of[nodes]
    out: dict[str, list] = {n: [] for n in names + ["end0", "end1", "groove_wall"]}
    flat = (lay == lay[0]).all(axis=0)
    for j in np.nonzero(flat)[0]:
        k = lay[0, j]
        out["end0" if k == first else "end1" if k == last else "groove_wall"].append(bf[j])
    for j in np.nonzero(~flat)[0]:
        pair2d = tuple(sorted(set(node2d[nodes[:, j]].tolist())))
        out[names[edge_name[pair2d]]].append(bf[j])
    out["groove_floor"] = out.pop("split")
    return {n: np.array(sorted(v), dtype=np.int64) for n, v in out.items() if v or n in ("end0", "end1")}


def flank_position(mesh, flank: np.ndarray, pair: GearPair, member: int, frame: HelixFrame) -> np.ndarray:
    """(helix, tooth, side) of each facet of ``flank`` (3, n): helix 0 left (z < b), 1 right (z > b + g), −1 in
    between; tooth k = −(n−1)/2 … (n−1)/2 (tooth 0 the middle one, k > 0 counter-clockwise); side 0 the +X flank
    of the untwisted tooth (the one the LTCA loads on tooth 0), 1 the other."""
    z = pair.z1 if member == 1 else pair.z2
    pitch = 2 * math.pi / z
    c = mesh.p[:, mesh.facets[:, flank]].mean(axis=1)
    helix = np.where(c[2] < pair.b, 0, np.where(c[2] > pair.b + frame.groove, 1, -1))
    polar = np.arctan2(c[1], c[0]) - frame.theta(c[2]) - math.pi / 2      # from the middle tooth's centre line
    polar = (polar + math.pi) % (2 * math.pi) - math.pi
    tooth = np.rint(polar / pitch).astype(np.int64)
    side = np.where(polar - tooth * pitch < 0, 0, 1)
    return np.vstack([helix, tooth, side])


def flank_regions(mesh, pair: GearPair, member: int, spec: SegmentSpec) -> dict[str, np.ndarray]:
    """The ``flank`` facets of a :func:`member_body` by helix, tooth and side: ``flank_<left|right>_t<k>_<drive|coast>``
    (``drive`` the +X side, the LTCA's loaded flank on tooth 0: ``loaded_flank`` = ``flank_left_t+0_drive``)."""
    flank = mesh.boundaries["flank"]
    pos = flank_position(mesh, flank, pair, member, helix_frame(pair, member, spec))
    out = {}
    for h, hname in ((0, "left"), (1, "right")):
        for k in range(-(spec.n_teeth // 2), spec.n_teeth // 2 + 1):
            for s, sname in ((0, "drive"), (1, "coast")):
                sel = flank[(pos[0] == h) & (pos[1] == k) & (pos[2] == s)]
                if sel.size:
                    out[f"flank_{hname}_t{k:+d}_{sname}"] = sel
    return out


def _loaded_flank(mesh, flank: np.ndarray, pair: GearPair, member: int, frame: HelixFrame, helix: int) -> np.ndarray:
    """Facets of ``flank`` on the +X side of the middle tooth of ``helix`` (0 left, 1 right), untwisted."""
    pos = flank_position(mesh, flank, pair, member, frame)
    return flank[(pos[0] == helix) & (pos[1] == 0) & (pos[2] == 0)]
