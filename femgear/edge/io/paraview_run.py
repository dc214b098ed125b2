"""The main job's ParaView output (layout and geometry: :mod:`femgear.edge.io.paraview`)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from femgear.edge.io.paraview import Frame, collection_files, flank_surface, write_collection, write_vtu
from femgear.results import RunResult

N_FACE = 9          # points across the face width of one helix
N_RING = 72         # points around a pitch circle
MAX_FRAMES = 50     # time steps of the mesh cycle written


def _inv(alpha: float) -> float:
    return float(np.tan(alpha) - alpha)


def flank_frames(result: RunResult) -> list[Frame]:
    """One surface per member (both helices; the one helix, centred on z = 0, of a single-helical or spur pair)
    with the fields along the path."""
    import meshio

    from femgear.edge.io.along_path import along_path

    case, pair = result.case, result.case.pair
    fields = along_path(result)
    b, s = pair.b, pair.b + case.scene.pair.groove_width
    shared = {k: fields[k] for k in ("hertz_pressure", "film_central", "film_minimum", "load_per_length",
                                     "sliding_speed", "friction_coefficient", "temperature_rise") if k in fields}
    frames = []
    members = (("pinion", pair.rb1, fields["radius_pinion"], (0.0, 0.0), -_inv(pair.alpha_wt), +1.0),
               ("gear", pair.rb2, fields["radius_gear"], (pair.a_w, 0.0), np.pi - _inv(pair.alpha_wt), -1.0))
    for part, (name, rb, r, centre, angle0, hand) in enumerate(members):
        data = dict(shared)
        for key, label in (("wear", "wear_depth"), ("thermal_deviation", "thermal_deviation")):
            if f"{key}_{name}" in fields:
                data[label] = fields[f"{key}_{name}"]
        points, quads, point_data = [], [], {k: [] for k in data}
        helices = ((+1.0, -s / 2), (-1.0, +s / 2)) if pair.n_helices == 2 else ((+1.0, 0.0),)
        for sigma, zc in helices:      # left, right helix (one helix: the left's hand, in the mid-plane)
            z = np.linspace(zc - b / 2, zc + b / 2, N_FACE)
            twist = hand * sigma * np.tan(pair.beta_b) / rb
            pts, q = flank_surface(rb, r, centre, angle0, +1.0, z, zc, twist)
            quads.append(q + sum(len(p) for p in points))
            points.append(pts)
            for k, v in data.items():
                point_data[k].append(np.tile(np.asarray(v, dtype=float), N_FACE))
        mesh = meshio.Mesh(np.concatenate(points), [("quad", np.concatenate(quads))],
                           point_data={k: np.concatenate(v) for k, v in point_data.items()})
        frames.append(Frame(time=0.0, part=part, name=f"flank_{name}", mesh=mesh))
    return frames


def dynamics_frames(result: RunResult) -> list[Frame]:
    """The last mesh cycle: pitch circles of the four helix halves with their displacement."""
    import meshio

    from femgear.system.dynamics.layout import BODIES, point_jacobian

    pair = result.case.pair
    res = result.coupled.state.dynamics.response
    t = res.t
    period = 1.0 / res.mesh_frequency
    idx = np.flatnonzero(t >= t[-1] - period)
    idx = idx[np.linspace(0, len(idx) - 1, min(len(idx), MAX_FRAMES)).round().astype(int)]
    half = result.coupled.state.dynamics.model.half_spacing
    angle = np.linspace(0.0, 2.0 * np.pi, N_RING, endpoint=False)
    rings = []
    for body in BODIES:
        radius, cx = (pair.rw1, 0.0) if body.startswith("pinion") else (pair.rw2, pair.a_w)
        zc = -half if body.endswith("_L") else half
        offsets = np.column_stack([radius * np.cos(angle), radius * np.sin(angle), np.zeros(N_RING)])
        rings.append((offsets + [cx, 0.0, zc], np.stack([point_jacobian(o) for o in offsets])))
    points = np.concatenate([p for p, _ in rings])
    seg = np.column_stack([np.arange(N_RING), (np.arange(N_RING) + 1) % N_RING])
    lines = np.concatenate([seg + k * N_RING for k in range(len(BODIES))])
    mean = res.displacement[idx].mean(axis=0)
    frames = []
    for i in idx:
        u = np.concatenate([J @ res.displacement[i, 6 * k: 6 * k + 6] for k, (_, J) in enumerate(rings)])
        w = np.concatenate([J @ (res.displacement[i] - mean)[6 * k: 6 * k + 6] for k, (_, J) in enumerate(rings)])
        force = np.repeat([res.mesh_force[i, 0], res.mesh_force[i, 1]] * 2, N_RING)
        mesh = meshio.Mesh(points, [("line", lines)],
                           point_data={"displacement": u, "vibration": w, "mesh_force": force})
        frames.append(Frame(time=float(t[i] - t[idx[0]]), part=0, name="response", mesh=mesh))
        if res.bearings is not None:
            frames.append(Frame(time=float(t[i] - t[idx[0]]), part=1, name="bearings",
                                mesh=bearing_mesh(result, res.bearings, i)))
    return frames


def bearing_mesh(result: RunResult, loads, i: int):
    """The four bearing stations at time index ``i`` as vertices on the shaft axes, with ``bearing_force`` (the load
    of the shaft on the bearing) and ``bearing_force_dynamic`` (about its mean over the record) [N]."""
    import meshio

    model = result.coupled.state.dynamics.model
    points = model.bearings.centre
    return meshio.Mesh(points, [("vertex", np.arange(len(points))[:, None])],
                       point_data={"bearing_force": loads.force[i], "bearing_force_dynamic": loads.force[i] - loads.mean})


def body_frames(result: RunResult) -> list[Frame]:
    """``thermal = "fe"``: the FE gear sections of both members at the run's temperature rises
    (``RunResult.body``, :func:`femgear.stages.body_sections`): ``temperature_rise`` [K] and ``displacement`` [m]
    at the vertices, ``von_mises`` [Pa] per triangle (:func:`femgear.edge.io.fields.body_mesh`).  The gear's
    section is shifted by the centre distance along x."""
    from femgear.edge.io.fields import body_mesh

    a_w = result.case.pair.a_w
    return [Frame(time=0.0, part=part, name=("body_pinion", "body_gear")[part],
                  mesh=body_mesh(section, offset=(a_w if section.member == 2 else 0.0, 0.0)))
            for part, section in enumerate(result.body or ())]


def face_mesh(result: RunResult):
    """The face-resolved fields (``wear.field = "face"``: ``wear_depth``; ``thermal = "fe3d"``:
    ``thermal_deviation``, both [m]) on the 3-D loaded flanks of tooth 0 of both members, both helices (the one
    of a single-helical pair), as a meshio quad mesh (None without face fields).

    Each member's body frame (:func:`femgear.physics.ltca.flank_map.helix_flank_quads`: the LTCA's member bodies) turned
    into its meshing position, the gear's axis at (a_w, 0) (:func:`femgear.physics.ltca.maps.to_mesh`); a flank point at path position u_k has
    roll distance ρ₁ = u_k (pinion) or ρ₂ = T₁T₂ − u_k (gear), face coordinate ζ_m of the run's face grid.
    Point data also ``member`` (1, 2), ``helix`` (0 left, 1 right), ``u``, ``rho``, ``zeta`` [m]."""
    import meshio

    from femgear.physics.ltca.flank_map import helix_flank_quads
    from femgear.physics.ltca.maps import to_mesh
    from femgear.system.coupling.thermal import roll_distances

    t, case = result.tribology, result.case
    if t.face_grid is None:
        return None
    pair, grid = case.pair, np.asarray(t.face_grid, float)
    u = case.path.u
    rho = roll_distances(pair, u)
    fields = {k: v for k, v in (("wear_depth", t.wear_face), ("thermal_deviation", t.thermal_face)) if v is not None}
    points, quads, data = [], [], {k: [] for k in (*fields, "member", "helix", "u", "rho", "zeta")}
    U, Z = np.meshgrid(u, grid, indexing="ij")
    n_h = pair.n_helices
    for j in (0, 1):
        pts, q = helix_flank_quads(pair, j + 1, rho[j], grid, case.groove_width, case.stagger)
        pts = to_mesh(pair, j + 1, pts)
        quads.append(q + sum(len(p) for p in points))
        points.append(pts)
        for k, v in fields.items():
            data[k].append(np.asarray(v[j], float)[:n_h].reshape(-1))
        data["member"].append(np.full(len(pts), j + 1, np.int32))
        data["helix"].append(np.repeat(np.arange(n_h, dtype=np.int32), U.size))
        data["u"].append(np.tile(U.ravel(), n_h))
        data["rho"].append(np.tile(np.repeat(rho[j], grid.size), n_h))
        data["zeta"].append(np.tile(Z.ravel(), n_h))
    return meshio.Mesh(np.concatenate(points), [("quad", np.concatenate(quads))],
                       point_data={k: np.concatenate(v) for k, v in data.items()})


def write_run_paraview(result: RunResult, out_dir: str | Path) -> dict[str, Path]:
    """Write ``flanks.pvd``, with dynamics ``dynamics.pvd``, with ``thermal = "fe"`` ``body.pvd``, and with
    ``stiffness = "ltca"`` the LTCA's pressure and load maps on the 3-D loaded flanks of both members, both
    helices, each turned into its meshing position, ``ltca_pressure.vtu`` (``RunResult.ltca_maps``), and with
    face-resolved fields (``wear.field = "face"``, ``thermal = "fe3d"``) ``flank_face.vtu`` (:func:`face_mesh`).

    Returns every file written: a collection's ``.pvd`` by name (``flanks_pvd``) and its ``.vtu`` files by their
    path relative to ``out_dir`` (``flanks/flank_pinion_0000.vtu``)."""
    out_dir = Path(out_dir)
    files: dict[str, Path] = {}

    def collection(name: str, frames: list[Frame]) -> None:
        pvd = write_collection(out_dir, name, frames)
        files[f"{name}_pvd"] = pvd
        files.update({str(f.relative_to(out_dir)): f for f in collection_files(pvd)})

    collection("flanks", flank_frames(result))
    if result.ltca_maps is not None:
        from femgear.edge.io.ltca import write_maps_vtu

        files["ltca_pressure_vtu"] = write_maps_vtu(out_dir / "ltca_pressure.vtu", result.ltca_maps)
    face = face_mesh(result)
    if face is not None:
        files["flank_face_vtu"] = write_vtu(out_dir / "flank_face.vtu", face)
    if result.body is not None:
        collection("body", body_frames(result))
    if result.coupled is not None and result.coupled.state.dynamics is not None:
        collection("dynamics", dynamics_frames(result))
    return files


__all__ = ["body_frames", "dynamics_frames", "face_mesh", "flank_frames", "write_run_paraview"]
