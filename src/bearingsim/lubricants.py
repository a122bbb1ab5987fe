"""Lubricants (base oils): properties with units in TOML and a small named library.

A :class:`Lubricant` holds what the film-thickness, traction and rolling-resistance
models need:

* kinematic viscosity vs temperature by the Walther equation of ASTM D341,
  log₁₀ log₁₀(ν + 0.7) = A − B log₁₀ T  (ν in mm²/s = cSt, T in K), fitted through two
  measured points (usually 40 °C and 100 °C);
* density ρ(T) = ρ₁₅ [1 − β_ρ (T − 288.15 K)];
* dynamic viscosity η = ρ ν [Pa·s] and its temperature coefficient −d ln η/dT [1/K];
* pressure–viscosity coefficient α [1/Pa] (Barus; constant) and the Roelands index
  z = α / [5.1×10⁻⁹ (ln η₀ + 9.67)] that gives the same initial slope (Roelands 1966);
* thermal conductivity k [W/(m·K)];
* traction parameters: Eyring stress τ₀ [Pa]; limiting shear stress law
  τ_L = r_L [c₁ p/(c₂ + c₃ t) − c₄] (Dyson, via Zhou & Hoeprich 1991 eqs. 36–37, t in °C),
  floored at ``lss_floor``·p.

The Walther equation is used only inside the lubricant's defined temperature range
[min_temperature, max_temperature]; outside it raises :class:`InputError`.

Library files are ``bearingsim/data/lubricant-<name>.toml`` (every number cites a source or says that
it is an assumed typical value), read by :mod:`bearingsim.io.lubricant`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .errors import InputError

T15 = 288.15


@dataclass(frozen=True)
class Lubricant:
    """A base oil.  All SI: temperatures [K], kinematic viscosities [m²/s].

    Parameters
    ----------
    name : str
    temperature_1, temperature_2 : float  [K]  temperatures of the two viscosity points
    kinematic_viscosity_1, kinematic_viscosity_2 : float  [m²/s]
    density_15 : float  [kg/m³]  density at 15 °C
    density_temperature_coefficient : float  [1/K]  β_ρ
    pressure_viscosity_coefficient : float  [1/Pa]  α
    thermal_conductivity : float  [W/(m·K)]
    eyring_stress : float  [Pa]  τ₀
    lss_ratio, lss_c1, lss_c2, lss_c3, lss_c4 : limiting shear stress law (module docstring);
        c₁ [-], c₂ [-], c₃ [1/°C], c₄ [Pa]
    lss_floor : float  [-]  lower bound of τ_L/p
    min_temperature, max_temperature : float  [K]  range where the viscosity law is used
    description : str
    sources : dict  property name → source text
    """

    name: str
    temperature_1: float
    kinematic_viscosity_1: float
    temperature_2: float
    kinematic_viscosity_2: float
    density_15: float
    pressure_viscosity_coefficient: float
    thermal_conductivity: float
    density_temperature_coefficient: float = 6.4e-4
    eyring_stress: float = 5e6
    lss_ratio: float = 0.25
    lss_c1: float = 1.2
    lss_c2: float = 2.52
    lss_c3: float = 0.024
    lss_c4: float = 1e8
    lss_floor: float = 0.02
    min_temperature: float = 253.15
    max_temperature: float = 423.15
    description: str = ""
    sources: dict = field(default_factory=dict, compare=False, hash=False)

    def __post_init__(self):
        if not isinstance(self.name, str):
            raise InputError("lubricant.name", f"expected a string, got {type(self.name).__name__}", 'e.g. "my-oil"')

        def pos(fname, v):
            if isinstance(v, bool) or not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise InputError(f"{self.name}.{fname}", f"must be a positive finite number, got {v!r}",
                                 "check the value and its unit")
        for f in ("temperature_1", "kinematic_viscosity_1", "temperature_2", "kinematic_viscosity_2",
                  "density_15", "pressure_viscosity_coefficient", "thermal_conductivity", "eyring_stress",
                  "lss_ratio", "lss_c1", "lss_c2", "min_temperature", "max_temperature"):
            pos(f, getattr(self, f))
        for f in ("density_temperature_coefficient", "lss_c3", "lss_c4", "lss_floor"):
            v = getattr(self, f)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not (math.isfinite(v) and v >= 0):
                raise InputError(f"{self.name}.{f}", f"must be finite and >= 0, got {v!r}",
                                 "give a number >= 0 (SI units; in a file, with its unit)")
        if self.temperature_1 == self.temperature_2:
            raise InputError(f"{self.name}.viscosity", "the two viscosity points are at the same temperature",
                             "give viscosities at two temperatures, e.g. 40 degC and 100 degC")
        lo, hi = sorted([(self.temperature_1, self.kinematic_viscosity_1),
                         (self.temperature_2, self.kinematic_viscosity_2)])
        if not hi[1] < lo[1]:
            raise InputError(f"{self.name}.viscosity", "viscosity must fall as temperature rises",
                             "check the order of the two viscosity points")
        if min(self.kinematic_viscosity_1, self.kinematic_viscosity_2) < 2e-6:
            raise InputError(f"{self.name}.viscosity", "ASTM D341 (with 0.7) is valid down to 2 mm²/s",
                             "give viscosity points above 2 mm^2/s")
        if not self.min_temperature < self.max_temperature:
            raise InputError(f"{self.name}.min_temperature", "must be below max_temperature",
                             'e.g. temperature_range = ["-20 degC", "150 degC"]')
        if self.pressure_viscosity_coefficient > 1e-7 or self.pressure_viscosity_coefficient < 1e-10:
            raise InputError(f"{self.name}.pressure_viscosity_coefficient",
                             f"{self.pressure_viscosity_coefficient!r} 1/Pa is outside 0.1–100 1/GPa",
                             'oils have about "10 1/GPa" to "35 1/GPa"')

    # --- ASTM D341 (Walther) ---------------------------------------------------------
    @property
    def walther_constants(self) -> tuple[float, float]:
        """(A, B) of log₁₀log₁₀(ν+0.7) = A − B log₁₀T, ν in mm²/s, T in K (ASTM D341)."""
        y1 = math.log10(math.log10(self.kinematic_viscosity_1 * 1e6 + 0.7))
        y2 = math.log10(math.log10(self.kinematic_viscosity_2 * 1e6 + 0.7))
        x1, x2 = math.log10(self.temperature_1), math.log10(self.temperature_2)
        b = (y1 - y2) / (x2 - x1)
        return y1 + b * x1, b

    def check_temperature(self, temperature: float, field_name: str = "temperature") -> float:
        if not (isinstance(temperature, (int, float)) and math.isfinite(temperature)):
            raise InputError(field_name, f"must be a finite temperature, got {temperature!r}", 'e.g. "60 degC"')
        if not (self.min_temperature <= temperature <= self.max_temperature):
            raise InputError(field_name,
                             f"{temperature - 273.15:.1f} degC is outside the defined range of {self.name} "
                             f"({self.min_temperature - 273.15:.0f} to {self.max_temperature - 273.15:.0f} degC)",
                             "use a temperature inside the range or another lubricant")
        return float(temperature)

    def kinematic_viscosity(self, temperature: float) -> float:
        """ν(T) [m²/s] by ASTM D341 (Walther)."""
        t = self.check_temperature(temperature)
        a, b = self.walther_constants
        return (10.0 ** (10.0 ** (a - b * math.log10(t))) - 0.7) * 1e-6

    def density(self, temperature: float) -> float:
        """ρ(T) = ρ₁₅[1 − β_ρ(T − 288.15)]  [kg/m³]."""
        t = self.check_temperature(temperature)
        return self.density_15 * (1.0 - self.density_temperature_coefficient * (t - T15))

    def dynamic_viscosity(self, temperature: float) -> float:
        """η(T) = ρ(T) ν(T)  [Pa·s]."""
        return self.density(temperature) * self.kinematic_viscosity(temperature)

    def viscosity_temperature_coefficient(self, temperature: float) -> float:
        """β = −d ln η / dT  [1/K] (analytic derivative of Walther and of ρ(T))."""
        t = self.check_temperature(temperature)
        a, b = self.walther_constants
        y = a - b * math.log10(t)
        nu = 10.0 ** (10.0**y) - 0.7  # mm²/s
        dln_nu = -(nu + 0.7) / nu * math.log(10.0) * 10.0**y * b / t
        dln_rho = -self.density_temperature_coefficient / (1.0 - self.density_temperature_coefficient * (t - T15))
        return -(dln_nu + dln_rho)

    def roelands_index(self, temperature: float) -> float:
        """z = α / [5.1e-9 (ln η₀ + 9.67)] (Roelands 1966; η₀ in Pa·s, α in 1/Pa)."""
        eta = self.dynamic_viscosity(temperature)
        return self.pressure_viscosity_coefficient / (5.1e-9 * (math.log(eta) + 9.67))

    def summary(self, temperature: float | None = None) -> dict:
        out = {"name": self.name, "description": self.description,
               "viscosity_40C_mm2_s": self.kinematic_viscosity(313.15) * 1e6
               if self.min_temperature <= 313.15 <= self.max_temperature else None,
               "viscosity_100C_mm2_s": self.kinematic_viscosity(373.15) * 1e6
               if self.min_temperature <= 373.15 <= self.max_temperature else None,
               "density_15C_kg_m3": self.density_15,
               "pressure_viscosity_coefficient_1_Pa": self.pressure_viscosity_coefficient,
               "thermal_conductivity_W_mK": self.thermal_conductivity,
               "temperature_range_K": [self.min_temperature, self.max_temperature]}
        if temperature is not None:
            out["dynamic_viscosity_Pa_s"] = self.dynamic_viscosity(temperature)
        return out


# --------------------------------------------------------------------------- files
#: the readers of lubricant files live in :mod:`bearingsim.io.lubricant` (every file format in one
#: package); their names stay importable from here (forwarded on first use: no import cycle)
_READERS = ("lubricant_from_dict", "get_lubricant", "library", "library_names")


def __getattr__(name: str):
    if name in _READERS:
        from .io import lubricant as _reader

        return getattr(_reader, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


# the readers are forwarded by __getattr__ (ruff cannot see them)
__all__ = ["Lubricant", "lubricant_from_dict", "get_lubricant", "library", "library_names"]  # noqa: F822
