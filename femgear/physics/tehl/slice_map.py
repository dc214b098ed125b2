"""Face slices read off a friction map: the ``tehl-point`` level's solver in the coupling loop of a pair whose every
contact is a line contact.

An uncrowned pair (or one whose crowned ellipses are all more slender than the point solver's
:data:`femgear.physics.contact.crowning.MIN_POINT_RATIO`) has every contact handed over to line TEHL in face
slices (:mod:`femgear.physics.tehl.slices`).  Solved directly, that is :data:`~femgear.physics.tehl.slices.SLICES`
line TEHL solves per path position in every pass of the coupling loop: on the turbo zoo pair (131 m/s, 21 path
positions) the ``tehl-point`` cell ran past an hour.  The slices are line contacts, so their μ and surface rise
are what the ``tehl`` level's friction map interpolates (:func:`femgear.physics.tehl.solver.tehl_map_solver`):
one map over the envelope of the slices' own loads, radii, speeds and SRR (:func:`slice_map_axes`: the slices at
the ends of the line reach radii and sliding beyond the path's centre values) stands for all of them, built once
(≈ 170 solves) and measured against fresh solves (its error goes to the summary as the ``tehl`` map's does).

Each query contact is cut into the same slices as the direct hand-over (:func:`~femgear.physics.tehl.slices.
slice_inputs`: the same loads, kinematics and quadrature weights), each slice's μ read off the map and signed by
its sliding direction (μ_couette = −sign(SRR) μ, the Couette friction is signed like v2 − v1), and combined as
:func:`~femgear.physics.tehl.slices.slice_contact` combines solved slices: μ = |Σ W_j μ_c,j w_j| / Σ W_j w_j, the
contact's surface rise the largest of its slices'.  The film of the run's last pass is still solved directly, slice
by slice on the spike-resolving grids (:func:`femgear.levels.lubrication.tehl_path_options`).
"""

from __future__ import annotations

import math

import numpy as np

from femgear.physics.contact.crowning import MIN_POINT_RATIO, CrownedContact
from femgear.physics.tehl.slices import SliceGeometry, slice_inputs
from femgear.physics.tehl.solver import TEHLSetup, envelope_axes, tehl_map_solver


def all_slender(geo: CrownedContact, R) -> bool:
    """Whether every contact of profile radii ``R`` [m] is handed over to face slices: uncrowned, or more slender
    than :data:`~femgear.physics.contact.crowning.MIN_POINT_RATIO` (the hand-over rule of
    :func:`femgear.physics.tehl.point_level.tehl_point_solver`)."""
    if geo.kappa <= 0:
        return True
    Rx, Ry = geo.radii(np.ravel(R))
    return bool(np.all(Rx / Ry < MIN_POINT_RATIO))


def _slices_at(w, R, ue, srr, geo: CrownedContact, slices: SliceGeometry, E_red: float):
    """Per query contact (arrays of one shape, flattened), the slices of :func:`slice_inputs`: a list of
    (w_j, R_j, ue_j, srr_j, W_j) arrays."""
    with np.errstate(divide="ignore"):
        Rx, Ry = geo.radii(R)
    return [slice_inputs(float(w.flat[i]), float(R.flat[i]), float(ue.flat[i]), float(srr.flat[i]), float(Rx.flat[i]),
                         float(Ry.flat[i]), slices, E_red)[1:] for i in range(w.size)]


def slice_map_axes(contact, geo: CrownedContact, slices: SliceGeometry, E_red: float, ambient_temperature: float,
                   load_range=(0.5, 2.0), temperature_span: float = 40.0) -> dict[str, np.ndarray]:
    """Friction-map axes over the face slices of a contact pass (:class:`femgear.physics.contact.path.ContactPath`)
    at ``load_range`` times its mean load per length: the slices' loads (a factor about 2 between load values, at
    least three; an uncrowned line's slices carry the contact's load, so its axis is the ``tehl`` map's), their
    radii, speeds and SRR (:func:`femgear.physics.tehl.solver.envelope_axes`)."""
    k = contact.kin
    parts = [_slices_at(np.full(k.R.shape, f * contact.load_per_length), k.R, k.ue, np.abs(k.srr), geo, slices, E_red)
             for f in load_range]
    wj, Rj, uej, srrj = (np.concatenate([p[n] for ps in parts for p in ps]) for n in range(4))
    lo, hi = float(wj.min()), float(wj.max())
    count = max(3, math.ceil(math.log2(hi / lo) - 1e-9) + 1)
    return envelope_axes(np.geomspace(lo, hi, count), Rj, uej, srrj, ambient_temperature, temperature_span)


def slice_map_solver(geo: CrownedContact, slices: SliceGeometry, setup: TEHLSetup, axes: dict, **options):
    """The contacts' face slices read off a line TEHL friction map over ``axes`` (:func:`slice_map_axes`; built on
    first use by :func:`~femgear.physics.tehl.solver.tehl_map_solver` with ``options``, its queries clamped to the
    envelope), in the map signature ``solve(w=, R=, ue=, srr=, T=) -> (μ, ΔT)`` (module docstring); the solver's
    ``friction_map()`` is the map (None before the first query)."""
    fmap = tehl_map_solver(setup, axes, **options)

    def solve(w, R, ue, srr, T):
        w, R, ue, srr, T = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float))
                                                 for a in (w, R, ue, srr, T)))
        parts = _slices_at(w, R, ue, srr, geo, slices, setup.E_red)
        sizes = [p[0].size for p in parts]
        wj, Rj, uej, srrj, Wj = (np.concatenate([p[n] for p in parts]) for n in range(5))
        mu_j, dT_j = fmap(wj, Rj, uej, np.abs(srrj), np.repeat(T.ravel(), sizes))
        starts = np.r_[0, np.cumsum(sizes)[:-1]]     # each contact's first slice
        force = np.add.reduceat(Wj * -np.sign(srrj) * mu_j * wj, starts)
        mu = np.abs(force) / np.add.reduceat(Wj * wj, starts)
        dT = np.maximum.reduceat(dT_j, starts)
        return mu.reshape(w.shape), dT.reshape(w.shape)

    solve.friction_map = fmap.friction_map
    return solve
