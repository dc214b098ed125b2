"""Tier 1/3: the Timoshenko shaft element — identities and analytic beam frequencies."""

import math

import numpy as np
import pytest
from scipy.linalg import eigh

from femgear.system.dynamics.timoshenko import ShaftSection, beam_element_local, guyan, shaft_element

STEEL = dict(youngs_modulus=210e9, poisson_ratio=0.3, density=7850.0)


def assemble(section, length, ne):
    n = (ne + 1) * 6
    K, M = np.zeros((n, n)), np.zeros((n, n))
    for e in range(ne):
        k, m = shaft_element(section, length / ne)
        idx = np.arange(6 * e, 6 * e + 12)
        K[np.ix_(idx, idx)] += k
        M[np.ix_(idx, idx)] += m
    return K, M


def timoshenko_ss(section, length, mode):
    """Lower root of the simply supported Timoshenko frequency equation [Hz]."""
    E, G, A, I, rho, kap = (section.youngs_modulus, section.shear_modulus, section.area, section.second_moment,
                            section.density, section.shear_coefficient)
    k = mode * math.pi / length
    a = rho**2 * I / (kap * G)
    b = -(rho * A + rho * I * k**2 * (1 + E / (kap * G)))
    c = E * I * k**4
    return math.sqrt((-b - math.sqrt(b * b - 4 * a * c)) / (2 * a)) / (2 * math.pi)


def test_element_symmetric_and_rigid_body_modes():
    K, M = beam_element_local(ShaftSection(0.05, **STEEL), 0.1)
    assert np.allclose(K, K.T) and np.allclose(M, M.T)
    assert np.all(np.linalg.eigvalsh(M) > 0)
    w = np.linalg.eigvalsh(K)
    assert np.sum(np.abs(w) < 1e-6 * w.max()) == 6          # 3 translations + 3 rotations


@pytest.mark.parametrize("diameter", [0.05, 0.2])            # slender and thick (shear matters)
def test_simply_supported_bending_matches_timoshenko_theory(diameter):
    sec, L, ne = ShaftSection(diameter, **STEEL), 1.0, 30
    K, M = assemble(sec, L, ne)
    fix = [0, 1, 2, 5, 6 * ne + 0, 6 * ne + 1]              # pinned ends in x and y, axial/torsion held at one end
    free = np.setdiff1d(np.arange(K.shape[0]), fix)
    f = np.sqrt(np.abs(eigh(K[np.ix_(free, free)], M[np.ix_(free, free)], eigvals_only=True))) / (2 * math.pi)
    bending = [timoshenko_ss(sec, L, m) for m in (1, 2, 3)]
    for fa in bending:                                       # each appears twice (x and y planes)
        assert np.sum(np.abs(f - fa) / fa < 2e-3) == 2
    # the thick shaft differs from Euler-Bernoulli by several percent: shear is really in
    eb = (math.pi / L) ** 2 * math.sqrt(sec.youngs_modulus * sec.second_moment / (sec.density * sec.area)) / (2 * math.pi)
    if diameter == 0.2:
        assert bending[0] < 0.97 * eb


def test_axial_and_torsion_fixed_free():
    sec, L, ne = ShaftSection(0.05, **STEEL), 1.0, 30
    K, M = assemble(sec, L, ne)
    free = np.arange(6, K.shape[0])                          # clamped at node 0
    f = np.sqrt(np.abs(eigh(K[np.ix_(free, free)], M[np.ix_(free, free)], eigvals_only=True))) / (2 * math.pi)
    axial = math.sqrt(sec.youngs_modulus / sec.density) / (4 * L)
    torsion = math.sqrt(sec.shear_modulus / sec.density) / (4 * L)
    assert np.min(np.abs(f - axial)) / axial < 1e-3
    assert np.min(np.abs(f - torsion)) / torsion < 1e-3


def test_guyan_is_exact_for_statics():
    K, M = assemble(ShaftSection(0.05, **STEEL), 0.5, 4)
    keep = np.arange(6, 24)
    Kr, Mr, T = guyan(K + np.eye(K.shape[0]) * 1e3, M, keep)
    f = np.random.default_rng(0).normal(size=keep.size)
    full = np.zeros(K.shape[0])
    full[keep] = f
    u_full = np.linalg.solve(K + np.eye(K.shape[0]) * 1e3, full)
    assert np.allclose(np.linalg.solve(Kr, f), u_full[keep], rtol=1e-9, atol=1e-15)


def test_bad_section_refused():
    with pytest.raises(ValueError, match="diameter"):
        ShaftSection(0.0, **STEEL)
    with pytest.raises(ValueError, match="length"):
        beam_element_local(ShaftSection(0.05, **STEEL), -1.0)
