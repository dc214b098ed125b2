"""Gear-rotor dynamics of the double-helical pair (24 DOF: pinion-L/R, gear-L/R × 6).

- ``layout``     DOF numbering, frame, rigid-body point Jacobians, the rigid-shaft tie.
- ``timoshenko`` 12×12 Timoshenko shaft element (stiffness, consistent mass), Guyan.
- ``mesh``       line-of-action vectors per helix, mesh-stiffness tables (constant,
                 contact-line TVMS; any TVMS plugs in as a :class:`StiffnessTable`),
                 friction tables with the regularised sliding sign.
- ``structure``  half bodies, bearings and shafts per level (rigid tie or Timoshenko + Guyan).
- ``model``      the frozen :class:`GearRotorModel` (levels ``lumped``, ``timoshenko``)
                 and the drive/coast flank deviations :class:`MeshDeviation`.
- ``build``      :func:`build_model` from a :class:`femgear.case.Case` (structure, mesh,
                 excitation, damping builders); ``with_friction``/``with_deviation``.
- ``integrate``  :func:`simulate`, one entry point for the integrators:
  ``rk4``        fixed-step RK4 (paper) and its stability limit;
  ``expo``       exponential integrator, exact propagators per mesh phase (the fast one),
                 band-exact stiffness staircase, Taylor φ-functions for the sub-steps;
  ``newmark``    implicit HHT-α/Newmark with exact Newton on the gap;
  ``simulation`` the recorded :class:`Simulation` and shared input helpers.
- ``response``   amplitudes (half peak-to-peak), mesh forces, bearing accelerations,
                 Hanning spectra with mesh orders; frozen :class:`Response`.
- ``bearings``   bearing loads F = K_F q + C_F q̇ of the four stations from a state history (every level),
                 their mean, peak-to-peak and mesh orders; Newton's law per member.
- ``orders``     least-squares line fits at known frequencies (mesh and shaft orders).
- ``modal``      linearised (mean-stiffness) modal analysis with modal energy per DOF group;
                 the highest mode the mesh excitation reaches.
- ``sweep``      time-domain speed sweeps (DTE RMS vs mesh frequency).
- ``family``     :class:`SpeedFamily`: the models of a case at many speeds, the speed-independent parts built once.
- ``harmonic``   steady state per order by harmonic balance, flanks in contact (``harmonic_core``: the batched
                 equations); ``harmonic_sweep``: whine against speed, contact loss handed to time integration.
- ``aft``        nonlinear harmonic balance (alternating frequency–time) with pseudo-arclength continuation;
  ``sdof_hb``    the Kahraman–Singh oscillator traced through its folds.
- ``runup``      a speed ramp in the time domain and order tracking by resampling to shaft angle.
- ``sdof``       Kahraman–Singh single-DOF backlash oscillator and frequency sweeps.
- ``run``        one dynamic run of a model (integration → response → modes), pure; the default
                 step plan (docs/dynamics_step.md).
- (figures: :mod:`femgear.edge.plot.dynamics`; files: :mod:`femgear.edge.io.dynamics`.)
"""

from femgear.system.dynamics.build import build_model, with_deviation, with_friction
from femgear.system.dynamics.integrate import Simulation, simulate, stability_limit
from femgear.system.dynamics.mesh import StiffnessTable, constant_stiffness, contact_line_stiffness
from femgear.system.dynamics.modal import ModalResult, modal_analysis
from femgear.system.dynamics.model import GearRotorModel, MeshDeviation
from femgear.system.dynamics.response import Response, analyse
from femgear.system.dynamics.run import DynamicsRun, run_dynamics

__all__ = [
    "DynamicsRun", "GearRotorModel", "MeshDeviation", "StiffnessTable", "ModalResult", "Response", "Simulation", "analyse",
    "build_model", "constant_stiffness", "contact_line_stiffness", "modal_analysis", "run_dynamics", "simulate",
    "stability_limit", "with_deviation", "with_friction",
]
