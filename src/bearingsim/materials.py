"""Solid materials of balls and rings, with a small named library.

Every entry cites where its numbers come from.  Values are SI:
Young's modulus [Pa], Poisson's ratio [-], density [kg/m³].

Plausibility bounds (:data:`LIMITS`; the table of all bearing-input bounds is in
:mod:`bearingsim.geometry`): E 1–1000 GPa (polymers ~2 GPa to tungsten carbide ~600 GPa),
0 ≤ ν < 0.5, ρ 500–25 000 kg/m³.  Outside them a material is refused with
:class:`~bearingsim.errors.InputError`: ``E = 1 Pa`` or a density in g/cm³ written as kg/m³ is a
unit slip, not a material.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import InputError

#: plausibility bounds: Young's modulus [Pa], Poisson's ratio [-], density [kg/m³]
LIMITS = {"youngs_modulus": (1e9, 1e12), "poisson_ratio": (0.0, 0.5), "density": (500.0, 25000.0)}


@dataclass(frozen=True)
class Material:
    """An isotropic linear-elastic solid.

    Parameters
    ----------
    name : str
    youngs_modulus : float  [Pa]
    poisson_ratio : float  [-], in (-1, 0.5)
    density : float  [kg/m³]
    source : str
        Where the numbers come from.
    """

    name: str
    youngs_modulus: float
    poisson_ratio: float
    density: float
    source: str = "user input"

    def __post_init__(self):
        if not isinstance(self.name, str):
            raise InputError("material.name", f"expected a string, got {type(self.name).__name__}",
                             'e.g. "bearing_steel"')
        for key in ("youngs_modulus", "poisson_ratio", "density"):
            v = getattr(self, key)
            if isinstance(v, bool) or not isinstance(v, (int, float)) and type(v).__module__ != "numpy":
                raise InputError(f"{self.name}.{key}", f"expected a number in SI units, got {type(v).__name__}",
                                 "give a float (Pa, -, kg/m^3)")
        if not (math.isfinite(self.youngs_modulus) and self.youngs_modulus > 0):
            raise InputError(f"{self.name}.youngs_modulus", f"must be positive, got {self.youngs_modulus!r}",
                             'e.g. "208 GPa" for bearing steel')
        lo, hi = LIMITS["youngs_modulus"]
        if not lo <= self.youngs_modulus <= hi:
            raise InputError(f"{self.name}.youngs_modulus", f"{self.youngs_modulus:.4g} Pa is outside the plausible "
                             f"{lo / 1e9:g}–{hi / 1e9:g} GPa", 'check the value and its unit, e.g. "208 GPa"')
        lo, hi = LIMITS["poisson_ratio"]
        if not (lo <= self.poisson_ratio < hi):
            raise InputError(f"{self.name}.poisson_ratio", f"must lie in [0, 0.5), got {self.poisson_ratio!r}",
                             "e.g. 0.3 for steel, 0.26 for silicon nitride")
        if not (math.isfinite(self.density) and self.density > 0):
            raise InputError(f"{self.name}.density", f"must be positive, got {self.density!r}",
                             'e.g. "7850 kg/m^3"')
        lo, hi = LIMITS["density"]
        if not lo <= self.density <= hi:
            raise InputError(f"{self.name}.density", f"{self.density:.4g} kg/m³ is outside the plausible "
                             f"{lo:g}–{hi:g} kg/m³", 'check the value and its unit, e.g. "7850 kg/m^3"')

    @property
    def reduced_compliance(self) -> float:
        """(1 - ν²)/E  [1/Pa], this body's share of the Hertz contact compliance."""
        return (1.0 - self.poisson_ratio**2) / self.youngs_modulus


#: Built-in materials.  SKF values are those SKF gives for its hybrid bearings
#: ("Hybrid bearings", SKF Rolling bearings catalogue 17000/1 EN, 2018, table
#: "Comparison of bearing steel and bearing grade silicon nitride properties").
LIBRARY: dict[str, Material] = {
    "bearing_steel": Material(
        "bearing_steel", 208e9, 0.30, 7900.0,
        "SKF rolling bearings catalogue 17000/1 EN (2018), hybrid bearings, property table: "
        "bearing steel E = 208 GPa, nu = 0.3, density 7.9 g/cm3"),
    "silicon_nitride": Material(
        "silicon_nitride", 310e9, 0.26, 3200.0,
        "SKF rolling bearings catalogue 17000/1 EN (2018), hybrid bearings, property table: "
        "bearing grade Si3N4 E = 310 GPa, nu = 0.26, density 3.2 g/cm3"),
    "harris_steel": Material(
        "harris_steel", 2.075e11, 0.30, 7800.0,
        "Harris & Kotzalas, Rolling Bearing Analysis 5th ed. (2007), worked examples for AISI 52100: "
        "E = 2.075e11 Pa, nu = 0.3; density 7800 kg/m3 is a typical 52100 value (estimate, "
        "not taken from Harris)"),
    "cage_steel": Material(
        "cage_steel", 2.06e11, 0.30, 7850.0,
        "ASSUMED pressed-steel cage (typical low-carbon sheet steel: E = 206 GPa, nu = 0.3, 7850 kg/m3); "
        "neither [S0] nor [S1] gives the cage material"),
}


def get_material(name: str, field: str = "material") -> Material:
    """Return a library material by name, or raise :class:`InputError` listing the choices."""
    if not isinstance(name, str):
        raise InputError(field, f"expected a material name, got {type(name).__name__}",
                         f"use one of {', '.join(sorted(LIBRARY))}")
    key = name.strip().lower().replace("-", "_").replace(" ", "_")
    try:
        return LIBRARY[key]
    except KeyError:
        raise InputError(field, f"unknown material {name!r}",
                         f"use one of {', '.join(sorted(LIBRARY))} or give a table with "
                         "youngs_modulus, poisson_ratio and density") from None
