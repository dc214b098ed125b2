"""Physical plausibility of a valid scene: impossible operating points are refused,
implausible but computable ones are accepted with a logged warning naming the key.

The checks of the scene alone (the temperatures) run in :func:`femgear.scene.load_scene`;
those needing the bound pair (tip and pitch-line speeds) run when the case is bound
(:func:`femgear.case.build_case`), and the Hertz pressure check after the run's own
contact pass (:func:`femgear.case.checks.contact_warnings`).  One line per key is logged.

Refused (:class:`femgear.errors.SceneError`):

- a tip speed at which the rim would burst: the hoop stress of a thin rotating ring,
  σ = ρ v² (Timoshenko & Goodier, *Theory of Elasticity*, rotating disc, thin-ring
  limit), above the yield stress estimated from the flank hardness by Tabor's
  relation σ_y ≈ H/3 (Tabor, *The Hardness of Metals*, 1951). For the baseline steel
  (ρ = 7850 kg/m³, H = 6 GPa) that is v ≈ 500 m/s; the fastest turbo gears run at
  about 200 m/s.
- an oil temperature (ambient, viscosity reference) at or below 138 K, the pole T∞ of
  the Roelands viscosity-temperature law (Roelands 1966), where the law has no meaning.

Warned (logger ``femgear.scene``):

- maximum Hertz pressure along the path above 3 GPa (beyond case-hardened steel's
  contact fatigue limit, ISO 6336-5 σ_Hlim ≈ 1.5 GPa, with margin for static peaks);
- a pitch-line speed above 100 m/s (beyond the film formulas' usual validation range);
- an ambient temperature below 250 K (below the pour point of gear oils), or more than 60 K from the oil's viscosity reference
  temperature, or above 423 K (150 °C, the upper limit of mineral gear oils): the
  exponential viscosity-temperature law is then an extrapolation.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Sequence

from femgear.errors import SceneError
from femgear.scene.schema import Scene

log = logging.getLogger("femgear.scene")

MAX_HERTZ_PRESSURE = 3.0e9   # Pa
MAX_PLAUSIBLE_SPEED = 100.0  # m/s, pitch line
MAX_OIL_TEMPERATURE = 423.0  # K
MAX_VISCOSITY_EXTRAPOLATION = 60.0  # K
MIN_OIL_TEMPERATURE = 250.0  # K, pour point of gear oils
ROELANDS_POLE = 138.0        # K


def tip_speeds(scene: Scene, pair) -> tuple[float, float]:
    """Tip speeds of pinion and gear [m/s] from the driver's speed."""
    op = scene.operating
    ratio = scene.gear.teeth / scene.pinion.teeth
    n1 = op.speed_rpm if op.driver == "pinion" else op.speed_rpm * ratio
    w1 = 2.0 * math.pi * n1 / 60.0
    w2 = w1 / ratio
    return w1 * pair.ra1, w2 * pair.ra2


def check_temperatures(scene: Scene) -> None:
    """Raise :class:`SceneError` for an oil temperature at or below the Roelands pole."""
    for key, temperature in (("operating.ambient_temperature", scene.operating.ambient_temperature),
                             ("oil.reference_temperature", scene.oil_reference_temperature)):
        if temperature <= ROELANDS_POLE:
            raise SceneError(key, f"{temperature:g} K is at or below {ROELANDS_POLE:g} K, the pole of the Roelands "
                                  "viscosity-temperature law; give an absolute temperature in K")


def check_operating_limits(scene: Scene, pair) -> None:
    """Raise :class:`SceneError` for an operating point no gear survives (the rim bursts)."""
    v_tip = max(tip_speeds(scene, pair))
    rho, hardness = scene.material.density, scene.material.hardness
    v_burst = math.sqrt(hardness / 3.0 / rho)
    if v_tip > v_burst:
        raise SceneError(
            "operating.speed_rpm",
            f"{scene.operating.speed_rpm:g} rpm gives a tip speed of {v_tip:.4g} m/s; the rim's hoop stress "
            f"ρv² = {rho * v_tip**2 / 1e9:.3g} GPa exceeds the yield stress H/3 = {hardness / 3e9:.3g} GPa "
            f"(the rim bursts above {v_burst:.0f} m/s)")


def scene_warnings(scene: Scene, earlier: Sequence[str] = ()) -> list[str]:
    """``earlier`` (the input ranges' warnings, :mod:`femgear.scene.ranges`) and the oil temperature's
    warnings (each ``key: message``), not logged."""
    from femgear.scene.oils import unsourced_warning
    from femgear.scene.roughness import roughness_warnings

    out: list[str] = list(earlier)
    unsourced = unsourced_warning(scene.oil)
    if unsourced and scene.oil.name:            # a scene's own oil: logged at INFO (the default τ0 is its choice)
        out.append(unsourced)
    elif unsourced:
        log.info(unsourced)
    out += roughness_warnings(scene)
    t_amb, t_ref = scene.operating.ambient_temperature, scene.oil_reference_temperature
    if t_amb > MAX_OIL_TEMPERATURE:
        out.append(f"operating.ambient_temperature: {t_amb:g} K is above {MAX_OIL_TEMPERATURE:g} K, "
                   "the upper limit of mineral gear oils")
    if t_amb < MIN_OIL_TEMPERATURE:
        out.append(f"operating.ambient_temperature: {t_amb:g} K is below {MIN_OIL_TEMPERATURE:g} K, "
                   "below the pour point of gear oils")
    if abs(t_amb - t_ref) > MAX_VISCOSITY_EXTRAPOLATION:
        out.append(f"operating.ambient_temperature: {t_amb:g} K is {abs(t_amb - t_ref):.0f} K from the oil's "
                   f"viscosity reference {t_ref:g} K; the viscosity-temperature law is extrapolated")
    return out


def pair_warnings(scene: Scene, pair) -> list[str]:
    """The pitch-line speed's warning (``key: message``) of the bound ``pair``, not logged."""
    v_pitch = 2.0 * math.pi * pair.rw1 * scene.pinion_rpm / 60.0
    if v_pitch > MAX_PLAUSIBLE_SPEED:
        return [f"operating.speed_rpm: pitch-line speed {v_pitch:.4g} m/s is above {MAX_PLAUSIBLE_SPEED:g} m/s, "
                "beyond the range the film and friction formulas were fitted in"]
    return []


def pressure_warnings(max_hertz_pressure: float) -> list[str]:
    """The Hertz pressure's warning (``key: message``) of a contact pass's maximum [Pa], not logged."""
    if max_hertz_pressure > MAX_HERTZ_PRESSURE:
        return [f"operating.torque: maximum Hertz pressure {max_hertz_pressure / 1e9:.3g} GPa is above "
                f"{MAX_HERTZ_PRESSURE / 1e9:g} GPa (beyond the flank's contact strength)"]
    return []


def log_warnings(messages: Sequence[str], earlier: Sequence[str] = (), log_them: bool = True) -> list[str]:
    """The first of ``messages`` per key whose key is not among ``earlier``'s, logged (``log_them``)."""
    seen = {m.split(":", 1)[0] for m in earlier}
    first: dict[str, str] = {}
    for message in messages:
        key = message.split(":", 1)[0]
        if key not in seen:
            first.setdefault(key, message)
    if log_them:
        for message in first.values():
            log.warning(message)
    return list(first.values())


__all__ = ["check_operating_limits", "check_temperatures", "log_warnings", "pair_warnings", "pressure_warnings",
           "scene_warnings", "tip_speeds"]
