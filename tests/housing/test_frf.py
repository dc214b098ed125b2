"""FRF sets: validation, conversions, interpolation, and the UFF/CSV readers with their bad inputs."""

import numpy as np
import pytest

from femgear.errors import SceneError
from femgear.physics.housing.frf import SEAT_DOFS, FRFSet, modal_accelerance, to_receptance
from femgear.scene.frf_file import read_frf


def _set(f=(10.0, 20.0, 40.0)):
    f = np.asarray(f)
    H = np.ones((f.size, 2, 1), complex) * np.arange(1, f.size + 1)[:, None, None]
    return FRFSet(frequency=f, H=H, outputs=("S1", "gear_L.y"), inputs=("gear_L.y",))


def test_non_increasing_frequencies_refused():
    with pytest.raises(ValueError, match="not strictly increasing"):
        _set((10.0, 20.0, 20.0))


def test_inputs_must_be_seat_dofs():
    with pytest.raises(ValueError, match="bearing-seat DOFs"):
        FRFSet(frequency=np.array([1.0, 2.0]), H=np.ones((2, 1, 1)), outputs=("S1",), inputs=("hub.x",))


def test_interpolation_missing_inputs_and_range():
    s = _set()
    H = s.receptance(np.array([15.0, 30.0]), ("S1",))
    assert H.shape == (2, 1, 12)
    j = SEAT_DOFS.index("gear_L.y")
    assert np.allclose(H[:, 0, j], [1.5, 2.5]) and np.allclose(np.delete(H[0, 0], j), 0.0)
    assert not s.has_seat_block and len(s.missing_inputs) == 11
    with pytest.raises(ValueError, match="outside the FRF grid"):
        s.receptance(np.array([50.0]), ("S1",))


def test_kind_conversions():
    f = np.array([100.0])
    w = 2 * np.pi * 100.0
    assert np.allclose(to_receptance(np.array([-(w**2)]), f, "accelerance"), 1.0)
    assert np.allclose(to_receptance(np.array([1j * w]), f, "mobility"), 1.0)


def test_modal_accelerance_limits():
    """A gain and one mode: → −g r² far below the mode (stiffness line), → −g far above (mass line), resonant
    amplification 1/(2ζ) at the mode."""
    g, fn, z = 2.0, 1000.0, 0.05
    assert np.isclose(modal_accelerance(np.array([10.0]), g, fn, z)[0], g * 1e-4, rtol=1e-3)
    assert np.isclose(modal_accelerance(np.array([1e6]), g, fn, z)[0], -g, rtol=1e-3)
    assert np.isclose(abs(modal_accelerance(np.array([fn]), g, fn, z)[0]), g / (2 * z))


def _write_uff(path, refs, f, kind_code=12):
    import pyuff

    sets = []
    for (rsp_node, rsp_dir), (ref_node, ref_dir), value in refs:
        sets.append(pyuff.prepare_58(binary=0, id1="FRF", func_type=4, rsp_node=rsp_node, rsp_dir=rsp_dir,
                                     ref_node=ref_node, ref_dir=ref_dir, ord_data_type=6, abscissa_spec_data_type=18,
                                     ordinate_spec_data_type=kind_code, orddenom_spec_data_type=13,
                                     data=value * np.ones(f.size, complex), x=f, abscissa_min=f[0],
                                     abscissa_inc=f[1] - f[0]))
    pyuff.UFF(str(path)).write_sets(sets, mode="overwrite")


def test_uff_reader(tmp_path):
    f = np.linspace(100.0, 1000.0, 10)
    path = tmp_path / "h.uff"
    _write_uff(path, [((101, 2), (3, 2), 2.0), ((101, 2), (4, -1), 1.0)], f)
    s = read_frf(path, seat_nodes=[1, 2, 3, 4])
    assert s.outputs == ("101:+2",) and set(s.inputs) == {"gear_L.y", "gear_R.x"}
    w = 2 * np.pi * f
    H = s.receptance(f, ("101:+2",))
    assert np.allclose(H[:, 0, SEAT_DOFS.index("gear_R.x")], -1.0 / -(w**2))     # direction −1: the sign flips
    with pytest.raises(SceneError, match="housing.frf_kind"):
        read_frf(path, kind="receptance", seat_nodes=[1, 2, 3, 4])


def test_uff_whose_dofs_do_not_match_the_seats_refused(tmp_path):
    f = np.linspace(100.0, 1000.0, 10)
    path = tmp_path / "h.uff"
    _write_uff(path, [((101, 2), (7, 2), 2.0)], f)
    with pytest.raises(SceneError, match="not a bearing seat") as err:
        read_frf(path, seat_nodes=[1, 2, 3, 4])
    assert err.value.key == str(path)
    _write_uff(path, [((101, 2), (3, 5), 2.0)], f)                 # a rotation at a seat node
    with pytest.raises(SceneError, match="only translations"):
        read_frf(path, seat_nodes=[1, 2, 3, 4])


def test_csv_reader_and_non_increasing_frequencies(tmp_path):
    path = tmp_path / "h.csv"
    rows = ["frequency,output,input,real,imag"] + [f"{f},S1,pinion_L.x,{f},0" for f in (10, 20, 30)]
    path.write_text("\n".join(rows))
    s = read_frf(path, kind="receptance")
    assert s.sensors == ("S1",) and np.allclose(s.H[:, 0, 0], [10, 20, 30])
    path.write_text("\n".join(rows[:2] + [rows[3], rows[2]]))
    with pytest.raises(SceneError, match="non-increasing") as err:
        read_frf(path, kind="receptance")
    assert err.value.key == str(path)
    with pytest.raises(SceneError, match="frf_kind"):
        read_frf(path)
