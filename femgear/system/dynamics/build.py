"""Building a :class:`GearRotorModel` from a :class:`femgear.case.Case`, piece by piece.

:func:`build_model` joins four builders: the structure (bodies, bearings, shafts, the
power loop), the mesh (line-of-action vectors, stiffness table, mesh damping), the
excitation (eccentricity, pitch/profile errors, unbalance) and the damping (Rayleigh
on the flexible modes).  Friction and flank deviations change from one coupling pass
to the next: :func:`with_friction` and :func:`with_deviation` return the same model with
them replaced (build once, apply many: the structure, its modes and the integrators'
propagator caches stay valid).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np
from scipy.linalg import eigh

from femgear.case import Case
from femgear.case.checks import bearing_stations, toothed_width
from femgear.errors import SceneError
from femgear.levels import dynamics as dynamics_levels
from femgear.levels import housing as housing_levels
from femgear.levels import stiffness as stiffness_levels
from femgear.physics.excitation import CumulativePitchError, Eccentricity, ProfileError, RandomError, Unbalance
from femgear.system.dynamics.housing import couple_housing
from femgear.system.dynamics.layout import NDOF
from femgear.system.dynamics.mesh import (
    FrictionLines,
    MeshGeometry,
    StiffnessTable,
    as_stiffness_table,
    constant_stiffness,
    contact_line_stiffness,
    friction_from_lines,
    friction_table,
    mesh_geometry,
)
from femgear.system.dynamics.model import GearRotorModel, MeshDeviation
from femgear.system.dynamics.structure import assemble_structure

if TYPE_CHECKING:
    from femgear.physics.ltca.cycle import LTCACycle

Friction = float | Callable[[np.ndarray], np.ndarray]
"""μ as a number, or a callable μ(u) of the path position u [m]."""


def rayleigh_coefficients(omega_i: float, omega_j: float, ratio: float) -> tuple[float, float]:
    """a0, a1 with ζ(ω) = a0/(2ω) + a1 ω/2 equal to ``ratio`` at ω_i and ω_j [rad/s]."""
    if ratio == 0.0:
        return 0.0, 0.0
    return 2 * ratio * omega_i * omega_j / (omega_i + omega_j), 2 * ratio / (omega_i + omega_j)


def loop_spring(pair, T: np.ndarray, stiffness: float) -> np.ndarray:
    """Stiffness of a closed power loop (FZG rig) on the relative twist θz_gear + (r_b1/r_b2) θz_pinion.

    The free rotation of the train has zero twist; the loop resists the twist with
    ``stiffness`` [N m/rad] referred to the gear shaft (means over the halves).
    """
    w = np.zeros(NDOF)
    for side in range(2):
        w[6 * side + 5] = 0.5 * pair.rb1 / pair.rb2
        w[6 * (2 + side) + 5] = 0.5
    wr = w @ T
    return stiffness * np.outer(wr, wr)


#: the model's own mesh tables of c_γ (``stiffness.mesh_stiffness_per_width``), beside the stiffness levels
MODEL_TABLES: dict[str, Callable[[Case], StiffnessTable]] = {
    "constant": lambda case: constant_stiffness(case.pair, case.stiffness.mesh_stiffness_per_width),
    "contact-line": lambda case: contact_line_stiffness(case.pair, case.stiffness.mesh_stiffness_per_width,
                                                        case.stagger),
}


def stiffness_source(case: Case, stiffness):
    """The mesh stiffness: a given table or TVMS, "constant" (c_γ b), "contact-line" or a stiffness level
    (built through :mod:`femgear.levels.stiffness`)."""
    if stiffness is None:
        stiffness = case.levels.stiffness
    if isinstance(stiffness, str):
        table = MODEL_TABLES.get(stiffness)
        return table(case) if table is not None else stiffness_levels.REGISTRY.build(stiffness, case)
    return stiffness


LTCA_TABLE_SAMPLES = 512   #: samples per mesh period of the band-limited LTCA tables


def band_limited(samples: np.ndarray, n: int, orders: int | None = None) -> np.ndarray:
    """The trigonometric interpolant of one period of ``samples`` (length m) at n ≥ m equidistant phases.

    Keeps the mesh orders 0 … ``orders`` (default: all below the Nyquist order m/2; the
    Nyquist term of an even m is dropped: its phase is unknown) and adds none: the
    resampled table carries exactly the mesh orders the LTCA resolved.  (notes ltca_methods §5: resample with FFT, never
    linearly — a piecewise-linear table has kinks at every sample, i.e. spurious mesh
    orders m, 2m, … that, at low speed, fall on the 5–8 kHz mesh modes.)
    """
    x = np.asarray(samples, dtype=float)
    m = x.size
    if n < m:
        raise ValueError(f"band_limited: n = {n} must be ≥ the number of samples {m}")
    X = np.fft.rfft(x)
    keep = (m + 1) // 2 if orders is None else min((m + 1) // 2, orders + 1)     # orders 0 … keep − 1
    Y = np.zeros(n // 2 + 1, dtype=complex)
    Y[:keep] = X[:keep] * (n / m)
    return np.fft.irfft(Y, n=n)


def ltca_table(source) -> StiffnessTable | None:
    """The secant stiffness of an ``ltca`` level as a table band-limited to the mesh orders its contact
    discretisation resolves (``LTCACycle.resolved_orders``, :func:`femgear.physics.ltca.level.resolved_orders`);
    None for other levels."""
    cycle = getattr(source, "ltca", None)
    if cycle is None:
        return None
    exc = cycle.excitation
    n, H = max(LTCA_TABLE_SAMPLES, exc["k_secant_left"].size), cycle.resolved_orders
    return StiffnessTable(band_limited(exc["k_secant_left"], n, H), band_limited(exc["k_secant_right"], n, H),
                          label=f"ltca:{H}")


def tooth_contact_deviation(source) -> MeshDeviation | None:
    """The unloaded TE e_s = LTE_s − F_s/k_s of an ``ltca`` stiffness (None for other levels).

    With the secant stiffness k_s of the LTCA at the operating load, the mesh law
    N_s = k_s f(δ_s − e_s) reproduces the LTCA's own loads at that load (the LTCA's
    excitation identity; with k_s = F_s/(LTE − NLTE_s), e_s = NLTE_s).  e_s is the
    kinematic error of the flank modifications: it enters once, as a drive-flank
    deviation; the modifications are taken as equal on the coast flanks (the coast table
    is the drive table: exact for the uniform part, the coast flanks seldom touch).
    Band-limited like :func:`ltca_table`, on the same phase grid and to the same orders.
    """
    cycle = getattr(source, "ltca", None)
    if cycle is None:
        return None
    exc = cycle.excitation
    n, H = max(LTCA_TABLE_SAMPLES, exc["e_left"].size), cycle.resolved_orders
    e = np.array([band_limited(exc["e_left"], n, H), band_limited(exc["e_right"], n, H)])
    return MeshDeviation(drive=e, coast=e.copy())


def with_deviated_tooth_contact(model: GearRotorModel, unworn: LTCACycle, deviated: LTCACycle) -> GearRotorModel:
    """``model`` (built on the ``ltca`` cycle ``unworn``) excited by the LTCA of deviated flanks ``deviated``.

    ``unworn``/``deviated``: the :class:`~femgear.physics.ltca.cycle.LTCACycle` of
    :func:`femgear.physics.ltca.level.ltca_cycle` and its :meth:`~femgear.physics.ltca.cycle.LTCACycle.deviated`
    (wear, thermal growth).  The stiffness table
    stays the unworn secant k_s,0 (the structure, its modes and the integrators'
    propagators stay valid); the drive-flank deviation becomes e'_s = LTE − F_s/k_s,0 of
    the deviated cycle, so that the mesh law N_s = k_s,0 (δ − e'_s) reproduces the deviated
    LTCA's own loads and approach at the operating load (the excitation identity of
    :func:`tooth_contact_deviation` with the unworn secant; only the response to load
    changes about the operating point keeps the unworn secant).  Wear acts on the drive
    flanks: the coast flanks keep the unworn e_s.  Band-limited to the unworn cycle's orders.
    """
    if model.base_deviation is None:
        raise ValueError("with_deviated_tooth_contact: the model was not built on an ltca stiffness")
    from femgear.physics.ltca.analysis import unloaded_te

    k0, exc = unworn.excitation, deviated.excitation
    n, H = model.base_deviation.drive.shape[1], unworn.resolved_orders
    rows = [band_limited(unloaded_te(exc[f"lte_{h}"], exc[f"force_{h}"], k0[f"k_secant_{h}"]), n, H)
            for h in ("left", "right")]
    return replace(model, base_deviation=MeshDeviation(drive=np.array(rows), coast=model.base_deviation.coast))


def mesh_damping(geom: MeshGeometry, M24: np.ndarray, table: StiffnessTable, zeta_m: float) -> np.ndarray:
    """c_s = 2 ζ_m sqrt(k̄_s m_eq,s), m_eq,s = 1/Σ_j g_sj²/m_j [N s/m]."""
    if not 0 <= zeta_m < 1:
        raise ValueError(f"mesh_damping_ratio must be in [0, 1) (got {zeta_m!r})")
    mdiag = np.diag(M24)
    return np.array([2 * zeta_m * math.sqrt(k / np.sum(geom.g[s] ** 2 / mdiag)) for s, k in enumerate(table.mean)])


def excitations(case: Case, omega: tuple[float, float], fm: float):
    """Profile-error harmonics, random pitch errors, eccentricities and unbalances of both members."""
    err, (p, g) = case.errors, case.members
    offsets = (0.0, case.stagger)
    profile = tuple(ProfileError(err.profile_error, fm, err.profile_error_orders,
                                 math.radians(err.profile_error_phase_deg), off) for off in offsets)
    rnd = tuple(RandomError(err.random, fm, case.pair.z1, case.pair.z2, err.seed, off) for off in offsets)
    ecc = tuple(Eccentricity(m.eccentricity, w, math.radians(m.eccentricity_phase_deg)) for m, w in zip((p, g), omega))
    unb = tuple(Unbalance(m.unbalance, w, math.radians(m.eccentricity_phase_deg)) for m, w in zip((p, g), omega))
    return profile, rnd, ecc, unb


def pitch_errors(case: Case, fm: float) -> tuple[tuple[CumulativePitchError, ...], ...]:
    """Per helix (its mesh offset: the stagger), the cumulative pitch deviations of the members that have one."""
    members = [(m.cumulative_pitch_error, z, math.radians(m.cumulative_pitch_phase_deg))
               for m, z in zip(case.members, (case.pair.z1, case.pair.z2))]
    return tuple(tuple(CumulativePitchError(a, fm, z, phi, off) for a, z, phi in members if a > 0)
                 for off in (0.0, case.stagger))


def rayleigh_damping(M: np.ndarray, K_struct: np.ndarray, K_mean: np.ndarray, ratio: float):
    """a0 M_f + a1 K_struct on the two lowest flexible modes of the mean system.

    M_f = M − M Φ_r Φ_rᵀ M removes the rigid-body modes Φ_r (mass-normalised kernel of
    ``K_mean``), so rigid-body motion is not damped.  Returns (C_R, (a0, a1), flexible ω).
    """
    if not 0 <= ratio < 1:
        raise ValueError(f"rayleigh_ratio must be in [0, 1) (got {ratio!r})")
    w2, phi = eigh(K_mean, M)
    rigid = w2 <= 1e-6 * w2.max()
    wflex = np.sqrt(w2[~rigid])
    a0, a1 = rayleigh_coefficients(wflex[0], wflex[1], ratio)
    Mphi = M @ phi[:, rigid]
    return a0 * (M - Mphi @ Mphi.T) + a1 * K_struct, (a0, a1), wflex


def build_model(case: Case, level: str | None = None, *, stiffness: StiffnessTable | str | None = None,
                friction: Friction | None = None, rayleigh_ratio: float | None = None,
                mesh_damping_ratio: float | None = None, v_reg: float | None = None,
                bearing_span: tuple[float, float] | None = None, shaft_diameter: tuple[float, float] | None = None,
                backlash: float | None = None, load_stiffness: float | None = None,
                deviation: MeshDeviation | None = None, rigid_housing: bool = False) -> GearRotorModel:
    """Assemble the model of ``case``.

    ``level``: "lumped" or "timoshenko" (default: ``physics.dynamics``, "lumped" when that
    is "none").  ``stiffness``: a :class:`StiffnessTable`, "constant" (c_γ b),
    "contact-line", or a level of :mod:`femgear.physics.stiffness` (default ``physics.stiffness``).
    ``friction``: μ as a number or a callable μ(u) of the path position u [m] (default:
    :func:`femgear.levels.lubrication.static_friction`, the lubrication level's μ at the
    static load; the coupling passes its own μ(u)).
    The other keywords override the scene keys of the same meaning: ``<member>.bearing_span``,
    ``<member>.shaft_diameter``, ``stiffness.rayleigh_ratio``, ``stiffness.damping_ratio``,
    ``friction.regularisation_speed``, ``pair.backlash`` and ``operating.loop_stiffness``.
    ``deviation``: flank deviations of the drive and coast flanks (:class:`MeshDeviation`).
    An FE ``[housing]`` is coupled (:func:`femgear.system.dynamics.housing.couple_housing`: the bearings join the
    shafts to its seats) unless ``rigid_housing``.
    """
    pair, members = case.pair, case.members
    dyn = dynamics_levels.model_level(level, case.levels.dynamics)
    if not dyn.is_dynamic:
        raise SceneError("physics.dynamics", f"level {dyn.name!r} has no rotor model; choose a dynamic level")
    bearing_span = bearing_span or tuple(m.bearing_span for m in members)
    shaft_diameter = shaft_diameter or tuple(m.shaft_diameter for m in members)
    # helix centres at ±half; a pair with one mesh (spur, single helix) meshes in the mid-plane of its face: the
    # two "halves" coincide and the right one carries no mesh (k_right = 0 from the stiffness level)
    half = 0.5 * (pair.b + case.groove_width) if pair.n_helices == 2 else 0.0
    stations = tuple(bearing_stations(name, span, m.face_offset, toothed_width(case.scene, name))
                     for name, span, m in zip(("pinion", "gear"), bearing_span, members))
    load_stiffness = case.operating.loop_stiffness if load_stiffness is None else load_stiffness
    if load_stiffness < 0:
        raise ValueError(f"load_stiffness must be non-negative (got {load_stiffness!r})")
    b0 = case.backlash if backlash is None else backlash
    if b0 < 0:
        raise ValueError(f"backlash must be non-negative (got {b0!r})")

    st = assemble_structure(members, case.material, pair, dyn.shaft_elements, stations, shaft_diameter, half)
    K = st.K + (loop_spring(pair, st.T, load_stiffness) if load_stiffness > 0 else 0.0)
    geom = mesh_geometry(pair, half)
    G = geom.g @ st.T
    source = stiffness_source(case, stiffness)
    table = ltca_table(source)
    table = as_stiffness_table(source) if table is None else table
    zeta_m = case.stiffness.damping_ratio if mesh_damping_ratio is None else mesh_damping_ratio
    K_mean = st.K + sum(k * np.outer(G[s], G[s]) for s, k in enumerate(table.mean))
    ratio = case.stiffness.rayleigh_ratio if rayleigh_ratio is None else rayleigh_ratio
    C_R, (a0, a1), wflex = rayleigh_damping(st.M, K, K_mean, ratio)
    omega, fm = case.omega, case.operating.mesh_frequency
    torque = np.zeros(NDOF)
    for side in range(2):
        torque[6 * side + 5] = case.operating.pinion_torque / 2
        torque[6 * (2 + side) + 5] = case.operating.gear_torque / 2
    rate = np.zeros(NDOF)
    for side in range(2):
        rate[6 * side + 5], rate[6 * (2 + side) + 5] = omega
    profile, rnd, ecc, unb = excitations(case, omega, fm)
    model = GearRotorModel(
        level=dyn.name, pair=pair, M=st.M, K=K, C=st.C + C_R, T=st.T, G=G, H0=geom.h0 @ st.T, H1=geom.h1 @ st.T,
        stiffness=table, mesh_damping=mesh_damping(geom, st.M24, table, zeta_m), backlash=float(b0), mu=0.0,
        friction=None, mesh_frequency=fm, omega=omega, torque_full=torque, bearing_map=st.bearing_map,
        stagger=case.stagger, profile_errors=profile, random_errors=rnd, eccentricities=ecc, unbalances=unb,
        rayleigh=(a0, a1), geometry=geom, nominal_rate=rate, flexible_modes_hz=tuple(wflex / (2 * math.pi)),
        half_spacing=half, v_reg=case.friction.regularisation_speed if v_reg is None else v_reg,
        load_stiffness=load_stiffness, bearings=st.bearings, base_deviation=tooth_contact_deviation(source),
        pitch_errors=pitch_errors(case, fm),
    )
    layer = None if rigid_housing else housing_levels.of(case)
    if layer is not None and layer.reduced is not None:
        try:
            model = couple_housing(model, layer.reduced)
        except ValueError as exc:
            raise SceneError("housing.model", str(exc)) from None
    if friction is None:
        from femgear.levels.lubrication import static_friction

        friction = static_friction(case)
    return with_deviation(with_friction(model, friction), deviation)


def with_friction(model: GearRotorModel, friction: Friction, lines: FrictionLines | None = None) -> GearRotorModel:
    """``model`` with friction μ (a number or μ(u)); the load torque absorbs the mean friction torque.

    ``lines``: the contact-line points of :func:`femgear.system.dynamics.mesh.friction_lines` when already
    built (they do not depend on speed or friction; :class:`femgear.system.dynamics.family.SpeedFamily`)."""
    mu_of_u = None
    if callable(friction):              # μ(u) along the path is folded into the tables
        mu_of_u, mu = friction, 1.0
    else:
        mu = float(friction)
    if not mu >= 0:
        raise ValueError(f"friction coefficient must be non-negative (got {friction!r})")
    geom, rate, T1 = model.geometry, model.nominal_rate, model.torque_full[5] * 2
    torque = model.torque_full.copy()
    for side in range(2):
        torque[6 * (2 + side) + 5] = T1 * model.pair.rb2 / model.pair.rb1 / 2
    if mu == 0:
        return replace(model, mu=0.0, friction=None, torque_full=torque)
    if lines is None:
        ftab = friction_table(model.pair, geom.h0 @ rate, geom.h1 @ rate, model.stagger, model.v_reg, mu_of_u=mu_of_u)
    else:
        ftab = friction_from_lines(lines, geom.h0 @ rate, geom.h1 @ rate, model.v_reg, mu_of_u)
    # the load torque absorbs the mean friction power, so the free rotation does not drift
    N0 = T1 / model.pair.n_helices / geom.g[0, 5]     # mean normal force of a loaded helix
    Qf = -mu * N0 * (ftab.A.mean(axis=1) @ geom.h0 + ftab.B.mean(axis=1) @ geom.h1)
    rigid = rate / rate[5]
    loss = Qf @ rigid
    for d in (6 * 2 + 5, 6 * 3 + 5):
        torque[d] -= loss / (2 * rigid[d])
    return replace(model, mu=mu, friction=ftab, torque_full=torque)


def with_deviation(model: GearRotorModel, deviation: MeshDeviation | None) -> GearRotorModel:
    """``model`` with the drive/coast flank deviations ``deviation`` (None: none) added to
    the model's own (``base_deviation``: the flank modifications of the ``ltca`` level)."""
    if model.base_deviation is not None:
        deviation = model.base_deviation.plus(deviation)
    if deviation is not None and np.any(model.backlash + deviation.opening < 0):
        closing = -float(np.min(deviation.opening)) * 1e6
        raise SceneError("pair.backlash", f"the flank deviations close the dead zone by up to {closing:.3g} µm, more "
                                          f"than the backlash {model.backlash * 1e6:.3g} µm: the flanks would "
                                          "interpenetrate (the pair jams); give a larger backlash or less expansion")
    return replace(model, deviation=deviation)
