"""The ring model a bearing file asks for: the ``[rings]`` table (parsed by :mod:`bearingsim.io.bearing`).

A bearing (or arrangement) file may say::

    [rings]
    model = "fe"                      # "rigid" (default) or "fe"

    [rings.housing]                   # the seat sleeve around the outer ring (optional)
    outer_diameter = "120 mm"         # housing outside diameter
    material = "bearing_steel"        # optional: a name of bearingsim.materials (default: the ring material)
    # youngs_modulus = "72 GPa"       # optional, instead of / overriding the material's
    # poisson_ratio = 0.33

    [rings.shaft]                     # the seat sleeve under the inner ring (optional)
    inner_diameter = "20 mm"          # shaft bore; "0 mm" = solid shaft
    # rigid = true                    # a rigid seat instead of a sleeve (either table)

The parsed table is a :class:`RingSpec`, kept in the bearing's ``notes["rings"]`` (like
``notes["operating_clearance"]``: the notes travel with ``dataclasses.replace`` and with pickling, so a map's
workers and a bearing changed by the clearance module keep it).  Without a sleeve table the defaults of
:func:`bearingsim.rings.coupling.ring_model` apply (shaft bore 0.5 d, housing outside diameter 1.5 D).

An arrangement file (a double-row unit, e.g. a wheel hub) may also give the boundary dimensions of a ring
section shared by the rows (docs/rings.md, "hub unit")::

    [rings.outer_ring]                # one outer ring carrying the grooves of all rows
    outside_diameter = "85 mm"
    width = "40 mm"
    [rings.inner_rings]               # the inner rings: one per row (separate rings), of this bore
    bore = "40 mm"
    width = "20 mm"                   # width of each inner ring (default: row spacing, capped at the unit)

Solid shaft (``inner_diameter = "0 mm"``).  The harmonic FE needs r > 0 (terms in 1/r), and the seat sleeve
needs a surface where the shaft's rigid motion (harmonic 1) is imposed: held on a vanishing core, the
harmonic-1 response would grow like log(1/core radius) (a pinned point in an elastic disc).  A solid shaft is
therefore modelled as a sleeve of bore :data:`SOLID_SHAFT_BORE_FRACTION` × the ring's bore, held in harmonic 1
there and free otherwise: a rigid core of a quarter of the bore diameter.  This is an approximation with a
first-order sensitivity (docs/rings.md: a core of 0.15 d or 0.35 d instead of 0.25 d changes the radial
self-coefficient of the 7011 inner ring by −23 % / +53 %); a hollow shaft of known bore is the better-defined
input.

Units: SI floats (m, Pa).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import InputError

RING_MODELS = ("rigid", "fe")
#: bore of the sleeve standing for a solid shaft, as a fraction of the ring's bore (see the module docstring)
SOLID_SHAFT_BORE_FRACTION = 0.25


@dataclass(frozen=True)
class Sleeve:
    """A seat sleeve: ``diameter`` [m] (housing outside diameter, or shaft bore, 0 for a solid shaft),
    ``youngs_modulus`` [Pa] / ``poisson_ratio`` [-] (None: the ring's material), ``rigid`` (a rigid seat instead
    of a sleeve: ``diameter`` unused), ``material`` (name, for the description)."""

    diameter: float = 0.0
    youngs_modulus: float | None = None
    poisson_ratio: float | None = None
    rigid: bool = False
    material: str = ""

    def __post_init__(self):
        if not (isinstance(self.diameter, (int, float)) and math.isfinite(self.diameter) and self.diameter >= 0):
            raise InputError("sleeve.diameter", f"must be a length ≥ 0, got {self.diameter!r}", "e.g. 0.12 (m)")
        if self.youngs_modulus is not None and not (math.isfinite(self.youngs_modulus) and self.youngs_modulus > 0):
            raise InputError("sleeve.youngs_modulus", f"must be positive, got {self.youngs_modulus!r} Pa",
                             "e.g. 208e9")
        if self.poisson_ratio is not None and not 0.0 <= self.poisson_ratio < 0.5:
            raise InputError("sleeve.poisson_ratio", f"must be in [0, 0.5), got {self.poisson_ratio!r}", "e.g. 0.3")


@dataclass(frozen=True)
class RingSpec:
    """The ``[rings]`` table of a bearing file (module docstring): ring ``model``, optional ``housing`` and
    ``shaft`` sleeves, and for double-row units the shared outer ring's ``outer_ring`` = (outside diameter,
    width) [m] and the inner rings' ``inner_rings`` = (bore, width) [m] (0 where not given)."""

    model: str = "rigid"
    housing: Sleeve | None = None
    shaft: Sleeve | None = None
    outer_ring: tuple = (0.0, 0.0)
    inner_rings: tuple = (0.0, 0.0)

    def __post_init__(self):
        if self.model not in RING_MODELS:
            raise InputError("rings.model", f"unknown ring model {self.model!r}", 'use "rigid" or "fe"')

    def describe(self) -> dict:
        """Plain summary for JSON output [m, Pa]."""
        def sleeve(s):
            if s is None:
                return None
            return {"rigid": s.rigid, "diameter_m": s.diameter, "youngs_modulus_Pa": s.youngs_modulus,
                    "poisson_ratio": s.poisson_ratio, "material": s.material}

        return {"model": self.model, "housing": sleeve(self.housing), "shaft": sleeve(self.shaft),
                "outer_ring_outside_diameter_m": self.outer_ring[0], "outer_ring_width_m": self.outer_ring[1],
                "inner_ring_bore_m": self.inner_rings[0], "inner_ring_width_m": self.inner_rings[1]}


def spec_of(bearing) -> RingSpec | None:
    """The :class:`RingSpec` a bearing (or bearing system) was read with, or None.  For a system without its own
    ``[rings]`` table, that of its first row's bearing (the rows of a set come from one file)."""
    notes = getattr(bearing, "notes", None)
    spec = notes.get("rings") if isinstance(notes, dict) else None
    if isinstance(spec, RingSpec):
        return spec
    if getattr(bearing, "kind", None) == "bearing_system":  # a system: its rows' bearings
        for row in bearing.rows:
            s = spec_of(row.bearing)
            if s is not None:
                return s
    return None


def model_of(bearing) -> str:
    """``"fe"`` or ``"rigid"``: the ring model of the bearing's file (``rigid`` without a ``[rings]`` table)."""
    spec = spec_of(bearing)
    return spec.model if spec is not None else "rigid"


__all__ = ["RING_MODELS", "RingSpec", "SOLID_SHAFT_BORE_FRACTION", "Sleeve", "model_of", "spec_of"]
