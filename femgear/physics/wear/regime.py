"""The share of the load the asperities carry, as a function of the load, for wear that knows the film.

Archard's law wears a flank where its asperities touch the other flank; where a film separates
them, it carries the load and nothing wears.  With the load-sharing concept of Johnson, Greenwood &
Poon (Wear 19 (1972) 91) the contact load per unit length w' splits into a fluid part and an
asperity part W_a = f_a(w') w', f_a from the Greenwood–Tripp asperity pressure at the film of the
fluid part (:func:`femgear.physics.lubrication.mixed.jgp_split`, the split femgear's ``formula``
friction uses).  The wear then takes the asperity-borne load in place of the whole load,

    Δh_j = (K/H) f_a(w') w' |v_s| / v_j,

the sliding-wear model of Wu & Cheng (ASME J. Tribol. 115 (1993) 493) in the form of Akbarzadeh &
Khonsari (*Prediction of steady state adhesive wear in spur gears using the EHL load sharing
concept*, ASME J. Tribol. 131 (2009) 024503), with K the dimensionless Archard coefficient of the
asperity contacts.  In full film (λ = h/σ > 3) f_a is below 10⁻⁴ and the wear vanishes.  As λ
falls f_a grows, but only to what the Greenwood–Tripp asperities carry at the separation the fluid
part still keeps (the split's film never closes): with the default asperity statistics
(ηβσ = 0.04, σ/β = 3·10⁻³) on the paper's pair 0.03 % at λ 2.2, 2.5 % at λ 0.7, 9 % at λ 0.07.
So K of this form is the coefficient of the asperity contacts themselves; a K fitted to measured
wear with the whole load (the paper's "wear rate") belongs to ``wear.load = "total"``.

:class:`AsperityShare` is that split tabulated at every path position over a range of loads (it is
solved once per case and read at every wear step, where the load changes with the wear); this
module only reads the table: it is built by the wear level (:mod:`femgear.levels.wear`) from the
case's oil, steel and roughness, since the lubrication leaf sits beside this one.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: the asperities carry less than this share of the load at every loaded position: the pair runs in full film as
#: far as wear goes (the constant-coefficient form overstates its wear by more than 1/FULL_FILM_SHARE)
FULL_FILM_SHARE = 0.01


@dataclass(frozen=True)
class AsperityShare:
    """f_a(w', u) = W_a/W and the film parameter λ(w', u), tabulated: ``loads`` (m,) ascending [N/m], and
    ``fraction``, ``film_parameter`` (n_u, m) at the wear's path positions u (its kinematics' ``u``).

    Read by :meth:`__call__` and :meth:`film` at loads of shape (..., n_u): linear in ln w' between the
    tabulated loads, held at the ends beyond them.  ``sigma`` is the composite roughness of the table."""

    loads: np.ndarray
    fraction: np.ndarray
    film_parameter: np.ndarray
    sigma: float      #: composite RMS roughness σ = √(Rq1² + Rq2²) [m]

    def __post_init__(self):
        w = np.asarray(self.loads, float)
        if w.ndim != 1 or w.size < 2 or np.any(w <= 0) or np.any(np.diff(w) <= 0):
            raise ValueError("AsperityShare.loads must be positive and ascending (at least two)")
        for name in ("fraction", "film_parameter"):
            a = np.asarray(getattr(self, name), float)
            if a.ndim != 2 or a.shape[1] != w.size or not np.all(np.isfinite(a)):
                raise ValueError(f"AsperityShare.{name} must be finite with shape (n_u, {w.size})")
        if np.any(self.fraction < 0) or np.any(self.fraction > 1):
            raise ValueError("AsperityShare.fraction must lie in [0, 1]")

    def _read(self, table: np.ndarray, load) -> np.ndarray:
        load = np.asarray(load, float)
        if load.shape[-1] != table.shape[0]:
            raise ValueError(f"load has {load.shape[-1]} path positions, the table {table.shape[0]}")
        x = np.log(np.clip(load, self.loads[0], self.loads[-1]))
        grid = np.log(self.loads)
        j = np.clip(np.searchsorted(grid, x, side="right") - 1, 0, grid.size - 2)
        t = (x - grid[j]) / (grid[j + 1] - grid[j])
        k = np.broadcast_to(np.arange(table.shape[0]), load.shape)
        return (1 - t) * table[k, j] + t * table[k, j + 1]

    def __call__(self, load) -> np.ndarray:
        """W_a/W at the loads per unit length ``load`` (..., n_u) [N/m] [-]."""
        return self._read(self.fraction, load)

    def film(self, load) -> np.ndarray:
        """λ = h/σ of the fluid part's central film at ``load`` (..., n_u) [-]."""
        return self._read(self.film_parameter, load)


@dataclass(frozen=True)
class Regime:
    """How the film shares the wear's load along the path at one load distribution."""

    film_parameter_min: float   #: smallest λ = h/σ over the loaded path positions [-]
    share_max: float            #: largest asperity share W_a/W over them [-]

    @property
    def full_film(self) -> bool:
        """The asperities carry less than :data:`FULL_FILM_SHARE` of the load everywhere."""
        return self.share_max < FULL_FILM_SHARE


def regime(share: AsperityShare, load: np.ndarray) -> Regime:
    """The :class:`Regime` of ``load`` (n_u,) [N/m] (positions with no load left out; all of them when none is)."""
    load = np.asarray(load, float)
    on = load > 0
    lam, f = share.film(load), share(load)
    on = on if on.any() else np.ones(load.shape, bool)
    return Regime(film_parameter_min=float(np.min(lam[on])), share_max=float(np.max(f[on])))


__all__ = ["FULL_FILM_SHARE", "AsperityShare", "Regime", "regime"]
