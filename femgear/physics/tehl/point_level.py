"""The ``tehl-point`` lubrication level: thermal EHL of the crowned flanks' elliptic contacts.

At each path position the pair's contact is an ellipse (:mod:`femgear.physics.contact.crowning`:
R_x across the contact line from the profile radius and the crowning, R_y along it from
the lead crowning ``modifications.crowning``; the load of one tooth pair from the line
load of the load sharing times its mean contact-line length). The contact is solved by
:func:`femgear.physics.tehl.point.solve_tehl_point` (isothermal nested start, then the strip-wise
energy loop) in the map signature of every lubrication level
(:mod:`femgear.levels.lubrication`): ``solver(w=, R=, ue=, srr=, T=) -> (mu, dT)``, μ the
sliding (Couette) friction, dT the largest film temperature rise.  The stationary
roughness (``[roughness.peak]`` fixed at x0, the paper's model; ``[roughness.synthetic]``)
enters each contact's film (:func:`femgear.physics.tehl.point.rough_levels`).

Frame: X along the entrainment, normal to the contact line, Y along it. The rolling
velocity of a helical pair lies in the transverse plane, at beta_b to X; the solver takes
the entrainment speed of the path (its transverse rolling speed) along X and neglects the
component along the contact line, i.e. along the major axis of the slender ellipse. By
Chittenden et al.'s (1985) oblique-entrainment fit (recalled, /work/shared/notes/
ehl_extensions.md) the film follows the radius in the flow direction, 1/R_e = cos^2 th/R_x
+ sin^2 th/R_y ~ cos^2 th/R_x for a slender ellipse (th = beta_b), and h_c ~ R^0.46 at fixed
speed and load (Hamrock-Dowson), so solving with R_x instead of R_e gives h_c lower by a
factor ~ (cos^2 beta_b)^0.46: 0.89 at beta_b = 28 deg (the paper's pair; 1 for spur gears).
Reported, not modelled.

``POINT_LEVEL`` is the grid level used by default (16 2^k intervals along X, stretched in
Y): level 1 (33 x ~33 nodes) meets the path speed target (studies/benchmarks/tehl_point.py
reports its time and its difference from level 2).  Where the point solver fails (a heavily
loaded slender ellipse: the paper's pair with 10 µm crowning under the LTCA's line-end loads,
M ≈ 5000–5500 at R_x/R_y ≈ 0.0045, where the Newton trials on level 1 and on level 2 lose the
film), that contact is solved as a line contact of the same load per unit length on R_x (the
R_x/R_y → 0 limit), with one warning line naming it.
"""

from __future__ import annotations

import logging

import numpy as np

from femgear.errors import ConvergenceError
from femgear.physics.contact.crowning import MIN_POINT_RATIO, CrownedContact
from femgear.physics.tehl.point import solve_tehl_point
from femgear.physics.tehl.reuse import LatestSolve, RecordingSolver, ReuseReport, reusable
from femgear.physics.tehl.slices import SLICES, SliceGeometry, SliceLevel, slice_contact
from femgear.physics.tehl.solver import TEHLSetup

POINT_LEVEL = 1
log = logging.getLogger("femgear.physics.tehl")


