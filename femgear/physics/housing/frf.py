"""Frequency-response functions of a housing: from forces at the bearing seats to seat and sensor responses.

An :class:`FRFSet` holds receptances H_oi(f) = u_o / F_i [m/N] on one strictly increasing frequency grid, for
inputs i at the bearing-seat DOFs (``"<station>.<axis>"``, station of
:data:`femgear.physics.mesh.housing.STATIONS`, axis x, y or z of the model frame) and outputs o at sensors (any
other name, read along the sensor's own direction) and, where measured, at the seats themselves.  Accelerances
(m/s² per N) and mobilities (m/s per N) are converted on entry: H = A / (−ω²) = Y / (iω).

Between the grid's frequencies the real and imaginary parts are interpolated linearly (a measured FRF's grid is
fine enough for that, or the measurement does not resolve the peak either); outside the grid nothing is
extrapolated: :meth:`FRFSet.receptance` refuses, and callers keep only the frequencies :meth:`FRFSet.covers`.

Two uses (:mod:`femgear.system.dynamics.housing`): a *receiver* (sensor = H_so · F, the bearing forces of the
model on a rigid housing; needs only the seat-to-sensor columns; exact where the housing does not load the
bearings) and *coupled* by frequency-based substructuring (:mod:`femgear.physics.housing.fbs`; needs the 12 × 12
seat-to-seat block as well).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from femgear.physics.mesh.housing import STATIONS

AXES = ("x", "y", "z")
#: the 12 seat DOFs in the order of the dynamics' bearing arrays (station-major, x y z)
SEAT_DOFS = tuple(f"{s}.{a}" for s in STATIONS for a in AXES)
KINDS = ("receptance", "mobility", "accelerance")


def to_receptance(values: np.ndarray, frequency: np.ndarray, kind: str) -> np.ndarray:
    """Receptance [m/N] from ``values`` of ``kind`` over ``frequency`` [Hz] (axis 0)."""
    if kind not in KINDS:
        raise ValueError(f"FRF kind must be one of {', '.join(KINDS)} (got {kind!r})")
    w = 2 * np.pi * np.asarray(frequency, dtype=float).reshape((-1,) + (1,) * (np.ndim(values) - 1))
    return {"receptance": lambda v: v, "mobility": lambda v: v / (1j * w),
            "accelerance": lambda v: v / (-w**2)}[kind](np.asarray(values, dtype=complex))


@dataclass(frozen=True)
class FRFSet:
    """Receptances ``H`` (n_f, n_outputs, n_inputs) [m/N] at ``frequency`` (n_f,) [Hz] (module docstring)."""

    frequency: np.ndarray
    H: np.ndarray
    outputs: tuple[str, ...]
    inputs: tuple[str, ...]
    source: str = ""          #: where the data came from (a file name), for messages [-]

    def __post_init__(self):
        f = np.asarray(self.frequency, dtype=float)
        H = np.asarray(self.H, dtype=complex)
        where = f" in {self.source}" if self.source else ""
        if f.ndim != 1 or f.size < 2 or not np.all(np.isfinite(f)) or f[0] <= 0:
            raise ValueError(f"FRF frequencies{where} must be at least two finite values > 0 Hz")
        if np.any(np.diff(f) <= 0):
            k = int(np.argmax(np.diff(f) <= 0))
            raise ValueError(f"FRF frequencies{where} are not strictly increasing ({f[k]:.6g} Hz then {f[k + 1]:.6g} Hz)")
        if H.shape != (f.size, len(self.outputs), len(self.inputs)) or not np.all(np.isfinite(H)):
            raise ValueError(f"FRF data{where} must be finite, shape (frequencies, outputs, inputs) = "
                             f"{(f.size, len(self.outputs), len(self.inputs))} (got {H.shape})")
        bad = [i for i in self.inputs if i not in SEAT_DOFS]
        if bad:
            raise ValueError(f"FRF inputs{where} must be bearing-seat DOFs {', '.join(SEAT_DOFS)} (got {', '.join(bad)})")
        for name, names in (("inputs", self.inputs), ("outputs", self.outputs)):
            if len(set(names)) != len(names):
                raise ValueError(f"FRF {name}{where} repeat a DOF")
        object.__setattr__(self, "frequency", f)
        object.__setattr__(self, "H", H)

    @property
    def sensors(self) -> tuple[str, ...]:
        """The outputs that are not seat DOFs, in order."""
        return tuple(o for o in self.outputs if o not in SEAT_DOFS)

    @property
    def has_seat_block(self) -> bool:
        """Whether the 12 × 12 seat-to-seat receptance is complete (coupling by substructuring is possible)."""
        return set(SEAT_DOFS) <= set(self.inputs) and set(SEAT_DOFS) <= set(self.outputs)

    @property
    def missing_inputs(self) -> tuple[str, ...]:
        """The seat DOFs with no measured input column (their bearing forces cannot reach a sensor)."""
        return tuple(d for d in SEAT_DOFS if d not in self.inputs)

    def covers(self, f: np.ndarray) -> np.ndarray:
        """Mask of the frequencies ``f`` [Hz] inside the measured grid."""
        f = np.asarray(f, dtype=float)
        return (f >= self.frequency[0]) & (f <= self.frequency[-1])

    def receptance(self, f: np.ndarray, outputs: tuple[str, ...], inputs: tuple[str, ...] = SEAT_DOFS) -> np.ndarray:
        """(len(f), len(outputs), len(inputs)) receptance at ``f`` [Hz], interpolated; inputs not measured are 0.

        ValueError for a frequency outside the grid or an output that is not in the set."""
        f = np.atleast_1d(np.asarray(f, dtype=float))
        if not np.all(self.covers(f)):
            raise ValueError(f"frequencies {f[~self.covers(f)].min():.6g} … outside the FRF grid "
                             f"{self.frequency[0]:.6g} … {self.frequency[-1]:.6g} Hz")
        missing = [o for o in outputs if o not in self.outputs]
        if missing:
            raise ValueError(f"FRF set{' ' + self.source if self.source else ''} has no output {', '.join(missing)}")
        oi = [self.outputs.index(o) for o in outputs]
        out = np.zeros((f.size, len(outputs), len(inputs)), dtype=complex)
        for c, name in enumerate(inputs):
            if name not in self.inputs:
                continue
            col = self.H[:, oi, self.inputs.index(name)]                           # (n_f, n_out)
            for r in range(len(outputs)):
                out[:, r, c] = np.interp(f, self.frequency, col[:, r].real) + 1j * np.interp(f, self.frequency,
                                                                                              col[:, r].imag)
        return out


def modal_accelerance(frequency: np.ndarray, gain: float, natural_frequency: float | None = None,
                      damping_ratio: float = 0.05) -> np.ndarray:
    """A path model with few parameters: the accelerance of a gain and one mode [m/s² per N].

    A(ω) = g r² / (1 − r² + 2iζ r), r = ω/ω_n: a mode of natural frequency ``natural_frequency`` [Hz] and damping
    ratio ``damping_ratio`` seen through its mass line g = 1/m [1/kg] (A → −g above the mode, → −g r² below it,
    where the path is stiff); ``natural_frequency`` None: the mass line A = g alone (the gain-only model).
    """
    f = np.asarray(frequency, dtype=float)
    if natural_frequency is None:
        return np.full(f.shape, complex(gain))
    r = f / natural_frequency
    return gain * r**2 / (1.0 - r**2 + 2j * damping_ratio * r)
