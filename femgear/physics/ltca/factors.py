"""The face and transverse load factors K_Hβ, K_Hα of an LTCA cycle (the ratings' own factors, issue 42).

ISO 6336-1 defines K_Hβ as the largest load per unit face width over its mean, and K_Hα as the
factor by which the uneven sharing of the load between the tooth pairs in contact raises the load
of a pair above the uniform sharing its Z factors assume.  The LTCA solves both distributions;
here they are read off one cycle (:class:`femgear.physics.ltca.analysis.LTCAResult`, line loads kept).

**Face load distribution.**  Every contact point carries f = w Δℓ over a segment whose face extent is
Δζ = Δℓ cos β_b about its ζ; its load is spread evenly over that extent into ``n_bins`` equal face bins
(exact overlaps), and divided by the bin width: the load per unit face width w_F(ζ, φ) of each helix at
each phase.  Its mean over the cycle, w̄_F(ζ), is what a face load distribution means for a helical
mesh: over one mesh period every face position passes through every contact state, so for an
aligned, unmodified pair w̄_F is uniform up to the face-end effects of the teeth, whatever the
overlap.  (At one phase w_F of a helical pair also varies with the number of contact lines crossing
the face position and with the tip-edge loads of the line ends: the transverse sharing, not the face
distribution.)  K_Hβ = max over the helices and ζ of w̄_F over its mean over both helices and the face (the
nominal load per face width of one helix, F/(n_h b), but for the end bins below): for a double-helical pair an
uneven split between the helices counts too, since the rating takes F_t/2 per helix.

The two face-end bins are read by linear extrapolation of their two inner neighbours to the end face,
not from their own load: there each contact line ends with a point whose local (half-space) compliance
has material on one side only in the model but none beyond the face in the gear, where both members end
in one plane (two equal elastic bodies ending together have no end concentration, unlike a short roller
on a long one).  The spike the half-space term puts there (1.14–1.16 × the mean on an aligned spur pair,
coarse bodies) is a model artefact; a misalignment that loads the face end shows in the extrapolation.

**Transverse sharing.**  At each phase the tooth pairs of a helix (its contact lines, j) carry F_j over
the lengths L_j; uniform sharing gives every pair the mesh's mean intensity F_h/L_h.  The load-weighted
mean intensity over the pairs, Σ_j F_j (F_j/L_j) / F_h, over F_h/L_h is ≥ 1, and exactly 1 for the uniform
sharing (Cauchy–Schwarz); K_Hα is its largest value over the phases and helices.  It is read on the points
away from the flank edges: a line's end point on a tip edge carries an edge contact (up to 30× the mean
load per length on unmodified flanks, :mod:`femgear.physics.ltca.flank_map`), a contact the Hertz line
load does not describe and that ISO leaves to tip relief and running-in (C_ay); the weighting keeps a short
line piece from reading as an overloaded pair.

Both factors are at the cycle's own load (the operating torque, without K_A) and under the
modifications and misalignment (``modifications.helix_slope_deviation_*``) the cycle was solved with.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.geometry.gear import GearPair


@document_fields
@dataclass(frozen=True)
class LTCALoadFactors:
    """K_Hβ and K_Hα of one LTCA cycle, with the face load distribution they come from (SI)."""

    K_Hbeta: float
    """face load factor: the peak of the cycle-mean load per unit face width over its mean, both helices [-]"""
    K_Halpha: float
    """transverse load factor: the largest load-weighted mean intensity of the tooth pairs over the mesh mean [-]"""
    zeta: np.ndarray
    """face coordinates of the bin centres [m]"""
    face_load: np.ndarray
    """(helix, bin) cycle mean of the load per unit face width w̄_F(ζ), the end bins as solved (K_Hβ reads them
    extrapolated, :func:`end_extrapolated`) [N/m]"""
    peak_helix: int
    """helix of the peak (0 left, 1 right) [-]"""
    peak_zeta: float
    """face coordinate of the peak [m]"""
    sharing: np.ndarray
    """(helix, phase) load-weighted mean intensity of the pairs over the mean intensity [-]"""
    worst_phase: float
    """phase of the largest ``sharing`` [base pitches]"""


def face_load(result, pair: GearPair, n_bins: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(ζ of the bin centres [m], (helix, phase, bin) load per unit face width [N/m]) of ``result``'s points."""
    if not result.line_load:
        raise ValueError("the load factors need the line loads: run mesh_cycle(..., keep_lines=True)")
    n = max(8, int(result.n_line)) if n_bins is None else int(n_bins)
    b, cb = pair.b, math.cos(pair.beta_b)
    edges = np.linspace(0.0, b, n + 1)
    out = np.zeros((result.n_helices, len(result.line_load), n))
    for i, (arr, dl) in enumerate(zip(result.line_load, result.line_length)):
        half = 0.5 * dl * cb
        lo, hi = arr[:, 3] - half, arr[:, 3] + half
        overlap = np.clip(np.minimum(hi[:, None], edges[None, 1:]) - np.maximum(lo[:, None], edges[None, :-1]), 0, None)
        share = overlap / np.maximum(hi - lo, 1e-300)[:, None]          # each segment's load spread over its extent
        f = arr[:, 4] * dl
        for h in range(result.n_helices):
            s = arr[:, 0] == h
            out[h, i] = f[s] @ share[s] / (b / n)
    return 0.5 * (edges[1:] + edges[:-1]), out


