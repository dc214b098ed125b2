"""Validation (issue 38, item 2): gear friction of the FZG A test gear over the load stages KS 5–12 against
ISO/TS 6336-20:2017's μ_mC, Schlenk's fit to FZG back-to-back power-loss measurements (femgear's rating of the same
case; A/8.3/90, mineral ISO VG 100, R_a 0.35 µm, :mod:`studies.validation.fzg_friction`).

femgear's μ̄ (the constant μ of its own mesh loss) of the ``formula`` level with the load share of Zhou & Hoeprich
(J. Tribol. 113:590, 1991: W_C/W = exp(−B λ^C), λ the local thermal central film over σ along the path; B, C of
Wingertszahn et al., Lubricants 11:369, 2023), boundary μ_b 0.1 (the GEARpie library's value for every base oil,
Fernandes), the flanks' bulk temperature femgear's own fixed point.  Measured with it (``PYTHONPATH=$PWD python
studies/validation/fzg_friction.py --contact=zhou-hoeprich``): μ̄/μ_mC 1.32, 1.32, 1.32, 1.31, 1.30, 1.30, 1.28,
1.27 at KS 5–12, μ̄ rising 1.30× where μ_mC rises 1.35×, λ 0.08–0.31.  With the default Greenwood–Tripp split
(today's main) μ̄/μ_mC falls 0.61 → 0.42 and μ̄ falls 7 %: the trend test fails there.
"""

from __future__ import annotations

import numpy as np
import pytest

from studies.validation import fzg_friction


@pytest.fixture(scope="module")
def stages():
    return fzg_friction.run(contact="zhou-hoeprich")["rows"]


def test_fzg_a_friction_rises_with_load_below_lambda_one_as_iso_mu_mC(stages):
    """Every stage runs below λ = 1 (the rating's λ_min and the path mean of the local h_c/σ the share reads), μ̄
    rises from stage to stage, and μ̄ normalised by its KS 5 value follows μ_mC normalised alike within ±10 % at
    every stage (main's Greenwood–Tripp split: −31 % at KS 12)."""
    assert [r["stage"] for r in stages] == list(range(5, 13))
    assert all(r["film_parameter_mean"] < 1 and r["lambda_min"] < 1 for r in stages)
    mu, iso = (np.array([r[k] for r in stages]) for k in ("mu_mean", "mu_mC_iso"))
    assert np.all(np.diff(mu) > 0)
    np.testing.assert_allclose((mu / mu[0]) / (iso / iso[0]), 1.0, atol=0.10)


@pytest.mark.xfail(strict=True, reason="not met: μ̄/μ_mC 1.27–1.32 at KS 5–12 (the trend is met, the level is "
                                        "2–7 points above the band; docs/models/lubrication.md)")
def test_fzg_a_friction_within_25_percent_of_iso_mu_mC(stages):
    """The issue's check: μ̄ within ±25 % of μ_mC at every stage KS 5–12."""
    ratio = np.array([r["ratio_iso"] for r in stages])
    assert np.all(np.abs(ratio - 1) <= 0.25), ratio
