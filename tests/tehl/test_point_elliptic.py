"""The ``tehl-point`` level: crowned-flank curvature, the elliptic thermal point EHL, the
scene refusal of an uncrowned flank and the level in the lubrication registry."""

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from femgear.case import build_case
from femgear.errors import SceneError
from femgear.levels.contact import contact_pass
from femgear.levels.lubrication import crowning, lubrication_solver, tehl_point_solver, tehl_setup
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


def test_uncrowned_flank_refused_naming_the_key():
    with pytest.raises(SceneError, match=r"modifications\.crowning"):     # when the case is bound
        build_case(_scene(None))
    with pytest.raises(SceneError, match=r"modifications\.crowning"):
        case = _scene(None, lubrication="formula")
        crowned_contact(case.pair, crowning(case))


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


def test_a_contact_the_point_solver_cannot_hold_is_solved_as_a_line_contact(monkeypatch, caplog):
    """The R_x/R_y → 0 limit: where the point solve raises, the contact gets the line TEHL of the same load
    per unit length on R_x, and a warning names it."""
    import femgear.physics.tehl.point_level as pl
    from femgear.errors import ConvergenceError
    from femgear.physics.tehl.line import solve_tehl_line

    case = _scene(10e-6)

    def fail(*args, **kw):
        raise ConvergenceError("ehl point", "load continuation failed")

    monkeypatch.setattr(pl, "solve_tehl_point", fail)
    w, R, ue, srr, T = 9.0e4, 0.0123, 1.0, 0.3, 313.0
    with caplog.at_level("WARNING", logger="femgear.physics.tehl"):
        mu, dT = tehl_point_solver(case)(w=w, R=R, ue=ue, srr=srr, T=T)
    Rx, _ = crowned_contact(case.pair, crowning(case)).radii(R)
    line = solve_tehl_line(w, float(Rx), ue, srr, T, level=case.numerics.ehl_level, **tehl_setup(case).kwargs())
    assert mu[0] == pytest.approx(line.mu, rel=1e-12) and dT[0] == pytest.approx(line.dT_max, rel=1e-12)
    assert "solved as a line contact" in caplog.text


def test_the_tehl_levels_are_refused_above_their_speed_range():
    """The turbo zoo pair (131 m/s pitch line): both TEHL levels refuse before computing, naming the key and
    the levels that run there; the marine pair (13 m/s) is accepted."""
    from femgear.scene import load_scene

    zoo = BASE.parents[0] / "zoo"
    for level in ("tehl", "tehl-point"):
        with pytest.raises(SceneError, match=r'above 100 m/s.*"ehl-line"') as info:
            build_case(load_scene(zoo / "turbo.toml", [f'physics.lubrication="{level}"',
                                                       "modifications.crowning=20e-6"]))
        assert info.value.key == "physics.lubrication"
    assert build_case(load_scene(zoo / "marine.toml", ['physics.lubrication="tehl"'])).levels.lubrication == "tehl"


def test_tehl_is_refused_where_its_map_leaves_the_line_solvers_range():
    """The wind stage's map corner reaches Moes M = 346 at L = 4.3, where the line solve does not start: refused
    before computing, pointing to the direct ehl-line; the FZG C pair's corner (127) is accepted."""
    from femgear.levels.contact import reduced_modulus_of
    from femgear.levels.lubrication import oil_law, tehl_axes
    from femgear.physics.tehl.solver import map_corner_moes
    from femgear.scene import load_scene

    zoo = BASE.parents[0] / "zoo"
    with pytest.raises(SceneError, match=r"Moes M = 346.*\"ehl-line\""):
        build_case(load_scene(zoo / "wind.toml", ['physics.lubrication="tehl"']))
    fzg = build_case(load_scene(zoo / "fzg_c14.toml"))
    assert map_corner_moes(tehl_axes(fzg), oil_law(fzg), reduced_modulus_of(fzg))[0] == pytest.approx(126.8, rel=1e-3)
    build_case(load_scene(zoo / "fzg_c14.toml", ['physics.lubrication="tehl"']))
