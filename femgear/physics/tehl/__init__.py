"""Thermal EHL (TEHL) and friction: energy equation of film and solids coupled to the FE
EHL (line and point contacts), traction (Couette and Poiseuille parts), path and map solvers."""

from femgear.physics.tehl.energy import ThermalProps
from femgear.physics.tehl.line import TEHLResult, solve_tehl_line
from femgear.physics.tehl.point import TEHLPointResult, solve_tehl_point

__all__ = ["ThermalProps", "TEHLResult", "TEHLPointResult", "solve_tehl_line", "solve_tehl_point"]
