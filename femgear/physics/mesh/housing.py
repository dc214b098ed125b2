"""A parametric gearbox housing meshed by gmsh (OpenCASCADE) → a tetrahedral skfem mesh with named boundaries.

The housing (:class:`HousingGeometry`, SI, in the gear-rotor model's frame: shafts along z, the pinion axis at
(0, 0), the gear axis at (a_w, 0)) is a closed box with

- side walls of thickness ``wall`` around the two gears (the cavity reaches ``clearance`` beyond each tip circle
  along ±x and ±y, and from one end wall to the other along z);
- two end walls of thickness ``end_wall`` whose mid-planes sit at z = ±``end_position``; each carries the bores of
  both shafts in cylindrical bosses of outer radius ``bore_radius + boss`` and axial length ``boss_length``,
  centred on the wall's mid-plane (longer than the wall: they stick out on both sides);
- four feet under the floor (y < 0), ``foot`` × ``foot_height`` × ``foot`` blocks at the corners, clamped on
  their soles.

The bearing seat of station j (pinion_L, pinion_R, gear_L, gear_R; stations at z = ∓span/2 of their member) is
the part of its bore's cylinder of radius ``bore_radius[member]`` that lies within ±``bearing_width``/2 of the
station: the outer rings of the model's bearings sit there.

Named boundaries of the returned mesh (facet indices, :func:`housing_mesh`): ``seat_<station>`` (the four
seats), ``feet`` (the soles), ``outer`` (the outer skin that radiates to the surroundings: every boundary facet
outside the closed cavity, neither a bore nor a sole), ``inner`` (the cavity's walls and the bores away from the
seats).  Classified from the facets' centroids and normals after meshing: integer tags never leave this module.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from femgear.physics.mesh.section import _gmsh_session

#: the four bearing stations, in the order of every (4, …) bearing array of the dynamics
STATIONS = ("pinion_L", "pinion_R", "gear_L", "gear_R")
#: a facet belongs to a seat when its centroid is within this fraction of the element size of the bore cylinder
SEAT_TOLERANCE = 0.05


@dataclass(frozen=True)
class HousingGeometry:
    """Dimensions of the parametric housing [m] (module docstring)."""

    centre_distance: float          #: a_w: the gear axis at (a_w, 0) [m]
    tip_radius: tuple[float, float]  #: r_a of pinion and gear [m]
    station_z: tuple[float, float, float, float]   #: z of the four bearing stations [m]
    bore_radius: tuple[float, float]  #: radius of the bearing seat (bearing outer ring) of pinion and gear [m]
    bearing_width: tuple[float, float]  #: axial width of the seat of pinion and gear bearings [m]
    wall: float = 0.010             #: side wall thickness [m]
    end_wall: float = 0.012         #: end wall thickness [m]
    end_position: float | None = None  #: z of the end walls' mid-planes (± this) [m]; None: the outer stations
    clearance: float = 0.020        #: cavity beyond each tip circle [m]
    boss: float = 0.010             #: radial thickness of the bosses around the bores [m]
    boss_length: float | None = None  #: axial length of the bosses [m]; None: with the default ``end_position`` the
                                      #: shortest that holds every bearing seat (:func:`default_boss_length`), with
                                      #: a given one the end wall's thickness
    foot: float = 0.040             #: edge length of the square feet [m]
    foot_height: float = 0.020      #: height of the feet below the floor [m]
    size: float = 0.012             #: target element size [m]

    @property
    def boss_axial(self) -> float:
        """The bosses' axial length [m] (``boss_length``, else :func:`default_boss_length` with the default end walls,
        else the end wall's thickness)."""
        if self.boss_length is not None:
            return float(self.boss_length)
        return default_boss_length(self) if self.end_position is None else float(self.end_wall)

    @property
    def walls_at(self) -> float:
        """z of the end walls' mid-planes [m]."""
        return float(np.max(np.abs(self.station_z))) if self.end_position is None else float(self.end_position)

    def cavity(self) -> tuple[np.ndarray, np.ndarray]:
        """(low, high) corners of the closed cavity [m]."""
        ra1, ra2 = self.tip_radius
        z = self.walls_at - 0.5 * self.end_wall
        return (np.array([-ra1 - self.clearance, -max(ra1, ra2) - self.clearance, -z]),
                np.array([self.centre_distance + ra2 + self.clearance, max(ra1, ra2) + self.clearance, z]))

    def axis(self, station: int) -> np.ndarray:
        """(x, y) of the axis of ``station``'s shaft [m]."""
        return np.array([0.0 if station < 2 else self.centre_distance, 0.0])

    def check(self) -> None:
        """ValueError naming the first dimension that cannot make a housing."""
        for name in ("wall", "end_wall", "clearance", "boss", "boss_axial", "foot", "foot_height", "size"):
            if not getattr(self, name) > 0:
                raise ValueError(f"{name} must be positive (got {getattr(self, name)!r})")
        lo, hi = self.cavity()
        if not hi[2] > lo[2]:
            raise ValueError(f"end_position {self.walls_at!r} leaves no cavity between end walls {self.end_wall!r} thick")
        for member in range(2):
            r = self.bore_radius[member] + self.boss
            if not self.bore_radius[member] > 0:
                raise ValueError(f"bore_radius must be positive (got {self.bore_radius!r})")
            if r >= hi[1] + self.wall:
                raise ValueError(f"the boss of radius {r:.4g} m does not fit in the housing's height")


