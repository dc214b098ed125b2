"""The ``tehl-point`` level: crowned-flank curvature, the elliptic thermal point EHL, the hand-over of wide
helices to face slices of line TEHL and the level in the lubrication registry."""

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from femgear.case import build_case
from femgear.errors import SceneError
from femgear.levels.contact import contact_pass
from femgear.levels.lubrication import crowning, lubrication_solver, tehl_path_options, tehl_point_solver, tehl_setup
from femgear.physics.contact.crowning import CrownedContact, crowned_contact
from femgear.physics.tehl.point import solve_tehl_point
from femgear.scene import scene_from_dict

from ._case import E_RED, OIL, PROPS, TAU0

BASE = Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml"


def _scene(crown=None, lubrication="tehl-point"):
    d = tomllib.loads(BASE.read_text())
    if crown is not None:
        d["modifications"] = {"crowning": crown}
    d["physics"]["lubrication"] = lubrication
    return build_case(scene_from_dict(d))


def test_an_uncrowned_flank_is_handed_over_to_face_slices(caplog):
    """An uncrowned pair is a line contact along its whole contact line: ``tehl-point`` binds and hands every
    contact over to line TEHL in face slices, saying so in one line; ``crowned_contact`` itself still needs a
    crowning (naming the key)."""
    from femgear.physics.tehl.slices import SLICES, SliceResult

    case = _scene(None)
    k = case.path
    i = k.u.size // 2 + 8
    with caplog.at_level("WARNING", logger="femgear.physics.tehl"):
        solve = tehl_point_solver(case)
        mu, dT = solve(w=4e5, R=k.R[i], ue=k.ue[i], srr=abs(k.srr[i]), T=313.0)
    r = solve.latest.results[0]
    assert isinstance(r, SliceResult) and solve.latest.handed_over == 1 and np.allclose(r.load, 4e5)
    assert len(r.results) == SLICES and 0.005 < mu[0] < 0.1 and dT[0] > 0
    assert len([m for m in caplog.messages if "handed over to line TEHL" in m]) == 1
    with pytest.raises(SceneError, match=r"modifications\.crowning"):
        crowned_contact(case.pair, crowning(case))


