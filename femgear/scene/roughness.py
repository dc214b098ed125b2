"""The flanks' roughness, resolved once from the one ``[roughness]`` table (and, for one release, the old keys).

:func:`flank_roughness` returns R_a and R_q of both members, the composite σ the tribology reads and
where each came from; :func:`check_roughness` refuses what no flank has (run with the input ranges, before
any computing); :func:`roughness_warnings` names the new key of every deprecated one used.

R_q/R_a: Gaussian heights give R_q = √(π/2) R_a = 1.2533 R_a (the ratio of the standard deviation to the
mean absolute deviation of a normal distribution); ground and honed gear flanks lie near it.  R_q ≥ R_a holds
for any surface (the quadratic mean is never below the arithmetic one), so R_q < R_a is a contradiction, and
above 1.6 R_a the two describe different surfaces: both refused, naming ``roughness.rq``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from femgear.errors import SceneError
from femgear.scene.schema import FINISHING_RA, Scene

RQ_PER_RA = math.sqrt(math.pi / 2)
RQ_RA_RANGE = (1.0, 1.6)
#: R_a a gear flank can have [m]: ISO 1302 roughness grades N1 (0.025 µm) … N10 (12.5 µm), possible to 50 µm
RA_PLAUSIBLE, RA_POSSIBLE = (0.02e-6, 12.5e-6), 50e-6


@dataclass(frozen=True)
class FlankRoughness:
    """R_a, R_q of pinion and gear and the composite σ of the tribology (SI), with their provenance."""

    ra: tuple[float, float]        #: arithmetic mean roughness [m]
    rq: tuple[float, float]        #: RMS roughness [m]
    sigma: float                   #: composite σ of the tribology [m] (0: smooth flanks)
    model: str                     #: "greenwood-tripp" or "smooth"
    source: str                    #: which keys (or defaults) gave the values, in words
    finishing: str | None = None   #: the finishing that set R_a (None: given)
    state: str = "new"             #: running-in state: "new" or "run-in"
    run_in_factor: float = 1.0     #: factor applied to the as-manufactured R_a, R_q, σ [-] (1: new)

    @property
    def ra_mean(self) -> float:
        """(R_a1 + R_a2)/2, ISO's R_a [m]."""
        return 0.5 * (self.ra[0] + self.ra[1])


def flank_roughness(scene: Scene) -> FlankRoughness:
    """The flanks' roughness of ``scene`` (the new keys first, then the deprecated ones, then the default)."""
    r, rating = scene.roughness, scene.rating
    rq_list = list(r.rq) if isinstance(r.rq, list) else None
    ra = list(r.ra) if r.ra is not None else (list(rating.roughness_ra) if rating.roughness_ra is not None else None)
    finishing = None
    if ra is None and rq_list is None:
        finishing = r.finishing or rating.finishing or "ground"
        ra = [FINISHING_RA[finishing]] * 2
        source = f"roughness.finishing = {finishing}" + ("" if (r.finishing or rating.finishing) else " (default)")
    else:
        source = " and ".join(k for k, v in (("roughness.ra", r.ra), ("rating.roughness_ra", rating.roughness_ra),
                                             ("roughness.rq", rq_list)) if v is not None)
    if ra is None:
        ra = [q / RQ_PER_RA for q in rq_list]
    rq = rq_list if rq_list is not None else [a * RQ_PER_RA for a in ra]
    sigma, model = math.hypot(*rq), r.model
    if isinstance(r.rq, float | int) and not isinstance(r.rq, bool) and r.rq is not None:   # the old composite σ
        sigma, source = float(r.rq), source + "; the tribology's σ from roughness.rq (one number)"
        model = "smooth" if sigma == 0 else model
    factor = 1.0
    if r.state == "run-in":
        from femgear.physics.lubrication.running_in import run_in_factor

        given = r.run_in_factor is not None
        factor = r.run_in_factor if given else run_in_factor(finishing or r.finishing or rating.finishing or "ground")
        source += (f"; run-in: × {factor:.3g} " + ("(roughness.run_in_factor)" if given else
                                                   "(the finishing's typical factor, GearCalc manual §14.12)"))
        ra, rq, sigma = [a * factor for a in ra], [q * factor for q in rq], sigma * factor
    return FlankRoughness(ra=(float(ra[0]), float(ra[1])), rq=(float(rq[0]), float(rq[1])), sigma=sigma,
                          model=model, source=source, finishing=finishing, state=r.state, run_in_factor=factor)