def tehl_point_solver(geo: CrownedContact, setup: TEHLSetup, line_options: dict, roughness=None, level: int | None = None,
                      details: list | None = None, slices: SliceGeometry | None = None, **options):
    """Direct thermal point-EHL solves (one per query point) in the map signature.

    ``geo``: the crowned contact of the pair (:func:`femgear.physics.contact.crowning.crowned_contact`; its
    ``kappa`` 0 for an uncrowned pair); ``setup``: oil, solids and traction; ``roughness``: a ``[roughness]``
    table with stationary features, or None (smooth); ``line_options``: the options of the line TEHL
    sequences of the hand-over (:func:`femgear.physics.tehl.solver.tehl_path_results`: tolerance, first level and,
    from :func:`femgear.levels.lubrication.tehl_path_options`, the spike-resolving grids, with its plain-grid
    fallback per slice).  ``slices``: the kinematics of the pair's face slices
    (:class:`femgear.physics.tehl.slices.SliceGeometry`): a contact more slender than
    :data:`femgear.physics.contact.crowning.MIN_POINT_RATIO` (every contact of an uncrowned pair), or one the
    point solver fails on, is handed over to line TEHL in face slices (:func:`femgear.physics.tehl.slices.
    slice_contact`), said in one log line per call; without ``slices`` such a contact is solved as one line
    contact of the same load per length on R_x.  ``details``: a list that receives each contact's result
    (:class:`femgear.physics.tehl.point.TEHLPointResult` or :class:`~femgear.physics.tehl.slices.SliceResult`);
    a contact queried again (same radii and speeds) at a load and bulk temperature that changed so little that
    the change of μ and ΔT is estimated below 1e-4 reuses its latest solve (:mod:`femgear.physics.tehl.reuse`;
    reported in the solver's :attr:`~femgear.physics.tehl.reuse.RecordingSolver.latest`, which also holds the
    inputs and results of the latest call, its reuse and its hand-overs (the film of the run's last pass,
    :meth:`femgear.levels.lubrication.Lubrication.film`)."""
    kw = {**setup.kwargs(), "roughness": roughness, **options}
    level = POINT_LEVEL if level is None else level

    memory: dict = {}     # per contact (R_x, R_y, ue, srr): the latest solves [(load, result, T)], newest last
    sliced = SliceLevel()  # the grid level of the latest face-slice hand-over (the next contact's first try)

    def solve(w, R, ue, srr, T):
        w, R, ue, srr, T = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float))
                                                 for a in (w, R, ue, srr, T)))
        with np.errstate(divide="ignore"):
            Rx, Ry = geo.radii(R)
        F = geo.load(w)
        mu, dT = np.empty(w.shape), np.empty(w.shape)
        results, reuse, handed = [], ReuseReport(), []
        for i in np.ndindex(w.shape):
            args = (float(F[i]), float(Rx[i]), float(ue[i]), abs(float(srr[i])), float(T[i]))
            key = args[1:4] + (float(Ry[i]),)
            r = reusable(memory.get(key, []), args[0], reuse, args[4], setup.oil.beta_t)
            if r is None:
                ratio = float(Rx[i] / Ry[i]) if np.isfinite(Ry[i]) else 0.0
                if ratio < MIN_POINT_RATIO and slices is not None:
                    handed.append("slender")
                    r = _slices(w[i], R[i], ue[i], srr[i], T[i], Rx[i], Ry[i], slices, setup, line_options, sliced)
                else:
                    try:
                        r = solve_tehl_point(*args, Ry=float(Ry[i]), level=level, **kw)
                    except ConvergenceError as exc:
                        if slices is None:
                            r = _line_contact(float(w[i]), args, setup, line_options, exc)
                        else:
                            handed.append("failed")
                            r = _slices(w[i], R[i], ue[i], srr[i], T[i], Rx[i], Ry[i], slices, setup, line_options,
                                        sliced)
                memory[key] = (memory.get(key, []) + [(args[0], r, args[4])])[-2:]
            mu[i], dT[i] = r.mu, r.dT_surface
            results.append(r)
        if handed:
            log.warning("tehl-point: %d of %d contacts handed over to line TEHL in up to %d face slices each, with each "
                        "slice's own load, curvature, speeds and SRR (%d more slender than the point solver's "
                        "R_x/R_y = %g or uncrowned, %d where the point solver failed)", len(handed), w.size, SLICES,
                        handed.count("slender"), MIN_POINT_RATIO, handed.count("failed"))
        if details is not None:
            details.extend(results)
        if reuse.reused:
            log.info("tehl-point: %s", reuse.describe())
        latest = LatestSolve((w.copy(), R.copy(), ue.copy(), srr.copy(), T.copy()), tuple(results), reuse, len(handed))
        return mu, dT, latest

    return RecordingSolver(solve)


def _slices(w, R, ue, srr, T, Rx, Ry, geo: SliceGeometry, setup: TEHLSetup, options: dict, last: SliceLevel):
    """The contact in face slices, first tried on ``last.level`` with ``last.layers`` (the previous hand-over's,
    updated)."""
    layers = {} if last.layers is None else {"nz": last.layers}
    r = slice_contact(float(w), float(R), float(ue), float(srr), float(T), float(Rx), float(Ry), geo, setup,
                      start_level=last.level, **{**options, **layers})
    last.level, last.layers = r.level, r.layers
    return r


def _line_contact(w: float, args: tuple, setup: TEHLSetup, options: dict, exc: ConvergenceError):
    """The line-contact TEHL solve (``options`` of :func:`solve_tehl_line`) of a contact the point solver could not hold (R_x/R_y → 0
    limit: the same load per unit length on the radius R_x across the line), logged as a warning naming the
    contact."""
    from femgear.physics.tehl.line import solve_tehl_line

    F, Rx, ue, srr, T = args
    log.warning("tehl-point: the point solver failed at F = %.4g N, R_x = %.4g m (%s); this contact is solved "
                "as a line contact (physics.lubrication = \"tehl\" there)", F, Rx,
                str(exc).split(": ", 1)[-1].split(" (last:")[0][:100])
    return solve_tehl_line(w, Rx, ue, srr, T, **setup.kwargs(), **options)