def end_extrapolated(face: np.ndarray) -> np.ndarray:
    """``face`` (helix, bin) with each end bin replaced by the linear extrapolation of its two inner neighbours to
    the bin's centre (module docstring; at least 5 bins)."""
    if face.shape[-1] < 5:
        raise ValueError(f"the face load needs at least 5 bins, got {face.shape[-1]}")
    out = np.array(face, float)
    out[..., 0] = 2 * face[..., 1] - face[..., 2]
    out[..., -1] = 2 * face[..., -2] - face[..., -3]
    return np.maximum(out, 0.0)


def pair_sharing(result) -> np.ndarray:
    """(helix, phase): Σ_j F_j²/L_j · L/F² over the contact lines j of each helix at each phase (1: uniform), on the
    points away from the flank edges (the lines' end points, :func:`femgear.physics.ltca.te.line_ends`, left out)."""
    from femgear.physics.ltca.te import line_ends

    out = np.ones((result.n_helices, len(result.line_load)))
    for i, (arr, dl) in enumerate(zip(result.line_load, result.line_length)):
        f = arr[:, 4] * dl
        inner = ~line_ends(arr)
        for h in range(result.n_helices):
            s = (arr[:, 0] == h) & inner
            lines = arr[s, 1]
            F = np.bincount(np.unique(lines, return_inverse=True)[1], weights=f[s])
            L = np.bincount(np.unique(lines, return_inverse=True)[1], weights=dl[s])
            total = F.sum()
            if total > 0:
                out[h, i] = float(np.sum(F**2 / L)) * L.sum() / total**2
    return out


def ltca_load_factors(result, pair: GearPair, n_bins: int | None = None) -> LTCALoadFactors:
    """The :class:`LTCALoadFactors` of the LTCA cycle ``result`` (module docstring); ``n_bins`` face bins (default
    the cycle's points per contact line, at least 8)."""
    zeta, w = face_load(result, pair, n_bins)
    mean = w.mean(axis=1)
    read = end_extrapolated(mean)
    h, k = np.unravel_index(int(np.argmax(read)), read.shape)
    sharing = pair_sharing(result)
    hs, i = np.unravel_index(int(np.argmax(sharing)), sharing.shape)
    return LTCALoadFactors(K_Hbeta=float(read[h, k] / read.mean()), K_Halpha=float(sharing[hs, i]), zeta=zeta,
                           face_load=mean, peak_helix=int(h), peak_zeta=float(zeta[k]), sharing=sharing,
                           worst_phase=float(result.phase[i]))


__all__ = ["LTCALoadFactors", "face_load", "ltca_load_factors", "pair_sharing"]
