"""Thermal network and operating point of a bearing: :mod:`.network` (nodes, conductances, linear
steady solve), :mod:`.correlations` (convection, contact conductance), :mod:`.operating_point` (the fixed point
temperatures → clearance → load distribution → friction → temperatures)."""

from .network import NetworkSolution, ThermalNetwork, axial_conduction, convection, radial_conduction
from .operating_point import ThermalOperatingPoint, ThermalSetup, bearing_at_temperatures, thermal_operating_point

__all__ = ["ThermalNetwork", "NetworkSolution", "radial_conduction", "axial_conduction", "convection",
           "ThermalSetup", "ThermalOperatingPoint", "thermal_operating_point", "bearing_at_temperatures"]
