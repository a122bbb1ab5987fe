"""Quantities with units at the edge of the program.

Everything inside bearingsim is a plain SI float.  Strings such as ``"11.1 mm"``,
``"11200 rpm"`` or ``"310 GPa"`` from TOML files and the command line are parsed
here once, with pint, and checked for dimension.  A bare number is taken in the
field's default unit (e.g. N for forces, rpm for speeds).
"""

from __future__ import annotations

import math
from functools import lru_cache
from tokenize import TokenError

from .errors import InputError

# dimension name -> (pint dimensionality string, SI unit used inside, default unit for bare numbers)
DIMENSIONS: dict[str, tuple[str, str, str]] = {
    "length": ("[length]", "m", "m"),
    "angle": ("", "rad", "deg"),
    "force": ("[mass] * [length] / [time] ** 2", "N", "N"),
    "moment": ("[mass] * [length] ** 2 / [time] ** 2", "N*m", "N*m"),
    "speed": ("1 / [time]", "rad/s", "rpm"),
    "pressure": ("[mass] / [length] / [time] ** 2", "Pa", "Pa"),
    "density": ("[mass] / [length] ** 3", "kg/m^3", "kg/m^3"),
    "mass": ("[mass]", "kg", "kg"),
    "time": ("[time]", "s", "s"),
    "frequency": ("1 / [time]", "Hz", "Hz"),
    "temperature": ("[temperature]", "K", "degC"),
    "dimensionless": ("", "", ""),
    "stiffness": ("[mass] / [time] ** 2", "N/m", "N/m"),
    "kinematic_viscosity": ("[length] ** 2 / [time]", "m^2/s", "mm^2/s"),
    "inverse_temperature": ("1 / [temperature]", "1/K", "1/K"),
    "inverse_pressure": ("[length] * [time] ** 2 / [mass]", "1/Pa", "1/Pa"),
    "thermal_conductivity": ("[mass] * [length] / [time] ** 3 / [temperature]", "W/(m*K)", "W/(m*K)"),
}


@lru_cache(maxsize=1)
def registry():
    """The shared pint UnitRegistry (created lazily on first use: importing pint costs ~0.3 s)."""
    import pint

    try:  # parsed definitions cached on disk: 0.02 s instead of 0.5 s per start
        return pint.UnitRegistry(autoconvert_offset_to_baseunit=True, cache_folder=":auto:")
    except (OSError, ImportError):  # pragma: no cover - read-only home or no platformdirs
        return pint.UnitRegistry(autoconvert_offset_to_baseunit=True)


def parse_quantity(value, dimension: str, field: str) -> float:
    """Convert ``value`` to a plain SI float of the given dimension.

    Parameters
    ----------
    value : str | int | float
        ``"11.1 mm"``, ``"11200 rpm"``, ``"60 degC"`` or a bare number, which is
        taken in the dimension's default unit (see :data:`DIMENSIONS`).
    dimension : str
        One of the keys of :data:`DIMENSIONS`.
    field : str
        Name of the input field, used in error messages.

    Returns
    -------
    float
        The value in SI units [m, rad, N, N·m, rad/s, Pa, kg/m³, kg, s, Hz, K].

    Raises
    ------
    InputError
        Unknown unit, wrong dimension, or a value that is not a finite number.
    """
    dim, si, default = DIMENSIONS[dimension]
    if isinstance(value, bool):
        raise InputError(field, f"expected a quantity, got {value!r}", f'write e.g. "1 {default or si}"')
    if isinstance(value, (int, float)):
        out = float(value)
        if default and default != si:
            out = _convert(f"{value} {default}", si, field)
        if not math.isfinite(out):
            raise InputError(field, f"{value!r} is not a finite number", "give a finite value")
        return out
    if not isinstance(value, str):
        raise InputError(field, f"expected a quantity string such as '1 {default or si}', got {type(value).__name__}",
                         "write the value as a string with its unit")
    text = value.strip()
    if not text:
        raise InputError(field, "empty value", f'write e.g. "1 {default or si}"')
    try:
        out = float(text)
    except ValueError:
        out = None
    if out is not None:
        return parse_quantity(out, dimension, field)
    return _convert(text, si, field, dim, default)


def _convert(text: str, si: str, field: str, dim: str | None = None, default: str = "") -> float:
    import pint

    ureg = registry()
    try:
        q = ureg.Quantity(text)
    except (pint.errors.UndefinedUnitError, pint.errors.DefinitionSyntaxError, AttributeError,
            ValueError, TypeError, AssertionError, SyntaxError, TokenError) as exc:
        raise InputError(field, f"cannot read {text!r} as a quantity ({exc.__class__.__name__}: {exc})",
                         f'write a number and a unit, e.g. "1 {default or si}"') from None
    try:
        if si == "":
            mag = q.to("dimensionless").magnitude if hasattr(q, "to") else float(q)
        elif si == "rad" and q.dimensionless:
            mag = q.to("rad").magnitude
        elif si in ("rad/s", "Hz"):
            # pint treats the radian as dimensionless, so it cannot tell "50 Hz" (cycles per second)
            # from "50 rad/s".  A rate written with an angle unit (rpm, rad/s, deg/s) converts as an
            # angular speed; a bare reciprocal time (Hz, 1/s, 1/min) counts cycles.
            cycles = all(name.endswith("hertz") or ureg.Quantity(1, name).dimensionality == {"[time]": 1}
                         for name, _ in q.unit_items())
            angular = not cycles
            w = q.to("rad/s").magnitude if angular else 2.0 * math.pi * q.to("Hz").magnitude
            mag = w if si == "rad/s" else w / (2.0 * math.pi)
        else:
            mag = q.to(si).magnitude
    except pint.errors.DimensionalityError:
        raise InputError(field, f"{text!r} has dimension {q.dimensionality}, expected {dim or si}",
                         f'give it in a unit such as "{default or si}"') from None
    out = float(mag)
    if not math.isfinite(out):
        raise InputError(field, f"{text!r} is not a finite number", "give a finite value")
    return out

