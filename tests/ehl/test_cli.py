"""`femgear ehl point|line --json` prints one JSON object as the last stdout line."""

import json

import pytest

from femgear.edge.cli import main


def _last_json(capsys):
    out = capsys.readouterr().out.strip().splitlines()
    return json.loads(out[-1])


def test_cli_line_json(capsys, tmp_path):
    rc = main(["ehl", "line", "--M", "20", "--L", "10", "--level", "4", "--json",
               "--out", str(tmp_path)])
    d = _last_json(capsys)
    assert rc == 0 and d["converged"] is True
    for key in ("Hc", "Hmin", "Pmax", "iterations", "nodes", "seconds"):
        assert key in d
    assert 4.5 < d["Hc"] < 5.8
    assert (tmp_path / "ehl_line.vtu").exists() and (tmp_path / "ehl_line_centreline.png").exists()


def test_cli_point_json(capsys):
    rc = main(["ehl", "point", "--M", "20", "--L", "10", "--level", "1", "--json"])
    d = _last_json(capsys)
    assert rc == 0 and d["converged"] is True and d["nodes"] == 33 * 33
    assert 0 < d["Hmin"] < d["Hc"]


@pytest.mark.slow
def test_cli_nonconvergence_is_reported(capsys):
    rc = main(["ehl", "point", "--M", "1000", "--L", "10", "--level", "1", "--json"])
    d = _last_json(capsys)
    if rc != 0:  # the coarse-only high-load case is allowed to fail, but loudly
        assert d["converged"] is False and d["Hc"] is None and "error" in d
    else:
        assert d["converged"] is True and d["Hc"] > 0


@pytest.mark.slow
def test_cli_point_method_picks_the_solver_and_reports_it(capsys):
    """--method fas and --method newton solve (20, 10) on 129² within 1 % of each other (two independent
    discretisations, FD multigrid and FE Newton); the JSON says which solver ran; auto takes the multigrid there."""
    got = {}
    for method in ("fas", "newton", "auto"):
        assert main(["ehl", "point", "--M", "20", "--L", "10", "--level", "3", "--method", method, "--json"]) == 0
        got[method] = _last_json(capsys)
    assert got["fas"]["method"] == "fas" and got["newton"]["method"] == "newton" and got["auto"]["method"] == "fas"
    assert abs(got["fas"]["Hc"] / got["newton"]["Hc"] - 1) < 0.01
    assert abs(got["fas"]["Hmin"] / got["newton"]["Hmin"] - 1) < 0.01
    assert got["fas"]["fallback"] == []
