"""Files of the LTCA tool (``femgear ltca``) and the LTCA figures of the main job's ``results.json``.

``results.json`` of ``femgear ltca`` (SI values; ``units`` names each key's unit):

- ``summary``: ``scene``, ``torques`` [N m], ``design_torque``, ``model_seconds``, ``cached``,
  ``seconds``, ``options`` (n_phases, n_line, n_harmonics, refine_check, helix_alone, level) and
  ``per_torque``: a list of :func:`te_summary` objects, one per torque, ``design`` the same at the
  design torque;
- ``curves``: per torque the arrays over one mesh period: ``phase`` [base pitches], ``lte``,
  ``lte_left``, ``lte_right``, ``nlte`` [m], ``force_left``, ``force_right`` [N], ``k_total`` [N/m]
  (a single-helical or spur pair: no per-helix curves, no load share; ``helices`` says how many);
- ``harris`` (with ``--harris``): ``torque``, ``force``, ``peak_to_peak``,
  ``peak_to_peak_unmodified``, ``first_harmonic``, ``first_harmonic_unmodified``;
- ``units``, ``scene`` (the validated scene), ``outputs`` (files).

The maps (:func:`write_maps`): one ParaView collection per torque, ``ltca_maps_T<torque>Nm.pvd``,
with the pinion (part 0) and the gear (part 1) each on its own flank in mesh
(:mod:`femgear.physics.ltca.maps`); all VTK through :func:`femgear.edge.io.paraview.write_vtu`.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from femgear.edge.io.paraview import Frame, write_collection, write_vtu
from femgear.edge.io.results import write_json
from femgear.physics.ltca.maps import LoadMaps
from femgear.physics.ltca.te import HarrisMap, TEAnalysis

#: unit of every key of :func:`te_summary`, the curves and the Harris map
UNITS = {
    "torque": "N m", "design_torque": "N m", "force": "N", "lte_peak_to_peak": "m", "lte_harmonics": "m",
    "lte_harmonics_refined": "m", "lte_harmonics_change": "1 (of the largest refined amplitude)",
    "lte_peak_to_peak_refined": "m", "lte_mean": "m", "lte_transverse_peak_to_peak": "m",
    "nlte_peak_to_peak": "m", "nlte_max": "m", "stiffness_mean": "N/m", "stiffness_ripple": "1 (peak-to-peak / mean)",
    "load_share_left": "1", "load_share_right": "1", "load_balance_error": "1", "interior_load_share_min": "1 (left, right)", "max_pressure": "Pa",
    "max_pressure_interior": "Pa", "max_pressure_phase": "base pitches", "max_pressure_u": "m",
    "max_pressure_zeta": "m", "helices": "1", "lte_left_peak_to_peak": "m", "lte_right_peak_to_peak": "m",
    "phase": "base pitches", "lte": "m", "lte_left": "m", "lte_right": "m", "nlte": "m", "force_left": "N",
    "force_right": "N", "k_total": "N/m", "peak_to_peak": "m", "peak_to_peak_unmodified": "m",
    "first_harmonic": "m", "first_harmonic_unmodified": "m", "seconds": "s", "model_seconds": "s",
}


def _opt(x) -> Any:
    return None if x is None else x


def te_summary(a: TEAnalysis, cos_beta_b: float) -> dict[str, Any]:
    """The scalar figures of one :class:`TEAnalysis` (SI; the loaded TE along the normal line of action,
    ``lte_transverse_peak_to_peak`` on the transverse base tangent)."""
    p = a.pressure
    out = {
        "torque": a.torque, "force": a.force, "lte_peak_to_peak": a.peak_to_peak, "lte_mean": float(np.mean(a.lte)),
        "lte_transverse_peak_to_peak": a.peak_to_peak / cos_beta_b, "lte_harmonics": a.harmonics,
        "lte_harmonics_orders": list(range(1, a.harmonics.size + 1)),
        "lte_harmonics_refined": _opt(a.harmonics_refined), "lte_harmonics_change": _opt(a.harmonics_change),
        "lte_peak_to_peak_refined": _opt(a.peak_to_peak_refined),
        "lte_left_peak_to_peak": None if a.lte_left is None else float(np.ptp(a.lte_left)),
        "lte_right_peak_to_peak": None if a.lte_right is None else float(np.ptp(a.lte_right)),
        "nlte_peak_to_peak": a.nlte_peak_to_peak, "nlte_max": float(np.max(a.nlte)),
        "stiffness_mean": a.stiffness_mean, "stiffness_ripple": a.stiffness_ripple,
        "load_balance_error": a.balance_error,
        "interior_load_share_min": None if a.interior_force is None else
        (np.min(a.interior_force[:a.n_helices], axis=1) / a.force).tolist(),
        "max_pressure": p.pressure, "max_pressure_interior": p.interior_pressure, "max_pressure_phase": p.phase,
        "max_pressure_helix": p.helix, "max_pressure_u": p.u, "max_pressure_zeta": p.zeta,
        "max_pressure_where": p.where, "edge_contact": p.edge, "helices": a.n_helices,
    }
    if a.n_helices == 2:       # a load share and helix fields only where there are two helices
        out.update({"load_share_left": a.share_left, "load_share_right": a.share_right})
    else:
        for key in ("lte_left_peak_to_peak", "lte_right_peak_to_peak", "max_pressure_helix"):
            out.pop(key)
    return out


def te_curves(a: TEAnalysis) -> dict[str, Any]:
    """The curves over one mesh period; the per-helix ones (``lte_left``/``_right``, ``force_left``/``_right``)
    only for a two-helix pair."""
    out = {"torque": a.torque, "phase": a.phase, "lte": a.lte, "nlte": a.nlte, "k_total": a.k_total}
    if a.n_helices == 2:
        out.update({"lte_left": _opt(a.lte_left), "lte_right": _opt(a.lte_right), "force_left": a.force_left,
                    "force_right": a.force_right})
    return out


def harris_payload(h: HarrisMap) -> dict[str, Any]:
    return {"torque": h.torque, "force": h.force, "peak_to_peak": h.peak_to_peak,
            "peak_to_peak_unmodified": h.peak_to_peak_unmodified, "first_harmonic": h.first_harmonic,
            "first_harmonic_unmodified": h.first_harmonic_unmodified, "design_torque": h.design_torque}


def ltca_summary(result, scene_name: str, cos_beta_b: float) -> dict[str, Any]:
    """The ``summary`` object of the tool's ``results.json`` (:class:`femgear.physics.ltca.tool.LTCAToolResult`)."""
    o = result.options
    return {"scene": scene_name, "torques": list(result.torques), "design_torque": result.design.torque,
            "model_seconds": result.model_seconds, "cached": result.cached, "seconds": result.seconds,
            "options": {"n_phases": o.n_phases, "n_line": o.n_line, "n_harmonics": o.n_harmonics,
                        "refine_check": o.refine_check, "helix_alone": o.helix_alone, "level": o.level},
            "per_torque": [te_summary(a, cos_beta_b) for a in result.analyses],
            "design": te_summary(result.design, cos_beta_b)}