def check_roughness(scene: Scene) -> list[str]:
    """Refuse (:class:`SceneError`, the key named) a roughness no flank has or R_a and R_q that contradict each
    other, and a key given both the old and the new way; return the warnings of unusual values."""
    r, rating = scene.roughness, scene.rating
    if rating.roughness_ra is not None and (r.ra is not None or isinstance(r.rq, list)):
        raise SceneError("rating.roughness_ra", "is deprecated and given beside roughness.ra/rq: keep roughness.ra")
    if rating.finishing is not None and r.finishing is not None and rating.finishing != r.finishing:
        raise SceneError("rating.finishing", f"{rating.finishing!r} contradicts roughness.finishing = {r.finishing!r}:"
                                             " keep roughness.finishing")
    if r.run_in_factor is not None and r.state != "run-in":
        raise SceneError("roughness.run_in_factor", 'applies to run-in flanks only: set roughness.state = "run-in"')
    m = scene.pair.normal_module
    out: list[str] = []
    for key, values, factor in (("roughness.ra", r.ra, 1.0), ("rating.roughness_ra", rating.roughness_ra, 1.0),
                                ("roughness.rq", r.rq if isinstance(r.rq, list) else None, RQ_PER_RA)):
        for member, v in zip(("pinion", "gear"), values or (), strict=False):
            limit = min(RA_POSSIBLE, 0.05 * m) * factor
            if v > limit:
                hint = f"; did you mean {v:g} µm = {v * 1e-6:g} m?" if v * 1e-6 <= RA_PLAUSIBLE[1] * factor else ""
                raise SceneError(key, f"{v:g} m ({member}) is impossible for a flank roughness: at most "
                                      f"{limit * 1e6:.3g} µm (m_n = {m * 1e3:g} mm){hint}")
            lo, hi = RA_PLAUSIBLE[0] * factor, RA_PLAUSIBLE[1] * factor
            if not lo <= v <= hi:
                out.append(f"{key}: {v * 1e6:.3g} µm ({member}) is unusual for a gear flank: plausible "
                           f"{lo * 1e6:.3g}…{hi * 1e6:.3g} µm")
    if r.ra is not None and isinstance(r.rq, list):
        for member, a, q in zip(("pinion", "gear"), r.ra, r.rq, strict=True):
            lo, hi = RQ_RA_RANGE
            if not lo <= q / a <= hi:
                raise SceneError("roughness.rq", f"R_q = {q * 1e6:.3g} µm contradicts roughness.ra = {a * 1e6:.3g} µm "
                                                 f"on the {member}: R_q/R_a = {q / a:.3g}, a surface has {lo:g}…{hi:g} "
                                                 f"(Gaussian heights {RQ_PER_RA:.3f}); give one of them")
    if isinstance(r.rq, float | int) and not isinstance(r.rq, bool) and r.rq > min(1e-4, 0.1 * m):
        hint = f"; did you mean {r.rq:g} µm = {r.rq * 1e-6:g} m?" if r.rq * 1e-6 <= 1e-5 else ""
        raise SceneError("roughness.rq", f"{r.rq:g} m is impossible for a composite flank roughness "
                                         f"(at most {min(1e-4, 0.1 * m) * 1e6:.3g} µm){hint}")
    return out


def roughness_warnings(scene: Scene) -> list[str]:
    """One line per deprecated roughness key the scene uses, naming its new key."""
    r, rating = scene.roughness, scene.rating
    out = []
    if rating.roughness_ra is not None:
        out.append("rating.roughness_ra: deprecated (read this release): use roughness.ra, which the ratings and the "
                   "tribology both read")
    if rating.finishing is not None:
        out.append("rating.finishing: deprecated (read this release): use roughness.finishing")
    if isinstance(r.rq, float | int) and not isinstance(r.rq, bool):
        new = 'roughness.model = "smooth"' if r.rq == 0 else "roughness.rq = [R_q1, R_q2] (or roughness.ra)"
        out.append(f"roughness.rq: one number (the composite σ) is deprecated (read this release): use {new}")
    return out
