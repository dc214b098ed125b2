"""The flag of an unresolved outlet spike (:func:`femgear.physics.ehl.fd.line.spike_resolved`) and where the
spike-resolving bump goes (:func:`~femgear.physics.ehl.fd.line.spike_peak`).

On a heavy contact the Hertzian dome is higher than the spike.  The bump used to go to the largest pressure, the
dome, and the spike stayed on the plain grid: its peak pressure and the film's peak temperature on it were low (the
marine zoo pair: 22.5 K against 47.6 K resolved at one path position), which the films' Richardson estimate does not
see.  It now goes to the outlet-most local maximum.  These checks can fail: a locator or flag that read the global
maximum, or any grid as resolving, would pass the dome case or fail the bumped one."""

import numpy as np

from femgear.physics.ehl.fd.line import SPIKE_NODES, solve_line_fd, spike_peak, spike_resolved
from femgear.physics.ehl.fd.line_grid import SPIKE_WIDTH


def _dome_and_spike(X):
    """A Hertzian dome of 1 with a spike of 0.7 at X 0.88, downstream of it (the heavy contact's shape)."""
    dome = np.sqrt(np.clip(1.0 - X**2, 0.0, None))
    return np.maximum(dome, 0.7 * np.exp(-(((X - 0.88) / 0.01) ** 2)))


def test_a_spike_below_the_dome_on_a_plain_grid_is_unresolved():
    X = np.linspace(-3.0, 1.5, 451)        # 0.01 apart: 5 nodes across the spike width
    assert SPIKE_WIDTH / 0.01 < SPIKE_NODES
    assert not spike_resolved(X, _dome_and_spike(X))


def test_the_same_spike_on_a_grid_bumped_at_it_is_resolved():
    X = np.unique(np.r_[np.linspace(-3.0, 1.5, 451), np.linspace(0.83, 0.93, 201)])   # 0.0005 at the spike
    assert spike_resolved(X, _dome_and_spike(X))


def test_a_dome_without_a_spike_has_nothing_to_resolve():
    """The fast turbo contacts: inlet heating flattens the spike away, the maximum is the dome's near the centre."""
    X = np.linspace(-3.0, 1.5, 451)
    assert spike_resolved(X, np.sqrt(np.clip(1.0 - (X - 0.03) ** 2, 0.0, None)))


def test_the_bump_goes_to_the_spike_not_to_the_higher_dome():
    X = np.linspace(-3.0, 1.5, 451)
    assert abs(spike_peak(X, _dome_and_spike(X)) - 0.88) < 0.01


def test_a_bumped_grid_at_the_dome_leaves_the_spike_unresolved():
    """A bump at the global maximum, the dome, does not count."""
    X = np.unique(np.r_[np.linspace(-3.0, 1.5, 451), np.linspace(-0.05, 0.05, 201)])
    assert not spike_resolved(X, _dome_and_spike(X))


def test_line_solves_with_and_without_a_resolved_spike():
    """(M, L) = (2, 11.7): the bumped solve resolves the spike (16.97 p_h against 3.25 on the plain 1025-node grid);
    (16, 11.7): the bumped grid's Newton fails, the plain answer stands in, and the flag says so."""
    light = solve_line_fd(2.0, 11.7, tol=None, level=6, spike=True)
    assert spike_resolved(light.x, light.P) and light.Pmax > 10.0
    plain = solve_line_fd(2.0, 11.7, tol=None, level=6)
    assert not spike_resolved(plain.x, plain.P) and plain.Pmax < 0.5 * light.Pmax
    heavy = solve_line_fd(16.0, 11.7, tol=None, level=6, spike=True)
    assert "not resolved" in heavy.history.get("spike", "")
    assert not spike_resolved(heavy.x, heavy.P)
