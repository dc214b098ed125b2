"""gmsh meshes of transverse gear sections and simple reference domains → skfem meshes.

The only module of femgear that imports gmsh (inside the functions).  Every mesh comes
back as a :class:`skfem.MeshTri` whose ``boundaries`` dict carries the named physical
groups (``flank``, ``fillet``, ``tip``, ``bore``, ``sides``; ``inner``/``outer`` for an
annulus) — integer tags never leave this module.

Mesh size is one knob ``h`` [m]; ``refine_at`` (x, y) adds a Distance/Threshold field
that shrinks the size to ``h * refine_ratio`` within ``h`` of that point (the contact
point of a compliance solve).
"""

from __future__ import annotations

import math
from contextlib import contextmanager

import numpy as np

from femgear.physics.geometry.gear import GearPair
from femgear.physics.geometry.profile import tooth_profile


@contextmanager
def _gmsh_session(name: str):
    import gmsh

    # interruptible=False: gmsh's default sets SIGINT to SIG_DFL for the rest of the process (never restored), so
    # a later Ctrl-C killed femgear without its "interrupted" line and exit code 130
    gmsh.initialize(["-noenv"], readConfigFiles=False, interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("General.NumThreads", 1)
        gmsh.model.add(name)
        yield gmsh
    finally:
        gmsh.finalize()


def _to_skfem(gmsh, groups: dict[str, int]):
    """Linear triangles of the current gmsh model → MeshTri with named boundaries."""
    import skfem

    tags, coords, _ = gmsh.model.mesh.getNodes()
    xy = coords.reshape(-1, 3)[:, :2]
    index = np.full(int(tags.max()) + 1, -1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(tags.size)
    etypes, _, enodes = gmsh.model.mesh.getElements(2)
    tri = [index[n.astype(np.int64)].reshape(-1, 3) for et, n in zip(etypes, enodes) if et == 2]
    t = np.vstack(tri)
    used = np.unique(t)
    remap = np.full(xy.shape[0], -1, dtype=np.int64)
    remap[used] = np.arange(used.size)
    p = xy[used].T.copy()
    t = remap[t].T.copy()
    mesh = skfem.MeshTri(p, t)
    facet_key = {tuple(sorted(f)): i for i, f in enumerate(mesh.facets.T)}
    boundaries = {}
    for name, tag in groups.items():
        ids = []
        for ent in gmsh.model.getEntitiesForPhysicalGroup(1, tag):
            ets, _, ens = gmsh.model.mesh.getElements(1, ent)
            for et, en in zip(ets, ens):
                if et != 1:
                    continue
                for a, b in remap[index[en.astype(np.int64)]].reshape(-1, 2):
                    ids.append(facet_key[(min(a, b), max(a, b))])
        boundaries[name] = np.unique(np.array(ids, dtype=np.int64))
    return skfem.MeshTri(mesh.p, mesh.t, _boundaries=boundaries)


def _size_field(gmsh, h: float, refine_at, refine_ratio: float, refine_radius: float | None = None,
                grade: tuple[float, float, float] | None = None, tip: tuple[list, float] | None = None):
    """Background size: ``h``, refined to ``h·refine_ratio`` within ``refine_radius`` of ``refine_at``.

    ``grade`` = (r0, rate, h_max, reach): below the radius r0 the size may grow with the depth and beyond
    ``reach`` from ``refine_at`` with the distance, max(refined size, h·refine_ratio + rate·(r0 − r),
    h + rate·(distance − reach)), capped at h_max (a far field coarse towards the bore and round the ring).
    ``tip`` = (tip curves, h_tip): the size is at most h_tip on those curves, growing from them at the rate
    :data:`TIP_GRADE` (a narrow tip gets its two elements across without refining the whole tooth).
    """
    f = gmsh.model.mesh.field
    if refine_at is None and tip is None:
        gmsh.option.setNumber("Mesh.MeshSizeMin", h)
        gmsh.option.setNumber("Mesh.MeshSizeMax", h)
        return
    if refine_at is None:
        base = f.add("MathEval")
        f.setString(base, "F", f"{h:.9f}")
        _background(gmsh, _with_tip(gmsh, base, tip))
        return
    geo = gmsh.model.geo
    pt = geo.addPoint(refine_at[0], refine_at[1], 0.0, h)
    geo.synchronize()
    d = f.add("Distance")
    f.setNumbers(d, "PointsList", [pt])
    th = f.add("Threshold")
    f.setNumber(th, "InField", d)
    f.setNumber(th, "SizeMin", h * refine_ratio)
    f.setNumber(th, "SizeMax", h)
    rr = 0.5 * h if refine_radius is None else refine_radius
    f.setNumber(th, "DistMin", rr)
    f.setNumber(th, "DistMax", rr + 3 * h)
    if grade is not None:
        r0, rate, h_max, reach = grade
        radial, cap, far = f.add("MathEval"), f.add("MathEval"), f.add("MathEval")
        f.setString(radial, "F", f"{h * refine_ratio:.9f} + {rate:.9f} * ({r0:.9f} - Sqrt(x*x + y*y))")
        f.setString(cap, "F", f"{h_max:.9f}")
        x0, y0 = refine_at
        f.setString(far, "F", f"{h:.9f} + {rate:.9f} * (Sqrt((x - {x0:.9f})^2 + (y - {y0:.9f})^2) - {reach:.9f})")
        hi = f.add("Max")
        f.setNumbers(hi, "FieldsList", [th, radial, far])
        th = f.add("Min")
        f.setNumbers(th, "FieldsList", [hi, cap])
    _background(gmsh, _with_tip(gmsh, th, tip))


def _with_tip(gmsh, field: int, tip: tuple[list, float] | None) -> int:
    """``field``, capped near the tip curves of ``tip`` = (curves, h_tip) by h_tip + TIP_GRADE·distance."""
    if tip is None:
        return field
    f = gmsh.model.mesh.field
    curves, h_tip = tip
    d = f.add("Distance")
    f.setNumbers(d, "CurvesList", curves)
    f.setNumber(d, "Sampling", 40)
    near = f.add("MathEval")
    f.setString(near, "F", f"{h_tip:.9f} + {TIP_GRADE:.9f} * F{d}")
    out = f.add("Min")
    f.setNumbers(out, "FieldsList", [field, near])
    return out


def _background(gmsh, field: int) -> None:
    gmsh.model.mesh.field.setAsBackgroundMesh(field)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)


def annulus(r_in: float, r_out: float, h: float):
    """Annulus r_in < r < r_out (r_in = 0: full disc) with boundaries ``inner``/``outer``."""
    if not 0 <= r_in < r_out:
        raise ValueError(f"need 0 ≤ r_in < r_out, got r_in={r_in}, r_out={r_out}")
    if not 0 < h < (r_out - r_in):
        raise ValueError(f"mesh size h={h} must be positive and below the wall thickness {r_out - r_in}")
    with _gmsh_session("annulus") as gmsh:
        geo = gmsh.model.geo
        c = geo.addPoint(0, 0, 0, h)

        def circle(r):
            return _circle(geo, c, r, h)

        outer = circle(r_out)
        loops = [geo.addCurveLoop(outer)]
        inner = []
        if r_in > 0:
            inner = circle(r_in)
            loops.append(geo.addCurveLoop(inner))
        s = geo.addPlaneSurface(loops)
        geo.synchronize()
        if r_in == 0:
            gmsh.model.mesh.embed(0, [c], 2, s)
        groups = {"outer": gmsh.model.addPhysicalGroup(1, outer)}
        if inner:
            groups["inner"] = gmsh.model.addPhysicalGroup(1, inner)
        gmsh.model.addPhysicalGroup(2, [s])
        _size_field(gmsh, h, None, 1.0)
        gmsh.model.mesh.generate(2)
        return _to_skfem(gmsh, groups)


def _circle(geo, c, r, h):
    """Circle of radius r as four arcs with nodes at 0, π/2, π, 3π/2 (support points)."""
    pts = [geo.addPoint(r * math.cos(a), r * math.sin(a), 0, h) for a in np.arange(4) * math.pi / 2]
    return [geo.addCircleArc(pts[i], c, pts[(i + 1) % 4]) for i in range(4)]


MIN_RIM = 0.5         #: thinnest rim the bodies mesh, s_R/h_t (ISO 6336-3: Y_B defined for 0.5 < s_R/h_t < 1.2)
THICK_RIM = 1.2       #: s_R/h_t from which ISO 6336-3's rim factor Y_B is 1
THIN_RIM = 1.0        #: below this s_R/h_t a rim is meshed with RIM_ELEMENTS elements through it
RIM_ELEMENTS = 3.0    #: elements through a thin rim
TIP_FRACTION = 0.45   #: element size on a narrow tip circle, as a fraction of the tip's width
TIP_GRADE = 0.3       #: growth of the element size with the distance from a narrow tip [m/m]


def _rot(x, y, a):
    c, s = math.cos(a), math.sin(a)
    return c * x - s * y, s * x + c * y


def tip_width(prof) -> float:
    """Arc width of the tooth on its tip circle [m]."""
    return 2 * prof.ra * float(prof.half_angle(np.array([prof.ra * (1 - 1e-9)]))[0])


def tip_size(prof, h: float) -> float | None:
    """Element size the tip circle needs when ``h`` puts fewer than two elements across it (None: ``h`` does):
    :data:`TIP_FRACTION` of the tip's width (a pointed tip of a high addendum modification, e.g. the FZG A
    pinion's 0.59 mm = 0.13 m_n)."""
    width = tip_width(prof)
    if not width > 0:
        raise ValueError(f"the tooth tip has no width ({width * 1e3:.3g} mm): a pointed tooth cannot be meshed")
    return None if h <= width / 2 else TIP_FRACTION * width


def rim_limit(pair: GearPair, member: int) -> float:
    """The largest bore radius the FE bodies mesh: the root radius less ISO 6336-3's thinnest rim,
    s_R = :data:`MIN_RIM` h_t (h_t = r_a − r_f, the tooth depth) [m]."""
    rf, ra = (pair.rf1, pair.ra1) if member == 1 else (pair.rf2, pair.ra2)
    return rf - MIN_RIM * (ra - rf)


def check_rim(pair: GearPair, member: int, r_bore: float) -> None:
    """Raise ValueError (naming ``bore_radius`` and the thinnest rim that runs) for a rim s_R = r_f − r_bore below
    :data:`MIN_RIM` h_t, ISO 6336-3's lower limit of the rim factor Y_B."""
    rf, ra = (pair.rf1, pair.ra1) if member == 1 else (pair.rf2, pair.ra2)
    limit = rim_limit(pair, member)
    if not 0 < r_bore <= limit * (1 + 1e-12):
        raise ValueError(
            f"bore_radius={r_bore * 1e3:.4g} mm leaves a rim s_R = {(rf - r_bore) * 1e3:.4g} mm = "
            f"{(rf - r_bore) / (ra - rf):.3g} h_t below the root circle, under ISO 6336-3's lower limit "
            f"{MIN_RIM:g} h_t (h_t = {(ra - rf) * 1e3:.4g} mm); the thinnest rim that runs has bore_radius ≤ "
            f"{math.floor(limit * 1e6) / 1e3:g} mm")       # rounded down to the µm: the figure itself runs


def shaft_clamp_radius(pair: GearPair, member: int, shaft_radius: float) -> float:
    """Where the body of a member cut on its shaft (no bore) is clamped: at the shaft radius, but never less
    than :data:`THICK_RIM` h_t below the root circle [m].  The body is solid; below ISO 6336-3's thick-rim
    depth 1.2 h_t (Y_B = 1) the core no longer changes the tooth's deflection or root stress, and the steel
    between is kept elastic: a pinion shaft whose journals are nearly as large as its root circle (the zoo's
    automotive and wind pinions) is a solid pinion, not a thin rim."""
    rf, ra = (pair.rf1, pair.ra1) if member == 1 else (pair.rf2, pair.ra2)
    return min(shaft_radius, rf - THICK_RIM * (ra - rf))


def rim_size(pair: GearPair, member: int, r_bore: float) -> float | None:
    """Largest element size in a thin rim (s_R < :data:`THIN_RIM` h_t, where ISO 6336-3's Y_B > 1.29 and the rim
    bends with the tooth): s_R/:data:`RIM_ELEMENTS` [m]; None for a thicker rim (its far field's own rule)."""
    rf, ra = (pair.rf1, pair.ra1) if member == 1 else (pair.rf2, pair.ra2)
    s_r = rf - r_bore
    return s_r / RIM_ELEMENTS if s_r < THIN_RIM * (ra - rf) else None


def _teeth_outline(geo, c, prof, offsets, full: bool, h: float):
    """gmsh curves of the teeth outline (root space centre to root space centre, fillets, flanks, tips).

    Returns (outline curves in loop order, {"flank", "fillet", "tip"} curve lists, first space point,
    last space point).  Each tooth is built from its right space centre (−π/z) to its left (+π/z).
    """
    z, rf = prof.z, prof.rf
    pitch = 2 * math.pi / z
    fil = prof.part <= 1
    inv_ = (prof.part == 2)
    xf, yf = prof.x[fil], prof.y[fil]
    xi = np.concatenate([[prof.x[fil][-1]], prof.x[inv_]])
    yi = np.concatenate([[prof.y[fil][-1]], prof.y[inv_]])

    def pts(xs, ys, a):                              # tooth frame (centre line along +x) → rotated to +y and by a
        return [geo.addPoint(*_rot(x, y, a + math.pi / 2), 0, h) for x, y in zip(xs, ys)]

    def space(a, side):
        return geo.addPoint(*_rot(rf * math.cos(side * pitch / 2), rf * math.sin(side * pitch / 2), a + math.pi / 2), 0, h)

    flanks, fillets, tips, outline = [], [], [], []
    first_space = prev_end = None
    for a in offsets:
        # right half has y ≥ 0 in the tooth frame → rotated, it lies at larger angle; mirror y → −y first
        right_space = space(a, -1) if prev_end is None else prev_end
        first_space = right_space if first_space is None else first_space
        pf_r = pts(xf, -yf, a)                         # fillet, mirrored half (angle −)
        pi_r = pts(xi[1:], -yi[1:], a)
        pi_l = pts(xi[1:][::-1], yi[1:][::-1], a)
        pf_l = pts(xf[::-1], yf[::-1], a)
        prev_end = first_space if full and a == offsets[-1] else space(a, 1)
        tooth = [geo.addCircleArc(right_space, c, pf_r[0]), geo.addSpline(pf_r), geo.addSpline([pf_r[-1]] + pi_r),
                 geo.addCircleArc(pi_r[-1], c, pi_l[0]), geo.addSpline(pi_l + [pf_l[0]]), geo.addSpline(pf_l),
                 geo.addCircleArc(pf_l[-1], c, prev_end)]
        outline += tooth
        fillets += [tooth[0], tooth[1], tooth[5], tooth[6]]
        flanks += [tooth[2], tooth[4]]
        tips.append(tooth[3])
    return outline, {"flank": flanks, "fillet": fillets, "tip": tips}, first_space, prev_end


def _teeth_reach(prof, n_teeth: int, refine_at) -> float:
    """Distance from ``refine_at`` that covers every tooth of an ``n_teeth`` sector centred on +y [m]."""
    half = (n_teeth / 2) * 2 * math.pi / prof.z
    tip = np.array([prof.ra * math.sin(half), prof.ra * math.cos(half)])
    return float(np.hypot(*(tip - np.asarray(refine_at))))


def gear_section(pair: GearPair, member: int, h: float, n_teeth: int | None = 3, bore_radius: float | None = None,
                 refine_at: tuple[float, float] | None = None, refine_ratio: float = 0.2,
                 refine_radius: float | None = None,
                 split_radius: float | None = None, grade: tuple | None = None, ring: bool = False):
    """Transverse section of ``member`` (1 pinion, 2 gear): ``n_teeth`` teeth down to the bore.

    Tooth 0 is centred on the +y axis; ``n_teeth=None`` meshes the whole gear.  A
    sector is cut along radial lines through the middle of the tooth spaces (boundary
    ``sides``).  ``bore_radius`` defaults to half the root radius (a gear on a shaft).
    ``split_radius``: a circle (arc) of that radius embedded in the mesh, its edges named
    ``split`` (interior; the groove floor of :mod:`femgear.physics.mesh.segment`).  ``grade`` =
    (rate, h_max[, fine_teeth]): below ``split_radius`` (or the root circle) the size grows with the
    depth at ``rate`` [m/m] up to ``h_max`` (needs ``refine_at``), and so it does with the distance
    beyond the middle ``fine_teeth`` teeth (default all ``n_teeth``).
    ``ring``: the ``n_teeth`` teeth sit on a whole ring (root circle outside them, named ``rim``) on a
    whole bore circle, instead of a sector cut along radial lines.
    A tip narrower than two elements of size ``h`` gets its own size near the tip circles (:func:`tip_size`);
    a thin rim (:func:`rim_size`) caps the far field at a third of its thickness.  Raises ValueError (naming
    ``bore_radius``) if the rim is thinner than ISO 6336-3's 0.5 h_t (:func:`check_rim`).
    """
    prof = tooth_profile(pair, member)
    z = prof.z
    rf = prof.rf
    r_bore = 0.5 * rf if bore_radius is None or bore_radius <= 0 else bore_radius
    check_rim(pair, member, r_bore)
    if split_radius is not None and not r_bore < split_radius < rf:
        raise ValueError(f"split_radius={split_radius:.4g} m must lie between the bore and the root circle")
    if not h > 0:
        raise ValueError(f"mesh size h={h!r} must be positive")
    h_tip = tip_size(prof, h)
    thin = rim_size(pair, member, r_bore)
    if thin is not None and grade is not None:       # a thin rim: RIM_ELEMENTS elements through it, all round
        grade = (grade[0], min(grade[1], max(thin, h * refine_ratio))) + tuple(grade[2:])
    full = n_teeth is None or n_teeth >= z
    nt = z if full else int(n_teeth)
    if nt < 1:
        raise ValueError(f"n_teeth must be ≥ 1, got {n_teeth}")
    pitch = 2 * math.pi / z
    offsets = [(k - (nt - 1) / 2) * pitch for k in range(nt)] if not full else [k * pitch for k in range(nt)]
    with _gmsh_session("gear_section") as gmsh:
        geo = gmsh.model.geo
        c = geo.addPoint(0, 0, 0, h)
        outline, groups_curves, first_space, last_space = _teeth_outline(geo, c, prof, offsets, full, h)
        a_last = offsets[-1] + pitch / 2 + math.pi / 2
        a_first = offsets[0] - pitch / 2 + math.pi / 2
        surf, groups_curves["bore"], sides, split = _close_section(geo, c, outline, full, r_bore, split_radius,
                                                                   (first_space, last_space, a_first, a_last), h,
                                                                   ring and not full, rf)
        if sides:
            groups_curves["rim" if ring else "sides"] = sides
        geo.synchronize()
        if split:
            gmsh.model.mesh.embed(1, split, 2, surf)
            groups_curves["split"] = split
        groups = {name: gmsh.model.addPhysicalGroup(1, cs) for name, cs in groups_curves.items()}
        gmsh.model.addPhysicalGroup(2, [surf])
        _size_field(gmsh, h, refine_at, refine_ratio, refine_radius,
                    None if grade is None else (split_radius or rf, grade[0], grade[1],
                                                _teeth_reach(prof, grade[2] if len(grade) > 2 else nt, refine_at)),
                    None if h_tip is None else (groups_curves["tip"], h_tip))
        gmsh.model.mesh.generate(2)
        return _to_skfem(gmsh, groups)


def _close_section(geo, c, outline, full, r_bore, split_radius, ends, h, ring=False, rf=0.0):
    """The section's plane surface: the teeth ``outline`` closed by the bore (and the sector's sides).

    Returns (surface, bore curves, side curves — the toothless root circle with ``ring`` —, split
    curves to embed).  ``ends`` = (first space point, last space point, polar angle of the first side,
    of the last side).  ``ring``: the teeth sit on a whole ring: the outline goes on round the root
    circle (radius ``rf``) and the bore is a whole circle.
    """
    first_space, last_space, a_first, a_last = ends
    if full or ring:
        if ring:                                  # the root circle on round from the last tooth space to the first
            span = 2 * math.pi - (a_last - a_first)
            mids = [geo.addPoint(rf * math.cos(a_last + span * i / 3), rf * math.sin(a_last + span * i / 3), 0, h)
                    for i in (1, 2)]
            rim = [geo.addCircleArc(p0, c, p1) for p0, p1 in zip([last_space] + mids, mids + [first_space])]
            outline = outline + rim
        bore = _circle(geo, c, r_bore, h)
        surf = geo.addPlaneSurface([geo.addCurveLoop(outline), geo.addCurveLoop(bore)])
        return surf, bore, (rim if ring else []), (_circle(geo, c, split_radius, h) if split_radius else [])

    def at(r, a):
        return geo.addPoint(r * math.cos(a), r * math.sin(a), 0, h)

    bl, bf = at(r_bore, a_last), at(r_bore, a_first)
    arc = geo.addCircleArc(bl, c, bf)
    if split_radius:
        sl, sf = at(split_radius, a_last), at(split_radius, a_first)
        sides = [geo.addLine(last_space, sl), geo.addLine(sl, bl), geo.addLine(bf, sf), geo.addLine(sf, first_space)]
        loop = outline + sides[:2] + [arc] + sides[2:]
        split = [geo.addCircleArc(sl, c, sf)]
    else:
        sides = [geo.addLine(last_space, bl), geo.addLine(bf, first_space)]
        loop = outline + [sides[0], arc, sides[1]]
        split = []
    return geo.addPlaneSurface([geo.addCurveLoop(loop)]), [arc], sides, split
