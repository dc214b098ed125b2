"""Tier 3: the Kahraman–Singh backlash oscillator shows the softening jump."""

import numpy as np

from femgear.system.dynamics.sdof import kahraman_singh_sweep


def test_up_and_down_sweeps_differ_with_contact_loss_near_resonance():
    w = np.linspace(0.7, 1.2, 26)
    up = kahraman_singh_sweep(w, direction="up")
    down = kahraman_singh_sweep(w, direction="down")
    a_up, a_down = up.amplitude, down.amplitude[::-1]
    gap = a_down - a_up
    assert gap.max() > 0.05                                   # two branches: hysteresis
    band = w[gap > 0.02]
    assert band.max() < 1.0                                   # the bistable band lies below Ω = 1: softening
    jump_up = w[np.argmax(np.diff(a_up)) + 1]                 # the up-sweep jumps up at a higher Ω ...
    jump_down = w[np.argmax(np.diff(a_down))]                 # ... than where the down-sweep falls off
    assert jump_up > jump_down
    loss_up = up.contact_loss
    assert loss_up[np.argmax(a_up)] > 0.1                     # contact is lost at the peak
    assert np.all(loss_up[(w < 0.75) | (w > 1.15)] == 0)      # and kept far from resonance
    assert np.allclose(a_up[w > 1.12], a_down[w > 1.12], rtol=1e-3)


def test_linear_limit_matches_the_harmonic_response():
    """Small excitation: no contact loss, the amplitude is F_a/|1 − Ω² + 2iζΩ|."""
    w = np.array([0.5, 1.0, 1.5])
    r = kahraman_singh_sweep(w, zeta=0.05, mean_load=0.5, alternating_load=0.01, cycles=80, measure=10)
    exact = 0.01 / np.abs(1 - w**2 + 2j * 0.05 * w)
    assert np.allclose(r.amplitude, exact, rtol=2e-3)
    assert np.all(r.contact_loss == 0)