def default_boss_length(g: HousingGeometry) -> float:
    """The shortest boss, at least the end wall thick, that holds every bearing seat: 2 max_j(|z_w − |z_j|| + w_j/2) [m]."""
    need = max(abs(g.walls_at - abs(z)) + 0.5 * g.bearing_width[j // 2] for j, z in enumerate(g.station_z))
    return max(g.end_wall, 2.0 * need)


@dataclass(frozen=True)
class HousingMesh:
    """A tetrahedral housing mesh (skfem ``MeshTet``, named ``boundaries``) and the geometry it was built from."""

    mesh: object
    geometry: HousingGeometry


def housing_mesh(geometry: HousingGeometry) -> HousingMesh:
    """Mesh ``geometry`` with gmsh (linear tetrahedra of size ``geometry.size``) and name its boundaries."""
    geometry.check()
    with _gmsh_session("housing") as gmsh:
        _build(gmsh, geometry)
        gmsh.option.setNumber("Mesh.MeshSizeMax", geometry.size)
        gmsh.option.setNumber("Mesh.MeshSizeMin", 0.25 * geometry.size)
        gmsh.option.setNumber("Mesh.Algorithm3D", 1)
        gmsh.model.mesh.generate(3)
        p, t = _tets(gmsh)
    import skfem

    mesh = skfem.MeshTet(p, t)
    return HousingMesh(mesh=mesh.with_boundaries(_classify(mesh, geometry)), geometry=geometry)


def _build(gmsh, g: HousingGeometry) -> None:
    """The OpenCASCADE solid: box shell + bosses + feet − bores."""
    occ = gmsh.model.occ
    lo, hi = g.cavity()
    zw, te = g.walls_at, g.end_wall
    outer = occ.addBox(lo[0] - g.wall, lo[1] - g.wall, -zw - 0.5 * te, hi[0] - lo[0] + 2 * g.wall,
                       hi[1] - lo[1] + 2 * g.wall, 2 * zw + te)
    cavity = occ.addBox(lo[0], lo[1], lo[2], *(hi - lo))
    parts = [(3, occ.addBox(x, lo[1] - g.wall - g.foot_height, z, g.foot, g.foot_height, g.foot))
             for x in (lo[0] - g.wall, hi[0] + g.wall - g.foot) for z in (-zw - 0.5 * te, zw + 0.5 * te - g.foot)]
    bores = []
    for j, z in enumerate(g.station_z):
        member = j // 2
        x, y = g.axis(j)
        zc = zw if z > 0 else -zw
        z0, z1 = zc - 0.5 * g.boss_axial, zc + 0.5 * g.boss_axial
        parts.append((3, occ.addCylinder(x, y, z0, 0, 0, z1 - z0, g.bore_radius[member] + g.boss)))
        bores.append((3, occ.addCylinder(x, y, z0 - g.size, 0, 0, z1 - z0 + 2 * g.size, g.bore_radius[member])))
    shell, _ = occ.cut([(3, outer)], [(3, cavity)])
    body, _ = occ.fuse(shell, parts)
    occ.cut(body, bores)
    occ.synchronize()


def _tets(gmsh) -> tuple[np.ndarray, np.ndarray]:
    """(points (3, n), tetrahedra (4, m)) of the current gmsh model, unused nodes dropped."""
    tags, coords, _ = gmsh.model.mesh.getNodes()
    xyz = coords.reshape(-1, 3)
    index = np.full(int(tags.max()) + 1, -1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(tags.size)
    etypes, _, enodes = gmsh.model.mesh.getElements(3)
    t = np.vstack([index[n.astype(np.int64)].reshape(-1, 4) for et, n in zip(etypes, enodes) if et == 4])
    used = np.unique(t)
    remap = np.full(xyz.shape[0], -1, dtype=np.int64)
    remap[used] = np.arange(used.size)
    return xyz[used].T.copy(), remap[t].T.copy()


def _classify(mesh, g: HousingGeometry) -> dict[str, np.ndarray]:
    """Named boundary facets from centroids and normals (module docstring)."""
    facets = mesh.boundary_facets()
    c = mesh.p[:, mesh.facets[:, facets]].mean(axis=1)                  # (3, nf) centroids
    tol = SEAT_TOLERANCE * g.size
    lo, hi = g.cavity()
    sole = lo[1] - g.wall - g.foot_height
    names: dict[str, np.ndarray] = {"feet": facets[np.abs(c[1] - sole) < 1e-9 + 1e-6 * g.size]}
    on_bore = np.zeros(facets.size, bool)
    for j, z in enumerate(g.station_z):
        member = j // 2
        x, y = g.axis(j)
        # a facet lies on the bore cylinder when its three vertices do (chord facets: the centroid is a little inside)
        v = mesh.p[:, mesh.facets[:, facets]]                           # (3, 3 vertices, nf)
        r = np.hypot(v[0] - x, v[1] - y)
        bore = np.all(np.abs(r - g.bore_radius[member]) < tol + 1e-9, axis=0)
        on_bore |= bore
        names[f"seat_{STATIONS[j]}"] = facets[bore & (np.abs(c[2] - z) <= 0.5 * g.bearing_width[member] + 1e-9)]
    inside = np.all((c >= lo[:, None] - 1e-9) & (c <= hi[:, None] + 1e-9), axis=0)
    seats = np.concatenate([names[f"seat_{s}"] for s in STATIONS])
    names["outer"] = facets[~inside & ~on_bore & ~np.isin(facets, names["feet"])]
    names["inner"] = np.setdiff1d(facets, np.concatenate([names["outer"], names["feet"], seats]))
    return names
