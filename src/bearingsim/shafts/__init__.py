"""Shaft systems: a stepped Timoshenko shaft on ball bearings and springs, its static equilibrium with the
bearings' full Jones–Harris response, the linearised stiffness at any node, natural frequencies and the export
to ROSS.

Modules: :mod:`.model` (inputs and mesh), :mod:`.solve` (assembly, Newton, stiffness at a node), :mod:`.modes`
(eigenproblem, Campbell), :mod:`.sweep` (speed and preload sweeps), :mod:`.ross` (ROSS rotor).
"""

from .model import (
    NODE_DOF,
    BearingSupport,
    DistributedLoad,
    Gravity,
    HelicalGear,
    Mesh,
    PointLoad,
    PointMass,
    Section,
    ShaftSystem,
    SpringSupport,
)

__all__ = ["NODE_DOF", "BearingSupport", "DistributedLoad", "Gravity", "HelicalGear", "Mesh", "PointLoad",
           "PointMass", "Section", "ShaftSystem", "SpringSupport"]
