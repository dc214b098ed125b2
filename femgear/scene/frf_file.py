"""Reading a housing's FRF file (``housing.frf_file``) into a :class:`femgear.physics.housing.frf.FRFSet`.

Two formats, by suffix:

- **UFF/UNV dataset 58** (``.uff``, ``.unv``; read with ``pyuff``): one function per (response, reference)
  pair; ``func_type`` 4 (frequency response function), abscissa in Hz.  The reference (input) DOFs must be
  bearing seats: node ``housing.seat_nodes[j]`` is station j (pinion_L, pinion_R, gear_L, gear_R), direction
  1/2/3 (±) = x/y/z of the dynamics' frame (−1 … −3 flip the sign).  A response at a seat node is a seat
  output, any other response node a sensor named ``"<node>:<dir>"`` (e.g. ``"101:+3"``).  The ordinate's type
  (8 displacement, 11 velocity, 12 acceleration) tells receptance, mobility or accelerance.
- **CSV** (``.csv``): a header line ``frequency,output,input,real,imag`` and one row per frequency and DOF
  pair; ``input`` a seat DOF ``<station>.<axis>`` (``gear_L.y``), ``output`` a seat DOF or a sensor name;
  ``housing.frf_kind`` says what the values are.

Every pair must share one strictly increasing frequency grid.  Any failure is a
:class:`femgear.errors.SceneError` naming the file (or ``housing.seat_nodes`` / ``housing.frf_kind``).
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

from femgear.errors import SceneError
from femgear.physics.housing.frf import AXES, FRFSet, to_receptance
from femgear.physics.mesh.housing import STATIONS

#: UFF dataset 58 ordinate types (its "specific data type" code) → the FRF's kind
UFF_KINDS = {8: "receptance", 11: "mobility", 12: "accelerance"}
MAX_FRF_BYTES = 200 << 20


def read_frf(path: str | Path, kind: str | None = None, seat_nodes: list[int] | None = None) -> FRFSet:
    """The FRF set of ``path`` (module docstring)."""
    path = Path(path)
    if not path.is_file():
        raise SceneError(str(path), "FRF file not found (housing.frf_file)")
    if path.stat().st_size > MAX_FRF_BYTES:
        raise SceneError(str(path), f"FRF file larger than {MAX_FRF_BYTES >> 20} MiB")
    suffix = path.suffix.lower()
    try:
        if suffix in (".uff", ".unv"):
            return _read_uff(path, kind, seat_nodes)
        if suffix == ".csv":
            return _read_csv(path, kind)
    except ValueError as exc:            # the FRFSet's own checks (grid, shapes, DOF names)
        raise SceneError(str(path), str(exc)) from None
    raise SceneError(str(path), "unknown FRF format: give a .uff/.unv (dataset 58) or .csv file")


def _assemble(pairs: dict[tuple[str, str], tuple[np.ndarray, np.ndarray]], kind: str, path: Path) -> FRFSet:
    """One FRFSet from {(output, input): (frequency, values)} on a common grid."""
    if not pairs:
        raise SceneError(str(path), "holds no frequency-response function")
    grids = [f for f, _ in pairs.values()]
    f0 = grids[0]
    for (o, i), (f, _) in pairs.items():
        if np.any(np.diff(f) <= 0):
            k = int(np.argmax(np.diff(f) <= 0))
            raise SceneError(str(path), f"the FRF {o} / {i} has non-increasing frequencies ({f[k]:.6g} Hz then "
                                        f"{f[k + 1]:.6g} Hz)")
        if f.shape != f0.shape or not np.allclose(f, f0, rtol=1e-9, atol=0):
            raise SceneError(str(path), f"the FRF {o} / {i} is not on the frequency grid of the others")
    outputs = tuple(dict.fromkeys(o for o, _ in pairs))
    inputs = tuple(dict.fromkeys(i for _, i in pairs))
    H = np.zeros((f0.size, len(outputs), len(inputs)), dtype=complex)
    for (o, i), (_, v) in pairs.items():
        H[:, outputs.index(o), inputs.index(i)] = v
    return FRFSet(frequency=f0, H=to_receptance(H, f0, kind), outputs=outputs, inputs=inputs, source=path.name)


def _read_csv(path: Path, kind: str | None) -> FRFSet:
    if kind is None:
        raise SceneError("housing.frf_kind", f"a CSV FRF file ({path.name}) needs frf_kind (receptance, mobility or "
                                             "accelerance)")
    rows: dict[tuple[str, str], list[tuple[float, complex]]] = {}
    with path.open(newline="", encoding="utf-8") as fh:
        reader = csv.reader(fh)
        header = [h.strip().lower() for h in next(reader, [])]
        if header[:5] != ["frequency", "output", "input", "real", "imag"]:
            raise SceneError(str(path), "the CSV header must be frequency,output,input,real,imag")
        for n, row in enumerate(reader, start=2):
            if not row or not "".join(row).strip():
                continue
            try:
                f, o, i, re, im = row[:5]
                rows.setdefault((o.strip(), i.strip()), []).append((float(f), complex(float(re), float(im))))
            except ValueError:
                raise SceneError(str(path), f"line {n}: expected frequency,output,input,real,imag") from None
    pairs = {k: (np.array([f for f, _ in v]), np.array([x for _, x in v])) for k, v in rows.items()}
    return _assemble(pairs, kind, path)


def _dof(node: int, direction: int, seat_nodes: list[int]) -> tuple[str, float] | None:
    """(seat DOF name, sign) of a UFF (node, direction) at a seat node, None for another node."""
    if node not in seat_nodes:
        return None
    if abs(direction) not in (1, 2, 3):
        raise ValueError(f"seat node {node} has direction {direction}: only translations 1/2/3 (x/y/z) can meet a "
                         "bearing")
    return f"{STATIONS[seat_nodes.index(node)]}.{AXES[abs(direction) - 1]}", (1.0 if direction > 0 else -1.0)


def _read_uff(path: Path, kind: str | None, seat_nodes: list[int] | None) -> FRFSet:
    import pyuff

    if seat_nodes is None:
        raise SceneError("housing.seat_nodes", f"a UFF FRF file ({path.name}) needs the node numbers of the four "
                                               "bearing seats (pinion_L, pinion_R, gear_L, gear_R)")
    if len(set(seat_nodes)) != 4:
        raise SceneError("housing.seat_nodes", f"must be four different nodes (got {seat_nodes})")
    try:
        sets = pyuff.UFF(str(path)).read_sets()
    except Exception as exc:     # pyuff raises bare Exceptions and KeyErrors on malformed files
        raise SceneError(str(path), f"not a readable UFF file: {exc}") from None
    sets = [s for s in (sets if isinstance(sets, list) else [sets]) if s.get("type") == 58]
    pairs: dict[tuple[str, str], tuple[np.ndarray, np.ndarray]] = {}
    kinds = set()
    for s in sets:
        if s.get("func_type") != 4:
            continue
        ref = _dof(int(s["ref_node"]), int(s["ref_dir"]), seat_nodes)
        if ref is None:
            raise SceneError(str(path), f"the FRF input at node {s['ref_node']} direction {s['ref_dir']} is not a "
                                        f"bearing seat: housing.seat_nodes = {seat_nodes}")
        rsp = _dof(int(s["rsp_node"]), int(s["rsp_dir"]), seat_nodes)
        name, sign = rsp if rsp is not None else (f"{int(s['rsp_node'])}:{int(s['rsp_dir']):+d}", 1.0)
        kinds.add(UFF_KINDS.get(int(s.get("ordinate_spec_data_type", 0)), "unknown"))
        pairs[(name, ref[0])] = (np.asarray(s["x"], dtype=float), sign * ref[1] * np.asarray(s["data"], dtype=complex))
    if not pairs:
        raise SceneError(str(path), "holds no frequency-response function (dataset 58, function type 4)")
    if len(kinds) != 1 or "unknown" in kinds:
        raise SceneError(str(path), f"ordinate types {sorted(kinds)}: every FRF must be one of displacement (8), "
                                    "velocity (11) or acceleration (12) per force")
    found = kinds.pop()
    if kind is not None and kind != found:
        raise SceneError("housing.frf_kind", f"{kind!r}, but {path.name} holds {found}")
    return _assemble(pairs, found, path)
