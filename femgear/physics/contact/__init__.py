"""Analytic contact mechanics: the oracles every solver is checked against.

- ``hertz``  line, circular and elliptical Hertz contact (exact elliptic integrals).
- ``film``   EHL film formulas (Hamrock–Dowson, Dowson–Higginson, Dowson–Toyoda,
             Moes line, Nijenbanning–Venner–Moes) and the Moes groups M, L.
- ``sharing`` quasi-static load sharing between the tooth pairs in contact (spur, helical).
- ``path``   the quasi-static Hertz + film pass along the path of contact (with load sharing).
"""

from femgear.physics.contact.film import (
    dowson_higginson_minimum,
    dowson_toyoda_central,
    hamrock_dowson_central,
    hamrock_dowson_minimum,
    line_film,
    moes_line,
    moes_line_central,
    moes_point,
    moes_to_h,
    nvm_central,
)
from femgear.physics.contact.hertz import (
    HertzLine,
    HertzPoint,
    ellipticity_exact,
    ellipticity_hamrock_brewe,
    hertz_line,
    hertz_point,
    reduced_modulus,
)

__all__ = [
    "HertzLine", "HertzPoint", "dowson_higginson_minimum", "dowson_toyoda_central", "ellipticity_exact",
    "ellipticity_hamrock_brewe", "hamrock_dowson_central", "hamrock_dowson_minimum", "hertz_line",
    "hertz_point", "line_film", "moes_line", "moes_line_central", "moes_point", "moes_to_h",
    "nvm_central", "reduced_modulus",
]
