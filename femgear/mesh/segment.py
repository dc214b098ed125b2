"""3-D tetrahedral segment of one helix of a gear member, graded towards its middle tooth.

The transverse section of :func:`femgear.mesh.section.gear_section` (rack-generated
involute + trochoid fillet, ``n_teeth`` teeth, rim down to ``r_bore``) is meshed with a
size field that is fine (``h_tooth``) on the middle tooth and coarse (``h``) elsewhere,
then twist-extruded along the helix (``layers`` structured layers over the face width b).
The other helix of a double-helical member is the mirror image z → b − z of this one
(opposite hand), so one helix mesh serves both; the groove, which joins the helices
through the body, is not meshed (the cross-compliance of the helices through the rim is
dropped: notes ltca_methods §5).

Hand.  The loaded flank is the +X flank of the middle tooth (tooth 0 centred on +y at
z = 0).  On that flank the transverse section turns by ``hand · z tan β / r``, so the
roll distance ρ of a generator (contact line) varies as dρ/dz = −hand · tan β_b
(derived in :mod:`femgear.ltca.flank`).  The pinion is built with hand −1 and the gear
with hand +1 (meshing helical gears have opposite hands); then both flank kernels see
the contact lines of :func:`femgear.geometry.contact_lines` with z = ζ on the left helix.

Named regions (boundary facet sets, integer tags never leave :mod:`femgear.mesh`):
``flank``, ``fillet``, ``tip``, ``bore``, ``sides``, ``end0``, ``end1`` from gmsh
physical groups, plus ``loaded_flank`` (the +X flank of the middle tooth).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.geometry.gear import GearPair

HAND = {1: -1, 2: 1}   #: helix hand of the meshed (left) helix per member


@dataclass(frozen=True)
class SegmentSpec:
    """Resolution and extent of a member segment (all lengths in m)."""

    h_tooth: float       #: element size on the middle tooth
    h: float             #: element size away from it
    layers: int          #: structured layers over the face width
    n_teeth: int = 5     #: teeth in the segment (odd: the middle one is loaded)
    r_bore: float = 0.0  #: clamped inner radius; 0: r_f − 3 m_n (rim backup ratio ≈ 1.3)

    def key(self) -> tuple:
        return (round(self.h_tooth, 12), round(self.h, 12), self.layers, self.n_teeth, round(self.r_bore, 12))


def default_spec(pair: GearPair, member: int, level: int = 1, n_teeth: int = 5, r_bore: float = 0.0) -> SegmentSpec:
    """Segment resolution ``level`` (0 coarse, 1 default, 2 fine, 3 finer).

    h_tooth = m_n / (2 + level) (at most half the tip width); the far field is capped by the two-elements-across-
    the-tip rule of :func:`gear_section`; layers ≈ b / (1.6 h_tooth).
    """
    if level < 0:
        raise ValueError(f"level must be ≥ 0, got {level}")
    tip = min(pair.tip_thickness(1), pair.tip_thickness(2))
    h_tooth = min(pair.m_n / (2 + level), 0.49 * tip)
    h = max(min(0.49 * tip, 2.0 * h_tooth), h_tooth)
    layers = max(4, int(math.ceil(pair.b / (1.6 * h_tooth))))
    return SegmentSpec(h_tooth=h_tooth, h=h, layers=layers, n_teeth=n_teeth, r_bore=r_bore)


def bore_radius(pair: GearPair, member: int, spec: SegmentSpec) -> float:
    rf = pair.rf1 if member == 1 else pair.rf2
    return spec.r_bore if spec.r_bore > 0 else rf - 3.0 * pair.m_n


def helix_segment(pair: GearPair, member: int, spec: SegmentSpec):
    """The tetrahedral segment (skfem ``MeshTet``) of ``member``'s meshed helix, named regions attached."""
    import skfem

    from femgear.mesh.section import gear_section

    if spec.n_teeth < 1 or spec.n_teeth % 2 == 0:
        raise ValueError(f"n_teeth must be odd and ≥ 1 (the middle tooth is loaded), got {spec.n_teeth}")
    if not 0 < spec.h_tooth <= spec.h:
        raise ValueError(f"need 0 < h_tooth ≤ h, got h_tooth={spec.h_tooth}, h={spec.h}")
    z = pair.z1 if member == 1 else pair.z2
    rf = pair.rf1 if member == 1 else pair.rf2
    ra = pair.ra1 if member == 1 else pair.ra2
    r_ref = z * pair.m_t / 2
    angle = HAND[member] * pair.b * math.tan(pair.beta) / r_ref
    mesh = gear_section(pair, member, spec.h, n_teeth=spec.n_teeth, bore_radius=bore_radius(pair, member, spec),
                        refine_at=(0.0, 0.5 * (rf + ra)), refine_ratio=spec.h_tooth / spec.h,
                        refine_radius=0.75 * (ra - rf), _extrude=(pair.b, angle, spec.layers))
    boundaries = dict(mesh.boundaries)
    boundaries["loaded_flank"] = _loaded_flank(mesh, pair, member)
    return skfem.MeshTet(mesh.p, mesh.t, _boundaries=boundaries)


def _loaded_flank(mesh, pair: GearPair, member: int) -> np.ndarray:
    """Facets of ``flank`` on the +X side of the middle tooth (untwisted to z = 0)."""
    z = pair.z1 if member == 1 else pair.z2
    r_ref = z * pair.m_t / 2
    f = mesh.boundaries["flank"]
    c = mesh.p[:, mesh.facets[:, f]].mean(axis=1)
    twist = HAND[member] * c[2] * math.tan(pair.beta) / r_ref
    polar = np.arctan2(c[1], c[0]) - twist - math.pi / 2      # from the middle tooth's centre line
    polar = (polar + math.pi) % (2 * math.pi) - math.pi
    return f[(polar < 0) & (polar > -math.pi / z)]