def test_point_and_face_slices_agree_at_the_crossover():
    """At the point solver's slender limit (the paper's pair with 10 µm crowning: R_x/R_y ≈ 0.0049, just above
    0.004) the point TEHL and the face-slice line TEHL of the same contact agree: h_c within 5 %, μ within 10 %
    (issue 43; measured 2.8 % and 0.1-0.6 % on both sides of the pitch point)."""
    from femgear.physics.tehl.slices import SliceGeometry, slice_contact

    case = _scene(10e-6)
    k, geo, setup = case.path, crowned_contact(case.pair, crowning(case)), tehl_setup(case)
    contact = contact_pass(case)
    om1 = 2 * math.pi * case.operating.pinion_rpm / 60
    sl = SliceGeometry(om1, om1 * case.pair.z1 / case.pair.z2, case.pair.beta_b, geo.contact_length, geo.kappa)
    T = case.operating.ambient_temperature
    for i in (k.u.size // 2 - 8, k.u.size // 2 + 8):
        w, R, ue, srr = float(np.broadcast_to(contact.line_load, k.u.shape)[i]), float(k.R[i]), float(k.ue[i]), float(k.srr[i])
        Rx, Ry = (float(v) for v in geo.radii(R))
        assert 0.004 < Rx / Ry < 0.0055
        point = solve_tehl_point(float(geo.load(w)), Rx, ue, abs(srr), T, Ry=Ry, level=1, **setup.kwargs())
        sliced = slice_contact(w, R, ue, srr, T, Rx, Ry, sl, setup, tol=0.01)
        assert sliced.hc == pytest.approx(point.hc, rel=0.05) and sliced.mu == pytest.approx(point.mu, rel=0.10)


def test_crowning_radii_spur_and_helical():
    """Spur (beta_b = 0): R_x = R, R_y = b^2/(8 (C1 + C2)). Helical: the eigenvalues of the
    curvature tensor, close to 1/R + kappa sin^2 and kappa cos^2 (kappa R << 1)."""
    spur = CrownedContact(kappa=8 * 20e-6 / 0.02**2, beta_b=0.0, contact_length=0.02)
    Rx, Ry = spur.radii(0.01)
    assert float(Rx) == pytest.approx(0.01, rel=1e-12)
    assert float(Ry) == pytest.approx(0.02**2 / (8 * 20e-6), rel=1e-12)
    hel = CrownedContact(kappa=0.5, beta_b=math.radians(28.0), contact_length=0.01)
    Rx, Ry = hel.radii(0.01)
    s2, c2 = math.sin(hel.beta_b) ** 2, math.cos(hel.beta_b) ** 2
    assert 1 / float(Rx) == pytest.approx(100.0 + 0.5 * s2, rel=1e-5)
    assert 1 / float(Ry) == pytest.approx(0.5 * c2, rel=2e-3)  # - (kappa s c)^2 R
    # invariants of the tensor: trace and determinant
    assert 1 / Rx + 1 / Ry == pytest.approx(100.0 + 0.5, rel=1e-12)


def test_baseline_crowned_contact_and_level():
    """10 um on both members of the paper's pair: slender ellipses (lambda ~ 0.005), the load
    of one tooth pair; the registered level solves one position (grid level 1)."""
    case = _scene(10e-6)
    geo = crowned_contact(case.pair, crowning(case))
    assert geo.kappa == pytest.approx(8 * 20e-6 / case.pair.b**2)
    Rx, Ry = geo.radii(case.path.R)
    assert np.all((Rx / Ry > 0.003) & (Rx / Ry < 0.006))
    cp = contact_pass(case)
    i = int(np.argmax(np.abs(case.path.srr)))
    solver = lubrication_solver(case)
    mu, dT = solver(w=cp.line_load[i], R=case.path.R[i], ue=case.path.ue[i], srr=abs(case.path.srr[i]),
                    T=case.operating.ambient_temperature)
    assert 0.005 < float(mu[0]) < 0.1 and 1.0 < float(dT[0]) < 100.0


def test_elliptic_thermal_film_thicker_than_circular():
    """Same load and R_x: the wide ellipse (lambda = 0.1) carries a thicker film (NVM: +30 %
    at these conditions, the isothermal start) and a lower pressure."""
    kw = dict(oil=OIL, E_red=E_RED, props=PROPS, tau0=TAU0, level=1)
    circ = solve_tehl_point(100.0, 0.0123, 1.09, 0.3, 313.0, **kw)
    ell = solve_tehl_point(100.0, 0.0123, 1.09, 0.3, 313.0, Ry=0.123, **kw)
    assert ell.hc > 1.1 * circ.hc and ell.pmax < circ.pmax
    assert np.all(np.isfinite(ell.p)) and ell.dT_max > 0


def test_a_contact_the_point_solver_cannot_hold_is_handed_over_to_face_slices(monkeypatch, caplog):
    """Where the point solve raises, the contact gets the face-slice line TEHL of the same contact (the hand-over
    of the slender limit), and one warning line says so."""
    import femgear.physics.tehl.point_level as pl
    from femgear.errors import ConvergenceError
    from femgear.physics.tehl.slices import SliceGeometry, slice_contact

    case = _scene(10e-6)

    def fail(*args, **kw):
        raise ConvergenceError("ehl point", "load continuation failed")

    monkeypatch.setattr(pl, "solve_tehl_point", fail)
    w, R, ue, srr, T = 9.0e4, 0.0123, 1.0, 0.3, 313.0
    with caplog.at_level("WARNING", logger="femgear.physics.tehl"):
        mu, dT = tehl_point_solver(case)(w=w, R=R, ue=ue, srr=srr, T=T)
    geo = crowned_contact(case.pair, crowning(case))
    Rx, Ry = (float(v) for v in geo.radii(R))
    om1 = 2 * math.pi * case.operating.pinion_rpm / 60
    sl = SliceGeometry(om1, om1 * case.pair.z1 / case.pair.z2, case.pair.beta_b, geo.contact_length, geo.kappa)
    ref = slice_contact(w, R, ue, srr, T, Rx, Ry, sl, tehl_setup(case), **tehl_path_options(case))
    assert mu[0] == pytest.approx(ref.mu, rel=1e-12) and dT[0] == pytest.approx(ref.dT_surface, rel=1e-12)
    assert "handed over to line TEHL" in caplog.text


def test_the_tehl_levels_run_at_turbo_speed_and_refuse_beyond_their_envelope():
    """The turbo zoo pair (131 m/s pitch line, u_e to 57 m/s) and the wind stage (map corner beyond Moes M 340) are
    accepted by both TEHL levels; the turbo pair at 1.6 times its speed (u_e to 90 m/s, above the envelope's
    100 m/s only at 1.8 times) is refused before computing, naming the key and the levels that run there."""
    from femgear.levels import check_case
    from femgear.levels.contact import reduced_modulus_of
    from femgear.levels.lubrication import oil_law, tehl_axes
    from femgear.physics.tehl.solver import MAX_ENTRAINMENT, map_corner_moes
    from femgear.scene import load_scene

    zoo = BASE.parents[0] / "zoo"
    for level in ("tehl", "tehl-point"):
        build_case(load_scene(zoo / "turbo.toml", [f'physics.lubrication="{level}"', "modifications.crowning=20e-6"]))
        with pytest.raises(SceneError, match=r'entrainment speed reaches.*"ehl-line"') as info:
            check_case(build_case(load_scene(zoo / "turbo.toml", [f'physics.lubrication="{level}"',
                                                                  "operating.speed_rpm=28000",
                                                                  "modifications.crowning=20e-6"])))
        assert info.value.key == "physics.lubrication" and MAX_ENTRAINMENT == 100.0
    wind = build_case(load_scene(zoo / "wind.toml", ['physics.lubrication="tehl"']))
    assert map_corner_moes(tehl_axes(wind), oil_law(wind), reduced_modulus_of(wind))[0] > 300.0