def write_ltca_results(path: str | Path, result, scene, cos_beta_b: float, outputs: dict[str, Path]) -> Path:
    """Write the tool's ``results.json`` (layout in the module docstring)."""
    payload = {"summary": ltca_summary(result, scene.meta.name, cos_beta_b),
               "curves": [te_curves(a) for a in result.analyses],
               "units": UNITS, "scene": scene.model_dump(), "outputs": {k: str(v) for k, v in outputs.items()}}
    if result.harris is not None:
        payload["harris"] = harris_payload(result.harris)
    return write_json(path, payload)


def member_mesh(m):
    """A :class:`femgear.physics.ltca.maps.MemberMap` as a meshio quad mesh with its point data and ``member``."""
    import meshio

    data = {k: np.asarray(v) for k, v in m.fields.items()}
    data["member"] = np.full(len(m.points), m.member, np.int32)
    return meshio.Mesh(m.points, [("quad", m.quads)], point_data=data)


def maps_mesh(maps: LoadMaps):
    """Both members of ``maps`` in one meshio quad mesh (point data of :func:`member_mesh`)."""
    import meshio

    meshes = [member_mesh(m) for m in maps.members]
    n0 = len(meshes[0].points)
    quads = np.vstack([meshes[0].cells[0].data, meshes[1].cells[0].data + n0])
    data = {k: np.concatenate([meshes[0].point_data[k], meshes[1].point_data[k]]) for k in meshes[0].point_data}
    return meshio.Mesh(np.vstack([meshes[0].points, meshes[1].points]), [("quad", quads)], point_data=data)


def torque_tag(torque: float) -> str:
    return f"T{torque:g}Nm"


def write_maps(out_dir: str | Path, maps: LoadMaps) -> Path:
    """``ltca_maps_T<torque>Nm.pvd``: the pinion (part 0) and the gear (part 1) maps at one torque."""
    frames = [Frame(time=0.0, part=i, name=("pinion", "gear")[i], mesh=member_mesh(m))
              for i, m in enumerate(maps.members)]
    return write_collection(out_dir, f"ltca_maps_{torque_tag(maps.torque)}", frames)


def write_maps_vtu(path: str | Path, maps: LoadMaps) -> Path:
    """Both members' maps as one ``.vtu`` (the main job's ``ltca_pressure.vtu``)."""
    return write_vtu(path, maps_mesh(maps))


def write_flank_pressure(path: str | Path, result, pair, youngs_modulus: float, poisson_ratio: float) -> Path:
    """Write the pressure map on the 3-D pinion flanks of both helices, in the pinion's body frame, as VTK
    unstructured quads (``.vtu``; :func:`femgear.physics.ltca.flank_map.flank_pressure_map`).

    The body's groove width and stagger come from ``result.groove`` and ``result.stagger``
    (:func:`femgear.physics.ltca.analysis.mesh_cycle`).
    Point data: ``p_max`` [Pa], ``w_mean`` [N/m], ``rho``, ``zeta`` [m], ``helix`` (0 left, 1 right),
    ``edge`` (1 on the flank's edges, where ``p_max`` is an edge contact and not a Hertz pressure).
    Both members in mesh: :func:`write_maps`, :func:`write_maps_vtu`.
    """
    import meshio

    from femgear.physics.ltca.flank_map import flank_pressure_map, helix_flank_quads

    fmap = flank_pressure_map(result, pair, youngs_modulus, poisson_ratio)
    pts, quads = helix_flank_quads(pair, 1, fmap.rho, fmap.zeta, result.groove, result.stagger)
    R, Z = np.meshgrid(fmap.rho, fmap.zeta, indexing="ij")
    n_h = fmap.p_max.shape[0]
    data = {"p_max": fmap.p_max.reshape(-1), "w_mean": fmap.w_mean.reshape(-1), "rho": np.tile(R.ravel(), n_h),
            "zeta": np.tile(Z.ravel(), n_h), "helix": np.repeat(np.arange(n_h), R.size).astype(np.int32),
            "edge": np.tile(fmap.edge.ravel(), n_h).astype(np.int32)}
    return write_vtu(path, meshio.Mesh(pts, [("quad", quads)], point_data=data))


__all__ = ["UNITS", "harris_payload", "ltca_summary", "maps_mesh", "member_mesh", "te_curves", "te_summary",
           "torque_tag", "write_flank_pressure", "write_ltca_results", "write_maps", "write_maps_vtu"]
