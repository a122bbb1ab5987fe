"""Heat-transfer correlations for a bearing's thermal network, each with its source and validity range.

All SI: [W/(m² K)], [W/K], [m], [m/s], [K], [Pa·s], [kg/m³], [W/(m K)], [J/(kg K)].
"""

from __future__ import annotations

import math

from ..errors import InputError

#: thermal conductivity of AISI 52100 bearing steel [W/(m K)] (Harris & Kotzalas 2007 vol. 1 table of
#: material properties: 43 W/(m K); Incropera et al. 2007 table A.1 gives 40–45 for low-alloy steels)
STEEL_CONDUCTIVITY = 43.0
#: silicon nitride [W/(m K)] (SKF hybrid bearing property table: 30–35; 30 taken)
SILICON_NITRIDE_CONDUCTIVITY = 30.0
_R_AIR = 287.05
_P_ATM = 101325.0


def _pos(name, v):
    v = float(v)
    if not (math.isfinite(v) and v > 0):
        raise InputError(name, f"must be positive and finite, got {v!r}", "give a positive value in SI units")
    return v


def flat_plate_convection(velocity: float, length: float, density: float, viscosity: float,
                          conductivity: float, specific_heat: float) -> float:
    """Mean convection coefficient h [W/(m² K)] of a surface swept at ``velocity`` over ``length``.

    Incropera et al. 2007 (6th ed.): laminar, Re_L ≤ 5·10⁵, Nu = 0.664 Re^½ Pr^⅓ (eq. 7.30, 0.6 ≤ Pr);
    mixed laminar–turbulent, 5·10⁵ < Re_L ≤ 10⁸, Nu = (0.037 Re^⅘ − 871) Pr^⅓ (eq. 7.38, 0.6 ≤ Pr ≤ 60).
    Harris & Kotzalas 2007 vol. 1 ch. 15 take this flat-plate form for the rings and balls in the lubricant;
    a Pr above 60 (oils) is outside eq. 7.38's stated range and Re above 10⁸ is clipped to it.
    At zero velocity the coefficient is 0 (no forced convection)."""
    L = _pos("length", length)
    if velocity == 0.0:
        return 0.0
    re = min(_pos("density", density) * abs(velocity) * L / _pos("viscosity", viscosity), 1e8)
    pr = _pos("specific_heat", specific_heat) * viscosity / _pos("conductivity", conductivity)
    if re <= 5e5:
        nu = 0.664 * re**0.5 * pr ** (1.0 / 3.0)
    else:
        nu = (0.037 * re**0.8 - 871.0) * pr ** (1.0 / 3.0)
    return nu * conductivity / L


def air_properties(temperature: float) -> tuple[float, float, float, float]:
    """(density [kg/m³], viscosity [Pa·s], conductivity [W/(m K)], Prandtl [-]) of dry air at 1 atm.

    Ideal gas; Sutherland's viscosity (μ₀ = 1.716e-5 Pa·s at 273.15 K, S = 110.4 K); conductivity linear
    through Incropera et al. 2007 table A.4 (0.0223 at 250 K, 0.0338 at 400 K: within 2 % of the table over
    250–500 K); Pr = 0.70 (table A.4: 0.690–0.720 over 250–500 K)."""
    t = _pos("temperature", temperature)
    rho = _P_ATM / (_R_AIR * t)
    mu = 1.716e-5 * (t / 273.15) ** 1.5 * (273.15 + 110.4) / (t + 110.4)
    k = 0.0223 + (0.0338 - 0.0223) * (t - 250.0) / 150.0
    return rho, mu, k, 0.70


def natural_convection_cylinder(diameter: float, surface_temperature: float, ambient_temperature: float) -> float:
    """Mean coefficient h [W/(m² K)] of a long horizontal cylinder in still air (Churchill & Chu 1975;
    Incropera et al. 2007 eq. 9.34): Nu = {0.60 + 0.387 Ra^⅙ / [1 + (0.559/Pr)^(9/16)]^(8/27)}², valid
    Ra ≤ 10¹²; air properties at the film temperature (:func:`air_properties`), β = 1/T_film.
    A housing's outer surface is treated as such a cylinder."""
    d = _pos("diameter", diameter)
    ts, ta = _pos("surface_temperature", surface_temperature), _pos("ambient_temperature", ambient_temperature)
    tf = 0.5 * (ts + ta)
    rho, mu, k, pr = air_properties(tf)
    nu_k = mu / rho
    alpha = nu_k / pr
    ra = 9.81 * (1.0 / tf) * abs(ts - ta) * d**3 / (nu_k * alpha)
    nu = (0.60 + 0.387 * ra ** (1.0 / 6.0) / (1.0 + (0.559 / pr) ** (9.0 / 16.0)) ** (8.0 / 27.0)) ** 2
    return nu * k / d


def contact_conductance(semi_major: float, semi_minor: float, conductivity_1: float, conductivity_2: float) -> float:
    """Conductance [W/K] of a ball–raceway contact: the constriction resistance of an isothermal circular
    contact of radius a on a half-space, R = 1/(4 k a), on each side (Holm 1967; Yovanovich & Marotta 2003,
    in Bejan & Kraus, *Heat Transfer Handbook*, ch. 4, eq. 4.22), a = √(a_major b_minor) of the Hertz
    ellipse.  Stationary contact: at speed (Péclet number u a/α ≫ 1) the moving contact's resistance is
    lower, so this is a lower bound of the conductance."""
    a = math.sqrt(_pos("semi_major", semi_major) * _pos("semi_minor", semi_minor))
    r = 1.0 / (4.0 * _pos("conductivity_1", conductivity_1) * a) + 1.0 / (4.0 * _pos("conductivity_2",
                                                                                     conductivity_2) * a)
    return 1.0 / r


__all__ = ["flat_plate_convection", "natural_convection_cylinder", "contact_conductance", "air_properties",
           "STEEL_CONDUCTIVITY", "SILICON_NITRIDE_CONDUCTIVITY"]
