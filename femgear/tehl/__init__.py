"""Thermal EHL (TEHL) and friction: energy equation of film and solids coupled to the FE
line EHL, traction (Couette and Poiseuille parts), path and map solvers."""

from femgear.tehl.energy import ThermalProps
from femgear.tehl.line import TEHLResult, solve_tehl_line

__all__ = ["ThermalProps", "TEHLResult", "solve_tehl_line"]
