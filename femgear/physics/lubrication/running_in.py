"""Running-in of gear flanks: the roughness a flank has after running-in, from its as-manufactured roughness.

Source: the GearCalc manual (Geartech), section 14.12 "Surface roughness" (gearcalc.com/downloads/manual/
manualse81.html), which holds that the roughness the scoring (flash-temperature) calculation takes is the one after
running-in, and prints typical RMS roughness of gear teeth as manufactured and after run-in by manufacturing method
[µin rms]:

    ============  ================  =============
    method        as manufactured   after run-in
    ============  ================  =============
    milling       64–125            32–64
    shaping       32–125            25–50
    hobbing       30–80             20–45
    lapping       20–100            20–40
    shaving       10–40             10–25
    grinding      10–40             10–25
    honing        6–20              5–15
    ============  ================  =============

with, in its text, improvements of up to 4:1 for slow, soft gears, 2:1 for medium-hard, medium-speed gears and
25 → 17 µin rms (0.68) for high-speed carburized gears.  The factor femgear applies to R_a and R_q of a flank is
the ratio of the range midpoints of its finishing (:data:`RUN_IN_FACTOR`): ground and shaved 17.5/25 = 0.70, honed
10/13 = 0.77, hobbed 32.5/55 = 0.59 — typical values, as the manual says; a measured ratio of one's own gears is
given as ``roughness.run_in_factor``.
"""

from __future__ import annotations

#: (as manufactured, after run-in) RMS roughness ranges [µin] of the GearCalc manual's table, by femgear finishing
RUN_IN_TABLE: dict[str, tuple[tuple[float, float], tuple[float, float]]] = {
    "ground": ((10.0, 40.0), (10.0, 25.0)),
    "honed": ((6.0, 20.0), (5.0, 15.0)),
    "shaved": ((10.0, 40.0), (10.0, 25.0)),
    "hobbed": ((30.0, 80.0), (20.0, 45.0)),
}


def _midpoint(r: tuple[float, float]) -> float:
    return 0.5 * (r[0] + r[1])


#: roughness after run-in over as manufactured, by finishing: the ratio of the table's range midpoints [-]
RUN_IN_FACTOR: dict[str, float] = {k: _midpoint(after) / _midpoint(new) for k, (new, after) in RUN_IN_TABLE.items()}


def run_in_factor(finishing: str) -> float:
    """R_q (and R_a) after running-in over as manufactured for a flank of ``finishing`` [-]."""
    try:
        return RUN_IN_FACTOR[finishing]
    except KeyError:
        raise ValueError(f"no running-in factor for finishing {finishing!r}: one of {sorted(RUN_IN_FACTOR)}") from None
