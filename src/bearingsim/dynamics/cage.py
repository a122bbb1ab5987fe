"""The cage: rigid now, laid out so that modal (elastic) coordinates can be added.

Seed 001 §3 (Table 3): the cage has 3 translations and 3 rotations and, in IBDAS, 56
elastic modes.  Here the cage is rigid: its state block is

    r (3), v (3), θ, βy, βz, θ̇, β̇y, β̇z                    (N_CAGE = 12 values)

and its pocket surfaces are spheres or cylinders in the pocket frame (:func:`pocket_geometry`);
the contact routine finds the surface point nearest the ball centre in closed form.  An elastic
cage adds n modal coordinates η and rates η̇ after these 12 values (:func:`block_size`) and
displaces that contact point by Σ η_i φ_i(point); only the mode shapes at the contact point and
the generalized modal forces Σ φ_i·F need adding.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import InputError
from .model import GUIDANCE, N_CAGE, pocket_geometry, steel_cage_constant  # noqa: F401  (re-exported)


def block_size(n_modes: int = 0) -> int:
    """Length of one cage's state block: 12 rigid-body values + 2 per elastic mode."""
    if n_modes < 0:
        raise InputError("cage.n_modes", "must be ≥ 0", "0 for a rigid cage")
    return N_CAGE + 2 * n_modes


@dataclass(frozen=True)
class CageSpec:
    """Cage data (SI).  None: the default of :func:`bearingsim.dynamics.model.build_model`.

    mass [kg]; pocket_clearance [m] (pocket radius − ball radius); friction μ [-] (seed 001:
    0.06); guidance "balls" | "outer-land" | "inner-land"; land_clearance [m];
    pocket_shape "sphere" | "cylinder"; n_modes (0: rigid; > 0 not implemented yet).
    """

    mass: float | None = None
    pocket_clearance: float | None = None
    friction: float = 0.06
    guidance: str = "balls"
    land_clearance: float = 2e-4
    pocket_shape: str = "sphere"
    n_modes: int = 0

    def __post_init__(self):
        if self.mass is not None and not (math.isfinite(self.mass) and self.mass > 0):
            raise InputError("cage.mass", f"must be positive, got {self.mass!r}", 'e.g. "0.03 kg"')
        if self.pocket_clearance is not None and not self.pocket_clearance > 0:
            raise InputError("cage.pocket_clearance", "must be positive", 'e.g. "0.2 mm"')
        if not (0 <= self.friction < 1):
            raise InputError("cage.friction", f"must lie in [0, 1), got {self.friction!r}", "seed 001 uses 0.06")
        if self.guidance not in GUIDANCE:
            raise InputError("cage.guidance", f"unknown guidance {self.guidance!r}", "use balls, outer-land, inner-land")
        if self.land_clearance <= 0:
            raise InputError("cage.land_clearance", "must be positive", 'e.g. "0.2 mm"')
        if self.n_modes != 0:
            raise InputError("cage.n_modes", "the elastic (modal) cage is not implemented yet", "use n_modes = 0")

    def model_options(self) -> dict:
        """Keyword arguments of :func:`bearingsim.dynamics.model.build_model`."""
        return dict(cage_mass=self.mass, pocket_clearance=self.pocket_clearance, cage_mu=self.friction,
                    guidance=self.guidance, land_clearance=self.land_clearance, pocket_shape=self.pocket_shape)
